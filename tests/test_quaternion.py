"""Tests of course_lib.quaternion: identities (hypothesis), scipy's Rotation as the oracle on
random and edge inputs (scipy is scalar LAST: reordered here), the quaternion and slerp cases of
scipy's, pytransform3d's and spatialmath's test suites (named after their origin), bad input.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation, Slerp

from course_lib import TOL, so3
from course_lib import quaternion as Q

EPS = np.finfo(float).eps
WXYZ = [3, 0, 1, 2]  # scipy (x, y, z, w) -> ours (w, x, y, z)
XYZW = [1, 2, 3, 0]

coords = st.floats(-1.0, 1.0, allow_nan=False)
quats = (
    st.tuples(coords, coords, coords, coords)
    .map(np.array)
    .filter(lambda q: np.linalg.norm(q) > 1e-3)
    .map(lambda q: q / np.linalg.norm(q))
)
vectors = st.tuples(*[st.floats(-10.0, 10.0)] * 3).map(np.array)
fractions = st.floats(0.0, 1.0)


def scipy_quat(R):
    """scipy's canonical quaternion of R, reordered scalar first."""
    return Rotation.from_matrix(R).as_quat(canonical=True)[..., WXYZ]


def same_rotation(p, q, atol):
    """q or −q equals p within atol (elementwise), for every row."""
    d = np.minimum(np.abs(p - q).max(axis=-1), np.abs(p + q).max(axis=-1))
    return bool(np.all(d <= atol))


def random_quats(n, seed):
    q = np.random.default_rng(seed).standard_normal((n, 4))
    return q / np.linalg.norm(q, axis=-1, keepdims=True)


def edge_rotations():
    """Near and at 180°, tiny angles, the identity, coordinate axes, mixed-sign axes."""
    axes = np.random.default_rng(5).standard_normal((40, 3))
    axes = np.concatenate([axes, np.eye(3), [[1, -1, 0], [1, 1, -1e-9], [3, -4, 0]]])
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    out = [2.0 * np.einsum("ni,nj->nij", axes, axes) - np.eye(3)]  # exactly π
    for theta in (np.pi, np.pi - 1e-12, np.pi - 1e-6, 3.0, 1e-300, 1e-9, 0.0):
        out.append(so3.exp(axes * theta))
    return np.concatenate(out)


# --- identities -------------------------------------------------------------------------


@given(quats)
def test_q_and_minus_q_are_the_same_rotation(q):
    assert np.array_equal(Q.to_matrix(q), Q.to_matrix(-q))
    assert np.array_equal(Q.from_matrix(Q.to_matrix(-q)), Q.from_matrix(Q.to_matrix(q)))


@given(quats, quats)
def test_multiply_matches_the_matrix_product(p, q):
    assert np.abs(Q.to_matrix(Q.multiply(p, q)) - Q.to_matrix(p) @ Q.to_matrix(q)).max() < 1e-14


@given(quats, vectors)
def test_rotate_matches_to_matrix_times_v(q, v):
    assert np.abs(Q.rotate(q, v) - Q.to_matrix(q) @ v).max() <= 1e-14 * max(1, np.abs(v).max())


@given(quats, vectors)
def test_rotate_is_the_vector_part_of_q_v_qstar(q, v):
    # Q.multiply validates unit input: (0, v) is not unit, so use the unvalidated product
    qvq = Q._product(Q._product(q, np.r_[0.0, v]), Q.conjugate(q))
    scale = max(1.0, np.abs(v).max())
    assert abs(qvq[0]) <= 1e-14 * scale
    assert np.abs(qvq[1:] - Q.rotate(q, v)).max() <= 1e-14 * scale


@given(quats)
def test_conjugate_is_the_inverse(q):
    assert np.abs(Q.multiply(q, Q.conjugate(q)) - [1, 0, 0, 0]).max() <= 4 * EPS
    assert np.abs(Q.to_matrix(Q.conjugate(q)) - Q.to_matrix(q).T).max() <= 1e-15


@given(quats)
def test_matrix_round_trip_gives_the_canonical_quaternion(q):
    canonical = q if q[0] > 0 else -q
    q2 = Q.from_matrix(Q.to_matrix(q))
    assert q2[0] >= 0
    if abs(q[0]) > 1e-14:
        assert np.abs(q2 - canonical).max() <= 1e-14
    else:  # w below the rounding of R: R does not know its sign; w = 0 and x, y, z decide
        assert same_rotation(q2, q, 1e-14)
    assert np.abs(Q.to_matrix(q2) - Q.to_matrix(q)).max() <= 1e-14


@given(quats)
def test_axis_angle_round_trip(q):
    axis, angle = Q.to_axis_angle(q)
    assert 0.0 <= angle <= np.pi and abs(np.linalg.norm(axis) - 1) <= 2 * EPS
    assert same_rotation(Q.from_axis_angle(axis, angle), q, 1e-14)
    assert np.abs(so3.exp(axis, angle) - Q.to_matrix(q)).max() <= 1e-14


@settings(max_examples=200)
@given(quats, quats)
def test_slerp_endpoints(q0, q1):
    assert np.abs(Q.slerp(q0, q1, 0.0) - q0).max() <= 1e-15
    assert same_rotation(Q.slerp(q0, q1, 1.0), q1, 1e-14)


@settings(max_examples=200)
@given(quats, quats)
def test_slerp_has_constant_angular_speed(q0, q1):
    R = Q.to_matrix(Q.slerp(q0, q1, np.linspace(0.0, 1.0, 9)))
    steps = so3.angle_between(R[:-1], R[1:])
    total = so3.angle_between(R[0], R[-1])
    assert np.abs(steps - total / 8).max() <= 1e-13


