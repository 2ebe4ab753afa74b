"""Tests of course_lib.rodrigues: the axis from spherical angles, R(ω, θ), the three terms of
Rodrigues' formula (eq. 159) and a body spinning at unit angular velocity (eq. 123-125).

Pure numpy: checked against scipy's rotation vectors and against the notes' identities.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from course_lib import so3
from course_lib.rodrigues import (
    axis_from_spherical,
    rodrigues_terms,
    rodrigues_vectors,
    rotated_frame,
    spin_rotations,
    spin_times,
)
from course_lib.tolerance import TOL

polars = st.floats(0.0, np.pi)  # the ranges of the explorers' sliders
azimuths = st.floats(-np.pi, np.pi)
thetas = st.floats(0.0, 2.0 * np.pi)
coords = st.floats(-2.0, 2.0)
points = st.tuples(coords, coords, coords)
Q0 = (1.0, 0.0, 0.0)


def unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


# --------------------------------------------------------------------------------------------
# axis_from_spherical
# --------------------------------------------------------------------------------------------


@given(polars, azimuths)
def test_axis_from_spherical_is_unit(polar, azimuth):
    w = axis_from_spherical(polar, azimuth)
    assert w.shape == (3,) and w.dtype == np.float64
    assert abs(np.linalg.norm(w) - 1.0) <= TOL


@given(st.floats(0.01, np.pi - 0.01), st.floats(-np.pi + 0.01, np.pi - 0.01))
def test_axis_from_spherical_round_trips_through_arccos_and_atan2(polar, azimuth):
    x, y, z = axis_from_spherical(polar, azimuth)
    assert abs(np.arccos(np.clip(z, -1, 1)) - polar) <= 1e-7
    assert abs(np.arctan2(y, x) - azimuth) <= 1e-7


def test_axis_from_spherical_poles_and_equator():
    assert np.allclose(axis_from_spherical(0.0, 1.234), [0, 0, 1], atol=TOL, rtol=0)
    assert np.allclose(axis_from_spherical(np.pi, -0.5), [0, 0, -1], atol=TOL, rtol=0)
    assert np.allclose(axis_from_spherical(np.pi / 2, 0.0), [1, 0, 0], atol=TOL, rtol=0)
    assert np.allclose(axis_from_spherical(np.pi / 2, -np.pi / 2), [0, -1, 0], atol=TOL, rtol=0)


def test_axis_from_spherical_broadcasts():
    polar = np.linspace(0, np.pi, 4)[:, None]
    azimuth = np.linspace(-np.pi, np.pi, 5)[None, :]
    w = axis_from_spherical(polar, azimuth)
    assert w.shape == (4, 5, 3)
    assert np.allclose(w[2, 3], axis_from_spherical(polar[2, 0], azimuth[0, 3]))


def test_axis_from_spherical_refuses_nan_and_strings_and_mismatched_shapes():
    with pytest.raises(ValueError, match="polar contains NaN"):
        axis_from_spherical(np.nan, 0.0)
    with pytest.raises(TypeError, match="azimuth must be an array of real numbers"):
        axis_from_spherical(0.0, "east")
    with pytest.raises(ValueError, match="must broadcast together"):
        axis_from_spherical([0.1, 0.2], [0.1, 0.2, 0.3])


# --------------------------------------------------------------------------------------------
# rotated_frame
# --------------------------------------------------------------------------------------------


@given(polars, azimuths, thetas)
@settings(max_examples=50)
def test_rotated_frame_matches_scipy_rotvec(polar, azimuth, theta):
    w = axis_from_spherical(polar, azimuth)
    R = rotated_frame(polar, azimuth, theta)
    assert so3.is_rotation(R)
    assert np.linalg.norm(R - Rotation.from_rotvec(w * theta).as_matrix()) <= TOL
    assert np.linalg.norm(R @ w - w) <= TOL  # the axis does not move


def test_rotated_frame_batches_over_angles():
    theta = np.linspace(0, 2 * np.pi, 7)
    R = rotated_frame(0.3, 1.1, theta)
    assert R.shape == (7, 3, 3)
    assert np.allclose(R[3], rotated_frame(0.3, 1.1, theta[3]))


# --------------------------------------------------------------------------------------------
# rodrigues_terms and rodrigues_vectors
# --------------------------------------------------------------------------------------------


@given(polars, azimuths, st.floats(-10.0, 10.0))
@settings(max_examples=60)
def test_rodrigues_terms_sum_to_exp(polar, azimuth, theta):
    w = axis_from_spherical(polar, azimuth)
    identity, sin_term, cos_term = rodrigues_terms(w, theta)
    R = so3.exp(w, theta)
    assert np.linalg.norm(identity + sin_term + cos_term - R) <= TOL
    assert np.linalg.norm(identity - np.eye(3)) == 0.0
    assert np.linalg.norm(sin_term + sin_term.T) <= TOL  # sinθ ω̂ is skew: the odd part of R
    assert np.linalg.norm(cos_term - cos_term.T) <= TOL  # (1 − cosθ) ω̂² is symmetric


@given(polars, azimuths, st.floats(-10.0, 10.0))
@settings(max_examples=40)
def test_rodrigues_terms_match_the_series_split_of_eq_158(polar, azimuth, theta):
    """Term 1 is the odd powers of the series, term 2 the even powers above zero."""
    w = axis_from_spherical(polar, azimuth)
    W = so3.hat(w)
    _, sin_term, cos_term = rodrigues_terms(w, theta)
    # Even and odd parts of e^{ŵθ}: (R − Rᵀ)/2 = sinθ ŵ, (R + Rᵀ)/2 − I = (1 − cosθ) ŵ².
    R = Rotation.from_rotvec(w * theta).as_matrix()
    assert np.linalg.norm(sin_term - (R - R.T) / 2) <= TOL
    assert np.linalg.norm(cos_term - ((R + R.T) / 2 - np.eye(3))) <= TOL
    assert np.linalg.norm(sin_term - np.sin(theta) * W) <= TOL


def test_rodrigues_terms_batch_shapes_broadcast():
    axes = axis_from_spherical(np.linspace(0, np.pi, 5), 0.4)  # (5, 3)
    theta = np.linspace(0, 3, 5)
    terms = rodrigues_terms(axes, theta)
    assert [t.shape for t in terms] == [(5, 3, 3)] * 3
    assert np.allclose(sum(terms), so3.exp(axes, theta))
    terms = rodrigues_terms([0, 0, 1], np.zeros((2, 4)))
    assert [t.shape for t in terms] == [(2, 4, 3, 3)] * 3


def test_rodrigues_terms_refuses_non_unit_axis_instead_of_returning_a_wrong_sum():
    with pytest.raises(
        ValueError,
        match=r"axis must be a unit vector: ‖axis‖ = 2, .* > TOL = 1e-09; divide it by its norm",
    ):
        rodrigues_terms([0, 0, 2], 1.0)
    with pytest.raises(ValueError, match=r"at batch index \(1,\)"):
        rodrigues_terms([[0, 0, 1], [0, 1e-3, 1]], 1.0)


def test_rodrigues_terms_refuses_bad_shapes_and_values():
    with pytest.raises(ValueError, match=r"shape \(\.\.\., 3\)"):
        rodrigues_terms([1, 0], 1.0)
    with pytest.raises(ValueError, match="does not broadcast"):
        rodrigues_terms([[0, 0, 1], [1, 0, 0]], [1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="theta contains NaN"):
        rodrigues_terms([0, 0, 1], np.inf)


@given(polars, azimuths, thetas, points)
@settings(max_examples=60)
def test_rodrigues_vectors_add_up_to_the_rotated_point(polar, azimuth, theta, q0):
    w = axis_from_spherical(polar, azimuth)
    first, sin_vec, cos_vec = rodrigues_vectors(w, theta, q0)
    assert np.array_equal(first, np.asarray(q0, float))
    assert np.linalg.norm(first + sin_vec + cos_vec - so3.exp(w, theta) @ q0) <= TOL
    # sinθ ω̂q0 = sinθ (ω × q0) is orthogonal to the axis and to q0 ...
    assert abs(sin_vec @ w) <= TOL and abs(sin_vec @ np.asarray(q0)) <= TOL
    # ... and (1 − cosθ) ω̂²q0 = (1 − cosθ)(ω ωᵀq0 − q0) (eq. 141) points at the axis.
    expected = (1 - np.cos(theta)) * ((w @ q0) * w - np.asarray(q0))
    assert np.linalg.norm(cos_vec - expected) <= TOL


def test_rodrigues_vectors_vanish_for_a_point_on_the_axis():
    w = unit([1, 2, 2])
    q0, sin_vec, cos_vec = rodrigues_vectors(w, 2.5, 3 * w)
    assert np.linalg.norm(sin_vec) <= TOL and np.linalg.norm(cos_vec) <= TOL


def test_rodrigues_vectors_broadcast_points_against_angles():
    parts = rodrigues_vectors([0, 0, 1], np.array([0.0, np.pi]), [[1, 0, 0], [0, 1, 0]])
    assert [p.shape for p in parts] == [(2, 3)] * 3
    assert np.allclose(sum(parts), [[1, 0, 0], [0, -1, 0]])
    with pytest.raises(ValueError, match="q0 of shape"):
        rodrigues_vectors([0, 0, 1], np.zeros(2), np.zeros((3, 3)))


# --------------------------------------------------------------------------------------------
# Spinning at unit angular velocity
# --------------------------------------------------------------------------------------------


def test_spin_times_are_equal_steps_without_the_end_point():
    t = spin_times(8)
    assert t.shape == (8,) and t[0] == 0.0
    assert np.allclose(np.diff(t), 2 * np.pi / 8)
    assert t[-1] < 2 * np.pi
    with pytest.raises(ValueError, match="frames must be >= 2"):
        spin_times(1)
    with pytest.raises(TypeError, match="frames must be an integer"):
        spin_times(5.0)
    with pytest.raises(ValueError, match="duration must be > 0"):
        spin_times(5, duration=-1.0)


@given(points.filter(lambda p: np.linalg.norm(p) > 0.1), st.floats(0.0, 3.1))
@settings(max_examples=50)
def test_spin_rotations_turn_one_radian_per_second(axis, t):
    w = unit(axis)
    R = spin_rotations(axis, t)
    axis_out, angle = so3.axis_angle(R)
    assert abs(angle - t) <= 1e-8  # θ = t (eq. 125)
    if t > 1e-3:
        assert np.linalg.norm(axis_out - w) <= 1e-6
    # q̇ = ω̂ q (eq. 122): a central difference of R(t) q0 matches ω × R(t) q0
    h = 1e-5
    q0 = np.array([0.3, -0.4, 0.8])
    q_dot = (spin_rotations(axis, t + h) - spin_rotations(axis, t - h)) @ q0 / (2 * h)
    assert np.linalg.norm(q_dot - np.cross(w, R @ q0)) <= 1e-8


def test_spin_rotations_refuses_a_zero_axis():
    with pytest.raises(
        ValueError, match=r"axis must be non-zero .* ‖axis‖ = 0\.0e\+00 ≤ TOL = 1e-09"
    ):
        spin_rotations([0, 0, 0], 1.0)
    with pytest.raises(ValueError, match=r"axis must be one 3-vector of shape \(3,\)"):
        spin_rotations([[0, 0, 1]], 1.0)
