"""The real nbgrader round trip (nbgrader 0.9.6, pinned in environment.txt).

In a course directory written by ``make course`` (instructor/grading/course.py: the confined kernel
and the grader's preprocessors in its nbgrader_config.py):

1. ``nbgrader generate_assignment`` accepts every problem set as it is (no marker word in the
   prose, balanced markers, unique grade ids) and releases copies without the solutions or the
   hidden tests.
2. ``nbgrader autograde`` of the problem sets (``problem_sets/``, written by
   instructor/build/sync_exercises.py) gives the instructor's notebooks full marks, more than 0,
   and the released copies 0; an instructor's hidden test in a check cell runs.
3. ``nbgrader validate`` fails on a released (blank) copy with one line per failed check that
   holds the whole hint, and no output of a check cell reads as a (partial) score.
"""

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest
from grading_helpers import TRUSTED_AUTOGRADE

from course_lib.exercises import exercises
from instructor.grading.course import write_course

ROOT = Path(__file__).resolve().parents[1]


pytestmark = pytest.mark.notebook_exec
NBGRADER = Path(sys.executable).with_name("nbgrader")
PROBLEM_SETS = sorted((ROOT / "problem_sets").glob("ps[0-9]*.ipynb"))


def run(args, cwd):
    env = {**os.environ, "PATH": f"{NBGRADER.parent}{os.pathsep}{os.environ.get('PATH', '')}"}
    proc = subprocess.run(
        [str(NBGRADER), *args], cwd=cwd, capture_output=True, text=True, timeout=300, env=env
    )  # nbgrader runs `alembic` from PATH
    return proc.returncode, proc.stdout + proc.stderr


@pytest.fixture(scope="module")
def course(tmp_path_factory):
    root = tmp_path_factory.mktemp("course")
    write_course(root)
    sections = root / "source" / "exercises"
    sections.mkdir(parents=True)
    for path in PROBLEM_SETS:
        nb = nbformat.read(path, as_version=4)
        if path.name.startswith("ps01"):  # an instructor's hidden test
            cell = next(c for c in nb.cells if c.id == "coords_by_projection-check")
            cell.source += (
                "\n### BEGIN HIDDEN TESTS\n"
                "assert check('coords_by_projection', answer_coords_by_projection)\n"
                "### END HIDDEN TESTS"
            )
        nbformat.write(nb, sections / f"{path.name[2:4]}_exercises.ipynb")
    return root


def _scores(course, student):
    from nbgrader.api import Gradebook

    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gb:
        sub = gb.find_submission("exercises", student)
        return sub.score, sub.max_score


@pytest.fixture(scope="module")
def graded(course):
    code, out = run(["generate_assignment", "exercises", "--force", "--create"], course)
    assert code == 0, out
    for student, src in (("instructor", course / "source"), ("blank", course / "release")):
        dest = course / "submitted" / student / "exercises"
        shutil.copytree(src / "exercises", dest)
        (dest / "timestamp.txt").write_text("2026-01-01 00:00:00.000000 UTC")
    code, out = run(["autograde", "exercises", "--force", "--create", *TRUSTED_AUTOGRADE], course)
    assert code == 0, out
    return course


def test_released_copies_hold_neither_solutions_nor_hidden_tests(graded):
    nb = nbformat.read(graded / "release" / "exercises" / "01_exercises.ipynb", as_version=4)
    text = "\n".join(c.source for c in nb.cells)
    assert "HIDDEN TESTS" not in text and "BEGIN SOLUTION" not in text
    check_cell = next(c for c in nb.cells if c.id == "coords_by_projection-check")
    assert "assert result.ok, result.message" in check_cell.source


def test_autograde_gives_the_instructor_full_marks_and_a_blank_copy_zero(graded):
    total = sum(ex.points for ex in exercises())
    score, max_score = _scores(graded, "instructor")
    assert max_score == total > 0
    assert score == max_score
    score, max_score = _scores(graded, "blank")
    assert (score, max_score) == (0, total)


def test_autograded_check_cells_of_a_blank_copy_hold_the_graders_note(graded):
    nb = json.loads(
        (graded / "autograded" / "blank" / "exercises" / "03_exercises.ipynb").read_text()
    )
    checks = [c for c in nb["cells"] if c.get("metadata", {}).get("nbgrader", {}).get("grade")]
    assert len(checks) == len(exercises(3))
    for cell in checks:
        (error,) = cell["outputs"]
        assert error["output_type"] == "error" and error["ename"] == "GradingNote"
        assert error["evalue"].endswith("0 points from the grader: no answer recorded.")


def test_no_check_cell_output_reads_as_a_score(graded):
    nb = json.loads(
        (graded / "autograded" / "instructor" / "exercises" / "02_exercises.ipynb").read_text()
    )
    for cell in nb["cells"]:
        if cell.get("metadata", {}).get("nbgrader", {}).get("grade"):
            assert [o["output_type"] for o in cell["outputs"]] == ["display_data"]
            assert "".join(cell["outputs"][0]["data"]["text/plain"]).startswith("✓ ")


def test_validate_prints_one_whole_line_per_failed_check_and_passes_the_instructor_copy(graded):
    blank = graded / "release" / "exercises" / "02_exercises.ipynb"
    code, out = run(["validate", str(blank)], graded)
    assert "VALIDATION FAILED ON 7 CELL(S)" in out, out
    assert "cannot be converted to a float" not in out
    lines = [line.strip() for line in out.splitlines() if "CheckFailed" in line]
    assert len(lines) == len(exercises(2)), out
    for ex, line in zip(exercises(2), lines):
        assert line == (
            f"CheckFailed: ✗ {ex.name}: no answer yet: assign your answer to "
            f"`{ex.answer_variable}`."
        )
    solved = graded / "source" / "exercises" / "02_exercises.ipynb"
    code, out = run(["validate", str(solved)], graded)
    assert "Success! Your notebook passes all the tests." in out, out
    assert "cannot be converted to a float" not in out