@settings(max_examples=200)
@given(quats, quats, fractions)
def test_slerp_follows_the_geodesic_of_so3(q0, q1, t):
    # chapter 04's geodesic R0 exp(t log(R0ᵀ R1)), the shorter way round
    R0, R1 = Q.to_matrix(q0), Q.to_matrix(q1)
    geodesic = R0 @ so3.exp(t * so3.log(R0.T @ R1))
    if so3.angle_between(R0, R1) < np.pi - 1e-6:  # at π both ways round are geodesics
        assert np.abs(Q.to_matrix(Q.slerp(q0, q1, t)) - geodesic).max() <= 1e-13


# --- scipy as the oracle ------------------------------------------------------------------


def test_from_matrix_agrees_with_scipy_within_1e14_on_random_rotations():
    R = so3.random_rotations(20000, seed=11)
    q = Q.from_matrix(R)
    assert np.abs(q - scipy_quat(R)).max() <= 1e-14
    assert np.abs(np.linalg.norm(q, axis=-1) - 1).max() <= 2 * EPS


def test_from_matrix_agrees_with_scipy_near_and_at_180_degrees_up_to_sign():
    R = edge_rotations()
    q = Q.from_matrix(R)
    assert same_rotation(q, scipy_quat(R), 1e-14)
    assert np.all(q[:, 0] >= 0)
    assert np.abs(Q.to_matrix(q) - R).max() <= 1e-14


def test_from_matrix_single_call_and_batch_agree():
    R = np.concatenate([edge_rotations(), so3.random_rotations(200, seed=2)])
    q = Q.from_matrix(R)
    for i in range(len(R)):
        assert np.array_equal(Q.from_matrix(R[i]), q[i]), i


def test_to_matrix_multiply_rotate_agree_with_scipy():
    p, q = random_quats(5000, 1), random_quats(5000, 2)
    rp, rq = Rotation.from_quat(p[:, XYZW]), Rotation.from_quat(q[:, XYZW])
    assert np.abs(Q.to_matrix(q) - rq.as_matrix()).max() <= 1e-14
    assert np.abs(Q.multiply(p, q) - (rp * rq).as_quat()[:, WXYZ]).max() <= 1e-14
    v = np.random.default_rng(3).standard_normal((5000, 3))
    assert np.abs(Q.rotate(q, v) - rq.apply(v)).max() <= 1e-14
    assert np.abs(Q.conjugate(q) - rq.inv().as_quat()[:, WXYZ]).max() <= 2 * EPS


def test_axis_angle_agrees_with_scipy_rotvec():
    axes = np.random.default_rng(4).standard_normal((2000, 3))
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    angles = np.random.default_rng(5).uniform(0, np.pi, 2000)
    q = Q.from_axis_angle(axes, angles)
    r = Rotation.from_rotvec(axes * angles[:, None])
    assert np.abs(q - r.as_quat()[:, WXYZ]).max() <= 1e-15
    axis, angle = Q.to_axis_angle(q)
    assert np.abs(axis * angle[:, None] - r.as_rotvec()).max() <= 1e-14


def test_slerp_agrees_with_scipy_slerp():
    q0, q1 = random_quats(300, 6), random_quats(300, 7)
    t = np.linspace(0, 1, 7)
    for a, b in zip(q0, q1):
        ours = Q.slerp(a, b, t)
        theirs = Slerp([0, 1], Rotation.from_quat(np.stack([a, b])[:, XYZW]))(t)
        assert np.abs(Q.to_matrix(ours) - theirs.as_matrix()).max() <= 1e-14


def test_non_unit_quaternions_are_rejected_where_scipy_normalises():
    # scipy's from_quat([3, 4, 0, 0]) normalises silently; course_lib names the norm
    for fn in (Q.to_matrix, Q.conjugate, Q.to_axis_angle):
        with pytest.raises(ValueError, match=r"q must be a unit quaternion: ‖q‖ = 5"):
            fn([3.0, 4.0, 0.0, 0.0])


# --- ported from scipy/spatial/transform/tests/test_rotation.py ----------------------------


def test_scipy_generic_quat_matrix():
    x = np.array([[3.0, 4, 0, 0], [5, 12, 0, 0]])  # scalar last in scipy
    q = (x / np.array([[5.0], [13.0]]))[:, WXYZ]
    assert np.allclose(Q.to_matrix(q), Rotation.from_quat(x).as_matrix(), atol=1e-15)
    with pytest.raises(ValueError, match=r"‖q‖ = 13.*at batch index \(1,\)"):
        Q.to_matrix(x[:, WXYZ])  # scipy normalises; we refuse, naming the worst


@pytest.mark.parametrize("ndim", range(1, 6))
def test_scipy_from_single_nd_quaternion(ndim):
    x = np.array([3.0, 4, 0, 0]).reshape((1,) * (ndim - 1) + (4,)) / 5  # scalar last
    R = Q.to_matrix(x[..., WXYZ])
    assert R.shape == (1,) * (ndim - 1) + (3, 3)
    assert np.allclose(Q.from_matrix(R), x[..., WXYZ], rtol=1e-15, atol=1e-16)


