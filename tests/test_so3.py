"""Tests of course_lib.so3: accuracy against scipy, the textbook failures, identities, bad input."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from course_lib import TOL, so3

EPS = np.finfo(float).eps

finite = st.floats(-10.0, 10.0, allow_nan=False, allow_infinity=False)
vectors = st.lists(finite, min_size=3, max_size=3).map(np.array)
unit_axes = vectors.filter(lambda v: np.linalg.norm(v) > 1e-3).map(lambda v: v / np.linalg.norm(v))
angles = st.floats(0.0, np.pi, allow_nan=False)


def mixed_sign_axes():
    axes = np.array([[1, -1, 1], [1, -1, -1], [-2, 1, 3], [0, 1, -1], [1, 1, -1e-9], [3, -4, 0]])
    return axes / np.linalg.norm(axes, axis=1, keepdims=True)


def sample_axes(n=500, seed=7):
    axes = np.random.default_rng(seed).standard_normal((n, 3))
    return np.concatenate([axes / np.linalg.norm(axes, axis=1, keepdims=True), mixed_sign_axes()])


def exact_pi_rotation(axis):
    """R = 2 ω ωᵀ − I: a rotation by exactly π, built without any sine or cosine."""
    return 2.0 * np.outer(axis, axis) - np.eye(3)


# --- hat / vee ---------------------------------------------------------------------------


def test_hat_matches_definition_5():
    assert np.array_equal(so3.hat([1, 2, 3]), [[0, -3, 2], [3, 0, -1], [-2, 1, 0]])


@given(vectors, vectors)
def test_hat_is_the_cross_product(a, b):
    assert np.allclose(so3.hat(a) @ b, np.cross(a, b), atol=1e-12)


@given(vectors)
def test_vee_inverts_hat(w):
    assert np.array_equal(so3.vee(so3.hat(w)), w)


def test_hat_and_vee_broadcast_over_leading_axes():
    w = np.arange(24.0).reshape(2, 4, 3)
    W = so3.hat(w)
    assert W.shape == (2, 4, 3, 3)
    assert np.array_equal(so3.vee(W), w)


def test_vee_refuses_a_matrix_that_is_not_skew():
    with pytest.raises(ValueError, match=r"not skew-symmetric: ‖W \+ Wᵀ‖ = 3\.5e\+00"):
        so3.vee(np.eye(3))


@given(vectors)
def test_hat_cubed_is_minus_norm_squared_hat(w):
    W = so3.hat(w)
    assert np.allclose(W @ W @ W, -np.dot(w, w) * W, atol=1e-9 * (1 + np.dot(w, w) ** 1.5))


# --- exp ---------------------------------------------------------------------------------


def test_exp_agrees_with_scipy_to_4e15_for_every_angle_from_0_to_pi():
    axes = sample_axes()
    for theta in np.concatenate(
        [[0, 1e-12, 1e-8, 1e-4], np.linspace(0, np.pi, 61), [np.pi - 1e-12]]
    ):
        R = so3.exp(axes, theta)
        ref = Rotation.from_rotvec(axes * theta).as_matrix()
        assert np.abs(R - ref).max() <= 4e-15, theta


def test_exp_is_orthogonal_with_unit_determinant_to_a_few_epsilons():
    r = sample_axes() * np.random.default_rng(1).uniform(0, np.pi, 506)[:, None]
    R = so3.exp(r)
    ref = Rotation.from_rotvec(r).as_matrix()
    for M in (R, ref):  # ours within a few epsilons, and no worse than scipy's
        orth = np.abs(np.swapaxes(M, -1, -2) @ M - np.eye(3)).max()
        det = np.abs(np.linalg.det(M) - 1).max()
        print(orth / EPS, det / EPS)
    assert np.abs(np.swapaxes(R, -1, -2) @ R - np.eye(3)).max() <= 10 * EPS
    assert np.abs(np.linalg.det(R) - 1).max() <= 10 * EPS


@pytest.mark.parametrize("turns", [1, 3, 5])
def test_exp_stays_accurate_where_the_half_angle_tangent_blows_up(turns):
    # exp takes cos(θ/2) and sin(θ/2) from t = tan(θ/2); near θ = 2π·(odd) t is ~1e16
    theta = turns * 2 * np.pi + np.array([0.0, 1e-12, -1e-12, 1e-6, -1e-6])
    r = sample_axes(40)[:, None, :] * theta[:, None]
    R = so3.exp(r)
    assert np.abs(R - Rotation.from_rotvec(r.reshape(-1, 3)).as_matrix().reshape(R.shape)).max() < (
        8 * EPS * turns
    )
    assert np.abs(np.swapaxes(R, -1, -2) @ R - np.eye(3)).max() <= 10 * EPS
    for w, M in zip(r[:, 0], R[:, 0]):  # the single-call path (math.tan) agrees, to the
        atol = 4e-16 * np.abs(w).max()  # rounding of ‖w‖ (hypot there, a square root here)
        np.testing.assert_allclose(so3.exp(w), M, rtol=0, atol=atol)


def test_exp_with_theta_equals_exp_of_rotation_vector():
    axes = sample_axes(50)
    assert np.allclose(so3.exp(axes, 0.7), so3.exp(0.7 * axes), atol=1e-15)


def test_exp_theta_broadcasts_against_axes():
    R = so3.exp([0, 0, 1], np.linspace(0, 1, 5))
    assert R.shape == (5, 3, 3)
    assert np.allclose(R, so3.rot_z(np.linspace(0, 1, 5)), atol=1e-15)


def test_exp_of_tiny_rotation_vector_keeps_its_off_diagonal_entries():
    # θ² underflows below 1e-154; the skew entries must still be exactly ±r.
    R = so3.exp([1e-200, -2e-200, 0.0])
    assert R[2, 1] == 1e-200 and R[2, 0] == 2e-200


def test_exp_matches_rot_xyz():
    t = 0.83
    assert np.allclose(so3.exp([1, 0, 0], t), so3.rot_x(t), atol=1e-15)
    assert np.allclose(so3.exp([0, 1, 0], t), so3.rot_y(t), atol=1e-15)
    assert np.allclose(so3.exp([0, 0, 1], t), so3.rot_z(t), atol=1e-15)


def test_exp_refuses_non_unit_axis_with_theta():
    with pytest.raises(
        ValueError, match=r"w must be a unit vector: ‖w‖ = 2, .*> TOL = 1e-09; normalise"
    ):
        so3.exp([0, 0, 2], 0.5)


# --- log ---------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "theta", [0.0, 1e-12, 1e-8, 0.3, np.pi / 2, 2.0, 3.0, np.pi - 1e-6, np.pi - 1e-12, np.pi]
)
def test_log_reproduces_R_to_1e14_at_every_angle(theta):
    axes = sample_axes()
    R = so3.exp(axes, theta)
    r = so3.log(R)
    assert np.all(np.linalg.norm(r, axis=-1) <= np.pi * (1 + 4 * EPS))
    assert so3.angle_between(so3.exp(r), R).max() <= 1e-14


@pytest.mark.parametrize("theta", [1e-12, 1e-8, 1e-3, 0.3, 1.0, 2.0, 3.0, 3.14])
def test_log_rotation_vector_relative_error_within_1e14_away_from_pi(theta):
    axes = sample_axes()
    r = so3.log(so3.exp(axes, theta))
    rel = np.linalg.norm(r - axes * theta, axis=-1) / theta
    assert rel.max() <= 1e-14


def test_log_at_exactly_pi_about_a_mixed_sign_axis_is_not_zero():
    # ModernRobotics' MatrixLog3 returns 0 here.
    for axis in mixed_sign_axes():
        r = so3.log(exact_pi_rotation(axis))
        assert abs(np.linalg.norm(r) - np.pi) <= 1e-15
        assert np.allclose(np.abs(r @ axis), np.pi, atol=1e-14)


def test_log_axis_signs_at_exactly_pi_reproduce_R():
    # pytransform3d gets the relative signs of the axis components wrong at exactly π.
    for axis in mixed_sign_axes():
        R = exact_pi_rotation(axis)
        assert so3.angle_between(so3.exp(so3.log(R)), R) <= 1e-14


def test_log_just_below_pi_is_not_off_by_1e4():
    # spatialmath's trlog is off by 8e-4 at θ = π − 1e-6.
    axes = sample_axes()
    theta = np.pi - 1e-6
    r = so3.log(so3.exp(axes, theta))
    assert np.abs(r - axes * theta).max() <= 1e-14


def test_log_of_identity_is_zero_and_axis_angle_returns_e3():
    assert np.array_equal(so3.log(np.eye(3)), np.zeros(3))
    axis, angle = so3.axis_angle(np.eye(3))
    assert np.array_equal(axis, [0, 0, 1]) and angle == 0


@pytest.mark.parametrize("t", [1e-100, 1e-155, 1e-200, 1e-300, 5e-320])
def test_axis_angle_of_a_1e200_rotation_is_not_the_identity(t):
    # The squared norm of the skew part underflowed below 1e-154: axis_angle returned e3 and
    # the angle 0 for a rotation by 1.4e-200 about (1, 0, -1)/√2.
    R = so3.exp([t, 0.0, -t])
    for batch in (R, R[None]):
        axis, angle = so3.axis_angle(batch)
        assert np.allclose(axis, [2**-0.5, 0.0, -(2**-0.5)], atol=1e-4 if t < 1e-307 else 1e-15)
        assert abs(angle - np.sqrt(2) * t) <= (1e-4 if t < 1e-307 else 4 * EPS) * np.sqrt(2) * t
        assert np.array_equal(so3.log(batch), np.reshape([t, 0.0, -t], np.shape(batch)[:-1]))


def test_log_single_call_and_batch_agree_at_every_branch():
    # Two code paths (9 Python floats, chunked rows): each branch (identity, tiny, v / sin θ,
    # the switch at 150°, R + Rᵀ, exactly π) must agree in both, to the last bits (math.atan2
    # and numpy's vectorised arctan2 can differ by one unit in the last place).
    switch = 5 * np.pi / 6
    thetas = [0.0, 1e-300, 1e-200, 1e-9, 1.0, np.nextafter(switch, 0), switch]
    thetas += [np.nextafter(switch, 4), 3.0, np.pi - 1e-9, np.pi]
    axes = sample_axes(40)
    for theta in thetas:
        R = so3.exp(axes, theta)
        r, (axis, angle) = so3.log(R), so3.axis_angle(R)
        for i in range(len(R)):
            one_axis, one_angle = so3.axis_angle(R[i])
            assert np.abs(so3.log(R[i]) - r[i]).max() <= 4 * EPS * angle[i], (theta, i)
            assert np.abs(one_axis - axis[i]).max() <= 4 * EPS, (theta, i)
            assert abs(one_angle - angle[i]) <= 4 * EPS * angle[i], (theta, i)


@pytest.mark.parametrize("theta", [2.5, 2.6, 2.617, 2.618, 2.62, 2.7])
def test_log_keeps_full_accuracy_either_side_of_the_150_degree_switch(theta):
    axes = sample_axes()
    r = so3.log(so3.exp(axes, theta))
    rel = np.linalg.norm(r - axes * theta, axis=-1) / theta
    assert rel.max() <= 6 * EPS


def test_axis_angle_returns_unit_axes_and_angles():
    r = sample_axes() * np.random.default_rng(3).uniform(1e-9, np.pi, 506)[:, None]
    axis, angle = so3.axis_angle(so3.exp(r))
    assert np.allclose(np.linalg.norm(axis, axis=-1), 1, atol=1e-15)
    assert np.allclose(axis * angle[:, None], r, atol=1e-13)


def test_log_keeps_batch_shape():
    R = so3.random_rotations(24, seed=0).reshape(2, 3, 4, 3, 3)
    assert so3.log(R).shape == (2, 3, 4, 3)
    assert np.allclose(so3.exp(so3.log(R)), R, atol=1e-14)


def test_log_refuses_a_reflection():
    with pytest.raises(ValueError, match=r"reflection, not a rotation: det\(R\) = -1"):
        so3.log(np.diag([1.0, 1.0, -1.0]))


def test_log_refuses_a_non_orthogonal_matrix_naming_the_residual():
    with pytest.raises(ValueError, match=r"‖RᵀR − I‖ = 3\.0e-02 > TOL = 1e-09"):
        so3.log(np.diag([1, 1, 1.015]))  # ‖RᵀR − I‖ = 1.015² − 1


def test_log_names_the_batch_index_of_the_first_bad_matrix():
    R = so3.random_rotations(10, seed=2)
    R[6] *= -1
    with pytest.raises(ValueError, match=r"batch index \(6,\)"):
        so3.log(R)


def test_log_refuses_nan_instead_of_returning_nan():
    R = np.eye(3)
    R[1, 1] = np.nan
    with pytest.raises(ValueError, match="NaN or infinity"):
        so3.log(R)


# --- exp_series --------------------------------------------------------------------------


def test_exp_series_converges_to_exp():
    W = so3.hat([0.3, -1.2, 2.0])
    assert np.abs(so3.exp_series(W, 40) - so3.exp([0.3, -1.2, 2.0])).max() <= 1e-14


def test_exp_series_of_any_square_matrix():
    A = np.array([[1.0, 2.0], [0.0, 1.0]])  # e^A = e [[1, 2], [0, 1]]
    assert np.allclose(so3.exp_series(A, 30), np.e * A, atol=1e-14)
    assert np.array_equal(so3.exp_series(A, 1), np.eye(2))


def test_exp_series_refuses_zero_terms_and_non_square():
    with pytest.raises(ValueError, match="terms must be >= 1"):
        so3.exp_series(np.eye(3), 0)
    with pytest.raises(ValueError, match="square"):
        so3.exp_series(np.ones((2, 3)), 3)


# --- membership, random rotations, angles -------------------------------------------------


def test_is_rotation_examples():
    assert so3.is_rotation(so3.rot_y(np.pi)) is True
    assert so3.is_rotation(np.diag([-1, -1, -1])) is False
    assert so3.is_rotation(np.full((3, 3), np.nan)) is False
    assert so3.is_rotation(np.eye(3) + 1e-10) is True
    assert list(so3.is_rotation(np.stack([np.eye(3), 2 * np.eye(3)]))) == [True, False]


def test_check_rotation_message_for_2I():
    with pytest.raises(ValueError, match=r"not a rotation: ‖RᵀR − I‖ = 5\.2e\+00 .*det = 8"):
        so3.check_rotation(2 * np.eye(3))


def test_random_rotations_are_rotations_and_reproducible():
    Rs = so3.random_rotations(2000, seed=11)
    assert Rs.shape == (2000, 3, 3) and so3.is_rotation(Rs).all()
    assert np.array_equal(Rs, so3.random_rotations(2000, seed=11))


def test_random_rotations_are_uniform_haar():
    # Under the Haar measure the angle has density (1 − cos θ)/π, so E[cos θ] = −1/2, and each
    # entry of R has mean 0 and variance 1/3.
    Rs = so3.random_rotations(200_000, seed=5)
    cos = 0.5 * (np.trace(Rs, axis1=1, axis2=2) - 1)
    assert abs(cos.mean() + 0.5) < 0.01
    assert np.abs(Rs.mean(axis=0)).max() < 0.01
    assert np.abs(Rs.var(axis=0) - 1 / 3).max() < 0.01


def test_angle_between_is_accurate_for_tiny_angles():
    for t in [1e-15, 1e-12, 1e-9, 1e-5]:
        assert abs(so3.angle_between(np.eye(3), so3.rot_x(t)) - t) <= 1e-15 * t


def test_angle_between_matches_log_of_relative_rotation():
    R1, R2 = so3.random_rotations(300, seed=3), so3.random_rotations(300, seed=4)
    ref = np.linalg.norm(so3.log(np.swapaxes(R1, -1, -2) @ R2), axis=-1)
    assert np.allclose(so3.angle_between(R1, R2), ref, atol=1e-14)


# --- properties --------------------------------------------------------------------------


@settings(max_examples=200)
@given(unit_axes, angles)
def test_exp_log_round_trip(axis, theta):
    R = so3.exp(axis, theta)
    assert so3.angle_between(so3.exp(so3.log(R)), R) <= 1e-14


@given(st.integers(0, 2**32 - 1), vectors)
def test_conjugating_hat_rotates_the_vector(seed, w):
    R = so3.random_rotations(1, seed=seed)[0]
    assert np.allclose(R @ so3.hat(w) @ R.T, so3.hat(R @ w), atol=1e-12 * (1 + np.abs(w).max()))


@given(st.integers(0, 2**32 - 1), vectors, vectors)
def test_rotation_preserves_cross_products(seed, v, w):
    R = so3.random_rotations(1, seed=seed)[0]
    scale = 1 + np.abs(v).max() * np.abs(w).max()
    assert np.allclose(R @ np.cross(v, w), np.cross(R @ v, R @ w), atol=1e-12 * scale)


@given(st.integers(0, 2**32 - 1))
def test_products_of_rotations_are_rotations(seed):
    R1, R2 = so3.random_rotations(2, seed=seed)
    assert so3.is_rotation(R1 @ R2)


# --- regressions found by the peer suites (issue 19) ---------------------------------------


@pytest.mark.parametrize("sign", [1.0, -1.0])
@pytest.mark.parametrize("k", [0, 1, 2])
def test_exp_at_exactly_pi_about_a_coordinate_axis_had_diagonal_minus_1_0000000000000009(k, sign):
    # exp(log(diag(1, −1, −1))) = exp([π, 0, 0]) gave −1.0000000000000009 (4 ulp) on the
    # diagonal, so arccos of an entry was NaN; every peer library gives −1 there.
    axis = np.eye(3)[k]
    expected = 2.0 * np.diag(axis) - np.eye(3)
    for R in (
        so3.exp(sign * np.pi * axis),
        so3.exp(list(sign * np.pi * axis)),
        so3.exp(sign * np.pi * axis[None])[0],
        so3.exp(axis, sign * np.pi),
        so3.exp(axis[None], [sign * np.pi])[0],
    ):
        assert np.array_equal(np.diagonal(R), np.diagonal(expected))
        assert np.abs(R).max() <= 1.0
        assert not np.isnan(np.arccos(np.diagonal(R))).any()
    assert np.array_equal(np.diagonal(so3.exp(so3.log(expected))), np.diagonal(expected))


def test_exp_has_no_entry_beyond_1_in_magnitude_at_and_near_pi():
    axes = sample_axes(2000)
    for theta in (np.pi, np.nextafter(np.pi, 0), np.pi - 1e-9, np.pi / 2):
        R = so3.exp(axes * theta)
        assert np.abs(R).max() <= 1.0, theta
        for i in range(0, len(axes), 97):
            assert np.abs(so3.exp(axes[i] * theta)).max() <= 1.0, (theta, i)


@settings(max_examples=300)
@given(unit_axes, st.sampled_from([np.pi / 2, 2 * np.pi / 3, np.pi]), st.integers(-2, 2))
def test_exp_has_no_entry_beyond_1_where_an_entry_is_exactly_1(axis, theta, ulps):
    # the 120° turn about (1, 1, 1) permutes the axes; π/2 and π put ±1 on many entries
    theta = theta + ulps * EPS * 4
    for w in (axis * theta, np.ones(3) / np.sqrt(3) * theta):
        assert np.abs(so3.exp(w)).max() <= 1.0
        assert np.abs(so3.exp(w[None])).max() <= 1.0


subnormal_rotvecs = st.lists(
    st.integers(-(2**12), 2**12).map(lambda k: k * 5e-324), min_size=3, max_size=3
).filter(lambda v: any(v))


@settings(max_examples=300)
@given(subnormal_rotvecs)
def test_axis_angle_of_a_subnormal_angle_returned_an_axis_of_length_1_118(w):
    # ‖v‖ rounded to a coarse subnormal: v / ‖v‖ had lengths such as 1.118 or 0.99
    R = so3.exp(np.array(w))
    for batch in (R, R[None], np.stack([R, np.eye(3)])):
        axis, _ = so3.axis_angle(batch)
        assert np.abs(np.linalg.norm(axis, axis=-1) - 1.0).max() <= 2 * EPS


def test_axis_angle_of_rotation_by_1e_323_about_111_is_the_unit_diagonal():
    R = so3.exp(np.full(3, 1e-323))
    for batch in (R, R[None]):
        axis, angle = so3.axis_angle(batch)
        assert np.allclose(axis, np.full(3, 3**-0.5), atol=2 * EPS, rtol=0)
        assert 0.0 < np.ravel(angle)[0] < 1e-322


# --- bad input ---------------------------------------------------------------------------


@pytest.mark.parametrize(
    "fn, arg, exc, pattern",
    [
        (so3.hat, [1, 2], ValueError, r"shape \(\.\.\., 3\).*got shape \(2,\)"),
        (so3.hat, "abc", TypeError, "array of real numbers"),
        (so3.hat, [1, None, 3], TypeError, "real numbers"),
        (so3.hat, [1, np.inf, 3], ValueError, "NaN or infinity"),
        (so3.hat, [1 + 2j, 0, 0], TypeError, "complex"),
        (so3.exp, [np.nan, 0, 0], ValueError, "NaN or infinity"),
        (so3.exp, [[1, 2], [3]], ValueError, "rectangular"),
        (so3.log, np.eye(2), ValueError, r"shape \(\.\.\., 3, 3\)"),
        (so3.log, [["a"] * 3] * 3, TypeError, "real numbers"),
        (so3.vee, np.ones(3), ValueError, r"shape \(\.\.\., 3, 3\)"),
        (so3.rot_z, "0.5", TypeError, "real numbers"),
        (so3.random_rotations, 2.5, TypeError, "integer"),
        (so3.random_rotations, -1, ValueError, ">= 0"),
    ],
)
def test_bad_input_gets_a_clear_error(fn, arg, exc, pattern):
    with pytest.raises(exc, match=pattern):
        fn(arg)


def test_tolerance_policy_is_the_single_default():
    import inspect

    for fn in (so3.vee, so3.log, so3.axis_angle, so3.is_rotation, so3.check_rotation):
        assert inspect.signature(fn).parameters["tol"].default is TOL
