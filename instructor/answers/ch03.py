"""Reference solutions of chapter 3 (instructor side; not part of the installed package)."""

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
