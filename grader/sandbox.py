"""The confined kernel that runs a submission at ``nbgrader autograde``.

:class:`ConfinedKernelManager` ignores the kernel a notebook names and starts ipykernel under
Debian's ``bubblewrap`` (``bwrap``):

- the whole file system is mounted **read-only** (``--ro-bind / /``), and the only writable
  places are fresh, empty tmpfs: ``/tmp`` (the kernel's working directory ``/tmp/work``, its
  ``HOME``) and a private ``/dev``;
- the instructor's folders (:attr:`ConfinedKernelManager.hide`: the course directory with
  ``source/``, ``release/``, ``submitted/``, ``autograded/`` and ``gradebook.db``, and the
  repository with ``tools/solutions``) are covered by empty, read-only tmpfs; only the installed
  ``course_lib`` and the Python environment are mounted back, read-only;
- the kernel runs in new PID, IPC and UTS namespaces (``--unshare-pid``), with every
  capability dropped (so even as root it cannot unmount what covers the instructor's folders),
  and dies with the ``bwrap`` process the kernel manager stops (``--die-with-parent``);
- Python starts with ``-P`` (the working directory is not put on ``sys.path``), imports the
  installed ``course_lib`` before any cell runs, and its working directory is the empty
  scratch folder: a ``course_lib/`` folder handed in beside the notebook is never seen.

The connection file is handed in as a copy (``--file``), so the kernel writes nothing outside
its scratch folder. Run as ``python sandbox.py --hide DIR ... --expose DIR ... -- -f FILE``
(the kernel manager does); it only uses the standard library, since the repository that holds
it is hidden from the kernel.
"""

from __future__ import annotations

import argparse
import os
import shutil
import sys
from pathlib import Path

__all__ = ["ConfinedKernelManager", "bwrap_command", "BOOT"]

SCRATCH = "/tmp/work"
#: What the kernel runs first: the installed course_lib, then ipykernel.
BOOT = (
    "import sys\n"
    "sys.path[:] = [p for p in sys.path if p not in ('', '.')]\n"
    "import course_lib, course_lib.exercises, course_lib.record\n"
    "from ipykernel.kernelapp import launch_new_instance\n"
    "launch_new_instance()\n"
)


def bwrap_command(hide, expose, connection_fd, kernel_args, python=sys.executable, path=()):
    """The ``bwrap`` argv that starts ipykernel confined (see the module's docstring)."""
    cmd = [shutil.which("bwrap") or "bwrap", "--ro-bind", "/", "/", "--dev", "/dev"]
    cmd += ["--proc", "/proc", "--tmpfs", "/tmp"]
    for folder in hide:
        cmd += ["--tmpfs", folder]
    for folder in expose:
        cmd += ["--ro-bind", folder, folder]
    for folder in hide:  # empty and read-only (after the mount points above were made)
        cmd += ["--remount-ro", folder]
    cmd += ["--dir", SCRATCH, "--chdir", SCRATCH, "--file", str(connection_fd), "/tmp/kernel.json"]
    cmd += ["--unshare-pid", "--unshare-ipc", "--unshare-uts", "--die-with-parent"]
    cmd += ["--new-session", "--cap-drop", "ALL"]
    env = {
        "HOME": SCRATCH,
        "IPYTHONDIR": f"{SCRATCH}/.ipython",
        "MPLCONFIGDIR": f"{SCRATCH}/.matplotlib",
        "PYTHONSAFEPATH": "1",
        "PYTHONDONTWRITEBYTECODE": "1",
        "JUPYTER_RUNTIME_DIR": f"{SCRATCH}/.runtime",
        "PYTHONPATH": os.pathsep.join(path),
    }
    for key, value in env.items():
        cmd += ["--setenv", key, value]
    # jupyter_client's PID means nothing in the kernel's PID namespace: --die-with-parent
    # ends the kernel with bwrap instead of ipykernel's parent poller.
    cmd += ["--unsetenv", "JPY_PARENT_PID"]
    return cmd + ["--", python, "-P", "-c", BOOT, "-f", "/tmp/kernel.json", *kernel_args]


def _split_kernel_args(args):
    """The connection file (after ``-f``) and the other kernel arguments."""
    out, connection, it = [], None, iter(args)
    for arg in it:
        if arg == "-f":
            connection = next(it)
        elif arg.startswith("--f="):
            connection = arg[4:]
        else:
            out.append(arg)
    return connection, out


def main(argv=None):
    """Replace this process with the confined kernel (the kernel manager stops bwrap)."""
    parser = argparse.ArgumentParser(description="start ipykernel under bubblewrap")
    parser.add_argument("--hide", action="append", default=[])
    parser.add_argument("--expose", action="append", default=[])
    parser.add_argument("--python", default=sys.executable)
    parser.add_argument("--pythonpath", action="append", default=[])
    parser.add_argument("kernel", nargs=argparse.REMAINDER)
    args = parser.parse_args(argv)
    kernel = args.kernel[1:] if args.kernel[:1] == ["--"] else args.kernel
    connection, rest = _split_kernel_args(kernel)
    if shutil.which("bwrap") is None:
        print("grader.sandbox: bwrap not found (apt-get install -y bubblewrap)", file=sys.stderr)
        return 2
    fd = os.open(connection, os.O_RDONLY)
    os.set_inheritable(fd, True)
    quiet = os.open(os.devnull, os.O_WRONLY)  # ipykernel's banner; errors still go to stderr
    os.dup2(quiet, 1)
    cmd = bwrap_command(args.hide, args.expose, fd, rest, python=args.python, path=args.pythonpath)
    os.execv(cmd[0], cmd)
    return 1  # not reached


if __name__ == "__main__":
    sys.exit(main())
else:  # imported by nbgrader (the instructor's process): the kernel manager
    from jupyter_client import AsyncKernelManager
    from jupyter_client.kernelspec import KernelSpec
    from traitlets import List, Unicode

    class ConfinedKernelManager(AsyncKernelManager):
        """A kernel manager that always starts the confined kernel, whatever the notebook's
        kernelspec says (nbgrader's ``Execute`` reads the notebook's; this one does not)."""

        hide = List(
            Unicode(),
            help="Folders the kernel must not see (covered by empty tmpfs).",
        ).tag(config=True)

        def _expose(self):
            import course_lib

            paths = {str(Path(course_lib.__file__).resolve().parent), str(Path(sys.prefix))}
            return sorted(p for p in paths if any(_inside(p, h) for h in self.hide))

        @property
        def kernel_spec(self):
            if self._kernel_spec is None:
                argv = [sys.executable, str(Path(__file__).resolve())]
                argv += [f"--hide={os.path.abspath(h)}" for h in self.hide]
                argv += [f"--expose={p}" for p in self._expose()]
                import course_lib

                lib = Path(course_lib.__file__).resolve().parent
                argv += [f"--pythonpath={lib.parent}", "--python", sys.executable]
                argv += ["--", "-f", "{connection_file}"]
                self._kernel_spec = KernelSpec(
                    argv=argv,
                    display_name="Python 3 (confined)",
                    language="python",
                    interrupt_mode="message",
                    env={},
                )
            return self._kernel_spec


def _inside(path, folder):
    path, folder = os.path.abspath(path), os.path.abspath(folder)
    return path == folder or path.startswith(folder.rstrip(os.sep) + os.sep)
