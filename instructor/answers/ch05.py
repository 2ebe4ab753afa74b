"""The answers of chapter 5 (instructor side; not part of the installed package).

An exercise with variants reads its numbers from ``P`` (instructor/answers/ch04.py says how).

DRAWS: variant key -> (a function of a numpy Generator that draws one set of the exercise's
numbers, a function that lists why a set is unfit); instructor/build/variant_draws.py says
what a draw is.
"""

from fractions import Fraction

import numpy as np

from course_lib import quaternion
from instructor.answers.common import (
    apart,
    integer_quaternion,
    quaternion_matrix,
    rational_unit_quaternions,
    unit_axis,
)

SOLUTIONS = {
    "quaternion_of_turn": """\
direction = sp.Matrix(P["direction"])
axis = direction / direction.norm()  # unit
half = sp.pi * P["angle"] / 360  # θ/2 in radians
answer_quaternion_of_turn = [sp.cos(half), *(sp.sin(half) * axis)]""",
    "angle_from_ros": """\
x, y, z, w = P["x"], P["y"], P["z"], P["w"]  # ROS order: scalar last
answer_angle_from_ros = 2 * np.arctan2(np.linalg.norm([x, y, z]), w)""",
    "compose_quaternions": """\
axes = {"x": [1, 0, 0], "y": [0, 1, 0], "z": [0, 0, 1]}
q_1 = quaternion.from_axis_angle(axes[P["axis1"]], np.radians(P["a1"]))  # the first turn
q_2 = quaternion.from_axis_angle(axes[P["axis2"]], np.radians(P["a2"]))
answer_compose_quaternions = quaternion.multiply(q_2, q_1)  # world axes: from the left""",
    "proper_euler_angles": """\
R = sp.Matrix(P["R"])  # the exact entries (strings such as "sqrt(3)/4" or "-2/9")
# R_z(α) R_y(β) R_z(γ): third column (cα sβ, sα sβ, cβ), third row (−sβ cγ, sβ sγ, cβ);
# with sin β < 0 the entries divided by sin β change sign
alpha = sp.atan2(-R[1, 2], -R[0, 2])
beta = -sp.atan2(sp.sqrt(R[0, 2] ** 2 + R[1, 2] ** 2), R[2, 2])
gamma = sp.atan2(-R[2, 1], R[2, 0])
answer_proper_euler_angles = [alpha, beta, gamma]  # the default: (π/2, −2π/3, −5π/6)""",
    "unreachable_omega": """\
phi = sp.pi * sp.Rational(str(P["roll"])) / 180  # pitch 90°, yaw 0
Rx = sp.Matrix([[1, 0, 0], [0, sp.cos(phi), -sp.sin(phi)], [0, sp.sin(phi), sp.cos(phi)]])
Ry = sp.Matrix([[0, 0, 1], [0, 1, 0], [-1, 0, 0]])  # R_y(90°)
e_x, e_y, e_z = (sp.eye(3)[:, k] for k in range(3))  # the coordinate axes
yaw_col, pitch_col, roll_col = Rx.T * Ry.T * e_z, Rx.T * e_y, e_x  # yaw_col = −roll_col
n = roll_col.cross(pitch_col)
n = n * sp.sign(sum(n))  # of the two normals, the one with n · (1, 1, 1) > 0
answer_unreachable_omega = list(n / n.norm())""",
    "slerp_angular_velocity": """\
q0, q1 = np.array(P["q0"]), np.array(P["q1"])  # scalar first
R0, R1 = quaternion.to_matrix(q0), quaternion.to_matrix(q1)
T = P["T"]  # seconds
answer_slerp_angular_velocity = so3.log(R1 @ R0.T) / T  # world (the default: (0, 0, 2π/9))""",
    "angle_between_quaternions": """\
q0 = np.array(P["q0"])
x, y, z, w = P["x"], P["y"], P["z"], P["w"]  # the ROS message, scalar last
q1 = np.array([w, x, y, z])
answer_angle_between_quaternions = 2 * np.arccos(abs(q0 @ q1))""",
}

