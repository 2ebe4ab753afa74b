"""Reference solutions of chapter 2 (instructor side; not part of the installed package)."""

SOLUTIONS = {
    "which_in_so3": '''\
candidates = {
    "a": [[0, -1, 0], [1, 0, 0], [0, 0, 1]], "b": np.diag([1, 1, -1]),
    "c": [[0.6, 0.8, 0], [-0.8, 0.6, 0], [0, 0, 1]], "d": [[1, 1, 0], [0, 1, 0], [0, 0, 1]],
    "e": [[0, 0, 1], [1, 0, 0], [0, 1, 0]], "f": -np.eye(3),
}
def in_so3(M):
    M = np.asarray(M, dtype=float)
    return np.allclose(M.T @ M, np.eye(3)) and np.isclose(np.linalg.det(M), 1)
answer_which_in_so3 = {k for k, M in candidates.items() if in_so3(M)}''',
    "vb_from_va": '''\
R_ab = np.column_stack([[1, 0, 0], [0, 0, 1], [0, -1, 0]])
v_a = np.array([1, 2, 3])
answer_vb_from_va = R_ab.T @ v_a                 # v_b = R_ba v_a = R_abᵀ v_a''',
    "complete_rotation": '''\
r1 = sp.Matrix([2, 1, 2]) / 3
r2 = sp.Matrix([-2, 2, 1]) / 3
assert r1.dot(r1) == r2.dot(r2) == 1 and r1.dot(r2) == 0
answer_complete_rotation = r1.cross(r2)''',
    "inverse_of_product": '''\
answer_inverse_of_product = B.T * A.T            # (AB)⁻¹ = B⁻¹A⁻¹ = BᵀAᵀ''',
    "rigid_inverse": '''\
# g⁻¹(g(p)) = Rᵀ(Rp + d) + e = p + Rᵀd + e, so e = −Rᵀd
answer_rigid_inverse = -R.T * d''',
    "hat_product": '''\
# x̂ŷv = x × (y × v) = y (xᵀv) − (xᵀy) v, so x̂ŷ + (xᵀy) I = y xᵀ
assert sp.expand(hat(x) * hat(y) + x.dot(y) * sp.eye(3) - y * x.T) == sp.zeros(3, 3)
answer_hat_product = Y * X.T''',
    "two_mirrors": '''\
c, s = np.cos(np.pi / 6), np.sin(np.pi / 6)
M1 = np.eye(3) - 2 * np.outer([1, 0, 0], [1, 0, 0])
M2 = np.eye(3) - 2 * np.outer([c, s, 0], [c, s, 0])
turn = M2 @ M1
assert np.allclose(turn.T @ turn, np.eye(3)) and np.isclose(np.linalg.det(turn), 1)
answer_two_mirrors = np.arctan2(turn[1, 0], turn[0, 0])''',
}

MISTAKES = {
    "which_in_so3": {"orthogonal": '{"a", "b", "c", "e", "f"}'},
    "vb_from_va": {"direction": "R_ab @ v_a"},
    "complete_rotation": {"det": "-r1.cross(r2)"},
    "inverse_of_product": {"order": "A.T * B.T", "forward": "A * B"},
    "rigid_inverse": {"minus_d": "-d", "no_transpose": "-R * d"},
    "two_mirrors": {"half": "np.pi / 6", "order": "-np.pi / 3"},
}
