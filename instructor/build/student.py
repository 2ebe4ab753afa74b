r"""Student copies of the course notebooks: solutions replaced by stubs, nothing else of them kept.

The chapter notebooks hold their solutions between nbgrader markers::

    answer_hat_squared = None
    ### BEGIN SOLUTION
    answer_hat_squared = omega * omega.T - sp.eye(3)
    ### END SOLUTION

in cells whose metadata marks them as nbgrader solution cells
(``{"nbgrader": {"solution": true, "grade_id": "<unique>", ...}}``).

Markers follow nbgrader's own rule exactly (``nbgrader.preprocessors.ClearSolutions``,
``ClearHiddenTests``, ``ClearMarkScheme``), so the two never disagree: **any line that contains**
``BEGIN SOLUTION`` opens a region and any line that contains ``END SOLUTION`` closes it, in every
cell and wherever the words stand in the line (a sentence of prose that names them is a marker
too). Likewise ``BEGIN HIDDEN TESTS`` / ``END HIDDEN TESTS`` (removed; only in autograder test
cells, ``"grade": true``) and ``BEGIN MARK SCHEME`` / ``END MARK SCHEME`` (removed; only in
manually graded task cells, ``"task": true``). A region in a cell without the matching metadata,
a nested or an unclosed region is refused, as nbgrader refuses it. The one place where this tool
is stricter: a closing marker outside any region, which nbgrader silently deletes, is refused.

A student copy keeps every cell, every id and the cell metadata. Each solution region becomes a
stub: in a code cell ``# YOUR CODE HERE`` and ``raise NotImplementedError(...)`` naming the
exercise, indented like the ``BEGIN`` line; in a markdown or raw cell the prompt
``YOUR ANSWER HERE``. A solution cell without markers is replaced whole, as nbgrader does.
Nothing stored by a run is kept: outputs and execution counts are cleared, the output-view and
timing metadata of cells (``collapsed``, ``scrolled``, ``execution``) and the notebook's widget
state (``metadata.widgets``) dropped, and an attachment survives only where the student copy of
its cell still refers to it (so a solution's images go with the solution).

Command line (``make student`` runs it)::

    python -m instructor.build.student SRC_DIR OUT_DIR [--force]

The sources are only read. Every notebook is converted in memory, then all copies are written
into a temporary folder inside OUT_DIR (on its filesystem) and moved into place, replacing the
directory entries (never writing through a link), only when every one of them is written. On
any error (a malformed notebook, OUT_DIR equal to or inside SRC_DIR, an existing file without
``--force``, a file in OUT_DIR that is a link to a source, a directory in the way, a full disk,
no permission) nothing is written and nothing is left behind: the command prints one line on
stderr and exits with status 2.
"""

from __future__ import annotations

import argparse
import contextlib
import copy
import os
import re
import shutil
import sys
import tempfile
from pathlib import Path

import nbformat

__all__ = [
    "StudentNotebookError",
    "make_student_notebooks",
    "nbgrader_metadata",
    "student_notebook",
    "main",
]

CODE_STUB = "# YOUR CODE HERE"
MARKDOWN_STUB = "YOUR ANSWER HERE"
# (marker words, the nbgrader metadata flag a cell needs to hold them, nbgrader's name of such
# cells); in nbgrader's order: solutions are cleared first, then hidden tests, then mark schemes.
REGIONS = (
    ("SOLUTION", "solution", "solution cells"),
    ("HIDDEN TESTS", "grade", "autograder test cells"),
    ("MARK SCHEME", "task", "manually graded task cells"),
)
CELL_RUN_STATE = ("collapsed", "scrolled", "execution")
NOTEBOOK_RUN_STATE = ("widgets", "celltoolbar")
_ANSWER = re.compile(r"\banswer_([A-Za-z_][A-Za-z0-9_]*)\b")
_ATTACHMENT = re.compile(r"attachment:([^\s)\"'>]+)")


class StudentNotebookError(ValueError):
    """A notebook or a directory that cannot be turned into a student copy (nothing written)."""


# --------------------------------------------------------------------------------- one notebook


