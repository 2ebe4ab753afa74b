"""Tests of course_lib.euler: round trips for all 12 sequences x 2 conventions (hypothesis),
scipy's Rotation as the oracle on random and gimbal-lock inputs, the Euler-angle cases of
scipy's, pytransform3d's and spatialmath's test suites (named after their origin), bad seq.
"""

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from course_lib import euler, so3

EXTRINSIC = ["".join(p) for p in itertools.product("xyz", repeat=3) if p[0] != p[1] != p[2]]
SEQS = EXTRINSIC + [s.upper() for s in EXTRINSIC]
TAIT_BRYAN = [s for s in SEQS if s[0].lower() != s[2].lower()]
PROPER = [s for s in SEQS if s[0].lower() == s[2].lower()]
ROT = {"x": so3.rot_x, "y": so3.rot_y, "z": so3.rot_z}

angle = st.floats(-np.pi, np.pi)
middle_tb = st.floats(-np.pi / 2, np.pi / 2)
middle_proper = st.floats(0.0, np.pi)


def lock_distance(angles, seq):
    """How far the middle angle is from gimbal lock (radians)."""
    b = angles[..., 1]
    if seq in TAIT_BRYAN:
        return np.pi / 2 - np.abs(b)
    return np.minimum(np.abs(b), np.pi - np.abs(b))


def scipy_euler(R, seq):
    """scipy's angles, its gimbal-lock warning allowed (pytest turns warnings into errors)."""
    import warnings

    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", "Gimbal lock detected", UserWarning)
        return Rotation.from_matrix(R).as_euler(seq)


def test_there_are_12_sequences_in_2_conventions():
    assert len(SEQS) == 24 and len(TAIT_BRYAN) == len(PROPER) == 12


# --- the definition -------------------------------------------------------------------------


@pytest.mark.parametrize("seq", SEQS)
def test_to_matrix_is_the_product_of_the_three_turns(seq):
    a = np.array([0.3, -1.1, 2.5])
    turns = [ROT[c](t) for c, t in zip(seq.lower(), a)]
    expected = turns[0] @ turns[1] @ turns[2] if seq.isupper() else turns[2] @ turns[1] @ turns[0]
    assert np.abs(euler.to_matrix(a, seq) - expected).max() <= 1e-15


@pytest.mark.parametrize("seq", EXTRINSIC)
def test_intrinsic_is_extrinsic_with_the_order_reversed(seq):
    a = np.random.default_rng(0).uniform(-np.pi, np.pi, (50, 3))
    assert np.array_equal(euler.to_matrix(a, seq), euler.to_matrix(a[:, ::-1], seq[::-1].upper()))


# --- round trips: every sequence, both conventions --------------------------------------


@settings(max_examples=60)
@pytest.mark.parametrize("seq", SEQS)
@given(a=angle, b=middle_tb, c=angle, b_proper=middle_proper)
def test_round_trip_reproduces_R_and_the_angles(seq, a, b, c, b_proper):
    angles = np.array([a, b_proper if seq in PROPER else b, c])
    R = euler.to_matrix(angles, seq)
    back = euler.from_matrix(R, seq)
    assert np.abs(euler.to_matrix(back, seq) - R).max() <= 1e-14
    if lock_distance(angles, seq) > 1e-3 and np.abs(angles[[0, 2]]).max() < np.pi - 1e-9:
        # away from lock the angles are well conditioned (error ~ eps / distance)
        assert np.abs(back - angles).max() <= 1e-12


@pytest.mark.parametrize("seq", SEQS)
def test_from_matrix_ranges(seq):
    a = euler.from_matrix(so3.random_rotations(2000, seed=3), seq)
    assert np.abs(a[:, [0, 2]]).max() <= np.pi
    if seq in PROPER:
        assert a[:, 1].min() >= 0 and a[:, 1].max() <= np.pi
    else:
        assert np.abs(a[:, 1]).max() <= np.pi / 2


# --- scipy as the oracle ------------------------------------------------------------------


