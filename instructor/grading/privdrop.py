"""The second confinement: a privilege drop, for a grader that runs as root where bubblewrap
cannot start (Gradescope's Docker container, any container whose seccomp profile refuses user
namespaces, a root JupyterHub). It needs no namespace, no mount and no account.

Root starts the kernel (:mod:`instructor.grading.sandbox`'s launcher) and, before ``execve``,
becomes a dedicated unprivileged user: uid = gid = :data:`KERNEL_ID` + a slot (``0 <= slot <``
:data:`SLOTS`, one per kernel running at once, held by a lock of the kernel manager), numbers
that no account or group may use (checked at start, :func:`problem`). The launcher calls
``setgroups([])``, drops every capability from the bounding set, ``setresgid``/``setresuid``
(which clear the permitted, effective and ambient sets), sets ``PR_SET_NO_NEW_PRIVS`` and the
limits of :data:`instructor.grading.sandbox.LIMITS`, which bind a user that is not root
(``RLIMIT_NPROC`` counts every process of that uid). The kernel gets a fresh empty home (and
``TMPDIR`` inside it) owned by that uid, mode 0700, removed with every file the uid left in the
shared temporary folders (:data:`SHARED_TMP`) once the kernel stops, after every process of that uid
is killed (``kill(-1, SIGKILL)`` sent as that uid, :func:`kill_all`: a child that left the kernel's
process group ends too).

What it may read is decided by permissions, checked empirically before any submission runs:

- it must reach the Python installation, the environment and a read-only copy of the
  installed ``course_lib`` (:func:`lib_copy`; the copy, so that an editable install inside the
  instructor's repository needs no change of modes): :func:`problem` opens, in a child that
  has dropped to :data:`PROBE_ID` (an "other" like the kernel's uid, never a kernel's), the
  Python, its standard library and the packages the
  kernel needs;
  where a folder on the way is closed to others (a Python under ``/root``, mode 0700), it
  refuses and names the folder and the ``chmod`` that opens it;
- it must read and write nothing in the hidden folders (the course directory with
  ``source/``, ``gradebook.db``, ``submitted/`` and ``autograded/``, the repository or
  Gradescope's ``source/`` with ``instructor/answers``, the instructor's notebooks and the
  grader's code): :func:`hidden_problem` walks them as root, keeps every path whose modes let
  "others" through (the kernel is neither owner nor in any group), adds the first entries of
  each folder whatever their modes, and a child process that has dropped to :data:`PROBE_ID`
  tries to list, open, open for writing and create in each of them. One success and the
  grader refuses, naming the path and the ``chmod`` that closes it.
"""

from __future__ import annotations

import ctypes
import errno
import fcntl
import grp
import json
import os
import pwd
import shutil
import signal
import stat
import sys
import tempfile
import time
from functools import cache
from pathlib import Path

__all__ = [
    "KERNEL_ID",
    "PROBE_ID",
    "SLOTS",
    "problem",
    "hidden_problem",
    "lib_copy",
    "slot_lock",
    "acquire_slot",
    "kill_all",
    "make_home",
    "clean",
    "drop",
]

#: uid = gid of the kernel in slot 0; slot n uses KERNEL_ID + n. In Debian's range 60000-64999
#: (no distribution's default account) and below 65536 (a container's user namespace usually
#: maps 0-65535 only). An account or group with one of these numbers makes privdrop refuse.
KERNEL_ID = 60500
SLOTS = 16
#: The uid of the checks made before grading (can that uid start Python, reach a hidden
#: folder?): the first number after the slots, never a kernel's, so a check run by one grader
#: never shares a uid with a student's kernel of another (nor is killed by its clean-up).
#: Every check is about what *others* may do: any uid without an account or a group answers
#: it alike.
PROBE_ID = KERNEL_ID + SLOTS
#: World-writable folders where the kernel's uid may leave files: emptied of them after it.
SHARED_TMP = ("/tmp", "/var/tmp", "/dev/shm", "/run/lock")
#: Where the slot locks live (root only); the first that can be made.
LOCK_DIRS = ("/run/rotations-grader", os.path.join(tempfile.gettempdir(), "rotations-grader"))
#: Modules the kernel imports: they must be found and readable as the kernel's uid.
MODULES = ("ipykernel", "zmq", "numpy", "sympy", "matplotlib")
PR_SET_NO_NEW_PRIVS = 38
PR_CAPBSET_DROP = 24
PROBE_LIMIT = 3000  # paths walked per hidden folder, at most


