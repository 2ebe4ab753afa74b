"""Reference solutions of chapter 4 (instructor side; not part of the installed package).

An exercise with variants reads its numbers from ``P``, the student's parameters: the answer
cell sets ``P = parameters(name)`` before the solution, and the tools set ``P`` to each variant.
"""

SOLUTIONS = {
    "compose_frames": """\
R_ab = np.column_stack([P["x_ab"], P["y_ab"], P["z_ab"]])
R_bc = np.column_stack([P["x_bc"], P["y_bc"], P["z_bc"]])
answer_compose_frames = R_ab @ R_bc""",
    "chain_vector": """\
R_ab = np.column_stack([P["x_ab"], P["y_ab"], P["z_ab"]])
R_bc = np.column_stack([P["x_bc"], P["y_bc"], P["z_bc"]])
v_c = np.array(P["v_c"])
answer_chain_vector = R_ab @ (R_bc @ v_c)""",
    "angle_from_trace": """\
trace = sum(sp.Rational(str(P[k])) for k in ("R11", "R22", "R33"))  # only the diagonal
answer_angle_from_trace = sp.acos((trace - 1) / 2)""",
    "axis_of_rotation": """\
skew = P["factor"] * np.array(P["M"])  # R − Rᵀ, as given
angle = np.arccos((P["trace"] - 1) / 2)  # from tr R = 1 + 2 cos θ
S = skew / (2 * np.sin(angle))  # = ω̂
answer_axis_of_rotation = np.array([S[2, 1], S[0, 2], S[1, 0]])""",
    "fixed_vs_body": """\
turns = []  # R_x, R_y or R_z of the notes, for each of the three turns
for k in (1, 2, 3):
    c, s = np.cos(np.radians(P[f"a{k}"])), np.sin(np.radians(P[f"a{k}"]))
    i, j = [(1, 2), (2, 0), (0, 1)]["xyz".index(P[f"axis{k}"])]  # the plane it turns
    turn_k = np.eye(3)
    turn_k[i, i], turn_k[i, j], turn_k[j, i], turn_k[j, j] = c, -s, s, c
    turns.append(turn_k)
R1, R2, R3 = turns
R = R1  # about a world axis, from R = I
R = R @ R2  # about the camera's own axis: from the right
R = R3 @ R  # about a world axis: from the left
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
    "two_half_turns": """\
u = sp.Matrix(P["q_u"]) / P["n_u"]
v = sp.Matrix(P["q_v"]) / P["n_v"]
H = lambda a: 2 * a * a.T - sp.eye(3)  # R(a, π) = I + 2â² = 2aaᵀ − I
R = H(u) * H(v)
n = u.cross(v)  # both half turns map the line of n onto itself (n → −n → n)
# In the plane ⟂ n each half turn is a mirror in the line of its axis; two mirrors at angle α
# make a turn by 2α; when α > 90° (u·v < 0) the short way is θ = 2π − 2α:
cos_t = (R.trace() - 1) / 2  # = 2(u·v)² − 1
s = sp.Matrix([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]]) / 2  # sin θ ω
assert s.cross(n) == sp.zeros(3, 1)  # the axis lies along u × v
angle = sp.acos(cos_t)  # in [0, π]
answer_two_half_turns = angle * s / s.norm()  # ω θ, ω along ±u × v""",
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
        "unnormalized": "np.array([skew[2, 1], skew[0, 2], skew[1, 0]])",
        "no_two": "2 * answer_axis_of_rotation",
        "sign": "-answer_axis_of_rotation",
    },
    "fixed_vs_body": {
        "all_body": "R1 @ R2 @ R3",
        "all_world": "R3 @ R2 @ R1",
        "swapped": "R2 @ R1 @ R3",
    },
    "composed_angle": {
        "no_minus_one": "(Rx * Rz).trace() / 2",
        "sum": "sp.cos(alpha + beta)",
        "angle": "sp.acos(cos_xz)",
    },
    "small_angle": {
        "first_order": "sp.Matrix([alpha, 0, beta])",
        "sign": "sp.Matrix([alpha, -alpha * beta / 2, beta])",
    },
    "two_half_turns": {
        "order": "-answer_two_half_turns",
        "long_way": "(angle - 2 * sp.pi) * s / s.norm()",
        "single_angle": "angle / 2 * s / s.norm()",
        "unit_axis": "s / s.norm()",
        "sum": "sp.pi * (u + v)",
    },
}
