r"""Student copies of the course notebooks: solutions replaced by stubs, outputs cleared.

The chapter notebooks hold their solutions between nbgrader markers::

    answer_hat_squared = None
    ### BEGIN SOLUTION
    answer_hat_squared = omega * omega.T - sp.eye(3)
    ### END SOLUTION

in cells whose metadata marks them as nbgrader solution cells
(``{"nbgrader": {"solution": true, "grade_id": "<unique>", ...}}``). A student copy keeps every
cell, every id and all metadata, and replaces each marked region by a stub: in a code cell
``# YOUR CODE HERE`` and ``raise NotImplementedError(...)`` naming the exercise, indented like
the ``BEGIN`` marker; in a markdown cell the prompt ``YOUR ANSWER HERE``. A solution cell without
markers is replaced whole, as nbgrader does. All outputs and execution counts are cleared.

Command line (``make student`` runs it)::

    python -m course_lib.student SRC_DIR OUT_DIR [--force]

The sources are only read. Every notebook is processed in memory before anything is written,
so an error (unbalanced markers, a marked cell without nbgrader metadata, a repeated grade_id,
an OUT_DIR equal to or inside SRC_DIR, existing files without ``--force``) writes nothing; the
command then prints one line on stderr and exits with status 2.
"""

from __future__ import annotations

import argparse
import copy
import re
import sys
from pathlib import Path

import nbformat

__all__ = ["StudentNotebookError", "make_student_notebooks", "student_notebook", "main"]

BEGIN = re.compile(r"^\s*#+\s*BEGIN SOLUTION\s*$")
END = re.compile(r"^\s*#+\s*END SOLUTION\s*$")
CODE_STUB = "# YOUR CODE HERE"
MARKDOWN_STUB = "YOUR ANSWER HERE"
_ANSWER = re.compile(r"\banswer_([A-Za-z_][A-Za-z0-9_]*)\b")


class StudentNotebookError(ValueError):
    """A notebook or a directory that cannot be turned into a student copy (nothing written)."""


def _where(nb_name, index, cell):
    cid = cell.get("id")
    return f"{nb_name}: cell {index}" + (f" (id {cid})" if cid else "")


def _exercise_label(cell):
    """What the stub's NotImplementedError names: the exercise answered in the cell."""
    m = _ANSWER.search(cell.source)
    if m:
        return f"exercise {m.group(1)!r}"
    gid = cell.get("metadata", {}).get("nbgrader", {}).get("grade_id")
    return f"exercise {gid!r}" if gid else "this exercise"


def _stub_lines(cell, indent):
    if cell.cell_type == "code":
        what = _exercise_label(cell)
        return [f"{indent}{CODE_STUB}",
                f"{indent}raise NotImplementedError(\"write your solution to {what} here\")"]
    return [f"{indent}{MARKDOWN_STUB}"]


def _regions(lines, where):
    """(begin, end) line indices of the marked regions; StudentNotebookError if unbalanced."""
    regions, begin = [], None
    for i, line in enumerate(lines):
        if BEGIN.match(line):
            if begin is not None:
                raise StudentNotebookError(f"{where}: nested BEGIN SOLUTION at line {i + 1} "
                                           f"(the one at line {begin + 1} is not closed)")
            begin = i
        elif END.match(line):
            if begin is None:
                raise StudentNotebookError(f"{where}: END SOLUTION without BEGIN SOLUTION at "
                                           f"line {i + 1}")
            regions.append((begin, i))
            begin = None
    if begin is not None:
        raise StudentNotebookError(f"{where}: BEGIN SOLUTION at line {begin + 1} without "
                                   "END SOLUTION")
    return regions


def _stub_cell(cell, where):
    lines = cell.source.split("\n")
    regions = _regions(lines, where)
    meta = cell.get("metadata", {}).get("nbgrader", {})
    is_solution = bool(meta.get("solution"))
    if regions and not is_solution:
        raise StudentNotebookError(f"{where}: has SOLUTION markers but no nbgrader metadata "
                                   "with \"solution\": true (nbgrader refuses such cells)")
    if not is_solution:
        return cell
    new = copy.deepcopy(cell)
    if not regions:  # nbgrader replaces a solution cell without markers whole
        new.source = "\n".join(_stub_lines(cell, ""))
        return new
    out, pos = [], 0
    for begin, end in regions:
        out += lines[pos:begin]
        indent = re.match(r"\s*", lines[begin]).group(0)
        out += _stub_lines(cell, indent)
        pos = end + 1
    out += lines[pos:]
    new.source = "\n".join(out)
    return new


