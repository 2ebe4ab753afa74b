"""Benchmark: how long course_lib.exercises.check takes, per exercise (run by hand).

    python benchmarks/bench_exercises.py

A student presses shift-enter on a check cell and expects an answer at once. For every exercise
this prints the median and the worst of REPEATS timed calls (after one warm-up call) of check()
on the reference solution (right), on its first known mistake or its negative (wrong) and on a
hostile answer (a huge power, a long sum, a deep matrix power, a long string). Targets: median
at most 20 ms, worst at most 1 s.
"""

import functools
import statistics
import sys
import time
from pathlib import Path

import numpy as np
import sympy as sp

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from course_lib import exercises  # noqa: E402
from course_lib.exercises import Choice, Value, _engine, check  # noqa: E402
from tools import exercise_fingerprints as F  # noqa: E402

REPEATS = 7
MEDIAN_TARGET, WORST_TARGET = 0.020, 1.0


def timings(fn):
    fn()
    out = []
    for _ in range(REPEATS):
        start = time.perf_counter()
        fn()
        out.append(time.perf_counter() - start)
    return statistics.median(out), max(out)


def answers(ex):
    """(right, wrong, hostile) answers of one exercise."""
    sols, mistakes = F.solutions(ex.chapter)
    ns = F.run(ex, sols[ex.name])
    right = ns[ex.answer_variable]
    ms = mistakes.get(ex.name, {})
    spec = ex.answer
    if ms:
        wrong = eval(next(iter(ms.values())), ns)
    elif isinstance(spec, Choice):
        wrong = "a"
    else:
        wrong = -right
    if isinstance(spec, Choice):
        hostile = "ab" * 50_000
    elif isinstance(spec, Value):
        hostile = (
            np.full(spec.shape, sp.Add(*[sp.sin(k) for k in range(1, 300)]), dtype=object).tolist()
            if spec.shape
            else sp.Add(*[sp.sin(k) for k in range(1, 1400)])
        )
    elif spec.matrix_degree is not None:
        mats = [s for s in spec.allowed if isinstance(s, sp.MatrixSymbol)]
        square = next((m for m in mats if m.shape == (3, 3)), None)
        base = square if square is not None else mats[0] * mats[0].T
        hostile = sp.MatPow(base, 40)
        if spec.shape != (3, 3):
            hostile = hostile * next(m for m in mats if m.shape == (3, 1))
    else:
        syms = _engine.base_symbols(spec)
        big = (sp.Add(*syms) + 1) ** 20
        hostile = big if spec.shape == () else [big] * spec.shape[0]
    return right, wrong, hostile


def main():
    print(
        f"{'exercise':26} {'right':>15} {'wrong':>15} {'hostile':>15}   "
        f"(median / worst of {REPEATS}, ms)"
    )
    medians, worsts = [], []
    for name, ex in exercises.EXERCISES.items():
        cells = []
        for answer in answers(ex):
            med, worst = timings(functools.partial(check, name, answer))
            medians.append(med)
            worsts.append(worst)
            cells.append(f"{med * 1e3:6.1f} / {worst * 1e3:6.1f}")
        print(f"{name:26} " + " ".join(f"{c:>15}" for c in cells))
    print(
        f"\nslowest median {max(medians) * 1e3:.1f} ms (target {MEDIAN_TARGET * 1e3:.0f} ms, "
        f"ratio {max(medians) / MEDIAN_TARGET:.2f}); slowest worst {max(worsts) * 1e3:.1f} ms "
        f"(target {WORST_TARGET * 1e3:.0f} ms, ratio {max(worsts) / WORST_TARGET:.2f})"
    )


if __name__ == "__main__":
    main()
