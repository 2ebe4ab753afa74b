"""The confined kernel that runs a submission at ``nbgrader autograde``.

:class:`ConfinedKernelManager` ignores the kernel a notebook names and starts ipykernel under
Debian's ``bubblewrap`` (``bwrap``) with an **allow-list** view of the machine:

- the root is an empty, read-only tmpfs; only what the kernel needs is mounted into it,
  read-only: the system (``/usr`` and the ``/bin``, ``/lib*`` links), a few files of ``/etc``
  (:data:`ETC`), the Python installation (``sys.base_prefix``) and environment
  (``sys.prefix``, with its ``site-packages``) and the folder of the installed ``course_lib``
  package (for an editable install, that folder only: never ``tools/`` or the repository).
  Home folders, other checkouts, nbgrader's exchange, Jupyter's runtime folder (the connection
  files of other kernels) and the course directory do not exist in the kernel's view;
- the only writable places are a size-limited tmpfs ``/tmp`` (:data:`TMP_BYTES`; the kernel's
  working directory ``/tmp/work`` and its ``HOME``), a size-limited tmpfs ``/dev/shm``
  (:data:`SHM_BYTES`; the rest of the private ``/dev`` is read-only) and the kernel's own
  scratch folder (its connection file and ipc sockets), made afresh for each kernel and, for
  a grader run as root, sealed once the kernel is ready
  (:meth:`ConfinedKernelManager.seal_scratch`);
- every namespace bwrap can unshare is new (``--unshare-all``: user, PID, network, IPC, UTS,
  cgroup): no network at all (the kernel talks to nbgrader over ipc sockets in the scratch
  folder, not TCP), and ``/proc`` is the sandbox's own (``/proc/1`` is its init); every
  capability is dropped; the kernel gets a new session and dies with the ``bwrap`` process
  the kernel manager stops (``--die-with-parent``);
- the environment is cleared (bwrap's own too, so ``/proc/1/environ`` holds nothing of the
  grader's): only :func:`kernel_env`;
- resource limits (:data:`LIMITS`): address space, file size, processes (the process limit
  does not bind a kernel run by root: Linux exempts the host's uid 0, and bwrap's ``--uid``
  inside does not change it; tested), no core files;
- Python starts with ``-P`` (the working directory is not put on ``sys.path``), imports the
  installed ``course_lib`` before any cell runs: a ``course_lib/`` folder handed in beside the
  notebook is never seen.

Run as ``python sandbox.py --scratch DIR --expose DIR ... -- -f FILE`` (the kernel manager
does); it only uses the standard library.

**Where bubblewrap cannot start** and the grader runs as root (Gradescope's Docker container,
any container whose seccomp profile refuses user namespaces, a root hub), the kernel is
confined by a privilege drop instead (:mod:`instructor.grading.privdrop`: a dedicated unprivileged
uid, an empty home, the same cleared environment and limits, the hidden folders closed to it by
permissions checked at start). :func:`confinement` says which confinement is used here.

**With neither** (macOS, Windows, a Linux machine without bubblewrap or user namespaces where
the grader is not root) there is no confinement: :func:`confinement_problem` says why, and
``nbgrader autograde`` refuses to run students' code
(:class:`instructor.grading.preprocessor.ConfinedExporter`) unless the instructor opts in with
``ConfinedKernelManager.unconfined = True``. Then the kernel runs as the instructor
(``--unconfined``): the same cleared environment, ``-P``, the installed ``course_lib``
imported first and the address-space and file-size limits, but it can read and write
whatever the instructor can.
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import subprocess
import sys
import tempfile
from functools import cache
from pathlib import Path

__all__ = [
    "ConfinedKernelManager",
    "bwrap_command",
    "bubblewrap_problem",
    "confinement",
    "confinement_problem",
    "kernel_env",
    "BOOT",
    "INSTALL",
    "LIMITS",
]

SCRATCH = "/tmp/work"
TMP_BYTES = 256 * 2**20
#: The sandbox's /dev/shm (POSIX shared memory, multiprocessing's semaphores): a tmpfs of its own.
SHM_BYTES = 64 * 2**20
#: Owner of the kernel's scratch folder once the kernel is ready (grader run as root): not the
#: kernel's uid, so the kernel (no capabilities) can neither write there nor chmod it back.
SEAL_UID = 65534
#: Resource limits of the kernel (soft = hard).
LIMITS = {
    "RLIMIT_AS": 4 * 2**30,
    "RLIMIT_FSIZE": 64 * 2**20,
    "RLIMIT_NPROC": 64,
    "RLIMIT_CORE": 0,
    "RLIMIT_NOFILE": 1024,
    # CPU seconds of each process (SIGXCPU, then SIGKILL): above any notebook's honest run and
    # the Gradescope run's 480 s budget, so it only ends a kernel that spins past every limit
    "RLIMIT_CPU": 900,
}
#: The confinements, in the order they are tried; $ROTATIONS_CONFINEMENTS (a comma list) may
#: leave some out (never add one, never allow unconfined grading).
KINDS = ("bubblewrap", "privdrop")
#: How to install bubblewrap, for the messages that say it is missing.
INSTALL = "sudo apt-get install bubblewrap (Debian, Ubuntu; Fedora: sudo dnf install bubblewrap)"
#: The system folders mounted read-only (or re-created as the same symbolic links).
SYSTEM = ("/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32")
#: The files of /etc the kernel may read (no secrets: the loader, time zone, users, fonts).
ETC = ("ld.so.cache", "ld.so.conf", "ld.so.conf.d", "localtime", "passwd", "group")
ETC += ("nsswitch.conf", "alternatives", "fonts", "mime.types")
#: What the kernel runs first: the installed course_lib, then ipykernel.
BOOT = (
    "import sys\n"
    "sys.path[:] = [p for p in sys.path if p not in ('', '.')]\n"
    "import course_lib, course_lib.exercises, course_lib.record\n"
    "from ipykernel.kernelapp import launch_new_instance\n"
    "launch_new_instance()\n"
)


def kernel_env(path=(), prefix=sys.prefix, work=SCRATCH, student=""):
    """The kernel's whole environment (``work``: its working directory and ``HOME``;
    ``student``: the course's key of the submission's student, as ``COURSE_GRADER_ID``, so
    that the submission's own checks use that student's exercise variants, as the grader does,
    whatever id the notebook sets)."""
    env = {
        "PATH": f"{prefix}/bin:/usr/bin:/bin",
        "LANG": "C.UTF-8",
        "HOME": work,
        "IPYTHONDIR": f"{work}/.ipython",
        "MPLCONFIGDIR": f"{work}/.matplotlib",
        "PYTHONSAFEPATH": "1",
        "PYTHONDONTWRITEBYTECODE": "1",
        "JUPYTER_RUNTIME_DIR": f"{work}/.runtime",
        "PYTHONPATH": os.pathsep.join(path),
        # one BLAS/OpenMP thread: RLIMIT_NPROC counts threads too, and the course's matrices
        # are small (OpenBLAS starts a thread per core, and fails where the limit binds)
        "OMP_NUM_THREADS": "1",
        "OPENBLAS_NUM_THREADS": "1",
    }
    if student:  # the grader's id wins over the notebook's set_student_id()
        env["COURSE_GRADER_ID"] = student
    return env


@cache
def _choice():
    allowed = os.environ.get("ROTATIONS_CONFINEMENTS", ",".join(KINDS)).split(",")
    why = []
    for kind in KINDS:
        if kind not in allowed:
            why.append(f"{kind}: left out by ROTATIONS_CONFINEMENTS")
            continue
        problem = bubblewrap_problem() if kind == "bubblewrap" else _privdrop().problem()
        if problem is None:
            return kind, None
        why.append(f"{kind}: {problem}")
    return None, "; ".join(why)


def confinement():
    """Which confinement runs a student's kernel here: ``"bubblewrap"`` when bwrap can make
    its sandbox, else ``"privdrop"`` when the grader is root and can start the kernel's Python
    as the kernel's unprivileged uid (:mod:`instructor.grading.privdrop`), else None
    (:func:`confinement_problem` says why).

    Examples
    --------
    >>> confinement() in ("bubblewrap", "privdrop", None)
    True
    """
    return _choice()[0]


def confinement_problem():
    """Why no confinement can start on this machine (each one's reason), or None when one can.

    Examples
    --------
    >>> (confinement_problem() is None) == (confinement() is not None)
    True
    """
    return _choice()[1]


def hidden_problem(hide):
    """Privdrop only: why the kernel's uid could reach something in the folders ``hide``, or
    None (tried as that uid, :func:`instructor.grading.privdrop.hidden_problem`); the Python, the
    environment and the kernel's copy of the installed ``course_lib`` are exposed."""
    import course_lib

    privdrop = _privdrop()
    copy = privdrop.lib_copy(str(Path(course_lib.__file__).resolve().parent))
    return privdrop.hidden_problem(tuple(hide), (sys.base_prefix, sys.prefix, copy)), copy


def _privdrop():
    try:
        from . import privdrop
    except ImportError:  # run as a script (the kernel's launcher)
        import privdrop
    return privdrop


@cache
def bubblewrap_problem():
    """Why bubblewrap cannot start its sandbox on this machine, or None when it can.

    bubblewrap must be on ``PATH`` and able to make the sandbox's namespaces here (a kernel
    may forbid unprivileged user namespaces, a container's seccomp profile refuses them: bwrap
    is then installed but fails).

    Examples
    --------
    >>> bubblewrap_problem() is None or "bwrap" in bubblewrap_problem()
    True
    """
    bwrap = shutil.which("bwrap")
    if bwrap is None:
        return "bwrap is not on PATH"
    probe = [bwrap, "--unshare-all", "--die-with-parent", "--ro-bind", "/", "/"]
    probe += ["--proc", "/proc", "--dev", "/dev", sys.executable, "-S", "-c", ""]
    try:
        done = subprocess.run(probe, capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.SubprocessError) as exc:
        return f"bwrap could not be started: {exc}"
    if done.returncode != 0:
        why = (done.stderr.strip().splitlines() or ["no message"])[-1][:200]
        return f"bwrap is installed but cannot make a sandbox here: {why}"
    return None


def _system():
    out = []
    for folder in SYSTEM:
        if os.path.islink(folder):
            out += ["--symlink", os.readlink(folder), folder]
        elif os.path.isdir(folder):
            out += ["--ro-bind", folder, folder]
    for name in ETC:
        out += ["--ro-bind-try", f"/etc/{name}", f"/etc/{name}"]
    return out


def bwrap_command(expose, scratch, kernel_args, python=sys.executable, path=(), student=""):
    """The ``bwrap`` argv that starts ipykernel confined (see the module's docstring).

    ``expose``: folders mounted read-only; ``scratch``: the kernel's own folder (connection
    file, ipc sockets), mounted writable at the same path; ``kernel_args``: ipykernel's.
    """
    cmd = [shutil.which("bwrap") or "bwrap", "--unshare-all", "--hostname", "grading"]
    cmd += ["--die-with-parent", "--new-session", "--cap-drop", "ALL", "--clearenv"]
    cmd += _system()
    cmd += ["--proc", "/proc", "--dev", "/dev"]
    # bwrap's /dev is a tmpfs of half the RAM: a sized /dev/shm, and /dev itself read-only
    cmd += ["--size", str(SHM_BYTES), "--tmpfs", "/dev/shm", "--remount-ro", "/dev"]
    cmd += ["--size", str(TMP_BYTES), "--tmpfs", "/tmp"]
    # after the tmpfs: a venv or checkout that lives under /tmp (a CI clone) stays visible
    for folder in expose:
        cmd += ["--ro-bind", folder, folder]
    cmd += ["--bind", str(scratch), str(scratch), "--dir", SCRATCH, "--chdir", SCRATCH]
    cmd += ["--remount-ro", "/"]
    for key, value in kernel_env(path, student=student).items():
        cmd += ["--setenv", key, value]
    return cmd + ["--", python, "-P", "-c", BOOT, *kernel_args]


def _limit(unconfined=False):
    for name, value in LIMITS.items():
        if unconfined and name == "RLIMIT_NPROC":
            continue  # counted over all the instructor's processes, not the kernel's own
        try:
            resource.setrlimit(getattr(resource, name), (value, value))
        except (ValueError, OSError) as exc:  # macOS refuses some (RLIMIT_AS)
            if not unconfined:
                raise
            print(f"instructor.grading.sandbox: {name} not set here: {exc}", file=sys.stderr)


def _exec_unconfined(scratch, kernel, python, path, student=""):
    """The kernel without bubblewrap (the instructor opted in): it runs as the instructor."""
    work = os.path.join(scratch, "work")
    os.makedirs(work, exist_ok=True)
    os.chdir(work)
    _limit(unconfined=True)
    env = kernel_env(path, work=work, student=student)
    os.execve(python, [python, "-P", "-c", BOOT, *kernel], env)


def _exec_privdrop(args, kernel):
    """The kernel as the unprivileged ``args.privdrop_uid``
    (:mod:`instructor.grading.privdrop`); root."""
    uid, home = args.privdrop_uid, args.home
    # the scratch folder: the kernel reads its connection file and binds its ipc sockets there
    # until it answers, then the kernel manager seals it (seal_scratch)
    os.chown(args.scratch, 0, uid)
    os.chmod(args.scratch, 0o1770)
    connection = kernel[kernel.index("-f") + 1]
    os.chown(connection, 0, uid)
    os.chmod(connection, 0o640)
    os.chdir(home)
    _limit()
    _privdrop().drop(uid)
    os.umask(0o077)
    env = kernel_env(args.pythonpath, work=home, student=args.student_id)
    env["TMPDIR"] = os.path.join(home, "tmp")
    os.execve(args.python, [args.python, "-P", "-c", BOOT, *kernel], env)


def main(argv=None):
    """Replace this process with the confined kernel (the kernel manager stops bwrap)."""
    parser = argparse.ArgumentParser(description="start ipykernel under bubblewrap")
    parser.add_argument("--expose", action="append", default=[])
    parser.add_argument("--scratch", required=True)
    parser.add_argument("--python", default=sys.executable)
    parser.add_argument("--pythonpath", action="append", default=[])
    parser.add_argument("--unconfined", action="store_true", help="no bubblewrap (opted in)")
    parser.add_argument("--student-id", default="", help="nbgrader's student id of the work")
    parser.add_argument("--privdrop-uid", type=int, help="no bubblewrap: run as this uid")
    parser.add_argument("--home", help="the kernel's home (--privdrop-uid)")
    parser.add_argument("kernel", nargs=argparse.REMAINDER)
    args = parser.parse_args(argv)
    kernel = args.kernel[1:] if args.kernel[:1] == ["--"] else args.kernel
    quiet = os.open(os.devnull, os.O_WRONLY)  # ipykernel's banner; errors still go to stderr
    if args.privdrop_uid is not None:
        os.dup2(quiet, 1)
        _exec_privdrop(args, kernel)
    if args.unconfined:
        os.dup2(quiet, 1)
        _exec_unconfined(args.scratch, kernel, args.python, args.pythonpath, args.student_id)
    if shutil.which("bwrap") is None:
        print(f"instructor.grading.sandbox: bwrap not found: {INSTALL}", file=sys.stderr)
        return 2
    os.dup2(quiet, 1)
    cmd = bwrap_command(
        args.expose, args.scratch, kernel, args.python, args.pythonpath, args.student_id
    )
    _limit()
    # bwrap is the sandbox's PID 1: its environment must hold nothing of the grader's either
    os.execve(cmd[0], cmd, {"PATH": "/usr/bin:/bin", "LANG": "C.UTF-8"})
    return 1  # not reached


if __name__ == "__main__":
    sys.exit(main())
else:  # imported by nbgrader (the instructor's process): the kernel manager
    from jupyter_client import AsyncKernelManager
    from jupyter_client.kernelspec import KernelSpec
    from traitlets import Bool, List, Unicode
    from traitlets.config.loader import DeferredConfig

    class ConfinedKernelManager(AsyncKernelManager):
        """A kernel manager that always starts the confined kernel, whatever the notebook's
        kernelspec says (nbgrader's ``Execute`` reads the notebook's; this one does not).
        It talks to the kernel over ipc sockets in a fresh private scratch folder."""

        hide = List(
            Unicode(),
            help="Folders the kernel must never see: under bubblewrap, exposing a folder that "
            "holds one, or is inside one (but for the installed course_lib and the Python "
            "environment), is an error; under privdrop, each is tried as the kernel's uid at "
            "start, and one it can list, read or write is an error naming the chmod to run.",
        ).tag(config=True)
        unconfined = Bool(
            False,
            help="Run the kernel without bubblewrap: students' code runs as you and can read "
            "and change whatever you can (the solutions, the gradebook). Only for a machine "
            "without bubblewrap, and work you trust (docs/grading.md).",
        ).tag(config=True)
        #: The course's key of the submission's student (set by ConfinedExecute): the kernel's
        #: ``COURSE_GRADER_ID``, so the submission's checks use that student's variants.
        student = Unicode("")

        @classmethod
        def unconfined_in(cls, config):
            """Whether traitlets ``config`` opts in to unconfined grading (from a config file,
            or the command line, where the value arrives as text)."""
            value = config.get(cls.__name__, {}).get("unconfined", False)
            if isinstance(value, DeferredConfig):
                value = value.get_value(cls.class_traits()["unconfined"])
            return value is True

        def __init__(self, **kwargs):
            kwargs["transport"] = "ipc"
            super().__init__(**kwargs)
            self.scratch = tempfile.mkdtemp(prefix="rotations-kernel-")
            self.connection_file = os.path.join(self.scratch, "kernel.json")
            self.ip = os.path.join(self.scratch, "ipc")

        def _expose(self):
            import course_lib

            lib = Path(course_lib.__file__).resolve().parent
            paths = {Path(sys.base_prefix).resolve(), Path(sys.prefix).absolute(), lib}
            for path in paths:
                for folder in self.hide:
                    if _inside(folder, path) and path != lib:
                        raise ValueError(f"confined kernel: {path} holds hidden {folder}")
            return sorted(str(p) for p in paths)

        @property
        def kind(self):
            """The confinement of this kernel: "bubblewrap", "privdrop" or "unconfined"."""
            if self.unconfined:
                return "unconfined"
            kind = confinement()
            if kind is None:
                raise RuntimeError(f"no confinement for the kernel here: {confinement_problem()}")
            return kind

        @property
        def kernel_spec(self):
            if self._kernel_spec is None:
                import course_lib

                argv = [sys.executable, str(Path(__file__).resolve())]
                lib = Path(course_lib.__file__).resolve().parent
                if self.kind == "privdrop":
                    argv += self._privdrop_args()
                else:
                    argv += [f"--expose={p}" for p in self._expose()]
                    argv += [f"--pythonpath={lib.parent}"]
                argv += ["--python", sys.executable]
                argv += [f"--scratch={self.scratch}"] + ["--unconfined"] * self.unconfined
                argv += [f"--student-id={self.student}"] * bool(self.student)
                argv += ["--", "-f", "{connection_file}"]
                self._kernel_spec = KernelSpec(
                    argv=argv,
                    display_name=f"Python 3 (confined: {self.kind})",
                    language="python",
                    interrupt_mode="message",
                    env={},
                )
            return self._kernel_spec

        def _privdrop_args(self):
            """The hidden folders checked as the kernel's uid (refused: RuntimeError), a slot,
            a fresh home; the launcher's arguments."""
            privdrop = _privdrop()
            problem, copy = hidden_problem(self.hide)
            if problem:
                raise RuntimeError(f"privdrop confinement refused: {problem}")
            self._uid, self._lock = privdrop.acquire_slot()
            self._home = privdrop.make_home(self._uid)
            return [f"--privdrop-uid={self._uid}", f"--home={self._home}", f"--pythonpath={copy}"]

        def seal_scratch(self):
            """Once the kernel has bound its ipc sockets (it answered ``kernel_info``): the
            scratch folder and its files are given to :data:`SEAL_UID`, read-only, when the
            grader runs as root. The kernel (uid 0 inside, every capability dropped) can then
            not write there (it was a writable host folder on the host's disk, no size limit),
            nor chmod it back; nbgrader (root) still reaches the sockets and removes the
            folder. Returns whether it was sealed (as another user, the kernel is that user:
            only ``RLIMIT_FSIZE`` bounds what it writes there)."""
            if os.geteuid() != 0:
                return False
            for entry in os.scandir(self.scratch):
                os.chown(entry.path, SEAL_UID, SEAL_UID, follow_symlinks=False)
                if entry.is_file(follow_symlinks=False):
                    os.chmod(entry.path, 0o400)
            os.chown(self.scratch, SEAL_UID, SEAL_UID)
            os.chmod(self.scratch, 0o555)
            return True

        async def _async_cleanup_resources(self, restart=False):
            await super()._async_cleanup_resources(restart=restart)
            if not restart:
                shutil.rmtree(self.scratch, ignore_errors=True)
                if getattr(self, "_lock", None) is not None:  # privdrop: its uid's processes,
                    _privdrop().clean(self._uid, self._home, self._lock)  # home, slot
                    self._lock = None

        cleanup_resources = _async_cleanup_resources


def _inside(path, folder):
    path, folder = os.path.abspath(path), os.path.abspath(folder)
    return path == folder or path.startswith(folder.rstrip(os.sep) + os.sep)
