"""Reference solutions of chapter 4 (instructor side; not part of the installed package)."""

SOLUTIONS = {
    "compose_frames": """\
R_ab = np.column_stack([[0, 0, -1], [0, 1, 0], [1, 0, 0]])
R_bc = np.column_stack([[0, 0, 1], [1, 0, 0], [0, 1, 0]])
answer_compose_frames = R_ab @ R_bc""",
    "chain_vector": """\
R_ab = np.column_stack([[0, 0, -1], [0, 1, 0], [1, 0, 0]])
R_bc = np.column_stack([[0, 0, 1], [1, 0, 0], [0, 1, 0]])
v_c = np.array([1, 2, 3])
answer_chain_vector = R_ab @ (R_bc @ v_c)""",
    "angle_from_trace": """\
trace = sp.Rational(6, 10) + sp.Rational(1, 10) - sp.Rational(2, 10)  # only the diagonal
answer_angle_from_trace = sp.acos((trace - 1) / 2)  # arccos(−1/4)""",
    "axis_of_rotation": """\
skew = sp.Matrix([[0, -2, 1], [2, 0, -2], [-1, 2, 0]]) / sp.sqrt(3)  # R − Rᵀ
angle = sp.acos((0 - 1) / sp.Integer(2))  # tr R = 0: θ = 2π/3
S = skew / (2 * sp.sin(angle))  # = ω̂
answer_axis_of_rotation = sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])  # (2, 1, 2)/3""",
    "fixed_vs_body": """\
Rz = np.array([[0, -1, 0], [1, 0, 0], [0, 0, 1]])  # 90° about z
Rx90 = np.array([[1, 0, 0], [0, 0, -1], [0, 1, 0]])  # 90° about x
c, s = np.cos(np.pi / 3), np.sin(np.pi / 3)
Rx60 = np.array([[1, 0, 0], [0, c, -s], [0, s, c]])  # 60° about x
R = Rz  # about the world z axis, from R = I
R = R @ Rx90  # about the camera's own x axis: from the right
R = Rx60 @ R  # about the world x axis: from the left
answer_fixed_vs_body = R""",
    "composed_angle": """\
Rx = sp.Matrix([[1, 0, 0], [0, sp.cos(alpha), -sp.sin(alpha)], [0, sp.sin(alpha), sp.cos(alpha)]])
Rz = sp.Matrix([[sp.cos(beta), -sp.sin(beta), 0], [sp.sin(beta), sp.cos(beta), 0], [0, 0, 1]])
cos_xz = ((Rx * Rz).trace() - 1) / 2
assert sp.expand(cos_xz - ((Rz * Rx).trace() - 1) / 2) == 0  # same angle
answer_composed_angle = cos_xz""",
    "small_angle": """\
# e^{K angle} to second order (K = a hat):
second_order = lambda angle, K: sp.eye(3) + angle * K + angle**2 * K * K / 2
z_hat = sp.Matrix([[0, -1, 0], [1, 0, 0], [0, 0, 0]])
x_hat = sp.Matrix([[0, 0, 0], [0, 0, -1], [0, 1, 0]])
R_near = (second_order(beta, z_hat) * second_order(alpha, x_hat)).applyfunc(sp.expand)
skew = (R_near - R_near.T) / 2  # sin θ ω̂ ≈ θ ω̂: θ/sin θ = 1 + O(θ²)
vec = sp.Matrix([skew[2, 1], skew[0, 2], skew[1, 0]])
keep = lambda e: sum(
    c * alpha**i * beta**j for (i, j), c in sp.Poly(e, alpha, beta).terms() if i + j <= 2
)
answer_small_angle = vec.applyfunc(keep)  # (α, αβ/2, β)""",
    "half_turn_axis": """\
row = sp.Matrix([[23, -24, 36]]) / 49  # first row of R
P_row = (row + sp.Matrix([[1, 0, 0]])) / 2  # first row of (R + I)/2 = ω₁ ωᵀ
w1 = sp.sqrt(P_row[0])  # ω₁² = P₁₁, ω₁ > 0
answer_half_turn_axis = (P_row / w1).T  # (6, −2, 3)/7""",
}

MISTAKES = {
    "compose_frames": {"order": "R_bc @ R_ab", "rows": "R_ab.T @ R_bc.T"},
    "chain_vector": {
        "order": "R_bc @ (R_ab @ v_c)",
        "inverse": "(R_ab @ R_bc).T @ v_c",
        "rows": "R_ab.T @ (R_bc.T @ v_c)",
    },
    "angle_from_trace": {"cosine": "(trace - 1) / 2", "no_minus_one": "sp.acos(trace / 2)"},
    "axis_of_rotation": {
        "unnormalized": "sp.Matrix([skew[2, 1], skew[0, 2], skew[1, 0]])",
        "no_two": "2 * answer_axis_of_rotation",
    },
    "fixed_vs_body": {"all_body": "Rz @ Rx90 @ Rx60", "all_world": "Rx60 @ Rx90 @ Rz"},
    "composed_angle": {
        "no_minus_one": "(Rx * Rz).trace() / 2",
        "sum": "sp.cos(alpha + beta)",
        "angle": "sp.acos(cos_xz)",
    },
    "small_angle": {
        "first_order": "sp.Matrix([alpha, 0, beta])",
        "sign": "sp.Matrix([alpha, -alpha * beta / 2, beta])",
    },
    "half_turn_axis": {
        "other_sign": "-answer_half_turn_axis",
        "abs": "sp.Matrix([sp.Abs(e) for e in answer_half_turn_axis])",
        "row": "answer_half_turn_axis[0] * answer_half_turn_axis",
    },
}
