"""Reference solutions of chapter 5 (instructor side; not part of the installed package)."""

SOLUTIONS = {
    "quaternion_of_turn": """\
axis = sp.Matrix([1, 2, 2]) / 3  # unit: ‖(1, 2, 2)‖ = 3
half = sp.pi / 4  # θ/2
answer_quaternion_of_turn = [sp.cos(half), *(sp.sin(half) * axis)]""",
    "angle_from_ros": """\
x, y, z, w = 0.0, 0.0, 0.6, 0.8  # ROS order: scalar last
answer_angle_from_ros = 2 * np.arctan2(z, w)""",
    "compose_quaternions": """\
q_x = quaternion.from_axis_angle([1, 0, 0], np.pi / 2)
q_z = quaternion.from_axis_angle([0, 0, 1], np.pi / 2)
answer_compose_quaternions = quaternion.multiply(q_z, q_x)  # world axes: from the left""",
    "angles_of_matrix": """\
R = sp.Matrix(
    [
        [-sp.sqrt(3) / 4, sp.Rational(1, 4), -sp.sqrt(3) / 2],
        [sp.Rational(3, 4), -sp.sqrt(3) / 4, -sp.Rational(1, 2)],
        [-sp.Rational(1, 2), -sp.sqrt(3) / 2, 0],
    ]
)
yaw = sp.atan2(R[1, 0], R[0, 0])
pitch = sp.atan2(-R[2, 0], sp.sqrt(R[0, 0] ** 2 + R[1, 0] ** 2))
roll = sp.atan2(R[2, 1], R[2, 2])
answer_angles_of_matrix = [yaw, pitch, roll]  # (2π/3, π/6, −π/2)""",
    "proper_euler_lock": """\
gamma = sp.Symbol("gamma", real=True)
Rx = sp.Matrix([[1, 0, 0], [0, sp.cos(beta), -sp.sin(beta)], [0, sp.sin(beta), sp.cos(beta)]])
Rz = sp.Matrix([[sp.cos(gamma), -sp.sin(gamma), 0], [sp.sin(gamma), sp.cos(gamma), 0], [0, 0, 1]])
e1, e3 = sp.Matrix([1, 0, 0]), sp.Matrix([0, 0, 1])
E = sp.Matrix.hstack(Rz.T * Rx.T * e3, Rz.T * e1, e3)
answer_proper_euler_lock = sp.trigsimp(E.det())  # −sin β""",
    "slerp_third": """\
q1 = quaternion.from_axis_angle([0, 0, 1], 2 * np.pi / 3)
answer_slerp_third = quaternion.slerp([1, 0, 0, 0], q1, 1 / 3)  # the turn by 40°""",
    "angle_between_quaternions": """\
q0, q1 = np.array([0.6, 0.8, 0, 0]), np.array([-0.8, 0, 0, 0.6])
answer_angle_between_quaternions = 2 * np.arccos(abs(q0 @ q1))""",
}

MISTAKES = {
    "quaternion_of_turn": {
        "full_angle": "[sp.cos(2 * half), *(sp.sin(2 * half) * axis)]",
        "not_unit": "[sp.cos(half), *(sp.sin(half) * 3 * axis)]",
        "scalar_last": "[*(sp.sin(half) * axis), sp.cos(half)]",
        "negated": "[-sp.cos(half), *(-sp.sin(half) * axis)]",
    },
    "angle_from_ros": {"scalar_first": "2 * np.arccos(x)", "half": "np.arctan2(z, w)"},
    "compose_quaternions": {
        "order": "quaternion.multiply(q_x, q_z)",
        "negated": "-quaternion.multiply(q_z, q_x)",
    },
    "angles_of_matrix": {
        "reversed": "[roll, pitch, yaw]",
        "pitch_sign": "[yaw, -pitch, roll]",
    },
    "proper_euler_lock": {"tait_bryan": "-sp.cos(beta)"},
    "slerp_third": {
        "nlerp": "(lambda v: v / np.linalg.norm(v))(2 / 3 * np.array([1, 0, 0, 0]) + q1 / 3)",
        "full_angle": "quaternion.from_axis_angle([0, 0, 1], 4 * np.pi / 9)",
        "negated": "-quaternion.slerp([1, 0, 0, 0], q1, 1 / 3)",
    },
    "angle_between_quaternions": {"long_way": "2 * np.arccos(q0 @ q1)"},
}
