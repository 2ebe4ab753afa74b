"""The course's nbgrader preprocessors on their own (grader/preprocessor.py): the output cap,
grading metadata a student added, and a kernel that dies in an answer cell (issue 17)."""

from __future__ import annotations

import shutil
import sys
import time
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
from course_lib.student import nbgrader_metadata  # noqa: E402
from grader import preprocessor as P  # noqa: E402


def _stream(text):
    return nbformat.v4.new_output("stream", name="stdout", text=text)


def test_200_megabytes_of_stdout_are_cut_to_the_cap_and_the_error_is_kept_regression_issue17():
    """200 x 1 MB of stdout gave a 191 MB autograded notebook and feedback."""
    cell = nbformat.v4.new_code_cell("for _ in range(200): print('x' * 10**6)")
    cell.outputs = [_stream("x" * 10**6 + "\n") for _ in range(200)]
    cell.outputs.append(
        nbformat.v4.new_output("error", ename="E", evalue="v" * 10**6, traceback=["t" * 10**6])
    )
    start = time.perf_counter()
    cell, _ = P.CapOutput().preprocess_cell(cell, {}, 0)
    assert time.perf_counter() - start < 1.0
    size = len(nbformat.writes(nbformat.v4.new_notebook(cells=[cell])))
    assert size < 120_000, size
    assert [o.output_type for o in cell.outputs][-1] == "stream"
    assert "bytes of output cut" in cell.outputs[-1].text
    errors = [o for o in cell.outputs if o.output_type == "error"]
    assert len(errors) == 1 and len(errors[0].evalue) <= 2_000  # the cell still scores 0


def test_small_outputs_are_left_alone():
    cell = nbformat.v4.new_code_cell("print(1)")
    cell.outputs = [_stream("1\n"), nbformat.v4.new_output("display_data", data={"a": "b"})]
    before = nbformat.writes(nbformat.v4.new_notebook(cells=[cell]))
    P.CapOutput().preprocess_cell(cell, {}, 0)
    assert nbformat.writes(nbformat.v4.new_notebook(cells=[cell])) == before


def _cell(gid, **kw):
    cell = nbformat.v4.new_code_cell("x = 1")
    cell.metadata = nbgrader_metadata(gid, **kw)
    return cell


GRADES, SOLUTIONS = {"ex-check": 2}, {"ex-answer"}
RELEASED = {"ex-check": ("code", ""), "ex-answer": ("code", "")}


def test_a_grade_cell_the_student_added_becomes_a_plain_cell_with_a_note():
    cell = _cell("my-free-points", grade=True, locked=True, points=100)
    note = P._unreleased(cell, GRADES, SOLUTIONS, RELEASED)
    assert "nbgrader" not in cell.metadata and "0 points" in note and "a grade cell" in note


def test_an_answer_cell_turned_into_a_graded_cell_keeps_only_its_answer_role():
    cell = _cell("ex-answer", grade=True, solution=True, points=100)
    note = P._unreleased(cell, GRADES, SOLUTIONS, RELEASED)
    meta = cell.metadata["nbgrader"]
    assert meta["solution"] and not meta["grade"] and "points" not in meta and note


def test_released_cells_are_left_alone():
    for cell in (_cell("ex-check", grade=True, locked=True, points=2), _cell("ex-answer")):
        cell.metadata["nbgrader"]["solution"] = cell.metadata["nbgrader"]["grade_id"] == "ex-answer"
        before = dict(cell.metadata["nbgrader"])
        assert P._unreleased(cell, GRADES, SOLUTIONS, RELEASED) is None
        assert cell.metadata["nbgrader"] == before


def test_os_exit_in_an_answer_cell_gives_the_grade_cells_after_it_0_with_a_note(tmp_path):
    """The kernel died and nbgrader left the student without any grade."""
    if shutil.which("bwrap") is None:
        pytest.fail("bubblewrap is needed for the confined kernel: apt-get install -y bubblewrap")
    before = _cell("a-check", grade=True, locked=True, points=1)
    before.source = "print('ran')"
    killer = nbformat.v4.new_code_cell("import os; os._exit(0)")
    after = _cell("b-check", grade=True, locked=True, points=2)
    nb = nbformat.v4.new_notebook(cells=[before, killer, after])
    nb.metadata["kernelspec"] = {
        "name": "python3",
        "display_name": "Python 3",
        "language": "python",
    }
    ex = P.ConfinedExecute(timeout=60)
    nb, _ = ex.preprocess(nb, {"metadata": {"path": str(tmp_path)}})
    assert [o.output_type for o in nb.cells[0].outputs] == ["stream"]
    (note,) = nb.cells[2].outputs
    assert note.output_type == "error" and "kernel died" in note.evalue
    assert "kernel died" in nb.cells[2].metadata[P.ZERO]
