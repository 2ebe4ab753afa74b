"""Benchmark: how long course_lib.exercises.check takes, per exercise (run by hand).

Students press shift-enter on a check cell and expect an answer at once; the target is well under
a second per check. Prints, for every exercise, the best of several runs of check() on the
reference answer and on a wrong answer (the hint path), after one warm-up call.
"""

import time

import numpy as np

from course_lib import exercises

REPEATS = 5


def best_time(fn):
    fn()
    best = float("inf")
    for _ in range(REPEATS):
        start = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - start)
    return best


def wrong(answer):
    """A plausible mistake of the same shape: the answer with its sign flipped."""
    return -answer if hasattr(answer, "__neg__") else -np.asarray(answer)


def main():
    print(f"{'exercise':24} {'correct':>10} {'wrong':>10}   (best of {REPEATS}, target < 1 s)")
    for name in exercises.names():
        expected = exercises.get(name)._expected()
        t_ok = best_time(lambda: exercises.check(name, expected))
        t_bad = best_time(lambda: exercises.check(name, wrong(expected)))
        print(f"{name:24} {t_ok * 1e3:8.1f}ms {t_bad * 1e3:8.1f}ms")


if __name__ == "__main__":
    main()