def test_scipy_from_quat_scalar_first():
    assert np.allclose(Q.to_matrix([1, 0, 0, 0]), np.eye(3), rtol=1e-15, atol=1e-16)
    tiled = np.tile([1.0, 0, 0, 0], (10, 1))
    assert np.allclose(Q.to_matrix(tiled), np.tile(np.eye(3), (10, 1, 1)), rtol=1e-15, atol=1e-16)
    q = np.random.RandomState(0).randn(100, 4)
    q /= np.linalg.norm(q, axis=1)[:, None]
    expected = Rotation.from_quat(q, scalar_first=True).as_matrix()
    assert np.allclose(Q.to_matrix(q), expected, rtol=0, atol=1e-15)
    for i in range(0, 100, 9):
        assert np.allclose(Q.to_matrix(q[i]), expected[i], rtol=0, atol=1e-15)


def test_scipy_as_quat_scalar_first():
    from course_lib import euler

    assert np.array_equal(Q.from_matrix(euler.to_matrix(np.zeros(3), "xyz")), [1, 0, 0, 0])
    tiled = Q.from_matrix(euler.to_matrix(np.zeros((10, 3)), "xyz"))
    assert np.array_equal(tiled, np.tile([1.0, 0, 0, 0], (10, 1)))
    q = np.random.RandomState(0).randn(100, 4)
    q /= np.linalg.norm(q, axis=1)[:, None]
    r = Rotation.from_quat(q)  # scalar last
    expected = r.as_quat(canonical=True, scalar_first=True)
    assert np.allclose(Q.from_matrix(r.as_matrix()), expected, rtol=0, atol=1e-15)


def test_scipy_quat_canonical():
    # scipy's canonical=True: w >= 0, then the first non-zero of x, y, z positive
    for q_xyzw in ([0.0, 0, 0, -1], [-1.0, 0, 0, 0], [0.0, -1, 0, 0], [0.0, 0, -1, 0]):
        q = np.array(q_xyzw)[WXYZ]
        assert np.array_equal(Q.from_matrix(Q.to_matrix(q)), -q + 0.0)
    for q_xyzw in ([0.0, -0.1, 0, 0.9], [0.0, 0.0, -0.1, 0.9]):
        q = np.array(q_xyzw)[WXYZ] / np.linalg.norm(q_xyzw)
        assert np.allclose(Q.from_matrix(Q.to_matrix(q)), q, atol=1e-15)


def test_scipy_quat_double_to_canonical_single_cover():
    x = np.array([[-1.0, 0, 0, 0], [0, -1, 0, 0], [0, 0, -1, 0], [0, 0, 0, -1], [-1, -1, -1, -1]])
    x /= np.linalg.norm(x, axis=1, keepdims=True)
    expected = np.abs(x)[:, WXYZ]
    assert np.allclose(Q.from_matrix(Q.to_matrix(x[:, WXYZ])), expected, atol=1e-15)


def test_scipy_quat_double_cover():
    q = np.array([1.0, 1, 0, 0]) / np.sqrt(2)  # 90° about x, scalar first
    r3 = Q.multiply(q, Q.multiply(q, q))
    assert np.allclose(r3 * np.sqrt(2), [-1, 1, 0, 0], atol=1e-15)
    assert np.allclose(Q.conjugate(q) * np.sqrt(2), [1, -1, 0, 0])
    assert np.allclose(Q.conjugate(r3) * np.sqrt(2), [-1, -1, 0, 0], atol=1e-15)
    assert np.allclose(Q.multiply(q, Q.conjugate(q)), [1, 0, 0, 0], atol=2e-16)
    assert np.allclose(Q.multiply(q, r3), [-1, 0, 0, 0], atol=2e-16)
    assert np.allclose(Q.multiply(Q.conjugate(q), Q.conjugate(r3)), [-1, 0, 0, 0], atol=2e-16)


def test_scipy_zero_norms_from_quat():
    with pytest.raises(ValueError, match=r"‖q‖ = 0.*at batch index \(1,\)"):
        Q.to_matrix(np.array([[1.0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 1, 0]]))


def test_scipy_as_matrix_from_square_input():
    quats = np.array([[0, 0, 1, 1], [0, 1, 0, 1], [0, 0, 0, 1], [0, 0, 0, -1]]) / np.sqrt(
        [[2], [2], [1], [1]]
    )
    mat = Q.to_matrix(quats[:, WXYZ])
    assert mat.shape == (4, 3, 3)
    assert np.allclose(mat[0], [[0, -1, 0], [1, 0, 0], [0, 0, 1]], atol=1e-16)
    assert np.allclose(mat[1], [[0, 0, 1], [0, 1, 0], [-1, 0, 0]], atol=1e-16)
    assert np.array_equal(mat[2], np.eye(3)) and np.array_equal(mat[3], np.eye(3))


def test_scipy_as_matrix_from_generic_input():
    q = np.array([1.0, 2, 3, 4]) / np.sqrt(30)  # scalar last
    expected = np.array([[0.4, -2, 2.2], [2.8, 1, 0.4], [-1, 2, 2]]) / 3
    assert np.allclose(Q.to_matrix(q[WXYZ]), expected, atol=1e-15)


@pytest.mark.parametrize("ndim", range(1, 6))
def test_scipy_from_single_nd_matrix(ndim):
    mat = np.array([[0.0, 0, 1], [1, 0, 0], [0, 1, 0]]).reshape((1,) * (ndim - 1) + (3, 3))
    expected = np.full((1,) * (ndim - 1) + (4,), 0.5)
    assert np.allclose(Q.from_matrix(mat), expected, atol=1e-16)


