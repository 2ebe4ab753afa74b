"""Run a command as root under Docker's constraint: no new user namespace, no mount.

    /usr/bin/python3 tests/docker_seccomp.py [--view REPO KEEP...] -- COMMAND ARGS...
    /usr/bin/python3 tests/docker_seccomp.py --view-only REPO KEEP... -- COMMAND ARGS...

Docker's default seccomp profile refuses ``unshare(2)`` and ``clone(2)`` with a namespace flag
to a process without ``CAP_SYS_ADMIN``, root included (``EPERM``), and answers ``clone3(2)``
with ``ENOSYS`` (so that libc falls back to ``clone``); Docker also gives root only 14
capabilities. This launcher loads the same refusals with libseccomp's Python bindings
(Debian's ``python3-seccomp``, for the system Python: run it with ``/usr/bin/python3``),
drops from the capability bounding set every capability Docker does not grant, then
``execv``'s the command: the filter is inherited by every process it starts, across exec.
bubblewrap then cannot start (it needs a new user namespace), as in a Gradescope container.

``--view REPO KEEP...`` first lays out the file system as a Gradescope image has it, in a
mount namespace of the launcher's own (nothing changes outside it): ``/root`` becomes an empty
tmpfs into which only the folders ``KEEP`` under ``/root`` (the Python installation) are
mounted back, and REPO (the checkout, which holds the environment ``REPO/.venv``) is overlaid
so that others may pass it but not list it, and may not enter anything in it but ``.venv``
(on Gradescope the environment is ``/opt/rotations-venv``, the source folder mode 0700).
``--view-only`` lays out the same view without the constraint (bubblewrap can start): the
benchmark grades with both confinements in the same view, so that the view's own cost (its
overlay) is in both.
"""

from __future__ import annotations

import ctypes
import errno
import os
import subprocess
import sys
import tempfile
from pathlib import Path

CLONE_NEW = {
    "CLONE_NEWNS": 0x00020000,
    "CLONE_NEWCGROUP": 0x02000000,
    "CLONE_NEWUTS": 0x04000000,
    "CLONE_NEWIPC": 0x08000000,
    "CLONE_NEWUSER": 0x10000000,
    "CLONE_NEWPID": 0x20000000,
    "CLONE_NEWNET": 0x40000000,
}
#: Docker's default capabilities (moby's oci/caps/defaults.go): CHOWN, DAC_OVERRIDE, FOWNER,
#: FSETID, KILL, SETGID, SETUID, SETPCAP, NET_BIND_SERVICE, NET_RAW, SYS_CHROOT, MKNOD,
#: AUDIT_WRITE, SETFCAP.
DOCKER_CAPS = {0, 1, 3, 4, 5, 6, 7, 8, 10, 13, 18, 27, 29, 31}
PR_CAPBSET_DROP = 24
IN_NAMESPACE = "_ROTATIONS_DOCKER_VIEW"


def load_filter():
    import seccomp

    rules = seccomp.SyscallFilter(defaction=seccomp.ALLOW)
    eperm = seccomp.ERRNO(errno.EPERM)
    for name in ("unshare", "setns", "mount", "umount2", "pivot_root"):
        rules.add_rule(eperm, name)
    for flag in CLONE_NEW.values():
        rules.add_rule(eperm, "clone", seccomp.Arg(0, seccomp.MASKED_EQ, flag, flag))
    rules.add_rule(seccomp.ERRNO(errno.ENOSYS), "clone3")
    rules.load()


def drop_capabilities():
    libc = ctypes.CDLL(None, use_errno=True)
    for cap in range(64):
        if cap in DOCKER_CAPS:
            continue
        if libc.prctl(PR_CAPBSET_DROP, cap, 0, 0, 0) != 0:
            if ctypes.get_errno() == errno.EINVAL:
                break
            raise OSError(ctypes.get_errno(), f"PR_CAPBSET_DROP {cap}")


def _mount(*args):
    subprocess.run(["mount", *args], check=True)


def _closed_ancestor(repo):
    """The topmost folder above ``repo``, outside /root, that others may not pass (a checkout
    in a ``mktemp -d`` folder, mode 0700), or None. On Gradescope the source's folders are
    passable: the view opens this one as it opens /root."""
    root = Path("/root")
    closed = [
        p
        for p in Path(repo).parents
        if p != Path("/") and p != root and root not in p.parents and not os.stat(p).st_mode & 1
    ]
    return str(closed[-1]) if closed else None


def _reopen(folder, places, stash):
    """``folder`` replaced by an empty tmpfs (mode 0755) into which only ``places`` (folders
    under it) are mounted back."""
    for n, place in enumerate(places):
        os.makedirs(f"{stash}/keep{n}")
        _mount("--rbind", place, f"{stash}/keep{n}")
    _mount("-t", "tmpfs", "-o", "mode=0755", "tmpfs", folder)
    for n, place in enumerate(places):
        os.makedirs(place, exist_ok=True)
        _mount("--move", f"{stash}/keep{n}", place)
        os.rmdir(f"{stash}/keep{n}")


def lay_out(repo, keep):
    """In this (private) mount namespace: /root emptied but for ``keep``; ``repo`` closed."""
    _mount("--make-rprivate", "/")
    stash = tempfile.mkdtemp(prefix="docker-view-")
    _mount("-t", "tmpfs", "-o", "mode=0700", "tmpfs", stash)
    closed = _closed_ancestor(repo)
    if closed is not None:
        _reopen(closed, [repo], stash)
    _reopen("/root", keep, stash)
    os.makedirs(f"{stash}/upper")
    os.makedirs(f"{stash}/work")
    _mount("-t", "overlay", "overlay", "-o", f"lowerdir={repo},upperdir={stash}/upper,"
           f"workdir={stash}/work", repo)  # fmt: skip
    os.chmod(repo, 0o711)
    for entry in os.scandir(repo):
        if entry.name != ".venv" and not entry.is_symlink():
            mode = entry.stat(follow_symlinks=False).st_mode
            os.chmod(entry.path, mode & 0o7770)


def command(argv, repo, python_prefixes=(), constraint=True):
    """The argv that runs ``argv`` under this launcher, in the view of ``repo``: what is under
    ``/root`` among ``repo`` and ``python_prefixes`` (the Python installation and environment
    of the grader: ``sys.base_prefix``, ``sys.prefix``) is mounted back."""
    places = {os.path.realpath(p) for p in (*python_prefixes, repo)}
    places = {p for p in places if p.startswith("/root/")}
    keep = sorted(p for p in places if not any(p != q and p.startswith(q + "/") for q in places))
    view = "--view" if constraint else "--view-only"
    return ["/usr/bin/python3", os.path.abspath(__file__), view, str(repo), *keep, "--", *argv]


def main(argv):
    if "--" not in argv:
        print(__doc__, file=sys.stderr)
        return 2
    split = argv.index("--")
    options, command = argv[:split], argv[split + 1 :]
    if options[:1] in (["--view"], ["--view-only"]):
        if os.environ.get(IN_NAMESPACE) != "1":
            env = {**os.environ, IN_NAMESPACE: "1"}
            unshare = ["unshare", "--mount", "--propagation", "private"]
            os.execvpe("unshare", [*unshare, sys.executable, __file__, *argv], env)
        lay_out(options[1], options[2:])
    os.environ.pop(IN_NAMESPACE, None)
    if options[:1] != ["--view-only"]:
        drop_capabilities()
        load_filter()
    os.execvp(command[0], command)
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
