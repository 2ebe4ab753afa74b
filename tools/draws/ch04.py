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


DRAWS = {"ch04_frames": (_frames, _frames_problems)}
