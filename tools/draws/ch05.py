"""The variant draws of chapter 5 (tools/variant_draws.py says what a draw is)."""

import numpy as np

from course_lib import quaternion
from draws.common import apart

#: Directions of integer length, no entry 0 (Pythagorean quadruples): axes along no coordinate
#: axis or plane, whose unit vector a first-year writes exactly.
_DIRECTIONS = [(1, 2, 2), (2, 3, 6), (1, 4, 8), (4, 4, 7), (2, 6, 9), (6, 6, 7), (3, 4, 12)]
#: Unit pairs (c, s) with two or three decimals: c² + s² = 1 exactly.
_PAIRS = [(0.6, 0.8), (0.8, 0.6), (0.28, 0.96), (0.96, 0.28), (0.352, 0.936), (0.936, 0.352)]
_AXES = {"x": [1, 0, 0], "y": [0, 1, 0], "z": [0, 0, 1]}


def _turn(rng):
    d = np.array(_DIRECTIONS[rng.integers(len(_DIRECTIONS))])
    d = d[rng.permutation(3)] * rng.choice([-1, 1], size=3)
    return {"angle": int(rng.choice([45, 60, 90, 120, 135])), "direction": d.tolist()}


def _turn_problems(p):
    d = np.array(p["direction"], dtype=float)
    axis, half = d / np.linalg.norm(d), np.radians(p["angle"]) / 2
    out = [] if 20 <= p["angle"] <= 160 else ["the angle is near 0 or 180°: w near 0 or 1"]
    if np.abs(axis).min() < 0.05:
        out.append("the axis lies along a coordinate plane")
    q = np.r_[np.cos(half), np.sin(half) * axis]
    values = {"answer": q, "full_angle": np.r_[np.cos(2 * half), np.sin(2 * half) * axis],
              "not_unit": np.r_[np.cos(half), np.sin(half) * d], "scalar_last": np.r_[q[1:], q[0]],
              "negated": -q}  # fmt: skip
    return out + apart("quaternion_of_turn", values)


def _ros(rng):
    w, s = _PAIRS[rng.integers(len(_PAIRS))]
    axis = str(rng.choice(list(_AXES)))
    vec = [s * e for e in _AXES[axis]]
    return {"x": vec[0], "y": vec[1], "z": vec[2], "w": w, "axis": axis}


def _ros_problems(p):
    v = np.array([p["x"], p["y"], p["z"]])
    out = []
    if abs(v @ v + p["w"] ** 2 - 1) > 1e-12 or np.count_nonzero(v) != 1:
        out.append("not a unit quaternion of a turn about one coordinate axis")
    elif v @ np.array(_AXES[p["axis"]]) <= 0:
        out.append("the statement's axis is not the quaternion's (or the angle is not in [0, π])")
    angle = 2 * np.arctan2(np.linalg.norm(v), p["w"])
    values = {"answer": angle, "scalar_first": 2 * np.arccos(p["x"]), "half": angle / 2}
    return out + apart("angle_from_ros", values)


def _two_turns(rng):
    first, second = rng.choice(list(_AXES), size=2, replace=False)
    a1, a2 = rng.choice([60, 90, 120], size=2)
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
    return {"roll": int(rng.choice([r for r in range(-165, 180, 15) if r % 90]))}


def _gimbal_problems(p):
    phi = np.radians(p["roll"])
    out = (
        [] if p["roll"] % 90 else ["roll 0 or a multiple of 90°: a column along a coordinate axis"]
    )
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


def _unit_quaternion(rng):
    """A unit quaternion with two non-zero decimal entries (c, s) and two zeros."""
    c, s = _PAIRS[rng.integers(len(_PAIRS))]
    q = np.zeros(4)
    i, j = rng.choice(4, size=2, replace=False)
    q[i], q[j] = c * rng.choice([-1, 1]), s * rng.choice([-1, 1])
    return q


def _two_sources(rng):
    q0, q1 = _unit_quaternion(rng), _unit_quaternion(rng)
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
    values = {"answer": 2 * np.arccos(abs(dot)), "long_way": 2 * np.arccos(np.clip(dot, -1, 1)),
              "scalar_last": 2 * np.arccos(abs(q0 @ np.r_[q1[1:], q1[0]]))}  # fmt: skip
    return out + apart("angle_between_quaternions", values)


DRAWS = {
    "ch05_turn": (_turn, _turn_problems),
    "ch05_ros": (_ros, _ros_problems),
    "ch05_two_turns": (_two_turns, _two_turns_problems),
    "ch05_gimbal": (_gimbal, _gimbal_problems),
    "ch05_two_sources": (_two_sources, _two_sources_problems),
}
