"""The course's nbgrader preprocessors on their own (instructor/grading/preprocessor.py): the
output cap, grading metadata a student added, and a kernel that dies in an answer cell (issue
17)."""

from __future__ import annotations

import json
import subprocess
import sys
import time
from pathlib import Path

import nbformat
import pytest
from grading_helpers import TRUSTED_CONFIG

from instructor.build.student import nbgrader_metadata
from instructor.grading import preprocessor as P

ROOT = Path(__file__).resolve().parents[1]


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
    ex = P.ConfinedExecute(timeout=60, config=TRUSTED_CONFIG)
    nb, _ = ex.preprocess(nb, {"metadata": {"path": str(tmp_path)}})
    assert [o.output_type for o in nb.cells[0].outputs] == ["stream"]
    (note,) = nb.cells[2].outputs
    assert note.output_type == "error" and "kernel died" in note.evalue
    assert "kernel died" in nb.cells[2].metadata[P.ZERO]


def _released_check(gid="ex-check"):
    return _cell(gid, grade=True, locked=True, points=2)


@pytest.mark.parametrize(
    "meta",
    [None, "grade", {"grade": "yes", "points": "1e9"}, {"points": "1e9"}, {"grade_id": ["x"]}],
    ids=["null", "string", "grade_yes_points_string", "points_string", "grade_id_list"],
)
def test_malformed_grading_metadata_dropped_the_student_now_the_cell_is_put_back(meta):
    """metadata.nbgrader null, a string, "grade": "yes" or "points": "1e9" on a check cell:
    GuardCells raised AttributeError (or nbgrader's OverwriteCells "Inconsistent checksums")
    and the student got no grade. Now the released grade cell is named, to be put back (0)."""
    cell = _released_check()
    cell.id = "ex-check"
    if isinstance(meta, dict):
        cell.metadata["nbgrader"].update(meta)
    else:
        cell.metadata["nbgrader"] = meta
    locked = {"ex-check"}
    gid, note = P._repair(cell, RELEASED, locked, GRADES, SOLUTIONS)
    assert gid == "ex-check" and "malformed" in note and "0 points" in note
    assert "nbgrader" not in cell.metadata
    zero = P._zero(RELEASED[gid], gid, GRADES[gid], P.MALFORMED)
    assert "malformed" in zero.metadata[P.ZERO]


def test_malformed_metadata_of_an_answer_cell_gets_its_released_metadata_back():
    cell = _cell("ex-answer", solution=True)
    cell.id = "ex-answer"
    cell.metadata["nbgrader"]["points"] = float("nan")
    gid, note = P._repair(cell, RELEASED, set(), GRADES, SOLUTIONS)
    meta = cell.metadata["nbgrader"]
    assert gid == "ex-answer" and meta["solution"] and not meta["grade"] and "points" not in meta
    assert "malformed" in note


def test_malformed_metadata_of_an_unreleased_cell_is_removed_with_a_note():
    cell = nbformat.v4.new_code_cell("x = 1")
    cell.metadata["nbgrader"] = "grade"
    gid, note = P._repair(cell, RELEASED, set(), GRADES, SOLUTIONS)
    assert gid is None and "plain cell" in note and "nbgrader" not in cell.metadata


def test_well_formed_metadata_is_left_to_the_other_checks():
    for cell in (
        _released_check(),
        _cell("ex-answer", solution=True),
        _cell("mine", grade=True, points=5),
    ):
        before = json.dumps(cell.metadata)
        assert P._repair(cell, RELEASED, set(), GRADES, SOLUTIONS) == (None, None)
        assert json.dumps(cell.metadata) == before


def _confined_run(cells, timeout):
    nb = nbformat.v4.new_notebook(cells=cells)
    nb.metadata["kernelspec"] = {
        "name": "python3",
        "display_name": "Python 3",
        "language": "python",
    }
    ex = P.ConfinedExecute(timeout=timeout, config=TRUSTED_CONFIG)
    return ex.preprocess(nb, {"metadata": {"path": "/tmp"}})[0]


def test_a_loop_that_ignores_sigint_past_the_timeout_is_killed_and_the_student_graded():
    """signal.signal(SIGINT, SIG_IGN); while True: pass — the interrupt at the timeout was
    ignored, nbclient raised CellTimeoutError and nbgrader dropped the student (exit 1)."""
    before = _cell("a-check", grade=True, locked=True, points=1)
    before.source = "print('ran')"
    hang = nbformat.v4.new_code_cell(
        "import signal\nsignal.signal(signal.SIGINT, signal.SIG_IGN)\nwhile True:\n    pass\n"
    )
    after = _cell("b-check", grade=True, locked=True, points=2)
    after.source = "print('after')"
    start = time.monotonic()
    nb = _confined_run([before, hang, after], timeout=3)
    assert time.monotonic() - start < 40
    assert [o.output_type for o in nb.cells[0].outputs] == ["stream"]
    assert "ignored the interrupt" in nb.cells[1].outputs[-1].evalue
    (note,) = nb.cells[2].outputs
    assert note.output_type == "error" and "kernel was stopped" in note.evalue
    assert "0 points" in nb.cells[2].metadata[P.ZERO]


FLOOD = """\
import sys, time
_t0 = time.time()
while time.time() - _t0 < {seconds}:
    sys.stdout.write("y" * 2**20 + "\\n"); sys.stdout.flush(); time.sleep(0.005)
"""

