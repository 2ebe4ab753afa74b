"""Tests for course_lib.plotting.primitives: Drawn, frames, vectors, points, segments, curves."""

import matplotlib

matplotlib.use("Agg")


import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from mpl_toolkits.mplot3d import proj3d
from plotting_helpers import (
    _arrows,
    _render,
    _rotation,
    _texts,
    seeds,
    vec3,
)

from course_lib import so3
from course_lib.plotting import (
    DPI,
    FRAME_COLORS,
    Drawn,
    axes2d,
    axes3d,
    draw_box,
    draw_curve,
    draw_frame,
    draw_point,
    draw_segment,
    draw_vector,
)
from course_lib.tolerance import TOL

FAST = settings(max_examples=25, deadline=None)


# --- Drawn ------------------------------------------------------------------------------------


def test_drawn_repr_has_no_memory_address_for_nbval():
    _, ax = axes3d("t")
    frame = draw_frame(ax)
    assert repr(frame) == "<Drawn frame: 7 artists, 3 points>"
    assert "0x" not in repr(frame)
    assert list(frame) == frame.artists and len(frame) == 7
    assert isinstance(frame, Drawn)


# --- draw_frame -------------------------------------------------------------------------------


@FAST
@given(seed=seeds, origin=vec3, scale=st.floats(0.1, 3.0))
def test_draw_frame_puts_arrow_tips_at_origin_plus_scaled_columns(ax3, seed, origin, scale):
    R = _rotation(seed)
    frame = draw_frame(ax3, R, origin=origin, label="B", scale=scale)
    arrows = _arrows(frame)
    assert len(arrows) == 3
    for i, arrow in enumerate(arrows):
        assert np.allclose(arrow.start, origin, atol=TOL)
        assert np.allclose(arrow.end, origin + scale * R[:, i], atol=TOL)
        # a rotation keeps the drawn axes orthonormal (up to the common scale)
        assert np.isclose(np.linalg.norm(arrow.end - arrow.start), scale, atol=TOL)
    assert np.allclose(frame.points, origin + scale * R.T, atol=TOL)


def test_draw_frame_labels_axes_with_the_frame_name_and_colours():
    _, ax = axes3d("frames")
    frame = draw_frame(ax, label="B")
    texts = [t.get_text() for t in _texts(frame)]
    assert texts == ["$x_{B}$", "$y_{B}$", "$z_{B}$", "$B$"]
    assert [matplotlib.colors.to_hex(a.get_edgecolor()) for a in _arrows(frame)] == [
        matplotlib.colors.to_hex(c) for c in FRAME_COLORS
    ]
    # each axis label sits beyond its arrow tip, on the axis direction
    for i, t in enumerate(_texts(frame)[:3]):
        pos = np.array(t.get_position_3d())
        assert pos[i] > 1.0 and np.allclose(np.delete(pos, i), 0.0)
    unnamed = draw_frame(ax, label=None)
    assert [t.get_text() for t in _texts(unnamed)] == ["$x$", "$y$", "$z$"]


def test_draw_frame_dashed_style_and_reflection_for_the_counterexample():
    _, ax = axes3d("reflection")
    reflection = np.diag([1.0, 1.0, -1.0])
    frame = draw_frame(ax, reflection, style="dashed", label=None)
    assert all(a.get_linestyle() == "--" for a in _arrows(frame))
    assert np.allclose(frame.points[2], [0, 0, -1])


def test_draw_frame_in_2d():
    _, ax = axes2d("planar frame")
    R = np.array([[0.0, -1.0], [1.0, 0.0]])
    frame = draw_frame(ax, R, origin=[0.5, 0.5], colors=("r", "g"), axis_names=("x", "y"))
    assert np.allclose([a.end for a in _arrows(frame)], [[0.5, 1.5], [-0.5, 0.5]])


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        ({"R": np.eye(2)}, ValueError, r"3x3 matrix .* got shape \(2, 2\)"),
        ({"R": [[1, 0, 0], [0, np.nan, 0], [0, 0, 1]]}, ValueError, "NaN"),
        ({"R": [[1, 0, 0], [0, 0, 0], [0, 0, 1]]}, ValueError, "column 1 .*zero length.*TOL"),
        (
            {"origin": [0, 0]},
            ValueError,
            r"origin must be one 3-vector of shape \(3,\), got shape \(2,\)",
        ),
        ({"scale": 0}, ValueError, "scale must be > 0"),
        ({"style": "wavy"}, ValueError, "style must be one of"),
        ({"R": "eye"}, TypeError, "R must be an array of real numbers"),
        ({"colors": ("r", "g")}, ValueError, "3 entries"),
    ],
)
def test_draw_frame_refuses_bad_input(kwargs, error, match):
    _, ax = axes3d("t")
    with pytest.raises(error, match=match):
        draw_frame(ax, **kwargs)


# --- draw_vector, draw_point, draw_segment, draw_curve ---------------------------------------


