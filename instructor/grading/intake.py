"""What the grader reads of a submission, on every path (Gradescope, ``submitted/``, the exchange).

Only a **regular file that lives inside the submission folder** is read, and only when it is
at most :data:`MAX_BYTES` long; its size is checked *before* a byte is read (a 2 GB upload
is never held in memory). Everything else is refused with a note that names what was found
and what is expected, and that notebook gets 0; the rest of the class is graded:

- a symbolic link (to the instructor's ``source/``, to ``/etc/shadow``, to another student's
  folder), or a path through a symbolic-linked folder: every component below the submission
  folder is opened with ``O_NOFOLLOW``, relative to the folder before it (no check-then-open
  race: what is checked is the open file itself, ``fstat``);
- a file with more than one name (a hard link, ``st_nlink > 1``): its other name may be
  outside the submission; the grader's own copies always have one name;
- a named pipe (FIFO), a device, a socket, a folder named ``*.ipynb``;
- an empty file, a file over :data:`MAX_BYTES`, a file that is not a notebook (JSON with a
  list of ``cells``).

A ``.zip`` in the folder is never unpacked here. Names are shown in notes as they are
(unicode and spaces are fine), cut to 80 characters, control characters escaped.

:func:`read_inside` is the one check; :func:`pick` chooses the notebook of a Gradescope
submission; :func:`refused_notebook` is what nbgrader grades in place of a refused file (an
empty notebook carrying the note: :class:`instructor.grading.preprocessor.GuardCells` then gives
every grade cell 0 with that note); :class:`SafeCollect` is ``nbgrader collect`` with this intake.
"""

from __future__ import annotations

import errno
import itertools
import json
import os
import stat

__all__ = ["MAX_BYTES", "NOTE", "Refused", "read_inside", "pick", "refused_notebook", "shown"]

#: The largest notebook read (bytes): the course's problem sets are 20-60 kB, 50 MB of output
#: is capped to 100 kB a cell while it runs, so a real submission is far below.
MAX_BYTES = 20 * 2**20
#: Notebook metadata key of a refused submission's note (:func:`refused_notebook`).
NOTE = "rotations_intake_refused"
#: At most this many entries of a submission folder are looked at (a folder of a million files).
MAX_ENTRIES = 1_000
_KINDS = (
    (stat.S_ISDIR, "a folder"),
    (stat.S_ISFIFO, "a named pipe (FIFO)"),
    (stat.S_ISCHR, "a device"),
    (stat.S_ISBLK, "a device"),
    (stat.S_ISSOCK, "a socket"),
    (stat.S_ISLNK, "a symbolic link"),
)


class Refused(ValueError):
    """A submitted file the grader will not read; ``str(err)`` is the note for the student."""


def shown(name, limit=80):
    """A file name as a note shows it: control characters escaped, at most ``limit`` characters.

    Examples
    --------
    >>> shown("my notebook ✓.ipynb")
    'my notebook ✓.ipynb'
    >>> shown("a\\nb")
    'a\\\\nb'
    """
    text = "".join(c if c.isprintable() else repr(c)[1:-1] for c in str(name))
    return text if len(text) <= limit else text[: limit - 3] + "..."


def _kind(mode):
    return next((what for test, what in _KINDS if test(mode)), "not a regular file")


