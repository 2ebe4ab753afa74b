"""The confined kernel (instructor/grading/sandbox.py) from the inside, with the real ``bwrap``.

Issue 17's sandbox escape: the kernel read the connection file of an unconfined kernel of the
grading user (``--ro-bind / /``) and reached it over host loopback (no ``--unshare-net``), read
other checkouts' ``instructor/answers``, classmates' submissions and ``/proc/1/environ``. One
confined kernel is started (about 2 s) and probes what it can reach.
"""

from __future__ import annotations

import asyncio
import json
import os
import shutil
import socket
import sys
import threading
from pathlib import Path

import pytest
from jupyter_core.paths import jupyter_runtime_dir

import course_lib
from instructor.grading import sandbox

ROOT = Path(__file__).resolve().parents[1]

confined = pytest.mark.confined  # the confinement itself: needs bubblewrap

MARKER = "ROTATIONS_GRADER_SECRET_7f3c"

PROBE = """\
import json, os, resource, socket, course_lib
out = {"course_lib": course_lib.__file__, "uid": os.getuid()}
def attempt(key, fn):
    try:
        out[key] = repr(fn())
    except Exception as err:
        out[key] = "refused " + type(err).__name__
attempt("solutions", lambda: os.listdir(SOLUTIONS))
attempt("repo_solutions", lambda: os.listdir(REPO_SOLUTIONS))
attempt("connection", lambda: open(CONNECTION).read())
attempt("exchange", lambda: os.listdir("/srv"))
attempt("graders_runtime", lambda: os.listdir(GRADERS_RUNTIME))
attempt("runtime", lambda: os.listdir(RUNTIME))
attempt("environ1", lambda: open("/proc/1/environ", "rb").read().decode())
attempt("environ", lambda: dict(os.environ))
attempt("tcp", lambda: socket.create_connection(("127.0.0.1", PORT), timeout=2))
attempt("write_root", lambda: open("/evil", "w"))
attempt("write_lib", lambda: open(os.path.join(os.path.dirname(course_lib.__file__), "x"), "w"))
import ipykernel.connect, time
scratch = os.path.dirname(ipykernel.connect.get_connection_file())
def fill(place, mb):
    done = 0
    try:
        with open(os.path.join(place, "fill"), "wb") as f:
            for _ in range(mb):
                f.write(bytes(2**20))
                f.flush()
                done += 1
    except OSError as err:
        return f"{done} MiB, refused {type(err).__name__}"
    finally:
        try:
            os.remove(os.path.join(place, "fill"))
        except OSError:
            pass
    return f"{done} MiB"
out["statvfs"] = {p: os.statvfs(p).f_blocks * os.statvfs(p).f_frsize for p in ("/dev/shm", "/tmp")}
out["fill_shm"] = fill("/dev/shm", 70)
out["fill_dev"] = fill("/dev", 1)
out["fill_scratch"] = fill(scratch, 1)
attempt("chmod_scratch", lambda: os.chmod(scratch, 0o777))
attempt("dev_null", lambda: open("/dev/null", "w").write("x"))
kids = []
try:
    for _ in range(80):  # bounded: at most 80 children, each sleeping 1 s
        pid = os.fork()
        if pid == 0:
            time.sleep(1)
            os._exit(0)
        kids.append(pid)
except OSError as err:
    out["fork_refused"] = type(err).__name__
out["forked"] = len(kids)
for pid in kids:
    os.waitpid(pid, 0)
out["as"] = resource.getrlimit(resource.RLIMIT_AS)[0]
out["fsize"] = resource.getrlimit(resource.RLIMIT_FSIZE)[0]
print("PROBE" + json.dumps(out))
"""


async def _run_confined(code, hide):
    km = sandbox.ConfinedKernelManager(hide=hide)
    await km.start_kernel()
    kc = km.client()
    kc.start_channels()
    texts = []
    try:
        await kc.wait_for_ready(timeout=60)
        km.seal_scratch()  # as ConfinedExecute does once the kernel has answered
        await kc.execute_interactive(
            code,
            output_hook=lambda m: texts.append(m["content"].get("text", "")),
            timeout=60,
        )
    finally:
        kc.stop_channels()
        await km.shutdown_kernel(now=True)
    return "".join(texts), km.scratch


