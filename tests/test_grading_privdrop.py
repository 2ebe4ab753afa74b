"""The privilege-drop confinement (instructor/grading/privdrop.py) under Docker's constraint, as
root.

Every run of student code here goes through ``tests/docker_seccomp.py``: root, Docker's 14
capabilities, a seccomp filter that refuses new user namespaces (``EPERM`` for ``unshare`` and
``clone`` with a namespace flag, ``ENOSYS`` for ``clone3``), and the file system laid out as
a Gradescope image has it (``--view``: ``/root`` empty but for the Python installation, the
checkout closed to others but for its ``.venv``). bubblewrap cannot start there, so
:func:`instructor.grading.sandbox.confinement` picks ``privdrop``: the first test prints the
evidence.

In ``make test``: the evidence, one kernel probed from the inside (ids, capabilities, limits,
environment, home, what it can read and write, a bounded fork test, its processes and files
after it), the refusals. Marked ``slow_grading``: a class through real ``nbgrader autograde``
with every attack; marked ``gradescope``: ``run_autograder`` in its own layout.
"""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest
from docker_seccomp import command

from instructor.grading import privdrop, sandbox

ROOT = Path(__file__).resolve().parents[1]


# One worker runs this file (make test-slow's --dist loadgroup): the tests count every process
# of the kernels' uids, which a second worker's privdrop kernel would be.
pytestmark = [pytest.mark.privdrop, pytest.mark.xdist_group("privdrop")]
MARKER = "ROTATIONS_GRADER_SECRET_41d9"


def under_docker(argv, timeout=600, env=None, cwd=ROOT):
    """Run ``argv`` as root under Docker's constraint, in the Gradescope-like view."""
    cmd = command(argv, ROOT, (sys.base_prefix, sys.prefix))
    return subprocess.run(
        cmd, capture_output=True, text=True, timeout=timeout, env=env or os.environ, cwd=cwd
    )


EVIDENCE = """\
import ctypes, json, os, subprocess
from instructor.grading.sandbox import bubblewrap_problem, confinement
libc = ctypes.CDLL(None, use_errno=True)
def errno_of(rc):
    return os.strerror(ctypes.get_errno()) if rc == -1 else "allowed"
bwrap = subprocess.run(["bwrap", "--unshare-all", "--ro-bind", "/", "/", "true"],
                       capture_output=True, text=True)
print(json.dumps({
    "unshare": errno_of(libc.unshare(0x10000000)),
    "clone3": errno_of(libc.syscall(435, 0, 0)),
    "bwrap": [bwrap.returncode, bwrap.stderr.strip()],
    "bubblewrap_problem": bubblewrap_problem(),
    "confinement": confinement(),
    "capbnd": [l for l in open("/proc/self/status") if l.startswith("CapBnd")][0].split()[1],
}))
"""


def test_bwrap_cannot_start_under_dockers_constraint_and_privdrop_is_chosen():
    done = under_docker([sys.executable, "-c", EVIDENCE])
    assert done.returncode == 0, done.stderr
    out = json.loads(done.stdout)
    print("evidence under the seccomp filter:", json.dumps(out, indent=1))
    assert out["unshare"] == "Operation not permitted", out
    assert out["clone3"] == "Function not implemented", out
    assert out["bwrap"][0] != 0 and "namespace" in out["bwrap"][1], out
    assert out["bubblewrap_problem"] and out["confinement"] == "privdrop", out
    assert out["capbnd"] == "00000000a80425fb", out  # Docker's 14 capabilities