def _open_below(folder_fd, parts, name):
    """Open ``parts/.../name`` below the open folder, never following a symbolic link."""
    fd = os.dup(folder_fd)
    try:
        for part in parts:
            try:
                new = os.open(part, os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW, dir_fd=fd)
            except OSError as err:
                if err.errno in (errno.ELOOP, errno.ENOTDIR):
                    raise Refused(
                        f"{shown(name)}: the folder {shown(part)} is a symbolic link "
                        "or not a folder: only files inside the submission are read"
                    ) from None
                raise
            os.close(fd)
            fd = new
        try:
            st = os.stat(name, dir_fd=fd, follow_symlinks=False)
        except FileNotFoundError:
            raise Refused(f"{shown(name)}: not found in the submission") from None
        if not stat.S_ISREG(st.st_mode):
            raise Refused(
                f"{shown(name)} is {_kind(st.st_mode)}, not a notebook file: "
                "only regular files inside the submission are read"
            )
        flags = os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_NOCTTY
        try:
            return os.open(name, flags, dir_fd=fd)
        except OSError as err:
            if err.errno == errno.ELOOP:
                raise Refused(
                    f"{shown(name)} is a symbolic link: only regular files inside "
                    "the submission are read"
                ) from None
            raise
    finally:
        os.close(fd)


def read_inside(path, folder, max_bytes=MAX_BYTES):
    """The bytes of ``path`` when it is a regular file of one name, inside ``folder``, of
    1 to ``max_bytes`` bytes; otherwise :class:`Refused` with the note (nothing read).

    Examples
    --------
    >>> import tempfile, pathlib
    >>> top = pathlib.Path(tempfile.mkdtemp())
    >>> _ = (top / "ps01.ipynb").write_text('{"cells": []}')
    >>> read_inside(top / "ps01.ipynb", top)
    b'{"cells": []}'
    >>> (top / "link.ipynb").symlink_to("/etc/passwd")
    >>> try:
    ...     read_inside(top / "link.ipynb", top)
    ... except Refused as err:
    ...     print(err)
    link.ipynb is a symbolic link, not a notebook file: only regular files inside the
    submission are read
    """
    base = os.path.realpath(folder)
    rel = os.path.relpath(os.path.abspath(path), os.path.abspath(folder))
    parts = rel.split(os.sep)
    if rel == "." or os.path.isabs(rel) or ".." in parts:
        raise Refused(f"{shown(path)} is outside the submission folder")
    folder_fd = os.open(base, os.O_RDONLY | os.O_DIRECTORY)
    try:
        fd = _open_below(folder_fd, parts[:-1], parts[-1])
    finally:
        os.close(folder_fd)
    with os.fdopen(fd, "rb") as f:
        st = os.fstat(f.fileno())
        name = shown(parts[-1])
        if not stat.S_ISREG(st.st_mode):  # replaced between the check and the open
            raise Refused(f"{name} is {_kind(st.st_mode)}, not a notebook file")
        if st.st_nlink > 1:
            raise Refused(
                f"{name} is a hard link ({st.st_nlink} names for one file): "
                "hand in a copy of the notebook, not a link"
            )
        if st.st_size == 0:
            raise Refused(f"{name} is empty (0 bytes): hand in the saved notebook")
        if st.st_size > max_bytes:
            raise Refused(
                f"{name} is {st.st_size / 2**20:.0f} MB, over the limit of "
                f"{max_bytes / 2**20:.0f} MB per notebook (clear the outputs and "
                "save it again): not read"
            )
        data = f.read(max_bytes + 1)
    if len(data) > max_bytes:  # it grew after fstat
        raise Refused(f"{name} is over the limit of {max_bytes / 2**20:.0f} MB: not read")
    return data


def parse(data, name):
    """The notebook (a dict) in ``data``, or :class:`Refused` saying why it is not one."""
    try:
        nb = json.loads(data.decode("utf-8"))
    except (RecursionError, MemoryError) as err:  # nested past what the parser can hold
        raise Refused(
            f"{shown(name)} is JSON nested too deep to be a notebook ({type(err).__name__}): "
            "hand in the .ipynb file that Jupyter saved"
        ) from None
    except (UnicodeDecodeError, ValueError) as err:
        raise Refused(
            f"{shown(name)} is not a readable notebook ({type(err).__name__}: not "
            "JSON text): hand in the .ipynb file that Jupyter saved"
        ) from None
    if not isinstance(nb, dict) or not isinstance(nb.get("cells"), list):
        raise Refused(f"{shown(name)} is JSON but not a notebook (no list of cells)")
    return nb


