"""Reference solutions of chapter 5 (instructor side; not part of the installed package).

An exercise with variants reads its numbers from ``P`` (tools/solutions/ch04.py says how).
"""

SOLUTIONS = {
    "quaternion_of_turn": """\
direction = sp.Matrix(P["direction"])
axis = direction / direction.norm()  # unit
half = sp.pi * P["angle"] / 360  # θ/2 in radians
answer_quaternion_of_turn = [sp.cos(half), *(sp.sin(half) * axis)]""",
    "angle_from_ros": """\
x, y, z, w = P["x"], P["y"], P["z"], P["w"]  # ROS order: scalar last
answer_angle_from_ros = 2 * np.arctan2(np.linalg.norm([x, y, z]), w)""",
    "compose_quaternions": """\
axes = {"x": [1, 0, 0], "y": [0, 1, 0], "z": [0, 0, 1]}
q_1 = quaternion.from_axis_angle(axes[P["axis1"]], np.radians(P["a1"]))  # the first turn
q_2 = quaternion.from_axis_angle(axes[P["axis2"]], np.radians(P["a2"]))
answer_compose_quaternions = quaternion.multiply(q_2, q_1)  # world axes: from the left""",
    "proper_euler_angles": """\
R = sp.Matrix(P["R"])  # the exact entries (strings such as "sqrt(3)/4" or "-2/9")
# R_z(α) R_y(β) R_z(γ): third column (cα sβ, sα sβ, cβ), third row (−sβ cγ, sβ sγ, cβ);
# with sin β < 0 the entries divided by sin β change sign
alpha = sp.atan2(-R[1, 2], -R[0, 2])
beta = -sp.atan2(sp.sqrt(R[0, 2] ** 2 + R[1, 2] ** 2), R[2, 2])
gamma = sp.atan2(-R[2, 1], R[2, 0])
answer_proper_euler_angles = [alpha, beta, gamma]  # the default: (π/2, −2π/3, −5π/6)""",
    "unreachable_omega": """\
phi = sp.pi * sp.Rational(str(P["roll"])) / 180  # pitch 90°, yaw 0
Rx = sp.Matrix([[1, 0, 0], [0, sp.cos(phi), -sp.sin(phi)], [0, sp.sin(phi), sp.cos(phi)]])
Ry = sp.Matrix([[0, 0, 1], [0, 1, 0], [-1, 0, 0]])  # R_y(90°)
e_x, e_y, e_z = (sp.eye(3)[:, k] for k in range(3))  # the coordinate axes
yaw_col, pitch_col, roll_col = Rx.T * Ry.T * e_z, Rx.T * e_y, e_x  # yaw_col = −roll_col
n = roll_col.cross(pitch_col)
n = n * sp.sign(sum(n))  # of the two normals, the one with n · (1, 1, 1) > 0
answer_unreachable_omega = list(n / n.norm())""",
    "slerp_angular_velocity": """\
q0, q1 = np.array(P["q0"]), np.array(P["q1"])  # scalar first
R0, R1 = quaternion.to_matrix(q0), quaternion.to_matrix(q1)
T = P["T"]  # seconds
answer_slerp_angular_velocity = so3.log(R1 @ R0.T) / T  # world (the default: (0, 0, 2π/9))""",
    "angle_between_quaternions": """\
q0 = np.array(P["q0"])
x, y, z, w = P["x"], P["y"], P["z"], P["w"]  # the ROS message, scalar last
q1 = np.array([w, x, y, z])
answer_angle_between_quaternions = 2 * np.arccos(abs(q0 @ q1))""",
}

MISTAKES = {
    "quaternion_of_turn": {
        "full_angle": "[sp.cos(2 * half), *(sp.sin(2 * half) * axis)]",
        "not_unit": "[sp.cos(half), *(sp.sin(half) * direction)]",
        "scalar_last": "[*(sp.sin(half) * axis), sp.cos(half)]",
        "negated": "[-sp.cos(half), *(-sp.sin(half) * axis)]",
        "degrees": "[sp.cos(P['angle'] / 2), *(sp.sin(P['angle'] / 2) * axis)]",
    },
    "angle_from_ros": {
        "scalar_first": "2 * np.arccos(x)",
        "half": "np.arctan2(np.linalg.norm([x, y, z]), w)",
    },
    "compose_quaternions": {
        "order": "quaternion.multiply(q_1, q_2)",
        "negated": "-quaternion.multiply(q_2, q_1)",
    },
    "proper_euler_angles": {
        "reversed": "[gamma, beta, alpha]",
        "gamma_sign": "[alpha, beta, sp.atan2(-R[2, 1], -R[2, 0])]",
        "positive_beta": "[sp.atan2(R[1, 2], R[0, 2]), -beta, sp.atan2(R[2, 1], -R[2, 0])]",
        "beta_only": "[sp.atan2(R[1, 2], R[0, 2]), beta, sp.atan2(R[2, 1], -R[2, 0])]",
    },
    "unreachable_omega": {
        "world_frame": "[1, 0, 0]  # normal of e_z, R_z(0) e_y, R_y(90°) e_x",
        "no_transpose": "list((lambda m: m / m.norm())(roll_col.cross(Rx * e_y)))",
        "parallel_columns": "list(roll_col.cross(yaw_col))",
        "sign": "list(-n / n.norm())",
    },
    "slerp_angular_velocity": {
        "body_frame": "so3.log(R0.T @ R1) / T",
        "per_move": "so3.log(R1 @ R0.T)",
        "half_angle": "so3.log(R1 @ R0.T) / T / 2",
        "long_way": "(lambda q: q[1:] / np.linalg.norm(q[1:]) * 2 * np.arccos(q[0]) / T)("
        "quaternion.multiply(q1, quaternion.conjugate(q0)))",
        "reverse": "so3.log(R0 @ R1.T) / T",
    },
    "angle_between_quaternions": {
        "long_way": "2 * np.arccos(q0 @ q1)",
        "scalar_last": "2 * np.arccos(abs(q0 @ np.array([x, y, z, w])))",
        "half_angle": "np.arccos(abs(q0 @ q1))",
    },
}
