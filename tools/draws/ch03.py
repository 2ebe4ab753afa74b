"""The variant draws of chapter 3 (tools/variant_draws.py says what a draw is)."""

import numpy as np

from draws.common import apart


def _growth(rng):
    t1, gap = int(rng.integers(1, 3)), int(rng.integers(1, 4))
    x1, x2 = (int(v) for v in rng.choice(np.arange(1, 21), size=2, replace=False))
    return {"t1": t1, "x1": x1, "t2": t1 + gap, "x2": x2, "gap": gap}


def _growth_problems(p):
    t1, x1, t2, x2 = p["t1"], p["x1"], p["t2"], p["x2"]
    out = [] if t1 >= 1 and t2 - t1 == p["gap"] >= 1 else ["the times must be 1 ≤ t1 < t2"]
    a = np.log(x2 / x1) / (t2 - t1)
    if not 0.1 <= abs(a) <= 2:
        out.append(f"a = {a:.2f}: too slow or too fast a growth")
    x0 = x1 * np.exp(-a * t1)
    wrong_a = np.log(x2 / x1) / t2
    values = {"answer": [a, x0], "interval": [wrong_a, x1 * (x2 / x1) ** (-t1 / t2)],
              "at_zero": [a, x1]}  # fmt: skip
    return out + apart("ode_shifted", values)


def _pendulum(rng):
    return {"r": float(rng.choice([1.5, 2, 2.5, 3, 4])), "n": int(rng.choice([4, 6, 8, 12])),
            "k": int(rng.choice([2, 3, 4])), "q": int(rng.choice([3, 4, 6, 8, 12]))}  # fmt: skip


def _pendulum_problems(p):
    r, n, k, q = p["r"], p["n"], p["k"], p["q"]
    t = np.pi / q
    rate = -np.pi / n * k * np.sin(k * t)  # θ̇
    out = [] if rate < -0.1 else ["θ̇ is not clearly negative there: the signed mistake is right"]
    values = {"answer": abs(r * rate), "angle": r * np.pi / n * np.cos(k * t),
              "no_length": abs(rate), "no_chain": abs(r * rate / k),
              "signed": r * rate}  # fmt: skip
    return out + apart("pendulum_speed", values)


#: Points (p1, p2) at the angles π/4, π/2, ... 7π/4 with exact coordinates.
_DIRECTIONS = [(1, 1), (0, 1), (-1, 1), (-1, -1), (0, -1), (1, -1)]


def _planar(rng):
    d = np.array(_DIRECTIONS[rng.integers(len(_DIRECTIONS))])
    return {"point": (int(rng.integers(1, 4)) * d).tolist()}


def _planar_problems(p):
    p1, p2 = p["point"]
    rho, phi = np.hypot(p1, p2), np.arctan2(p2, p1) % (2 * np.pi)
    if rho == 0 or p2 == 0:
        return ["a point on the x axis: a turn of 0 or π, degenerate"]
    a, x0 = (phi, rho) if phi <= np.pi else (phi - np.pi, -rho)
    values = {"answer": [a, x0], "direction": [a, -x0], "larger": [a + np.pi, -x0],
              "next_turn": [a + 2 * np.pi, x0], "degrees": [np.degrees(a), x0]}  # fmt: skip
    return apart("planar_ode", values)


DRAWS = {
    "ch03_growth": (_growth, _growth_problems),
    "ch03_pendulum": (_pendulum, _pendulum_problems),
    "ch03_planar": (_planar, _planar_problems),
}