@pytest.mark.parametrize("seq", SEQS)
def test_from_matrix_agrees_with_scipy_within_1e14(seq):
    R = so3.random_rotations(5000, seed=7)
    ours, theirs = euler.from_matrix(R, seq), scipy_euler(R, seq)
    # both reproduce R; near lock the first and third angle are ill conditioned (an error
    # of eps in q moves them by eps / distance), so they are compared where it is > 0.05
    assert np.abs(euler.to_matrix(ours, seq) - R).max() <= 1e-14
    assert np.abs(Rotation.from_euler(seq, ours).as_matrix() - R).max() <= 1e-14
    far = lock_distance(theirs, seq) > 0.05
    assert far.mean() > 0.9
    assert np.abs(ours[far] - theirs[far]).max() <= 1e-14


@pytest.mark.parametrize("seq", SEQS)
def test_to_matrix_agrees_with_scipy_within_1e14(seq):
    a = np.random.default_rng(8).uniform(-4, 4, (5000, 3))
    assert np.abs(euler.to_matrix(a, seq) - Rotation.from_euler(seq, a).as_matrix()).max() <= 1e-14


@pytest.mark.parametrize("seq", SEQS)
def test_gimbal_lock_sets_the_third_angle_to_0_like_scipy(seq):
    locks = [np.pi / 2, -np.pi / 2] if seq in TAIT_BRYAN else [0.0, np.pi]
    rng = np.random.default_rng(9)
    for b in locks:
        angles = np.column_stack([rng.uniform(-3, 3, 50), np.full(50, b), rng.uniform(-3, 3, 50)])
        R = Rotation.from_euler(seq, angles).as_matrix()
        ours = euler.from_matrix(R, seq)
        assert np.array_equal(ours[:, 2], np.zeros(50)), (seq, b)
        assert np.abs(euler.to_matrix(ours, seq) - R).max() <= 1e-14
        assert np.abs(ours - scipy_euler(R, seq)).max() <= 1e-14
        for i in range(0, 50, 7):
            assert np.abs(euler.from_matrix(R[i], seq) - ours[i]).max() <= 1e-15  # math vs numpy


@pytest.mark.parametrize("seq", ["xyz", "ZXZ"])
def test_next_to_gimbal_lock_the_angles_still_reproduce_R_to_1e14(seq):
    # scipy declares lock within 1e-7 and then reproduces R only to about 1e-7; we declare it
    # within 1e-15 and keep solving the angles (Bernardes-Viollet stays accurate there)
    lock = np.pi / 2 if seq in TAIT_BRYAN else 0.0
    for offset in (1e-14, 1e-12, 1e-9, 1e-8, 1e-6):
        angles = np.array([0.7, lock - offset if lock else offset, -1.9])
        R = euler.to_matrix(angles, seq)
        back = euler.from_matrix(R, seq)
        assert np.abs(euler.to_matrix(back, seq) - R).max() <= 1e-14, offset
        assert back[2] != 0.0


def test_single_call_and_batch_agree_for_every_sequence():
    R = np.concatenate([so3.random_rotations(60, seed=4), [np.eye(3), np.diag([1.0, -1, -1])]])
    for seq in SEQS:
        batch = euler.from_matrix(R, seq)
        for i in range(len(R)):
            assert np.abs(euler.from_matrix(R[i], seq) - batch[i]).max() <= 1e-15, (seq, i)


# --- ported from scipy/spatial/transform/tests/test_rotation.py ----------------------------

DEG = np.pi / 180
SCIPY_ANGLES = np.array([[30, 60, 45], [30, 60, 30], [45, 30, 60]]) * DEG


def test_scipy_from_euler_single_rotation():
    assert np.allclose(euler.to_matrix([90 * DEG, 0, 0], "zxz"), so3.rot_z(np.pi / 2), atol=1e-15)


def test_scipy_from_euler_rotation_order():
    a = np.random.RandomState(0).randint(low=0, high=180, size=(6, 3)) * DEG
    assert np.allclose(euler.to_matrix(a, "xyz"), euler.to_matrix(a[:, ::-1], "ZYX"), atol=1e-16)


def test_scipy_from_euler_elementary_extrinsic_rotation():
    # scipy: from_euler('zx', [90, 90]); with three letters, the third turn is 0
    mat = euler.to_matrix([90 * DEG, 90 * DEG, 0.0], "zxy")
    assert np.allclose(mat, [[0, -1, 0], [0, 0, -1], [1, 0, 0]], atol=1e-12)


