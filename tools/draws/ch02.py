"""The variant draws of chapter 2 (tools/variant_draws.py says what a draw is)."""

import itertools
from fractions import Fraction

import numpy as np

from draws.common import apart, signed_permutation

_THIRDS = np.array([[1, 2, 2], [2, 1, -2], [2, -2, 1]])  # 3 R: a rotation with entries k/3
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
    Q = _THIRDS[rng.permutation(3)][:, rng.permutation(3)] * rng.choice([-1, 1], size=3)
    if np.linalg.det(Q) < 0:
        Q = Q * np.array([1, 1, -1])
    rows = [[str(Fraction(int(e), 3)) for e in row] for row in Q]
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
    return apart("complete_rotation", {"answer": abc, "abs": np.abs(abc)})


def _mirrors(rng):
    return {"turn": int(rng.choice([t for t in range(30, 171, 10) if t != 120]))}


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