PROBE = r"""
import json, os, resource, socket, time
status = open("/proc/self/status").read().splitlines()
out = {l.split(":")[0]: l.split(":", 1)[1].split() for l in status
       if l.startswith(("Uid", "Gid", "Groups", "Cap", "NoNewPrivs"))}
out["env"] = sorted(os.environ)
out["home"] = os.environ["HOME"]
st = os.stat(out["home"])
out["home_stat"] = [st.st_uid, oct(st.st_mode & 0o777)]
out["home_entries"] = sorted(os.listdir(out["home"]))
out["tmpdir"] = os.environ.get("TMPDIR", "")
out["limits"] = {n: resource.getrlimit(getattr(resource, n))[0] for n in LIMITS}
def attempt(key, fn):
    try:
        out[key] = repr(fn())[:200]
    except Exception as err:
        out[key] = "refused " + type(err).__name__
attempt("list_solutions", lambda: os.listdir(REPO + "/instructor/answers"))
attempt("read_solutions", lambda: open(REPO + "/instructor/answers/ch01.py").read())
attempt("read_grader", lambda: open(REPO + "/instructor/grading/verify.py").read())
attempt("list_repo", lambda: os.listdir(REPO))
attempt("read_source", lambda: open(COURSE + "/source/ps01/ps01.ipynb").read())
attempt("list_course", lambda: os.listdir(COURSE))
attempt("write_gradebook", lambda: open(COURSE + "/gradebook.db", "a").write("x"))
attempt("write_grader", lambda: open(REPO + "/instructor/grading/verify.py", "a").write("x"))
attempt("environ1", lambda: open("/proc/1/environ", "rb").read())
attempt("grader_environ", lambda: open(f"/proc/{GRADER}/environ", "rb").read())
import ipykernel.connect
scratch = os.path.dirname(ipykernel.connect.get_connection_file())
attempt("write_scratch", lambda: open(scratch + "/fill", "w").write("x"))
attempt("big_file", lambda: open(out["home"] + "/big", "wb").write(bytes(65 * 2**20)))
attempt("memory", lambda: len(bytearray(5 * 2**30)))
open(f"/tmp/left-by-kernel-{os.getuid()}", "w").write("x")  # removed after the kernel
if os.fork() == 0:  # a child that leaves the kernel's session, to outlive it
    os.setsid()
    if os.fork() == 0:
        time.sleep(300)
    os._exit(0)
kids = []
try:
    for _ in range(80):  # bounded: at most 80 children, each sleeping 2 s
        pid = os.fork()
        if pid == 0:
            time.sleep(2)
            os._exit(0)
        kids.append(pid)
except OSError as err:
    out["fork_refused"] = type(err).__name__
out["forked"] = len(kids)
for pid in kids:
    os.waitpid(pid, 0)
print("PROBE" + json.dumps(out))
"""

DRIVER = """\
import asyncio, json, os, sys
from instructor.grading import sandbox
async def main(code, hide):
    km = sandbox.ConfinedKernelManager(hide=hide)
    await km.start_kernel()
    kc = km.client()
    kc.start_channels()
    texts = []
    try:
        await kc.wait_for_ready(timeout=60)
        km.seal_scratch()
        hook = lambda m: texts.append(m["content"].get("text", m["content"].get("evalue", "")))
        await kc.execute_interactive(code, output_hook=hook, timeout=120)
    finally:
        kc.stop_channels()
        uid, home = km._uid, km._home
        await km.shutdown_kernel(now=True)
    from instructor.grading.privdrop import _pids
    left = _pids(uid)  # live processes (a zombie is dead already)
    files = [f for f in (f"/tmp/left-by-kernel-{uid}", home) if os.path.exists(f)]
    print("AFTER" + json.dumps({"processes": left, "files": files, "kind": km.kind}))
    print("".join(texts))
asyncio.run(main(sys.argv[1], sys.argv[2:]))
"""


@pytest.fixture(scope="module")
def probe(tmp_path_factory):
    course = tmp_path_factory.mktemp("course")
    (course / "source" / "ps01").mkdir(parents=True)
    (course / "source" / "ps01" / "ps01.ipynb").write_text("BEGIN SOLUTION")
    (course / "gradebook.db").write_text("grades")
    names = {
        "REPO": str(ROOT),
        "COURSE": str(course),
        "GRADER": os.getpid(),
        "LIMITS": list(sandbox.LIMITS),
    }
    code = "".join(f"{k} = {v!r}\n" for k, v in names.items()) + PROBE
    env = {**os.environ, MARKER: "grader-only"}
    done = under_docker([sys.executable, "-c", DRIVER, code, str(ROOT), str(course)], env=env)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    assert "\nPROBE{" in done.stdout, done.stdout[-3000:]
    after = next(x for x in done.stdout.splitlines() if x.startswith("AFTER"))
    line = next(x for x in done.stdout.splitlines() if x.startswith("PROBE"))
    assert (course / "gradebook.db").read_text() == "grades"
    return json.loads(line[len("PROBE") :]), json.loads(after[len("AFTER") :])