def test_scipy_from_euler_intrinsic_rotation_312():
    mat = euler.to_matrix(SCIPY_ANGLES, "ZXY")
    expected = [
        [
            [0.3061862, -0.25, 0.9185587],
            [0.8838835, 0.4330127, -0.1767767],
            [-0.3535534, 0.8660254, 0.3535534],
        ],  # noqa: E501
        [
            [0.5334936, -0.25, 0.8080127],
            [0.8080127, 0.4330127, -0.3995191],
            [-0.25, 0.8660254, 0.4330127],
        ],  # noqa: E501
        [
            [0.0473672, -0.6123725, 0.7891491],
            [0.6597396, 0.6123725, 0.4355958],
            [-0.75, 0.5, 0.4330127],
        ],  # noqa: E501
    ]
    assert np.allclose(mat, expected, atol=1e-7)


def test_scipy_from_euler_intrinsic_rotation_313():
    mat = euler.to_matrix(SCIPY_ANGLES, "ZXZ")
    expected = [
        [
            [0.43559574, -0.78914913, 0.4330127],
            [0.65973961, -0.04736717, -0.75],
            [0.61237244, 0.61237244, 0.5],
        ],  # noqa: E501
        [[0.625, -0.64951905, 0.4330127], [0.64951905, 0.125, -0.75], [0.4330127, 0.75, 0.5]],
        [
            [-0.1767767, -0.91855865, 0.35355339],
            [0.88388348, -0.30618622, -0.35355339],
            [0.4330127, 0.25, 0.8660254],
        ],  # noqa: E501
    ]
    assert np.allclose(mat, expected, atol=1e-8)


def test_scipy_from_euler_extrinsic_rotation_312():
    mat = euler.to_matrix(SCIPY_ANGLES, "zxy")
    expected = [
        [
            [0.91855865, 0.1767767, 0.35355339],
            [0.25, 0.4330127, -0.8660254],
            [-0.30618622, 0.88388348, 0.35355339],
        ],  # noqa: E501
        [
            [0.96650635, -0.0580127, 0.25],
            [0.25, 0.4330127, -0.8660254],
            [-0.0580127, 0.89951905, 0.4330127],
        ],  # noqa: E501
        [
            [0.65973961, -0.04736717, 0.75],
            [0.61237244, 0.61237244, -0.5],
            [-0.43559574, 0.78914913, 0.4330127],
        ],  # noqa: E501
    ]
    assert np.allclose(mat, expected, atol=1e-8)


def test_scipy_from_euler_extrinsic_rotation_313():
    mat = euler.to_matrix(SCIPY_ANGLES, "zxz")
    expected = [
        [
            [0.43559574, -0.65973961, 0.61237244],
            [0.78914913, -0.04736717, -0.61237244],
            [0.4330127, 0.75, 0.5],
        ],  # noqa: E501
        [[0.625, -0.64951905, 0.4330127], [0.64951905, 0.125, -0.75], [0.4330127, 0.75, 0.5]],
        [
            [-0.1767767, -0.88388348, 0.4330127],
            [0.91855865, -0.30618622, -0.25],
            [0.35355339, 0.35355339, 0.8660254],
        ],  # noqa: E501
    ]
    assert np.allclose(mat, expected, atol=1e-8)


def test_scipy_from_euler_array_like():
    R = so3.random_rotations(3, seed=123)
    a = euler.from_matrix(R, "xyz")
    assert np.allclose(euler.to_matrix(a.tolist(), "xyz"), R, atol=1e-15)
    assert np.allclose(euler.to_matrix(a[0].tolist(), "xyz"), R[0], atol=1e-15)


def _scipy_random_angles(proper):
    rnd = np.random.RandomState(0)
    n = 1000
    angles = np.empty((n, 3))
    angles[:, 0] = rnd.uniform(low=-np.pi, high=np.pi, size=(n,))
    if proper:
        angles[:, 1] = rnd.uniform(low=0, high=np.pi, size=(n,))
    else:
        angles[:, 1] = rnd.uniform(low=-np.pi / 2, high=np.pi / 2, size=(n,))
    angles[:, 2] = rnd.uniform(low=-np.pi, high=np.pi, size=(n,))
    return angles


