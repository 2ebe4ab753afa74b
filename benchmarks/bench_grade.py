"""How long real nbgrader takes to grade a class (`make bench-grade`; a benchmark, not a test).

A class of ``--students`` simulated students (by turns: the instructor's solved copy, a blank
copy, a half-solved copy) hands in every problem set of a `make course` directory. Each
problem set is autograded as an instructor grades a large class: one
``nbgrader autograde PS --student=ID`` process per student, ``--jobs`` of them at a time (one
per core). Printed per problem set: the median and worst wall and CPU time of one student's
autograde (CPU: the nbgrader process and its confined kernel), the wall time of the whole
class; then the projection for 60 students and 5 problem sets from the measured throughput.
With ``--split``, ``--jobs`` nbgrader processes each grade a group of students
(``--student=GLOB``, one start-up per process); the per-submission numbers are then means.

    python benchmarks/bench_grade.py [--students 20] [--jobs 2] [--split] [--keep DIR]
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import nbformat

from instructor.grading.course import write_course

ROOT = Path(__file__).resolve().parents[1]

NBGRADER = Path(sys.executable).with_name("nbgrader")
KINDS = ("solved", "blank", "half")


def nbgrader(args, cwd):
    """(returncode, output, wall seconds, CPU seconds of the process and its children)."""
    env = {**os.environ, "PATH": f"{NBGRADER.parent}{os.pathsep}{os.environ.get('PATH', '')}"}
    start = time.perf_counter()
    proc = subprocess.Popen(
        [str(NBGRADER), *args], cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT
    )
    out = proc.stdout.read().decode(errors="replace")
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    return proc.returncode, out, time.perf_counter() - start, usage.ru_utime + usage.ru_stime


def hand_in(course, ps, student, kind):
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


def grade_one(course, ps, student):
    for _ in range(3):  # a parallel writer may hold the sqlite gradebook for a moment
        code, out, wall, cpu = nbgrader(["autograde", ps, f"--student={student}"], course)
        if code == 0:
            return wall, cpu
        if "database is locked" not in out:
            break
    raise RuntimeError(f"autograde {ps} {student} failed:\n{out[-3000:]}")


def grade_split(course, ps, students, jobs):
    """``jobs`` nbgrader processes, each grading every student whose id ends in one of its
    digits (``--student='s*[13579]'``): one start-up of nbgrader per process, not per student.
    Returns the wall time of the class and the CPU time of each process."""
    groups = ["".join(d for d in "0123456789" if int(d) % jobs == g) for g in range(jobs)]
    args = [["autograde", ps, f"--student=s*[{digits}]"] for digits in groups if digits]
    start = time.perf_counter()
    with ThreadPoolExecutor(jobs) as pool:
        runs = list(pool.map(lambda a: nbgrader(a, course), args))
    for code, out, _, _ in runs:
        if code != 0:
            raise RuntimeError(f"autograde {ps} failed:\n{out[-3000:]}")
    return time.perf_counter() - start, [r[3] for r in runs]


def scores(course, ps):
    from nbgrader.api import Gradebook

    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gb:
        return {s.student.id: s.score for s in gb.find_assignment(ps).submissions}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--students", type=int, default=20)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--keep", help="grade in this folder and keep it (default: a temp dir)")
    parser.add_argument(
        "--split",
        action="store_true",
        help="one nbgrader process per group of students (--student=GLOB) instead of per student",
    )
    args = parser.parse_args(argv)
    course = Path(args.keep or tempfile.mkdtemp(prefix="bench-grade-"))
    if args.keep and course.exists():
        shutil.rmtree(course)
    problem_sets = write_course(course)
    students = [f"s{i:02d}" for i in range(1, args.students + 1)]
    print(f"{len(students)} students, {len(problem_sets)} problem sets, {args.jobs} jobs")
    heads = ("set", "median s", "worst s", "median CPU", "worst CPU", "class s")
    print(f"{heads[0]:5} " + " ".join(f"{h:>10}" for h in heads[1:]))
    total_wall, all_cpu = 0.0, []
    try:
        for ps in problem_sets:
            code, out, _, _ = nbgrader(["generate_assignment", ps, "--create"], course)
            assert code == 0, out
            for i, sid in enumerate(students):
                hand_in(course, ps, sid, KINDS[i % len(KINDS)])
            if args.split:
                batch, cpu = grade_split(course, ps, students, args.jobs)
                times = [(batch * args.jobs / len(students), sum(cpu) / len(students))]
            else:
                start = time.perf_counter()
                with ThreadPoolExecutor(args.jobs) as pool:
                    times = list(pool.map(lambda s, p=ps: grade_one(course, p, s), students))
                batch = time.perf_counter() - start
            total_wall += batch
            walls, cpus = [t[0] for t in times], [t[1] for t in times]
            got = scores(course, ps)
            solved_full = all(got[s] > 0 for i, s in enumerate(students) if i % 3 == 0)
            blank_zero = all(got[s] == 0 for i, s in enumerate(students) if i % 3 == 1)
            assert solved_full and blank_zero, got
            row = (statistics.median(walls), max(walls), statistics.median(cpus), max(cpus), batch)
            print(f"{ps:5} " + " ".join(f"{v:10.1f}" for v in row))
            all_cpu += cpus
        per = total_wall / (len(students) * len(problem_sets))
        print(
            f"throughput: {per:.1f} s of wall time per submission with {args.jobs} parallel "
            f"nbgrader processes; 60 students x 5 problem sets: {60 * 5 * per / 60:.0f} min"
        )
        cores = os.cpu_count() or 1
        cpu = statistics.median(all_cpu)
        print(
            f"CPU: median {cpu:.1f} s per submission; 60 x 5 on {cores} idle cores: "
            f"{60 * 5 * cpu / cores / 60:.0f} min (load average now {os.getloadavg()[0]:.1f})"
        )
    finally:
        if not args.keep:
            shutil.rmtree(course, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