def nbgrader_metadata(
    grade_id, *, solution=False, grade=False, locked=False, task=False, points=None
):
    """The cell metadata by which nbgrader (schema 3) knows a cell: ``{"nbgrader": {...}}``.

    Examples
    --------
    >>> meta = nbgrader_metadata("x-check", grade=True, locked=True, points=2)["nbgrader"]
    >>> meta["grade_id"], meta["schema_version"], meta["solution"], meta["points"]
    ('x-check', 3, False, 2)
    """
    meta = {
        "grade": grade,
        "grade_id": grade_id,
        "locked": locked,
        "schema_version": 3,
        "solution": solution,
        "task": task,
    }
    if points is not None:
        meta["points"] = points
    return {"nbgrader": meta}


def _where(nb_name, index, cell):
    cid = cell.get("id")
    return f"{nb_name}: cell {index}" + (f" (id {cid})" if cid else "")


def _flag(cell, name):
    """nbgrader's ``utils.is_solution`` / ``is_grade`` / ``is_task``."""
    return bool(cell.get("metadata", {}).get("nbgrader", {}).get(name, False))


def _exercise_label(cell):
    """What the stub's NotImplementedError names: the exercise answered in the cell."""
    m = _ANSWER.search(cell.source)
    if m:
        return f"exercise {m.group(1)!r}"
    gid = cell.get("metadata", {}).get("nbgrader", {}).get("grade_id")
    return f"exercise {gid!r}" if gid else "this exercise"


def _stub_lines(cell):
    if cell.cell_type == "code":
        return [
            CODE_STUB,
            f'raise NotImplementedError("write your solution to {_exercise_label(cell)} here")',
        ]
    return [MARKDOWN_STUB]


def _clear_region(lines, words, stub, where, hint=""):
    """nbgrader's scan: (lines with every BEGIN..END region replaced by ``stub``, found any).

    ``lines`` are (line number in the instructor's cell, text) pairs, so that a message names
    the line the instructor sees even after an earlier region was replaced.
    """
    begin, end = f"BEGIN {words}", f"END {words}"
    out, start, found = [], None, False
    for number, line in lines:
        if begin in line:
            if start is not None:
                raise StudentNotebookError(
                    f"{where}: nested {begin} at line {number} "
                    f"(the one at line {start} is not closed){hint}"
                )
            start, found = number, True
            indent = re.match(r"\s*", line).group(0)
            out += [(number, indent + s) for s in stub]
        elif end in line:
            if start is None:
                raise StudentNotebookError(f"{where}: {end} without {begin} at line {number}{hint}")
            start = None
        elif start is None:
            out.append((number, line))
    if start is not None:
        raise StudentNotebookError(f"{where}: {begin} at line {start} without {end}{hint}")
    return out, found


def _clear_cell(cell, where, clear_outputs=True):
    """Turn ``cell`` (a copy) into its student version, in place."""
    original = cell.source
    lines = list(enumerate(original.split("\n"), 1))
    for words, flag, kind in REGIONS:
        stub = _stub_lines(cell) if flag == "solution" else []
        hint = (
            ""
            if _flag(cell, flag)
            else (
                f"; nbgrader, too, takes any line containing 'BEGIN {words}' or 'END {words}' for "
                f"a marker, even in prose, and allows markers only in {kind} "
                f'("{flag}": true)'
            )
        )
        lines, found = _clear_region(lines, words, stub, where, hint)
        if found and not _flag(cell, flag):
            raise StudentNotebookError(
                f"{where}: a line contains 'BEGIN {words}' but the cell "
                f'has no nbgrader metadata with "{flag}": true{hint}'
            )
        if flag == "solution" and _flag(cell, "solution") and not found:
            lines = [(1, text) for text in _stub_lines(cell)]  # nbgrader replaces it whole
    cell.source = "\n".join(text for _, text in lines)
    if cell.source != original and "attachments" in cell:
        kept = set(_ATTACHMENT.findall(cell.source))
        cell.attachments = {k: v for k, v in cell.attachments.items() if k in kept}
        if not cell.attachments:
            del cell["attachments"]
    if cell.cell_type == "code" and (clear_outputs or cell.source != original):
        cell.outputs = []
        cell.execution_count = None
    for key in CELL_RUN_STATE:
        cell.get("metadata", {}).pop(key, None)


