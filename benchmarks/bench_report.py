"""How long the class report takes: 200 students × 5 problem sets (goal: at most 30 s).

A synthetic Gradescope export per problem set (``submission_metadata.yml`` with each test's
``extra_data``, as ``run_autograder`` writes it): every student answers every exercise of the
set, right, with one of the exercise's known mistakes, with one of a few unexplained answers, or
not at all, at random (seeded), on a random variant. Timed: reading the five exports, the
numbers and writing both copies (HTML with its figures, CSV) of the five reports.

    python -m benchmarks.bench_report [--students 200] [--sets 5]
"""

from __future__ import annotations

import argparse
import random
import tempfile
import time
from pathlib import Path

import yaml

from course_lib.exercises import get
from grader.course import problem_sets
from grader.report import write_reports
from grader.report_data import from_gradescope

GOAL = 30.0


def _extra(ex, rng):
    roll = rng.random()
    variant = rng.randrange(16) if ex.variants is not None else None
    item = {"exercise": ex.name, "variant": variant, "shown": variant, "mistake": None}
    item["checked"] = rng.random() < 0.8
    if roll < 0.5:
        return ex.points, {**item, "verdict": "correct"}
    if roll < 0.8 and ex.mistakes:
        return 0, {**item, "verdict": "wrong", "mistake": rng.choice(sorted(ex.mistakes))}
    if roll < 0.95:
        k = rng.randrange(4)
        return 0, {**item, "verdict": "wrong", "group": f"g{k}", "answer": f"answer {k}"}
    return 0, {**item, "verdict": "no answer"}


def synthetic_export(folder, ps, names, students, seed=0):
    """Write ``folder/submission_metadata.yml`` for ``students`` answering exercises ``names``
    of problem set ``ps``; returns the folder."""
    rng = random.Random(seed)
    data = {}
    for i in range(students):
        tests = []
        for number, name in enumerate(names, 1):
            ex = get(name)
            score, extra = _extra(ex, rng)
            tests.append(
                {
                    "name": name,
                    "number": str(number),
                    "score": float(score),
                    "max_score": float(ex.points),
                    "extra_data": extra,
                }
            )
        data[f"submission_{1000 + i}"] = {
            ":submitters": [{":name": f"Student {i}", ":sid": f"s{i:04d}"}],
            ":score": sum(t["score"] for t in tests),
            ":status": "processed",
            ":results": {"tests": tests, "extra_data": {"assignment": ps}},
        }
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "submission_metadata.yml").write_text(yaml.safe_dump(data))
    return folder


def _names(nb):
    return [
        c.metadata["nbgrader"]["grade_id"][: -len("-check")]
        for c in nb.cells
        if c.get("metadata", {}).get("nbgrader", {}).get("grade")
    ]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--students", type=int, default=200)
    parser.add_argument("--sets", type=int, default=5)
    args = parser.parse_args(argv)
    sets = list(problem_sets().items())[: args.sets]
    with tempfile.TemporaryDirectory() as tmp:
        exports = [
            synthetic_export(Path(tmp) / ps, ps, _names(nb), args.students, seed)
            for seed, ((ps, _), nb) in enumerate(sets)
        ]
        start, cpu = time.perf_counter(), time.process_time()
        loaded = [from_gradescope(folder) for folder in exports]
        written = write_reports(loaded, Path(tmp) / "report")
        wall, cpu = time.perf_counter() - start, time.process_time() - cpu
    print(
        f"report of {args.students} students x {len(sets)} problem sets: {wall:.1f} s wall, "
        f"{cpu:.1f} s CPU, {len(written)} files; goal {GOAL:.0f} s: ratio {wall / GOAL:.2f}"
    )
    return 0 if wall <= GOAL else 1


if __name__ == "__main__":
    raise SystemExit(main())
