"""The variant draws of chapter 3 (tools/variant_draws.py says what a draw is)."""

import numpy as np

from draws.common import apart


def _growth(rng):
    """Two measurements at least 2 time units apart (1 apart, not dividing by t2 − t1 gives
    the right rate: issue 33)."""
    t1, gap = int(rng.integers(1, 4)), int(rng.integers(2, 5))
    x1, x2 = (int(v) for v in rng.choice(np.arange(1, 31), size=2, replace=False))
    return {"t1": t1, "x1": x1, "t2": t1 + gap, "x2": x2, "gap": gap}


def _growth_problems(p):
    t1, x1, t2, x2 = p["t1"], p["x1"], p["t2"], p["x2"]
    out = [] if t1 >= 1 and t2 - t1 == p["gap"] >= 2 else ["the times must be 1 ≤ t1 < t1 + 2 ≤ t2"]
    a = np.log(x2 / x1) / (t2 - t1)
    if not 0.1 <= abs(a) <= 2:
        out.append(f"a = {a:.2f}: too slow or too fast a growth")
    x0 = x1 * np.exp(-a * t1)
    wrong_a = np.log(x2 / x1) / t2
    flat = np.log(x2 / x1)  # the rate without the division by t2 − t1
    values = {"answer": [a, x0], "interval": [wrong_a, x1 * (x2 / x1) ** (-t1 / t2)],
              "at_zero": [a, x1], "no_division": [flat, x1 * np.exp(-flat * t1)]}  # fmt: skip
    return out + apart("ode_shifted", values)


def _pendulum(rng):
    r = int(rng.integers(2, 11)) / 2  # 1 to 5 m in steps of 0.5
    return {"r": int(r) if r == int(r) else r, "n": int(rng.choice([3, 4, 5, 6, 8, 9, 10, 12])),
            "k": int(rng.choice([2, 3, 4, 5])),
            "q": int(rng.choice([3, 4, 5, 6, 7, 8, 9, 10, 12]))}  # fmt: skip


def _pendulum_problems(p):
    r, n, k, q = p["r"], p["n"], p["k"], p["q"]
    t = np.pi / q
    rate = -np.pi / n * k * np.sin(k * t)  # θ̇
    out = [] if rate < -0.1 else ["θ̇ is not clearly negative there: the signed mistake is right"]
    values = {"answer": abs(r * rate), "angle": r * np.pi / n * np.cos(k * t),
              "no_length": abs(rate), "no_chain": abs(r * rate / k),
              "signed": r * rate}  # fmt: skip
    return out + apart("pendulum_speed", values)


def _planar(rng):
    """An integer point above the x axis: the smallest a > 0 is its polar angle φ in (0, π)
    and x₀ its distance, positive (issue 33: a point below gave x₀ < 0, a case the statement
    does not announce)."""
    return {"point": [int(rng.integers(-30, 31)), int(rng.integers(1, 31))]}


def _planar_problems(p):
    p1, p2 = p["point"]
    if p2 <= 0:
        return ["a point on or below the x axis: x₀ would be 0 or negative"]
    a, x0 = np.arctan2(p2, p1), np.hypot(p1, p2)
    values = {"answer": [a, x0], "direction": [a, -x0], "larger": [a + np.pi, -x0],
              "next_turn": [a + 2 * np.pi, x0], "degrees": [np.degrees(a), x0]}  # fmt: skip
    return apart("planar_ode", values)


DRAWS = {
    "ch03_growth": (_growth, _growth_problems),
    "ch03_pendulum": (_pendulum, _pendulum_problems),
    "ch03_planar": (_planar, _planar_problems),
}