def pick(folder, expected):
    """``(file name, note or "")`` of the notebook to grade in a Gradescope submission folder:
    ``expected`` when it is there, else the only ``*.ipynb``; :class:`Refused` when there is
    none or more than one. Only the folder's own entries are looked at (no sub-folder, no
    archive unpacked), at most :data:`MAX_ENTRIES`."""
    with os.scandir(folder) as it:
        names = sorted(e.name for e in itertools.islice(it, MAX_ENTRIES))
    books = [n for n in names if n.lower().endswith(".ipynb")]
    if expected in books:
        others = [shown(n) for n in books if n != expected]
        return expected, (f"other notebooks not graded: {', '.join(others)}." if others else "")
    if len(books) == 1:
        return books[0], f"graded {shown(books[0])} (the problem set's file is {expected})."
    if not books:
        found = ", ".join(shown(n) for n in names[:5]) or "nothing"
        zipped = (
            " A .zip is not unpacked by the grader."
            if any(n.lower().endswith(".zip") for n in names)
            else ""
        )
        raise Refused(
            f"no notebook (.ipynb) in the submission (found: {found}).{zipped} "
            f"Upload {expected} itself."
        )
    raise Refused(
        f"{len(books)} notebooks in the submission ({', '.join(map(shown, books[:5]))}) "
        f"and none named {expected}: upload only {expected}."
    )


def refused_notebook(note):
    """The notebook graded in place of a refused file: no cells, the note in its metadata."""
    return {"cells": [], "metadata": {NOTE: note}, "nbformat": 4, "nbformat_minor": 5}


def _folder_of(path, coursedir):
    """``(the course folder that holds path, whether it is the students' submitted/)``:
    ``submitted/`` or nbgrader's own ``autograded/`` (the second stage of autograde)."""
    path = os.path.abspath(path)
    if coursedir is not None:
        for name in (coursedir.submitted_directory, coursedir.autograded_directory):
            root = os.path.abspath(coursedir.format_path(name, ".", "."))
            if path.startswith(root.rstrip(os.sep) + os.sep):
                return root, name == coursedir.submitted_directory
        return None, True
    return os.path.dirname(path), True


def nbgrader_read(filename, coursedir, resources=None, log=None):
    """``(notebook node, resources)`` of a notebook ``nbgrader autograde`` grades, read through
    :func:`read_inside` from the course's ``submitted/`` (or ``autograded/``) folder; a refused
    file becomes :func:`refused_notebook` with the note (logged as a warning)."""
    import nbformat

    resources = resources if resources is not None else {}
    meta = resources.setdefault("metadata", {}) or {}
    resources["metadata"] = meta
    meta["name"] = os.path.splitext(os.path.basename(filename))[0]
    meta["path"] = os.path.dirname(filename)
    folder, students = _folder_of(filename, coursedir)
    try:
        if folder is None:
            raise Refused(f"{shown(filename)} is outside the course's submitted/ folder")
        data = read_inside(filename, folder)
        parse(data, os.path.basename(filename))
        try:
            nb = nbformat.reads(data.decode("utf-8"), as_version=4)
        except Exception as err:  # noqa: BLE001 - nbformat's own refusal of the JSON
            raise Refused(
                f"{shown(os.path.basename(filename))} is not a notebook nbformat "
                f"can read ({type(err).__name__})"
            ) from None
        if students and nb.cells:  # the note of the intake's own placeholder (no cells) only
            nb.metadata.pop(NOTE, None)
        return nb, resources
    except (Refused, OSError) as err:
        note = f"0 points: {err}" if isinstance(err, Refused) else f"0 points: unreadable ({err})"
        if log is not None:
            log.warning("%s: refused at intake: %s", shown(filename, 200), note)
        return nbformat.from_dict(refused_notebook(note)), resources
