"""Tests of instructor.build.student: student copies of the notebooks.

Synthetic notebooks (built with nbformat in tmp_path) cover each rule; the marker rule is compared
with the real nbgrader's preprocessors; the failure modes (a hard link to a source, a directory
in the way, a full disk, a failure or an interrupt half-way) are produced for real; the real
notebooks in notebooks/ are converted too, and, in the last section (slow: it starts Jupyter
kernels), their student copies are executed to show that exactly the solution cells raise
NotImplementedError and exactly the autograder test cells fail.
"""

import base64
import copy
import errno
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from jupyter_client.manager import start_new_kernel
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook, new_output, new_raw_cell

from instructor.build import student as student_module
from instructor.build.student import (
    CELL_RUN_STATE,
    CODE_STUB,
    MARKDOWN_STUB,
    StudentNotebookError,
    main,
    make_student_notebooks,
    nbgrader_metadata,
    student_notebook,
)

NOTEBOOKS = Path(__file__).resolve().parent.parent / "notebooks"
PROBLEM_SETS = NOTEBOOKS.parent / "problem_sets"
KERNELSPEC = {"name": "python3", "display_name": "Python 3", "language": "python"}
PNG = base64.b64encode(b"\x89PNG\r\n\x1a\n solution figure").decode()
WIDGET_STATE = {
    "application/vnd.jupyter.widget-state+json": {
        "state": {"abc": {"model_name": "ImageModel", "state": {"value": PNG}}},
        "version_major": 2,
        "version_minor": 0,
    }
}


def nbgrader(grade_id, solution=True, grade=False, task=False, points=None):
    return nbgrader_metadata(
        grade_id, solution=solution, grade=grade, locked=not solution, task=task, points=points
    )


def executed(cell, count):
    cell.execution_count = count
    cell.outputs = [
        new_output("stream", name="stdout", text="solution output 42\n"),
        new_output("execute_result", data={"text/plain": "'secret'"}, execution_count=count),
    ]
    cell.metadata["execution"] = {"iopub.status.busy": "2026-01-01T00:00:00.000Z"}
    cell.metadata["scrolled"] = True
    return cell


def synthetic_notebook():
    """A notebook with every kind of cell the tool must handle."""
    cells = [
        new_markdown_cell("# Chapter\nIntro text."),
        executed(new_code_cell("import math\nfrom course_lib.exercises import check"), 1),
        executed(
            new_code_cell(
                "answer_hat_squared = None\n"
                "### BEGIN SOLUTION\n"
                "answer_hat_squared = SECRET_ONE\n"
                "helper = SECRET_TWO\n"
                "### END SOLUTION\n"
                "print('after the region')",
                metadata=nbgrader("hat-squared-solution"),
            ),
            2,
        ),
        executed(
            new_code_cell(
                'result = check("hat_squared", answer_hat_squared)\n'
                "assert result.ok, result.message\n"
                "### BEGIN HIDDEN TESTS\n"
                "assert SECRET_HIDDEN\n"
                "### END HIDDEN TESTS",
                metadata=nbgrader("hat-squared-check", solution=False, grade=True, points=2),
            ),
            3,
        ),
        new_code_cell(
            "def f(v):\n"
            "    total = 0\n"
            "    ### BEGIN SOLUTION\n"
            "    total = SECRET_THREE\n"
            "    ### END SOLUTION\n"
            "    return total\n"
            "\n"
            "answer_va_example = None\n"
            "# BEGIN SOLUTION\n"
            "answer_va_example = SECRET_FOUR\n"
            "# END SOLUTION",
            metadata=nbgrader("two-regions"),
        ),
        new_markdown_cell(
            "Explain why, with a sketch:\n\n### BEGIN SOLUTION\nBecause SECRET_FIVE.\n"
            "![sketch](attachment:solution.png)\n### END SOLUTION\n\n"
            "![given](attachment:given.png)\nEnd.",
            metadata=nbgrader("written-answer", grade=True, points=1),
            attachments={
                "solution.png": {"image/png": PNG},
                "given.png": {"image/png": "R0lGODlh"},
            },
        ),
        new_code_cell("answer_rodrigues = SECRET_SIX", metadata=nbgrader("whole-cell")),
        new_markdown_cell(
            "A figure the students need:\n![axes](attachment:axes.png)",
            attachments={"axes.png": {"image/png": "R0lGODlh"}},
        ),
        new_raw_cell("raw text stays"),
    ]
    return new_notebook(
        cells=cells,
        metadata={"kernelspec": KERNELSPEC, "custom": {"keep": [1, 2, 3]}, "widgets": WIDGET_STATE},
    )


