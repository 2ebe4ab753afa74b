"""The intake on nbgrader's paths (issue 32): ``nbgrader collect`` from the exchange and
``nbgrader autograde`` of ``submitted/`` with the course's configuration
(instructor/grading/intake.py,
instructor/grading/collect.py, ConfinedExporter). A submission that is not a regular file of one
name inside the student's folder was graded as the student's own notebook: full marks for a link
to the instructor's solved copy. Real nbgrader, marked ``slow_grading`` (CI's make test-slow).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest
from grading_helpers import TRUSTED_AUTOGRADE

from instructor.grading.course import write_course
from instructor.grading.intake import NOTE

ROOT = Path(__file__).resolve().parents[1]


pytestmark = [pytest.mark.slow_grading, pytest.mark.notebook_exec]
NBGRADER = Path(sys.executable).with_name("nbgrader")
PS = "ps01"
TOTAL = 14
STAMP = "2026-01-01 00:00:00.000000 UTC"


def run(args, cwd):
    env = {**os.environ, "PATH": f"{NBGRADER.parent}{os.pathsep}{os.environ.get('PATH', '')}"}
    done = subprocess.run(
        [str(NBGRADER), *args], cwd=cwd, capture_output=True, text=True, timeout=900, env=env
    )
    return done.returncode, done.stdout + done.stderr


def _sparse(path, size=2 * 2**30):
    with open(path, "wb") as f:
        f.truncate(size)


def _hand_in(folder, name, make):
    folder.mkdir(parents=True, exist_ok=True)
    make(folder / name)
    (folder / "timestamp.txt").write_text(STAMP)


def test_collect_and_autograde_read_only_regular_files_inside_each_submission(tmp_path):
    course = tmp_path / "course"
    write_course(course)
    code, out = run(["generate_assignment", PS, "--create"], course)
    assert code == 0, out
    solved = next((course / "source" / PS).glob("*.ipynb"))
    name = solved.name
    blank = (course / "release" / PS / name).read_bytes()
    sub = course / "submitted"

    # the exchange: alice's notebook is a link to the instructor's solved copy
    inbound = tmp_path / "exchange" / "rotations" / "inbound"
    _hand_in(inbound / f"alice+{PS}+{STAMP}", name, lambda p: p.symlink_to(solved))
    _hand_in(inbound / f"bob+{PS}+{STAMP}", name, lambda p: p.write_bytes(blank))
    (inbound / f"bob+{PS}+{STAMP}" / "data.txt").symlink_to("/etc/passwd")
    code, out = run(["collect", PS, f"--Exchange.root={tmp_path / 'exchange'}"], course)
    assert code == 0, out
    placeholder = json.loads((sub / "alice" / PS / name).read_text())
    assert "symbolic link" in placeholder["metadata"][NOTE], placeholder
    assert (sub / "bob" / PS / name).read_bytes() == blank
    assert not (sub / "bob" / PS / "data.txt").exists() and "refused" in out

    # submitted/ by hand: every other kind of file (and /etc/shadow beside a solved copy)
    _hand_in(sub / "a_solved" / PS, name, lambda p: p.write_bytes(solved.read_bytes()))
    _hand_in(sub / "c_link" / PS, name, lambda p: p.symlink_to(solved))
    (sub / "d_linked_folder").symlink_to(sub / "a_solved")
    _hand_in(sub / "e_fifo" / PS, name, os.mkfifo)
    _hand_in(sub / "f_not_json" / PS, name, lambda p: p.write_bytes(b"\x00\xffnot {"))
    _hand_in(sub / "g_2gb" / PS, name, _sparse)
    _hand_in(sub / "h_folder" / PS, name, lambda p: p.mkdir())
    _hand_in(sub / "i_hard_link" / PS, name, lambda p: os.link(solved, p))
    (sub / "a_solved" / PS / "notes.txt").symlink_to("/etc/shadow")

    code, out = run(["autograde", PS, "--create", *TRUSTED_AUTOGRADE], course)
    assert code == 0, out[-4000:]
    from nbgrader.api import Gradebook

    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gb:
        got = {s.student.id: s.score for s in gb.find_assignment(PS).submissions}
    assert got.pop("a_solved") == TOTAL, got  # nobody else's file changed it
    assert got == dict.fromkeys(got, 0.0) and len(got) == 9, got
    notes = {
        "alice": "symbolic link",
        "c_link": "symbolic link",
        "d_linked_folder": "symbolic link",
        "e_fifo": "named pipe",
        "f_not_json": "not a readable notebook",
        "g_2gb": "over the limit of 20 MB",
        "h_folder": "a folder",
        "i_hard_link": "hard link",
    }
    for student, said in notes.items():
        graded = nbformat.read(course / "autograded" / student / PS / name, as_version=4)
        errors = [o.evalue for c in graded.cells for o in c.get("outputs", []) if "evalue" in o]
        assert errors and all(said in e for e in errors), (student, errors[:2])
    assert not (course / "autograded" / "a_solved" / PS / "notes.txt").exists()
    assert "root:" not in out