def test_scipy_from_matrix_calculation():
    expected = np.array([1.0, 1, 6, 1])[WXYZ] / np.sqrt(39)
    mat = np.array(
        [
            [-0.8974359, -0.2564103, 0.3589744],
            [0.3589744, -0.8974359, 0.2564103],
            [0.2564103, 0.3589744, 0.8974359],
        ]
    )  # rounded to 7 digits: a rotation within 1e-6, not TOL
    assert np.allclose(Q.from_matrix(mat, tol=1e-6), expected, atol=1e-8)
    assert np.allclose(Q.from_matrix(mat[None], tol=1e-6), expected[None], atol=1e-8)
    with pytest.raises(ValueError, match="not a rotation"):
        Q.from_matrix(mat)


def test_scipy_matrix_calculation_pipeline():
    mat = so3.random_rotations(10, seed=0)
    assert np.allclose(Q.to_matrix(Q.from_matrix(mat)), mat, atol=1e-15)


def test_scipy_from_matrix_non_positive_determinant():
    # scipy: "Non-positive determinant"; here the rotation check says what failed
    mat = np.eye(3)
    mat[0, 0] = 0
    with pytest.raises(ValueError, match="not a rotation"):
        Q.from_matrix(mat)
    mat[0, 0] = -1
    with pytest.raises(ValueError, match="reflection"):
        Q.from_matrix(mat)


def test_scipy_from_matrix_array_like():
    R = so3.random_rotations(4, seed=123)
    assert np.array_equal(Q.from_matrix(R[0].tolist()), Q.from_matrix(R[0]))
    assert np.array_equal(Q.from_matrix(R.tolist()), Q.from_matrix(R))


def test_scipy_slerp():
    rnd = np.random.RandomState(0)
    key = rnd.uniform(size=(5, 4))
    key = (key / np.linalg.norm(key, axis=1, keepdims=True))[:, WXYZ]
    key = np.where(key[:, :1] < 0, -key, key)
    times = np.array([0, 0.5, 0.25, 1, 1.5, 2, 2.75, 3, 3.25, 3.60, 4])
    seg = np.minimum(times.astype(int), 3)
    q = Q.slerp(key[seg], key[seg + 1], times - seg)
    q = np.where(q[:, :1] < 0, -q, q)
    for i, k in ((0, 0), (3, 1), (5, 2), (7, 3), (10, 4)):  # the key frames, both ends
        assert np.allclose(q[i], key[k], atol=1e-15)
    cos1, cos2 = q[0] @ q[2], q[2] @ q[1]  # constant angular velocity
    assert np.isclose(cos1, cos2, rtol=1e-14)
    assert np.isclose(q[3] @ q[4], q[4] @ q[5], rtol=1e-14)
    assert np.isclose(q[1] @ q[3], 2 * cos1**2 - 1, rtol=1e-13)


def test_scipy_slerp_call_scalar_time():
    q0, q1 = Q.from_axis_angle([1, 0, 0], [0.0, np.radians(80)])
    delta = Q.multiply(
        Q.slerp(q0, q1, 0.25), Q.conjugate(Q.from_axis_angle([1, 0, 0], np.radians(20)))
    )
    assert Q.to_axis_angle(delta)[1] <= 1e-15


# --- ported from pytransform3d/rotations/test (test_quaternion, test_matrix, test_slerp,
# --- test_axis_angle) ---------------------------------------------------------------------

Q_ID, Q_I, Q_J, Q_K = np.eye(4)


def test_pytransform3d_concatenate_quaternions():
    rng = np.random.default_rng(0)
    for _ in range(5):
        (a1, t1), (a2, t2) = [(rng.standard_normal(3), rng.uniform(0, np.pi)) for _ in range(2)]
        q1 = Q.from_axis_angle(a1 / np.linalg.norm(a1), t1)
        q2 = Q.from_axis_angle(a2 / np.linalg.norm(a2), t2)
        R12 = Q.to_matrix(q1) @ Q.to_matrix(q2)
        assert same_rotation(Q.multiply(q1, q2), Q.from_matrix(R12), 1e-15)


def test_pytransform3d_concatenate_quaternions_list_array():
    assert np.array_equal(Q.multiply([1, 0, 0, 0], np.array([0, 0, 0, 1])), [0, 0, 0, 1])


def test_pytransform3d_quaternion_hamilton():
    q_ij = Q.multiply(Q_I, Q_J)
    assert np.array_equal(q_ij, Q_K)
    assert np.array_equal(Q.multiply(q_ij, Q_K), -Q_ID)


def test_pytransform3d_quaternion_rotation_consistent_with_multiplication():
    rng = np.random.default_rng(1)
    for _ in range(5):
        v, q = rng.standard_normal(3), random_quats(1, int(rng.integers(1000)))[0]
        qv = Q._product(q, Q._product(np.r_[0.0, v], Q.conjugate(q)))[1:]
        assert np.allclose(qv, Q.rotate(q, v), atol=1e-15)


def test_pytransform3d_quaternion_invert():
    q = np.array([0.58183503, -0.75119889, -0.24622332, 0.19116072])  # 8 digits: tol=1e-7
    assert np.allclose(Q.multiply(q, Q.conjugate(q, tol=1e-7), tol=1e-7), Q_ID, atol=1e-7)


def test_pytransform3d_matrix_from_quaternion_hamilton():
    R = Q.to_matrix(np.sqrt(0.5) * np.array([1, 0, 0, 1]))
    assert np.allclose(R, [[0, -1, 0], [1, 0, 0], [0, 0, 1]], atol=1e-16)