def write(nb, path):
    path.parent.mkdir(parents=True, exist_ok=True)
    nbformat.write(nb, path)
    return path


def snapshot(directory):
    """Every file under ``directory`` with its bytes (and the directories, to see leftovers)."""
    return {
        p: (p.read_bytes() if p.is_file() else None) for p in sorted(Path(directory).rglob("*"))
    }


def without_run_state(metadata):
    return {k: v for k, v in metadata.items() if k not in CELL_RUN_STATE}


@pytest.fixture
def src(tmp_path):
    d = tmp_path / "src"
    write(synthetic_notebook(), d / "a_chapter.ipynb")
    plain = new_notebook(cells=[executed(new_code_cell("print(1)"), 7)])
    write(plain, d / "b_plain.ipynb")
    write(synthetic_notebook(), d / ".ipynb_checkpoints" / "a_chapter-checkpoint.ipynb")
    return d


# --------------------------------------------------------------------------------- conversion


def test_marked_regions_become_stubs_and_everything_else_is_kept(src, tmp_path):
    original = nbformat.read(src / "a_chapter.ipynb", as_version=4)
    written = make_student_notebooks(src, tmp_path / "out")
    assert [p.name for p in written] == ["a_chapter.ipynb", "b_plain.ipynb"]
    student = nbformat.read(tmp_path / "out" / "a_chapter.ipynb", as_version=4)

    assert student.metadata == {"kernelspec": KERNELSPEC, "custom": {"keep": [1, 2, 3]}}
    assert len(student.cells) == len(original.cells)
    for old, new in zip(original.cells, student.cells, strict=True):
        assert new.id == old.id and new.cell_type == old.cell_type
        assert new.metadata == without_run_state(old.metadata)
        if new.cell_type == "code":
            assert new.outputs == [] and new.execution_count is None

    code = student.cells[2].source.split("\n")
    assert code == [
        "answer_hat_squared = None",
        CODE_STUB,
        "raise NotImplementedError(\"write your solution to exercise 'hat_squared' here\")",
        "print('after the region')",
    ]
    assert student.cells[3].source == (
        'result = check("hat_squared", answer_hat_squared)\nassert result.ok, result.message'
    )
    two = student.cells[4].source.split("\n")
    assert two[:3] == ["def f(v):", "    total = 0", "    " + CODE_STUB]
    assert two[3].startswith("    raise NotImplementedError(")
    assert two[4:7] == ["    return total", "", "answer_va_example = None"]
    assert two[7] == CODE_STUB and two[8].startswith("raise NotImplementedError(")
    assert student.cells[5].source == (
        f"Explain why, with a sketch:\n\n{MARKDOWN_STUB}\n\n![given](attachment:given.png)\nEnd."
    )
    assert list(student.cells[5].attachments) == ["given.png"]  # the solution's image is gone
    whole = student.cells[6].source
    assert whole.startswith(CODE_STUB) and "NotImplementedError" in whole
    for i in (0, 1, 7, 8):
        assert student.cells[i].source == original.cells[i].source
    assert student.cells[7].attachments == original.cells[7].attachments
    text = (tmp_path / "out" / "a_chapter.ipynb").read_text()
    for leak in ("SECRET", "solution output 42", "'secret'", PNG, "widget-state", "iopub"):
        assert leak not in text


def test_stubs_compile_and_raise_not_implemented_error():
    student = student_notebook(synthetic_notebook())
    namespace = {}
    with pytest.raises(NotImplementedError, match="hat_squared"):
        exec(student.cells[2].source, namespace)
    assert namespace["answer_hat_squared"] is None  # assigned before the raise
    compile(student.cells[4].source, "<cell>", "exec")


def test_student_notebook_does_not_modify_its_argument():
    nb = synthetic_notebook()
    before = copy.deepcopy(nb)
    student_notebook(nb)
    assert nb == before


def test_sources_are_untouched(src, tmp_path):
    before = snapshot(src)
    make_student_notebooks(src, tmp_path / "out")
    make_student_notebooks(src, tmp_path / "out", force=True)
    assert snapshot(src) == before


def test_checkpoints_are_skipped_and_no_staging_folder_is_left(src, tmp_path):
    make_student_notebooks(src, tmp_path / "out")
    make_student_notebooks(src, tmp_path / "out", force=True)
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == [
        "a_chapter.ipynb",
        "b_plain.ipynb",
    ]


# --------------------------------------------------------------------------------- nbgrader's rule


def one_cell(cell):
    return new_notebook(cells=[cell], metadata={"kernelspec": KERNELSPEC})


