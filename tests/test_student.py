"""Tests of course_lib.student: student copies of the notebooks.

Synthetic notebooks (built with nbformat in tmp_path) cover each rule; the real notebooks in
notebooks/ are converted too, and, in the last section (slow: it starts Jupyter kernels),
their student copies are executed to show that exactly the solution cells raise
NotImplementedError.
"""

import copy
import subprocess
import sys
from pathlib import Path

import nbformat
from jupyter_client.manager import start_new_kernel
import pytest
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook, new_output

from course_lib.student import (
    BEGIN, END, CODE_STUB, MARKDOWN_STUB, StudentNotebookError, make_student_notebooks,
    student_notebook,
)

NOTEBOOKS = Path(__file__).resolve().parent.parent / "notebooks"


def nbgrader(grade_id):
    return {"nbgrader": {"grade": False, "grade_id": grade_id, "locked": False,
                         "schema_version": 3, "solution": True, "task": False}}


def executed(cell, count):
    cell.execution_count = count
    cell.outputs = [new_output("stream", name="stdout", text="solution output 42\n"),
                    new_output("execute_result", data={"text/plain": "'secret'"},
                               execution_count=count)]
    return cell


def synthetic_notebook():
    """A notebook with every kind of cell the tool must handle."""
    cells = [
        new_markdown_cell("# Chapter\nIntro text."),
        executed(new_code_cell("import math\nfrom course_lib.exercises import check"), 1),
        executed(new_code_cell(
            "answer_hat_squared = None\n"
            "### BEGIN SOLUTION\n"
            "answer_hat_squared = SECRET_ONE\n"
            "helper = SECRET_TWO\n"
            "### END SOLUTION\n"
            "print('after the region')",
            metadata=nbgrader("hat-squared-solution")), 2),
        executed(new_code_cell('check("hat_squared", answer_hat_squared)'), 3),
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
            metadata=nbgrader("two-regions")),
        new_markdown_cell(
            "Explain why:\n\n### BEGIN SOLUTION\nBecause SECRET_FIVE.\n### END SOLUTION\n\nEnd.",
            metadata=nbgrader("written-answer")),
        new_code_cell("answer_rodrigues = SECRET_SIX", metadata=nbgrader("whole-cell")),
        new_code_cell("x = 1  # BEGIN SOLUTION is mentioned, but not as a marker"),
    ]
    nb = new_notebook(cells=cells, metadata={
        "kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"},
        "custom": {"keep": [1, 2, 3]}})
    return nb


def write(nb, path):
    path.parent.mkdir(parents=True, exist_ok=True)
    nbformat.write(nb, path)
    return path


def snapshot(directory):
    return {p: p.read_bytes() for p in sorted(Path(directory).rglob("*")) if p.is_file()}


def marked_lines(source):
    """Lines strictly between BEGIN and END markers."""
    inside, out = False, []
    for line in source.split("\n"):
        if BEGIN.match(line):
            inside = True
        elif END.match(line):
            inside = False
        elif inside:
            out.append(line)
    return out


def outside_lines(source):
    inside, out = False, []
    for line in source.split("\n"):
        if BEGIN.match(line):
            inside = True
        elif END.match(line):
            inside = False
        elif not inside:
            out.append(line)
    return out


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

    assert student.metadata == original.metadata
    assert len(student.cells) == len(original.cells)
    for old, new in zip(original.cells, student.cells):
        assert new.id == old.id and new.metadata == old.metadata
        assert new.cell_type == old.cell_type
        if new.cell_type == "code":
            assert new.outputs == [] and new.execution_count is None

    code = student.cells[2].source.split("\n")
    assert code == ["answer_hat_squared = None", CODE_STUB,
                    "raise NotImplementedError(\"write your solution to exercise "
                    "'hat_squared' here\")",
                    "print('after the region')"]
    two = student.cells[4].source.split("\n")
    assert two[:3] == ["def f(v):", "    total = 0", "    " + CODE_STUB]
    assert two[3].startswith("    raise NotImplementedError(")
    assert two[4:7] == ["    return total", "", "answer_va_example = None"]
    assert two[7] == CODE_STUB and two[8].startswith("raise NotImplementedError(")
    assert student.cells[5].source == f"Explain why:\n\n{MARKDOWN_STUB}\n\nEnd."
    whole = student.cells[6].source
    assert whole.startswith(CODE_STUB) and "NotImplementedError" in whole
    for i in (0, 1, 3, 7):
        assert student.cells[i].source == original.cells[i].source
    text = (tmp_path / "out" / "a_chapter.ipynb").read_text()
    assert "SECRET" not in text and "solution output 42" not in text and "'secret'" not in text


def test_stubs_compile_and_raise_not_implemented_error():
    student = student_notebook(synthetic_notebook())
    namespace = {}
    with pytest.raises(NotImplementedError, match="hat_squared"):
        exec(student.cells[2].source, namespace)
    assert namespace["answer_hat_squared"] is None     # assigned before the raise
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


def test_checkpoints_are_skipped(src, tmp_path):
    make_student_notebooks(src, tmp_path / "out")
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["a_chapter.ipynb",
                                                                     "b_plain.ipynb"]


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


def test_output_file_symlinked_to_a_source_is_never_written_through(src, tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "a_chapter.ipynb").symlink_to(src / "a_chapter.ipynb")
    before = snapshot(src)
    with pytest.raises(StudentNotebookError, match="refusing to write through it"):
        make_student_notebooks(src, out, force=True)
    assert snapshot(src) == before


