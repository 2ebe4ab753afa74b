"""The answers of chapter 2 (instructor side; not part of the installed package).

DRAWS: variant key -> (a function of a numpy Generator that draws one set of the exercise's
numbers, a function that lists why a set is unfit); instructor/build/variant_draws.py says
what a draw is.
"""

import itertools
from fractions import Fraction

import numpy as np

from instructor.answers.common import (
    apart,
    fraction_text,
    integer_quaternion,
    quaternion_matrix,
    signed_permutation,
)

SOLUTIONS = {
    "which_in_so3": """\
# XᵀX = I and det X = +1 for each, from (XY)ᵀ = YᵀXᵀ and det(XY) = det X det Y:
# (a) (RSRᵀ)ᵀRSRᵀ = RSᵀSRᵀ = I, det = 1  (b) det(−R) = (−1)³ = −1
# (c) (RᵀS)ᵀRᵀS = I, det = 1                     (d) det = (−1)(1)(−1) = 1, MᵀM = I
# (e) not orthogonal in general: R = S = R_z(90°) gives 2R − I
# (f) det = −1
Q = np.array([[0, -1, 0], [1, 0, 0], [0, 0, 1]])  # R = S = R_z(90°)
assert not np.allclose((2 * Q - np.eye(3)).T @ (2 * Q - np.eye(3)), np.eye(3))  # (e) fails
answer_which_in_so3 = {"a", "c", "d"}""",
    "vb_from_va": """\
x_ab, y_ab = np.array(P["x_ab"]), np.array(P["y_ab"])
R_ab = np.column_stack([x_ab, y_ab, np.cross(x_ab, y_ab)])  # right-handed: z = x × y
v_a = np.array(P["v_a"])
answer_vb_from_va = R_ab.T @ v_a  # v_b = R_ba v_a = R_abᵀ v_a""",
    "complete_rotation": """\
a_, b_, c_ = sp.symbols("a b c", real=True)
unknowns = {"a": a_, "b": b_, "c": c_}
Rm = sp.Matrix([[unknowns.get(e) or sp.Rational(e) for e in row] for row in P["R"]])
equations = list(Rm.T * Rm - sp.eye(3))  # orthonormal columns (Proposition 3)
solutions_abc = sp.solve(equations, [a_, b_, c_], dict=True)
assert len(solutions_abc) == 1 and Rm.subs(solutions_abc[0]).det() == 1
answer_complete_rotation = [solutions_abc[0][v] for v in (a_, b_, c_)]""",
    "inverse_of_product": """\
answer_inverse_of_product = B * A.T  # R_ca = R_cb R_ba = R_cb R_abᵀ""",
    "rigid_inverse": """\
# g⁻¹(g(p)) = Rᵀ(Rp + d) + e = p + Rᵀd + e, so e = −Rᵀd
answer_rigid_inverse = -R.T * d""",
    "hat_product": """\
# x̂ŷv = x × (y × v) = y (xᵀv) − (xᵀy) v, so x̂ŷ + (xᵀy) I = y xᵀ
assert sp.expand(hat(x) * hat(y) + x.dot(y) * sp.eye(3) - y * x.T) == sp.zeros(3, 3)
answer_hat_product = Y * X.T""",
    "two_mirrors": """\
psi = sp.Symbol("psi", real=True)
n1, n2 = sp.Matrix([1, 0, 0]), sp.Matrix([sp.cos(psi), sp.sin(psi), 0])
M1, M2 = sp.eye(3) - 2 * n1 * n1.T, sp.eye(3) - 2 * n2 * n2.T
turn = (M2 * M1).applyfunc(sp.trigsimp)  # = R_z(2ψ): first column (cos 2ψ, sin 2ψ, 0)
assert (turn - sp.rot_ccw_axis3(2 * psi)).applyfunc(sp.trigsimp) == sp.zeros(3, 3)
degrees = sp.Rational(str(P["turn"]))  # the turn in degrees, exact (a decimal: 47.3)
answer_two_mirrors = sp.pi * degrees / 180 / 2  # 2ψ = the turn""",
}

MISTAKES = {
    "which_in_so3": {
        "orthogonal": '{"a", "b", "c", "d", "f"}',
        "two_reflections": '{"a", "c"}',
        "sum": '{"a", "c", "d", "e"}',
        "minus": '{"a", "b", "c", "d"}',
    },
    "vb_from_va": {
        "direction": "R_ab @ v_a",
        "left_handed": "np.column_stack([x_ab, y_ab, -np.cross(x_ab, y_ab)]).T @ v_a",
    },
    "complete_rotation": {"abs": "[abs(v) for v in answer_complete_rotation]"},
    "inverse_of_product": {"order": "A.T * B", "forward": "A * B.T", "bc": "B.T * A.T"},
    "rigid_inverse": {"minus_d": "-d", "no_transpose": "-R * d"},
    "two_mirrors": {
        "double": "sp.pi * degrees / 180",
        "order": "sp.pi - sp.pi * degrees / 180 / 2",
    },
}


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