@pytest.mark.parametrize(
    "cell",
    [
        new_markdown_cell("Write your answer between `### BEGIN SOLUTION` and `### END SOLUTION`."),
        new_code_cell("x = 1  # the BEGIN SOLUTION marker opens a region"),
        new_raw_cell("BEGIN SOLUTIONS are marked like this"),
    ],
    ids=["markdown-prose", "code-comment", "raw-longer-word"],
)
def test_a_marker_word_anywhere_in_a_line_is_a_marker_as_for_nbgrader(cell):
    with pytest.raises(StudentNotebookError, match="for a marker, even in prose"):
        student_notebook(one_cell(cell))


@pytest.mark.parametrize(
    "text", ["begin solution (lower case)", "BEGIN  SOLUTION (two spaces)", "BEGIN_SOLUTION"]
)
def test_near_misses_are_not_markers(text):
    assert student_notebook(one_cell(new_markdown_cell(text))).cells[0].source == text


def test_a_marker_in_mid_line_of_a_solution_cell_opens_the_region_with_its_indent():
    cell = new_code_cell(
        "a = 1\n    x = 2  # BEGIN SOLUTION here\nsecret\nEND SOLUTION\nb", metadata=nbgrader("g")
    )
    lines = student_notebook(one_cell(cell)).cells[0].source.split("\n")
    assert lines[0] == "a = 1" and lines[1] == "    " + CODE_STUB and lines[-1] == "b"
    assert "secret" not in lines and len(lines) == 4


@pytest.mark.parametrize("words, flag", [("HIDDEN TESTS", "grade"), ("MARK SCHEME", "task")])
def test_hidden_tests_and_mark_schemes_are_removed_and_need_their_cell_kind(words, flag):
    source = f"visible\n### BEGIN {words}\nsecret\n### END {words}\nafter"
    cell = new_code_cell(source, metadata=nbgrader("g", solution=False, **{flag: True}))
    assert student_notebook(one_cell(cell)).cells[0].source == "visible\nafter"
    plain = new_code_cell(source)
    with pytest.raises(StudentNotebookError, match=f"'BEGIN {words}'.*\"{flag}\": true"):
        student_notebook(one_cell(plain))


def test_other_kernel_languages_are_refused():
    nb = one_cell(new_code_cell("1"))
    nb.metadata.kernelspec = {"name": "ir", "display_name": "R", "language": "R"}
    with pytest.raises(StudentNotebookError, match="kernel language 'R'"):
        student_notebook(nb, "r.ipynb")


# Real nbgrader (``pip install nbgrader``): the three generate_assignment passes that change the
# source, in its order. Ours must give the same source (up to the stub's message naming the
# exercise) or refuse where it refuses; the only case where ours alone refuses is a closing
# marker outside a region, which nbgrader deletes without a word.


def nbgrader_release(nb):
    preprocessors = pytest.importorskip("nbgrader.preprocessors")
    nb, resources = copy.deepcopy(nb), {}
    for cls in (
        preprocessors.ClearSolutions,
        preprocessors.ClearHiddenTests,
        preprocessors.ClearMarkScheme,
    ):
        nb, resources = cls().preprocess(nb, resources)
    return nb


_OUR_RAISE = re.compile(r'raise NotImplementedError\("write your solution to .* here"\)')


def assert_agrees_with_nbgrader(nb):
    try:
        theirs = nbgrader_release(nb)
    except RuntimeError:
        theirs = None
    try:
        ours = student_notebook(nb)
    except StudentNotebookError as err:
        if theirs is not None:  # ours is stricter only about a stray closing marker ...
            stray = re.search(
                r": cell (\d+) .*: END (?:SOLUTION|HIDDEN TESTS|MARK SCHEME) "
                r"without BEGIN .* at line (\d+)",
                str(err),
            )
            assert stray, err
            cell, line = int(stray.group(1)), int(stray.group(2))
            without = copy.deepcopy(nb)
            lines = without.cells[cell].source.split("\n")
            without.cells[cell].source = "\n".join(lines[: line - 1] + lines[line:])
            assert nbgrader_release(without) == theirs  # ... which nbgrader just deletes
        return "refused"
    assert theirs is not None, "nbgrader refuses a notebook that instructor.build.student accepts"
    for mine, reference in zip(ours.cells, theirs.cells, strict=True):
        assert _OUR_RAISE.sub("raise NotImplementedError()", mine.source) == reference.source
    return "same"


