"""Benchmark: course_lib's functions that have a scipy counterpart, one call and 10^6 inputs side
by side against ``scipy.spatial.transform`` in one run (`make bench`).

Target (issue 36): every function takes at most scipy's time for one call, and stays at or below
it for 10^6 inputs (ratio <= 1.0 in both columns). Not a test: shared machines are noisy, so
each time is the best of several rounds in which course_lib and scipy are timed in turn
(benchmarks/_timing.py, CPU time). course_lib validates every input (a unit quaternion within
TOL, a rotation matrix for change_frame); scipy normalises instead. The largest difference from
scipy's result is printed beside each row.
"""

import numpy as np
from scipy.spatial.transform import Rotation, Slerp

from benchmarks._timing import CLOCK_NAME, best_times
from course_lib import euler, frames, quaternion, so3

N = 10**6
SINGLE_REPEATS = 15
BATCH_REPEATS = 5


def _xyzw(q):
    """course_lib's quaternions (w, x, y, z) as scipy's (x, y, z, w)."""
    return np.roll(q, -1, axis=-1)


def _wxyz(q):
    """scipy's quaternions (x, y, z, w) as course_lib's (w, x, y, z)."""
    return np.roll(q, 1, axis=-1)


def cases(rng):
    """{name: (ours(inputs), scipy(inputs), single inputs, batch inputs)}."""
    q = quaternion.from_matrix(so3.random_rotations(N, seed=1))
    p = quaternion.from_matrix(so3.random_rotations(N, seed=2))
    v = rng.standard_normal((N, 3))
    angles = rng.uniform(-np.pi, np.pi, (N, 3))
    R = quaternion.to_matrix(q[0])
    small = 1e-6 * rng.standard_normal((N, 3))
    near_pi = v / np.linalg.norm(v, axis=1, keepdims=True) * (np.pi - 1e-3)
    return {
        "quaternion.to_matrix": (
            quaternion.to_matrix,
            lambda q: Rotation.from_quat(_xyzw(q)).as_matrix(),
            (q[0],),
            (q,),
        ),
        "quaternion.multiply": (
            quaternion.multiply,
            lambda p, q: _wxyz(
                (Rotation.from_quat(_xyzw(p)) * Rotation.from_quat(_xyzw(q))).as_quat()
            ),
            (p[0], q[0]),
            (p, q),
        ),
        "quaternion.rotate": (
            quaternion.rotate,
            lambda q, v: Rotation.from_quat(_xyzw(q)).apply(v),
            (q[0], v[0]),
            (q, v),
        ),
        "quaternion.slerp": (
            lambda p, q, t: quaternion.slerp(p, q, t),
            lambda p, q, t: _slerp_scipy(p, q, t),
            (p[0], q[0], 0.3),
            None,
        ),
        "euler.to_matrix xyz": (
            lambda a: euler.to_matrix(a, "xyz"),
            lambda a: Rotation.from_euler("xyz", a).as_matrix(),
            (angles[0],),
            (angles,),
        ),
        "frames.change_frame": (
            frames.change_frame,
            lambda R, v: Rotation.from_matrix(R).apply(v),
            (R, v[0]),
            (R, v),
        ),
        "so3.exp (1e-6 rad)": (
            so3.exp,
            lambda w: Rotation.from_rotvec(w).as_matrix(),
            (small[0],),
            (small,),
        ),
        "so3.exp (pi - 1e-3)": (
            so3.exp,
            lambda w: Rotation.from_rotvec(w).as_matrix(),
            (near_pi[0],),
            (near_pi,),
        ),
    }


def _slerp_scipy(p, q, t):
    """scipy's slerp of one pair at one fraction: its Slerp object, built and called."""
    key = Rotation.from_quat(np.stack([_xyzw(p), _xyzw(q)]))
    return _wxyz(Slerp([0.0, 1.0], key)(t).as_quat())


def _difference(ours, ref, args):
    a, b = np.asarray(ours(*args)), np.asarray(ref(*args))
    if a.shape[-1] == 4:  # quaternions: q and -q are one rotation
        return float(np.minimum(np.abs(a - b).max(-1), np.abs(a + b).max(-1)).max())
    return float(np.abs(a - b).max())


def main():
    rng = np.random.default_rng(36)
    rows = cases(rng)
    print(
        f"course_lib vs scipy.spatial.transform; best of {SINGLE_REPEATS} (one call) and "
        f"{BATCH_REPEATS} ({N:,} inputs) interleaved rounds; {CLOCK_NAME}; target: ratio <= 1"
    )
    print(f"{'':22} | {'one call':^32} | {f'{N:,} inputs':^32} | max |ours - scipy|")
    for name, row in rows.items():
        print(f"{name:22} | {_row(*row)}")


def _row(ours, ref, one, many):
    """One line of the table: one call, 10^6 inputs (when scipy has a batch form), difference."""
    t1 = best_times([lambda: ours(*one), lambda: ref(*one)], repeats=SINGLE_REPEATS)
    left = f"{t1[0] * 1e6:7.2f} us {t1[1] * 1e6:7.2f} us {t1[0] / t1[1]:6.2f}"
    right = f"{'(no batch form in scipy)':^32}"
    if many is not None:
        t2 = best_times([lambda: ours(*many), lambda: ref(*many)], BATCH_REPEATS, number=1)
        right = f"{t2[0] * 1e3:7.1f} ms {t2[1] * 1e3:7.1f} ms {t2[0] / t2[1]:6.2f}"
    diff = _difference(ours, ref, many if many is not None else one)
    return f"{left} | {right} | {diff:.1e}"


if __name__ == "__main__":
    main()