def test_the_kernel_runs_as_the_kernel_uid_with_no_capability_and_no_new_privileges(probe):
    out, after = probe
    assert after["kind"] == "privdrop"
    uid = int(out["Uid"][0])
    assert privdrop.KERNEL_ID <= uid < privdrop.KERNEL_ID + privdrop.SLOTS, out
    assert out["Uid"] == [str(uid)] * 4 and out["Gid"] == [str(uid)] * 4, out
    assert out["Groups"] == [], out
    for cap in ("CapInh", "CapPrm", "CapEff", "CapBnd", "CapAmb"):
        assert out[cap] == ["0000000000000000"], (cap, out)
    assert out["NoNewPrivs"] == ["1"], out


def test_fresh_home_cleared_environment_and_limits(probe):
    out, _ = probe
    assert out["home"].startswith("/tmp/rotations-home-"), out
    assert out["home_stat"] == [int(out["Uid"][0]), "0o700"], out
    assert out["tmpdir"] == out["home"] + "/tmp" and "tmp" in out["home_entries"], out
    assert set(out["home_entries"]) <= {"tmp", ".ipython", ".matplotlib", ".runtime"}, out
    allowed = {*sandbox.kernel_env(), "TMPDIR", "MPLBACKEND", "JPY_PARENT_PID"}
    # what ipykernel's shell sets itself (ZMQInteractiveShell.init_environment)
    allowed |= {"TERM", "CLICOLOR", "CLICOLOR_FORCE", "FORCE_COLOR", "PAGER", "GIT_PAGER"}
    allowed.add("PYDEVD_USE_FRAME_EVAL")  # ipykernel's debugger
    assert set(out["env"]) <= allowed and MARKER not in out["env"], out
    assert out["limits"] == sandbox.LIMITS, out
    assert out["big_file"] == "refused OSError", out  # RLIMIT_FSIZE (EFBIG)
    assert out["memory"] == "refused MemoryError", out  # RLIMIT_AS


def test_solutions_course_grader_and_scratch_are_closed_to_the_kernel(probe):
    out, _ = probe
    for key in ("list_solutions", "read_solutions", "read_grader", "list_repo"):
        assert out[key] == "refused PermissionError", (key, out)
    for key in ("read_source", "list_course", "write_gradebook", "write_grader"):
        assert out[key] == "refused PermissionError", (key, out)
    assert out["environ1"].startswith("refused") and out["grader_environ"].startswith("refused")
    assert out["write_scratch"] == "refused PermissionError", out  # sealed


def test_the_process_limit_binds_and_nothing_of_the_kernel_outlives_it(probe):
    """RLIMIT_NPROC binds the kernel's uid (it did not bind bubblewrap's root kernel); a child
    that left the kernel's session is killed with it; its files in /tmp are removed."""
    out, after = probe
    assert out["forked"] < sandbox.LIMITS["RLIMIT_NPROC"], out
    assert out["fork_refused"] == "BlockingIOError", out  # EAGAIN
    assert after["processes"] == [] and after["files"] == [], after


READABLE = """\
import json, os, sys, tempfile
from instructor.grading import privdrop, sandbox
top = tempfile.mkdtemp(prefix="hidden-")
os.chmod(top, 0o755)
os.makedirs(top + "/instructor/answers")
open(top + "/instructor/answers/ch01.py", "w").write("SOLUTIONS = {}")
for folder in (top + "/instructor", top + "/instructor/answers"):
    os.chmod(folder, 0o755)
os.chmod(top + "/instructor/answers/ch01.py", 0o644)
first = sandbox.hidden_problem([top])[0]
from traitlets.config import Config
from nbgrader.converters.base import NbGraderException
from instructor.grading.preprocessor import ConfinedExporter
try:  # what `nbgrader autograde` does first, before any submission is read
    ConfinedExporter(config=Config({"ConfinedKernelManager": {"hide": [top]}}))
    refused = None
except NbGraderException as err:
    refused = str(err)
os.chmod(top, 0o700)
privdrop.hidden_problem.cache_clear()
second = sandbox.hidden_problem([top])[0]
print(json.dumps({"top": top, "first": first, "second": second, "refused": refused}))
"""


