"""Reference solutions of chapter 3 (instructor side; not part of the installed package)."""

SOLUTIONS = {
    "ode_shifted": """\
rate, x_start = sp.symbols("rate x_start", real=True)
x_of = lambda time: sp.exp(rate * time) * x_start  # (106)
rate_value = sp.solve(sp.Eq(x_of(3) / x_of(1), sp.Rational(12, 3)), rate)[0]  # e^{2a} = 4
start_value = sp.solve(sp.Eq(x_of(1).subs(rate, rate_value), 3), x_start)[0]
answer_ode_shifted = [rate_value, start_value]  # (ln 2, 3/2)""",
    "pendulum_speed": """\
tau = sp.Symbol("tau", real=True)
angle = sp.pi / 6 * sp.cos(3 * tau)  # θ(t)
rate = angle.diff(tau)  # (117): ω = θ̇
answer_pendulum_speed = sp.Abs(2 * rate).subs(tau, sp.pi / 6)""",
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
# x(1) = (0, 2): x₀ cos a = 0 and x₀ sin a = 2; the smallest a > 0 is π/2, with x₀ = 2
assert [p.subs({a: sp.pi / 2, x_0: 2, t: 1}) for p in path] == [0, 2]
answer_planar_ode = [sp.pi / 2, 2]""",
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
        "interval": "[sp.log(4) / 3, 3 * 4 ** sp.Rational(-1, 3)]",
        "at_zero": "[sp.log(2), 3]",
    },
    "pendulum_speed": {
        "angle": "2 * angle.subs(tau, sp.pi / 6)",
        "no_length": "sp.Abs(rate).subs(tau, sp.pi / 6)",
        "no_chain": "sp.Abs(2 * rate / 3).subs(tau, sp.pi / 6)",
        "signed": "(2 * rate).subs(tau, sp.pi / 6)",
    },
    "hat_fifth": {"unit": "W"},
    "half_turn": {
        "mirror": "sp.Identity(3) - 2 * u * u.T",
        "inner": "2 * omega.dot(omega) * sp.eye(3) - sp.eye(3)",
    },
    "planar_ode": {
        "direction": "[sp.pi / 2, -2]",
        "larger": "[3 * sp.pi / 2, -2]",
        "next_turn": "[5 * sp.pi / 2, 2]",
        "degrees": "[90, 2]",
    },
    "exp_general_axis": {"unit": "sp.eye(3) + sp.sin(theta) * W + (1 - sp.cos(theta)) * W**2"},
    "spatial_angular_velocity": {"body": "[sp.cos(t), -sp.sin(t), 1]", "sum": "[1, 0, 1]"},
}