@FAST
@given(v=vec3, origin=vec3)
def test_draw_vector_goes_from_origin_to_origin_plus_v(ax3, v, origin):
    drawn = draw_vector(ax3, v, origin=origin, label="$v$")
    assert np.allclose(drawn.points, [origin, origin + v])
    arrows = _arrows(drawn)
    if np.linalg.norm(v) > 0:
        assert np.allclose(arrows[0].start, origin) and np.allclose(arrows[0].end, origin + v)
    else:
        assert arrows == []  # a zero vector is a dot, not a degenerate arrow
    assert _texts(drawn)[0].get_text() == "$v$"


def test_draw_vector_is_free_same_arrow_from_different_points():
    # eq. (8): p - q = r - s gives the same vector drawn at two places
    _, ax = axes3d("free vector")
    p, q = np.array([1.0, 1.0, 0.5]), np.array([0.2, 0.4, 0.0])
    s = np.array([-1.0, 0.0, 0.3])
    r = s + (p - q)
    a = draw_vector(ax, p - q, origin=q)
    b = draw_vector(ax, r - s, origin=s)
    assert np.allclose(np.diff(a.points, axis=0), np.diff(b.points, axis=0))
    assert np.allclose(a.points[1], p) and np.allclose(b.points[1], r)


def test_draw_vector_refuses_a_2d_vector_on_3d_axes():
    _, ax = axes3d("t")
    msg = r"v must be one 3-vector of shape \(3,\), got shape \(2,\)"
    with pytest.raises(ValueError, match=msg):
        draw_vector(ax, [1, 0])
    with pytest.raises(ValueError, match="NaN"):
        draw_vector(ax, [1, np.inf, 0])


def test_draw_point_draws_a_rigid_body_of_particles_with_labels():
    _, ax = axes2d("particles")
    P = np.array([[0.0, 0.0], [1.0, 0.0], [0.5, 0.8]])
    body = draw_point(ax, P, label=["$p_1$", None, "$p_3$"])
    assert np.allclose(body.artists[0].get_offsets(), P)
    assert [t.get_text() for t in _texts(body)] == ["$p_1$", "$p_3$"]
    single = draw_point(ax, [0.1, 0.2], label="$q$")
    assert single.points.shape == (1, 2)


def test_draw_point_refuses_wrong_number_of_labels_and_shapes():
    _, ax = axes3d("t")
    with pytest.raises(ValueError, match="one label per item: expected 2, got 1"):
        draw_point(ax, [[0, 0, 0], [1, 1, 1]], label=["$p$"])
    with pytest.raises(ValueError, match=r"shape \(3,\) or \(n, 3\)"):
        draw_point(ax, [[0, 0], [1, 1]])


@FAST
@given(p=vec3, q=vec3)
def test_draw_segment_joins_the_points_and_reports_the_distance(ax3, p, q):
    seg = draw_segment(ax3, p, q, label="d")
    line = seg.artists[0]
    assert np.allclose(np.array(line.get_data_3d()).T, [p, q])
    assert np.isclose(seg.length, np.linalg.norm(p - q))
    assert line.get_linestyle() == "--"


def _label_of(drawn, d):
    (text,) = _texts(drawn)
    return np.array(text.get_position_3d() if d == 3 else text.get_position())


@FAST
@given(p=vec3, q=vec3, t=st.floats(0.0, 1.0), elev=st.floats(-90, 90), azim=st.floats(-180, 180))
def test_draw_segment_label_sits_across_the_segment_at_the_fraction_label_at(
    ax3, p, q, t, elev, azim
):
    ax3.view_init(elev=elev, azim=azim)
    try:
        seg = draw_segment(ax3, p, q, label="d", label_at=t)
    finally:
        ax3.view_init(elev=20, azim=-60)
    pos = _label_of(seg, 3)
    assert np.allclose(pos, seg.label_position)
    gap = pos - (p + t * (q - p))
    lo, hi = ax3.get_xlim()
    assert np.isclose(np.linalg.norm(gap), 0.05 * (hi - lo))  # the label gap of the axes
    assert abs(gap @ (q - p)) <= 1e-6 * (1 + np.linalg.norm(q - p))  # across the segment ...
    e, a = np.radians(elev), np.radians(azim)
    camera = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
    assert abs(gap @ camera) <= 1e-9  # ... in the plane of the screen, so it is seen beside it
    # and up on the screen (up = camera × right, right = (−sin a, cos a, 0))
    up = np.cross(camera, [-np.sin(a), np.cos(a), 0.0])
    assert gap @ up >= -1e-9