def test_a_check_that_gives_no_answer_refuses_instead_of_passing_regression_killed_probe():
    """Before, a check child that died (a student's kernel of the same uid can kill it) or
    whose task raised read as "nothing found": the hidden folders passed unchecked. Checks now
    run as PROBE_ID, a uid no kernel has, and no answer is an error, a refusal upstream."""
    assert privdrop.PROBE_ID not in range(privdrop.KERNEL_ID, privdrop.KERNEL_ID + privdrop.SLOTS)
    with pytest.raises(OSError, match="did not finish"):
        privdrop._as_uid(privdrop.PROBE_ID, lambda: os.kill(os.getpid(), signal.SIGKILL))
    with pytest.raises(OSError, match="did not finish"):
        privdrop._as_uid(privdrop.PROBE_ID, lambda: 1 / 0)
    assert privdrop._as_uid(privdrop.PROBE_ID, os.getuid) == privdrop.PROBE_ID


def test_a_hidden_folder_readable_by_the_kernels_uid_is_refused_with_the_chmod():
    done = under_docker([sys.executable, "-c", READABLE])
    assert done.returncode == 0, done.stderr
    out = json.loads(done.stdout)
    assert f"`chmod 700 {out['top']}`" in out["first"], out
    assert "ch01.py" in out["first"] and "read" in out["first"], out
    assert out["refused"].startswith("refusing to run students' code: the kernel's user"), out
    assert f"`chmod 700 {out['top']}`" in out["refused"] and "Nothing was graded" in out["refused"]
    assert out["second"] is None, out


def test_a_python_behind_a_closed_folder_is_refused_with_the_chmod():
    """A Python under /root (mode 0700), as on the machines here: privdrop names the folder."""
    top = Path(tempfile.mkdtemp(prefix="closed-"))  # in /tmp, which others may pass
    try:
        (top / "py" / "bin").mkdir(parents=True)
        python = top / "py" / "bin" / "python3"
        python.write_text("")
        os.chmod(top, 0o700)
        problem = privdrop.problem(str(python))
        assert f"`chmod o+x {top}`" in problem, problem
    finally:
        shutil.rmtree(top)
    closed = privdrop._closed_ancestor(sys.base_prefix)
    if closed is not None:  # this machine's own Python (outside the Gradescope-like view)
        assert f"`chmod o+x {closed}`" in privdrop.problem(), privdrop.problem()
        print("outside the view, privdrop here says:", privdrop.problem())


# --- real nbgrader and Gradescope's run_autograder under the constraint (slow) ---------------

PS = "ps01"
TOTAL = 14
CELL_TIMEOUT = 10  # the endless cell waits for it; a loaded CI machine needs the room
NBGRADER = Path(sys.executable).with_name("nbgrader")
FORK_BOMB = """\
import os, time
_n = 0
try:
    while True:
        if os.fork() == 0:
            while True:  # every child forks too, for ever: bounded only by RLIMIT_NPROC
                try:
                    os.fork()
                except OSError:
                    time.sleep(0.05)
        _n += 1
except OSError as err:
    print("fork refused after", _n, "children:", type(err).__name__)
"""
MEMORY_HOG = """\
try:
    _hog = bytearray(6 * 2**30)
except MemoryError:
    print("memory refused")
"""
FLOOD = "for _ in range(60):\n    print('x' * 10**6, flush=True)\n"
ENDLESS = "import signal\nsignal.signal(signal.SIGINT, signal.SIG_IGN)\nwhile True:\n    pass\n"


def _snoop(places, writes):
    return f"""\
import glob, os
for top in {places!r}:
    for p in glob.glob(top + "/**", recursive=True):
        if os.path.isfile(p):
            print("SEEN", p)
            try:
                print(open(p, errors="replace").read()[:2000])
            except OSError as err:
                print("REFUSED", p, type(err).__name__)
for target in {writes!r}:
    try:
        os.makedirs(os.path.dirname(target), exist_ok=True)
        with open(target, "a") as f:
            f.write('{{"score": 1000.0, "output": "pwned"}}')
        print("WROTE", target)
    except OSError as err:
        print("REFUSED", target, type(err).__name__)
"""


def _notebook(folder):
    import nbformat

    path = next(Path(folder).glob("*.ipynb"))
    return path.name, nbformat.read(path, as_version=4)


def _with(nb, code, cell_id=None):
    import nbformat

    nb = nbformat.from_dict(json.loads(json.dumps(nb)))
    cell = next(c for c in nb.cells if c.id == cell_id or (not cell_id and "-answer" in c.id))
    cell.source = code + "\n" + cell.source
    return nb