def test_pytransform3d_quaternion_from_matrix_180():
    for axis in np.eye(3):
        q = Q.from_axis_angle(axis, np.pi)
        assert np.allclose(Q.from_matrix(so3.exp(axis, np.pi)), q, atol=1e-16)
    with pytest.raises(ValueError, match="not a rotation"):
        Q.from_matrix([[0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, -1.0]])
    R = np.array([[-1.0, 0.0, 0.0], [0.0, 0.00000001, 1.0], [0.0, 1.0, -0.00000001]])
    assert np.allclose(Q.to_matrix(Q.from_matrix(R)), R, atol=1e-15)  # 180° about ≈ (0, 1, 1)


def test_pytransform3d_quaternion_from_matrix_180_not_axis_aligned():
    rng = np.random.default_rng(0)
    for _ in range(10):
        axis = rng.standard_normal(3)
        axis /= np.linalg.norm(axis)
        q = Q.from_axis_angle(axis, np.pi)
        assert same_rotation(Q.from_matrix(so3.exp(axis, np.pi)), q, 1e-15)


def test_pytransform3d_bug_198_half_turn_about_the_diagonal_of_xy():
    R = np.array([[0, 1, 0], [1, 0, 0], [0, 0, -1]], dtype=float)
    assert np.array_equal(Q.to_matrix(Q.from_matrix(R)), R)


def test_pytransform3d_conversions_matrix_quaternion():
    for q in random_quats(5, 0):
        R = Q.to_matrix(q)
        assert so3.is_rotation(R)
        q2 = Q.from_matrix(R)
        assert same_rotation(q, q2, 1e-15)
        assert np.allclose(Q.to_matrix(q2), R, atol=1e-15)


def test_pytransform3d_conversions_axis_angle_quaternion():
    axis, angle = Q.to_axis_angle([1, 0, 0, 0])
    assert angle == 0.0 and np.array_equal(axis, [0, 0, 1])  # pytransform3d says (1, 0, 0)
    assert np.array_equal(Q.from_axis_angle(axis, angle), [1, 0, 0, 0])
    rng = np.random.default_rng(0)
    for _ in range(5):
        a = rng.standard_normal(3)
        a /= np.linalg.norm(a)
        t = rng.uniform(0, np.pi)
        axis, angle = Q.to_axis_angle(Q.from_axis_angle(a, t))
        assert np.allclose(axis, a, atol=1e-15) and np.isclose(angle, t, rtol=1e-15)


def test_pytransform3d_quaternion_conventions():
    q_wxyz = np.array([1.0, 0.0, 0.0, 0.0])
    assert np.array_equal(q_wxyz[XYZW], [0, 0, 0, 1])
    assert np.array_equal(q_wxyz[XYZW][WXYZ], q_wxyz)


def test_pytransform3d_interpolate_quaternion_constant_steps():
    q1, q2 = random_quats(2, 0)
    R = Q.to_matrix(Q.slerp(q1, q2, np.linspace(0, 1, 10)))
    norms = np.linalg.norm(np.diff(R, axis=0), axis=(1, 2))
    assert np.allclose(norms, norms[0], atol=1e-14)


def test_pytransform3d_interpolate_quaternion_shortest_path():
    q1 = random_quats(1, 2323)[0]
    axis, angle = Q.to_axis_angle(q1)
    q2 = Q.from_axis_angle(axis, angle * 1.1)
    t = np.linspace(0, 1, 10)
    R = Q.to_matrix(Q.slerp(q1, q2, t))
    R_opposite = Q.to_matrix(Q.slerp(q1, -q2, t))  # slerp always takes the shorter arc
    assert np.allclose(R, R_opposite, atol=1e-15)
    length = so3.angle_between(R[:-1], R[1:]).sum()
    assert np.isclose(length, 0.1 * angle, rtol=1e-12)


def test_pytransform3d_interpolate_same_quaternion():
    q = random_quats(1, 42)[0]
    assert np.allclose(Q.slerp(q, q, np.linspace(0, 1, 3)), q, atol=1e-16)


def test_pytransform3d_interpolate_shortest_path_same_quaternion():
    q = random_quats(1, 8353)[0]
    assert np.allclose(Q.slerp(q, q, 0.5), q, atol=1e-16)
    for q in np.eye(4)[1:]:
        assert np.allclose(Q.slerp(q, -q, 0.5), q, atol=1e-16)


def test_pytransform3d_q_R_slerps():
    rng = np.random.default_rng(833234)
    for _ in range(20):
        q0, q1 = random_quats(2, int(rng.integers(10**6)))
        t = rng.random()
        R0, R1 = Q.to_matrix(q0), Q.to_matrix(q1)
        R_t = R0 @ so3.exp(t * so3.log(R0.T @ R1))  # pytransform3d's matrix_slerp
        assert np.allclose(Q.to_matrix(Q.slerp(q0, q1, t)), R_t, atol=1e-14)


# --- ported from spatialmath-python tests/base/test_quaternions.py --------------------------


def test_spatialmath_qqmul_of_unit_quaternions():
    # spatialmath: qqmul([1, 2, 3, 4], [5, 6, 7, 8]) = [-60, 12, 30, 24]; bilinear, so the
    # unit quaternions give it divided by the two norms
    p, q = np.array([1.0, 2, 3, 4]), np.array([5.0, 6, 7, 8])
    n = np.linalg.norm(p) * np.linalg.norm(q)
    out = Q.multiply(p / np.linalg.norm(p), q / np.linalg.norm(q))
    assert np.allclose(out, np.array([-60, 12, 30, 24]) / n, atol=1e-15)
    out = Q.multiply(p / np.linalg.norm(p), p / np.linalg.norm(p))
    assert np.allclose(out, np.array([-28, 4, 6, 8]) / 30, atol=1e-15)


