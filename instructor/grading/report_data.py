"""The graded class as the report reads it, from either grading path (issue 34).

- :func:`from_course`: an nbgrader course directory: the points of every grade cell from
  ``gradebook.db`` (nbgrader's :class:`~nbgrader.api.Gradebook`), the grader's notes on each
  answer from ``answer-log/`` (:mod:`instructor.grading.answer_log`).
- :func:`from_gradescope`: Gradescope's exports of one programming assignment: *Export
  Submissions* (a ``.zip``, or its folder, holding ``submission_metadata.yml``: per submission
  ``:submitters:`` and ``:results:``, the ``results.json`` the autograder wrote, with each test's
  ``extra_data``), or *Download Grades* (a CSV: total scores only, said plainly in the report).

Both give :class:`ProblemSet` objects: the exercises, every submission's points per exercise
and, when recorded, the grader's notes; the students with no submission; notes on what the data
lacks (an exercise this course version does not have, submissions without notes).
"""

from __future__ import annotations

import csv
import io
import os
import sys
import zipfile
from dataclasses import dataclass, field
from pathlib import Path

from . import answer_log

__all__ = [
    "Answer",
    "Submission",
    "ProblemSet",
    "from_course",
    "from_gradescope",
    "apply_roster",
    "known",
]

SUFFIX = "-check"


@dataclass
class Answer:
    """One exercise of one submission: points, and the grader's notes (None: not recorded)."""

    score: float
    max_score: float
    verdict: str | None = None
    mistake: str | None = None
    variant: int | None = None
    shown: int | None = None
    checked: bool | None = None
    group: str | None = None
    text: str | None = None

    @property
    def right(self):
        return self.max_score > 0 and self.score >= self.max_score


@dataclass
class Submission:
    student: str  # the grader's student id
    name: str  # the student's name where the source has one, else ''
    answers: dict  # exercise -> Answer
    email: str = ""
    total: float | None = None  # the source's own total (Gradescope's, with any adjustment)

    @property
    def score(self):
        if self.total is not None:
            return self.total
        return sum(a.score for a in self.answers.values())


@dataclass
class ProblemSet:
    name: str
    exercises: list  # exercise names, in the order of the problem set
    points: dict  # exercise -> max score
    submissions: list = field(default_factory=list)
    missing: list = field(default_factory=list)  # (student id, name) with no submission
    notes: list = field(default_factory=list)
    unmatched: list = field(default_factory=list)  # (student id, name) in no roster row
    source: str = ""
    scores_only: bool = False

    @property
    def max_score(self):
        return sum(self.points.values())


def known(name):
    """Is ``name`` an exercise of this course version?"""
    from course_lib.exercises import EXERCISES

    return name in EXERCISES


def _answer(score, max_score, item):
    item = item if isinstance(item, dict) else {}

    def _int(key):
        value = item.get(key)
        return value if type(value) is int else None

    def _text(key, limit=200):
        value = item.get(key)
        return str(value)[:limit] if value is not None else None

    checked = item.get("checked")
    return Answer(
        score=float(score or 0.0),
        max_score=float(max_score or 0.0),
        verdict=_text("verdict", 40),
        mistake=_text("mistake", 80),
        variant=_int("variant"),
        shown=_int("shown"),
        checked=checked if isinstance(checked, bool) else None,
        group=_text("group", 80),
        text=_text("answer"),
    )


def _unknown_notes(ps):
    return [
        f"{ps.name}: '{name}' is not an exercise of this course version (renamed or removed?): "
        "its points are counted, without known mistakes, variants or hints."
        for name in ps.exercises
        if not known(name)
    ]


def _undetailed_note(ps, what):
    bare = sum(1 for s in ps.submissions if all(a.verdict is None for a in s.answers.values()))
    if bare:
        return [f"{ps.name}: {bare} of {len(ps.submissions)} submissions have no notes {what}."]
    return []


# ------------------------------------------------------------------------------ nbgrader


def _gradebook_path(course):
    db = Path(course) / "gradebook.db"
    if not db.is_file():
        raise ValueError(f"COURSE: no gradebook.db in {course} (run nbgrader autograde first)")
    bin_dir = str(Path(sys.executable).parent)  # nbgrader runs alembic from PATH
    if bin_dir not in os.environ.get("PATH", "").split(os.pathsep):
        os.environ["PATH"] = f"{bin_dir}{os.pathsep}{os.environ.get('PATH', '')}"
    return db