def _outputs(path):
    """The text of every output of the notebook at ``path`` (not its sources)."""
    nb = json.loads(Path(path).read_text())
    outs = [o for c in nb["cells"] for o in c.get("outputs", [])]
    return "".join(json.dumps(o) for o in outs)


def _digest(*folders):
    import hashlib

    h = hashlib.sha256()
    for folder in folders:
        for p in sorted(Path(folder).rglob("*")):
            if p.is_file() and "__pycache__" not in p.parts:
                h.update(str(p).encode() + p.read_bytes())
    return h.hexdigest()


def _kernel_uids_busy():
    """Every live process of the uid of a FREE slot, with its command line (empty: none). A
    slot whose lock someone holds is in use (another test's kernel may run in it right now:
    counting those failed this test now and then); a free slot must have no process left."""
    import fcntl

    out = []
    for n in range(privdrop.SLOTS):
        fd = os.open(privdrop.slot_lock(n), os.O_RDWR | os.O_CREAT, 0o600)
        try:
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError:
                continue  # in use
            for pid in privdrop._pids(privdrop.KERNEL_ID + n):
                try:
                    with open(f"/proc/{pid}/cmdline", "rb") as f:
                        cmd = f.read().replace(b"\0", b" ").decode(errors="replace")[:200]
                except OSError:
                    cmd = "(gone)"
                out.append((privdrop.KERNEL_ID + n, pid, cmd))
        finally:
            os.close(fd)
    return out


def _attacks(solved, blank, places, writes):
    return {
        "p_solved": solved,
        "p_blank": blank,
        "p_snoop": _with(blank, _snoop(places, writes)),
        "p_fork_bomb": _with(solved, FORK_BOMB),
        "p_memory": _with(solved, MEMORY_HOG),
        "p_flood": _with(solved, FLOOD),
        "p_endless": _with(solved, ENDLESS, "which_are_rigid-answer"),
    }


def _expect(got, sid):
    if sid in ("p_blank", "p_snoop"):
        assert sum(got.values()) == 0, (sid, got)
    elif sid == "p_endless":  # the checks before the endless cell keep their points
        assert got["coords_by_projection"] == got["angle_from_lengths"] == 1, (sid, got)
        assert sum(got.values()) == 2, (sid, got)
    else:  # solved, and every contained attack: the rest graded
        assert sum(got.values()) == TOTAL, (sid, got)


