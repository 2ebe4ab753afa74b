"""Tests for course_lib.plotting: the geometry of what is drawn, not its pixels."""

import matplotlib

matplotlib.use("Agg")

import io  # noqa: E402

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from hypothesis import assume, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402
from mpl_toolkits.mplot3d import proj3d  # noqa: E402
from scipy.spatial.transform import Rotation  # noqa: E402

from course_lib import so3  # noqa: E402
from course_lib.plotting import (  # noqa: E402
    DPI,
    FRAME_COLORS,
    TITLE_SIZE,
    Arrow,
    Drawn,
    axes2d,
    axes3d,
    axes_row,
    draw_arc,
    draw_box,
    draw_curve,
    draw_frame,
    draw_pendulum,
    draw_plane,
    draw_point,
    draw_segment,
    draw_vector,
    plot_convergence,
)
from course_lib.tolerance import TOL  # noqa: E402

FAST = settings(max_examples=25, deadline=None)

finite = st.floats(-3.0, 3.0, allow_nan=False, allow_infinity=False)
vec3 = st.tuples(finite, finite, finite).map(np.array)
seeds = st.integers(0, 2**32 - 1)
angles = st.floats(-2 * np.pi, 2 * np.pi, allow_nan=False)


@pytest.fixture(scope="module")
def ax3():
    """One 3D axes shared by the property tests of a module (a figure per example is slow)."""
    fig, ax = axes3d("shared 3D axes")
    yield ax


@pytest.fixture(scope="module")
def ax2():
    """One 2D axes shared by the property tests."""
    fig, ax = axes2d("shared 2D axes")
    yield ax


def _rotation(seed):
    return so3.random_rotations(1, seed=seed)[0]


def _arrows(drawn):
    return [a for a in drawn if isinstance(a, Arrow)]


def _texts(drawn):
    return [a for a in drawn if isinstance(a, matplotlib.text.Text)]


def _render(fig):
    """Draw the figure for real (projects 3D artists); any warning fails the test."""
    fig.canvas.draw()


def _outside_canvas(fig, boxes):
    """Pixels by which the union of ``boxes`` (display coordinates) sticks out of the canvas.

    The notebooks show the whole canvas (``bbox_inches=None``), so anything outside is cut off.
    """
    union = matplotlib.transforms.Bbox.union([b for b in boxes if b is not None])
    canvas = fig.bbox
    return max(
        canvas.x0 - union.x0, canvas.y0 - union.y0, union.x1 - canvas.x1, union.y1 - canvas.y1
    )


def _decorations_2d(fig):
    """Tight boxes of every 2D axes: ticks, tick labels, axis labels, title, legend."""
    renderer = fig.canvas.get_renderer()
    return [ax.get_tightbbox(renderer) for ax in fig.axes]


def _axis_labels_3d(fig):
    """Boxes of the x, y, z axes of every 3D panel: tick labels and axis labels."""
    renderer = fig.canvas.get_renderer()
    return [
        axis.get_tightbbox(renderer) for ax in fig.axes for axis in (ax.xaxis, ax.yaxis, ax.zaxis)
    ]


# --- figures and axes -------------------------------------------------------------------------


def test_axes3d_sets_title_labels_and_equal_cube():
    fig, ax = axes3d("Frame A", lim=2.0)
    assert ax.name == "3d"
    assert ax.get_title() == "Frame A"
    assert (ax.get_xlabel(), ax.get_ylabel(), ax.get_zlabel()) == ("$x$", "$y$", "$z$")
    for lim in (ax.get_xlim(), ax.get_ylim(), ax.get_zlim()):
        assert np.allclose(lim, (-2.0, 2.0))
    assert np.allclose(ax.get_box_aspect() / ax.get_box_aspect()[0], 1.0)


