"""The README's walk-through of adding an exercise, done end to end on a copy of the repository.

1. a new exercise in the bank (``course_lib/exercise_bank/ch01.py``), 2. its worked solution in
``instructor/answers/ch01.py``, 3. the commands of ``make exercises`` (fingerprints, then
``instructor/build/sync_exercises.py``). The copy's problem set then holds the new exercise after
the others, the instructor's hidden test of exercise 1.1 is still there, and in a fresh Python the
new check accepts the worked solution and refuses a blank answer and a wrong one.
"""

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[1]
HIDDEN = (
    "### BEGIN HIDDEN TESTS\nassert answer_coords_by_projection is not None\n### END HIDDEN TESTS"
)

BANK_ENTRY = """
EXERCISES.append(
    Exercise(
        name="vector_length",
        chapter=1,
        number=8,
        level="warm-up",
        title="The length of a vector",
        statement=r"What is the length $\\lVert v\\rVert$ of the vector $v = (3,\\ 4,\\ 12)$?",
        answer=Value(shape=()),
        tip="The length is the square root of v · v.",
    )
)
"""
SOLUTION_ENTRY = '''
SOLUTIONS["vector_length"] = """\\
v = np.array([3, 4, 12])
answer_vector_length = np.sqrt(v @ v)  # 13"""
'''


def _python(copy, *args):
    env = {**os.environ, "PYTHONPATH": str(copy)}
    return subprocess.run(
        [sys.executable, *args], cwd=copy, env=env, capture_output=True, text=True, timeout=600
    )


@pytest.fixture(scope="module")
def copy(tmp_path_factory):
    copy = tmp_path_factory.mktemp("repo")
    for name in ("course_lib", "instructor", "notebooks", "problem_sets"):
        shutil.copytree(ROOT / name, copy / name, ignore=shutil.ignore_patterns("__pycache__"))
    ps = copy / "problem_sets" / "ps01_rigid_body_motion.ipynb"
    nb = nbformat.read(ps, as_version=4)
    cell = next(c for c in nb.cells if c.id == "coords_by_projection-check")
    cell.source += "\n" + HIDDEN
    nbformat.write(nb, ps)
    with open(copy / "course_lib" / "exercise_bank" / "ch01.py", "a") as f:
        f.write(BANK_ENTRY)
    with open(copy / "instructor" / "answers" / "ch01.py", "a") as f:
        f.write(SOLUTION_ENTRY)
    for step in (
        ["-m", "instructor.build.exercise_fingerprints"],
        ["-m", "instructor.build.sync_exercises", "1"],
    ):
        run = _python(copy, *step)
        assert run.returncode == 0, run.stdout + run.stderr
    return copy


def test_the_problem_set_gets_the_exercise_and_keeps_the_hidden_test(copy):
    nb = nbformat.read(copy / "problem_sets" / "ps01_rigid_body_motion.ipynb", as_version=4)
    ids = [c.id for c in nb.cells]
    assert ids[-3:] == ["vector_length-statement", "vector_length-answer", "vector_length-check"]
    assert "### Exercise 1.8 (warm-up, 1 point): The length of a vector" in nb.cells[-3].source
    assert nb.cells[-2].metadata["nbgrader"]["solution"]
    assert nb.cells[-1].metadata["nbgrader"]["points"] == 1
    hidden = next(c for c in nb.cells if c.id == "coords_by_projection-check")
    assert hidden.source.endswith(HIDDEN)
    chapter = nbformat.read(copy / "notebooks" / "01_rigid_body_motion.ipynb", as_version=4)
    assert "8 exercises, 15 points (3 warm-up, 3 core, 2 challenge)" in chapter.cells[-1].source


def test_the_new_check_accepts_the_solution_and_refuses_blank_and_wrong_answers(copy):
    script = (
        "import json, numpy as np\n"
        "from course_lib.exercises import check\n"
        "ns = {'np': np}\n"
        "from instructor.build.exercise_fingerprints import solutions\n"
        "exec(solutions(1)[0]['vector_length'], ns)\n"
        "out = [check('vector_length', a) for a in (ns['answer_vector_length'], None, 12.0)]\n"
        "print(json.dumps([[r.ok, r.status] for r in out]))\n"
    )
    run = _python(copy, "-c", script)
    assert run.returncode == 0, run.stdout + run.stderr
    assert json.loads(run.stdout.strip().splitlines()[-1]) == [
        [True, "correct"],
        [False, "no answer"],
        [False, "wrong"],
    ]