def student_notebook(nb, name="notebook", keep_outputs=False):
    r"""The student copy of one notebook (a new object; ``nb`` is not modified).

    Parameters
    ----------
    nb : nbformat.NotebookNode
        A version 4 notebook.
    name : str
        Its name, used in error messages.
    keep_outputs : bool, default False
        Keep the outputs and execution counts of the cells before the first nbgrader cell (the
        reading part of a chapter, for strict nbval); every later cell is cleared all the same.

    Returns
    -------
    nbformat.NotebookNode
        Solution regions replaced by stubs, hidden tests and mark schemes removed (nbgrader's
        marker rule, see the module docstring), outputs, execution counts, cell run metadata,
        widget state and no longer referenced attachments dropped; all other content (cells,
        ids, metadata) unchanged.

    Raises
    ------
    StudentNotebookError
        On unbalanced or nested markers, markers in a cell without the matching nbgrader
        metadata, a repeated ``grade_id`` or a kernel language other than Python; the message
        names the notebook and the cell (index, id).

    Examples
    --------
    >>> cell = nbformat.v4.new_code_cell(
    ...     "answer_x = None\n### BEGIN SOLUTION\nanswer_x = 1\n### END SOLUTION",
    ...     metadata=nbgrader_metadata("x", solution=True))
    >>> print(student_notebook(nbformat.v4.new_notebook(cells=[cell])).cells[0].source)
    answer_x = None
    # YOUR CODE HERE
    raise NotImplementedError("write your solution to exercise 'x' here")
    """
    language = nb.get("metadata", {}).get("kernelspec", {}).get("language", "python")
    if language != "python":
        raise StudentNotebookError(
            f"{name}: kernel language {language!r}; the stubs are "
            "Python (language 'python' expected)"
        )
    new = copy.deepcopy(nb)
    for key in NOTEBOOK_RUN_STATE:
        new.metadata.pop(key, None)
    seen = {}
    graded = [i for i, c in enumerate(new.cells) if c.get("metadata", {}).get("nbgrader")]
    first_graded = 0
    if keep_outputs:
        first_graded = graded[0] if graded else len(new.cells)
    for i, cell in enumerate(new.cells):
        where = _where(name, i, cell)
        gid = cell.get("metadata", {}).get("nbgrader", {}).get("grade_id")
        if gid is not None:
            if gid in seen:
                raise StudentNotebookError(
                    f"{where}: grade_id {gid!r} repeats the one of cell {seen[gid]}"
                )
            seen[gid] = i
        _clear_cell(cell, where, clear_outputs=i >= first_graded)
    return new


# --------------------------------------------------------------------------------- a directory


def _is_relative_to(path, other):
    return path == other or other in path.parents


def _inodes(directory):
    """(device, inode) of every file under ``directory``: what a hard link would share."""
    found = set()
    for root, _, files in os.walk(directory):
        for f in files:
            st = os.stat(os.path.join(root, f), follow_symlinks=False)
            found.add((st.st_dev, st.st_ino))
    return found


def _check_target(target, src, src_r, source_inodes, force):
    """Refuse a target that is a directory, leads into SRC, or exists without ``force``."""
    if not os.path.lexists(target):
        return
    if target.is_dir():
        raise StudentNotebookError(
            f"{target} is a directory in the way of the student copy; "
            "move it away or choose another output directory"
        )
    st = target.stat() if target.exists() else None
    if _is_relative_to(target.resolve(), src_r) or (
        st is not None and (st.st_dev, st.st_ino) in source_inodes
    ):
        raise StudentNotebookError(
            f"{target} is a link to a file of the source directory {src}; "
            "refusing to replace it (remove it first)"
        )
    if _holds_solutions(target):
        raise StudentNotebookError(
            f"{target} holds solution regions (an instructor notebook); refusing to replace it, "
            "with or without --force (are SRC_DIR and OUT_DIR the wrong way round?)"
        )
    if not force:
        raise StudentNotebookError(f"{target} exists; use --force to overwrite")


