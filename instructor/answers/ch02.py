"""Reference solutions of chapter 2 (instructor side; not part of the installed package)."""

SOLUTIONS = {
    "which_in_so3": """\
# XᵀX = I and det X = +1 for each, from (XY)ᵀ = YᵀXᵀ and det(XY) = det X det Y:
# (a) (RSRᵀ)ᵀRSRᵀ = RSᵀSRᵀ = I, det = 1  (b) det(−R) = (−1)³ = −1
# (c) (RᵀS)ᵀRᵀS = I, det = 1                     (d) det = (−1)(1)(−1) = 1, MᵀM = I
# (e) not orthogonal in general: R = S = R_z(90°) gives 2R − I
# (f) det = −1
Q = np.array([[0, -1, 0], [1, 0, 0], [0, 0, 1]])  # R = S = R_z(90°)
assert not np.allclose((2 * Q - np.eye(3)).T @ (2 * Q - np.eye(3)), np.eye(3))  # (e) fails
answer_which_in_so3 = {"a", "c", "d"}""",
    "vb_from_va": """\
x_ab, y_ab = np.array(P["x_ab"]), np.array(P["y_ab"])
R_ab = np.column_stack([x_ab, y_ab, np.cross(x_ab, y_ab)])  # right-handed: z = x × y
v_a = np.array(P["v_a"])
answer_vb_from_va = R_ab.T @ v_a  # v_b = R_ba v_a = R_abᵀ v_a""",
    "complete_rotation": """\
a_, b_, c_ = sp.symbols("a b c", real=True)
unknowns = {"a": a_, "b": b_, "c": c_}
Rm = sp.Matrix([[unknowns.get(e) or sp.Rational(e) for e in row] for row in P["R"]])
equations = list(Rm.T * Rm - sp.eye(3))  # orthonormal columns (Proposition 3)
solutions_abc = sp.solve(equations, [a_, b_, c_], dict=True)
assert len(solutions_abc) == 1 and Rm.subs(solutions_abc[0]).det() == 1
answer_complete_rotation = [solutions_abc[0][v] for v in (a_, b_, c_)]""",
    "inverse_of_product": """\
answer_inverse_of_product = B * A.T  # R_ca = R_cb R_ba = R_cb R_abᵀ""",
    "rigid_inverse": """\
# g⁻¹(g(p)) = Rᵀ(Rp + d) + e = p + Rᵀd + e, so e = −Rᵀd
answer_rigid_inverse = -R.T * d""",
    "hat_product": """\
# x̂ŷv = x × (y × v) = y (xᵀv) − (xᵀy) v, so x̂ŷ + (xᵀy) I = y xᵀ
assert sp.expand(hat(x) * hat(y) + x.dot(y) * sp.eye(3) - y * x.T) == sp.zeros(3, 3)
answer_hat_product = Y * X.T""",
    "two_mirrors": """\
psi = sp.Symbol("psi", real=True)
n1, n2 = sp.Matrix([1, 0, 0]), sp.Matrix([sp.cos(psi), sp.sin(psi), 0])
M1, M2 = sp.eye(3) - 2 * n1 * n1.T, sp.eye(3) - 2 * n2 * n2.T
turn = (M2 * M1).applyfunc(sp.trigsimp)  # = R_z(2ψ): first column (cos 2ψ, sin 2ψ, 0)
assert (turn - sp.rot_ccw_axis3(2 * psi)).applyfunc(sp.trigsimp) == sp.zeros(3, 3)
degrees = sp.Rational(str(P["turn"]))  # the turn in degrees, exact (a decimal: 47.3)
answer_two_mirrors = sp.pi * degrees / 180 / 2  # 2ψ = the turn""",
}

MISTAKES = {
    "which_in_so3": {
        "orthogonal": '{"a", "b", "c", "d", "f"}',
        "two_reflections": '{"a", "c"}',
        "sum": '{"a", "c", "d", "e"}',
        "minus": '{"a", "b", "c", "d"}',
    },
    "vb_from_va": {
        "direction": "R_ab @ v_a",
        "left_handed": "np.column_stack([x_ab, y_ab, -np.cross(x_ab, y_ab)]).T @ v_a",
    },
    "complete_rotation": {"abs": "[abs(v) for v in answer_complete_rotation]"},
    "inverse_of_product": {"order": "A.T * B", "forward": "A * B.T", "bc": "B.T * A.T"},
    "rigid_inverse": {"minus_d": "-d", "no_transpose": "-R * d"},
    "two_mirrors": {
        "double": "sp.pi * degrees / 180",
        "order": "sp.pi - sp.pi * degrees / 180 / 2",
    },
}
