"""How long Gradescope's ``run_autograder`` takes per submission (`make bench-gradescope`).

The autograder of each problem set is laid out in a temporary root standing in for
``/autograder`` and prepared once (setup.sh's last step; not timed); then ``run_autograder``
grades ``--runs`` submissions by turns (the instructor's solved copy, a blank copy, every other
answer solved), each timed from start to end (wall and CPU of the process and its children).
Goal: a median under 10 s on 2 cores.

    python benchmarks/bench_gradescope.py [--runs 6] [ps01 ...]
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

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
from grader import gradescope  # noqa: E402

GOAL = 10.0


def lay_out(ps, top):
    for name, data in gradescope.members(ps).items():
        path = top / "source" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(data)
    env = {**os.environ, "ROTATIONS_AUTOGRADER_ROOT": str(top)}
    script = str(top / "source" / "grader" / "gradescope_run.py")
    subprocess.run([sys.executable, script, "prepare"], env=env, check=True, capture_output=True)


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


def run_once(top, ps, kind, n):
    sub = top / "submission"
    shutil.rmtree(sub, ignore_errors=True)
    sub.mkdir()
    name, nb = submission(top, ps, kind)
    nbformat.write(nb, sub / name)
    (top / "submission_metadata.json").write_text(json.dumps({"users": [{"sid": f"b{n:03d}"}]}))
    env = {**os.environ, "ROTATIONS_AUTOGRADER_ROOT": str(top), "ROTATIONS_PYTHON": sys.executable}
    before = os.times()
    start = time.perf_counter()
    subprocess.run(
        ["bash", str(top / "source" / "run_autograder")], env=env, check=True, capture_output=True
    )
    wall = time.perf_counter() - start
    after = os.times()
    cpu = (after.children_user - before.children_user) + (
        after.children_system - before.children_system
    )
    score = json.loads((top / "results" / "results.json").read_text())["score"]
    return wall, cpu, score


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("sets", nargs="*", default=["ps01", "ps02"])
    parser.add_argument("--runs", type=int, default=6)
    args = parser.parse_args(argv)
    print(f"{'set':5} {'median s':>9} {'worst s':>8} {'median CPU':>11}  scores")
    walls = []
    for ps in args.sets:
        top = Path(tempfile.mkdtemp(prefix="bench-gradescope-"))
        try:
            lay_out(ps, top)
            runs = [
                run_once(top, ps, ("solved", "blank", "half")[i % 3], i) for i in range(args.runs)
            ]
        finally:
            shutil.rmtree(top, ignore_errors=True)
        w = [r[0] for r in runs]
        walls += w
        print(
            f"{ps:5} {statistics.median(w):9.1f} {max(w):8.1f} "
            f"{statistics.median(r[1] for r in runs):11.1f}  {[r[2] for r in runs]}"
        )
    med = statistics.median(walls)
    verdict = "met" if med < GOAL else "NOT met"
    print(
        f"median {med:.1f} s per submission (goal < {GOAL:.0f} s: {verdict}); "
        f"load average {os.getloadavg()[0]:.1f}"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