def _holds_solutions(path):
    """Whether the file at ``path`` has a line with a solution marker (any text, read or not)."""
    try:
        text = path.read_bytes().decode("utf-8", errors="replace")
    except OSError:
        return False  # not readable: replacing its directory entry does not read it either
    return "BEGIN SOLUTION" in text or "END SOLUTION" in text


def _read_sources(src):
    sources = sorted(p for p in src.glob("*.ipynb") if p.is_file())
    if not sources:
        raise StudentNotebookError(f"no notebooks (*.ipynb) in {src}")
    notebooks = []
    for path in sources:
        try:
            nb = nbformat.read(path, as_version=nbformat.NO_CONVERT)
        except Exception as err:  # noqa: BLE001 - reported as one line
            raise StudentNotebookError(f"{path}: cannot read the notebook: {err}") from None
        if nb.get("nbformat") != 4:
            raise StudentNotebookError(
                f"{path}: nbformat {nb.get('nbformat')} notebooks are "
                "not supported (version 4 expected)"
            )
        notebooks.append((path, nb))
    return notebooks


def _serialized(nb):
    text = nbformat.writes(nb)
    return (text if text.endswith("\n") else text + "\n").encode("utf-8")


# --------------------------------------------------------------------------------- all or nothing


def _make_dirs(directory):
    """Create ``directory`` and its missing parents; return those created, outermost first."""
    missing = [d for d in [directory, *directory.parents] if not os.path.lexists(d)]
    created = []
    try:
        for d in reversed(missing):
            d.mkdir()
            created.append(d)
    except BaseException:
        _remove_dirs(created)
        raise
    return created


def _remove_dirs(created):
    for d in reversed(created):
        with contextlib.suppress(OSError):
            d.rmdir()


def _write_file(path, data):
    with open(path, "xb") as f:
        f.write(data)
        f.flush()
        os.fsync(f.fileno())  # a full disk shows here at the latest, not after the move


def _move_into_place(stage, names, out):
    """Rename the staged files over their targets; on any failure put the old ones back."""
    old = stage / ".replaced"
    old.mkdir()
    done = []  # (target, backup or None, new file in place)
    try:
        for name in names:
            target, backup = out / name, None
            if os.path.lexists(target):
                backup = old / name
                os.rename(target, backup)  # the directory entry moves; its file is untouched
            done.append([target, backup, False])
            os.rename(stage / name, target)
            done[-1][2] = True
    except BaseException:
        for target, backup, placed in reversed(done):
            try:
                if placed:
                    os.unlink(target)
                if backup is not None:
                    os.rename(backup, target)
            except OSError:
                pass  # the old file stays in .replaced; _write_all keeps it and says where
        raise


def _write_all(files, out):
    """Write ``files`` ({name: bytes}) into ``out``: all of them, or nothing and no trace."""
    created = _make_dirs(out)
    stage = None
    try:
        stage = Path(tempfile.mkdtemp(prefix=".student-copies-", dir=out))
        for name, data in files.items():
            _write_file(stage / name, data)
        _move_into_place(stage, list(files), out)
    except BaseException as err:
        kept = stage / ".replaced" if stage is not None else None
        if kept is not None and kept.is_dir() and any(kept.iterdir()):
            raise StudentNotebookError(
                f"cannot write the student copies to {out} ({err!r}) and "
                f"could not put the previous files back; they are in "
                f"{kept}"
            ) from None
        if stage is not None:
            shutil.rmtree(stage, ignore_errors=True)
        _remove_dirs(created)
        raise
    shutil.rmtree(stage, ignore_errors=True)


def _resolved(path, what):
    """``path`` with its links resolved, or a StudentNotebookError naming the trouble."""
    try:
        return path.resolve()
    except (OSError, RuntimeError) as err:  # RuntimeError: a symlink loop (Python < 3.13)
        trouble = "a symlink loop" if "loop" in str(err).lower() else str(err)
        raise StudentNotebookError(f"{what} {path}: {trouble}") from None


