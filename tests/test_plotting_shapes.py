"""Tests for course_lib.plotting.shapes: the plane patch, the arc, the box."""

import matplotlib

matplotlib.use("Agg")


import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from plotting_helpers import (
    _arrows,
    _render,
    _rotation,
    _signed_angle,
    _texts,
    angles,
    seeds,
    vec3,
)
from scipy.spatial.transform import Rotation

from course_lib import so3
from course_lib.plotting import (
    axes2d,
    axes3d,
    draw_arc,
    draw_box,
    draw_plane,
)
from course_lib.tolerance import TOL

FAST = settings(max_examples=25, deadline=None)


# --- draw_plane -------------------------------------------------------------------------------


@FAST
@given(a=vec3, b=vec3, origin=vec3)
def test_draw_plane_spans_a_and_b_and_its_normal_is_a_cross_b(ax3, a, b, origin):
    ax = ax3
    if np.linalg.norm(np.cross(a, b)) <= TOL:
        with pytest.raises(ValueError, match="parallel"):
            draw_plane(ax, a, b, origin=origin)
    else:
        patch = draw_plane(ax, a, b, origin=origin, label="span")
        assert np.allclose(patch.points, [origin, origin + a, origin + a + b, origin + b])
        n = patch.normal
        assert np.allclose(n, np.cross(a, b))
        # the normal is orthogonal to every edge of the patch, i.e. to the whole plane
        edges = np.diff(np.vstack([patch.points, patch.points[:1]]), axis=0)
        assert np.allclose(edges @ n, 0.0, atol=TOL)


def test_draw_plane_refuses_parallel_vectors_with_the_size_of_the_failure():
    _, ax = axes3d("t")
    msg = r"a and b are parallel .*‖a × b‖ = 0\.0e\+00 ≤ TOL = 1e-09"
    with pytest.raises(ValueError, match=msg):
        draw_plane(ax, [1, 2, 3], [2, 4, 6])
    _, ax2 = axes2d("t")
    with pytest.raises(ValueError, match="parallel"):
        draw_plane(ax2, [1, 1], [-2, -2])
    patch = draw_plane(ax2, [1, 0], [0, 1])
    assert patch.normal is None and np.allclose(patch.artists[0].get_xy()[:4], patch.points)


# --- draw_arc ---------------------------------------------------------------------------------


@FAST
@given(axis=vec3, start=vec3, angle=angles, center=vec3, n=st.integers(2, 80))
def test_draw_arc_points_stay_at_one_distance_from_the_axis_and_span_the_angle(
    ax3, axis, start, angle, center, n
):
    norm = np.linalg.norm(axis)
    assume(norm > 1e-3)  # zero axes are refused, see test_draw_arc_refuses_degenerate_input
    k = axis / norm
    radius = np.linalg.norm(start - (k @ start) * k)
    assume(radius > 1e-3)  # a start on the axis is refused, see the same test
    assume(abs(angle) / (n - 1) < np.pi - 1e-6)  # a step measured by atan2 must be below π
    arc = draw_arc(ax3, axis, start, angle, center=center, n=n)
    rel = arc.points - center
    assert arc.points.shape == (n, 3)
    assert np.allclose(arc.axis, k)
    # same distance from the axis, and in the plane perpendicular to it through the start
    dist = np.linalg.norm(rel - np.outer(rel @ k, k), axis=1)
    assert np.allclose(dist, radius, atol=TOL) and np.isclose(arc.radius, radius)
    assert np.allclose(rel @ k, start @ k, atol=TOL)
    # equal steps that add up to the requested angle
    perp = rel - np.outer(rel @ k, k)
    steps = np.array([_signed_angle(k, perp[j], perp[j + 1]) for j in range(n - 1)])
    assert np.allclose(steps, angle / (n - 1), atol=TOL)
    assert np.isclose(steps.sum(), angle, atol=TOL)
    # the end point is the start rotated by e^{k̂ angle}, checked against scipy
    expected = center + Rotation.from_rotvec(k * angle).apply(start)
    assert np.allclose(arc.points[-1], expected, atol=TOL)


def test_draw_arc_in_2d_rotates_in_the_plane_about_the_center():
    _, ax = axes2d("planar arc")
    arc = draw_arc(ax, None, [0.0, -1.0], np.pi / 2, center=[1.0, 1.0], label=r"$\theta$")
    assert np.allclose(arc.points[0], [1.0, 0.0]) and np.allclose(arc.points[-1], [2.0, 1.0])
    assert np.allclose(np.linalg.norm(arc.points - [1.0, 1.0], axis=1), 1.0)
    assert arc.axis is None
    (arrow,) = _arrows(arc)
    assert np.allclose(arrow.end, arc.points[-1])


