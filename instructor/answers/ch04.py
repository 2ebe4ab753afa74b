"""The answers of chapter 4 (instructor side; not part of the installed package).

An exercise with variants reads its numbers from ``P``, the student's parameters: the answer
cell sets ``P = parameters(name)`` before the solution, and the tools set ``P`` to each variant.

DRAWS: variant key -> (a function of a numpy Generator that draws one set of the exercise's
numbers, a function that lists why a set is unfit); instructor/build/variant_draws.py says
what a draw is.
"""

import numpy as np

from instructor.answers.common import apart, signed_permutation
from instructor.answers.common import unit_axis as _unit_axis

SOLUTIONS = {
    "compose_frames": """\
R_ab = np.column_stack([P["x_ab"], P["y_ab"], P["z_ab"]])
R_bc = np.column_stack([P["x_bc"], P["y_bc"], P["z_bc"]])
answer_compose_frames = R_ab @ R_bc""",
    "chain_vector": """\
R_ab = np.column_stack([P["x_ab"], P["y_ab"], P["z_ab"]])
R_bc = np.column_stack([P["x_bc"], P["y_bc"], P["z_bc"]])
v_c = np.array(P["v_c"])
answer_chain_vector = R_ab @ (R_bc @ v_c)""",
    "angle_from_trace": """\
trace = sum(sp.Rational(str(P[k])) for k in ("R11", "R22", "R33"))  # only the diagonal
answer_angle_from_trace = sp.acos((trace - 1) / 2)""",
    "axis_of_rotation": """\
skew = P["factor"] * np.array(P["M"])  # R − Rᵀ, as given
angle = np.arccos((P["trace"] - 1) / 2)  # from tr R = 1 + 2 cos θ
S = skew / (2 * np.sin(angle))  # = ω̂
answer_axis_of_rotation = np.array([S[2, 1], S[0, 2], S[1, 0]])""",
    "fixed_vs_body": """\
turns = []  # R_x, R_y or R_z of the notes, for each of the three turns
for k in (1, 2, 3):
    c, s = np.cos(np.radians(P[f"a{k}"])), np.sin(np.radians(P[f"a{k}"]))
    i, j = [(1, 2), (2, 0), (0, 1)]["xyz".index(P[f"axis{k}"])]  # the plane it turns
    turn_k = np.eye(3)
    turn_k[i, i], turn_k[i, j], turn_k[j, i], turn_k[j, j] = c, -s, s, c
    turns.append(turn_k)
R1, R2, R3 = turns
R = R1  # about a world axis, from R = I
R = R @ R2  # about the camera's own axis: from the right
R = R3 @ R  # about a world axis: from the left
answer_fixed_vs_body = R""",
    "composed_angle": """\
Rx = sp.Matrix([[1, 0, 0], [0, sp.cos(alpha), -sp.sin(alpha)], [0, sp.sin(alpha), sp.cos(alpha)]])
Rz = sp.Matrix([[sp.cos(beta), -sp.sin(beta), 0], [sp.sin(beta), sp.cos(beta), 0], [0, 0, 1]])
cos_xz = ((Rx * Rz).trace() - 1) / 2
assert sp.expand(cos_xz - ((Rz * Rx).trace() - 1) / 2) == 0  # same angle
answer_composed_angle = cos_xz""",
    "small_angle": """\
# e^{K angle} to second order (K = a hat):
second_order = lambda angle, K: sp.eye(3) + angle * K + angle**2 * K * K / 2
z_hat = sp.Matrix([[0, -1, 0], [1, 0, 0], [0, 0, 0]])
x_hat = sp.Matrix([[0, 0, 0], [0, 0, -1], [0, 1, 0]])
R_near = (second_order(beta, z_hat) * second_order(alpha, x_hat)).applyfunc(sp.expand)
skew = (R_near - R_near.T) / 2  # sin θ ω̂ ≈ θ ω̂: θ/sin θ = 1 + O(θ²)
vec = sp.Matrix([skew[2, 1], skew[0, 2], skew[1, 0]])
keep = lambda e: sum(
    c * alpha**i * beta**j for (i, j), c in sp.Poly(e, alpha, beta).terms() if i + j <= 2
)
answer_small_angle = vec.applyfunc(keep)  # (α, αβ/2, β)""",
    "two_half_turns": """\
u = sp.Matrix(P["q_u"]) / P["n_u"]
v = sp.Matrix(P["q_v"]) / P["n_v"]
H = lambda a: 2 * a * a.T - sp.eye(3)  # R(a, π) = I + 2â² = 2aaᵀ − I
R = H(u) * H(v)
n = u.cross(v)  # both half turns map the line of n onto itself (n → −n → n)
# In the plane ⟂ n each half turn is a mirror in the line of its axis; two mirrors at angle α
# make a turn by 2α; when α > 90° (u·v < 0) the short way is θ = 2π − 2α:
cos_t = (R.trace() - 1) / 2  # = 2(u·v)² − 1
s = sp.Matrix([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]]) / 2  # sin θ ω
assert s.cross(n) == sp.zeros(3, 1)  # the axis lies along u × v
angle = sp.acos(cos_t)  # in [0, π]
answer_two_half_turns = angle * s / s.norm()  # ω θ, ω along ±u × v""",
}

