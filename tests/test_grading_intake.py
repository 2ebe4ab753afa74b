"""The intake of a submission (instructor/grading/intake.py, instructor/grading/collect.py, issue
32): only a regular file of one name inside the submission folder is read, its size checked before
reading; the Gradescope runner's choice of notebook and its notes for bad input, without nbgrader
runs (those are in test_grading_gradescope.py and test_grading_intake_nbgrader.py)."""

from __future__ import annotations

import json
import logging
import os
import subprocess
import sys
from pathlib import Path

import pytest

from instructor.grading import gradescope_run as G
from instructor.grading import intake
from instructor.grading.intake import Refused, parse, pick, read_inside

ROOT = Path(__file__).resolve().parents[1]


NB = json.dumps({"cells": [], "metadata": {}, "nbformat": 4, "nbformat_minor": 5}).encode()
EXPECTED = "ps01_rigid_body_motion.ipynb"


def refused(path, folder):
    with pytest.raises(Refused) as err:
        read_inside(path, folder)
    return str(err.value)


@pytest.fixture
def sub(tmp_path):
    folder = tmp_path / "submission"
    folder.mkdir()
    secret = tmp_path / "source"
    secret.mkdir()
    (secret / EXPECTED).write_bytes(NB.replace(b"[]", b'["SOLVED"]', 1))
    return folder


def test_a_regular_notebook_is_read(sub):
    (sub / EXPECTED).write_bytes(NB)
    assert read_inside(sub / EXPECTED, sub) == NB


def test_a_notebook_symlinked_to_the_instructors_source_is_refused_regression_issue32(sub):
    """Full marks without one answer: the link to the solved copy was graded as the student's."""
    (sub / EXPECTED).symlink_to(sub.parent / "source" / EXPECTED)
    note = refused(sub / EXPECTED, sub)
    assert "symbolic link" in note and "SOLVED" not in note


def test_symlinks_to_system_files_and_through_symlinked_folders_are_refused(sub):
    (sub / "shadow.ipynb").symlink_to("/etc/passwd")
    assert "symbolic link" in refused(sub / "shadow.ipynb", sub)
    (sub / "inner").symlink_to(sub.parent / "source")
    assert "symbolic link" in refused(sub / "inner" / EXPECTED, sub)
    assert "outside" in refused(sub / ".." / "source" / EXPECTED, sub)


def test_a_hard_link_is_refused(sub):
    os.link(sub.parent / "source" / EXPECTED, sub / EXPECTED)
    assert "hard link" in refused(sub / EXPECTED, sub)


def test_a_fifo_a_folder_and_an_empty_file_are_refused_without_blocking(sub):
    os.mkfifo(sub / "pipe.ipynb")  # opening it for reading would wait for a writer
    assert "named pipe" in refused(sub / "pipe.ipynb", sub)
    (sub / "folder.ipynb").mkdir()
    assert "a folder" in refused(sub / "folder.ipynb", sub)
    (sub / "empty.ipynb").write_bytes(b"")
    assert "empty" in refused(sub / "empty.ipynb", sub)


@pytest.mark.skipif(os.geteuid() != 0, reason="mknod of a device needs root")
def test_a_device_is_refused(sub):
    os.mknod(sub / "zero.ipynb", 0o600 | 0o020000, os.makedev(1, 5))  # /dev/zero
    assert "a device" in refused(sub / "zero.ipynb", sub)


def test_kinds_are_named():
    import stat

    assert intake._kind(stat.S_IFCHR) == "a device" and intake._kind(stat.S_IFSOCK) == "a socket"


MEMORY = """\
import sys
from instructor.grading.intake import Refused, read_inside
try:
    read_inside({path!r}, {folder!r})
    print("READ")
except Refused as err:
    print(err)
status = open("/proc/self/status").read()
print(int(status.split("VmHWM:")[1].split()[0]) // 1024)
"""


def test_a_2_gb_file_is_refused_before_reading_regression_issue32(sub):
    """A 2 GB upload was read whole into memory (10.5 GB peak) before any cap."""
    path = sub / EXPECTED
    with open(path, "wb") as f:
        f.truncate(2 * 2**30)  # sparse: no disk used
    code = MEMORY.format(root=str(ROOT), path=str(path), folder=str(sub))
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    note, peak_mb = done.stdout.strip().splitlines()
    assert "2048 MB, over the limit of 20 MB" in note, done.stdout + done.stderr
    assert int(peak_mb) < 100, peak_mb  # VmHWM: the interpreter alone is about 10 MB