@pytest.mark.slow_grading
@pytest.mark.notebook_exec
def test_nbgrader_autograde_of_a_class_under_dockers_constraint(tmp_path):
    """`make course` + real `nbgrader autograde` as root under the seccomp filter: the
    instructor's copy full marks, a blank copy 0, every attack 0 or contained."""
    import nbformat
    from nbgrader.api import Gradebook

    from instructor.grading.course import write_course

    course = tmp_path / "course"
    write_course(course)
    env = {**os.environ, "PATH": f"{NBGRADER.parent}:{os.environ['PATH']}"}
    done = subprocess.run(
        [str(NBGRADER), "generate_assignment", PS, "--create"],
        cwd=course,
        env=env,
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    name, solved = _notebook(course / "source" / PS)
    _, blank = _notebook(course / "release" / PS)
    places = [str(course), str(ROOT / "instructor"), str(ROOT / "problem_sets")]
    writes = [str(course / "gradebook.db"), str(ROOT / "instructor" / "grading" / "verify.py")]
    writes.append(str(course / "source" / PS / name))
    subs = _attacks(solved, blank, places, writes)
    for sid, nb in subs.items():
        (course / "submitted" / sid / PS).mkdir(parents=True)
        nbformat.write(nb, course / "submitted" / sid / PS / name)
    before = _digest(course / "source", ROOT / "instructor" / "grading", ROOT / "instructor")
    argv = [str(NBGRADER), "autograde", PS, "--create", f"--Execute.timeout={CELL_TIMEOUT}"]
    done = under_docker(argv, env=env, cwd=course)
    log = done.stdout + done.stderr
    assert done.returncode == 0, log[-5000:]
    assert "confined by privdrop" in log and "confined by bubblewrap" not in log, log[-3000:]
    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gb:
        for sid in subs:
            sub = gb.find_submission(PS, sid)
            _expect({g.name[:-6]: g.score for nb in sub.notebooks for g in nb.grades}, sid)
    snooped = _outputs(course / "autograded" / "p_snoop" / PS / name)
    assert "SEEN" not in snooped and "WROTE" not in snooped, snooped[:3000]
    assert snooped.count("REFUSED") == len(writes), snooped[:3000]
    bomb = _outputs(course / "autograded" / "p_fork_bomb" / PS / name)
    assert "fork refused after" in bomb, bomb[:2000]
    assert "memory refused" in _outputs(course / "autograded" / "p_memory" / PS / name)
    assert (course / "autograded" / "p_flood" / PS / name).stat().st_size < 2_000_000
    assert (
        _digest(course / "source", ROOT / "instructor" / "grading", ROOT / "instructor") == before
    )
    assert not _kernel_uids_busy(), _kernel_uids_busy()


@pytest.mark.gradescope
@pytest.mark.notebook_exec
def test_run_autograder_in_its_own_layout_under_dockers_constraint(tmp_path):
    """Gradescope's run_autograder as root under the seccomp filter, in a temporary
    /autograder: the same cases, and an attack on results.json and the grader's files."""
    import nbformat

    from instructor.grading import gradescope

    top = tmp_path / "autograder"
    for member, data in gradescope.members(PS).items():
        path = top / "source" / member
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(data)
    env = {**os.environ, "ROTATIONS_AUTOGRADER_ROOT": str(top)}
    script = str(top / "source" / "instructor" / "grading" / "gradescope_run.py")
    prepare = [sys.executable, "-m", "instructor.grading.gradescope_run", "prepare"]
    done = subprocess.run(prepare, cwd=top / "source", env=env, capture_output=True)
    assert done.returncode == 0, done.stderr[-3000:]
    name, solved = _notebook(top / "course" / "source" / PS)
    _, blank = _notebook(top / "course" / "release" / PS)
    writes = [str(top / "results" / "results.json"), script]
    writes.append(str(top / "source" / "instructor" / "answers" / "ch01.py"))
    subs = _attacks(solved, blank, [str(top)], writes)
    # the fork bomb and the memory hog in one submission here (each alone above, through
    # nbgrader; the flood is cut in the grader's process, whatever the confinement: above, and
    # tests/test_grading_gradescope.py)
    subs["p_contained"] = _with(solved, FORK_BOMB + MEMORY_HOG)
    for sid in ("p_fork_bomb", "p_memory", "p_flood"):
        del subs[sid]
    before = _digest(top / "source")
    env |= {"ROTATIONS_PYTHON": sys.executable, "ROTATIONS_CELL_TIMEOUT": str(CELL_TIMEOUT)}
    folder = {}  # the nbgrader student of each submission (the e-mail, made a folder name)
    for n, (sid, nb) in enumerate(subs.items()):
        sub = top / "submission"
        shutil.rmtree(sub, ignore_errors=True)
        sub.mkdir()
        nbformat.write(nb, sub / name)
        meta = {"users": [{"sid": sid, "email": f"{sid}@example.edu", "id": n}]}
        (top / "submission_metadata.json").write_text(json.dumps(meta))
        (top / "results" / "results.json").unlink(missing_ok=True)
        done = under_docker(["bash", str(top / "source" / "run_autograder")], env=env, cwd=top)
        assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
        results = json.loads((top / "results" / "results.json").read_text())
        assert results["extra_data"]["confinement"] == "privdrop", results
        assert "Confinement of the student's code: privdrop." in results["output"], results
        assert "pwned" not in json.dumps(results), results
        _expect({t["name"]: t["score"] for t in results["tests"]}, sid)
        folder[sid] = results["extra_data"]["student"]
    snooped = _outputs(top / "course" / "autograded" / folder["p_snoop"] / PS / name)
    assert "SEEN" not in snooped and "WROTE" not in snooped, snooped[:3000]
    assert snooped.count("REFUSED") == len(writes), snooped[:3000]
    contained = _outputs(top / "course" / "autograded" / folder["p_contained"] / PS / name)
    assert "fork refused after" in contained and "memory refused" in contained
    assert _digest(top / "source") == before
    assert not _kernel_uids_busy(), _kernel_uids_busy()