MISTAKES = {
    "compose_frames": {"order": "R_bc @ R_ab", "rows": "R_ab.T @ R_bc.T"},
    "chain_vector": {
        "order": "R_bc @ (R_ab @ v_c)",
        "inverse": "(R_ab @ R_bc).T @ v_c",
        "rows": "R_ab.T @ (R_bc.T @ v_c)",
    },
    "angle_from_trace": {"cosine": "(trace - 1) / 2", "no_minus_one": "sp.acos(trace / 2)"},
    "axis_of_rotation": {
        "unnormalized": "np.array([skew[2, 1], skew[0, 2], skew[1, 0]])",
        "no_two": "2 * answer_axis_of_rotation",
        "sign": "-answer_axis_of_rotation",
    },
    "fixed_vs_body": {
        "all_body": "R1 @ R2 @ R3",
        "all_world": "R3 @ R2 @ R1",
        "swapped": "R2 @ R1 @ R3",
    },
    "composed_angle": {
        "no_minus_one": "(Rx * Rz).trace() / 2",
        "sum": "sp.cos(alpha + beta)",
        "angle": "sp.acos(cos_xz)",
    },
    "small_angle": {
        "first_order": "sp.Matrix([alpha, 0, beta])",
        "sign": "sp.Matrix([alpha, -alpha * beta / 2, beta])",
    },
    "two_half_turns": {
        "order": "-answer_two_half_turns",
        "long_way": "(angle - 2 * sp.pi) * s / s.norm()",
        "single_angle": "angle / 2 * s / s.norm()",
        "unit_axis": "s / s.norm()",
        "sum": "sp.pi * (u + v)",
    },
}


def _frames(rng):
    """Frames B in A and C in B, axes along signed coordinate axes (the warm-up's point: the
    axes read off as columns), and a vector of small distinct non-zero integers in C."""
    R_ab, R_bc = signed_permutation(rng), signed_permutation(rng)
    v_c = rng.choice([-4, -3, -2, -1, 1, 2, 3, 4], size=3, replace=False)
    names = ("x", "y", "z")
    out = {f"{n}_ab": R_ab[:, i].tolist() for i, n in enumerate(names)}
    out |= {f"{n}_bc": R_bc[:, i].tolist() for i, n in enumerate(names)}
    return out | {"v_c": v_c.tolist()}


def _frames_problems(p):
    R_ab = np.column_stack([p["x_ab"], p["y_ab"], p["z_ab"]])
    R_bc = np.column_stack([p["x_bc"], p["y_bc"], p["z_bc"]])
    v_c = np.array(p["v_c"])
    out = []
    for label, R in (("R_ab", R_ab), ("R_bc", R_bc)):
        if not (np.array_equal(R.T @ R, np.eye(3)) and round(np.linalg.det(R)) == 1):
            out.append(f"{label} is not a rotation")
        if np.array_equal(R, np.eye(3)):
            out.append(f"{label} is the identity")
    R_ac = R_ab @ R_bc
    if np.array_equal(R_ac, np.eye(3)):
        out.append("R_ac is the identity")
    if len(set(np.abs(v_c))) < 3 or 0 in v_c:
        out.append("v_c must have three distinct non-zero magnitudes")
    # integer entries: "less than 0.01 apart" is "equal"
    matrices = {"answer": R_ac, "order": R_bc @ R_ab, "rows": R_ab.T @ R_bc.T}
    vectors = {"answer": R_ac @ v_c, "order": R_bc @ R_ab @ v_c, "inverse": R_ac.T @ v_c,
               "rows": R_ab.T @ R_bc.T @ v_c}  # fmt: skip
    return out + apart("compose_frames", matrices) + apart("chain_vector", vectors)


def _trace(rng):
    """Three one-decimal diagonal entries (a rotation's: each at least cos θ, sum 1 + 2 cos θ)."""
    d = rng.integers(-9, 10, size=3) / 10
    return {"R11": float(d[0]), "R22": float(d[1]), "R33": float(d[2])}


def _trace_problems(p):
    d = np.array([p["R11"], p["R22"], p["R33"]])
    c = (d.sum() - 1) / 2  # cos θ
    out = []
    if not -0.95 <= c <= 0.5:  # θ near 0 or π; above 0.5 tr R/2 > 1 leaves no_minus_one undefined
        out.append(f"cos θ = {c:.2f} outside [-0.95, 0.5]")
    weights = (d - c) / (1 - c) if c < 1 else np.zeros(3)  # the axis's squared entries
    if np.any(weights < 0.02) or np.any(weights > 0.95):
        out.append("no rotation has these diagonal entries with an axis off the coordinate axes")
    theta = np.arccos(np.clip(c, -1, 1))
    values = {"answer": theta, "cosine": c, "no_minus_one": np.arccos(np.clip(d.sum() / 2, -1, 1))}
    return out + apart("angle_from_trace", values)


_AXES = "xyz"
_ANGLES = [30, 45, 60, 90, 120, 135, 150]