MISTAKES = {
    "quaternion_of_turn": {
        "full_angle": "[sp.cos(2 * half), *(sp.sin(2 * half) * axis)]",
        "not_unit": "[sp.cos(half), *(sp.sin(half) * direction)]",
        "scalar_last": "[*(sp.sin(half) * axis), sp.cos(half)]",
        "negated": "[-sp.cos(half), *(-sp.sin(half) * axis)]",
        "degrees": "[sp.cos(P['angle'] / 2), *(sp.sin(P['angle'] / 2) * axis)]",
    },
    "angle_from_ros": {
        "scalar_first": "2 * np.arccos(x)",
        "half": "np.arctan2(np.linalg.norm([x, y, z]), w)",
    },
    "compose_quaternions": {
        "order": "quaternion.multiply(q_1, q_2)",
        "negated": "-quaternion.multiply(q_2, q_1)",
    },
    "proper_euler_angles": {
        "reversed": "[gamma, beta, alpha]",
        "gamma_sign": "[alpha, beta, sp.atan2(-R[2, 1], -R[2, 0])]",
        "positive_beta": "[sp.atan2(R[1, 2], R[0, 2]), -beta, sp.atan2(R[2, 1], -R[2, 0])]",
        "beta_only": "[sp.atan2(R[1, 2], R[0, 2]), beta, sp.atan2(R[2, 1], -R[2, 0])]",
    },
    "unreachable_omega": {
        "world_frame": "[1, 0, 0]  # normal of e_z, R_z(0) e_y, R_y(90°) e_x",
        "no_transpose": "list((lambda m: m / m.norm())(roll_col.cross(Rx * e_y)))",
        "parallel_columns": "list(roll_col.cross(yaw_col))",
        "sign": "list(-n / n.norm())",
    },
    "slerp_angular_velocity": {
        "body_frame": "so3.log(R0.T @ R1) / T",
        "per_move": "so3.log(R1 @ R0.T)",
        "half_angle": "so3.log(R1 @ R0.T) / T / 2",
        "long_way": "(lambda q: q[1:] / np.linalg.norm(q[1:]) * 2 * np.arccos(q[0]) / T)("
        "quaternion.multiply(q1, quaternion.conjugate(q0)))",
        "reverse": "so3.log(R0 @ R1.T) / T",
    },
    "angle_between_quaternions": {
        "long_way": "2 * np.arccos(q0 @ q1)",
        "scalar_last": "2 * np.arccos(abs(q0 @ np.array([x, y, z, w])))",
        "half_angle": "np.arccos(abs(q0 @ q1))",
    },
}


_AXES = {"x": [1, 0, 0], "y": [0, 1, 0], "z": [0, 0, 1]}


def _turn(rng):
    """An angle of the special families and a direction of integer length (a Pythagorean
    quadruple: an axis along no coordinate axis or plane)."""
    d, _ = unit_axis(rng)
    angle = int(rng.choice([30, 45, 60, 72, 90, 108, 120, 135, 144, 150]))
    return {"angle": angle, "direction": d}


def _turn_problems(p):
    d = np.array(p["direction"], dtype=float)
    axis, half = d / np.linalg.norm(d), np.radians(p["angle"]) / 2
    out = [] if 20 <= p["angle"] <= 160 else ["the angle is near 0 or 180°: w near 0 or 1"]
    if np.abs(axis).min() < 0.05:
        out.append("the axis lies along a coordinate plane")
    q = np.r_[np.cos(half), np.sin(half) * axis]
    values = {"answer": q, "full_angle": np.r_[np.cos(2 * half), np.sin(2 * half) * axis],
              "not_unit": np.r_[np.cos(half), np.sin(half) * d], "scalar_last": np.r_[q[1:], q[0]],
              "negated": -q,
              "degrees": np.r_[np.cos(p["angle"] / 2), np.sin(p["angle"] / 2) * axis]}  # fmt: skip
    return out + apart("quaternion_of_turn", values)


def _decimal_quaternion(rng):
    """A unit quaternion (w, x, y, z) with entries of at most two decimals: an integer
    quadruple of length n = 10 or 25, divided by n."""
    n = int(rng.choice([10, 25]))
    table = rational_unit_quaternions(n)
    return [round(v / n, 2) for v in table[rng.integers(len(table))]]


def _ros(rng):
    w, x, y, z = _decimal_quaternion(rng)
    return {"x": x, "y": y, "z": z, "w": abs(w)}


def _ros_problems(p):
    v = np.array([p["x"], p["y"], p["z"]])
    out = []
    if abs(v @ v + p["w"] ** 2 - 1) > 1e-12 or p["w"] < 0:
        out.append("not a unit quaternion with w ≥ 0 (the angle would not be in [0, π])")
    angle = 2 * np.arctan2(np.linalg.norm(v), p["w"])
    if not 0.3 < angle < np.pi - 0.3:
        out.append("the angle is near 0 or π")
    values = {"answer": angle, "scalar_first": 2 * np.arccos(p["x"]), "half": angle / 2}
    return out + apart("angle_from_ros", values)


def _two_turns(rng):
    first, second = rng.choice(list(_AXES), size=2, replace=False)
    a1, a2 = rng.choice(np.arange(10, 171, 5), size=2)
    return {"a1": int(a1), "axis1": str(first), "a2": int(a2), "axis2": str(second)}


