"""How long the class report takes: 200 students × 5 problem sets (goal: at most 30 s).

A synthetic Gradescope export per problem set (``submission_metadata.yml`` with each test's
``extra_data``, as ``run_autograder`` writes it): every student answers every exercise of the
set, right, with one of the exercise's known mistakes, with one of a few unexplained answers, or
not at all, at random (seeded), on a random variant. Timed: reading the five exports, the
numbers and writing both copies (HTML with its figures, CSV) of the five reports.

    python -m benchmarks.bench_report [--students 200] [--sets 5] [--nbgrader]

``--nbgrader``: the same answers in an nbgrader course directory instead (a real
``gradebook.db`` made with nbgrader's API and the grader's ``answer-log/``; making it takes
about a minute and is not timed).
"""

from __future__ import annotations

import argparse
import random
import tempfile
import time
from pathlib import Path

import yaml

from course_lib.exercises import get
from instructor.grading import answer_log
from instructor.grading.course import problem_sets
from instructor.grading.report import write_reports
from instructor.grading.report_data import from_course, from_gradescope

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


def synthetic_course(folder, sets, students, seed=0):
    """An nbgrader course directory of ``students`` answering ``sets`` = [(ps, names)]."""
    import os
    import sys
    import warnings

    from nbgrader.api import Gradebook
    from sqlalchemy.exc import SAWarning

    warnings.simplefilter("ignore", SAWarning)  # nbgrader's own add_submission (SQLAlchemy 2)

    bin_dir = str(Path(sys.executable).parent)  # nbgrader runs alembic from PATH
    os.environ["PATH"] = f"{bin_dir}{os.pathsep}{os.environ.get('PATH', '')}"
    rng = random.Random(seed)
    ids = [f"s{i:04d}" for i in range(students)]
    with Gradebook(f"sqlite:///{folder / 'gradebook.db'}") as gb:
        for sid in ids:
            gb.add_student(sid, first_name="Student", last_name=sid)
        for ps, names in sets:
            gb.add_assignment(ps)
            gb.update_or_create_notebook("nb", ps)
            for n in names:
                gb.update_or_create_grade_cell(
                    f"{n}-check", "nb", ps, max_score=get(n).points, cell_type="code"
                )
            for sid in ids:
                drawn = {n: _extra(get(n), rng) for n in names}
                for g in gb.add_submission(ps, sid).notebooks[0].grades:
                    g.auto_score = drawn[g.name[: -len("-check")]][0]
                answer_log.write(folder, ps, sid, "nb", [e for _, e in drawn.values()])
            gb.db.commit()
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
    parser.add_argument("--nbgrader", action="store_true", help="from an nbgrader course")
    args = parser.parse_args(argv)
    sets = [(ps, _names(nb)) for (ps, _), nb in list(problem_sets().items())[: args.sets]]
    with tempfile.TemporaryDirectory() as tmp:
        if args.nbgrader:
            course = synthetic_course(Path(tmp), sets, args.students)
        else:
            exports = [
                synthetic_export(Path(tmp) / ps, ps, names, args.students, seed)
                for seed, (ps, names) in enumerate(sets)
            ]
        start, cpu = time.perf_counter(), time.process_time()
        if args.nbgrader:
            loaded = from_course(course)
        else:
            loaded = [from_gradescope(folder) for folder in exports]
        written = write_reports(loaded, Path(tmp) / "report")
        wall, cpu = time.perf_counter() - start, time.process_time() - cpu
    print(
        f"report of {args.students} students x {len(sets)} problem sets "
        f"({'nbgrader course' if args.nbgrader else 'Gradescope exports'}): {wall:.1f} s wall, "
        f"{cpu:.1f} s CPU, {len(written)} files; goal {GOAL:.0f} s: ratio {wall / GOAL:.2f}"
    )
    return 0 if wall <= GOAL else 1


if __name__ == "__main__":
    raise SystemExit(main())
