"""The instructor's grader: points decided outside the student's kernel (not installed).

- :mod:`instructor.grading.records`: reads an answer record (``course_lib.record``) with a
  whitelist;
- :mod:`instructor.grading.verify`: re-checks it against ``instructor/answers`` at fresh random
  points;
- :mod:`instructor.grading.preprocessor`: the nbgrader preprocessors that plug both into
  ``autograde``;
- :mod:`instructor.grading.sandbox`: the confined kernel that runs a submission;
- :mod:`instructor.grading.intake`: what is read of a submission (regular files inside it, 20 MB at
  most), :mod:`instructor.grading.collect`: ``nbgrader collect`` through it;
- :mod:`instructor.grading.course`: ``make course COURSE=DIR``, an nbgrader course directory;
- :mod:`instructor.grading.identity`: one key per student, the instructor's roster (never shipped);
  :mod:`instructor.grading.id_preprocessors`: the roster in nbgrader, the numbers a notebook showed.

This package lives in the instructor's repository only: it is not part of the wheel, and the
kernel that runs a submission cannot read it.
"""