LINES = [
    "x = 1",
    "    y = 2",
    "\tz = 3",
    "",
    "answer_e = None",
    "### BEGIN SOLUTION",
    "    # BEGIN SOLUTION",
    "### END SOLUTION",
    "  # END SOLUTION",
    "text BEGIN SOLUTION text",
    "BEGIN SOLUTIONS",
    "begin solution",
    "BEGIN  SOLUTION",
    "### BEGIN HIDDEN TESTS",
    "### END HIDDEN TESTS",
    "BEGIN MARK SCHEME",
    "END MARK SCHEME",
    "BEGIN SOLUTION END SOLUTION",
    "## END HIDDEN TESTS and BEGIN SOLUTION",
]


@st.composite
def graded_cells(draw, index):
    source = "\n".join(draw(st.lists(st.sampled_from(LINES), max_size=7)))
    kind = draw(st.sampled_from(["code", "markdown", "raw"]))
    flags = draw(
        st.none()
        | st.fixed_dictionaries(
            {"solution": st.booleans(), "grade": st.booleans(), "task": st.booleans()}
        )
    )
    metadata = {} if flags is None else nbgrader(f"cell-{index}", **flags)
    make = {"code": new_code_cell, "markdown": new_markdown_cell, "raw": new_raw_cell}[kind]
    return make(source, metadata=metadata)


@settings(max_examples=300)
@given(st.integers(1, 3).flatmap(lambda n: st.tuples(*[graded_cells(i) for i in range(n)])))
def test_marker_rule_is_nbgraders_on_random_cells(cells):
    nb = new_notebook(cells=list(cells), metadata={"kernelspec": KERNELSPEC})
    assert_agrees_with_nbgrader(nb)


@pytest.mark.parametrize(
    "source",
    [
        "text BEGIN SOLUTION text\nx = 1\n### END SOLUTION\nx = 1\n### END HIDDEN TESTS",
        "text BEGIN SOLUTION text\nx = 1\n### END SOLUTION\n### END HIDDEN TESTS",
    ],
)
def test_regression_a_stray_marker_after_a_solution_was_reported_at_the_wrong_line(source):
    # Found by the property test above: the line of the stray END HIDDEN TESTS was counted in
    # the cell with its solution already replaced by the stub, not in the instructor's cell.
    cell = new_code_cell(source, metadata=nbgrader("cell-0", solution=True))
    nb = new_notebook(cells=[cell], metadata={"kernelspec": KERNELSPEC})
    with pytest.raises(StudentNotebookError, match=f"at line {source.count(chr(10)) + 1};"):
        student_notebook(nb)
    assert assert_agrees_with_nbgrader(nb) == "refused"


def test_marker_rule_is_nbgraders_on_the_synthetic_and_the_real_notebooks():
    assert assert_agrees_with_nbgrader(synthetic_notebook()) == "same"
    for path in sorted([*NOTEBOOKS.glob("*.ipynb"), *PROBLEM_SETS.glob("*.ipynb")]):
        assert_agrees_with_nbgrader(nbformat.read(path, as_version=4))


# --------------------------------------------------------------------------------- refusals


def test_out_dir_equal_to_or_inside_src_is_refused(src):
    before = snapshot(src)
    for out in (src, src / "student", src / "." / "deeper" / ".."):
        with pytest.raises(StudentNotebookError, match="source directory"):
            make_student_notebooks(src, out)
    assert snapshot(src) == before


def test_out_dir_reaching_into_src_through_a_symlink_is_refused(src, tmp_path):
    link = tmp_path / "link"
    link.symlink_to(src, target_is_directory=True)
    before = snapshot(src)
    with pytest.raises(StudentNotebookError, match="inside the source directory"):
        make_student_notebooks(src, link / "student")
    with pytest.raises(StudentNotebookError, match="is the source directory"):
        make_student_notebooks(src, link)
    assert snapshot(src) == before


@pytest.mark.parametrize("link", ["symlink", "hardlink", "hardlink-other-name"])
def test_output_file_linked_to_a_source_is_refused_and_nothing_is_written(src, tmp_path, link):
    out = tmp_path / "out"
    out.mkdir()
    target = out / ("b_plain.ipynb" if link == "hardlink-other-name" else "a_chapter.ipynb")
    if link == "symlink":
        target.symlink_to(src / "a_chapter.ipynb")
    else:
        os.link(src / "a_chapter.ipynb", target)
    before, before_out = snapshot(src), snapshot(out)
    with pytest.raises(StudentNotebookError, match="is a link to a file of the source directory"):
        make_student_notebooks(src, out, force=True)
    assert snapshot(src) == before and snapshot(out) == before_out