def student_notebook(nb, name="notebook"):
    r"""The student copy of one notebook (a new object; ``nb`` is not modified).

    Parameters
    ----------
    nb : nbformat.NotebookNode
        A version 4 notebook.
    name : str
        Its name, used in error messages.

    Returns
    -------
    nbformat.NotebookNode
        Marked regions replaced by stubs, outputs and execution counts cleared, all other
        content (cells, ids, metadata) unchanged.

    Raises
    ------
    StudentNotebookError
        On unbalanced or nested markers, markers in a cell without nbgrader solution metadata,
        or a repeated ``grade_id``; the message names the notebook and the cell (index, id).

    Examples
    --------
    >>> cell = nbformat.v4.new_code_cell(
    ...     "answer_x = None\n### BEGIN SOLUTION\nanswer_x = 1\n### END SOLUTION",
    ...     metadata={"nbgrader": {"grade": False, "grade_id": "x", "locked": False,
    ...                            "schema_version": 3, "solution": True, "task": False}})
    >>> print(student_notebook(nbformat.v4.new_notebook(cells=[cell])).cells[0].source)
    answer_x = None
    # YOUR CODE HERE
    raise NotImplementedError("write your solution to exercise 'x' here")
    """
    seen = {}
    new = copy.deepcopy(nb)
    for i, cell in enumerate(nb.cells):
        where = _where(name, i, cell)
        gid = cell.get("metadata", {}).get("nbgrader", {}).get("grade_id")
        if gid is not None:
            if gid in seen:
                raise StudentNotebookError(f"{where}: grade_id {gid!r} repeats the one of cell "
                                           f"{seen[gid]}")
            seen[gid] = i
        new_cell = _stub_cell(cell, where)
        if new_cell.cell_type == "code":
            new_cell = copy.deepcopy(new_cell) if new_cell is cell else new_cell
            new_cell.outputs = []
            new_cell.execution_count = None
        new.cells[i] = new_cell
    return new


def _is_relative_to(path, other):
    return path == other or other in path.parents


def make_student_notebooks(src_dir, out_dir, force=False):
    r"""Write a student copy of every notebook of ``src_dir`` into ``out_dir``.

    Parameters
    ----------
    src_dir : str or pathlib.Path
        Directory of the source notebooks (``*.ipynb``, not recursive; never modified).
    out_dir : str or pathlib.Path
        Where the copies go (created if needed); must not be ``src_dir`` or inside it.
    force : bool, default False
        Overwrite existing files in ``out_dir``.

    Returns
    -------
    list of pathlib.Path
        The written notebooks, in name order.

    Raises
    ------
    StudentNotebookError
        If ``src_dir`` is missing or holds no notebook, ``out_dir`` is ``src_dir`` or inside it
        (after resolving symlinks), a copy would overwrite a file without ``force``, or a
        notebook is malformed (see :func:`student_notebook`). Nothing is written then.

    Examples
    --------
    >>> make_student_notebooks("notebooks", "notebooks/student")
    Traceback (most recent call last):
    ...
    course_lib.student.StudentNotebookError: output directory notebooks/student is inside the source directory notebooks; choose one outside it
    """
    src, out = Path(src_dir), Path(out_dir)
    src_r, out_r = src.resolve(), out.resolve()
    if _is_relative_to(out_r, src_r):
        what = "is the source directory" if out_r == src_r else "is inside the source directory"
        raise StudentNotebookError(f"output directory {out} {what} {src}; choose one outside it")
    if not src.is_dir():
        raise StudentNotebookError(f"source directory {src} does not exist")
    if out.exists() and not out.is_dir():
        raise StudentNotebookError(f"output path {out} exists and is not a directory")
    sources = sorted(p for p in src.glob("*.ipynb")
                     if p.is_file() and ".ipynb_checkpoints" not in p.parts)
    if not sources:
        raise StudentNotebookError(f"no notebooks (*.ipynb) in {src}")

    copies = []
    for path in sources:
        try:
            nb = nbformat.read(path, as_version=nbformat.NO_CONVERT)
        except Exception as err:  # noqa: BLE001 - reported as one line
            raise StudentNotebookError(f"{path}: cannot read the notebook: {err}") from None
        if nb.get("nbformat") != 4:
            raise StudentNotebookError(f"{path}: nbformat {nb.get('nbformat')} notebooks are "
                                       "not supported (version 4 expected)")
        copies.append((out / path.name, student_notebook(nb, str(path))))

    for target, _ in copies:
        if target.is_symlink() or target.exists():
            if _is_relative_to(target.resolve(), src_r):
                raise StudentNotebookError(f"{target} points into the source directory {src}; "
                                           "refusing to write through it")
            if not force:
                raise StudentNotebookError(f"{target} exists; use --force to overwrite")

    out.mkdir(parents=True, exist_ok=True)
    written = []
    for target, nb in copies:
        if target.is_symlink():
            target.unlink()
        nbformat.write(nb, target)
        written.append(target)
    return written


def main(argv=None):
    """Command line: ``python -m course_lib.student SRC_DIR OUT_DIR [--force]``."""
    parser = argparse.ArgumentParser(
        prog="python -m course_lib.student",
        description="Write student copies of the notebooks of SRC_DIR into OUT_DIR: solutions "
                    "replaced by stubs, outputs cleared.")
    parser.add_argument("src_dir", metavar="SRC_DIR")
    parser.add_argument("out_dir", metavar="OUT_DIR")
    parser.add_argument("--force", action="store_true", help="overwrite existing files")
    args = parser.parse_args(argv)
    try:
        written = make_student_notebooks(args.src_dir, args.out_dir, force=args.force)
    except StudentNotebookError as err:
        print(f"course_lib.student: error: {err}", file=sys.stderr)
        return 2
    print(f"wrote {len(written)} student notebook(s) to {args.out_dir}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
