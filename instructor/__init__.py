"""Everything of the course that students never get (issue 36; docs/architecture.md).

- :mod:`instructor.answers`: per chapter one module ``chNN.py``, the reference solutions, the
  known mistakes and the variant draws of its exercises (:func:`instructor.answers.load`);
- :mod:`instructor.build`: the build steps (variant tables, fingerprints, problem-set sync,
  notebooks, alt text, links, chapter counts, the figure audit, student copies);
- :mod:`instructor.grading`: grading (nbgrader's preprocessors, the confined kernel,
  Gradescope, Canvas, the verdict, the class report);
- :mod:`instructor.release`: the student edition, the wheel and the leak gate.

Every tool runs from the repository's root as ``python -m instructor.<role>.<tool>``; the
students' package is ``course_lib`` (the wheel holds it alone).
"""
