"""The one timing helper of the benchmarks: CPU time, best of N, candidates interleaved.

Shared machines are noisy: another process can take the core in the middle of a run. So the
clock is the CPU time of this process (``time.process_time``: time spent off the core does
not count; the code is single-threaded, so on an idle machine it equals the wall time), the
best (smallest) of several repeats is kept, and the candidates are timed in turn within each
repeat (ours, the reference, ours, ...), so both see the same load and their ratio stays
meaningful when the absolute times drift.

    from _timing import best_times
    t_ours, t_ref = best_times([lambda: ours(x), lambda: reference(x)], repeats=7)
"""

import time

CLOCK = time.process_time
CLOCK_NAME = "CPU time (time.process_time)"


def calls_per_repeat(fn, target=0.02):
    """How many calls of ``fn`` take about ``target`` seconds (at least 1), after a warm-up."""
    fn()
    number = 1
    while True:
        start = CLOCK()
        for _ in range(number):
            fn()
        if CLOCK() - start >= target or number >= 1 << 20:
            return number
        number *= 4


def best_times(fns, repeats=7, number=None):
    """Seconds per call of each function: the best of ``repeats``, the functions interleaved.

    Parameters
    ----------
    fns : list of callables taking no arguments
    repeats : int
        How many rounds; each round times every function once, in turn.
    number : int, optional
        Calls per timing (default: enough for about 20 ms, found per function).

    Returns
    -------
    list of float
        Seconds per call, in the order of ``fns``.
    """
    numbers = [number or calls_per_repeat(fn) for fn in fns]
    best = [float("inf")] * len(fns)
    for _ in range(repeats):
        for i, (fn, n) in enumerate(zip(fns, numbers)):
            start = CLOCK()
            for _ in range(n):
                fn()
            best[i] = min(best[i], (CLOCK() - start) / n)
    return best


def best_time(fn, repeats=7, number=None):
    """Seconds per call of one function, the best of ``repeats`` (see :func:`best_times`)."""
    return best_times([fn], repeats, number)[0]