def _closed_ancestor(path):
    """The first folder on the way to ``path`` that others cannot pass (no ``o+x``), or None."""
    path = Path(os.path.realpath(path))
    for folder in [*reversed(path.parents), path]:
        try:
            mode = os.stat(folder).st_mode
        except OSError:
            return None
        if stat.S_ISDIR(mode) and not mode & stat.S_IXOTH:
            return folder
    return None


def _accounts():
    for uid in range(KERNEL_ID, PROBE_ID + 1):
        for lookup, what in ((pwd.getpwuid, "user"), (grp.getgrgid, "group")):
            try:
                name = lookup(uid)
            except KeyError:
                continue
            return f"the {what} {name[0]!r} has id {uid}, which the kernel would use"
    return None


def _needed(python):
    """The files the kernel's Python must open: itself, its standard library, the packages."""
    import importlib.util
    import sysconfig

    files = [os.path.realpath(python), os.path.join(sysconfig.get_path("stdlib"), "os.py")]
    files.append(os.path.join(sys.prefix, "pyvenv.cfg") if sys.prefix != sys.base_prefix else "")
    for name in MODULES:
        spec = importlib.util.find_spec(name)
        files.append(spec.origin if spec and spec.origin else f"<{name} not installed>")
    return [f for f in files if f]


def _opens(python, files):
    """As the kernel's uid: which of ``files`` it cannot open (and run, for ``python``)."""
    bad = []
    for path in files:
        try:
            with open(path, "rb") as f:
                f.read(1)
        except OSError as err:
            bad.append(f"{path}: {err.strerror}")
    if not os.access(python, os.X_OK):  # the real uid is the kernel's here: a real check
        bad.append(f"{python}: not executable")
    return bad


@cache
def problem(python=sys.executable):
    """Why the privilege drop cannot confine a kernel here, or None when it can: the grader
    must run as root, the kernel's ids must be free, and ``python``, its standard library and
    the packages of the kernel must open as the kernel's uid (tried, in a child process that
    has dropped to that uid)."""
    if os.geteuid() != 0:
        return "the grader is not root (only root can start the kernel as another user)"
    taken = _accounts()
    if taken:
        return taken
    for place in (python, sys.base_prefix, sys.prefix):
        closed = _closed_ancestor(place)
        if closed is not None:
            return (
                f"the kernel's user (uid {PROBE_ID}) cannot reach {place}: {closed} is closed "
                f"to other users (mode {os.stat(closed).st_mode & 0o777:o}); run "
                f"`chmod o+x {closed}` (it lets others pass, not list), or install Python "
                "and the environment outside it"
            )
    files = _needed(python)
    try:
        bad = _as_uid(PROBE_ID, lambda: _opens(python, files))
    except OSError as err:
        return f"setuid to {PROBE_ID} failed here: {err}"
    if bad:
        return f"as uid {PROBE_ID}, the kernel's Python cannot be read: {'; '.join(bad[:3])}"
    return None


def _inside(path, folder):
    path, folder = os.path.abspath(path), os.path.abspath(folder)
    return path == folder or path.startswith(folder.rstrip(os.sep) + os.sep)


def _candidates(top, expose, limit=PROBE_LIMIT):
    """Paths under ``top`` to try as the kernel's uid: every one whose modes let others read
    or write it along a way others can pass, and the first entries of each folder walked."""
    out, stack, seen = [top], [top], 0
    while stack and seen < limit:
        folder = stack.pop()
        try:
            if not os.lstat(folder).st_mode & stat.S_IXOTH:
                continue  # nothing below can be reached by others
            entries = list(os.scandir(folder))
        except OSError:
            continue
        for number, entry in enumerate(entries):
            seen += 1
            if any(_inside(entry.path, x) or _inside(x, entry.path) for x in expose):
                if not any(_inside(entry.path, x) for x in expose):
                    stack.append(entry.path)  # on the way to an exposed folder: walk it
                continue
            try:
                mode = entry.stat(follow_symlinks=False).st_mode
            except OSError:
                continue
            if number < 8 or mode & (stat.S_IROTH | stat.S_IWOTH):
                out.append(entry.path)
            if stat.S_ISDIR(mode):
                stack.append(entry.path)
    return out