def test_axes3d_accepts_a_pair_of_limits_and_an_existing_axes():
    fig = plt.figure()
    ax0 = fig.add_subplot(projection="3d")
    fig1, ax = axes3d("given", ax=ax0, lim=(-0.5, 2.5), elev=30, azim=45)
    assert ax is ax0 and fig1 is fig
    assert np.allclose(ax.get_zlim(), (-0.5, 2.5))
    assert (ax.elev, ax.azim) == (30, 45)


def test_axes2d_sets_title_labels_and_equal_aspect():
    fig, ax = axes2d("Pendulum", lim=(-1.0, 0.5), labels=("horizontal", "vertical"))
    assert ax.name != "3d"
    assert ax.get_title() == "Pendulum"
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("horizontal", "vertical")
    assert np.allclose(ax.get_xlim(), (-1.0, 0.5)) and np.allclose(ax.get_ylim(), (-1.0, 0.5))
    assert ax.get_aspect() == 1.0


def test_axes_row_makes_one_labelled_panel_per_title():
    fig, axes = axes_row(["time 0", "time t", "reflection"])
    assert [a.get_title() for a in axes] == ["time 0", "time t", "reflection"]
    assert all(a.name == "3d" and a.get_xlabel() == "$x$" for a in axes)
    fig2, axes2 = axes_row(["left", "right"], kind="2d", lim=1.0)
    assert all(a.name != "3d" and a.get_ylabel() == "$y$" for a in axes2)
    assert fig.get_size_inches()[0] > fig2.get_size_inches()[0]


@pytest.mark.parametrize(
    ("call", "error", "match"),
    [
        (lambda: axes3d("t", lim=0), ValueError, "lim must be"),
        (lambda: axes3d("t", lim=(1, -1)), ValueError, "lo < hi"),
        (lambda: axes3d("t", lim=np.nan), ValueError, "NaN"),
        (lambda: axes3d(3), TypeError, "title must be a str"),
        (lambda: axes2d("t", lim=-1), ValueError, "lim must be"),
        (lambda: axes_row([]), ValueError, "at least one title"),
        (lambda: axes_row("time 0"), TypeError, "sequence of str"),
        (lambda: axes_row(["a"], kind="4d"), ValueError, "kind must be"),
    ],
)
def test_axes_refuse_bad_arguments(call, error, match):
    with pytest.raises(error, match=match):
        call()


# --- layout: nothing is cut off on the full canvas ---------------------------------------------


@pytest.mark.parametrize(
    "make",
    [
        # long negative tick labels and a tall label with units (the pendulum of notebook 03)
        lambda: axes2d("A pendulum", lim=(-1.6, 1.4), labels=("$x$ (m)", "$y$ (m)")),
        lambda: axes2d("wide ticks", lim=(-12000.5, -10000.5), labels=("$x$", r"$\dfrac{y}{y_0}$")),
        lambda: axes_row(["left", "right"], kind="2d", lim=(-1.6, 1.4)),
        # log ticks 10^{-16} and a y label with hats and subscripts (series plot of notebook 03)
        lambda: plot_convergence(
            np.arange(1, 31),
            np.logspace(1, -16, 30),
            ylabel=r"error $\|S_N - e^{\hat\omega\theta}\|_F$",
        ),
    ],
)
def test_2d_figures_lay_themselves_out_inside_the_canvas(make):
    fig, _ = make()
    assert fig.get_layout_engine() is not None  # no fig.tight_layout() needed in a notebook
    _render(fig)
    assert _outside_canvas(fig, _decorations_2d(fig)) <= 0


def test_2d_layout_makes_room_for_what_is_added_later():
    # a colour bar (the group table of notebook 02) and a legend added after creation
    fig, ax = axes2d(
        "Products of the 24 cube rotations",
        lim=(-0.5, 23.5),
        labels=("index of $h$", "index of $g$"),
    )
    image = ax.imshow(np.arange(24 * 24).reshape(24, 24) % 24, origin="lower")
    fig.colorbar(image, ax=ax, label="index of $g h$", shrink=0.8)
    fig2, ax2 = plot_convergence([4, 8, 16], [1e-3, 1e-7, 1e-11], label="RK4")
    ax2.plot([4, 16], [1e-3, 1e-11], "k--", label="slope $N^{-4}$")
    ax2.set_xscale("log")
    ax2.legend()
    for f in (fig, fig2):
        _render(f)
        assert _outside_canvas(f, _decorations_2d(f)) <= 0
    # the axes stay square and inside the figure next to the colour bar
    box = ax.get_position()
    assert 0 <= box.x0 < box.x1 <= 1 and 0 <= box.y0 < box.y1 <= 1


