"""The answers of chapter 1 (instructor side; not part of the installed package).

SOLUTIONS: exercise name -> the worked solution, the code between the solution markers of the
notebook's answer cell. MISTAKES: name -> {mistake id: an expression of the typical wrong
answer}; instructor/build/exercise_fingerprints.py stores fingerprints of both, never the code.

DRAWS: variant key -> (a function of a numpy Generator that draws one set of the exercise's
numbers, a function that lists why a set is unfit); instructor/build/variant_draws.py says
what a draw is.
"""

import numpy as np

from instructor.answers.common import apart

SOLUTIONS = {
    "coords_by_projection": """\
o, p = np.array(P["o"]), np.array(P["p"])
directions = [np.array(P[k]) for k in ("d1", "d2", "d3")]
e1, e2, e3 = [v / np.linalg.norm(v) for v in directions]  # unit vectors, eq. (1)
answer_coords_by_projection = [(p - o) @ e1, (p - o) @ e2, (p - o) @ e3]  # eqs (3)-(5)""",
    "angle_from_lengths": """\
a, b, m = P["a"], P["b"], P["m"]  # ‖x‖, ‖y‖ and ‖x − y‖²
x_dot_y = sp.Rational(a**2 + b**2 - m, 2)  # m = ‖x − y‖² = ‖x‖² + ‖y‖² − 2 xᵀy
diagonals_dot = a**2 - b**2  # (x − y)ᵀ(x + y) = ‖x‖² − ‖y‖²
sum_length = sp.sqrt(a**2 + b**2 + 2 * x_dot_y)  # ‖x + y‖² = ‖x‖² + ‖y‖² + 2 xᵀy
answer_angle_from_lengths = sp.acos(diagonals_dot / (sp.sqrt(m) * sum_length))""",
    "which_are_rigid": """\
# g(p) = M p + d keeps distances iff M is orthogonal; it keeps cross products iff det M = +1
half_z = np.diag([-1, 1, 1]) @ np.diag([1, -1, 1])  # = diag(-1, -1, 1)
quarter_x = np.array([[1, 0, 0], [0, 0, -1], [0, 1, 0]])
n = np.array([1, 1, 0]) / np.sqrt(2)
M = {
    "a": np.array([[0, 1, 0], [1, 0, 0], [0, 0, 1]]),  # swaps x and y
    "b": 2 * np.outer(n, n) - np.eye(3),  # half turn about n
    "c": half_z @ (-np.eye(3)),  # = diag(1, 1, -1)
    "d": np.diag([1, -1, 1]) @ np.diag([-1, 1, 1]),
    "e": quarter_x,  # the translation drops out of g_*
    "f": -np.eye(3),
}
answer_which_are_rigid = {k for k, Mk in M.items() if np.isclose(np.linalg.det(Mk), 1)}""",
    "unit_tangent": """\
p = sp.Matrix([sp.cos(2 * t), sp.sin(2 * t), 3 * t])
velocity = p.diff(t)
speed = sp.sqrt(sp.trigsimp(velocity.dot(velocity)))  # sqrt(4 + 9)
answer_unit_tangent = velocity / speed""",
    "lagrange_identity": """\
lhs = sp.expand(x.cross(y).dot(x.cross(y)))
guess = xx * yy - xy**2
in_components = guess.subs({xx: x.dot(x), yy: y.dot(y), xy: x.dot(y)})
assert sp.expand(lhs - in_components) == 0
answer_lagrange_identity = guess""",
    "bac_cab": """\
lhs = x.cross(y.cross(z))
alpha_, beta_ = x.dot(z), -x.dot(y)
assert sp.expand(lhs - (alpha_ * y + beta_ * z)) == sp.zeros(3, 1)
answer_bac_cab = [alpha_, beta_]""",
    "motion_from_points": """\
a, b, c = (np.array(P[k]) for k in ("a", "b", "c"))
ga, gb, gc = (np.array(P[k]) for k in ("ga", "gb", "gc"))
u, v, gu, gv = b - a, c - a, gb - ga, gc - ga  # g_*(u) = R u: d drops out
F = np.column_stack([u, v, np.cross(u, v)])
G = np.column_stack([gu, gv, np.cross(gu, gv)])  # condition 2: g_*(u × v) = gu × gv
answer_motion_from_points = G @ np.linalg.inv(F)  # R F = G""",
}