def test_issue_reproduction_hard_link_to_a_source_with_force(src, tmp_path, capsys):
    out = tmp_path / "out"
    out.mkdir()
    os.link(src / "a_chapter.ipynb", out / "a_chapter.ipynb")
    before = snapshot(src)
    assert main([str(src), str(out), "--force"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "is a link to a file of the source directory" in err
    assert snapshot(src) == before
    assert sorted(p.name for p in out.iterdir()) == ["a_chapter.ipynb"]


def test_force_replaces_a_hard_link_to_a_file_outside_src_without_writing_through_it(src, tmp_path):
    mine = tmp_path / "elsewhere" / "my_notes.ipynb"
    mine.parent.mkdir()
    mine.write_text("the instructor's own file")
    out = tmp_path / "out"
    out.mkdir()
    os.link(mine, out / "a_chapter.ipynb")
    make_student_notebooks(src, out, force=True)
    assert mine.read_text() == "the instructor's own file"
    assert "YOUR CODE HERE" in (out / "a_chapter.ipynb").read_text()


def test_existing_files_are_refused_without_force(src, tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "b_plain.ipynb").write_text("old")
    with pytest.raises(StudentNotebookError, match="exists; use --force"):
        make_student_notebooks(src, out)
    assert sorted(p.name for p in out.iterdir()) == ["b_plain.ipynb"]  # nothing written
    assert (out / "b_plain.ipynb").read_text() == "old"
    make_student_notebooks(src, out, force=True)
    assert nbformat.read(out / "b_plain.ipynb", as_version=4).cells[0].outputs == []


def test_missing_or_empty_source_directory_is_refused(tmp_path):
    with pytest.raises(StudentNotebookError, match="does not exist"):
        make_student_notebooks(tmp_path / "nope", tmp_path / "out")
    (tmp_path / "empty").mkdir()
    with pytest.raises(StudentNotebookError, match="no notebooks"):
        make_student_notebooks(tmp_path / "empty", tmp_path / "out")


BAD_CELLS = {
    "begin_without_end": (
        new_code_cell("a = 1\n### BEGIN SOLUTION\nb = 2", metadata=nbgrader("g")),
        "BEGIN SOLUTION at line 2 without END SOLUTION",
    ),
    "end_without_begin": (
        new_code_cell("a = 1\n### END SOLUTION", metadata=nbgrader("g")),
        "END SOLUTION without BEGIN SOLUTION at line 2",
    ),
    "nested_begin": (
        new_code_cell(
            "### BEGIN SOLUTION\n### BEGIN SOLUTION\nb = 2\n### END SOLUTION",
            metadata=nbgrader("g"),
        ),
        "nested BEGIN SOLUTION at line 2",
    ),
    "markers_without_metadata": (
        new_code_cell("### BEGIN SOLUTION\nb = 2\n### END SOLUTION"),
        "no nbgrader metadata",
    ),
    "markdown_begin_without_end": (
        new_markdown_cell("### BEGIN SOLUTION\nwords", metadata=nbgrader("g")),
        "without END SOLUTION",
    ),
    "hidden_tests_without_end": (
        new_code_cell(
            "### BEGIN HIDDEN TESTS\nassert x", metadata=nbgrader("g", solution=False, grade=True)
        ),
        "BEGIN HIDDEN TESTS at line 1 without END HIDDEN TESTS",
    ),
}


@pytest.mark.parametrize("kind", list(BAD_CELLS))
def test_malformed_markers_are_refused_and_nothing_is_written(tmp_path, kind):
    bad_cell, fragment = BAD_CELLS[kind]
    src = tmp_path / "src"
    write(synthetic_notebook(), src / "a_good.ipynb")  # converted first, in memory only
    bad = new_notebook(cells=[new_markdown_cell("intro"), bad_cell])
    write(bad, src / "b_bad.ipynb")
    with pytest.raises(StudentNotebookError) as info:
        make_student_notebooks(src, tmp_path / "out")
    message = str(info.value)
    assert fragment in message
    assert "b_bad.ipynb" in message and "cell 1" in message and f"id {bad_cell.id}" in message
    assert not (tmp_path / "out").exists()


def test_repeated_grade_ids_are_refused(tmp_path):
    nb = synthetic_notebook()
    nb.cells[4].metadata = nbgrader("hat-squared-solution")
    write(nb, tmp_path / "src" / "dup.ipynb")
    with pytest.raises(StudentNotebookError, match="grade_id 'hat-squared-solution' repeats"):
        make_student_notebooks(tmp_path / "src", tmp_path / "out")
    assert not (tmp_path / "out").exists()


# --------------------------------------------------------------------------------- failures
# "Writes nothing, one line on stderr, exit status 2": each failure is produced for real where
# the machine allows it, and OUT_DIR (fresh, or holding an older copy that --force would
# replace) is left exactly as it was.


def big_notebook():
    """About 200 kB of student copy: more than the small filesystem below holds."""
    return new_notebook(
        cells=[new_markdown_cell("long text " * 20_000)], metadata={"kernelspec": KERNELSPEC}
    )


def assert_fails_cleanly(src, out, capsys, fragment, force=True):
    before = snapshot(out) if out.exists() else None
    assert main([str(src), str(out)] + (["--force"] if force else [])) == 2
    err = capsys.readouterr().err
    assert err.startswith("instructor.build.student: error: ") and err.count("\n") == 1, err
    assert fragment in err and "Traceback" not in err
    assert (snapshot(out) if out.exists() else None) == before


def test_a_directory_in_the_way_writes_nothing(src, tmp_path, capsys):
    out = tmp_path / "out"
    (out / "b_plain.ipynb").mkdir(parents=True)
    (out / "a_chapter.ipynb").write_text("older copy")
    assert_fails_cleanly(src, out, capsys, "b_plain.ipynb is a directory in the way")


def try_small_tmpfs(mountpoint):
    """Mount a 64 KiB tmpfs at ``mountpoint``; False where this process may not mount."""
    if not hasattr(os, "geteuid") or os.geteuid() != 0 or shutil.which("mount") is None:
        return False
    done = subprocess.run(
        ["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", str(mountpoint)], capture_output=True
    )
    return done.returncode == 0


@pytest.fixture
def small_disk(tmp_path, monkeypatch):
    """A directory on a 64 KiB filesystem: a real tmpfs when mounting is allowed (as root), else
    a write that stops at 64 KiB with ENOSPC, as the kernel's does."""
    mountpoint = tmp_path / "small"
    mountpoint.mkdir()
    if try_small_tmpfs(mountpoint):
        yield mountpoint
        subprocess.run(["umount", str(mountpoint)], check=True)
        return

    real = student_module._write_file

    def write_until_full(path, data):
        if len(data) <= 65_536:
            return real(path, data)
        real(path, data[:65_536])
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(path))

    monkeypatch.setattr(student_module, "_write_file", write_until_full)
    yield mountpoint


@pytest.mark.parametrize("existing", [False, True], ids=["fresh-out", "older-copy-in-out"])
def test_a_full_disk_writes_nothing(src, small_disk, capsys, existing):
    write(big_notebook(), src / "c_big.ipynb")
    out = small_disk / "out"
    if existing:
        out.mkdir()
        (out / "a_chapter.ipynb").write_text("older copy")
    assert_fails_cleanly(src, out, capsys, "No space left on device")
    assert not out.exists() or [p.name for p in out.iterdir()] == ["a_chapter.ipynb"]
    (src / "c_big.ipynb").unlink()  # without it, the copies fit
    assert main([str(src), str(out), "--force"]) == 0
    assert sorted(p.name for p in out.iterdir()) == ["a_chapter.ipynb", "b_plain.ipynb"]


def failing_rename(monkeypatch, fail_at, exc):
    """Let call number ``fail_at`` (from 0) of ``os.rename`` raise ``exc``, the others work."""
    real, calls = os.rename, []

    def rename(a, b):
        calls.append((a, b))
        if len(calls) == fail_at + 1:
            raise exc
        return real(a, b)

    monkeypatch.setattr(os, "rename", rename)
    return calls


@pytest.mark.parametrize("fail_at", [0, 1, 2, 3])
@pytest.mark.parametrize(
    "exc",
    [OSError(errno.EIO, "Input/output error"), KeyboardInterrupt()],
    ids=["io-error", "ctrl-c"],
)
def test_a_failure_while_moving_into_place_puts_the_old_files_back(
    src, tmp_path, capsys, monkeypatch, fail_at, exc
):
    out = tmp_path / "out"
    out.mkdir()
    (out / "a_chapter.ipynb").write_text("older copy of a")
    (out / "b_plain.ipynb").write_text("older copy of b")
    (out / "mine.txt").write_text("not ours")
    before = snapshot(out)
    calls = failing_rename(monkeypatch, fail_at, exc)
    fragment = "Input/output error" if isinstance(exc, OSError) else "interrupted"
    assert_fails_cleanly(src, out, capsys, fragment)
    assert len(calls) > fail_at and snapshot(out) == before


def test_an_interrupt_while_writing_leaves_nothing(src, tmp_path, capsys, monkeypatch):
    real = student_module._write_file
    count = []

    def interrupted(path, data):
        count.append(path)
        if len(count) == 2:
            raise KeyboardInterrupt
        return real(path, data)

    monkeypatch.setattr(student_module, "_write_file", interrupted)
    assert_fails_cleanly(src, tmp_path / "deeper" / "out", capsys, "interrupted")
    assert not (tmp_path / "deeper").exists()


# --------------------------------------------------------------------------------- command line


# ------------------------------------------------------------ swapped folders, file system trouble


def test_regression_swapped_folders_never_replace_instructor_notebooks(src, tmp_path, capsys):
    """The issue's typo: `instructor.build.student build/student notebooks --force` (folders
    swapped)."""
    copies = tmp_path / "copies"
    make_student_notebooks(src, copies)
    assert_fails_cleanly(copies, src, capsys, "holds solution regions")
    assert "BEGIN SOLUTION" in (src / "a_chapter.ipynb").read_text()


def test_a_symlink_loop_as_output_is_one_line(src, tmp_path, capsys):
    (tmp_path / "loop1").symlink_to(tmp_path / "loop2")
    (tmp_path / "loop2").symlink_to(tmp_path / "loop1")
    for out in (tmp_path / "loop1", tmp_path / "loop1" / "deeper"):
        assert main([str(src), str(out), "--force"]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "symlink loop" in err and "Traceback" not in err


def test_a_file_where_a_folder_should_be_is_one_line(src, tmp_path, capsys):
    (tmp_path / "afile").write_text("not a folder")
    for out, fragment in [("afile", "is not a directory"), ("afile/sub", "Not a directory")]:
        assert main([str(src), str(tmp_path / out)]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and fragment in err and "Traceback" not in err
    assert (tmp_path / "afile").read_text() == "not a folder"


def test_no_permission_is_one_line(src, tmp_path, capsys, monkeypatch):
    def refuse(path, *args, **kwargs):
        raise PermissionError(errno.EACCES, "Permission denied", str(path))

    monkeypatch.setattr(Path, "mkdir", refuse)  # root ignores modes: refuse as the OS would
    assert_fails_cleanly(src, tmp_path / "out", capsys, "Permission denied")


def test_keep_outputs_keeps_the_reading_part_and_clears_from_the_first_graded_cell():
    nb = synthetic_notebook()
    nb.cells.insert(1, executed(new_code_cell("print('reading')"), 1))
    copy_ = student_notebook(nb, keep_outputs=True)
    assert copy_.cells[1].outputs and copy_.cells[1].execution_count == 1
    first = next(i for i, c in enumerate(nb.cells) if c.metadata.get("nbgrader"))
    assert all(not c.get("outputs") for c in copy_.cells[first:])
    assert sum(bool(c.get("outputs")) for c in copy_.cells) == first - 1  # the two before it
    assert not student_notebook(nb).cells[1].outputs


def run_cli(*args):
    return subprocess.run(
        [sys.executable, "-m", "instructor.build.student", *map(str, args)],
        capture_output=True,
        text=True,
        timeout=120,
    )


def test_cli_writes_copies_and_exits_zero(src, tmp_path):
    result = run_cli(src, tmp_path / "out")
    assert result.returncode == 0, result.stderr
    assert "wrote 2 student notebook(s)" in result.stdout
    assert (tmp_path / "out" / "a_chapter.ipynb").exists()


def test_cli_errors_exit_two_with_one_line_and_no_traceback(src, tmp_path):
    out = tmp_path / "out"
    make_student_notebooks(src, out)
    for args, fragment in [
        ((src, out), "exists; use --force"),
        ((src, src / "inner"), "inside the source directory"),
    ]:
        result = run_cli(*args)
        assert result.returncode == 2
        assert result.stderr.count("\n") == 1 and fragment in result.stderr
        assert "Traceback" not in result.stderr
        assert result.stderr.startswith("instructor.build.student: error: ")
    assert run_cli(src, out, "--force").returncode == 0


def test_cli_unbalanced_markers_exit_two_and_write_nothing(tmp_path):
    bad = new_notebook(cells=[new_code_cell("### BEGIN SOLUTION\nx = 1", metadata=nbgrader("g"))])
    write(bad, tmp_path / "src" / "bad.ipynb")
    result = run_cli(tmp_path / "src", tmp_path / "out")
    assert result.returncode == 2 and "bad.ipynb: cell 0" in result.stderr
    assert "Traceback" not in result.stderr
    assert not (tmp_path / "out").exists()


# --------------------------------------------------------------------------------- real notebooks

REAL = sorted(p for p in PROBLEM_SETS.glob("*.ipynb") if "BEGIN SOLUTION" in p.read_text())


def cells_with(nb, flag, cell_type=None):
    return {
        i
        for i, c in enumerate(nb.cells)
        if c.get("metadata", {}).get("nbgrader", {}).get(flag) and cell_type in (None, c.cell_type)
    }


def region_lines(source):
    """(lines inside any marked region, lines outside them), by nbgrader's substring rule."""
    inside, secret, kept = False, [], []
    for line in source.split("\n"):
        if any(f"BEGIN {w}" in line for w in ("SOLUTION", "HIDDEN TESTS", "MARK SCHEME")):
            inside = True
        elif any(f"END {w}" in line for w in ("SOLUTION", "HIDDEN TESTS", "MARK SCHEME")):
            inside = False
        else:
            (secret if inside else kept).append(line)
    return secret, kept


def test_real_notebooks_have_solution_cells():
    # The problem sets carry the exercises (the chapters none); the tests below need them.
    assert len(REAL) >= 3, [p.name for p in PROBLEM_SETS.glob("*.ipynb")]


@pytest.fixture(scope="module")
def real_copies(tmp_path_factory):
    before = snapshot(PROBLEM_SETS)
    out = tmp_path_factory.mktemp("student")
    make_student_notebooks(PROBLEM_SETS, out)
    assert snapshot(PROBLEM_SETS) == before  # the sources are untouched
    return out


@pytest.mark.parametrize("path", REAL, ids=lambda p: p.name)
def test_real_notebook_student_copy_has_no_solution_and_no_output(path, real_copies):
    original = nbformat.read(path, as_version=4)
    student = nbformat.read(real_copies / path.name, as_version=4)
    assert cells_with(original, "solution"), "no solution cell"
    assert "widgets" not in student.metadata
    assert len(student.cells) == len(original.cells)
    for old, new in zip(original.cells, student.cells, strict=True):
        assert new.id == old.id and new.metadata == without_run_state(old.metadata)
        if new.cell_type == "code":
            assert new.outputs == [] and new.execution_count is None
        secret, kept = region_lines(old.source)
        for line in secret:
            if line.strip() and line not in kept:
                assert line not in new.source.split("\n"), (old.id, line)
        is_solution = old.get("metadata", {}).get("nbgrader", {}).get("solution")
        if not secret and not is_solution:
            assert new.source == old.source
        if is_solution:
            assert "attachment:" not in new.source and not new.get("attachments")
        for words in ("SOLUTION", "HIDDEN TESTS", "MARK SCHEME"):
            assert f"BEGIN {words}" not in new.source and f"END {words}" not in new.source


# --------------------------------------------------------------------------------- execution
# SLOW (a few seconds per notebook): starts a python3 kernel of this environment per notebook.
# Cells are sent one by one through a blocking kernel client, the way nbval does it: nbclient's
# asynchronous client can sit on an execute reply after an ipywidgets cell until its timeout
# (jupyter/nbclient#312), which once cost minutes here.


def run_cells(nb, cwd, timeout=120):
    """Execute the code cells of ``nb`` in a fresh kernel; return {cell index: error name}."""
    km, kc = start_new_kernel(kernel_name="python3", cwd=str(cwd))
    errors = {}
    try:
        for i, cell in enumerate(nb.cells):
            if cell.cell_type != "code":
                continue
            msg_id = kc.execute(cell.source, allow_stdin=False)
            reply = kc.get_shell_msg(timeout=timeout)
            while reply["parent_header"].get("msg_id") != msg_id:
                reply = kc.get_shell_msg(timeout=timeout)
            if reply["content"]["status"] == "error":
                errors[i] = reply["content"]["ename"]
            while True:  # drain this cell's output up to the kernel going idle
                msg = kc.get_iopub_msg(timeout=timeout)
                if (
                    msg["parent_header"].get("msg_id") == msg_id
                    and msg["msg_type"] == "status"
                    and msg["content"]["execution_state"] == "idle"
                ):
                    break
    finally:
        kc.stop_channels()
        km.shutdown_kernel(now=True)
    return errors


@pytest.mark.notebook_exec
@pytest.mark.parametrize("path", REAL, ids=lambda p: p.name)
def test_executing_real_student_notebook_fails_exactly_in_solution_and_grade_cells(
    path, real_copies
):
    nb = nbformat.read(real_copies / path.name, as_version=4)
    errors = run_cells(nb, real_copies)
    solutions = cells_with(nb, "solution", "code")
    grades = cells_with(nb, "grade", "code") - solutions  # nbgrader's autograder tests
    seen = {i: (e, nb.cells[i].id) for i, e in errors.items()}
    assert set(errors) == solutions | grades, seen
    assert {errors[i] for i in solutions} == {"NotImplementedError"}, seen
    assert "NotImplementedError" not in {errors[i] for i in grades}, seen