def test_given_2d_axes_keep_their_figure_layout():
    fig, ax0 = plt.subplots()
    assert fig.get_layout_engine() is None
    axes2d("given", ax=ax0)
    plot_convergence([1, 2], [1e-1, 1e-3], ax=ax0)
    assert fig.get_layout_engine() is None


@pytest.mark.parametrize("elev", [20, 30, 45, 60, 75])
def test_axes_row_keeps_3d_tick_labels_inside_the_canvas_at_any_elevation(elev):
    # seen from 30°-60° above, the front corner of the cube and its tick labels reach lowest
    fig, axes = axes_row(
        [r"frame A: $v_a = (0, \sqrt{2}, 3)$", r"Frame B: $R_{ab}$ (eq. 27)"],
        lim=(-0.5, 3),
        elev=elev,
    )
    _render(fig)
    renderer = fig.canvas.get_renderer()
    titles = [ax.title.get_window_extent(renderer) for ax in axes]
    assert _outside_canvas(fig, _axis_labels_3d(fig) + titles) <= 0  # all sides, default azimuth
    for azim in range(-180, 180, 40):  # the bottom, from every side
        for ax in axes:
            ax.view_init(elev=elev, azim=azim)
        _render(fig)
        lowest = min(
            axis.get_tightbbox(renderer).y0
            for ax in axes
            for axis in (ax.xaxis, ax.yaxis, ax.zaxis)
        )
        assert lowest >= fig.bbox.y0, (elev, azim)


def test_axes3d_refuses_a_2d_axes_and_axes2d_a_3d_axes():
    _, ax2 = axes2d("flat")
    _, ax3 = axes3d("solid")
    with pytest.raises(TypeError, match="3D axes"):
        axes3d("t", ax=ax2)
    with pytest.raises(TypeError, match="2D axes"):
        axes2d("t", ax=ax3)


def test_figure_style_does_not_depend_on_global_rcparams():
    # the inline backend and users change rcParams; our figures must not follow them
    with plt.rc_context({"figure.dpi": 72, "font.size": 20, "axes.titlesize": 30}):
        fig, ax = axes3d("fixed")
        fig2, ax2 = axes2d("fixed")
    for f, a in ((fig, ax), (fig2, ax2)):
        assert f.dpi == DPI
        assert a.title.get_fontsize() == TITLE_SIZE


@pytest.mark.parametrize(
    "make",
    [
        lambda: axes3d("first"),
        lambda: axes2d("first"),
        lambda: axes_row(["first", "second"]),
        lambda: plot_convergence([1, 2], [1e-1, 1e-3]),
    ],
)
def test_first_figure_in_a_notebook_keeps_the_backend_interactive(monkeypatch, make):
    # The notebook backend turns interactive mode on while the first figure is being created.
    # Creating figures inside plt.rc_context rolled that back on exit, and every later figure of
    # the notebook was silently not displayed. Simulate the backend's switch and check it stays.
    real_figure = plt.figure

    def backend_activating_figure(*args, **kwargs):
        matplotlib.rcParams["interactive"] = True
        return real_figure(*args, **kwargs)

    monkeypatch.setitem(matplotlib.rcParams, "interactive", False)
    monkeypatch.setattr(plt, "figure", backend_activating_figure)
    make()
    assert matplotlib.rcParams["interactive"] is True


