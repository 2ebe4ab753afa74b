"""The build steps (docs/architecture.md): ``make exercises`` runs :mod:`.variant_tables`,
:mod:`.exercise_fingerprints`, :mod:`.sync_exercises` and :mod:`.notebooks`; ``make notebooks``
runs :mod:`.alt_text`, :mod:`.notebooks` and :mod:`.course_links`; ``make student`` runs
:mod:`.student`; ``make variant`` runs :mod:`.show_variant`."""