def _two_turns_problems(p):
    out = [] if p["axis1"] != p["axis2"] else ["both turns about one axis: the order is moot"]
    q_1 = quaternion.from_axis_angle(_AXES[p["axis1"]], np.radians(p["a1"]))
    q_2 = quaternion.from_axis_angle(_AXES[p["axis2"]], np.radians(p["a2"]))
    q = quaternion.multiply(q_2, q_1)
    if q[0] < 0.05:
        out.append("the product's w is not clearly positive")
    values = {"answer": q, "order": quaternion.multiply(q_1, q_2), "negated": -q}
    return out + apart("compose_quaternions", values)


def _gimbal(rng):
    """A roll of −179.9° to 179.9° in steps of 0.1° (an integer one as an int)."""
    tenths = int(rng.integers(-1799, 1800))
    return {"roll": tenths // 10 if tenths % 10 == 0 else tenths / 10}


def _sympy_size(degrees):
    """How many nodes sympy's exact cos and sin of ``degrees`` have (the solution is exact)."""
    import sympy as sp

    phi = sp.pi * sp.Rational(str(degrees)) / 180
    return max(len(list(sp.preorder_traversal(f(phi)))) for f in (sp.cos, sp.sin))


def _gimbal_problems(p):
    phi = np.radians(p["roll"])
    near = abs((p["roll"] + 45) % 90 - 45)  # degrees from the nearest multiple of 90°
    out = [] if near >= 5 else ["roll within 5° of a multiple of 90°: a column near an axis"]
    if _sympy_size(p["roll"]) > 40:  # e.g. 25.5°: the reader refuses the exact answer
        out.append("sympy writes cos and sin of this roll as long nested radicals")
    # the body-frame columns at pitch 90°: roll e_x, pitch R_x(φ)ᵀ e_y; their normal n
    roll_col, pitch_col = np.array([1.0, 0, 0]), np.array([0, np.cos(phi), -np.sin(phi)])
    n = np.cross(roll_col, pitch_col)
    n /= np.linalg.norm(n)
    if abs(n.sum()) < 0.2:
        out.append("n is nearly orthogonal to (1, 1, 1): the sign rule is fragile")
    n *= np.sign(n.sum())
    wrong = np.cross(roll_col, [0, np.cos(phi), np.sin(phi)])
    values = {"answer": n, "world_frame": [1, 0, 0], "no_transpose": wrong / np.linalg.norm(wrong),
              "parallel_columns": [0, 0, 0], "sign": -n}  # fmt: skip
    return out + apart("unreachable_omega", values)


def _two_sources(rng):
    q0, q1 = np.array(_decimal_quaternion(rng)), np.array(_decimal_quaternion(rng))
    x, y, z, w = (float(v) for v in (q1[1], q1[2], q1[3], q1[0]))
    return {"q0": q0.tolist(), "x": x, "y": y, "z": z, "w": w}


def _two_sources_problems(p):
    q0 = np.array(p["q0"])
    q1 = np.array([p["w"], p["x"], p["y"], p["z"]])
    dot = float(q0 @ q1)
    out = []
    if dot > -0.1:
        out.append("q₀ · q₁ is not clearly negative: the double cover would not matter")
    if abs(dot) > 0.95:
        out.append("the two orientations are nearly the same")
    acos = lambda c: np.arccos(np.clip(c, -1, 1))  # noqa: E731
    values = {"answer": 2 * acos(abs(dot)), "long_way": 2 * acos(dot),
              "scalar_last": 2 * acos(abs(q0 @ np.r_[q1[1:], q1[0]])),
              "half_angle": acos(abs(dot))}  # fmt: skip
    return out + apart("angle_between_quaternions", values)


def _fraction_tex(f):
    """An exact rational as LaTeX: ``-\\tfrac{2}{9}``, ``0``, ``1``."""
    if f.denominator == 1:
        return str(f.numerator)
    return ("-" if f < 0 else "") + rf"\tfrac{{{abs(f.numerator)}}}{{{f.denominator}}}"


def _matrix_tex(rows):
    body = r"\\ ".join(" & ".join(_fraction_tex(f) for f in row) for row in rows)
    return rf"\begin{{bmatrix}} {body} \end{{bmatrix}}"


def _euler(rng):
    """A rational rotation R = M / n from an integer quaternion (n = |q|² <= 36): its exact
    entries for the solution, its LaTeX for the statement."""
    while True:
        M, n = quaternion_matrix(integer_quaternion(rng, largest=4))
        if n <= 36:
            break
    rows = [[Fraction(int(e), n) for e in row] for row in M]
    return {"R_tex": _matrix_tex(rows), "R": [[str(f) for f in row] for row in rows]}


def euler_values(R):
    """The answer and the known mistakes of 5.4 for the rotation ``R`` (floats), as the
    reference solution and MISTAKES compute them."""
    alpha, gamma = np.arctan2(-R[1, 2], -R[0, 2]), np.arctan2(-R[2, 1], R[2, 0])
    beta = -np.arctan2(np.hypot(R[0, 2], R[1, 2]), R[2, 2])
    a_pos, g_pos = np.arctan2(R[1, 2], R[0, 2]), np.arctan2(R[2, 1], -R[2, 0])
    return {"answer": [alpha, beta, gamma], "reversed": [gamma, beta, alpha],
            "gamma_sign": [alpha, beta, np.arctan2(-R[2, 1], -R[2, 0])],
            "positive_beta": [a_pos, -beta, g_pos], "beta_only": [a_pos, beta, g_pos]}  # fmt: skip


def _euler_problems(p):
    R = np.array([[float(Fraction(e)) if "sqrt" not in e else _surd(e) for e in row]
                  for row in p["R"]])  # fmt: skip
    out = []
    if np.abs(R.T @ R - np.eye(3)).max() > 1e-12 or np.linalg.det(R) < 0:
        out.append("R is not a rotation")
    if abs(R[2, 2]) > 0.9:
        out.append("sin β near 0: near the gimbal case, the angles are ill-conditioned")
    values = euler_values(R)
    if (
        np.abs(np.abs(values["answer"]) - np.pi).min() < 0.05
        or min(abs(values["answer"][0]), abs(values["answer"][2])) < 0.05
    ):
        out.append("α or γ near 0 or ±π: the range's edge")
    return out + apart("proper_euler_angles", values)


def _surd(text):
    import sympy as sp

    return float(sp.sympify(text))


def _slerp(rng):
    """Two unit quaternions with rational entries (integer quadruples of length n <= 9) whose
    dot product is negative (the statement's shorter way matters), and a duration."""
    n0, n1 = (int(v) for v in rng.choice([3, 5, 6, 7, 9], size=2))
    t0, t1 = rational_unit_quaternions(n0), rational_unit_quaternions(n1)
    q0 = [Fraction(v, n0) for v in t0[rng.integers(len(t0))]]
    q1 = [Fraction(v, n1) for v in t1[rng.integers(len(t1))]]
    tex = lambda q: r"\big(" + ", ".join(_fraction_tex(f) for f in q) + r"\big)"  # noqa: E731
    return {"q0_tex": tex(q0), "q1_tex": tex(q1), "T": int(rng.integers(2, 7)),
            "q0": [float(f) for f in q0], "q1": [float(f) for f in q1]}  # fmt: skip


def slerp_values(q0, q1, T):
    """The answer and the known mistakes of 5.6 (world angular velocity of the slerp)."""
    from course_lib import so3

    R0, R1 = quaternion.to_matrix(q0), quaternion.to_matrix(q1)
    omega = so3.log(R1 @ R0.T)
    q = quaternion.multiply(q1, quaternion.conjugate(q0))
    with np.errstate(invalid="ignore", divide="ignore"):  # q₀ = ±q₁: rejected by the dot
        long_way = q[1:] / np.linalg.norm(q[1:]) * 2 * np.arccos(np.clip(q[0], -1, 1)) / T
    return {"answer": omega / T, "body_frame": so3.log(R0.T @ R1) / T, "per_move": omega,
            "half_angle": omega / T / 2, "long_way": long_way,
            "reverse": so3.log(R0 @ R1.T) / T}  # fmt: skip


def _slerp_problems(p):
    q0, q1 = np.array(p["q0"]), np.array(p["q1"])
    out = []
    if abs(q0 @ q0 - 1) > 1e-12 or abs(q1 @ q1 - 1) > 1e-12:
        out.append("not unit quaternions")
    dot = float(q0 @ q1)
    if not -0.9 < dot < -0.1:
        out.append("q₀ · q₁ not clearly negative, or the two orientations nearly the same")
    if p["T"] < 2:
        out.append("T = 1: the rate and the rotation vector of the move are the same")
    return out + apart("slerp_angular_velocity", slerp_values(q0, q1, p["T"]))


DRAWS = {
    "ch05_turn": (_turn, _turn_problems),
    "ch05_ros": (_ros, _ros_problems),
    "ch05_two_turns": (_two_turns, _two_turns_problems),
    "ch05_gimbal": (_gimbal, _gimbal_problems),
    "ch05_two_sources": (_two_sources, _two_sources_problems),
    "ch05_euler": (_euler, _euler_problems),
    "ch05_slerp": (_slerp, _slerp_problems),
}