MISTAKES = {
    "coords_by_projection": {
        "weights": "np.column_stack([e1, e2, e3]) @ (p - o)",
        "no_origin": "[p @ e1, p @ e2, p @ e3]",
        "unnormalized": "[(p - o) @ v for v in directions]",
    },
    "angle_from_lengths": {
        "cosine": "diagonals_dot / (sp.sqrt(m) * sum_length)",
        "sign": "sp.acos(diagonals_dot / (sp.sqrt(m) * sp.sqrt(a**2 + b**2 - 2 * x_dot_y)))",
        "x_and_y": "sp.acos(x_dot_y / (a * b))",
        "reversed": "sp.acos(-diagonals_dot / (sp.sqrt(m) * sum_length))",
    },
    "which_are_rigid": {
        "mirrors": '{"a", "b", "c", "d", "e", "f"}',
        "translation": '{"b", "d"}',
        "two_mirrors": '{"b", "e"}',
        "point_reflection": '{"b", "c", "d", "e"}',
    },
    "unit_tangent": {"velocity": "velocity"},
    "lagrange_identity": {"plus": "xx * yy + xy**2"},
    "bac_cab": {"swapped": "[beta_, alpha_]"},
    "motion_from_points": {
        "mirror": "np.column_stack([gu, gv, -np.cross(gu, gv)]) @ np.linalg.inv(F)",
        "points": "np.column_stack([ga, gb, gc]) @ np.linalg.inv(np.column_stack([a, b, c]))",
        "columns": "np.column_stack([gu, gv, np.cross(gu, gv)])",
    },
}


#: Rotations with rational entries (columns of integer length n): a frame whose unit axes a
#: first-year writes exactly, none along a coordinate axis.
_RATIONAL = [
    (np.array([[1, 2, 2], [2, 1, -2], [2, -2, 1]]), 3),
    (np.array([[2, 3, 6], [3, -6, 2], [6, 2, -3]]), 7),
    (np.array([[1, 4, 8], [4, 7, -4], [8, -4, 1]]), 9),
]


def _rational_rotation(rng, family=None):
    """A rational rotation ``(Q, n)``: integer Q with orthogonal columns of length n, det > 0
    (of ``_RATIONAL[family]``, or of any family)."""
    Q, n = _RATIONAL[rng.integers(len(_RATIONAL)) if family is None else family]
    Q = Q[rng.permutation(3)][:, rng.permutation(3)] * rng.choice([-1, 1], size=3)
    if np.linalg.det(Q) < 0:
        Q = Q * np.array([1, 1, -1])
    return Q, n


def _frame(rng):
    Q, _ = _rational_rotation(rng, family=0)  # a warm-up: the thirds
    scales = rng.integers(1, 3, size=3)  # each direction 1 or 2 times a column: not unit
    o, p = rng.integers(-3, 4, size=3), rng.integers(-3, 4, size=3)
    out = {f"d{i + 1}": (scales[i] * Q[:, i]).tolist() for i in range(3)}
    return {"o": o.tolist(), **out, "p": p.tolist()}


def _frame_problems(p):
    D = np.column_stack([p["d1"], p["d2"], p["d3"]]).astype(float)
    E = D / np.linalg.norm(D, axis=0)
    out = []
    if np.abs(E.T @ E - np.eye(3)).max() > 1e-12 or np.linalg.det(E) < 0:
        out.append("the directions are not a right-handed orthogonal frame")
    po = np.array(p["p"]) - np.array(p["o"])
    if np.count_nonzero(po) < 2 or not np.any(p["o"]):
        out.append("p − o along a coordinate axis, or o the origin: mistakes too easy to miss")
    values = {"answer": E.T @ po, "weights": E @ po, "no_origin": E.T @ np.array(p["p"]),
              "unnormalized": D.T @ po}  # fmt: skip
    return out + apart("coords_by_projection", values)