def _exercise(grade_id):
    return grade_id[: -len(SUFFIX)] if grade_id.endswith(SUFFIX) else grade_id


def _course_set(gb, assignment, course):
    from nbgrader.api import MissingEntry

    cells = [(c.name, c.max_score) for nb in assignment.notebooks for c in nb.grade_cells]
    ps = ProblemSet(assignment.name, [_exercise(n) for n, _ in cells], {})
    ps.points = {_exercise(n): float(m) for n, m in cells}
    ps.source = f"nbgrader course {course}"
    logs = answer_log.read(course, assignment.name)
    for student in gb.students:
        name = f"{student.first_name or ''} {student.last_name or ''}".strip()
        try:
            sub = gb.find_submission(assignment.name, student.id)
        except MissingEntry:
            ps.missing.append((student.id, name))
            continue
        notes = logs.get(student.id, {})
        answers = {}
        for nb in sub.notebooks:
            for g in nb.grades:
                ex = _exercise(g.name)
                answers[ex] = _answer(g.score, g.max_score, notes.get(ex))
        ps.submissions.append(Submission(student.id, name, answers))
    ps.notes += _unknown_notes(ps)
    ps.notes += _undetailed_note(ps, "from the grader (graded before the answer log existed?)")
    return ps


def from_course(course, assignments=None):
    """The :class:`ProblemSet` of every (or each named) assignment of an nbgrader course."""
    from nbgrader.api import Gradebook

    db = _gradebook_path(course)
    with Gradebook(f"sqlite:///{db}") as gb:
        found = {a.name: a for a in gb.assignments}
        if not found:
            raise ValueError(f"COURSE: the gradebook of {course} has no assignment yet")
        names = list(assignments or sorted(found))
        for name in names:
            if name not in found:
                raise ValueError(f"ASSIGNMENT: {name!r} is not in the gradebook ({sorted(found)})")
        return [_course_set(gb, found[name], Path(course)) for name in names]


# ------------------------------------------------------------------------------ Gradescope


def _metadata_text(path):
    path = Path(path)
    if path.is_dir():
        found = sorted(path.rglob("submission_metadata.yml"))
        if not found:
            raise ValueError(f"GRADESCOPE: no submission_metadata.yml in the folder {path}")
        return found[0].read_text(encoding="utf-8")
    with zipfile.ZipFile(path) as zf:
        names = [n for n in zf.namelist() if n.endswith("submission_metadata.yml")]
        if not names:
            raise ValueError(f"GRADESCOPE: no submission_metadata.yml in {path}")
        return zf.read(sorted(names, key=len)[0]).decode("utf-8")


def _people(entry):
    people = entry.get(":submitters") or []
    person = people[0] if people and isinstance(people[0], dict) else {}
    sid = str(person.get(":sid") or person.get(":email") or "").strip()
    return sid, str(person.get(":name") or "").strip(), str(person.get(":email") or "")


def _tests(results):
    tests = results.get("tests") if isinstance(results, dict) else None
    return [t for t in tests if isinstance(t, dict)] if isinstance(tests, list) else []


def _set_name(entries, assignment):
    if assignment:
        return assignment
    for entry in entries:
        extra = (entry.get(":results") or {}).get("extra_data")
        if isinstance(extra, dict) and extra.get("assignment"):
            return str(extra["assignment"])[:40]
    return "gradescope"