def _as_uid(uid, task):
    """``task()`` (JSON-able) run in a forked child that has dropped to ``uid``; its result.
    OSError when the child could not become ``uid``, or did not finish (killed, or the task
    raised): a child that gives no answer never counts as "nothing found"."""
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: system calls only, then _exit
        code = 3
        try:
            os.close(read)
            os.setgroups([])
            os.setresgid(uid, uid, uid)
            os.setresuid(uid, uid, uid)
            code = 4
            os.write(write, json.dumps(task()).encode())
            code = 0
        finally:
            os._exit(code)
    os.close(write)
    chunks = []
    while chunk := os.read(read, 65536):
        chunks.append(chunk)
    os.close(read)
    _, status = os.waitpid(pid, 0)
    code = os.waitstatus_to_exitcode(status)
    if code == 3:
        raise OSError(errno.EPERM, f"the child could not become uid {uid}")
    if code != 0:  # killed (a signal) or failed: its silence is no answer, never "nothing found"
        raise OSError(errno.ECHILD, f"the check as uid {uid} did not finish (status {code})")
    return json.loads(b"".join(chunks))


def _try_as(uid, paths):
    """In a child that has dropped to ``uid``: which of ``paths`` it can list, read, write or
    create in (a list of ``(path, what)``)."""
    return _as_uid(uid, lambda: [found for path in paths for found in _attempts(path)]) or []


def _attempts(path):
    found = []
    if os.path.isdir(path):
        try:
            os.listdir(path)
            found.append((path, "listed"))
        except OSError:
            pass
        probe = os.path.join(path, f".rotations-privdrop-probe-{os.getpid()}")
        try:
            os.close(os.open(probe, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600))
            os.unlink(probe)
            found.append((path, "created a file in"))
        except OSError:
            pass
        return found
    for flags, what in ((os.O_RDONLY, "read"), (os.O_WRONLY, "opened for writing")):
        try:
            fd = os.open(path, flags | os.O_NONBLOCK | os.O_NOFOLLOW)
            if flags == os.O_RDONLY:
                os.read(fd, 1)
            os.close(fd)
            found.append((path, what))
        except OSError:
            pass
    return found


@cache
def hidden_problem(hide, expose, uid=PROBE_ID):
    """Why the kernel's uid could read or write something in the folders ``hide`` (a tuple),
    or None: tried by a child process that has dropped to ``uid`` (see the module's text).
    Folders in ``expose`` (the Python, the environment) are left out of the walk."""
    expose = tuple(os.path.realpath(x) for x in expose)
    paths = []
    for top in hide:
        if os.path.lexists(top):
            paths += _candidates(os.path.realpath(top), expose)
    try:
        found = _try_as(uid, paths)
    except OSError as err:  # no answer is a refusal, never a pass
        return f"the hidden folders could not be checked as uid {uid}: {err}"
    if not found:
        return None
    lines = []
    for path, what in found[:5]:
        top = next(t for t in hide if _inside(path, os.path.realpath(t)))
        near = [x for x in expose if _inside(x, os.path.realpath(top))]
        fix = f"chmod o-rwx {path}" if near else f"chmod 700 {top}"
        lines.append(f"it {what} {path} (hidden folder {top}): run `{fix}`")
    more = f" (and {len(found) - 5} more)" if len(found) > 5 else ""
    return f"the kernel's user (uid {uid}) can reach hidden files: " + "; ".join(lines) + more


@cache
def lib_copy(lib):
    """A read-only copy of the package folder ``lib`` (the installed ``course_lib``, what
    students have), in a fresh folder others can read; removed when the grader exits."""
    top = tempfile.mkdtemp(prefix="rotations-lib-")
    dest = os.path.join(top, os.path.basename(lib))
    shutil.copytree(lib, dest, symlinks=False)
    for folder, _dirs, files in os.walk(top):
        os.chmod(folder, 0o755)
        for name in files:
            os.chmod(os.path.join(folder, name), 0o644)
    import atexit

    atexit.register(shutil.rmtree, top, True)
    return top


def slot_lock(n):
    """The lock file of slot ``n``, in the first folder of :data:`LOCK_DIRS` that can be made
    (root only, 0700)."""
    for folder in LOCK_DIRS:
        try:
            os.makedirs(folder, mode=0o700, exist_ok=True)
            os.chmod(folder, 0o700)
            break
        except OSError:
            continue
    return os.path.join(folder, f"slot-{n}.lock")


