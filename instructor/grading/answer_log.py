"""Where the grader keeps what it noted about each graded answer (issue 34), beside the grade.

Each ``nbgrader autograde`` run of one student's notebook writes one small JSON file,
``<course>/answer-log/<assignment>/<student>/<notebook>.json`` (the course directory is that of
``gradebook.db``)::

    {"version": 1, "assignment": "ps01", "student": "ada", "notebook": "ps01_...",
     "answers": [{"exercise": "bac_cab", "verdict": "wrong", "mistake": "swapped",
                  "variant": null, "shown": null, "checked": true}, ...]}

One file per student and notebook, written whole to a temporary name and then renamed
(``os.replace``): autograde processes running at once for different students never write the
same file, a reader never sees half a file, and grading a student again replaces their file
(no stale lines, unlike one shared log appended to). On Gradescope the same entries go into each
test's ``extra_data`` (:func:`instructor.grading.gradescope_run.results_for`).

:class:`NoteChecksRun` (first of the sanitize preprocessors, before ``ClearOutput`` empties the
outputs) notes on each check cell whether the student had run it in the notebook they handed
in: it had an execution count or outputs. That is what the handed-in file says (a student can
clear outputs, or edit the file); it is a statistic for the instructor, never points.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from urllib.parse import quote, unquote

from nbgrader import utils
from nbgrader.preprocessors import NbGraderPreprocessor

__all__ = ["FOLDER", "NoteChecksRun", "course_of", "save", "write", "read", "read_student"]

FOLDER = "answer-log"
VERSION = 1
CHECKED = (
    "rotations_course_checked"  # instructor.grading.diagnose.CHECKED (not imported: sympy is slow)
)
SUFFIX = "-check"


class NoteChecksRun(NbGraderPreprocessor):
    """Mark each exercise check cell: had the student run it in the handed-in notebook?"""

    def preprocess_cell(self, cell, resources, cell_index):
        meta = cell.get("metadata")
        if cell.get("cell_type") != "code" or not isinstance(meta, dict):
            return cell, resources
        meta.pop(CHECKED, None)  # never the student's own value
        try:
            graded = utils.is_grade(cell)
        except Exception:  # noqa: BLE001 - malformed metadata: GuardCells deals with it
            graded = False
        gid = meta.get("nbgrader", {}).get("grade_id", "") if graded else ""
        if isinstance(gid, str) and gid.endswith(SUFFIX):
            ran = cell.get("execution_count") is not None or bool(cell.get("outputs"))
            meta[CHECKED] = ran
        return cell, resources


def course_of(resources):
    """The course directory (that of ``gradebook.db``) of an nbgrader run, or None."""
    url = str((resources or {}).get("nbgrader", {}).get("db_url") or "")
    if not url.startswith("sqlite:///"):
        return None
    return Path(url[len("sqlite:///") :]).parent


def _path(course, assignment, student, notebook):
    parts = [quote(str(p), safe="") for p in (assignment, student, notebook)]
    return Path(course) / FOLDER / parts[0] / parts[1] / f"{parts[2]}.json"


def write(course, assignment, student, notebook, answers):
    """Write one student's entries for one notebook (whole, then renamed); returns the path.

    Examples
    --------
    >>> import tempfile
    >>> course = tempfile.mkdtemp()
    >>> path = write(course, "ps01", "ada lovelace", "ps01_x", [{"exercise": "bac_cab"}])
    >>> path.relative_to(course).as_posix()
    'answer-log/ps01/ada%20lovelace/ps01_x.json'
    >>> read(course, "ps01")
    {'ada lovelace': {'bac_cab': {'exercise': 'bac_cab'}}}
    """
    path = _path(course, assignment, student, notebook)
    path.parent.mkdir(parents=True, exist_ok=True)
    data = {
        "version": VERSION,
        "assignment": assignment,
        "student": student,
        "notebook": notebook,
        "answers": list(answers),
    }
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    tmp.write_text(json.dumps(data, ensure_ascii=False, indent=0))
    os.replace(tmp, path)
    return path


def save(resources, answers, log=None):
    """:func:`write` the entries of the notebook nbgrader is grading (``resources``); a
    failure is logged, never raised (the grade does not depend on it)."""
    info = (resources or {}).get("nbgrader", {})
    course = course_of(resources)
    if course is None or not info.get("student") or not info.get("assignment"):
        return None
    notebook = info.get("notebook") or resources.get("unique_key") or "notebook"
    try:
        return write(course, info["assignment"], info["student"], notebook, answers)
    except (OSError, TypeError, ValueError) as err:
        if log is not None:
            log.warning("answer log not written (%s): the class report lacks it", err)
        return None


def _load(path):
    try:
        data = json.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if not isinstance(data, dict) or data.get("version") != VERSION:
        return None
    answers = data.get("answers")
    return [a for a in answers if isinstance(a, dict)] if isinstance(answers, list) else None


def read_student(course, assignment, student):
    """``{exercise: entry}`` of one student's notebooks of ``assignment`` ({} when none)."""
    folder = Path(course) / FOLDER / quote(str(assignment), safe="") / quote(student, safe="")
    out = {}
    for path in sorted(folder.glob("*.json")) if folder.is_dir() else ():
        for item in _load(path) or ():
            out[str(item.get("exercise"))] = item
    return out


def read(course, assignment):
    """``{student: {exercise: entry}}`` of every student logged for ``assignment``."""
    folder = Path(course) / FOLDER / quote(str(assignment), safe="")
    if not folder.is_dir():
        return {}
    return {
        unquote(d.name): read_student(course, assignment, unquote(d.name))
        for d in sorted(folder.iterdir())
        if d.is_dir()
    }
