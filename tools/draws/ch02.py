"""The variant draws of chapter 2 (tools/variant_draws.py says what a draw is)."""

import itertools
from fractions import Fraction

import numpy as np

from draws.common import (
    apart,
    fraction_text,
    integer_quaternion,
    quaternion_matrix,
    signed_permutation,
)

_MISSING = [(0, 2), (1, 1), (2, 0)]  # where a, b and c stand


def _frame(rng):
    R = signed_permutation(rng)
    v = rng.choice([-4, -3, -2, -1, 1, 2, 3, 4], size=3, replace=False)
    return {"x_ab": R[:, 0].tolist(), "y_ab": R[:, 1].tolist(), "v_a": v.tolist()}


def _frame_problems(p):
    x, y, v = np.array(p["x_ab"]), np.array(p["y_ab"]), np.array(p["v_a"])
    R = np.column_stack([x, y, np.cross(x, y)])
    out = []
    if np.abs(R.T @ R - np.eye(3)).max() or len(set(np.abs(v))) < 3 or 0 in v:
        out.append("not two orthonormal axes, or v_a without three distinct magnitudes")
    left = np.column_stack([x, y, -np.cross(x, y)])
    values = {"answer": R.T @ v, "direction": R @ v, "left_handed": left.T @ v}
    return out + apart("vb_from_va", values)


def _missing(rng):
    """A rational rotation from an integer quaternion (entries k/n, n = |q|² <= 33), three of
    its entries hidden."""
    while True:
        M, n = quaternion_matrix(integer_quaternion(rng, largest=4))
        if n <= 33:
            break
    rows = [[fraction_text(Fraction(int(e), n)) for e in row] for row in M]
    for (i, j), name in zip(_MISSING, "abc"):
        rows[i][j] = name
    return {"R": rows}


def _completions(rows):
    """Every (a, b, c) that makes the matrix a rotation (from the magnitudes the unit columns
    fix, with every choice of signs)."""
    M = np.array([[0.0 if e in "abc" else float(Fraction(e)) for e in row] for row in rows])
    found = []
    for signs in itertools.product([-1, 1], repeat=3):
        X = M.copy()
        for (i, j), s in zip(_MISSING, signs):
            X[i, j] = s * np.sqrt(max(0.0, 1 - (X[:, j] ** 2).sum()))
        if np.abs(X.T @ X - np.eye(3)).max() < 1e-9 and np.linalg.det(X) > 0:
            found.append([X[i, j] for i, j in _MISSING])
    return found


def _missing_problems(p):
    found = _completions(p["R"])
    if len(found) != 1:
        return [f"{len(found)} completions make it a rotation: the answer must be unique"]
    abc = np.array(found[0])
    out = [] if np.abs(abc).min() > 0.05 else ["a missing entry is 0: its sign is not asked"]
    return out + apart("complete_rotation", {"answer": abc, "abs": np.abs(abc)})


def _mirrors(rng):
    """A turn of 20.0° to 170.0° in steps of 0.1° (1,500 of them; an integer one as an int)."""
    tenths = int(rng.integers(200, 1701))
    return {"turn": tenths // 10 if tenths % 10 == 0 else tenths / 10}


def _mirrors_problems(p):
    theta = np.radians(p["turn"])
    out = [] if 20 <= p["turn"] <= 170 else ["the turn is near 0 or 180°"]
    values = {"answer": theta / 2, "double": theta, "order": np.pi - theta / 2}
    return out + apart("two_mirrors", values)


DRAWS = {
    "ch02_frame": (_frame, _frame_problems),
    "ch02_missing": (_missing, _missing_problems),
    "ch02_mirrors": (_mirrors, _mirrors_problems),
}