def test_same_cell_gives_identical_png():
    def cell():
        fig, ax = axes3d("reproducible")
        draw_frame(ax, so3.rot_z(0.3), label="B")
        draw_arc(ax, [0, 0, 1], [1, 0, 0], 1.0, label=r"$\theta$")
        draw_box(ax, so3.rot_x(0.4), marks=[0.1, 0.2, 0.05], mark_labels="$p$")
        buf = io.BytesIO()
        fig.savefig(buf, format="png", metadata={"Software": None})
        plt.close(fig)
        return buf.getvalue()

    assert cell() == cell()


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


def _signed_angle(k, u, v):
    """Angle from u to v about the unit axis k (right hand rule), in (-pi, pi]."""
    return np.arctan2(k @ np.cross(u, v), u @ v)


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


# --- draw_pendulum ----------------------------------------------------------------------------


@FAST
@given(
    theta=angles, r=st.floats(0.1, 3.0), omega=st.floats(-5.0, 5.0), pivot=st.tuples(finite, finite)
)
def test_draw_pendulum_speed_is_r_times_omega_and_tangent(ax2, theta, r, omega, pivot):
    pend = draw_pendulum(ax2, theta, r=r, omega=omega, pivot=pivot)
    c, bob = pend.points
    assert np.allclose(c, pivot)
    assert np.isclose(np.linalg.norm(bob - c), r)
    assert np.isclose(np.linalg.norm(pend.velocity), abs(r * omega))  # eq. (118)
    assert np.isclose((bob - c) @ pend.velocity, 0.0, atol=TOL)  # tangent to the circle
    # theta is measured from the downward vertical
    down = _signed_angle(np.array([0, 0, 1.0]), np.array([0, -1.0, 0]), np.append(bob - c, 0))
    assert np.isclose(np.exp(1j * down), np.exp(1j * theta), atol=TOL)


def test_draw_pendulum_draws_the_velocity_in_green():
    _, ax = axes2d("pendulum", lim=2.5)
    pend = draw_pendulum(ax, 0.4, r=1.0, omega=2.0, velocity_scale=0.5)
    assert np.allclose(ax.get_xlim(), (-2.5, 2.5)) and np.allclose(ax.get_ylim(), (-2.5, 2.5))
    green = [
        a
        for a in _arrows(pend)
        if matplotlib.colors.to_hex(a.get_edgecolor()) == matplotlib.colors.to_hex("tab:green")
    ]
    (v_arrow,) = green
    assert np.allclose(v_arrow.end - v_arrow.start, 0.5 * pend.velocity)
    assert {"$r$", r"$\theta$", "$v$"} <= {t.get_text() for t in _texts(pend)}
    _render(ax.figure)


def test_draw_pendulum_refuses_bad_input():
    _, ax = axes2d("t")
    with pytest.raises(ValueError, match="r must be > 0"):
        draw_pendulum(ax, 0.1, r=0)
    with pytest.raises(ValueError, match="NaN"):
        draw_pendulum(ax, np.nan)
    _, ax3 = axes3d("t")
    with pytest.raises(TypeError, match="2D axes"):
        draw_pendulum(ax3, 0.1)


# --- plot_convergence -------------------------------------------------------------------------


def test_plot_convergence_of_the_exponential_series():
    w = np.array([0.3, -0.4, 1.2])
    terms = np.arange(1, 21)

    def error(th, n):
        return np.linalg.norm(so3.exp_series(so3.hat(w * th), int(n)) - so3.exp(w * th))

    errors = {f"θ = {th}": [error(th, n) for n in terms] for th in (0.5, 2.0)}
    fig, ax = plot_convergence(terms, errors, title="Series (124)")
    assert ax.get_title() == "Series (124)" and ax.get_yscale() == "log"
    assert ax.get_xlabel() and ax.get_ylabel()
    lines = ax.get_lines()
    assert [ln.get_label() for ln in lines] == ["θ = 0.5", "θ = 2.0", "TOL = 1e-09"]
    assert np.allclose(lines[2].get_ydata(), TOL)
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert legend == ["θ = 0.5", "θ = 2.0", "TOL = 1e-09"]
    # the errors shrink: the series converges
    y = np.asarray(lines[0].get_ydata(), dtype=float)
    assert y[-1] < y[0]
    _render(fig)