@pytest.fixture(scope="module")
def probe(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("outside")
    solutions = tmp / "other-checkout" / "instructor" / "answers"
    solutions.mkdir(parents=True)
    (solutions / "ch01.py").write_text("SOLUTIONS = {}\n")
    runtime = tmp / "runtime"
    runtime.mkdir()
    connection = runtime / "kernel-outside.json"
    connection.write_text(json.dumps({"key": "outside-kernel-key", "transport": "tcp"}))
    server = socket.create_server(("127.0.0.1", 0))
    server.settimeout(10)
    accepted = []
    thread = threading.Thread(target=lambda: _accept(server, accepted), daemon=True)
    thread.start()
    names = {
        "SOLUTIONS": str(solutions),
        "REPO_SOLUTIONS": str(ROOT / "instructor" / "answers"),
        "CONNECTION": str(connection),
        "RUNTIME": str(runtime),
        "PORT": server.getsockname()[1],
        "GRADERS_RUNTIME": jupyter_runtime_dir(),
    }
    code = "".join(f"{k} = {v!r}\n" for k, v in names.items()) + PROBE
    os.environ[MARKER] = "grader-only"
    try:
        text, scratch = asyncio.run(_run_confined(code, [str(ROOT), str(tmp)]))
    finally:
        del os.environ[MARKER]
        server.close()
        thread.join(5)
    line = next(x for x in text.splitlines() if x.startswith("PROBE"))
    return json.loads(line[len("PROBE") :]), accepted, scratch


def _accept(server, accepted):
    try:
        accepted.append(server.accept())
    except OSError:
        pass


@confined
def test_other_checkouts_solutions_and_the_repository_are_not_in_the_kernels_view(probe):
    out, _, _ = probe
    assert out["solutions"] == "refused FileNotFoundError", out
    assert out["repo_solutions"] == "refused FileNotFoundError", out
    assert out["exchange"] == "refused FileNotFoundError", out  # nbgrader's exchange


@confined
def test_the_grading_users_jupyter_runtime_folder_is_not_in_the_kernels_view(probe):
    out, _, _ = probe
    assert out["graders_runtime"] == "refused FileNotFoundError", out


@confined
def test_no_tcp_to_the_hosts_loopback(probe):
    out, accepted, _ = probe
    assert out["tcp"].startswith("refused "), out
    assert not accepted


@confined
def test_the_graders_environment_is_not_in_proc_1_or_the_kernel(probe):
    out, _, _ = probe
    assert MARKER not in out["environ1"] and MARKER not in out["environ"], out
    assert out["environ1"] != "refused FileNotFoundError"  # /proc is the sandbox's own


@confined
def test_a_connection_file_of_an_outside_kernel_cannot_be_read(probe):
    out, _, _ = probe
    assert out["connection"] == "refused FileNotFoundError", out
    assert out["runtime"] == "refused FileNotFoundError", out


@confined
def test_the_installed_course_lib_is_imported_read_only_and_limits_hold(probe):
    out, _, scratch = probe
    assert out["course_lib"] == course_lib.__file__
    assert out["write_root"].startswith("refused ") and out["write_lib"].startswith("refused ")
    assert out["as"] == sandbox.LIMITS["RLIMIT_AS"]
    assert out["fsize"] == sandbox.LIMITS["RLIMIT_FSIZE"]
    assert not os.path.exists(scratch)  # the kernel's scratch folder is removed with it


def test_exposing_a_folder_that_holds_a_hidden_one_is_refused():
    km = sandbox.ConfinedKernelManager(hide=[sys.prefix + "/lib"])
    with pytest.raises(ValueError, match="holds hidden"):
        km._expose()
    shutil.rmtree(km.scratch)


def test_regression_a_venv_under_tmp_is_mounted_over_the_sandboxs_own_tmp():
    """A CI clone under /tmp: its venv and course_lib were bound before the kernel's tmpfs /tmp,
    which then hid them, and every confined kernel died before replying (found in a CI dry run)."""
    cmd = sandbox.bwrap_command(
        ["/tmp/clone/.venv", "/tmp/clone/course_lib"], "/tmp/s", ["-f", "x"]
    )
    tmpfs = max(i for i, a in enumerate(cmd) if a == "--tmpfs" and cmd[i + 1] == "/tmp")
    binds = [i for i, a in enumerate(cmd) if a == "--ro-bind" and cmd[i + 1].startswith("/tmp/")]
    assert binds and all(i > tmpfs for i in binds)


@confined
def test_dev_shm_dev_and_scratch_writes_are_bounded_regression_attack_6b(probe):
    """/dev and /dev/shm were tmpfs of half the RAM (11.8 GiB here, not counted by
    RLIMIT_AS) and the scratch folder a writable host folder on the host's disk."""
    out, _, _ = probe
    assert out["statvfs"]["/dev/shm"] == sandbox.SHM_BYTES, out
    assert out["statvfs"]["/tmp"] == sandbox.TMP_BYTES, out
    assert out["fill_shm"].endswith("refused OSError"), out  # ENOSPC at 64 MiB
    assert int(out["fill_shm"].split()[0]) < 70, out
    assert out["fill_dev"].startswith("0 MiB, refused"), out  # /dev is read-only
    assert out["dev_null"] == "1", out
    if os.geteuid() == 0:  # sealed: given to another uid, read-only, no capability to undo it
        assert out["fill_scratch"].startswith("0 MiB, refused"), out
        assert out["chmod_scratch"].startswith("refused"), out


@confined
def test_the_process_limit_binds_only_when_the_grader_is_not_root(probe):
    """RLIMIT_NPROC does not bind uid 0 (Linux exempts the host's root user, also inside a
    user namespace, also with bwrap's --uid 1000: the kernel's host uid stays 0). Measured
    with a bounded fork test (80 children at most), never a bomb."""
    out, _, _ = probe
    if os.geteuid() == 0:
        assert out["forked"] == 80, out  # the documented gap: a cell's timeout ends them
    else:
        assert out["forked"] < sandbox.LIMITS["RLIMIT_NPROC"], out
