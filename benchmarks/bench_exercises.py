"""Benchmark: the cost of a guess against the fingerprints, and of a check() (run by hand).

    python benchmarks/bench_exercises.py

1. **Offline guessing.** What one guess costs an attacker who holds the package: the old
   fingerprint (a salted sha256 of an entry's cell, as the package stored before) against the
   new one (a salted scrypt digest, ``course_lib.exercises._digests.stretched``), CPU time per
   digest, best of several runs; target: the new one at least 1,000 times slower.
2. **One check.** For every exercise, the median and the worst (wall clock and CPU time) of
   REPEATS calls of check() on the reference solution (right), on its first known mistake or its
   negative (wrong) and on a hostile answer (a huge power, a long sum, a deep matrix power, a
   long string). The digest cache is emptied before every call, so each call pays for all its
   digests. Target: at most 200 ms.
3. **Hostile input.** The inputs of issue 17, each once; target: a message within 1 s.
4. **Variants** (issue 33). The one-time cost of reading the variant tables and the
   fingerprints in a fresh process (the first check of a session); then, for every exercise
   with variants, check() of a student on the table's last row (right, and its first known
   mistake) and the grader's verdict on that student's right answer (``instructor.grading.verify``:
   the reference solution run on the student's numbers), median of REPEATS.

CPU time is what the machine is asked to do; the wall clock on a shared machine also counts
the time other processes hold the core.
"""

import functools
import hashlib
import os
import statistics
import subprocess
import sys
import time
from decimal import Decimal
from pathlib import Path

import numpy as np
import sympy as sp

from benchmarks._timing import best_times
from course_lib import exercises
from course_lib.exercises import Choice, Value, _digests, _engine, alpha, check
from instructor import answers as instructor_answers

ROOT = Path(__file__).resolve().parents[1]


REPEATS = 5
CHECK_TARGET, HOSTILE_TARGET, GUESS_RATIO_TARGET = 0.200, 1.0, 1000


def old_digest(name, i, cell):
    """The fingerprint of an entry before: a salted sha256, 16 hex digits."""
    text = "|".join(["rotations-course/exercises/v1", name, str(i), str(cell)])
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def new_digest(name, i, cell):
    """A digest now, without the cache (an attacker's guess is new): a whole vector's cells."""
    return _digests.stretched.__wrapped__(name, "value0", (cell, i, 0))


#: Simple closed forms an attacker tries per number (attack 8 of the grading attacks).
FORMS = 7_300


def guess_costs():
    counter = iter(range(10**9))
    old, new = best_times(
        [
            lambda: old_digest("vb_from_va", 0, next(counter)),
            lambda: new_digest("vb_from_va", 0, next(counter)),
        ],
        repeats=5,
    )
    print("1. Offline guessing: CPU time per digest (best of 5)")
    print(f"   before (salted sha256):   {old * 1e6:9.2f} µs")
    print(f"   now (salted scrypt {_digests.SCRYPT}): {new * 1e3:6.2f} ms")
    print(f"   ratio {new / old:,.0f}x (target at least {GUESS_RATIO_TARGET:,}x)")
    # A 3-vector of simple closed forms, FORMS candidates per entry: with a digest per entry
    # (before) the entries are found one at a time; digested whole, only together.
    years = FORMS**3 * new / 3.15e7
    print(f"   a 3-vector of simple closed forms ({FORMS:,} per entry), searched offline:")
    print(f"     a digest per entry, sha256 (issue 17):   {3 * FORMS * old:10.3f} s")
    print(f"     a digest per entry, scrypt (stop 20):    {3 * FORMS * new:10.1f} s")
    print(f"     one digest of the whole vector (now):    {years:10.2e} years of CPU\n")


def timed(fn):
    _digests.stretched.cache_clear()
    wall, cpu = time.perf_counter(), time.process_time()
    fn()
    return time.perf_counter() - wall, time.process_time() - cpu


def timings(fn):
    fn()  # warm-up: sample points and lambdify caches, as after a notebook's first check
    runs = [timed(fn) for _ in range(REPEATS)]
    walls, cpus = [w for w, _ in runs], [c for _, c in runs]
    return statistics.median(walls), max(walls), statistics.median(cpus), max(cpus)


def answers(ex):
    """(right, wrong, hostile) answers of one exercise."""
    mistakes = instructor_answers.mistakes(ex.chapter)
    ns = instructor_answers.worked(ex.name)
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


def check_costs():
    print(f"2. One check(), ms: median / worst wall clock, median / worst CPU ({REPEATS} calls)")
    print(f"   {'exercise':26} {'right':>27} {'wrong':>27} {'hostile':>27}")
    worst_wall, worst_cpu = 0.0, 0.0
    for name, ex in exercises.EXERCISES.items():
        cells = []
        for answer in answers(ex):
            mw, ww, mc, wc = timings(functools.partial(check, name, answer))
            worst_wall, worst_cpu = max(worst_wall, ww), max(worst_cpu, wc)
            cells.append(f"{mw * 1e3:5.0f}/{ww * 1e3:5.0f} {mc * 1e3:5.0f}/{wc * 1e3:5.0f}")
        print(f"   {name:26} " + " ".join(f"{c:>27}" for c in cells))
    print(
        f"   slowest: {worst_wall * 1e3:.0f} ms wall, {worst_cpu * 1e3:.0f} ms CPU "
        f"(target {CHECK_TARGET * 1e3:.0f} ms)\n"
    )