# The grader's peak memory is its VmHWM (/proc/self/status), the high-water mark of its own
# address space. Not ru_maxrss: Linux carries that across execve from the process that started
# it, so under a full pytest run (its parent at 480 MB) it read 484 MB whatever the grader did.
MEMORY = """\
import json, sys
sys.path[:0] = [{root!r}, {root!r} + "/tests"]
import nbformat
from tests.test_grading_preprocessor import _confined_run
cells = [nbformat.v4.new_code_cell({flood!r}), nbformat.v4.new_code_cell("print('after')")]
nb = _confined_run(cells, timeout=60)
status = open("/proc/self/status").read()
hwm_kb = int(status.split("VmHWM:")[1].split()[0])
print(json.dumps({{"outputs": [c.outputs for c in nb.cells], "maxrss_mb": hwm_kb // 1024}}))
"""


def test_flushed_output_flood_is_capped_while_it_arrives_not_held_in_the_grader():
    """20 s of flushed 1 MB writes made the grader hold 1.5 GB before CapOutput cut it (3 such
    cells: 3.2 GB and the student dropped). The grader (a process of its own here, to read
    its peak memory) now keeps about the cap per cell, plus a note."""
    code = MEMORY.format(root=str(ROOT), flood=FLOOD.format(seconds=6))
    proc = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=300, cwd=ROOT
    )
    assert proc.returncode == 0, proc.stderr[-3000:]
    out = json.loads(proc.stdout.splitlines()[-1])
    flood, after = out["outputs"]
    # the kernel may send print's "after" and its newline as two messages on a loaded machine
    assert "".join(o["text"] for o in after if o["output_type"] == "stream") == "after\n"
    note = flood[-1]["text"]
    assert "bytes of output cut while the cell ran" in note, flood
    cut = int(note.split("GradingNote: ")[1].split()[0])
    assert cut > 200_000_000, cut  # the flood did arrive
    assert len(json.dumps(flood)) < 110_000
    assert out["maxrss_mb"] < 400, out["maxrss_mb"]  # before: 1.5 GB for 20 s of flood


def test_output_messages_are_capped_as_they_arrive_and_the_first_errors_kept():
    ex = P.ConfinedExecute(max_output_bytes=10_000)
    ex._start_cell(0)
    cell = nbformat.v4.new_code_cell("x")
    ex.clear_before_next_output = False

    def msg(kind, **content):
        return {
            "msg_type": kind,
            "content": content,
            "parent_header": {"msg_id": "m"},
            "header": {"msg_type": kind},
            "metadata": {},
            "buffers": [],
        }

    for _ in range(50):
        ex.process_message(msg("stream", name="stdout", text="x" * 1000), cell, 0)
        ex.process_message(
            msg("display_data", data={"text/plain": "y" * 1000}, metadata={}), cell, 0
        )
    ex.process_message(
        msg("error", ename="E", evalue="v" * 10**6, traceback=["t" * 10**6]), cell, 0
    )
    assert sum(len(json.dumps(o)) for o in cell.outputs) < 20_000
    errors = [o for o in cell.outputs if o.output_type == "error"]
    assert len(errors) == 1 and len(errors[0].evalue) <= 2_000
    assert ex._cut > 80_000


def test_the_kernel_is_killed_after_the_last_cell_with_every_output_kept_issue36(monkeypatch):
    """A graceful stop (a shutdown request, then the kernel's own teardown) cost about 0.35 s of
    CPU and 0.6 s of waiting per submission (issue 36): the kernel is now killed once the last
    cell is done, and every output of every cell, the last one's too, is kept whole."""
    stops = []
    original = P.ConfinedKernelManager.shutdown_kernel

    async def shutdown(self, now=False, restart=False):
        await original(self, now=now, restart=restart)
        stops.append((now, await self.is_alive()))

    monkeypatch.setattr(P.ConfinedKernelManager, "shutdown_kernel", shutdown)
    many = nbformat.v4.new_code_cell("for i in range(3000):\n    print(i)")
    last = nbformat.v4.new_code_cell("import atexit\natexit.register(print, 'bye')\nprint('last')")
    nb = _confined_run([many, last], timeout=60)
    text = "".join(o.text for o in nb.cells[0].outputs if o.output_type == "stream")
    assert text == "".join(f"{i}\n" for i in range(3000))
    assert "".join(o.text for o in nb.cells[1].outputs) == "last\n"
    assert stops == [(True, False)]  # killed, and gone


def _processes_with(argv):
    """The pids whose command line is ``argv`` (Linux's /proc)."""
    want = "\0".join(argv).encode() + b"\0"
    found = []
    for entry in Path("/proc").iterdir():
        try:
            if entry.name.isdigit() and (entry / "cmdline").read_bytes() == want:
                found.append(int(entry.name))
        except OSError:
            continue
    return found


@pytest.mark.confined
def test_a_process_the_last_cell_left_in_a_session_of_its_own_dies_with_the_killed_kernel():
    """Killed without its graceful stop (issue 36), the confined kernel still leaves nothing
    running: a child in a new session (out of the kernel's process group, which the kill
    reaches) ends with bubblewrap's PID namespace or privdrop's kill of the kernel's uid."""
    argv = ["sleep", f"{300 + time.time() % 1:.6f}"]  # one no other process has
    code = f"import subprocess\nsubprocess.Popen({argv!r}, start_new_session=True)\nprint('ok')"
    nb = _confined_run([nbformat.v4.new_code_cell(code)], timeout=60)
    assert "".join(o.text for o in nb.cells[0].outputs) == "ok\n"
    deadline = time.monotonic() + 10
    while _processes_with(argv) and time.monotonic() < deadline:
        time.sleep(0.1)
    assert _processes_with(argv) == []