def test_spatialmath_rotation():
    for axis, rot in zip(np.eye(3), (so3.rot_x, so3.rot_y, so3.rot_z)):
        assert np.allclose(Q.from_matrix(rot(np.pi)), np.r_[0.0, axis], atol=1e-15)
        assert np.allclose(Q.to_matrix(np.r_[0.0, axis]), rot(np.pi), atol=1e-15)
    assert np.array_equal(Q.rotate([0, 1, 0, 0], [0, 0, 1]), [0, 0, -1])
    q = Q.from_matrix(so3.rot_x(np.pi + 0.01))
    assert q[0] > 0 and same_rotation(q, Q.from_axis_angle([1, 0, 0], np.pi + 0.01), 1e-15)


def test_spatialmath_slerp():
    q1, q2 = np.array([0.0, 1, 0, 0]), np.array([0.0, 0, 1, 0])
    assert np.allclose(Q.slerp(q1, q2, 0), q1) and np.allclose(Q.slerp(q1, q2, 1), q2)
    assert np.allclose(Q.slerp([0, 1, 0, 0], [0, 0, 1, 0], 0.5), [0, 2**-0.5, 2**-0.5, 0])
    mid = Q.slerp(Q.from_matrix(so3.rot_x(-0.3)), Q.from_matrix(so3.rot_x(0.3)), 0.5)
    assert np.allclose(mid, [1, 0, 0, 0], atol=1e-16)
    mid = Q.slerp(Q.from_matrix(so3.rot_y(0.3)), Q.from_matrix(so3.rot_y(0.5)), 0.5)
    assert np.allclose(mid, Q.from_matrix(so3.rot_y(0.4)), atol=1e-16)


def test_spatialmath_r2q():
    s = np.sqrt(0.5)
    assert np.array_equal(Q.from_matrix(np.eye(3)), [1, 0, 0, 0])
    cases = [
        (so3.rot_x(np.pi / 2), [s, s, 0, 0]),
        (so3.rot_x(-np.pi / 2), [s, -s, 0, 0]),
        (so3.rot_y(np.pi / 2), [s, 0, s, 0]),
        (so3.rot_y(-np.pi / 2), [s, 0, -s, 0]),
        (so3.rot_z(np.pi / 2), [s, 0, 0, s]),
        (so3.rot_z(-np.pi / 2), [s, 0, 0, -s]),
        (np.array([[0.0, -1, 0], [-1, 0, 0], [0, 0, -1]]), [0, s, -s, 0]),  # github issue case
        (so3.rot_x(0.1), [9.987503e-01, 4.997917e-02, 0.0, 0.0]),
    ]
    for R, expected in cases:
        assert np.allclose(Q.from_matrix(R), expected, atol=1e-7), R
    # rot_x(±π) are 180° turns: spatialmath gives [0, 1, 0, 0]; rot_x(−π) has sin(−π) =
    # −1.2e-16 in it, so our canonical w >= 0 quaternion is (1.2e-16, −1, 0, 0), the same turn
    for rot in (so3.rot_x, so3.rot_y, so3.rot_z):
        for theta in (np.pi, -np.pi):
            q = Q.from_matrix(rot(theta))
            assert q[0] >= 0 and same_rotation(q, Q.from_matrix(rot(np.pi)), 1e-15)


def test_spatialmath_qangle():
    q1 = [1.0, 0, 0, 0]
    for q2 in ([2**-0.5, 0, 2**-0.5, 0], [2**-0.5, 2**-0.5, 0, 0]):
        relative = Q.multiply(Q.conjugate(q1), q2)
        assert np.isclose(Q.to_axis_angle(relative)[1], np.pi / 2, rtol=1e-15)


# --- ported from spatialmath-python tests/test_quaternion.py (UnitQuaternion) ----------------


def test_spatialmath_unitquaternion_canonic():
    c, s = np.cos(np.pi / 4), np.sin(np.pi / 4)
    assert np.array_equal(Q.from_matrix(so3.rot_x(0)), [1, 0, 0, 0])
    for axis, rot in zip(np.eye(3), (so3.rot_x, so3.rot_y, so3.rot_z)):
        assert np.allclose(Q.from_matrix(rot(np.pi / 2)), np.r_[c, s * axis], atol=1e-16)
        assert np.allclose(Q.from_matrix(rot(-np.pi / 2)), np.r_[c, -s * axis], atol=1e-16)
        for theta in (np.pi, -np.pi):  # qcompare accepts q or −q
            assert same_rotation(Q.from_matrix(rot(theta)), np.r_[0.0, axis], 1e-16)


