"""A mid-term release reaching a hub student who already edited a chapter (nbgitpuller 1.3.0).

The student edition (instructor/release/student_edition.py) is the "public repository"; a student's
home gets it with nbgitpuller's own puller (what the hub link runs), solves an exercise of problem
set 1 and re-runs it (new execution counts all through the file). Then the course releases a
correction: a sentence in that same problem set, a sentence in chapter 02, and a change to the
very lines the student edited. The student clicks the link again. What happens
(docs/release.md says it):

* nbgitpuller commits the student's work and merges the release with ``git merge -Xours``:
  line by line, so the correction of the untouched chapter arrives, and so does the correction
  in the edited chapter, wherever the student did not change the same lines;
* where both changed the same lines, the student's lines win and the release's change to them
  is dropped without a word; the notebook stays a valid notebook;
* a notebook the student deleted comes back as the release has it.
"""

import importlib.util
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest

from instructor.release import student_edition

ROOT = Path(__file__).resolve().parents[1]


assert importlib.util.find_spec("nbgitpuller"), "nbgitpuller is pinned in environment.txt"

# a problem set (the student's work), and a chapter the student only read; the exercises were
# at the end of the chapters before the problem sets had notebooks of their own
PS1 = next(
    f"{folder}/{name}"
    for folder, name in [
        ("problem_sets", "ps01_rigid_body_motion.ipynb"),
        ("notebooks", "01_rigid_body_motion.ipynb"),
    ]
    if (ROOT / folder / name).is_file()
)
CH2 = "notebooks/02_rotations.ipynb"


PULL = (
    "import sys; from nbgitpuller.pull import GitPuller; "
    "print(''.join(GitPuller(sys.argv[1], sys.argv[2], branch=sys.argv[3]).pull()))"
)


def _pull(upstream, home):
    """What the hub link runs, in a process of its own (it leaves pipes to the GC: warnings)."""
    run = subprocess.run(
        [sys.executable, "-c", PULL, f"file://{upstream}", str(home), student_edition.BRANCH],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert run.returncode == 0, run.stderr
    return run.stdout


def _edit(path, change):
    nb = nbformat.read(path, as_version=4)
    change(nb)
    nbformat.write(nb, path)


def _stub_index(nb):
    return next(i for i, c in enumerate(nb.cells) if "raise NotImplementedError(" in c.source)


def _student_solves_and_reruns(nb):
    i = _stub_index(nb)
    lines = nb.cells[
        i
    ].source.splitlines()  # [P = parameters(...) (with variants),] answer_x = None
    numbers = lines[:1] if lines[0].startswith("P = parameters(") else []
    prefill = lines[len(numbers)]
    assert prefill.endswith(" = None"), prefill
    mine = prefill.replace("None", "[1, 2, 3]  # MINE")
    nb.cells[i].source = "\n".join([*numbers, prefill, mine])
    for cell in nb.cells:
        if cell.cell_type == "code" and cell.execution_count:
            cell.execution_count += 100


def _add_sentence(index_of, text):
    def change(nb):
        nb.cells[index_of(nb)].source += f"\n\n{text}"

    return change


def _markdown(k):
    return lambda nb: [i for i, c in enumerate(nb.cells) if c.cell_type == "markdown"][k]


@pytest.fixture
def hub(tmp_path):
    upstream, home = tmp_path / "upstream", tmp_path / "home" / "rotations-course"
    student_edition.build_student_edition(ROOT, upstream)
    _pull(upstream, home)
    return upstream, home


def _release(upstream, *changes):
    for path, change in changes:
        _edit(upstream / path, change)
    ident = ["-c", "user.name=course", "-c", "user.email=course@example.invalid"]
    subprocess.run(
        ["git", "-C", str(upstream), *ident, "commit", "-qam", "mid-term release"], check=True
    )


def test_a_mid_term_release_merges_into_a_students_edited_chapter(hub):
    upstream, home = hub
    _edit(home / PS1, _student_solves_and_reruns)

    def upstream_edits_the_students_lines(nb):
        i = _stub_index(nb)
        nb.cells[i].source = nb.cells[i].source.replace("# YOUR CODE HERE", "# RELEASE 2")

    _release(
        upstream,
        (PS1, _add_sentence(_markdown(-1), "RELEASE 2 FIXES PROBLEM SET 1.")),
        (CH2, _add_sentence(_markdown(2), "RELEASE 2 FIXES CHAPTER 2.")),
        (PS1, upstream_edits_the_students_lines),
    )
    log = _pull(upstream, home)
    assert "Automatic commit by nbgitpuller" in log and "merge -Xours" in log

    merged = nbformat.read(home / PS1, as_version=4)
    nbformat.validate(merged)  # still a notebook
    text = (home / PS1).read_text()
    assert " = [1, 2, 3]  # MINE" in text  # the student's work stays
    assert "RELEASE 2 FIXES PROBLEM SET 1." in text  # a correction elsewhere in it arrives
    assert "# RELEASE 2" not in text  # the release's change to the student's lines: dropped
    assert "RELEASE 2 FIXES CHAPTER 2." in (home / CH2).read_text()


def test_a_deleted_notebook_comes_back_as_released(hub):
    upstream, home = hub
    (home / CH2).unlink()
    _release(upstream, (CH2, _add_sentence(_markdown(2), "RELEASE 2 FIXES CHAPTER 2.")))
    _pull(upstream, home)
    assert "RELEASE 2 FIXES CHAPTER 2." in (home / CH2).read_text()