def test_draw_arc_of_zero_angle_is_a_point_without_arrow_head():
    _, ax = axes3d("zero")
    arc = draw_arc(ax, [0, 0, 1], [1, 0, 0], 0.0)
    assert np.allclose(arc.points, [1, 0, 0]) and _arrows(arc) == []
    _render(ax.figure)


@pytest.mark.parametrize(
    ("axis", "start", "kwargs", "error", "match"),
    [
        (
            [0, 0, 0],
            [1, 0, 0],
            {},
            ValueError,
            r"axis must be non-zero to define a direction: ‖axis‖ = 0\.0e\+00 ≤ TOL",
        ),
        ([0, 0, 2], [0, 0, 1], {}, ValueError, "start lies on the axis"),
        ([0, 0, 1], [1, 0, 0], {"n": 1}, ValueError, "must be >= 2"),
        ([0, 0, 1], [1, 0, 0], {"n": 2.5}, TypeError, "must be an integer"),
        (None, [1, 0, 0], {}, TypeError, "needs an axis"),
        ([0, 0, 1], [1, 0], {}, ValueError, "start must be one 3-vector"),
    ],
)
def test_draw_arc_refuses_degenerate_input(axis, start, kwargs, error, match):
    _, ax = axes3d("t")
    with pytest.raises(error, match=match):
        draw_arc(ax, axis, start, 1.0, **kwargs)


def test_draw_arc_in_2d_refuses_an_axis():
    _, ax = axes2d("t")
    with pytest.raises(TypeError, match="axis=None"):
        draw_arc(ax, [0, 0, 1], [1, 0], 1.0)


# --- draw_box ---------------------------------------------------------------------------------


@FAST
@given(seed=seeds, center=vec3, marks=st.lists(vec3, min_size=2, max_size=5))
def test_draw_box_marked_points_keep_their_distances_under_rotation(ax3, seed, center, marks):
    R = _rotation(seed)
    M = np.array(marks)
    before = draw_box(ax3, marks=M)
    after = draw_box(ax3, R, center=center, marks=M)
    assert np.allclose(before.points, M)
    assert np.allclose(after.points, center + M @ R.T)
    d0 = np.linalg.norm(before.points[:, None] - before.points[None], axis=-1)
    d1 = np.linalg.norm(after.points[:, None] - after.points[None], axis=-1)
    assert np.allclose(d0, d1, atol=TOL)  # eq. (9): the body is rigid


def test_draw_box_corners_form_a_box_of_the_given_size():
    _, ax = axes3d("box")
    R, c, size = so3.exp([0.3, -0.5, 0.8]), np.array([0.2, 0.1, -0.3]), np.array([0.4, 1.0, 0.1])
    box = draw_box(ax, R, center=c, size=size)
    assert box.corners.shape == (8, 3) and box.points.shape == (0, 3)
    assert np.allclose(box.corners.mean(axis=0), c)
    body = (box.corners - c) @ R  # back to body coordinates
    assert np.allclose(np.abs(body), size / 2)
    _render(ax.figure)
    assert len(box.artists[0].get_paths()) == 6  # six faces, projected when drawn


def test_draw_box_with_body_frame_and_mark_labels():
    _, ax = axes3d("phone")
    R = so3.rot_z(np.pi / 3)
    box = draw_box(
        ax,
        R,
        marks=[[0.1, 0.3, 0.05], [-0.1, -0.3, 0.05]],
        mark_labels=["$p_1$", "$p_2$"],
        frame="B",
    )
    texts = [t.get_text() for t in _texts(box)]
    assert texts[:2] == ["$p_1$", "$p_2$"] and "$x_{B}$" in texts
    frame_tips = [a.end for a in _arrows(box)]
    assert np.allclose(np.array(frame_tips) / np.linalg.norm(frame_tips[0]), R.T)


def test_draw_box_refuses_a_reflection_as_orientation():
    _, ax = axes3d("t")
    with pytest.raises(ValueError, match="R"):
        draw_box(ax, np.diag([1.0, 1.0, -1.0]))
    with pytest.raises(ValueError, match="size must have three positive"):
        draw_box(ax, size=(1, 0, 1))
    with pytest.raises(ValueError, match="mark_labels given without marks"):
        draw_box(ax, mark_labels=["$p$"])
    _, ax2 = axes2d("t")
    with pytest.raises(TypeError, match="3D axes"):
        draw_box(ax2)
