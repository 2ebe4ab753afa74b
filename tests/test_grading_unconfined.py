"""A machine without bubblewrap (issue 24): a PATH that holds no ``bwrap`` stands in for it.

- ``make test`` there skips only the tests that need the confined kernel, with one line that
  says how many, why and how to install it; with ``CONFINED_REQUIRED=1`` they fail instead.
- ``nbgrader autograde`` with the course's configuration refuses to run students' code, before
  anything is touched (a re-grade with ``--force`` keeps the earlier autograded copies and
  the gradebook as they were); with the documented opt-in it grades, unconfined.
- ``make course`` says that autograde will refuse, and why.
"""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from instructor.grading.course import write_course

ROOT = Path(__file__).resolve().parents[1]

pytestmark = pytest.mark.notebook_exec
BIN = Path(sys.executable).parent
PS = "ps01"
OPT_IN = "--ConfinedKernelManager.unconfined=True"


def no_bwrap_env(**extra):
    """The environment with a PATH of the venv's programs only: no bwrap on it; and no
    privilege drop either (a root grader would use it: tests/test_grading_privdrop.py)."""
    env = {k: v for k, v in os.environ.items() if not k.endswith("_REQUIRED")}
    return {**env, "PATH": str(BIN), "ROTATIONS_CONFINEMENTS": "bubblewrap", **extra}


def test_the_confinement_probe_names_the_missing_bwrap():
    code = "from instructor.grading.sandbox import confinement_problem as p; print(p())"
    done = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, env=no_bwrap_env(), capture_output=True, text=True
    )
    assert done.stdout.strip() == (
        "bubblewrap: bwrap is not on PATH; privdrop: left out by ROTATIONS_CONFINEMENTS"
    ), done.stdout + done.stderr


NEEDS_BWRAP = """
import pytest

@pytest.mark.confined
def test_inside_the_sandbox():
    pass

@pytest.mark.confined
def test_inside_the_sandbox_too():
    pass

def test_anywhere():
    pass
"""


def _pytest(tmp_path, **extra):
    (tmp_path / "test_tools.py").write_text(NEEDS_BWRAP)
    argv = [sys.executable, "-m", "pytest", "-p", "conftest", "-o", "addopts=", "-q"]
    argv += ["--rootdir", str(tmp_path), "-p", "no:cacheprovider", str(tmp_path)]
    env = no_bwrap_env(PYTHONPATH=str(ROOT), **extra)
    done = subprocess.run(argv, cwd=tmp_path, env=env, capture_output=True, text=True)
    return done.returncode, done.stdout + done.stderr


def test_without_bwrap_only_the_confined_tests_are_skipped_with_one_line_that_says_how(tmp_path):
    code, out = _pytest(tmp_path)
    assert code == 0, out
    assert "1 passed, 2 skipped" in out, out
    (line,) = [ln for ln in out.splitlines() if "tests skipped" in ln]
    assert line.startswith("2 tests skipped: they need bubblewrap (bwrap)"), line
    assert "sudo apt-get install bubblewrap" in line and "CONFINED_REQUIRED=1" in line, line


def test_with_confined_required_a_missing_bwrap_fails_the_confined_tests(tmp_path):
    code, out = _pytest(tmp_path, CONFINED_REQUIRED="1")
    assert code == 1, out
    assert "1 passed, 2 errors" in out, out  # failed in set-up, before the test ran
    assert "CONFINED_REQUIRED=1, but this test needs bubblewrap (bwrap)" in out, out


def nbgrader(args, course, opt_in=False):
    argv = [str(BIN / "nbgrader"), *args, *([OPT_IN] if opt_in else [])]
    done = subprocess.run(
        argv, cwd=course, env=no_bwrap_env(), capture_output=True, text=True, timeout=600
    )
    return done.returncode, done.stdout + done.stderr


def digest(course):
    """Of everything autograde may write: the autograded copies and the gradebook's rows."""
    from nbgrader.api import Gradebook

    h = hashlib.sha256()
    for path in sorted((course / "autograded").rglob("*")):
        if path.is_file():
            h.update(str(path).encode() + path.read_bytes())
    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gb:
        for sub in gb.assignment_submissions(PS):
            h.update(f"{sub.student_id} {sub.score} {sub.max_score}".encode())
    return h.hexdigest()


@pytest.fixture(scope="module")
def course(tmp_path_factory):
    """A course directory, its problem set released and the instructor's copy handed in."""
    root = tmp_path_factory.mktemp("unconfined") / "course"
    write_course(root)
    code, out = nbgrader(["generate_assignment", PS, "--create"], root)
    assert code == 0, out
    for student, kind in (("instructor", "source"), ("blank", "release")):
        shutil.copytree(root / kind / PS, root / "submitted" / student / PS)
    return root


def test_autograde_without_bwrap_refuses_before_touching_anything(course):
    code, out = nbgrader(["autograde", PS, "--create"], course)
    assert code == 1, out
    assert "refusing to run students' code" in out and "bwrap is not on PATH" in out, out
    assert "sudo apt-get install bubblewrap" in out and OPT_IN in out, out
    assert "read the solutions" in out  # the risk, in the message
    assert not (course / "autograded").exists(), "nothing may be half-graded"


def test_opted_in_it_grades_unconfined_and_a_forced_regrade_refused_loses_nothing(course):
    from nbgrader.api import Gradebook

    code, out = nbgrader(["autograde", PS, "--create"], course, opt_in=True)
    assert code == 0, out
    assert "grading UNCONFINED" in out, out
    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gb:
        scores = {s.student_id: (s.score, s.max_score) for s in gb.assignment_submissions(PS)}
    total = scores["instructor"][1]
    assert total > 0 and scores == {"instructor": (total, total), "blank": (0, total)}, scores
    before = digest(course)
    code, out = nbgrader(["autograde", PS, "--force"], course)
    assert code == 1 and "refusing to run students' code" in out, out
    assert digest(course) == before, "a refused re-grade must keep the earlier grades"


def test_make_course_says_autograde_will_refuse(tmp_path):
    done = subprocess.run(
        [sys.executable, "-m", "instructor.grading.course", str(tmp_path / "course")],
        cwd=ROOT,
        env=no_bwrap_env(),
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    assert "`nbgrader autograde` will refuse to run students' code" in done.stderr
    assert "bwrap is not on PATH" in done.stderr and "docs/grading.md" in done.stderr
    config = (tmp_path / "course" / "nbgrader_config.py").read_text()
    assert "# c.ConfinedKernelManager.unconfined = True" in config