def acquire_slot():
    """A free slot: ``(uid, lock file descriptor)``; the lock is held until the descriptor is
    closed (:func:`clean`). Leftover processes of that uid are killed first."""
    for n in range(SLOTS):
        fd = os.open(slot_lock(n), os.O_RDWR | os.O_CREAT, 0o600)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            os.close(fd)
            continue
        kill_all(KERNEL_ID + n)
        return KERNEL_ID + n, fd
    raise RuntimeError(f"privdrop: all {SLOTS} kernel slots are in use")


def _pids(uid):
    """The live processes of ``uid`` (a zombie is dead already: its parent, or init, reaps it)."""
    out = []
    for entry in os.scandir("/proc"):
        if entry.name.isdigit():
            try:
                if entry.stat().st_uid != uid:
                    continue
                with open(f"/proc/{entry.name}/stat", "rb") as f:
                    state = f.read().rsplit(b")", 1)[1].split()[0]
            except (OSError, IndexError):
                continue
            if state not in (b"Z", b"X"):
                out.append(int(entry.name))
    return out


def kill_all(uid, seconds=10.0):
    """Kill every process of ``uid``: ``kill(-1, SIGKILL)`` sent by a child that is that uid
    (it reaches every process of the uid at once, a fork bomb's too), again until none is left
    or ``seconds`` have passed (a killed process can take a while to exit on a loaded machine:
    half a second was not always enough). Whether none is left."""
    deadline = time.monotonic() + seconds
    pause = 0.01
    while _pids(uid):
        if time.monotonic() > deadline:
            return False
        pid = os.fork()
        if pid == 0:
            try:
                os.setgroups([])
                os.setresgid(uid, uid, uid)
                os.setresuid(uid, uid, uid)
                os.kill(-1, signal.SIGKILL)
            finally:
                os._exit(0)
        os.waitpid(pid, 0)
        time.sleep(pause)
        pause = min(2 * pause, 0.2)
    return True


def make_home(uid):
    """A fresh empty home for the kernel (``TMPDIR`` is its ``tmp``), owned by ``uid``, 0700."""
    home = tempfile.mkdtemp(prefix="rotations-home-")
    os.makedirs(os.path.join(home, "tmp"), mode=0o700)
    for path in (home, os.path.join(home, "tmp")):
        os.chown(path, uid, uid)
        os.chmod(path, 0o700)
    return home


def clean(uid, home, lock_fd):
    """After the kernel: its processes killed, its home and its files in :data:`SHARED_TMP`
    removed, its slot freed. A uid with a process left is not freed: the slot stays taken (for
    as long as this process lives) rather than hand the next student's kernel a uid that a
    process of the last one still runs as."""
    if not kill_all(uid):
        print(
            f"privdrop: processes of uid {uid} outlived SIGKILL for 10 s; its slot is not reused",
            file=sys.stderr,
        )
        lock_fd = None
    shutil.rmtree(home, ignore_errors=True)
    for shared in SHARED_TMP:
        try:
            entries = list(os.scandir(shared))
        except OSError:
            continue
        for entry in entries:
            try:
                if entry.stat(follow_symlinks=False).st_uid != uid:
                    continue
                if entry.is_dir(follow_symlinks=False):
                    shutil.rmtree(entry.path, ignore_errors=True)
                else:
                    os.unlink(entry.path)
            except OSError:
                pass
    if lock_fd is not None:
        os.close(lock_fd)


def drop(uid):
    """Become ``uid`` for good (the launcher, just before ``execve`` of the kernel)."""
    libc = ctypes.CDLL(None, use_errno=True)
    os.setgroups([])
    for cap in range(64):  # needs CAP_SETPCAP (Docker's root has it); EINVAL past the last
        if libc.prctl(PR_CAPBSET_DROP, cap, 0, 0, 0) != 0 and ctypes.get_errno() == errno.EINVAL:
            break
    os.setresgid(uid, uid, uid)
    os.setresuid(uid, uid, uid)
    if libc.prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0:
        raise OSError(ctypes.get_errno(), "prctl(PR_SET_NO_NEW_PRIVS)")
    if os.getresuid() != (uid,) * 3 or os.getresgid() != (uid,) * 3 or os.getgroups():
        raise OSError("privdrop: the ids did not change")