@pytest.mark.parametrize("seq", TAIT_BRYAN)
def test_scipy_as_euler_asymmetric_axes(seq):
    angles = _scipy_random_angles(proper=False)
    back = euler.from_matrix(euler.to_matrix(angles, seq), seq)
    assert np.allclose(back, angles, atol=0, rtol=1e-12)
    error = back - angles
    assert np.all(np.abs(error.mean(axis=0)) < 1e-15)
    assert np.all(np.hypot(error.mean(axis=0), error.std(axis=0)) < 1e-14)


@pytest.mark.parametrize("seq", PROPER)
def test_scipy_as_euler_symmetric_axes(seq):
    angles = _scipy_random_angles(proper=True)
    back = euler.from_matrix(euler.to_matrix(angles, seq), seq)
    assert np.allclose(back, angles, atol=0, rtol=1.1e-13)
    error = back - angles
    assert np.all(np.abs(error.mean(axis=0)) < 1e-15)  # scipy: 1e-16 for its own from_euler
    assert np.all(np.hypot(error.mean(axis=0), error.std(axis=0)) < 1e-14)


@pytest.mark.parametrize("seq", TAIT_BRYAN)
def test_scipy_as_euler_degenerate_asymmetric_axes(seq):
    angles = np.array([[45, 90, 35], [35, -90, 20], [35, 90, 25], [25, -90, 15]]) * DEG
    R = euler.to_matrix(angles, seq)
    estimates = euler.from_matrix(R, seq)
    assert np.allclose(euler.to_matrix(estimates, seq), R, atol=1e-12)
    assert np.array_equal(estimates[:, 2], np.zeros(4))


@pytest.mark.parametrize("seq", PROPER)
def test_scipy_as_euler_degenerate_symmetric_axes(seq):
    angles = np.array([[15, 0, 60], [35, 0, 75], [60, 180, 35], [15, -180, 25]]) * DEG
    R = euler.to_matrix(angles, seq)
    estimates = euler.from_matrix(R, seq)
    assert np.allclose(euler.to_matrix(estimates, seq), R, atol=1e-12)
    assert np.array_equal(estimates[:, 2], np.zeros(4))


@pytest.mark.parametrize("ndim", range(1, 4))
def test_scipy_as_euler_nd_rotation(ndim):
    angles = np.array([0.0, 0, 90 * DEG]).reshape((1,) * (ndim - 1) + (3,))
    R = euler.to_matrix(angles, "xyz")
    assert R.shape == (1,) * (ndim - 1) + (3, 3)
    assert np.allclose(euler.from_matrix(R, "xyz"), angles, atol=1e-15)


# --- ported from pytransform3d/rotations/test/test_euler.py and test_quaternion.py ----------

# pytransform3d names a sequence by axis indices (i, j, k) and a flag; "extrinsic" there is
# our lower case, "intrinsic" our upper case
PT3D_AXES = [
    [0, 2, 0], [0, 1, 0], [1, 0, 1], [1, 2, 1], [2, 1, 2], [2, 0, 2],
    [0, 2, 1], [0, 1, 2], [1, 0, 2], [1, 2, 0], [2, 1, 0], [2, 0, 1],
]  # fmt: skip


def _pt3d_seq(ea, extrinsic):
    seq = "".join("xyz"[i] for i in ea)
    return seq if extrinsic else seq.upper()


def _pt3d_random_angles(rng, proper):
    e = rng.random(3)
    e[0] = 2.0 * np.pi * e[0] - np.pi
    e[1] = np.pi * e[1]
    e[2] = 2.0 * np.pi * e[2] - np.pi
    if not proper:
        e[1] -= np.pi / 2.0  # the middle Tait-Bryan angle in [-π/2, π/2]
    return e


def test_pytransform3d_general_matrix_euler_conversions():
    rng = np.random.default_rng(22)
    for ea in PT3D_AXES:
        for extrinsic in (False, True):
            seq = _pt3d_seq(ea, extrinsic)
            for _ in range(5):
                e = _pt3d_random_angles(rng, ea[0] == ea[2])
                R = euler.to_matrix(e, seq)
                e_R = euler.from_matrix(R, seq)
                assert np.allclose(e_R, e, atol=1e-12), seq
                assert np.allclose(euler.to_matrix(e_R, seq), R, atol=1e-15)


