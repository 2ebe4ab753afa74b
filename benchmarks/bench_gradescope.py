"""How long Gradescope's ``run_autograder`` takes per submission (`make bench-gradescope`).

The autograder of each problem set is laid out in a temporary root standing in for
``/autograder`` and prepared once (setup.sh's last step; not timed); then ``run_autograder``
grades ``--runs`` submissions by turns (the instructor's solved copy, a blank copy, every other
answer solved), each timed from start to end (wall and CPU of the process and its children).
Goal: a median under 10 s on 2 cores.

Each submission is graded twice, by turns, both through ``tests/docker_seccomp.py`` (which
needs ``python3-seccomp``) in its Gradescope-like view of the file system: with bubblewrap
(``--view-only``: the view, no constraint) and as root under Docker's seccomp constraint, where
bubblewrap cannot start and the privilege drop (``instructor/grading/privdrop.py``) confines the
kernel. Both pay the view's own cost (a mount namespace, the checkout's overlay, a Python start; the
launcher alone is timed and printed). Goal: privdrop at most 1.10 x bubblewrap, as the median
over submissions of privdrop's wall time over bubblewrap's for the same submission (graded one
after the other: the load of a shared machine evens out).

CPU (of the processes ``run_autograder`` waited for) is not comparable between the two:
bubblewrap's kernel dies with its PID namespace when bwrap is stopped and its CPU is not
counted (about 0.04 s counted for a kernel that used 0.8 s), the privdrop kernel's is.

    python benchmarks/bench_gradescope.py [--runs 6] [--only bubblewrap|privdrop] [ps01 ...]
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import nbformat

from instructor.grading import gradescope

ROOT = Path(__file__).resolve().parents[1]

GOAL = 10.0
RATIO_GOAL = 1.10
HARNESS = ROOT / "tests" / "docker_seccomp.py"


def harness(argv, constraint=True):
    """``argv`` in tests/docker_seccomp.py's Gradescope view, under Docker's constraint or not."""
    from tests.docker_seccomp import command

    return command(argv, ROOT, (sys.base_prefix, sys.prefix), constraint)


def lay_out(ps, top):
    for name, data in gradescope.members(ps).items():
        path = top / "source" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(data)
    env = {**os.environ, "ROTATIONS_AUTOGRADER_ROOT": str(top)}
    prepare = [sys.executable, "-m", "instructor.grading.gradescope_run", "prepare"]
    subprocess.run(prepare, cwd=top / "source", env=env, check=True, capture_output=True)


def submission(top, ps, kind):
    solved = next((top / "course" / "source" / ps).glob("*.ipynb"))
    blank = top / "course" / "release" / ps / solved.name
    nb = nbformat.read(solved if kind == "solved" else blank, as_version=4)
    if kind == "half":
        good = nbformat.read(solved, as_version=4)
        for i, c in enumerate(nb.cells):
            if c.get("id", "").endswith("-answer") and i % 2 == 0:
                nb.cells[i] = good.cells[i]
    return solved.name, nb


def run_once(top, ps, kind, n, confinement="bubblewrap"):
    sub = top / "submission"
    shutil.rmtree(sub, ignore_errors=True)
    sub.mkdir()
    name, nb = submission(top, ps, kind)
    nbformat.write(nb, sub / name)
    (top / "submission_metadata.json").write_text(json.dumps({"users": [{"sid": f"b{n:03d}"}]}))
    env = {**os.environ, "ROTATIONS_AUTOGRADER_ROOT": str(top), "ROTATIONS_PYTHON": sys.executable}
    argv = ["bash", str(top / "source" / "run_autograder")]
    argv = harness(argv, constraint=confinement == "privdrop")
    before = os.times()
    start = time.perf_counter()
    subprocess.run(argv, env=env, check=True, capture_output=True)
    wall = time.perf_counter() - start
    after = os.times()
    cpu = (after.children_user - before.children_user) + (
        after.children_system - before.children_system
    )
    results = json.loads((top / "results" / "results.json").read_text())
    used = results.get("extra_data", {}).get("confinement")
    if used != confinement:
        raise RuntimeError(f"expected {confinement}, graded by {used}: {results['output']}")
    return wall, cpu, results["score"]


def launcher_cost(runs=5):
    """Wall seconds of the privdrop launcher alone (``true`` under it), the median."""
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        subprocess.run(harness(["true"]), check=True)
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("sets", nargs="*", default=["ps01", "ps02"])
    parser.add_argument("--runs", type=int, default=6)
    parser.add_argument("--only", choices=("bubblewrap", "privdrop"))
    args = parser.parse_args(argv)
    kinds = [args.only] if args.only else ["bubblewrap", "privdrop"]
    print(f"{'set':5} {'confinement':11} {'median s':>9} {'worst s':>8} {'median CPU':>11}  scores")
    walls = {k: [] for k in kinds}
    for ps in args.sets:
        top = Path(tempfile.mkdtemp(prefix="bench-gradescope-"))
        runs = {k: [] for k in kinds}
        try:
            lay_out(ps, top)
            for i in range(args.runs):
                kind = ("solved", "blank", "half")[i % 3]
                for c in kinds if i % 2 == 0 else kinds[::-1]:  # by turns: load evens out
                    runs[c].append(run_once(top, ps, kind, i, c))
        finally:
            shutil.rmtree(top, ignore_errors=True)
        for c in kinds:
            w = [r[0] for r in runs[c]]
            walls[c] += w
            print(
                f"{ps:5} {c:11} {statistics.median(w):9.1f} {max(w):8.1f} "
                f"{statistics.median(r[1] for r in runs[c]):11.1f}  {[r[2] for r in runs[c]]}"
            )
    for c in kinds:
        med = statistics.median(walls[c])
        verdict = "met" if med < GOAL else "NOT met"
        print(f"{c}: median {med:.1f} s per submission (goal < {GOAL:.0f} s: {verdict})")
    if len(kinds) == 2:
        pairs = list(zip(walls["privdrop"], walls["bubblewrap"], strict=True))
        launcher = launcher_cost()
        ratio = statistics.median(p / b for p, b in pairs)
        verdict = "met" if ratio <= RATIO_GOAL else "NOT met"
        print(
            f"privdrop / bubblewrap, median of {len(pairs)} paired submissions: {ratio:.2f} "
            f"(goal <= {RATIO_GOAL:.2f}: {verdict}); the test launcher alone {launcher:.2f} s "
            "(in both)"
        )
    print(f"load average {os.getloadavg()[0]:.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