def test_spatialmath_unitquaternion_interp():
    from course_lib import euler

    identity = np.array([1.0, 0, 0, 0])
    q = Q.from_matrix(euler.to_matrix([0.2, 0.3, 0.4], "xyz"))  # UnitQuaternion.RPY
    rx = Q.from_axis_angle([1, 0, 0], np.pi / 2)
    assert np.allclose(Q.slerp(identity, q, 0), identity)
    assert np.allclose(Q.slerp(identity, q, 1), q, atol=1e-16)
    half = Q.slerp(identity, q, 0.5)
    assert np.allclose(Q.multiply(half, half), q, atol=1e-15)
    assert Q.slerp(identity, rx, np.linspace(0, 1, 11)).shape == (11, 4)
    both = Q.slerp(q, rx, [0, 1])
    assert np.allclose(both, [q, rx], atol=1e-16)
    # the "shortest" case (commented out there): half way from Rx(0.9π) to Rx(−0.9π) is Rx(π)
    q1, q2 = Q.from_axis_angle([1, 0, 0], [0.9 * np.pi, -0.9 * np.pi])
    middle = Q.slerp(q1, q2, 0.5)
    assert same_rotation(middle, Q.from_axis_angle([1, 0, 0], np.pi), 1e-15)


# --- shapes, broadcasting, bad input ----------------------------------------------------


def test_functions_keep_and_broadcast_leading_axes():
    q = random_quats(24, 9).reshape(2, 3, 4, 4)
    R = Q.to_matrix(q)
    assert R.shape == (2, 3, 4, 3, 3)
    assert Q.from_matrix(R).shape == (2, 3, 4, 4)
    assert Q.multiply(q, q[0, 0, 0]).shape == (2, 3, 4, 4)
    assert Q.rotate(q, [1.0, 0, 0]).shape == (2, 3, 4, 3)
    assert Q.slerp(q[0, 0, 0], q[1, 0, 0], np.linspace(0, 1, 5)[:, None]).shape == (5, 1, 4)
    axis, angle = Q.to_axis_angle(q)
    assert axis.shape == (2, 3, 4, 3) and angle.shape == (2, 3, 4)
    assert Q.from_axis_angle([0, 0, 1], np.zeros((2, 5))).shape == (2, 5, 4)


@pytest.mark.parametrize(
    "call, exc, pattern",
    [
        (lambda: Q.to_matrix([1, 0, 0]), ValueError, r"shape \(\.\.\., 4\).*got shape \(3,\)"),
        (lambda: Q.to_matrix([1, 0, 0, np.nan]), ValueError, "NaN or infinity"),
        (lambda: Q.to_matrix([np.inf, 0, 0, 0]), ValueError, "NaN or infinity"),
        (lambda: Q.to_matrix([1, 1e-4, 0, 0]), ValueError, r"\|‖q‖ − 1\| = 5\.0e-09 > TOL"),
        (lambda: Q.multiply([1, 0, 0, 0], [2, 0, 0, 0]), ValueError, r"q must be a unit.*‖q‖ = 2"),
        (lambda: Q.multiply([0.5, 0, 0, 0], [1, 0, 0, 0]), ValueError, r"p must be a unit"),
        (lambda: Q.rotate([1, 0, 0, 0], [1, 2]), ValueError, r"v must have shape"),
        (lambda: Q.slerp([1, 0, 0, 0], [0, 1, 0, 0], np.nan), ValueError, "t contains NaN"),
        (lambda: Q.slerp([1, 0, 0, 0], [0, 2, 0, 0], 0.5), ValueError, "q1 must be a unit"),
        (lambda: Q.from_axis_angle([0, 0, 2], 1.0), ValueError, r"axis must be a unit vector"),
        (lambda: Q.from_matrix(2 * np.eye(3)), ValueError, "not a rotation"),
        (lambda: Q.from_matrix(np.full((3, 3), np.nan)), ValueError, "NaN or infinity"),
        (lambda: Q.to_matrix("wxyz"), TypeError, "real numbers"),
        (lambda: Q.conjugate([1 + 1j, 0, 0, 0]), TypeError, "complex"),
        (lambda: Q.multiply(np.eye(4)[:2], np.eye(4)[:3]), ValueError, "do not broadcast"),
    ],
)
def test_bad_input_gets_a_clear_error(call, exc, pattern):
    with pytest.raises(exc, match=pattern):
        call()


def test_a_quaternion_within_TOL_of_unit_is_accepted_and_normalised():
    q = np.array([1.0 + 0.9 * TOL, 0, 0, 0])
    assert np.array_equal(Q.to_matrix(q), np.eye(3))
    with pytest.raises(ValueError, match=r"‖q‖ = 1.*at batch index \(1,\)"):
        Q.to_matrix([[1, 0, 0, 0], [1 + 2 * TOL, 0, 0, 0]])


@given(quats)
def test_to_matrix_has_no_entry_beyond_1(q):
    assert np.abs(Q.to_matrix(q)).max() <= 1.0


def test_to_matrix_of_a_half_turn_about_the_yz_diagonal_has_no_entry_below_minus_1():
    # with 1 − 2(y² + z²), R_11 was −1.0000000000000004 for q = (0, 0, √½, √½)
    R = Q.to_matrix([0.0, 0.0, np.sqrt(0.5), np.sqrt(0.5)])
    assert R[0, 0] == -1.0 and np.abs(R).max() <= 1.0


# --- adversarial: magnitudes, dtypes, layouts, empty batches --------------------------------

finite = st.floats(allow_nan=False, allow_infinity=False)


def _finite_or_clear_error(fn, *args, names=("q", "R", "p", "v", "q0", "q1")):
    """fn(*args) gives finite numbers (no RuntimeWarning: pytest makes it an error) or a
    ValueError naming one of the arguments."""
    try:
        out = fn(*args)
    except ValueError as err:
        assert any(str(err).startswith(n + " ") for n in names), str(err)
        assert "nan" not in str(err).lower() or "NaN or infinity" in str(err)
        return None
    for value in out if isinstance(out, tuple) else (out,):
        assert np.all(np.isfinite(value)), (fn, args, value)
    return out


