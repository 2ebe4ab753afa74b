"""Benchmark: course_lib.so3.exp and .log against scipy's Rotation on 10^6 batched inputs.

Run by hand (`make bench`); prints times, the ratio course_lib / scipy and the accuracy in the
same run. Targets (issue 2): exp <= 1.0x scipy's time, log (with its input validation) <= 0.10x
scipy's from_matrix(...).as_rotvec(). Not a test: shared machines are noisy, so each timing is
the best of several repeats.
"""

import time

import numpy as np
from scipy.spatial.transform import Rotation

from course_lib import so3

N = 10**6
REPEATS = 5


def best_time(fn, repeats=REPEATS):
    best = np.inf
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - start)
    return best


def main():
    rng = np.random.default_rng(2024)
    axes = rng.standard_normal((N, 3))
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    angles = rng.uniform(0.0, np.pi, N)
    rotvecs = axes * angles[:, None]

    t_exp = best_time(lambda: so3.exp(rotvecs))
    t_exp_ref = best_time(lambda: Rotation.from_rotvec(rotvecs).as_matrix())
    R = so3.exp(rotvecs)
    R_ref = Rotation.from_rotvec(rotvecs).as_matrix()

    t_log = best_time(lambda: so3.log(R))
    t_log_ref = best_time(lambda: Rotation.from_matrix(R).as_rotvec())
    r = so3.log(R)
    r_ref = Rotation.from_matrix(R).as_rotvec()

    print(f"{N:,} rotations, angles uniform in [0, pi], best of {REPEATS}")
    print(f"{'':6} {'course_lib':>12} {'scipy':>12} {'ratio':>8}  target")
    print(f"{'exp':6} {t_exp * 1e3:10.1f}ms {t_exp_ref * 1e3:10.1f}ms {t_exp / t_exp_ref:8.3f}  <= 1.00")
    print(f"{'log':6} {t_log * 1e3:10.1f}ms {t_log_ref * 1e3:10.1f}ms {t_log / t_log_ref:8.3f}  <= 0.10")
    orth = np.abs(np.swapaxes(R, -1, -2) @ R - np.eye(3)).max()
    print(f"exp: max |R - scipy| = {np.abs(R - R_ref).max():.1e}, max |RᵀR - I| = {orth:.1e}, "
          f"max |det R - 1| = {np.abs(np.linalg.det(R) - 1).max():.1e}")
    rel = np.linalg.norm(r - rotvecs, axis=1) / np.maximum(angles, 1e-300)
    geo = so3.angle_between(so3.exp(r), R)
    print(f"log: max relative error of the rotation vector = {rel.max():.1e} "
          f"(scipy: {(np.linalg.norm(r_ref - rotvecs, axis=1) / np.maximum(angles, 1e-300)).max():.1e}), "
          f"max geodesic angle(exp(log R), R) = {geo.max():.1e}")


if __name__ == "__main__":
    main()