def test_existing_files_are_refused_without_force(src, tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "b_plain.ipynb").write_text("old")
    with pytest.raises(StudentNotebookError, match="exists; use --force"):
        make_student_notebooks(src, out)
    assert sorted(p.name for p in out.iterdir()) == ["b_plain.ipynb"]   # nothing written
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
        "BEGIN SOLUTION at line 2 without END SOLUTION"),
    "end_without_begin": (
        new_code_cell("a = 1\n### END SOLUTION", metadata=nbgrader("g")),
        "END SOLUTION without BEGIN SOLUTION at line 2"),
    "nested_begin": (
        new_code_cell("### BEGIN SOLUTION\n### BEGIN SOLUTION\nb = 2\n### END SOLUTION",
                      metadata=nbgrader("g")),
        "nested BEGIN SOLUTION at line 2"),
    "markers_without_metadata": (
        new_code_cell("### BEGIN SOLUTION\nb = 2\n### END SOLUTION"),
        "no nbgrader metadata"),
    "markdown_begin_without_end": (
        new_markdown_cell("### BEGIN SOLUTION\nwords", metadata=nbgrader("g")),
        "without END SOLUTION"),
}


@pytest.mark.parametrize("kind", list(BAD_CELLS))
def test_malformed_markers_are_refused_and_nothing_is_written(tmp_path, kind):
    bad_cell, fragment = BAD_CELLS[kind]
    src = tmp_path / "src"
    write(synthetic_notebook(), src / "a_good.ipynb")       # converted first, in memory only
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


# --------------------------------------------------------------------------------- command line

def run_cli(*args):
    return subprocess.run([sys.executable, "-m", "course_lib.student", *map(str, args)],
                          capture_output=True, text=True, timeout=120)


def test_cli_writes_copies_and_exits_zero(src, tmp_path):
    result = run_cli(src, tmp_path / "out")
    assert result.returncode == 0, result.stderr
    assert "wrote 2 student notebook(s)" in result.stdout
    assert (tmp_path / "out" / "a_chapter.ipynb").exists()


def test_cli_errors_exit_two_with_one_line_and_no_traceback(src, tmp_path):
    out = tmp_path / "out"
    make_student_notebooks(src, out)
    for args, fragment in [((src, out), "exists; use --force"),
                           ((src, src / "inner"), "inside the source directory")]:
        result = run_cli(*args)
        assert result.returncode == 2
        assert result.stderr.count("\n") == 1 and fragment in result.stderr
        assert "Traceback" not in result.stderr
        assert result.stderr.startswith("course_lib.student: error: ")
    assert run_cli(src, out, "--force").returncode == 0


def test_cli_unbalanced_markers_exit_two_and_write_nothing(tmp_path):
    bad = new_notebook(cells=[new_code_cell("### BEGIN SOLUTION\nx = 1",
                                            metadata=nbgrader("g"))])
    write(bad, tmp_path / "src" / "bad.ipynb")
    result = run_cli(tmp_path / "src", tmp_path / "out")
    assert result.returncode == 2 and "bad.ipynb: cell 0" in result.stderr
    assert "Traceback" not in result.stderr
    assert not (tmp_path / "out").exists()


# --------------------------------------------------------------------------------- real notebooks

REAL = sorted(p for p in NOTEBOOKS.glob("*.ipynb") if "BEGIN SOLUTION" in p.read_text())


def solution_cells(nb):
    return [i for i, c in enumerate(nb.cells)
            if c.get("metadata", {}).get("nbgrader", {}).get("solution")]


def test_real_notebooks_have_solution_cells():
    # The chapter notebooks carry their exercises; the tests below need them.
    assert len(REAL) >= 3, [p.name for p in NOTEBOOKS.glob("*.ipynb")]


@pytest.fixture(scope="module")
def real_copies(tmp_path_factory):
    before = snapshot(NOTEBOOKS)
    out = tmp_path_factory.mktemp("student")
    make_student_notebooks(NOTEBOOKS, out)
    assert snapshot(NOTEBOOKS) == before             # the sources are untouched
    return out


@pytest.mark.parametrize("path", REAL, ids=lambda p: p.name)
def test_real_notebook_student_copy_has_no_solution_and_no_output(path, real_copies):
    original = nbformat.read(path, as_version=4)
    student = nbformat.read(real_copies / path.name, as_version=4)
    assert solution_cells(original), "no solution cell"
    assert len(student.cells) == len(original.cells)
    for old, new in zip(original.cells, student.cells):
        assert new.id == old.id and new.metadata == old.metadata
        if new.cell_type == "code":
            assert new.outputs == [] and new.execution_count is None
        secret = [line for line in marked_lines(old.source) if line.strip()]
        kept = set(outside_lines(old.source))
        for line in secret:
            if line not in kept:
                assert line not in new.source.split("\n"), (old.id, line)
        if not secret and not old.get("metadata", {}).get("nbgrader", {}).get("solution"):
            assert new.source == old.source
        assert not any(BEGIN.match(x) or END.match(x) for x in new.source.split("\n"))


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
                if (msg["parent_header"].get("msg_id") == msg_id
                        and msg["msg_type"] == "status"
                        and msg["content"]["execution_state"] == "idle"):
                    break
    finally:
        kc.stop_channels()
        km.shutdown_kernel(now=True)
    return errors


@pytest.mark.notebook_exec
@pytest.mark.parametrize("path", REAL, ids=lambda p: p.name)
def test_executing_real_student_notebook_fails_exactly_in_solution_cells(path, real_copies):
    nb = nbformat.read(real_copies / path.name, as_version=4)
    errors = run_cells(nb, real_copies)
    code_solutions = {i for i in solution_cells(nb) if nb.cells[i].cell_type == "code"}
    assert set(errors) == code_solutions, {i: (e, nb.cells[i].id) for i, e in errors.items()}
    assert set(errors.values()) == {"NotImplementedError"}