def test_pytransform3d_from_quaternion_singularities():
    rng = np.random.default_rng(32)
    for ea in PT3D_AXES:
        for extrinsic in (False, True):
            seq = _pt3d_seq(ea, extrinsic)
            proper = ea[0] == ea[2]
            for _ in range(5):
                e = _pt3d_random_angles(rng, proper)
                singular = (0.0, np.pi) if proper else (-np.pi / 2, np.pi / 2)
                for e[1] in singular:  # the first and the second singularity
                    R = euler.to_matrix(e, seq)
                    assert np.allclose(euler.to_matrix(euler.from_matrix(R, seq), seq), R,
                                       atol=1e-14), (seq, e)  # fmt: skip


def test_pytransform3d_norm_euler():
    # angles beyond the ranges come back inside them, with the same matrix
    rng = np.random.default_rng(94322)
    for ea in PT3D_AXES:
        seq = _pt3d_seq(ea, True)
        for _ in range(10):
            e = (np.pi + rng.random(3) * np.pi * 2.0) * np.sign(rng.standard_normal(3))
            R = euler.to_matrix(e, seq)
            e_norm = euler.from_matrix(R, seq)
            assert np.allclose(euler.to_matrix(e_norm, seq), R, atol=1e-14)
            assert not np.allclose(e, e_norm)
            assert np.abs(e_norm[[0, 2]]).max() <= np.pi
            if ea[0] == ea[2]:
                assert 0.0 <= e_norm[1] <= np.pi
            else:
                assert -0.5 * np.pi <= e_norm[1] <= 0.5 * np.pi


# --- ported from spatialmath-python tests/base/test_transforms3d.py ------------------------


def test_spatialmath_rpy2r():
    # spatialmath's rpy2r(roll, pitch, yaw, order) is R = rotz(yaw) roty(pitch) rotx(roll) for
    # order "zyx": extrinsic "xyz"; order "xyz" is rotx(0.3) roty(0.2) rotz(0.1): extrinsic
    # "zyx"; order "yxz" is roty(0.3) rotx(0.2) rotz(0.1): extrinsic "zxy"
    rpy = [0.1, 0.2, 0.3]
    R = so3.rot_z(0.3) @ so3.rot_y(0.2) @ so3.rot_x(0.1)
    assert np.allclose(euler.to_matrix(rpy, "xyz"), R, atol=1e-15)
    R = so3.rot_x(0.3) @ so3.rot_y(0.2) @ so3.rot_z(0.1)
    assert np.allclose(euler.to_matrix(rpy, "zyx"), R, atol=1e-15)
    R = so3.rot_y(0.3) @ so3.rot_x(0.2) @ so3.rot_z(0.1)
    assert np.allclose(euler.to_matrix(rpy, "zxy"), R, atol=1e-15)


def test_spatialmath_eul2r():
    R = so3.rot_z(0.1) @ so3.rot_y(0.2) @ so3.rot_z(0.3)
    assert np.allclose(euler.to_matrix([0.1, 0.2, 0.3], "ZYZ"), R, atol=1e-15)


@pytest.mark.parametrize("seq", ["xyz", "zyx", "zxy"])  # spatialmath's "zyx", "xyz", "yxz"
def test_spatialmath_tr2rpy(seq):
    rpy = np.array([0.1, 0.2, 0.3])
    assert np.allclose(euler.from_matrix(euler.to_matrix(rpy, seq), seq), rpy, atol=1e-15)
    corners = [[np.pi, 0, 0], [0, np.pi, 0], [0, 0, np.pi], [0, np.pi / 2, 0], [0, -np.pi / 2, 0]]
    for ang in corners:  # the last two: the singularity
        a = euler.to_matrix(ang, seq)
        assert np.allclose(euler.to_matrix(euler.from_matrix(a, seq), seq), a, atol=1e-15)


def test_spatialmath_tr2eul():
    eul = np.array([0.1, 0.2, 0.3])
    assert np.allclose(euler.from_matrix(euler.to_matrix(eul, "ZYZ"), "ZYZ"), eul, atol=1e-15)
    R = euler.to_matrix([0.1, 0, 0.3], "ZYZ")  # the singularity
    assert np.allclose(euler.to_matrix(euler.from_matrix(R, "ZYZ"), "ZYZ"), R, atol=1e-15)
    assert np.allclose(euler.from_matrix(R, "ZYZ"), [0.4, 0, 0], atol=1e-15)