def test_not_json_and_json_that_is_not_a_notebook():
    with pytest.raises(Refused, match="not a readable notebook"):
        parse(b"\x00\xffnot a notebook {", "x.ipynb")
    with pytest.raises(Refused, match="not a notebook"):
        parse(b"[1, 2]", "x.ipynb")
    assert parse(NB, "x.ipynb")["cells"] == []


def test_pick_the_notebook_of_a_submission_folder(sub):
    with pytest.raises(Refused, match="no notebook"):
        pick(sub, EXPECTED)
    (sub / "bomb.zip").write_bytes(b"PK\x03\x04" + b"\0" * 100)
    with pytest.raises(Refused, match="A .zip is not unpacked"):
        pick(sub, EXPECTED)
    (sub / "mon devoir é.ipynb").write_bytes(NB)
    name, note = pick(sub, EXPECTED)
    assert name == "mon devoir é.ipynb" and EXPECTED in note
    (sub / "copy (2).ipynb").write_bytes(NB)
    with pytest.raises(Refused, match="2 notebooks") as err:
        pick(sub, EXPECTED)
    assert "mon devoir é.ipynb" in str(err.value) and EXPECTED in str(err.value)
    (sub / EXPECTED).write_bytes(NB)
    name, note = pick(sub, EXPECTED)
    assert name == EXPECTED and "not graded" in note and "copy (2).ipynb" in note


def test_names_in_notes_are_shown_with_control_characters_escaped():
    assert intake.shown("a\nb\x1b[31m") == "a\\nb\\x1b[31m"
    assert len(intake.shown("x" * 500)) == 80


@pytest.mark.parametrize(
    ("sid", "begins"),
    [
        ("../../etc", "etc-"),
        ("a/../b", "a_.._b-"),
        ("..", ""),
        ("/", ""),
        ("José Ñandú", "Jos___and-"),
        ("x" * 200, "x" * 80 + "-"),
    ],
)
def test_a_student_id_is_never_a_path(sid, begins):
    """A changed id keeps its safe letters and gets 8 hex digits of its hash (two ids that
    differ only in unsafe characters stay two folders)."""
    got = G.student_id({"users": [{"sid": sid}]})
    assert got.startswith(begins) and len(got) == len(begins) + 8
    assert "/" not in got and got not in (".", "..") and not got.startswith(".")
    assert got == G.student_id({"users": [{"sid": sid}]})


@pytest.fixture
def top(tmp_path, monkeypatch):
    """A Gradescope root whose submission is refused before any nbgrader run."""
    monkeypatch.setattr(G, "assignment", lambda source=None: ("ps01", EXPECTED))
    monkeypatch.setenv(G.ROOT_ENV, str(tmp_path))
    (tmp_path / "submission").mkdir()
    meta = {"users": [{"sid": "s1"}]}
    (tmp_path / "submission_metadata.json").write_text(json.dumps(meta))
    return tmp_path


def _results(top):
    results = json.loads((top / "results" / "results.json").read_text())
    assert results["score"] == 0.0 and results["output_format"] == "text"
    assert results["tests"][0]["status"] == "failed"
    return results["output"]


@pytest.mark.parametrize(
    ("make", "said"),
    [
        (lambda s: None, "no notebook"),
        (lambda s: (s / EXPECTED).write_bytes(b""), "empty"),
        (lambda s: (s / EXPECTED).write_bytes(b"\x00\xff{"), "not a readable notebook"),
        (lambda s: (s / EXPECTED).symlink_to("/etc/passwd"), "symbolic link"),
        (lambda s: os.mkfifo(s / EXPECTED), "named pipe"),
        (lambda s: (s / EXPECTED).mkdir(), "a folder"),
        (lambda s: [(s / n).write_bytes(NB) for n in ("a.ipynb", "b.ipynb")], "2 notebooks"),
    ],
    ids=["none", "empty", "not-json", "symlink", "fifo", "folder", "two"],
)
def test_a_students_bad_submission_gets_0_and_a_note_without_running_anything(top, make, said):
    make(top / "submission")
    assert G.main(["grade"]) == 0
    assert said in _results(top)
    assert not (top / "course").exists()  # nothing was copied, nbgrader never ran


