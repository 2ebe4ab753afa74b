"""What students get, built and checked (``make release``): :mod:`.make_release` builds the
student edition (:mod:`.student_edition`, from ``student_template/``), the wheel and the
website; :mod:`.leak_gate` scans all three for answers."""