# --- bad input ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "seq, exc, pattern",
    [
        ("xy", ValueError, "3 letters of x, y, z.*length 2"),
        ("xyzx", ValueError, "3 letters"),
        ("abc", ValueError, "3 letters of x, y, z"),
        ("xYz", ValueError, "all lower case .* or all upper case"),
        ("xxy", ValueError, "must not repeat an axis"),
        ("XYY", ValueError, "must not repeat an axis"),
        (None, TypeError, "seq must be a string"),
        (3, TypeError, "seq must be a string"),
    ],
)
def test_bad_seq_gets_a_clear_error(seq, exc, pattern):
    with pytest.raises(exc, match=pattern):
        euler.to_matrix([0.1, 0.2, 0.3], seq)
    with pytest.raises(exc, match=pattern):
        euler.from_matrix(np.eye(3), seq)


@pytest.mark.parametrize(
    "call, exc, pattern",
    [
        (lambda: euler.to_matrix([0.1, 0.2], "xyz"), ValueError, r"angles must have shape"),
        (lambda: euler.to_matrix([0.1, np.nan, 0], "xyz"), ValueError, "NaN or infinity"),
        (lambda: euler.to_matrix("abc", "xyz"), TypeError, "real numbers"),
        (lambda: euler.from_matrix(np.diag([1.0, 1, -1]), "xyz"), ValueError, "reflection"),
        (lambda: euler.from_matrix(np.eye(2), "xyz"), ValueError, r"shape \(\.\.\., 3, 3\)"),
        (lambda: euler.from_matrix(np.full((3, 3), np.inf), "xyz"), ValueError, "NaN or inf"),
    ],
)
def test_bad_angles_and_matrices_get_a_clear_error(call, exc, pattern):
    with pytest.raises(exc, match=pattern):
        call()


# --- adversarial: magnitudes, dtypes, layouts, empty batches --------------------------------

finite = st.floats(allow_nan=False, allow_infinity=False)


@settings(max_examples=200)
@given(st.lists(finite, min_size=9, max_size=9).map(lambda x: np.array(x).reshape(3, 3)))
def test_any_finite_matrix_gives_finite_angles_or_names_R(M):
    for seq in ("xyz", "ZXZ"):
        try:
            a = euler.from_matrix(M, seq)
        except ValueError as err:
            assert str(err).startswith("R "), str(err)
        else:
            assert np.all(np.isfinite(a))
            assert np.abs(euler.to_matrix(a, seq) - M).max() <= 1e-8  # M is a rotation


@given(st.lists(finite, min_size=3, max_size=3).map(np.array))
def test_any_finite_angles_give_a_rotation(angles):
    for seq in ("xyz", "ZXZ"):
        assert so3.is_rotation(euler.to_matrix(angles, seq))


def test_dtypes_layouts_and_empty_batches():
    R = so3.random_rotations(5, seed=2)
    a = euler.from_matrix(R, "ZYX")
    readonly = R.copy()
    readonly.flags.writeable = False
    for layout in (readonly, np.asfortranarray(R), R.tolist(), R[..., ::-1][..., ::-1]):
        assert np.array_equal(euler.from_matrix(layout, "ZYX"), a)
    assert np.array_equal(euler.from_matrix(np.eye(3, dtype=np.float32), "xyz"), np.zeros(3))
    assert np.array_equal(euler.to_matrix(np.zeros(3, dtype=np.int8), "xyz"), np.eye(3))
    assert euler.from_matrix(np.zeros((0, 3, 3)), "xyz").shape == (0, 3)
    assert euler.to_matrix(np.zeros((2, 0, 3)), "XYZ").shape == (2, 0, 3, 3)
    assert euler.from_matrix(np.broadcast_to(np.eye(3), (4, 2, 3, 3)), "zxz").shape == (4, 2, 3)


@settings(max_examples=200)
@given(st.tuples(*[st.floats(-10.0, 10.0)] * 3), st.sampled_from(SEQS))
def test_single_call_to_matrix_equals_the_batch_path(angles, seq):
    """Issue 36: one triple is computed on floats; it matches the batch path to an ulp or two
    (math's sin and cos against numpy's) and scipy to rounding."""
    one = euler.to_matrix(list(angles), seq)
    batch = euler.to_matrix(np.array([angles]), seq)[0]
    assert np.abs(one - batch).max() <= 4e-16
    assert np.abs(one - Rotation.from_euler(seq, angles).as_matrix()).max() <= 2e-15