def test_the_graders_own_fault_exits_1_and_writes_no_results(top, monkeypatch, capsys):
    """A run that failed for the grader's reasons recorded a 0 for the student."""
    (top / "submission" / EXPECTED).write_bytes(NB)
    (top / "results").mkdir()
    (top / "results" / "results.json").write_text('{"score": 14.0}')  # a stale one
    monkeypatch.setattr(G, "confinement", lambda: ("bubblewrap", "bwrap is not on PATH"))
    assert G.main(["grade"]) == 1
    assert not (top / "results" / "results.json").exists()
    assert "bwrap is not on PATH" in capsys.readouterr().err


def test_the_zip_of_a_set_holds_only_its_chapters_solutions():
    from instructor.grading import gradescope

    for ps, chapter in (("ps01", "ch01"), ("ps04", "ch04")):
        names = gradescope.members(ps)
        assert [n for n in names if n.startswith("instructor/answers/ch")] == [
            f"instructor/answers/{chapter}.py"
        ]
        # beside it, the loader and the draws' shared code only: no answer in either
        assert {n for n in names if n.startswith("instructor/answers/")} == {
            f"instructor/answers/{chapter}.py",
            "instructor/answers/__init__.py",
            "instructor/answers/common.py",
        }
        assert [n for n in names if n.startswith("problem_sets/")] == [
            f"problem_sets/{p.name}" for p in (ROOT / "problem_sets").glob(f"{ps}_*.ipynb")
        ]


def test_collect_copies_only_regular_files_inside_the_students_folder(tmp_path):
    """nbgrader's collect (shutil.copytree) copied a symlink's target into submitted/."""
    from instructor.grading.collect import copy_submission

    src, dest = tmp_path / "inbound" / "alice+ps01+2026", tmp_path / "submitted" / "alice"
    src.mkdir(parents=True)
    (tmp_path / "source.ipynb").write_bytes(NB.replace(b"[]", b'["SOLVED"]', 1))
    (src / EXPECTED).symlink_to(tmp_path / "source.ipynb")
    (src / "data.txt").symlink_to("/etc/passwd")
    (src / "notes.txt").write_text("mine")
    os.mkfifo(src / "pipe")
    (src / "sub").mkdir()
    (src / "sub" / "more.txt").write_text("also mine")
    copy_submission(str(src), str(dest), logging.getLogger("test"))
    placeholder = json.loads((dest / EXPECTED).read_text())
    assert placeholder["cells"] == [] and "symbolic link" in placeholder["metadata"][intake.NOTE]
    assert sorted(p.name for p in dest.rglob("*")) == sorted(
        [EXPECTED, "more.txt", "notes.txt", "sub"]
    )
    assert (dest / "sub" / "more.txt").read_text() == "also mine"


def test_cells_past_the_notebooks_time_budget_are_not_run_and_get_0_regression_issue32():
    """A notebook's run was bounded only per cell: 10,000 cells ran 308 s."""
    import nbformat
    from grading_helpers import TRUSTED_CONFIG

    from instructor.build.student import nbgrader_metadata
    from instructor.grading import preprocessor as P

    def grade_cell(gid, source):
        cell = nbformat.v4.new_code_cell(source)
        cell.metadata = nbgrader_metadata(gid, grade=True, locked=True, points=1)
        return cell

    cells = [grade_cell("a-check", "print('ran')"), nbformat.v4.new_code_cell("import time")]
    cells += [nbformat.v4.new_code_cell("time.sleep(2.5)"), grade_cell("b-check", "print(1)")]
    nb = nbformat.v4.new_notebook(cells=cells)
    nb.metadata["kernelspec"] = {
        "name": "python3",
        "display_name": "Python 3",
        "language": "python",
    }
    ex = P.ConfinedExecute(timeout=30, notebook_budget=2, config=TRUSTED_CONFIG)
    nb, _ = ex.preprocess(nb, {"metadata": {"path": "/tmp"}})
    assert [o.output_type for o in nb.cells[0].outputs] == ["stream"]  # before: kept
    assert nb.cells[2].execution_count is not None  # started within the budget: ran
    (note,) = nb.cells[3].outputs
    assert "time budget of 2 s" in note.evalue and nb.cells[3].metadata[P.ZERO]


