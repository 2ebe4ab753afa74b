"""The CPU a class costs through real nbgrader (`make bench-grade`; a benchmark, not a test).

A class of ``--students`` simulated students (by turns: the instructor's solved copy, a blank
copy, a half-solved copy) hands in every problem set of a `make course` directory. Each
problem set is autograded as ``nbgrader autograde PS`` grades a class: ``--jobs`` nbgrader
processes at once (one per core), each grading a group of students (``--student=GLOB``), so
nbgrader's start-up is paid once per process, not per student. ``--per-student``: one process
per student instead (what each Gradescope submission pays).

**CPU is that of every process of the run, the confined kernels' included.** The process that
waits for nbgrader does not see a confined kernel's CPU: bubblewrap's kernel dies with its PID
namespace, and its CPU is counted for no one that waits (measured: 0.07 s counted for a kernel
that used 3 s). So each nbgrader process runs in a cgroup of its own where the machine allows
one (Linux, root or a delegated cgroup: every process in it is counted, wherever it is
reparented); elsewhere its process tree is sampled every 20 ms (a lower bound: a process's
last 20 ms are missed). Printed: per problem set, the CPU and wall time per submission; then
where the CPU goes (nbgrader's start-up per process, nbgrader's work per submission, the
kernel's start, its cells, its stop), from two probes (an nbgrader process that grades no one;
confined kernels started and stopped as
:class:`instructor.grading.preprocessor.ConfinedExecute` does); then the projection for 200
students x 5 problem sets on 2 cores.

    python -m benchmarks.bench_grade [--students 20] [--jobs 2] [--per-student]
        [--shutdown immediate|graceful] [--keep DIR]
"""

from __future__ import annotations

import argparse
import contextlib
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
KINDS = ("solved", "blank", "half")
CLASS, SETS, CORES, GOAL = 200, 5, 2, 20.0  # the projection: students, sets, cores, minutes
PROBE_KERNELS = 3
SAMPLE = 0.02  # seconds between samples of a process tree (no cgroup)
CHILD = "--child"  # argv[1] of this module run as one measured process (see child())


# ---- one measured process: this module re-run as ``--child DIR KIND ARGS...`` ----


def _cpu_self():
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def child(argv):
    """Join the cgroup ``$BENCH_CGROUP`` (or become the subreaper of the kernels' orphans, so
    that the sampler sees them), write this process's own CPU to ``$BENCH_SELF`` at exit, then
    run ``nbgrader ARGS`` in folder DIR, or (KIND ``kernels``) the kernel probe."""
    folder, kind, *args = argv
    cgroup, out = os.environ.pop("BENCH_CGROUP", ""), os.environ.pop("BENCH_SELF")
    if cgroup:
        Path(cgroup, "cgroup.procs").write_text(str(os.getpid()))
    elif sys.platform == "linux":
        import ctypes

        ctypes.CDLL(None).prctl(36, 1, 0, 0, 0)  # PR_SET_CHILD_SUBREAPER
    import atexit

    atexit.register(lambda: Path(out).write_text(repr(_cpu_self())))  # runs last
    os.chdir(folder)
    if kind == "kernels":
        import asyncio

        asyncio.run(_kernels(args[0] == "immediate", int(args[1])))
        return 0
    from nbgrader.apps.nbgraderapp import main as nbgrader_main

    sys.argv = ["nbgrader", kind, *args]
    return nbgrader_main()


async def _kernels(now, count):
    """``count`` confined kernels, one after the other: started, ready, stopped (``now``: killed,
    as ConfinedExecute's default ``shutdown_kernel = "immediate"``; else a shutdown request)."""
    from instructor.grading.sandbox import ConfinedKernelManager

    for _ in range(count):
        km = ConfinedKernelManager()
        await km.start_kernel()
        kc = km.client()
        kc.start_channels()
        await kc.wait_for_ready(timeout=120)
        kc.stop_channels()
        await km.shutdown_kernel(now=now)