@given(st.lists(finite, min_size=4, max_size=4).map(np.array))
def test_any_finite_4_vector_gives_a_rotation_or_names_q(q):
    R = _finite_or_clear_error(Q.to_matrix, q)
    assert R is None or so3.is_rotation(R)
    for fn in (Q.conjugate, Q.to_axis_angle, lambda q: Q.multiply(q, q)):
        _finite_or_clear_error(fn, q)


@given(st.lists(finite, min_size=9, max_size=9).map(lambda x: np.array(x).reshape(3, 3)))
def test_any_finite_matrix_gives_a_unit_quaternion_or_names_R(M):
    q = _finite_or_clear_error(Q.from_matrix, M)
    assert q is None or abs(np.linalg.norm(q) - 1) <= 2 * EPS


@given(quats, st.lists(finite, min_size=3, max_size=3).map(np.array))
def test_rotate_keeps_the_length_of_every_finite_vector(q, v):
    # the partial sums overflowed for ‖v‖ near 1.8e308 (inf in a representable answer)
    out = _finite_or_clear_error(Q.rotate, q, v)
    big = np.abs(v).max()
    if out is None:  # refused: only where a rotated entry really passes 1.8e308
        assert np.linalg.norm(v / big) > 1.7e308 / big
    elif big > 0:
        assert abs(np.linalg.norm(out / big) - np.linalg.norm(v / big)) <= 1e-14


@pytest.mark.parametrize(
    "dtype", [np.float16, np.float32, np.longdouble, np.int8, np.int64, np.uint8]
)
def test_every_real_dtype_is_read_as_float64(dtype):
    assert np.array_equal(Q.from_matrix(np.eye(3, dtype=dtype)), [1, 0, 0, 0])
    assert np.array_equal(Q.to_matrix(np.array([1, 0, 0, 0], dtype=dtype)), np.eye(3))


def test_every_memory_layout_gives_the_same_result():
    R = so3.random_rotations(6, seed=1)
    q = Q.from_matrix(R)
    padded = np.zeros(R.shape + (2,))
    padded[..., 0] = R
    readonly = R.copy()
    readonly.flags.writeable = False
    layouts = [padded[..., 0], readonly, np.asfortranarray(R), R[..., ::-1][..., ::-1]]
    layouts += [np.ma.masked_array(R, mask=np.zeros(R.shape, bool)), R.tolist()]
    for layout in layouts:
        assert np.array_equal(Q.from_matrix(layout), q)
    assert np.array_equal(Q.to_matrix(np.asfortranarray(q)), Q.to_matrix(q))
    with pytest.raises(ValueError, match="masked array with 1 masked entry"):
        Q.to_matrix(np.ma.masked_array([1.0, 0, 0, 0], mask=[0, 1, 0, 0]))


def test_empty_batches_keep_their_shape():
    assert Q.from_matrix(np.zeros((0, 3, 3))).shape == (0, 4)
    assert Q.to_matrix(np.zeros((0, 4))).shape == (0, 3, 3)
    assert Q.multiply(np.zeros((0, 4)), [1, 0, 0, 0]).shape == (0, 4)
    assert Q.rotate(np.zeros((0, 4)), [1.0, 0, 0]).shape == (0, 3)
    assert Q.slerp(np.zeros((0, 4)), [1, 0, 0, 0], 0.5).shape == (0, 4)
    assert Q.to_axis_angle(np.zeros((0, 4)))[1].shape == (0,)
    assert Q.from_axis_angle(np.zeros((0, 3)), 1.0).shape == (0, 4)


# The single-call paths (issue 36: one call at most scipy's time) compute on Python floats; they
# must give what the batch path gives for the same quaternion, and leave every error to it.


@settings(max_examples=300)
@given(quats, quats, vectors)
def test_single_calls_equal_the_batch_path_bit_for_bit(p, q, v):
    assert np.array_equal(Q.to_matrix(q), Q.to_matrix(q[None])[0])
    assert np.array_equal(Q.multiply(p, q), Q.multiply(p[None], q[None])[0])
    assert np.array_equal(Q.rotate(q, v), Q.rotate(q[None], v[None])[0])
    assert np.array_equal(Q.to_matrix(list(q)), Q.to_matrix(q))


@settings(max_examples=300)
@given(quats, quats, st.floats(-2.0, 3.0))
def test_single_slerp_equals_the_batch_path(p, q, t):
    one, batch = Q.slerp(p, q, t), Q.slerp(p[None], q[None], np.array([t]))[0]
    assert np.abs(one - batch).max() <= 4 * EPS  # math's sin and numpy's may differ by an ulp


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: Q.to_matrix([1.0, 1.0, 0.0, 0.0]), "must be a unit quaternion"),
        (lambda: Q.to_matrix([1.0, float("nan"), 0.0, 0.0]), "NaN"),
        (lambda: Q.multiply([1, 0, 0, 0], [2, 0, 0, 0]), "q must be a unit quaternion"),
        (lambda: Q.rotate(Q.from_axis_angle([0, 0, 1], np.pi / 4), [1.7e308] * 3), "too long"),
        (lambda: Q.slerp([1, 0, 0, 0], [0, 1, 0, 0], float("inf")), "t"),
        (lambda: Q.to_matrix([1, 0, 0, 0], tol=-1.0), "tol"),
    ],
)
def test_bad_single_calls_get_the_batch_paths_message(call, message):
    with pytest.raises(ValueError, match=message):
        call()
