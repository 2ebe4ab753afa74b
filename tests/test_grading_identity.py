"""One student, one key, on both grading paths (issue 33), with the course's roster.

Problem set 1 in a `make course` directory with a roster (``key,alias,alias``); the same
notebooks through a Gradescope autograder that carries the roster are in
``tests/test_grading_gradescope.py`` (it reuses that file's prepared autograder). Each
student's notebook is the solved copy as the student ran it: the id set in its student-id
cell, executed, its answers hard-wired to the numbers of the id the student worked with
(``parameters(name, student=...)``), so that only the right numbers get the points.

- alice7 worked on a laptop as "Alice7@Example.EDU " (capitals, a space); nbgrader knows her
  as the hub user ``alice7``, Gradescope by her e-mail and sid: full marks on both paths.
- bob9 worked as "bob9" (a hub user, without the course's domain): graded on the numbers of
  his key, he loses the exercises whose numbers differ, and the feedback and the instructor's
  identity report say so (a regrade, not a silent 0).
- zed is not in the roster: graded on the id given, with a note, and listed.
"""

from __future__ import annotations

import csv
from pathlib import Path

import nbformat
import pytest
from test_grading_nbgrader import run

from course_lib.exercises import exercises
from course_lib.exercises._variants import table, variant_index
from instructor.grading.course import write_course

ROOT = Path(__file__).resolve().parents[1]


pytestmark = [pytest.mark.notebook_exec, pytest.mark.confined, pytest.mark.slow_grading]
PS, CHAPTER = "ps01", 1
TOTAL = sum(ex.points for ex in exercises(CHAPTER))
VARIED = [ex for ex in exercises(CHAPTER) if ex.variants is not None]
ROSTER = "key,alias,alias\nalice7@example.edu,alice7,3031042\nbob9@example.edu,bob9,3031043\n"
WORKED_AS = {"alice7": "Alice7@Example.EDU ", "bob9": "bob9", "zed": "zed"}


def differs(a, b):
    """The exercises of the set whose numbers differ for the ids ``a`` and ``b``."""
    out = []
    for ex in VARIED:
        rows = len(table()["keys"][ex.variants.key])
        if variant_index(ex.variants.key, rows, a) != variant_index(ex.variants.key, rows, b):
            out.append(ex)
    return out


def worked_copy(source, worked_as, monkeypatch):
    """The solved copy ``source`` as a student who set the id ``worked_as`` ran it."""
    from nbclient import NotebookClient

    nb = nbformat.read(source, as_version=4)
    for cell in nb.cells:
        if cell.get("id", "").endswith("student-id-cell"):
            assert 'set_student_id("")' in cell.source
            cell.source = cell.source.replace(
                'set_student_id("")', f"set_student_id({worked_as!r})"
            )
        for ex in VARIED:
            own = f'P = parameters("{ex.name}")'
            if cell.get("id") == f"{ex.name}-answer":
                assert own in cell.source
                wired = f'P = parameters("{ex.name}", student={worked_as!r})'
                cell.source = cell.source.replace(own, wired)
    monkeypatch.delenv("COURSE_STUDENT_ID", raising=False)
    NotebookClient(nb, timeout=120, kernel_name="python3", allow_errors=True).execute()
    return nb


@pytest.fixture(scope="module")
def worked(tmp_path_factory):
    """{student: notebook as they handed it in}, from the solved copy of ``make course``."""
    mp = pytest.MonkeyPatch()
    top = tmp_path_factory.mktemp("worked")
    write_course(top)
    source = next((top / "source" / PS).glob("*.ipynb"))
    try:
        return source.name, {s: worked_copy(source, who, mp) for s, who in WORKED_AS.items()}
    finally:
        mp.undo()


def _report(folder):
    path = folder / "identity-report.csv"
    with open(path, newline="", encoding="utf-8") as f:
        return {r["student"]: r for r in csv.DictReader(f)}


def test_nbgrader_with_the_roster_one_key_per_student(worked, tmp_path):
    from nbgrader.api import Gradebook

    name, subs = worked
    roster = tmp_path / "export.csv"
    roster.write_text(ROSTER)
    course = tmp_path / "course"
    write_course(course, roster=roster)
    assert "c.CourseIdentity.rosters" in (course / "nbgrader_config.py").read_text()
    code, out = run(["generate_assignment", PS, "--create"], course)
    assert code == 0, out
    for student, nb in subs.items():
        dest = course / "submitted" / student / PS
        dest.mkdir(parents=True)
        nbformat.write(nb, dest / name)
    code, out = run(["autograde", PS, "--create"], course)
    assert code == 0, out
    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gb:
        points = {
            s: {
                g.name.removesuffix("-check"): g.score
                for g in gb.find_submission(PS, s).notebooks[0].grades
            }
            for s in subs
        }
    assert sum(points["alice7"].values()) == TOTAL, points["alice7"]
    assert sum(points["zed"].values()) == TOTAL, points["zed"]
    lost = differs("bob9", "bob9@example.edu")
    assert lost, "bob9's and his key's numbers should differ somewhere"
    assert sum(points["bob9"].values()) == TOTAL - sum(ex.points for ex in lost)
    report = _report(course)
    assert "alice7" not in report  # her laptop id and her hub user are one key
    assert report["bob9"]["graded_as"] == "bob9@example.edu"
    assert set(report["bob9"]["lost"].split()) == {ex.name for ex in lost}
    assert report["bob9"]["shown_as"] == "bob9"
    assert report["zed"]["how"] == "not in the roster" and report["zed"]["graded_as"] == "zed"
    feedback = next((course / "autograded" / "bob9" / PS).glob("*.ipynb")).read_text()
    assert "graded on the numbers of 'bob9@example.edu'" in feedback
    assert "regrade" in feedback and "numbers of the id 'bob9'" in feedback