# ---- the meter: CPU of a whole process tree ----


def _cgroup_base():
    """A folder where a cgroup that counts CPU can be made here, and its usage reader; or None."""
    try:
        lines = Path("/proc/self/cgroup").read_text().splitlines()
    except OSError:
        return None
    for line in lines:
        _, controllers, path = line.split(":", 2)
        if "cpuacct" in controllers.split(","):
            base = Path("/sys/fs/cgroup/cpuacct", path.lstrip("/"))
            reader = lambda d: int(Path(d, "cpuacct.usage").read_text()) / 1e9  # noqa: E731
        elif controllers == "":
            top = Path("/sys/fs/cgroup/unified")
            top = top if top.is_dir() else Path("/sys/fs/cgroup")
            base = top / path.lstrip("/")
            reader = _v2_usage
        else:
            continue
        probe = base / f"bench-grade-{os.getpid()}-probe"
        try:  # can a process of ours move into a cgroup made here?
            probe.mkdir()
        except OSError:
            continue
        join = "import os, sys; open(sys.argv[1], 'w').write(str(os.getpid()))"
        done = subprocess.run(
            [sys.executable, "-c", join, str(probe / "cgroup.procs")], capture_output=True
        )
        time.sleep(0.1)
        with contextlib.suppress(OSError):
            probe.rmdir()
        if done.returncode == 0:
            return base, reader
    return None


def _v2_usage(folder):
    stat = dict(line.split() for line in Path(folder, "cpu.stat").read_text().splitlines())
    return int(stat["usage_usec"]) / 1e6


CGROUP = None  # (folder, usage reader) where cgroups count CPU here: set by main()


def _sample(pid, seen, stop):
    """Every SAMPLE s: the own CPU of every process under ``pid``, last seen, by (pid, start)."""
    import psutil

    try:
        top = psutil.Process(pid)
    except psutil.Error:
        return
    while not stop.is_set():
        try:
            procs = top.children(recursive=True)
        except psutil.Error:
            return
        for p in procs:
            with contextlib.suppress(psutil.Error):
                t = p.cpu_times()
                seen[(p.pid, p.create_time())] = t.user + t.system
        stop.wait(SAMPLE)