def test_draw_segment_label_in_2d_is_beside_the_segment_and_above_it():
    _, ax = axes2d("segment", lim=2.0)
    for p, q in [
        ([0, 0], [1, 0]),
        ([1, 0], [0, 0]),
        ([0, 0], [0, 1]),
        ([0, 0], [1, -1]),
        ([0, 0], [1, 1]),
    ]:
        seg = draw_segment(ax, p, q, label="d")
        gap = _label_of(seg, 2) - (np.array(p) + 0.65 * (np.subtract(q, p)))
        assert np.isclose(np.linalg.norm(gap), 0.2)  # 5% of the x span
        assert np.isclose(gap @ np.subtract(q, p), 0.0)
        assert gap[1] > 0 or (gap[1] == 0 and gap[0] > 0)  # up (right beside a vertical one)
    above = _texts(draw_segment(ax, [0, 0], [1, 0], label="d"))[0]
    assert (above.get_ha(), above.get_va()) == ("center", "bottom")  # grows away from the line
    right = _texts(draw_segment(ax, [0, 0], [0, 1], label="d"))[0]
    assert (right.get_ha(), right.get_va()) == ("left", "center")


@pytest.mark.parametrize("turned", [False, True])
def test_draw_segment_label_is_off_the_centre_of_a_box_with_symmetric_marks(turned, screen_box):
    # the phone of notebook 02: marks symmetric about the centre, so the midpoint of p1 p2 is
    # the origin of the body frame B, where its arrows start; the label used to sit there
    fig, ax = axes3d("phone", lim=0.8)
    R = so3.rot_z(np.pi / 3) @ so3.rot_x(np.pi / 4) if turned else np.eye(3)
    marks = [[0.2, 0.4, 0.05], [-0.2, -0.4, 0.05]]
    phone = draw_box(ax, R, marks=marks, mark_labels=["$p_1$", "$p_2$"], frame="B")
    assert np.allclose(phone.points.mean(axis=0), R @ [0, 0, 0.05])  # centre, on the top face
    seg = draw_segment(ax, *phone.points, label="0.894")
    _render(fig)
    renderer = fig.canvas.get_renderer()
    (label,) = _texts(seg)
    box = screen_box(label, ax, renderer)
    centre = ax.transData.transform(proj3d.proj_transform(*R @ [0, 0, 0.05], ax.get_proj())[:2])
    assert not box.padded(8 * DPI / 100).contains(*centre)  # clear of the frame's origin ...
    names = {t.get_text(): screen_box(t, ax, renderer) for t in _texts(phone)}
    for name in ("$x_{B}$", "$y_{B}$", "$z_{B}$"):  # ... and of the labels of its axes
        assert not box.overlaps(names[name]), name
    # the midpoint is still available on request, across the segment as well
    mid = draw_segment(ax, *phone.points, label="d", label_at=0.5)
    assert np.isclose(
        (mid.label_position - phone.points.mean(axis=0)) @ (phone.points[1] - phone.points[0]), 0.0
    )


def test_draw_segment_without_label_and_refusing_bad_label_at():
    _, ax = axes3d("t")
    seg = draw_segment(ax, [0, 0, 0], [1, 0, 0])
    assert seg.label_position is None and _texts(seg) == []
    for bad in (-0.1, 1.5):
        with pytest.raises(ValueError, match=r"label_at must be a fraction .* in \[0, 1\]"):
            draw_segment(ax, [0, 0, 0], [1, 0, 0], label="d", label_at=bad)
    with pytest.raises(ValueError, match="NaN"):
        draw_segment(ax, [0, 0, 0], [1, 0, 0], label_at=np.nan)
    with pytest.raises(TypeError, match="label must be a str"):
        draw_segment(ax, [0, 0, 0], [1, 0, 0], label=1.0)
    # a segment that points straight at the viewer still gets its label beside it
    ax.view_init(elev=90, azim=-60)
    up = draw_segment(ax, [0, 0, 0], [0, 0, 1], label="d")
    gap = up.label_position - [0, 0, 0.65]
    assert np.isclose(np.linalg.norm(gap), 0.15) and np.isclose(gap[2], 0.0)


def test_draw_curve_follows_the_trajectory_with_an_arrow_at_the_end():
    _, ax = axes3d("trajectory")
    t = np.linspace(0, 2, 40)
    P = np.stack([np.cos(t), np.sin(t), 0.2 * t], axis=-1)
    curve = draw_curve(ax, P, label="$p(t)$", arrow=True)
    assert np.allclose(np.array(curve.artists[0].get_data_3d()).T, P)
    (arrow,) = _arrows(curve)
    assert np.allclose(arrow.start, P[-2]) and np.allclose(arrow.end, P[-1])
    assert _texts(curve)[0].get_text() == "$p(t)$"


def test_draw_curve_arrow_skips_a_final_stop():
    # a trajectory that stops (repeated last sample) must not give a zero-length arrow
    _, ax = axes2d("stop")
    P = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 0.0]])
    (arrow,) = _arrows(draw_curve(ax, P, arrow=True))
    assert np.allclose(arrow.start, [0, 0]) and np.allclose(arrow.end, [1, 0])


def test_draw_curve_needs_two_points():
    _, ax = axes3d("t")
    with pytest.raises(ValueError, match="at least 2 points, got 1"):
        draw_curve(ax, [[0, 0, 0]])
