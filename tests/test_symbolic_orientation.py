"""Tests of course_lib.symbolic_orientation: the sympy quaternions and Euler angles agree with
their numeric twins (course_lib.quaternion, course_lib.euler) at random points, the general-case
identities vanish, and the rates matrix is the angular velocity (finite differences) and is
singular exactly at gimbal lock.
"""

import itertools

import numpy as np
import pytest
import sympy as sp

from course_lib import euler, so3
from course_lib import quaternion as Q
from course_lib import symbolic_orientation as so
from course_lib.symbolic import is_zero_matrix, omega, theta, vector

EXTRINSIC = ["".join(p) for p in itertools.product("xyz", repeat=3) if p[0] != p[1] != p[2]]
SEQS = EXTRINSIC + [s.upper() for s in EXTRINSIC]
P, QS = so.quaternion_symbols("p"), so.quaternion_symbols("q")
ABC = so.euler_symbols()


def numeric(M, values):
    return np.array(sp.Matrix(M).subs(values).evalf(), dtype=float)


def unit_quaternion(seed):
    q = np.random.default_rng(seed).standard_normal(4)
    return q / np.linalg.norm(q)


def test_quaternion_multiply_matches_the_numeric_product():
    product = so.quaternion_multiply(P, QS)
    for seed in range(5):
        p, q = unit_quaternion(seed), unit_quaternion(seed + 10)
        values = dict(zip(list(P) + list(QS), list(p) + list(q)))
        assert np.allclose(numeric(product, values).ravel(), Q.multiply(p, q), atol=1e-15)


def test_hamilton_rules_ij_k_and_ijk_minus_1():
    one, i, j, k = (sp.Matrix(list(r)) for r in sp.eye(4).tolist())
    assert so.quaternion_multiply(i, j) == k
    assert so.quaternion_multiply(so.quaternion_multiply(i, j), k) == -one


def test_quaternion_to_matrix_matches_the_numeric_one():
    R = so.quaternion_to_matrix(QS)
    for seed in range(5):
        q = unit_quaternion(seed)
        assert np.allclose(numeric(R, dict(zip(QS, q))), Q.to_matrix(q), atol=1e-15)


def test_q_and_minus_q_give_the_same_matrix():
    assert so.quaternion_to_matrix(QS) == so.quaternion_to_matrix(-QS)


def test_quaternion_of_axis_angle_gives_rodrigues_formula():
    assert is_zero_matrix(so.quaternion_rodrigues_residual())
    # the half angle matters: (cos θ, ω sin θ) is the turn by 2θ, not θ
    wrong = so.quaternion_to_matrix([sp.cos(theta), 0, 0, sp.sin(theta)])
    assert not is_zero_matrix(wrong - so.elementary_rotation("z", theta))


def test_q_v_qstar_is_R_of_q_times_v_up_to_the_norm_of_q():
    # q (0, v) q* − R(q) v = (‖q‖² − 1) v: equal exactly for unit q
    v = vector("v")
    difference = so.quaternion_rotate(QS, v) - so.quaternion_to_matrix(QS) * v
    assert is_zero_matrix(difference - (QS.dot(QS) - 1) * v)


def test_quaternion_rotate_by_axis_angle_is_rodrigues():
    v = vector("v")
    rotated = so.quaternion_rotate(so.quaternion_from_axis_angle([0, 0, 1], theta), v)
    expected = so.elementary_rotation("z", theta) * v
    assert is_zero_matrix(rotated - expected)


def test_quaternion_from_axis_angle_matches_the_numeric_one():
    q = so.quaternion_from_axis_angle(omega, theta)
    axis = np.array([2.0, -1.0, 0.5]) / np.linalg.norm([2.0, -1.0, 0.5])
    values = dict(zip(list(omega) + [theta], list(axis) + [1.3]))
    assert np.allclose(numeric(q, values).ravel(), Q.from_axis_angle(axis, 1.3), atol=1e-15)


@pytest.mark.parametrize("seq", SEQS)
def test_euler_to_matrix_matches_the_numeric_one(seq):
    angles = [0.4, -1.2, 2.2]
    R = numeric(so.euler_to_matrix(ABC, seq), dict(zip(ABC, angles)))
    assert np.allclose(R, euler.to_matrix(angles, seq), atol=1e-15)


@pytest.mark.parametrize("seq", ["ZYX", "xyz", "ZXZ", "zyz", "YXY", "xzy"])
def test_euler_rates_matrix_is_the_angular_velocity(seq):
    # ω̂_b = Rᵀ Ṙ and ω_s = R ω_b, Ṙ by central differences along the rates
    angles, rates, h = np.array([0.4, -0.7, 1.1]), np.array([0.3, -0.2, 0.5]), 1e-6
    R = euler.to_matrix(angles, seq)
    R_dot = euler.to_matrix(angles + h * rates, seq) - euler.to_matrix(angles - h * rates, seq)
    R_dot /= 2 * h
    w_body = so3.vee(R.T @ R_dot, tol=1e-8)
    values = dict(zip(ABC, angles))
    E_body = numeric(so.euler_rates_matrix(seq, frame="body"), values)
    E_space = numeric(so.euler_rates_matrix(seq, frame="space"), values)
    assert np.allclose(E_body @ rates, w_body, atol=1e-9)
    assert np.allclose(E_space @ rates, R @ w_body, atol=1e-9)


@pytest.mark.parametrize("seq, lock", [("ZYX", sp.pi / 2), ("xyz", -sp.pi / 2), ("ZXZ", 0)])
def test_euler_rates_matrix_is_singular_exactly_at_gimbal_lock(seq, lock):
    a, b, c = ABC
    det = sp.trigsimp(so.euler_rates_matrix(seq).det())
    assert det.free_symbols == {b}  # it depends on the middle angle alone
    assert sp.simplify(det.subs(b, lock)) == 0
    assert sp.simplify(det.subs(b, sp.pi / 3)) != 0


def test_bad_input_gets_a_clear_error():
    with pytest.raises(ValueError, match="4 entries"):
        so.quaternion_to_matrix([1, 0, 0])
    with pytest.raises(TypeError, match="string"):
        so.quaternion_conjugate("wxyz")
    with pytest.raises(ValueError, match="must not repeat an axis"):
        so.euler_to_matrix(ABC, "XXY")
    with pytest.raises(ValueError, match="frame must be"):
        so.euler_rates_matrix("ZYX", frame="world")
    with pytest.raises(ValueError, match="axis must be 'x', 'y' or 'z'"):
        so.elementary_rotation("w", theta)
    with pytest.raises(ValueError, match="3 expressions"):
        so.euler_to_matrix((theta, theta), "xyz")
