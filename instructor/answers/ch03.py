"""The answers of chapter 3 (instructor side; not part of the installed package).

DRAWS: variant key -> (a function of a numpy Generator that draws one set of the exercise's
numbers, a function that lists why a set is unfit); instructor/build/variant_draws.py says
what a draw is.
"""

import numpy as np

from instructor.answers.common import apart

SOLUTIONS = {
    "ode_shifted": """\
rate, x_start = sp.symbols("rate x_start", real=True)
x_of = lambda time: sp.exp(rate * time) * x_start  # (106)
t1, x1, t2, x2 = P["t1"], P["x1"], P["t2"], P["x2"]  # x(t1) = x1, x(t2) = x2
ratio = sp.Rational(x2, x1)  # = e^{a (t2 − t1)}: x(0) cancels
rate_value = sp.solve(sp.Eq(x_of(t2) / x_of(t1), ratio), rate)[0]
start_value = sp.solve(sp.Eq(x_of(t1).subs(rate, rate_value), x1), x_start)[0]
answer_ode_shifted = [rate_value, start_value]""",
    "pendulum_speed": """\
tau = sp.Symbol("tau", real=True)
r_len, at = sp.Rational(str(P["r"])), sp.pi / P["q"]  # the length, the time asked for
angle = sp.pi / P["n"] * sp.cos(P["k"] * tau)  # θ(t)
rate = angle.diff(tau)  # (117): ω = θ̇
answer_pendulum_speed = sp.Abs(r_len * rate).subs(tau, at)""",
    "hat_fifth": """\
n2 = omega.dot(omega)  # ‖ω‖², not 1 here
H = hat(omega)
assert sp.expand(H**3 + n2 * H) == sp.zeros(3, 3)  # ω̂³ = −‖ω‖² ω̂
answer_hat_fifth = n2**2 * W  # ω̂⁵ = −‖ω‖² ω̂³ = ‖ω‖⁴ ω̂""",
    "half_turn": """\
# sin π = 0, 1 − cos π = 2:  e^{ω̂π} = I + 2ω̂² = I + 2(ωωᵀ − I)
answer_half_turn = 2 * u * u.T - sp.Identity(3)""",
    "rodrigues_derivative": """\
rodrigues_coeffs = (1, sp.sin(theta), 1 - sp.cos(theta))  # of I, W, W²
d_coeffs = [sp.diff(c, theta) for c in rodrigues_coeffs]  # 0, cos θ, sin θ
answer_rodrigues_derivative = d_coeffs[1] * W + d_coeffs[2] * W**2""",
    "planar_ode": """\
x1, x2 = sp.Function("x1"), sp.Function("x2")
system = [sp.Eq(x1(t).diff(t), -a * x2(t)), sp.Eq(x2(t).diff(t), a * x1(t))]
sol = sp.dsolve(system, [x1(t), x2(t)], ics={x1(0): x_0, x2(0): 0})
path = [sp.simplify(s.rhs) for s in sol]  # x₀(cos at, sin at)
# x(1) = ρ(cos φ, sin φ) = x₀(cos a, sin a): x₀ = ρ and a = φ + 2πk, or x₀ = −ρ and
# a = φ − π + 2πk; the smallest a > 0 is φ (with x₀ = ρ) when φ ≤ π, else φ − π (x₀ = −ρ)
p1, p2 = P["point"]
rho, phi = sp.sqrt(p1**2 + p2**2), sp.atan2(p2, p1) % (2 * sp.pi)
a_value, x0_value = (phi, rho) if phi <= sp.pi else (phi - sp.pi, -rho)
assert [sp.simplify(p.subs({a: a_value, x_0: x0_value, t: 1})) for p in path] == [p1, p2]
answer_planar_ode = [a_value, x0_value]""",
    "exp_general_axis": """\
n = sp.sqrt(omega.dot(omega))  # ‖ω‖; ω̂ = ‖ω‖ n̂ with a unit n
# Rodrigues for the unit axis n and the angle ‖ω‖θ, with n̂ = ω̂/‖ω‖:
answer_exp_general_axis = (
    sp.eye(3) + sp.sin(n * theta) / n * W + (1 - sp.cos(n * theta)) / n**2 * W**2
)""",
    "spatial_angular_velocity": """\
R_x = sp.Matrix([[1, 0, 0], [0, sp.cos(t), -sp.sin(t)], [0, sp.sin(t), sp.cos(t)]])
R_z = sp.Matrix([[sp.cos(t), -sp.sin(t), 0], [sp.sin(t), sp.cos(t), 0], [0, 0, 1]])
R_t = R_x * R_z
Omega = sp.simplify(R_t.diff(t) * R_t.T)
answer_spatial_angular_velocity = [Omega[2, 1], Omega[0, 2], Omega[1, 0]]""",
}

MISTAKES = {
    "ode_shifted": {
        "interval": "[sp.log(ratio) / t2, x1 * ratio ** sp.Rational(-t1, t2)]",
        "at_zero": "[rate_value, x1]",
        "no_division": "[sp.log(ratio), x1 * ratio ** (-t1)]",
    },
    "pendulum_speed": {
        "angle": "r_len * angle.subs(tau, at)",
        "no_length": "sp.Abs(rate).subs(tau, at)",
        "no_chain": "sp.Abs(r_len * rate / P['k']).subs(tau, at)",
        "signed": "(r_len * rate).subs(tau, at)",
    },
    "hat_fifth": {"unit": "W"},
    "half_turn": {
        "mirror": "sp.Identity(3) - 2 * u * u.T",
        "inner": "2 * omega.dot(omega) * sp.eye(3) - sp.eye(3)",
    },
    "planar_ode": {
        "direction": "[a_value, -x0_value]",
        "larger": "[a_value + sp.pi, -x0_value]",
        "next_turn": "[a_value + 2 * sp.pi, x0_value]",
        "degrees": "[a_value * 180 / sp.pi, x0_value]",
    },
    "exp_general_axis": {"unit": "sp.eye(3) + sp.sin(theta) * W + (1 - sp.cos(theta)) * W**2"},
    "spatial_angular_velocity": {"body": "[sp.cos(t), -sp.sin(t), 1]", "sum": "[1, 0, 1]"},
}


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
