"""Reference solutions of chapter 4 (instructor side; not part of the installed package)."""

SOLUTIONS = {
    "compose_frames": '''\
R_ab = np.column_stack([[0, 1, 0], [-1, 0, 0], [0, 0, 1]])
R_bc = np.column_stack([[1, 0, 0], [0, 0, 1], [0, -1, 0]])
answer_compose_frames = R_ab @ R_bc''',
    "chain_vector": '''\
R_ab = np.column_stack([[0, 1, 0], [-1, 0, 0], [0, 0, 1]])
R_bc = np.column_stack([[1, 0, 0], [0, 0, 1], [0, -1, 0]])
v_c = np.array([1, 2, 3])
answer_chain_vector = R_ab @ (R_bc @ v_c)''',
    "angle_from_trace": '''\
R = sp.Matrix([[2, -1, 2], [2, 2, -1], [-1, 2, 2]]) / 3
assert R.T * R == sp.eye(3) and R.det() == 1
answer_angle_from_trace = sp.acos((R.trace() - 1) / 2)''',
    "axis_of_rotation": '''\
R = sp.Matrix([[2, -1, 2], [2, 2, -1], [-1, 2, 2]]) / 3
angle = sp.acos((R.trace() - 1) / 2)
S = (R - R.T) / (2 * sp.sin(angle))                  # = ω̂
answer_axis_of_rotation = sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])''',
    "fixed_vs_body": '''\
c = np.cos(np.pi / 2)
s = np.sin(np.pi / 2)
Rx = np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
Rz = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
R = Rz                      # about the world z axis, from R = I
R = R @ Rx                  # about the body's own x axis: from the right
R = Rx @ R                  # about the world x axis: from the left
answer_fixed_vs_body = R''',
    "composed_angle": '''\
Rx = sp.Matrix([[1, 0, 0], [0, sp.cos(alpha), -sp.sin(alpha)], [0, sp.sin(alpha), sp.cos(alpha)]])
Rz = sp.Matrix([[sp.cos(beta), -sp.sin(beta), 0], [sp.sin(beta), sp.cos(beta), 0], [0, 0, 1]])
cos_xz = ((Rx * Rz).trace() - 1) / 2
assert sp.expand(cos_xz - ((Rz * Rx).trace() - 1) / 2) == 0       # same angle
answer_composed_angle = cos_xz''',
    "small_angle": '''\
R_small = np.array([[1.0, -6.66666668e-09, -3.33333331e-09],
                    [6.66666666e-09, 1.0, -6.66666668e-09],
                    [3.33333336e-09, 6.66666666e-09, 1.0]])
naive = np.arccos((np.trace(R_small) - 1) / 2)       # 0.0: cos θ rounded to 1
S = (R_small - R_small.T) / 2                        # sin θ ω̂
sin_theta = np.linalg.norm([S[2, 1], S[0, 2], S[1, 0]])
answer_small_angle = np.arctan2(sin_theta, (np.trace(R_small) - 1) / 2)''',
    "half_turn_axis": '''\
R = sp.Matrix([[-7, -4, 4], [-4, -1, -8], [4, -8, -1]]) / 9
P = (R + sp.eye(3)) / 2                              # = ωωᵀ
w1 = sp.sqrt(P[0, 0])                                # ω₁ > 0
answer_half_turn_axis = sp.Matrix([w1, P[0, 1] / w1, P[0, 2] / w1])''',
}

MISTAKES = {
    "compose_frames": {"order": "R_bc @ R_ab"},
    "chain_vector": {"order": "R_bc @ (R_ab @ v_c)", "inverse": "(R_ab @ R_bc).T @ v_c"},
    "angle_from_trace": {"cosine": "(R.trace() - 1) / 2", "no_minus_one": "sp.acos(R.trace() / 2)"},
    "axis_of_rotation": {"unnormalized": "sp.Matrix([1, 1, 1])"},
    "fixed_vs_body": {"all_body": "Rz @ Rx @ Rx", "all_world": "Rx @ Rx @ Rz"},
    "composed_angle": {"no_minus_one": "(Rx * Rz).trace() / 2", "sum": "sp.cos(alpha + beta)"},
    "small_angle": {"arccos": "naive"},
    "half_turn_axis": {"other_sign": "-answer_half_turn_axis",
                       "abs": "sp.Matrix([sp.Abs(e) for e in answer_half_turn_axis])"},
}