def measured(argv, folder):
    """Run ``argv`` (``nbgrader ARGS`` or ``kernels MODE N``) in ``folder`` as one measured
    process: (returncode, output, wall s, CPU s of the whole tree, CPU s of the process)."""
    fd, out = tempfile.mkstemp(prefix="bench-grade-cpu-")
    os.close(fd)
    env = {**os.environ, "BENCH_SELF": out}
    env["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{env.get('PATH', '')}"  # alembic
    cgroup = None
    if CGROUP:
        cgroup = Path(tempfile.mkdtemp(prefix="bench-grade-", dir=CGROUP[0]))
        env["BENCH_CGROUP"] = str(cgroup)
    cmd = [sys.executable, "-m", "benchmarks.bench_grade", CHILD, str(folder), *argv]
    seen, stop = {}, threading.Event()
    start = time.perf_counter()
    pipe = {"stdout": subprocess.PIPE, "stderr": subprocess.STDOUT}
    proc = subprocess.Popen(cmd, cwd=ROOT, env=env, **pipe)
    sampler = None
    if cgroup is None:
        sampler = threading.Thread(target=_sample, args=(proc.pid, seen, stop), daemon=True)
        sampler.start()
    text = proc.stdout.read().decode(errors="replace")
    proc.wait()
    wall = time.perf_counter() - start
    own = float(Path(out).read_text() or 0)
    os.unlink(out)
    if cgroup is None:
        stop.set()
        sampler.join()
        return proc.returncode, text, wall, own + sum(seen.values()), own
    deadline = time.monotonic() + 10  # the kernels killed last may take a moment to go
    while Path(cgroup, "cgroup.procs").read_text().strip() and time.monotonic() < deadline:
        time.sleep(0.05)
    tree = CGROUP[1](cgroup)
    with contextlib.suppress(OSError):  # a process still in it (it was counted)
        cgroup.rmdir()
    return proc.returncode, text, wall, tree, own


# ---- the class ----


def hand_in(course, ps, student, kind):
    import nbformat

    solved = next((course / "source" / ps).glob("*.ipynb"))
    blank = course / "release" / ps / solved.name
    nb = nbformat.read(solved if kind == "solved" else blank, as_version=4)
    if kind == "half":
        good = nbformat.read(solved, as_version=4)
        answers = [i for i, c in enumerate(nb.cells) if c.get("id", "").endswith("-answer")]
        for i in answers[::2]:
            nb.cells[i] = good.cells[i]
    dest = course / "submitted" / student / ps
    dest.mkdir(parents=True, exist_ok=True)
    nbformat.write(nb, dest / solved.name)
    (dest / "timestamp.txt").write_text("2026-01-01 00:00:00.000000 UTC")


def groups(students, jobs, per_student):
    """The ``--student`` values, one per nbgrader process."""
    if per_student:
        return students
    digits = ["".join(d for d in "0123456789" if int(d) % jobs == g) for g in range(jobs)]
    return [f"s*[{d}]" for d in digits if d]


def grade(course, ps, student):
    """One nbgrader process grading ``student`` (an id or a glob): (wall, tree CPU, own CPU)."""
    for _ in range(3):  # a parallel writer may hold the sqlite gradebook for a moment
        code, out, wall, tree, own = measured(["autograde", ps, f"--student={student}"], course)
        if code == 0:
            return wall, tree, own
        if "database is locked" not in out:
            break
    raise RuntimeError(f"autograde {ps} {student} failed:\n{out[-3000:]}")


def scores(course, ps):
    from nbgrader.api import Gradebook

    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gb:
        return {s.student.id: s.score for s in gb.find_assignment(ps).submissions}


def check_scores(course, ps, students):
    got = scores(course, ps)
    solved_full = all(got[s] > 0 for i, s in enumerate(students) if i % 3 == 0)
    blank_zero = all(got[s] == 0 for i, s in enumerate(students) if i % 3 == 1)
    assert len(got) == len(students) and solved_full and blank_zero, got


def grade_class(course, problem_sets, students, args):
    """Every set graded; per set a row; returns (wall, tree CPU, own CPU, processes) in all."""
    heads = ("set", "wall s", "CPU s", "CPU/sub", "kernels/sub", "nbgrader/sub")
    print(f"{heads[0]:5} " + " ".join(f"{h:>12}" for h in heads[1:]))
    totals = [0.0, 0.0, 0.0, 0]
    for ps in problem_sets:
        code, out, *_ = measured(["generate_assignment", ps, "--create"], course)
        assert code == 0, out
        for i, sid in enumerate(students):
            hand_in(course, ps, sid, KINDS[i % len(KINDS)])
        who = groups(students, args.jobs, args.per_student)
        start = time.perf_counter()
        with ThreadPoolExecutor(args.jobs) as pool:
            runs = list(pool.map(lambda s, p=ps: grade(course, p, s), who))
        wall = time.perf_counter() - start
        check_scores(course, ps, students)
        tree, own = sum(r[1] for r in runs), sum(r[2] for r in runs)
        n = len(students)
        row = (wall, tree, tree / n, (tree - own) / n, own / n)
        print(f"{ps:5} " + " ".join(f"{v:12.2f}" for v in row))
        for i, v in enumerate((wall, tree, own, len(who))):
            totals[i] += v
    return totals


def probes(course, ps):
    """CPU of nbgrader's start-up (a process that grades no one) and of one confined kernel's
    start and stop, killed and graceful (each: the mean of PROBE_KERNELS)."""
    _, _, _, startup, startup_own = measured(["autograde", ps, "--student=nobody"], course)
    kernel = {}
    for mode in ("immediate", "graceful"):
        _, out, _, tree, own = measured(["kernels", mode, str(PROBE_KERNELS)], course)
        assert "Traceback" not in out, out
        kernel[mode] = (tree - own) / PROBE_KERNELS
    return (startup, startup_own), kernel


def report(totals, subs, startup, kernel, args):
    from instructor.grading.preprocessor import ConfinedExecute

    wall, tree, own, procs = totals
    (startup, startup_own) = startup
    mode = args.shutdown or ConfinedExecute.class_traits()["shutdown_kernel"].default_value
    start = kernel["immediate"]  # killing costs ~0.01 s: this is the start
    stop = max(0.0, kernel[mode] - start)
    # the start-up's own children (bwrap's probe) are start-up, not kernels
    kernels = tree - own - (startup - startup_own) * procs
    per = {
        "nbgrader start-up": startup * procs / subs,
        "nbgrader, per submission": (own - startup_own * procs) / subs,
        "kernel start": start,
        "kernel cells": kernels / subs - start - stop,
        f"kernel stop ({mode})": stop,
    }
    how = "cgroup (exact)" if CGROUP else f"process tree sampled every {SAMPLE:g} s (lower bound)"
    print(f"\nCPU per submission, counted by {how}, {subs} submissions in {procs} processes:")
    for name, value in per.items():
        print(f"  {name:26} {value:5.2f} s")
    print(f"  {'total (measured)':26} {tree / subs:5.2f} s")
    if mode != "graceful":
        print(f"  (a graceful stop would add {max(0.0, kernel['graceful'] - start):.2f} s)")
    print(f"  nbgrader start-up: {startup:.2f} s per process")
    work = tree / subs - per["nbgrader start-up"]  # everything but the start-ups
    count = 1 if args.per_student else CLASS / args.jobs  # students per process
    cpu = startup / count + work
    minutes = CLASS * SETS * cpu / CORES / 60
    print(
        f"projection: {CLASS} students x {SETS} problem sets on {CORES} idle cores, "
        f"{count:g} students per nbgrader process: {cpu:.2f} s of CPU per submission, "
        f"{minutes:.1f} min (goal {GOAL:g} min: {minutes / GOAL:.2f} x)"
    )
    print(
        f"wall here: {wall / subs:.2f} s per submission with {args.jobs} processes at once "
        f"(load average now {os.getloadavg()[0]:.1f})"
    )


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == [CHILD]:
        return child(argv[1:])
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--students", type=int, default=20)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--keep", help="grade in this folder and keep it (default: a temp dir)")
    parser.add_argument(
        "--per-student", action="store_true", help="one nbgrader process per student"
    )
    parser.add_argument(
        "--shutdown",
        choices=("immediate", "graceful"),
        help="how the kernel stops after the last cell (default: ConfinedExecute's)",
    )
    args = parser.parse_args(argv)
    from instructor.grading.course import write_course

    global CGROUP
    CGROUP = _cgroup_base() if sys.platform == "linux" else None

    course = Path(args.keep or tempfile.mkdtemp(prefix="bench-grade-")).resolve()
    if args.keep and course.exists():
        shutil.rmtree(course)
    problem_sets = write_course(course)
    if args.shutdown:  # to compare with the other way
        with open(course / "nbgrader_config.py", "a") as config:
            config.write(f"c.ConfinedExecute.shutdown_kernel = {args.shutdown!r}\n")
    students = [f"s{i:02d}" for i in range(1, args.students + 1)]
    print(f"{len(students)} students, {len(problem_sets)} problem sets, {args.jobs} jobs")
    try:
        totals = grade_class(course, problem_sets, students, args)
        startup, kernel = probes(course, problem_sets[0])
        report(totals, len(students) * len(problem_sets), startup, kernel, args)
    finally:
        if not args.keep:
            shutil.rmtree(course, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