def test_plot_convergence_zero_error_does_not_break_the_log_axis():
    # an exact 0 (series reproduced to the last bit) cannot sit on a log axis: it is left out
    fig, ax = plot_convergence([1, 2, 3], [1e-2, 1e-8, 0.0], label="error")
    y = np.asarray(ax.get_lines()[0].get_ydata(), dtype=float)
    assert np.isnan(y[2]) and np.allclose(y[:2], [1e-2, 1e-8])
    _render(fig)


@pytest.mark.parametrize(
    ("terms", "errors", "match"),
    [
        ([1, 2], [0.1, -0.1], "errors must be >= 0"),
        ([1, 2], [0.1], "shape of terms"),
        ([1, 2], [0.0, 0.0], "no error is positive"),
        ([1, 2], [0.1, np.nan], "NaN"),
        ([], [], "non-empty"),
    ],
)
def test_plot_convergence_refuses_bad_errors(terms, errors, match):
    with pytest.raises(ValueError, match=match):
        plot_convergence(terms, errors)


def test_plot_convergence_draws_dashed_references_on_log_log_axes():
    fig, ax = plot_convergence(
        [4, 8, 16],
        [1e-3, 6e-5, 4e-6],
        show_tol=False,
        logx=True,
        references={"slope $N^{-4}$": [1e-3, 6.25e-5, 3.9e-6]},
    )
    reference = ax.get_lines()[-1]
    assert (ax.get_xscale(), ax.get_yscale()) == ("log", "log")
    assert reference.get_label() == "slope $N^{-4}$" and reference.get_linestyle() == "--"
    assert [t.get_text() for t in ax.get_legend().get_texts()][-1] == "slope $N^{-4}$"
    plt.close(fig)


@pytest.mark.parametrize("reference", [[1.0, 2.0], [1.0, 0.0, 1.0], [1.0, -1.0, 1.0]])
def test_plot_convergence_refuses_bad_references(reference):
    with pytest.raises(ValueError, match="references.*positive with the shape of terms"):
        plot_convergence([1, 2, 3], [0.1, 0.01, 0.001], references={"bound": reference})


# --- a whole scene ----------------------------------------------------------------------------


def test_a_full_scene_renders_without_warnings_and_arrows_project_in_3d():
    fig, axes = axes_row(["A and B", "phone"])
    frame = draw_frame(axes[0], so3.rot_y(np.pi), label="B")
    draw_frame(axes[0], label="A", style="dashed")
    draw_vector(axes[0], [1, 1, 3], label="$v$")
    draw_plane(axes[0], [1, 0, 0], [0, 1, 0])
    draw_arc(axes[0], [0, 0, 1], [1, 0, 0], 2.0, label=r"$\theta$")
    draw_curve(axes[0], np.eye(3), arrow=True)
    draw_box(axes[1], so3.rot_x(0.5), marks=[[0.1, 0.2, 0.05]], frame="B")
    draw_point(axes[1], [[2.0, 2.0, 2.0], [0.0, 0.0, 0.0]])  # outside the cube: still no rescale
    _render(fig)
    # drawing never rescales the axes: the cube stays equal and fixed, as axes_row made it
    for ax in axes:
        for lim in (ax.get_xlim(), ax.get_ylim(), ax.get_zlim()):
            assert np.allclose(lim, (-1.5, 1.5))
    # after drawing, each 3D arrow has been projected to finite display positions
    for arrow in _arrows(frame):
        verts = arrow.get_path().vertices
        assert verts.size and np.all(np.isfinite(verts))
    buf = io.BytesIO()
    fig.savefig(buf, format="png", bbox_inches="tight")  # what the inline backend does
    assert buf.getvalue()[:8] == b"\x89PNG\r\n\x1a\n"
