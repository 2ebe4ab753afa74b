"""The variant draws of chapter 4 (tools/variant_draws.py says what a draw is)."""

import numpy as np


def _signed_permutation(rng):
    """A rotation whose columns are signed coordinate axes (one of the 24), not the identity."""
    while True:
        R = np.zeros((3, 3), dtype=int)
        R[rng.permutation(3), np.arange(3)] = rng.choice([-1, 1], size=3)
        if round(np.linalg.det(R)) == 1 and not np.array_equal(R, np.eye(3)):
            return R


def _frames(rng):
    """Frames B in A and C in B, axes along signed coordinate axes (the warm-up's point: the
    axes read off as columns), and a vector of small distinct non-zero integers in C."""
    R_ab, R_bc = _signed_permutation(rng), _signed_permutation(rng)
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
    wrong = {"order": R_bc @ R_ab, "rows": R_ab.T @ R_bc.T}
    for mid, M in wrong.items():
        if np.array_equal(M, R_ac):
            out.append(f"compose_frames: the mistake {mid!r} gives the right answer")
    if np.array_equal(wrong["order"], wrong["rows"]):
        out.append("compose_frames: the mistakes 'order' and 'rows' give the same matrix")
    v_a = R_ac @ v_c
    vectors = {"answer": v_a, "order": R_bc @ R_ab @ v_c, "inverse": R_ac.T @ v_c,
               "rows": R_ab.T @ R_bc.T @ v_c}  # fmt: skip
    seen = {}
    for label, v in vectors.items():
        key = tuple(v)
        if key in seen:
            out.append(f"chain_vector: {label!r} and {seen[key]!r} give the same vector")
        seen.setdefault(key, label)
    if len(set(np.abs(v_c))) < 3 or 0 in v_c:
        out.append("v_c must have three distinct non-zero magnitudes")
    return out


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
    names = list(values)
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            if abs(values[a] - values[b]) < 0.01:
                out.append(f"angle_from_trace: {a} and {b} are too close")
    return out


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
    matrices = {"answer": R3 @ R1 @ R2, "all_body": R1 @ R2 @ R3, "all_world": R3 @ R2 @ R1}
    names = list(matrices)
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            if np.abs(matrices[a] - matrices[b]).max() < 0.05:
                out.append(f"fixed_vs_body: {a} and {b} give the same orientation")
    return out


DRAWS = {
    "ch04_frames": (_frames, _frames_problems),
    "ch04_trace": (_trace, _trace_problems),
    "ch04_camera": (_camera, _camera_problems),
}