def _from_metadata(text, path, assignment):
    import yaml

    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)  # libyaml's: 20 times faster, as safe
    try:
        data = yaml.load(text, Loader=loader)  # noqa: S506 - a safe loader
    except yaml.YAMLError as err:
        msg = f"GRADESCOPE: submission_metadata.yml of {path} is not YAML ({err})"
        raise ValueError(msg) from None
    if not isinstance(data, dict):
        raise ValueError(f"GRADESCOPE: submission_metadata.yml of {path} is not a mapping")
    entries = [e for e in data.values() if isinstance(e, dict)]
    ps = ProblemSet(_set_name(entries, assignment), [], {}, source=f"Gradescope export {path}")
    failed = 0
    for entry in entries:
        sid, name, email = _people(entry)
        answers = {}
        tests = _tests(entry.get(":results"))
        if [t.get("name") for t in tests] == ["grading"]:  # gradescope_run.failure()
            failed, tests = failed + 1, []
        for test in tests:
            ex = str(test.get("name") or "")[:80]
            if ex not in ps.points:
                ps.exercises.append(ex)
                ps.points[ex] = float(test.get("max_score") or 0.0)
            answers[ex] = _answer(test.get("score"), test.get("max_score"), test.get("extra_data"))
        sid = sid or f"submission {len(ps.submissions) + 1}"
        total = entry.get(":score")
        total = float(total) if isinstance(total, (int, float)) else None
        ps.submissions.append(Submission(sid, name, answers, email, total))
    if not ps.submissions:
        ps.notes.append(f"{ps.name}: the export holds no submission.")
    if failed:
        ps.notes.append(
            f"{ps.name}: {failed} submissions were not graded by the autograder (its output "
            "says why; 0 points): counted as submissions, in no exercise."
        )
    ps.notes += _unknown_notes(ps)
    ps.notes += _undetailed_note(
        ps, "(no extra_data in their tests: graded by an older autograder?)"
    )
    return ps


def _float(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def _from_csv(path, assignment):
    text = Path(path).read_text(encoding="utf-8-sig")
    reader = csv.DictReader(io.StringIO(text))
    fields = reader.fieldnames or []
    if "Total Score" not in fields or not ({"SID", "Email"} & set(fields)):
        raise ValueError(
            f"GRADESCOPE: {path} is not a Gradescope grades CSV (no 'Total Score' and 'SID' "
            "or 'Email' column)"
        )
    name = assignment or Path(path).stem
    ps = ProblemSet(name, [], {}, source=f"Gradescope grades CSV {path}", scores_only=True)
    most = 0.0
    for row in reader:
        sid = (row.get("SID") or row.get("Email") or "").strip()
        who = row.get("Name") or f"{row.get('First Name', '')} {row.get('Last Name', '')}"
        score = _float(row.get("Total Score"))
        most = max(most, _float(row.get("Max Points")) or 0.0)
        if score is None or (row.get("Status") or "").strip().lower() == "missing":
            ps.missing.append((sid, who.strip()))
            continue
        answers = {"total": _answer(score, 0.0, None)}
        ps.submissions.append(Submission(sid, who.strip(), answers, row.get("Email") or ""))
    ps.exercises, ps.points = ["total"], {"total": most}
    for sub in ps.submissions:
        sub.answers["total"].max_score = most
    ps.notes.append(
        f"{ps.name}: scores only. A Gradescope grades CSV holds each student's total, not the "
        "points per exercise nor the grader's notes: no known mistakes, variants or checks. "
        "Export the submissions (Review Grades, Export Submissions) for the full report."
    )
    return ps


def from_gradescope(path, assignment=None):
    """The :class:`ProblemSet` of one Gradescope export (zip or folder of *Export
    Submissions*, or the *Download Grades* CSV)."""
    path = Path(path)
    if not path.exists():
        raise ValueError(f"GRADESCOPE: {path} does not exist")
    if path.suffix.lower() == ".csv":
        return _from_csv(path, assignment)
    if path.is_file() and not zipfile.is_zipfile(path):
        raise ValueError(f"GRADESCOPE: {path} is neither a zip, a folder nor a CSV")
    return _from_metadata(_metadata_text(path), path, assignment)


# ------------------------------------------------------------------------------ roster


def _keys(row):
    return {row.get("SIS User ID"), row.get("SIS Login ID"), row.get("ID")} - {"", None}


def apply_roster(ps, rows):
    """Match ``ps``'s submissions to a Canvas export's rows (by SIS User ID, SIS Login ID or
    Canvas ID): the roster's students with no submission become ``missing``, submissions under
    an id that no row has (a wrong id?) ``unmatched``; a matched student gets the roster's name
    where the source had none."""
    matched = set()
    for sub in ps.submissions:
        row = next((i for i, r in enumerate(rows) if sub.student in _keys(r)), None)
        if row is None:
            ps.unmatched.append((sub.student, sub.name))
            continue
        matched.add(row)
        sub.name = sub.name or (rows[row].get("Student") or "").strip()
    ps.missing = [
        (r.get("SIS User ID") or r.get("SIS Login ID") or r.get("ID") or "", r.get("Student", ""))
        for i, r in enumerate(rows)
        if i not in matched
    ]
    return ps