def _lengths(rng):
    a, b = (int(v) for v in rng.choice(np.arange(2, 10), size=2, replace=False))
    return {"a": a, "b": b, "m": int(rng.integers((a - b) ** 2 + 1, (a + b) ** 2))}


def _lengths_problems(p):
    a, b, m = p["a"], p["b"], p["m"]
    out = []
    if a == b or not (a - b) ** 2 < m < (a + b) ** 2:
        out.append("no such x and y, or equal lengths (the diagonals are then perpendicular)")
        return out
    if round(m**0.5) ** 2 == m:
        out.append("‖x − y‖² is a perfect square: the statement would show √16")
    if m == a * a + b * b or abs(a * a - b * b) > m:
        out.append("x ⟂ y, or the 'sign' mistake has no angle: too special")
        return out
    xy = (a * a + b * b - m) / 2
    s = np.sqrt(a * a + b * b + 2 * xy)
    cos = (a * a - b * b) / (np.sqrt(m) * s)
    values = {"answer": np.arccos(cos), "cosine": cos, "sign": np.arccos((a * a - b * b) / m),
              "x_and_y": np.arccos(xy / (a * b)), "reversed": np.arccos(-cos)}  # fmt: skip
    if abs(xy / (a * b)) > 0.95:
        out.append("x and y nearly parallel")
    return out + apart("angle_from_lengths", values)


def _motion(rng):
    """R from the thirds family (integer images of points with entries multiples of 3)."""
    Q, n = _rational_rotation(rng, family=0)
    pts = 3 * rng.integers(-1, 3, size=(3, 3))  # a, b, c as rows
    while not _points_ok(pts):
        pts = 3 * rng.integers(-1, 3, size=(3, 3))
    images = pts @ Q.T // n + rng.integers(-3, 4, size=3)  # R p + d, integers
    out = {k: pts[i].tolist() for i, k in enumerate("abc")}
    return out | {f"g{k}": images[i].tolist() for i, k in enumerate("abc")}


def _points_ok(pts):
    """No point and no difference along a coordinate axis (a column of R would show), b − a and
    c − a not perpendicular and not parallel."""
    u, v = pts[1] - pts[0], pts[2] - pts[0]
    if any(np.count_nonzero(r) < 2 for r in (*pts, u, v, v - u)):
        return False
    return np.linalg.norm(np.cross(u, v)) > 0 and u @ v != 0


def _motion_problems(p):
    a, b, c = (np.array(p[k], float) for k in "abc")
    ga, gb, gc = (np.array(p[f"g{k}"], float) for k in "abc")
    u, v, gu, gv = b - a, c - a, gb - ga, gc - ga
    if not _points_ok(np.array([a, b, c])):
        return ["a point is the origin or a basis vector, or b − a, c − a are perpendicular"]
    F = np.column_stack([u, v, np.cross(u, v)])
    R = np.column_stack([gu, gv, np.cross(gu, gv)]) @ np.linalg.inv(F)
    out = []
    if np.abs(R.T @ R - np.eye(3)).max() > 1e-9 or np.linalg.det(R) < 0:
        out.append("the images are not those of a rigid body transformation")
    if abs(np.linalg.det(np.column_stack([a, b, c]))) < 1e-9:
        out.append("a, b, c are linearly dependent: the 'points' mistake has no matrix")
        return out
    values = {"answer": R,
              "mirror": np.column_stack([gu, gv, -np.cross(gu, gv)]) @ np.linalg.inv(F),
              "points": np.column_stack([ga, gb, gc]) @ np.linalg.inv(np.column_stack([a, b, c])),
              "columns": np.column_stack([gu, gv, np.cross(gu, gv)])}  # fmt: skip
    return out + apart("motion_from_points", values)


DRAWS = {
    "ch01_frame": (_frame, _frame_problems),
    "ch01_lengths": (_lengths, _lengths_problems),
    "ch01_motion": (_motion, _motion_problems),
}