def _fs_error(err, out):
    what = err.strerror or type(err).__name__
    where = f" ({err.filename})" if err.filename else ""
    return StudentNotebookError(
        f"cannot write the student copies to {out}: {what}{where}; nothing was written"
    )


def make_student_notebooks(src_dir, out_dir, force=False):
    r"""Write a student copy of every notebook of ``src_dir`` into ``out_dir``, all or nothing.

    Parameters
    ----------
    src_dir : str or pathlib.Path
        Directory of the source notebooks (``*.ipynb``, not recursive; never modified).
    out_dir : str or pathlib.Path
        Where the copies go (created if needed); must not be ``src_dir`` or inside it.
    force : bool, default False
        Replace existing files in ``out_dir`` (the directory entry is replaced; a file it was a
        link to is never written).

    Returns
    -------
    list of pathlib.Path
        The written notebooks, in name order.

    Raises
    ------
    StudentNotebookError
        If ``src_dir`` is missing or holds no notebook, ``out_dir`` is ``src_dir`` or inside it
        (after resolving symlinks), a copy would replace a file without ``force``, a directory
        or a link to a source file, a notebook that holds solution regions (even with ``force``:
        SRC_DIR and OUT_DIR swapped would otherwise replace the instructor's notebooks), a
        notebook is malformed (see :func:`student_notebook`), or the file system is in the way
        (a symlink loop, a file where a folder should be, no permission, a full disk). Nothing
        is written then.

    Examples
    --------
    >>> make_student_notebooks("notebooks", "notebooks/student")
    Traceback (most recent call last):
    ...
    instructor.build.student.StudentNotebookError: output directory notebooks/student is inside the
    source directory notebooks; choose one outside it
    """
    src, out = Path(src_dir), Path(out_dir)
    src_r, out_r = _resolved(src, "source directory"), _resolved(out, "output directory")
    if _is_relative_to(out_r, src_r):
        what = "is the source directory" if out_r == src_r else "is inside the source directory"
        raise StudentNotebookError(f"output directory {out} {what} {src}; choose one outside it")
    if not src.is_dir():
        raise StudentNotebookError(f"source directory {src} does not exist")
    if os.path.lexists(out) and not out.is_dir():
        raise StudentNotebookError(f"output path {out} exists and is not a directory")
    try:
        notebooks = _read_sources(src)
    except OSError as err:
        raise StudentNotebookError(f"cannot read {src}: {err.strerror or err}") from None
    files = {path.name: _serialized(student_notebook(nb, str(path))) for path, nb in notebooks}
    try:
        source_inodes = _inodes(src)
        for name in files:
            _check_target(out / name, src, src_r, source_inodes, force)
        _write_all(files, out)
    except (OSError, RuntimeError) as err:
        if isinstance(err, RuntimeError):  # a symlink loop met while resolving a target
            raise StudentNotebookError(f"{out}: a symlink loop; nothing was written") from None
        raise _fs_error(err, out) from None
    return [out / name for name in files]


def main(argv=None):
    """Command line: ``python -m instructor.build.student SRC_DIR OUT_DIR [--force]``."""
    parser = argparse.ArgumentParser(
        prog="python -m instructor.build.student",
        description="Write student copies of the notebooks of SRC_DIR into OUT_DIR: solutions "
        "replaced by stubs, outputs cleared; all of them or nothing.",
    )
    parser.add_argument("src_dir", metavar="SRC_DIR")
    parser.add_argument("out_dir", metavar="OUT_DIR")
    parser.add_argument("--force", action="store_true", help="replace existing files")
    args = parser.parse_args(argv)
    try:
        written = make_student_notebooks(args.src_dir, args.out_dir, force=args.force)
    except StudentNotebookError as err:
        print(f"instructor.build.student: error: {err}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("instructor.build.student: error: interrupted; nothing was written", file=sys.stderr)
        return 2
    except (OSError, RuntimeError) as err:  # anything the checks above did not name
        print(f"instructor.build.student: error: {args.out_dir}: {err}", file=sys.stderr)
        return 2
    print(f"wrote {len(written)} student notebook(s) to {args.out_dir}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
