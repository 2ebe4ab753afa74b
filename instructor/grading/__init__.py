"""The instructor's grader: points decided outside the student's kernel (not installed).

- :mod:`grader.records`: reads an answer record (``course_lib.record``) with a whitelist;
- :mod:`grader.verify`: re-checks it against ``tools/solutions`` at fresh random points;
- :mod:`grader.preprocessor`: the nbgrader preprocessors that plug both into ``autograde``;
- :mod:`grader.sandbox`: the confined kernel that runs a submission;
- :mod:`grader.intake`: what is read of a submission (regular files inside it, 20 MB at most),
  :mod:`grader.collect`: ``nbgrader collect`` through it;
- :mod:`grader.course`: ``make course COURSE=DIR``, an nbgrader course directory;
- :mod:`grader.identity`: one key per student, the instructor's roster (never shipped);
  :mod:`grader.id_preprocessors`: the roster in nbgrader, the numbers a notebook showed.

This package lives in the instructor's repository only: it is not part of the wheel, and the
kernel that runs a submission cannot read it.
"""
