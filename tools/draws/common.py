"""What the chapters' variant draws share (tools/draws/chNN.py)."""

import numpy as np

__all__ = ["apart", "signed_permutation"]


def apart(exercise, values, gap=0.01):
    """Why the answer and the known mistakes of ``exercise`` are unfit: every pair of
    ``values`` (name -> value) that is not at least ``gap`` apart in some entry."""
    names = list(values)
    return [
        f"{exercise}: {a} and {b} are too close"
        for i, a in enumerate(names)
        for b in names[i + 1 :]
        if np.abs(np.ravel(values[a]) - np.ravel(values[b])).max() < gap
    ]


def signed_permutation(rng):
    """A rotation whose columns are signed coordinate axes (one of the 24), not the identity."""
    while True:
        R = np.zeros((3, 3), dtype=int)
        R[rng.permutation(3), np.arange(3)] = rng.choice([-1, 1], size=3)
        if round(np.linalg.det(R)) == 1 and not np.array_equal(R, np.eye(3)):
            return R