def _deep(n):
    e = alpha
    for _ in range(n):
        e = sp.sin(e)
    return e


class _NumpyClaim(np.float64):
    pass


_NumpyClaim.__module__ = "numpy"


class _SympySub(sp.Symbol):
    pass


HOSTILE = [
    ("two_mirrors", "Decimal('1E+10000000')", lambda: Decimal("1E+10000000")),
    ("two_mirrors", "Decimal('1E+100000000')", lambda: Decimal("1E+100000000")),
    ("motion_from_points", "[[0]*1000]*1000", lambda: [[0] * 1000] * 1000),
    ("vb_from_va", "list(range(10**5))", lambda: list(range(10**5))),
    ("two_mirrors", "sp.Pow(2, 10**29, evaluate=False)", lambda: sp.Pow(2, 10**29, evaluate=False)),
    ("composed_angle", "a 300-deep expression", lambda: _deep(300)),
    ("two_mirrors", "numpy float subclass", lambda: _NumpyClaim(0.5)),
    ("composed_angle", "sympy subclass", lambda: _SympySub("q")),
    ("two_mirrors", "0-d array np.array(0.87)", lambda: np.array(0.87)),
    ("hat_fifth", "a wrong explicit 3x3 Matrix", lambda: sp.Matrix(3, 3, range(9)) * 7),
]


def hostile_costs():
    print("3. Hostile input: wall clock of one check() (target 1 s), and the message")
    worst = 0.0
    for name, label, make in HOSTILE:
        answer = make()
        _digests.stretched.cache_clear()
        start = time.perf_counter()
        result = check(name, answer)
        elapsed = time.perf_counter() - start
        worst = max(worst, elapsed)
        print(f"   {elapsed * 1e3:7.1f} ms  {label:36} {str(result)[:90]}")
    print(f"   slowest {worst * 1e3:.0f} ms (target {HOSTILE_TARGET * 1e3:.0f} ms)")


def load_costs():
    """Wall clock of reading the tables and the fingerprints in a fresh process, best of 3."""
    code = (
        "import time; from course_lib.exercises import _fingerprints; "
        "from course_lib.exercises._variants import table; t = time.perf_counter(); "
        "table(); _fingerprints(); print(time.perf_counter() - t)"
    )
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    runs = [
        float(
            subprocess.run(
                [sys.executable, "-c", code],
                capture_output=True,
                text=True,
                check=True,
                env=env,
                cwd=ROOT,
            ).stdout
        )  # fmt: skip
        for _ in range(3)
    ]
    return min(runs)


def _last_row_student(ex):
    from course_lib.exercises import _variants as V

    rows = V.table()["keys"].get(ex.variants.key) or [None]
    salt = [s for s in [V.table().get("salts", {}).get(ex.variants.key)] if s]
    target = len(rows) - 1
    return next(
        f"s{i}" for i in range(10**6) if V.variant_index(ex.variants.key, len(rows), f"s{i}", *salt)
        == target
    )  # fmt: skip


def _graded(verify, name, record, sid):
    """The grader's verdict with its cache of reference answers emptied: every student of a
    class has other numbers, so grading runs the solution each time."""
    verify.expected.cache_clear()
    return verify.verdict(name, record, sid)


def variant_costs():
    from course_lib.exercises import parameters, set_student_id
    from course_lib.record import answer_record
    from instructor.grading import verify

    print("4. Variants: reading the tables and fingerprints once, then one check() / verdict")
    print(f"   first read in a fresh process: {load_costs() * 1e3:.0f} ms wall")
    print(f"   {'exercise':26} {'right':>13} {'wrong':>13} {'grade':>13}   (ms, median wall/CPU)")
    worst = 0.0
    for name, ex in exercises.EXERCISES.items():
        if ex.variants is None:
            continue
        sid = _last_row_student(ex)
        set_student_id(sid)
        mistakes = instructor_answers.mistakes(ex.chapter)
        ns = instructor_answers.worked(name, parameters(name))
        right = ns[ex.answer_variable]
        wrong = eval(next(iter(mistakes[name].values())), ns) if mistakes.get(name) else -right
        record = answer_record(name, right)
        cells = []
        for fn in (
            functools.partial(check, name, right),
            functools.partial(check, name, wrong),
            functools.partial(_graded, verify, name, record, sid),
        ):
            mw, ww, mc, wc = timings(fn)
            worst = max(worst, ww)
            cells.append(f"{mw * 1e3:5.0f}/{mc * 1e3:5.0f}")
        print(f"   {name:26} " + " ".join(f"{c:>13}" for c in cells))
    set_student_id(None)
    print(f"   slowest: {worst * 1e3:.0f} ms wall\n")


def main():
    guess_costs()
    check_costs()
    hostile_costs()
    variant_costs()


if __name__ == "__main__":
    main()
