"""The student's identity in nbgrader: the roster of the course, and the numbers the
notebook showed (issue 33).

- :class:`CourseIdentity` (``c.CourseIdentity.rosters``, written by ``make course
  ROSTER=...``): the roster files that map every alias of a student (nbgrader's student id, a
  hub user, an SIS id) to the course's key (:mod:`instructor.grading.identity`), read once per run;
  ``c.CourseIdentity.report``: the instructor's list of the students whose id needs a look
  (default ``identity-report.csv`` beside ``gradebook.db``).
- :class:`ShownNumbers` (sanitize stage, before ``ClearOutput``): which variant of each
  exercise the submitted notebook showed, read from the records its check cells left when the
  student ran them, kept in the notebook's metadata for
  :class:`~instructor.grading.preprocessor.VerifyRecords`.
  A note for the feedback and the report only: it never decides a point.
"""

from __future__ import annotations

import os
from functools import cache
from pathlib import Path

from nbgrader.preprocessors import NbGraderPreprocessor
from traitlets import List, Unicode
from traitlets.config import LoggingConfigurable

from course_lib.record import MIME

from .identity import REPORT, load

__all__ = ["CourseIdentity", "ShownNumbers", "SHOWN", "shown_phrase"]

SHOWN = "rotations_shown"  # notebook metadata: {exercise: {"variant": k, "student": id}}
SUFFIX = "-check"


@cache
def _load(paths, stamps):  # stamps: a changed file is read again
    return load(list(paths))


class CourseIdentity(LoggingConfigurable):
    """The course's roster(s) and the instructor's identity report."""

    rosters = List(
        Unicode(),
        help="Roster CSV files (a Canvas gradebook export, or key,alias,alias...) mapping "
        "every id of a student to the course's key. Empty: ids are only normalised.",
    ).tag(config=True)
    report = Unicode(
        "", help=f"The identity report CSV (default: {REPORT} beside gradebook.db)."
    ).tag(config=True)

    def roster(self):
        """The :class:`instructor.grading.identity.Roster` (RosterError when a file cannot be
        trusted)."""
        paths = tuple(str(p) for p in self.rosters)
        return _load(paths, tuple(os.stat(p).st_mtime_ns for p in paths))

    def report_path(self, resources):
        if self.report:
            return Path(self.report)
        url = resources.get("nbgrader", {}).get("db_url", "")
        if url.startswith("sqlite:///"):
            return Path(url.removeprefix("sqlite:///")).parent / REPORT
        return Path(REPORT)


def _shown(cell):
    """``{"variant": k, "student": id}`` from a check cell's submitted record, or None."""
    outputs = cell.get("outputs")
    for out in outputs if isinstance(outputs, list) else ():
        data = out.get("data") if isinstance(out, dict) else None
        data = data.get(MIME) if isinstance(data, dict) else None
        if isinstance(data, dict) and type(data.get("variant")) is int:
            student = data.get("student")
            return {
                "variant": data["variant"],
                "student": student[:200] if isinstance(student, str) else None,
            }
    return None


class ShownNumbers(NbGraderPreprocessor):
    """Keep, before the outputs are cleared, which numbers each check cell was run on."""

    def preprocess(self, nb, resources):
        shown = {}
        for cell in nb.cells:
            # it runs before GuardCells repairs anything: any metadata, any outputs, no error
            meta = cell.get("metadata") if isinstance(cell, dict) else None
            grading = meta.get("nbgrader") if isinstance(meta, dict) else None
            gid = grading.get("grade_id") if isinstance(grading, dict) else None
            if cell.get("cell_type") != "code" or not isinstance(gid, str):
                continue
            try:
                got = _shown(cell) if gid.endswith(SUFFIX) else None
            except Exception:  # noqa: BLE001 - a note only: a malformed output gives none
                got = None
            if got is not None:
                shown[gid[: -len(SUFFIX)]] = got
        nb.metadata[SHOWN] = shown  # replaces whatever the submission held under this name
        return nb, resources


def shown_phrase(shown):
    """Whose numbers a notebook showed, in words: "no student id (example numbers)", or the id."""
    student = shown.get("student")
    if student is None:
        return "numbers of an id the notebook did not record"
    if student in ("", "(example)"):
        return "example numbers (no student id was set)"
    return f"numbers of the id {student!r}"