@pytest.mark.parametrize(
    ("solved", "blank", "said"),
    [(13.0, 0.0, "the solved copy got 13 of 14"), (14.0, 2.0, "the blank copy got 2 of 14")],
)
def test_the_self_test_fails_the_build_unless_full_marks_and_0(
    tmp_path, monkeypatch, solved, blank, said
):
    """setup.sh's last step: a broken image never records a 0 (nor full marks) for a student."""
    course = tmp_path / "course"
    for folder in ("source", "release"):
        (course / folder / "ps01").mkdir(parents=True)
        (course / folder / "ps01" / EXPECTED).write_bytes(NB)
    monkeypatch.setattr(G, "assignment", lambda source=None: ("ps01", EXPECTED))
    got = iter([solved, blank])

    def fake_grade(top, course=None):
        assert (Path(top) / "submission" / EXPECTED).read_bytes() == NB
        score = next(got)
        return {"score": score, "tests": [{"max_score": 14.0}], "output": ""}

    monkeypatch.setattr(G, "grade", fake_grade)
    with pytest.raises(G.GraderFault, match=said):
        G.selftest(tmp_path)
    monkeypatch.setenv(G.ROOT_ENV, str(tmp_path))
    got = iter([solved, blank])
    assert G.main(["selftest"]) == 1


def test_nbgrader_reads_through_the_intake_and_a_students_own_refusal_flag_is_dropped(sub):
    """The refusal note lives in notebook metadata: a student who writes it into a notebook
    with cells must not have the kernel skipped (it would only cost them points, but the note
    shown must be the intake's)."""
    nb = json.loads(NB)
    nb["cells"] = [{"cell_type": "markdown", "id": "m", "metadata": {}, "source": "hi"}]
    nb["metadata"][intake.NOTE] = "0 points: <b>fake</b>"
    (sub / EXPECTED).write_text(json.dumps(nb))
    got, resources = intake.nbgrader_read(str(sub / EXPECTED), None, None)
    assert intake.NOTE not in got.metadata and resources["metadata"]["name"] == EXPECTED[:-6]
    (sub / "link.ipynb").symlink_to(sub / EXPECTED)
    got, _ = intake.nbgrader_read(str(sub / "link.ipynb"), None, None)
    assert got.cells == [] and "symbolic link" in got.metadata[intake.NOTE]


def test_collect_refuses_a_student_folder_that_is_a_link(tmp_path, caplog):
    """inbound/alice+ps01+... -> the instructor's source/ folder: nothing is collected."""
    from nbgrader.auth import Authenticator
    from nbgrader.coursedir import CourseDirectory

    from instructor.grading.collect import SafeCollect

    source = tmp_path / "source" / "ps01"
    source.mkdir(parents=True)
    (source / EXPECTED).write_bytes(NB)
    link = tmp_path / "inbound" / "alice+ps01+2026"
    link.parent.mkdir()
    link.symlink_to(source)
    collect = SafeCollect(
        coursedir=CourseDirectory(root=str(tmp_path)), authenticator=Authenticator()
    )
    with caplog.at_level(logging.WARNING):
        collect.do_copy(str(link), str(tmp_path / "submitted" / "alice" / "ps01"))
    assert not (tmp_path / "submitted").exists() and "not collected" in caplog.text


def test_regression_json_nested_too_deep_is_refused_not_a_crash():
    """Red team: 200,000 nested lists (400 kB) raised RecursionError past parse: nbgrader
    dropped the student, Gradescope blamed the grader (no results.json)."""
    data = b"[" * 200_000 + b"]" * 200_000
    with pytest.raises(intake.Refused, match="nested too deep"):
        intake.parse(data, "deep.ipynb")


def test_regression_collect_refuses_a_folder_that_claims_another_student(tmp_path):
    """Red team: mallory made inbound/alice+ps01+2099-... holding a blank copy; nbgrader
    collected it as alice's work, and its time beat every later submission of alice's."""
    import datetime

    from instructor.grading.collect import claim_problem

    now = datetime.datetime(2026, 12, 7, tzinfo=datetime.timezone.utc)
    folder = tmp_path / "daemon+ps01+x"
    folder.mkdir()
    os.chown(folder, 65534, 65534)  # made by nobody, claims daemon (uid 1)
    assert "not by 'daemon'" in claim_problem(str(folder), "daemon", now, now)
    assert claim_problem(str(folder), "nobody", now, now) is None
    later = now + datetime.timedelta(days=365 * 70)
    assert "later than now" in claim_problem(str(folder), "nobody", later, now)
    assert claim_problem(str(folder), "no-such-user-here", now, now) is None  # cannot check
