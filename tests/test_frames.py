"""Tests of course_lib.frames: frames, coordinates by projection, R_ab from axes, v_a = R_ab v_b."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib import so3
from course_lib.frames import (
    change_frame,
    check_frame,
    coordinates,
    frame_from_vectors,
    is_orthonormal,
    is_right_handed,
    rotation_from_axes,
)
from course_lib.tolerance import TOL

S = 1 / np.sqrt(2)
R_AC = [[S, -S, 0], [S, S, 0], [0, 0, 1]]  # eq. (28) / eq. (65): 45° about z

finite = st.floats(-1.0, 1.0, allow_nan=False, allow_infinity=False)
vectors = st.tuples(*[st.floats(-100.0, 100.0, allow_nan=False, allow_infinity=False)] * 3)


def quaternion_rotation(q):
    """Rotation matrix of a (not necessarily unit) quaternion, built independently of so3."""
    w, x, y, z = np.asarray(q, dtype=float) / np.linalg.norm(q)
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )


quaternions = st.tuples(finite, finite, finite, finite).filter(lambda q: np.linalg.norm(q) > 0.1)


# ------------------------------------------------------------------ the notes' examples


def test_rotation_from_axes_eq27_is_180_degrees_about_y():
    R_ab = rotation_from_axes([-1, 0, 0], [0, 1, 0], [0, 0, -1])
    assert R_ab.dtype == np.float64
    assert np.allclose(R_ab, np.diag([-1.0, 1.0, -1.0]), atol=TOL)
    assert np.linalg.norm(R_ab - so3.rot_y(np.pi)) <= TOL
    # the axis of rotation (y) is the unchanged column
    assert np.array_equal(R_ab[:, 1], [0.0, 1.0, 0.0])


def test_rotation_from_axes_eq28_is_45_degrees_about_z():
    R_ac = rotation_from_axes([S, S, 0], [-S, S, 0], [0, 0, 1])
    assert np.linalg.norm(R_ac - np.array(R_AC)) <= TOL
    assert np.linalg.norm(R_ac - so3.rot_z(np.pi / 4)) <= TOL
    assert np.array_equal(R_ac[:, 2], [0.0, 0.0, 1.0])


def test_rotation_from_axes_stacks_axes_as_columns():
    x, y, z = so3.rot_x(0.3) @ so3.rot_z(1.1)  # rows; take them as axes of some frame
    R = rotation_from_axes(x, y, z)
    assert np.array_equal(R[:, 0], x) and np.array_equal(R[:, 1], y) and np.array_equal(R[:, 2], z)


def test_change_frame_notes_example_eq65_to_eq68():
    v_a = change_frame(R_AC, [1, 1, 3])
    assert v_a.dtype == np.float64 and v_a.shape == (3,)
    assert np.linalg.norm(v_a - np.array([0.0, np.sqrt(2.0), 3.0])) <= TOL
    assert (
        np.linalg.norm(v_a - np.array([0.0, 2 / np.sqrt(2.0), 3.0])) <= TOL
    )  # eq. (68) as printed


def test_change_frame_is_the_combination_of_body_axes_eq62():
    R = so3.rot_x(0.4) @ so3.rot_y(-1.2)
    v_b = np.array([0.3, -2.0, 1.5])
    by_axes = v_b[0] * R[:, 0] + v_b[1] * R[:, 1] + v_b[2] * R[:, 2]
    assert np.linalg.norm(change_frame(R, v_b) - by_axes) <= TOL


def test_coordinates_are_projections_eqs_3_to_5():
    frame = so3.rot_y(0.7) @ so3.rot_z(-0.2)
    p = np.array([1.5, -0.5, 2.0])
    c = coordinates(p, frame)
    assert c.shape == (3,)
    for i in range(3):
        assert abs(c[i] - p @ frame[:, i]) <= TOL


def test_coordinates_in_standard_frame_are_the_point_itself():
    p = np.array([3.0, -4.0, 12.0])
    assert np.array_equal(coordinates(p, np.eye(3)), p)


def test_coordinates_uses_columns_not_rows():
    # Frame C of eq. (28): p = x_ac has coordinates (1, 0, 0) in C; multiplying by the frame
    # (projecting on its rows) instead of its transpose would give (0, 1, 0).
    x_ac = np.array(R_AC)[:, 0]
    assert np.linalg.norm(coordinates(x_ac, R_AC) - np.array([1.0, 0.0, 0.0])) <= TOL
    assert np.linalg.norm(np.array(R_AC) @ x_ac - np.array([1.0, 0.0, 0.0])) > 0.1


# ------------------------------------------------------------------ batching


def test_change_frame_batched_matches_loop_and_broadcasts():
    Rs = so3.random_rotations(5, seed=1)
    vs = np.random.default_rng(2).standard_normal((5, 3))
    batched = change_frame(Rs, vs)
    assert batched.shape == (5, 3)
    for R, v, out in zip(Rs, vs, batched):
        assert np.linalg.norm(out - R @ v) <= TOL
    one_R_many_v = change_frame(Rs[0], vs)
    assert one_R_many_v.shape == (5, 3)
    assert np.linalg.norm(one_R_many_v - vs @ Rs[0].T) <= TOL


def test_coordinates_batched_matches_loop():
    frames = so3.random_rotations(4, seed=3)
    ps = np.random.default_rng(4).standard_normal((4, 3))
    out = coordinates(ps, frames)
    assert out.shape == (4, 3)
    for F, p, c in zip(frames, ps, out):
        assert np.linalg.norm(c - F.T @ p) <= TOL


def test_frame_from_vectors_broadcasts_batches():
    e1 = np.tile([1.0, 0.0, 0.0], (4, 1))
    F = frame_from_vectors(e1, [0, 1, 0], [0, 0, 1])
    assert F.shape == (4, 3, 3)
    assert all(np.array_equal(f, np.eye(3)) for f in F)


def test_predicates_return_python_bool_for_one_frame_and_arrays_for_batches():
    assert is_orthonormal(np.eye(3)) is True
    assert is_right_handed(np.eye(3)) is True
    stack = np.stack([np.eye(3), np.diag([1.0, 1.0, -1.0]), 2 * np.eye(3)])
    assert is_orthonormal(stack).tolist() == [True, True, False]
    assert is_right_handed(stack).tolist() == [True, False, False]
    assert is_orthonormal(np.broadcast_to(np.eye(3), (2, 5, 3, 3))).shape == (2, 5)


def test_rotation_from_axes_batched_and_check_frame_returns_the_frame():
    Rs = so3.random_rotations(3, seed=5)
    R = rotation_from_axes(Rs[..., 0], Rs[..., 1], Rs[..., 2])
    assert R.shape == (3, 3, 3) and np.array_equal(R, Rs)
    out = check_frame(Rs.tolist())
    assert out.dtype == np.float64 and np.array_equal(out, Rs)


# ------------------------------------------------------------------ properties


@settings(deadline=None)
@given(quaternions, vectors)
def test_coordinates_of_frame_times_c_recover_c(q, c):
    frame = quaternion_rotation(q)
    c = np.array(c)
    assert np.linalg.norm(coordinates(frame @ c, frame) - c) <= TOL


@settings(deadline=None)
@given(quaternions, vectors, vectors)
def test_coordinates_from_a_frame_origin_recover_c(q, c, o):
    # p = o + c_1 e_1 + c_2 e_2 + c_3 e_3 has coordinates c in the frame with origin o
    frame, c, o = quaternion_rotation(q), np.array(c), np.array(o)
    p = o + frame @ c
    assert np.linalg.norm(coordinates(p, frame, origin=o) - c) <= TOL
    # ... and they are the projections of the free vector p − o, not of the point p
    assert np.linalg.norm(coordinates(p, frame, origin=o) - coordinates(p - o, frame)) <= TOL


@settings(deadline=None)
@given(quaternions, vectors)
def test_change_frame_preserves_length_and_coordinates_undo_it(q, v):
    R = quaternion_rotation(q)
    v = np.array(v)
    v_a = change_frame(R, v)
    assert abs(np.linalg.norm(v_a) - np.linalg.norm(v)) <= TOL
    assert np.linalg.norm(coordinates(v_a, R) - v) <= TOL


@settings(deadline=None)
@given(quaternions)
def test_rotation_columns_are_orthonormal_right_handed_frames(q):
    R = quaternion_rotation(q)
    assert is_orthonormal(R) and is_right_handed(R)
    assert np.array_equal(rotation_from_axes(R[:, 0], R[:, 1], R[:, 2]), R)
    # swapping two axes gives a left-handed frame, refused with the reason
    assert not is_right_handed(R[:, [1, 0, 2]])
    with pytest.raises(ValueError, match="left-handed"):
        check_frame(R[:, [1, 0, 2]])


# ------------------------------------------------------------------ failure messages


def test_check_frame_names_the_non_unit_vector_and_by_how_much():
    with pytest.raises(ValueError) as info:
        check_frame(frame_from_vectors([1, 0, 0], [0, 2, 0], [0, 0, 1]))
    msg = str(info.value)
    assert "not orthonormal" in msg and "e2 is not a unit vector" in msg
    assert "‖e2‖ = 2" in msg and "1.0e+00" in msg
    assert "e1 is not" not in msg and "e3 is not" not in msg
    assert "TOL = 1e-09" in msg and "divide it by its length" in msg


def test_check_frame_names_the_non_orthogonal_pair_and_the_dot_product():
    e2 = np.array([0.6, 0.8, 0.0])  # unit, but e1 · e2 = 0.6
    with pytest.raises(ValueError) as info:
        check_frame(frame_from_vectors([1, 0, 0], e2, np.cross([1, 0, 0], e2) / 0.8))
    msg = str(info.value)
    assert "e1 and e2 are not orthogonal" in msg and "e1 · e2 = 6.0e-01" in msg
    assert "Gram-Schmidt" in msg


def test_check_frame_left_handed_says_e1_cross_e2_is_minus_e3():
    with pytest.raises(ValueError) as info:
        check_frame(frame_from_vectors([1, 0, 0], [0, 1, 0], [0, 0, -1]))
    msg = str(info.value)
    assert "left-handed" in msg and "e1 × e2 = −e3" in msg and "2.0e+00" in msg
    assert "negate one basis vector" in msg


def test_check_frame_names_the_first_failing_frame_of_a_batch():
    stack = np.stack([np.eye(3), np.eye(3), np.diag([1.0, 1.0, -1.0]), 3 * np.eye(3)])
    with pytest.raises(ValueError, match=r"frame\[2\] \(2 of 4 frames fail\).*left-handed"):
        check_frame(stack)


def test_rotation_from_axes_left_handed_axes_get_a_clear_error():
    with pytest.raises(ValueError) as info:
        rotation_from_axes([1, 0, 0], [0, 1, 0], [0, 0, -1])
    msg = str(info.value)
    assert "do not form a rotation matrix" in msg
    assert "x_ab × y_ab = −z_ab" in msg and "det(R_ab) = -1" in msg


def test_rotation_from_axes_non_unit_axis_names_it_and_the_size():
    with pytest.raises(ValueError) as info:
        rotation_from_axes([1, 0, 0], [0, 1.1, 0], [0, 0, 1])
    msg = str(info.value)
    assert "y_ab is not a unit vector" in msg and "‖y_ab‖ = 1.1" in msg and "1.0e-01" in msg


def test_rotation_from_axes_refuses_sheared_axes():
    with pytest.raises(ValueError, match="x_ab and y_ab are not orthogonal"):
        rotation_from_axes([1, 0, 0], [S, S, 0], [0, 0, 1])


def test_change_frame_refuses_a_reflection():
    with pytest.raises(ValueError, match=r"R_ab is a reflection.*det\(R_ab\) = -1"):
        change_frame(np.diag([1.0, -1.0, 1.0]), [1, 2, 3])


# ------------------------------------------------------------------ tolerance policy


def test_rounded_frames_pass_within_TOL_and_fail_beyond_it():
    tiny = np.eye(3) + 1e-13 * np.array([[0, 1, 0], [0, 0, 0], [0, 0, 0]])
    assert is_orthonormal(tiny) and is_right_handed(tiny)
    assert check_frame(tiny) is not None
    off = np.eye(3) + 1e-6 * np.array([[0, 1, 0], [0, 0, 0], [0, 0, 0]])
    assert not is_orthonormal(off)
    assert is_orthonormal(off, tol=1e-5)
    check_frame(off, tol=1e-5)
    with pytest.raises(ValueError, match=r"‖FᵀF − I‖ = 1\.4e-06 > TOL = 1e-09"):
        check_frame(off)
    with pytest.raises(ValueError, match=r"> tol = 1e-07"):
        check_frame(off, tol=1e-7)


def test_notes_rounded_entries_of_eq28_pass():
    rounded = np.round(np.array(R_AC), 10)  # 0.7071067812, as typed by hand
    assert is_orthonormal(rounded) and is_right_handed(rounded)


@pytest.mark.parametrize(
    "tol, exc",
    [(-1e-9, ValueError), (float("nan"), ValueError), ("1e-9", TypeError), (True, TypeError)],
)
def test_bad_tol_is_refused(tol, exc):
    with pytest.raises(exc, match="tol must be"):
        is_orthonormal(np.eye(3), tol=tol)


# ------------------------------------------------------------------ bad input


@pytest.mark.parametrize("func", [is_orthonormal, is_right_handed, check_frame])
def test_frame_checks_refuse_nan(func):
    frame = np.eye(3)
    frame[1, 2] = np.nan
    with pytest.raises(ValueError, match=r"frame contains NaN or infinity.*\(1, 2\)"):
        func(frame)


@pytest.mark.parametrize("func", [is_orthonormal, is_right_handed, check_frame])
@pytest.mark.parametrize("shape", [(3,), (3, 2), (2, 3, 4), (4, 4)])
def test_frame_checks_refuse_wrong_shapes(func, shape):
    with pytest.raises(ValueError, match=r"frame must have shape \(\.\.\., 3, 3\)"):
        func(np.zeros(shape))


@pytest.mark.parametrize("bad", ["eye", None, [["a", "b", "c"]] * 3, np.eye(3) * 1j, {"x": 1}])
def test_frame_checks_refuse_non_numeric(bad):
    with pytest.raises(TypeError, match="frame must be"):
        check_frame(bad)


def test_ragged_frame_is_a_value_error():
    with pytest.raises(ValueError, match="rectangular"):
        check_frame([[1, 0, 0], [0, 1], [0, 0, 1]])


def test_frame_from_vectors_refuses_bad_vectors():
    with pytest.raises(ValueError, match=r"e2 must have shape \(\.\.\., 3\)"):
        frame_from_vectors([1, 0, 0], [0, 1], [0, 0, 1])
    with pytest.raises(
        ValueError, match=r"do not broadcast: e1 has shape \(2, 3\) .*e2 has shape \(5, 3\)"
    ):
        frame_from_vectors(np.zeros((2, 3)), np.zeros((5, 3)), [0, 0, 1])
    with pytest.raises(ValueError, match="e3 contains NaN"):
        frame_from_vectors([1, 0, 0], [0, 1, 0], [0, 0, np.inf])
    with pytest.raises(TypeError, match="e1 must be"):
        frame_from_vectors("x", [0, 1, 0], [0, 0, 1])


def test_coordinates_default_origin_is_the_reference_origin():
    p = np.array([0.3, -1.2, 2.0])
    frame = so3.rot_z(0.4) @ so3.rot_x(-0.7)
    assert np.array_equal(coordinates(p, frame), coordinates(p, frame, origin=(0, 0, 0)))


def test_coordinates_with_origin_are_the_notes_point_seen_from_frame_b():
    # notebook 01: a point and a frame B with another origin; projecting the point itself
    # (eqs. 3-5 read literally) does not rebuild it, projecting p − o_B does
    o_b = np.array([1.2, 0.3, -0.3])
    R_b = so3.rot_z(np.pi / 3) @ so3.rot_x(-np.pi / 6)
    p = np.array([0.9, 0.9, 1.0])
    p_b = coordinates(p, R_b, origin=o_b)
    assert np.linalg.norm(o_b + R_b @ p_b - p) <= TOL
    naive = coordinates(p, R_b)
    assert np.linalg.norm(o_b + R_b @ naive - p) > 0.1


def test_coordinates_with_origin_broadcast_over_batches():
    frames = so3.random_rotations(4, seed=5)
    origins = np.random.default_rng(6).standard_normal((4, 3))
    p = np.array([1.0, 2.0, 3.0])
    out = coordinates(p, frames, origin=origins)
    assert out.shape == (4, 3)
    for k in range(4):
        assert np.linalg.norm(out[k] - frames[k].T @ (p - origins[k])) <= TOL
    one_origin = coordinates(np.eye(3), np.eye(3), origin=[1.0, 1.0, 1.0])
    assert np.array_equal(one_origin, np.eye(3) - 1.0)


def test_coordinates_refuses_bad_origins():
    with pytest.raises(ValueError, match=r"origin must have shape \(\.\.\., 3\)"):
        coordinates([1, 2, 3], np.eye(3), origin=[0, 0])
    with pytest.raises(ValueError, match="origin contains NaN"):
        coordinates([1, 2, 3], np.eye(3), origin=[0, np.inf, 0])
    with pytest.raises(TypeError, match="origin must be an array of real numbers"):
        coordinates([1, 2, 3], np.eye(3), origin="o_B")
    with pytest.raises(
        ValueError, match=r"do not broadcast: p has shape \(2, 3\) .*origin has shape \(3, 3\)"
    ):
        coordinates(np.zeros((2, 3)), np.eye(3), origin=np.zeros((3, 3)))


def test_coordinates_refuses_bad_points_and_frames():
    with pytest.raises(ValueError, match=r"p must have shape \(\.\.\., 3\)"):
        coordinates([1, 2], np.eye(3))
    with pytest.raises(ValueError, match="p contains NaN"):
        coordinates([1, np.nan, 2], np.eye(3))
    with pytest.raises(ValueError, match="not orthonormal"):
        coordinates([1, 2, 3], 2 * np.eye(3))
    with pytest.raises(
        ValueError, match=r"do not broadcast: p has shape \(2, 3\) .*frame has shape \(3, 3, 3\)"
    ):
        coordinates(np.zeros((2, 3)), so3.random_rotations(3, seed=0))


def test_change_frame_refuses_bad_input():
    with pytest.raises(ValueError, match=r"v_b must have shape \(\.\.\., 3\)"):
        change_frame(np.eye(3), [1, 2, 3, 4])
    with pytest.raises(TypeError, match="v_b must be"):
        change_frame(np.eye(3), ["1", "2", "3"])
    with pytest.raises(ValueError, match="R_ab"):
        change_frame(np.eye(2), [1, 2, 3])
    with pytest.raises(
        ValueError, match=r"do not broadcast: R_ab has shape \(2, 3, 3\) .*v_b has shape \(3, 3\)"
    ):
        change_frame(so3.random_rotations(2, seed=0), np.zeros((3, 3)))


def test_rotation_from_axes_refuses_bad_shapes():
    with pytest.raises(ValueError, match=r"z_ab must have shape \(\.\.\., 3\)"):
        rotation_from_axes([1, 0, 0], [0, 1, 0], [0, 1])
    with pytest.raises(
        ValueError, match=r"do not broadcast: x_ab has shape \(2, 3\) .*y_ab has shape \(3, 3\)"
    ):
        rotation_from_axes(np.zeros((2, 3)), np.zeros((3, 3)), [0, 0, 1])


def test_single_and_many_vector_paths_equal_the_batch_path():
    """Issue 36: one rotation and one vector on floats, one rotation and many vectors as
    chunked matrix products; both give what the broadcast product gives."""
    rng = np.random.default_rng(36)
    R = so3.random_rotations(1, seed=3)[0]
    V = rng.standard_normal((40_000, 3)) * 10.0
    many = change_frame(R, V)
    batch = change_frame(np.broadcast_to(R, (len(V), 3, 3)), V)
    assert np.abs(many - batch).max() <= 1e-14
    for v in V[:50]:
        assert np.abs(change_frame(R, v) - change_frame(R[None], v[None])[0]).max() <= 1e-14
    assert change_frame(R, V.reshape(200, 200, 3)).shape == (200, 200, 3)


@pytest.mark.parametrize(
    ("R", "v", "message"),
    [
        (np.diag([1.0, 1.0, -1.0]), np.ones(3), "reflection"),
        (np.eye(3), np.array([1.0, np.nan, 0.0]), "NaN"),
        (so3.rot_z(np.pi / 4), np.array([[1.7e308, 1.7e308, 0.0]] * 3), "overflows"),
        (np.eye(3), np.ones((5, 2)), "shape"),
    ],
)
def test_bad_input_on_the_fast_paths_gets_the_full_message(R, v, message):
    with pytest.raises(ValueError, match=message):
        change_frame(R, v)