def _turn(degrees, axis):
    c, s = np.cos(np.radians(degrees)), np.sin(np.radians(degrees))
    i, j = [(1, 2), (2, 0), (0, 1)][_AXES.index(axis)]
    M = np.eye(3)
    M[i, i], M[i, j], M[j, i], M[j, j] = c, -s, s, c
    return M


def _camera(rng):
    """Three turns: about a world axis, the camera's own axis, a world axis."""
    angles = rng.choice(_ANGLES, size=3)
    axes = rng.choice(list(_AXES), size=3)
    out = {}
    for k in range(3):
        out[f"a{k + 1}"], out[f"axis{k + 1}"] = int(angles[k]), str(axes[k])
    return out


def _camera_problems(p):
    R1, R2, R3 = (_turn(p[f"a{k}"], p[f"axis{k}"]) for k in (1, 2, 3))
    out = []
    if p["axis1"] == p["axis2"]:
        out.append("the first two turns share their axis: world and own axis are the same")
    matrices = {"answer": R3 @ R1 @ R2, "all_body": R1 @ R2 @ R3, "all_world": R3 @ R2 @ R1,
                "swapped": R2 @ R1 @ R3}  # fmt: skip
    return out + apart("fixed_vs_body", matrices, gap=0.05)


#: Angles of 4.4 with a trace and 2 sin θ a first-year writes exactly: (tr R, its LaTeX,
#: 2 sin θ and the LaTeX of its root). θ = π/2 is left out: there 2 sin θ = 2 and the two known
#: mistakes (no division by 2 sin θ; no factor 2) give the same vector.
_AXIS_ANGLES = [(2.0, "2", 3**0.5, r"\sqrt3"), (0.0, "0", 3**0.5, r"\sqrt3"),
                (1 + 2**0.5, r"1 + \sqrt2", 2**0.5, r"\sqrt2"),
                (1 - 2**0.5, r"1 - \sqrt2", 2**0.5, r"\sqrt2")]  # fmt: skip


def _hat(q):
    x, y, z = q
    return [[0, -z, y], [z, 0, -x], [-y, x, 0]]


def _axis(rng):
    """A unit axis q / n and an angle of the table: tr R and R − Rᵀ = (2 sin θ / n) q̂."""
    q, n = _unit_axis(rng)
    trace, trace_tex, two_sin, root = _AXIS_ANGLES[rng.integers(len(_AXIS_ANGLES))]
    return {"trace_tex": trace_tex, "factor_tex": rf"\frac{{{root}}}{{{n}}}", "M": _hat(q),
            "trace": trace, "factor": two_sin / n}  # fmt: skip


def _axis_problems(p):
    skew = p["factor"] * np.array(p["M"], dtype=float)
    c = (p["trace"] - 1) / 2
    out = []
    if not -0.95 < c < 0.95:
        out.append("θ too close to 0 or π: the axis is ill-conditioned")
    sin = np.sqrt(max(0.0, 1 - c * c))
    S = skew / (2 * sin)
    w = np.array([S[2, 1], S[0, 2], S[1, 0]])
    if abs(np.linalg.norm(w) - 1) > 1e-9 or np.abs(S + S.T).max() > 1e-12:
        out.append("the trace and the skew part belong to no rotation")
    if np.abs(w).min() < 0.05:
        out.append("the axis lies along a coordinate plane or axis")
    values = {"answer": w, "unnormalized": 2 * sin * w, "no_two": 2 * w, "sign": -w}
    out += apart("axis_of_rotation", values)
    return out


def _half_turns(rng):
    (q_u, n_u), (q_v, n_v) = _unit_axis(rng), _unit_axis(rng)
    return {"n_u": n_u, "q_u": q_u, "n_v": n_v, "q_v": q_v}


def _half_turns_problems(p):
    u, v = np.array(p["q_u"]) / p["n_u"], np.array(p["q_v"]) / p["n_v"]
    out = []
    d = float(u @ v)
    if abs(d) > 0.9:
        out.append("u and v are nearly the same line: the product is nearly I")
    if abs(d) < 0.2:
        out.append("u and v are nearly perpendicular: the product is nearly a half turn")
    if out:
        return out
    H = lambda a: 2 * np.outer(a, a) - np.eye(3)  # noqa: E731
    R = H(u) @ H(v)
    angle = np.arccos(np.clip((np.trace(R) - 1) / 2, -1, 1))
    s = np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]]) / 2
    axis = s / np.linalg.norm(s)
    values = {"answer": angle * axis, "order": -angle * axis,
              "long_way": (angle - 2 * np.pi) * axis, "single_angle": angle / 2 * axis,
              "unit_axis": axis, "sum": np.pi * (u + v)}  # fmt: skip
    return out + apart("two_half_turns", values)


DRAWS = {
    "ch04_frames": (_frames, _frames_problems),
    "ch04_trace": (_trace, _trace_problems),
    "ch04_camera": (_camera, _camera_problems),
    "ch04_axis": (_axis, _axis_problems),
    "ch04_half_turns": (_half_turns, _half_turns_problems),
}
