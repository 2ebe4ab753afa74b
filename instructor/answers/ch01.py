"""Reference solutions of chapter 1 (instructor side; not part of the installed package).

SOLUTIONS: exercise name -> the worked solution, the code between the solution markers of the
notebook's answer cell. MISTAKES: name -> {mistake id: an expression of the typical wrong
answer}; tools/exercise_fingerprints.py stores fingerprints of both, never the code.
"""

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
