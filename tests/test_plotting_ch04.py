"""Tests for the chapter-04 helpers of course_lib.plotting: what they draw, and bad input."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from hypothesis import assume, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from course_lib import so3  # noqa: E402
from course_lib.plotting import (  # noqa: E402
    Arrow,
    frame_panels,
    plot_error_curves,
    plot_geodesic,
    plot_rodrigues_circle,
)
from course_lib.tolerance import TOL  # noqa: E402

FAST = settings(max_examples=20, deadline=None)


def _texts(ax):
    return [t.get_text() for t in ax.texts]


# frame_panels ---------------------------------------------------------------------------------


def test_frame_panels_draws_each_item_in_its_panel():
    R = so3.rot_z(np.pi / 2)
    fig, axes, drawn = frame_panels(
        [
            {
                "title": "one",
                "frames": [{"label": "A"}, {"R": R, "label": "B", "scale": 0.5}],
                "vectors": [{"v": [0, 0, 1], "label": "$v$"}],
                "axis": {"direction": [0, 0, 2]},
            },
            {"title": "two", "boxes": [{"R": R}]},
        ]
    )
    assert [a.get_title() for a in axes] == ["one", "two"]
    assert [d.kind for d in drawn[0]] == ["frame", "frame", "vector", "axis"]
    assert np.allclose(drawn[0][1].points, 0.5 * R.T)  # tips o + s R e_i
    assert np.allclose(drawn[0][3].points, [[0, 0, -1.2], [0, 0, 1.2]])  # unit axis, ±1.2
    assert [d.kind for d in drawn[1]] == ["box"]
    assert "$B$" in _texts(axes[0]) and "$v$" in _texts(axes[0])


def test_frame_panels_name_false_leaves_out_only_the_name():
    fig, axes, drawn = frame_panels([{"title": "t", "frames": [{"label": "B", "name": False}]}])
    texts = _texts(axes[0])
    assert "$B$" not in texts  # no name at the origin
    assert {"$x_{B}$", "$y_{B}$", "$z_{B}$"} <= set(texts)  # the axis labels stay
    assert len(drawn[0][0].artists) == 6  # 3 arrows + 3 labels


def _position(text):
    return np.array([text._x, text._y, text._z], dtype=float)


def test_frame_panels_labels_beside_keeps_labels_off_a_shared_axis():
    # regression: the short frame before a turn about z wrote z_B on the longer z_B' arrow
    R = so3.rot_y(np.pi / 4)
    fig, axes, drawn = frame_panels(
        [
            {
                "title": "t",
                "frames": [
                    {"R": R, "label": "B", "scale": 0.6, "labels": "beside"},
                    {"R": R @ so3.rot_z(np.pi / 2), "label": "C"},
                ],
            }
        ]
    )
    frame = drawn[0][0]
    labels = [a for a in frame.artists if hasattr(a, "get_text")][:3]
    for tip, text in zip(frame.points, labels):
        step = _position(text) - tip
        axis = (tip - frame.origin) / np.linalg.norm(tip - frame.origin)
        assert np.linalg.norm(step) > 0.01  # moved away from the tip
        assert abs(step @ axis) < 1e-12  # sideways, not along the arrow


def test_frame_panels_rejects_unknown_label_placement():
    with pytest.raises(ValueError, match="labels must be 'tip' or 'beside'"):
        frame_panels([{"title": "t", "frames": [{"labels": "middle"}]}])


@pytest.mark.parametrize(
    "panels, error",
    [
        (["not a dict"], TypeError),
        ([{"frames": []}], TypeError),  # no title
        ([{"title": "t", "colour": "red"}], ValueError),  # unknown key
        ([{"title": "t", "frames": [np.eye(3)]}], TypeError),  # item is not a dict
        ([{"title": "t", "frames": [{"R": np.eye(3), "size": 2}]}], TypeError),
        ([{"title": "t", "boxes": [{"R": np.diag([1.0, 1.0, -1.0])}]}], ValueError),  # reflection
        ([{"title": "t", "axis": {"direction": [0, 0, 0]}}], ValueError),
    ],
)
def test_frame_panels_rejects_bad_panels(panels, error):
    with pytest.raises(error):
        frame_panels(panels)


# plot_error_curves ----------------------------------------------------------------------------


def test_error_curves_are_log_log_and_floor_exact_zeros():
    x = np.logspace(-1, -6, 6)
    fig, ax = plot_error_curves(x, {"a": 1e-16 / x, "zero": np.zeros(6)}, "t", "gap", floor=1e-18)
    assert ax.get_xscale() == ax.get_yscale() == "log"
    assert ax.xaxis_inverted()
    lines = {line.get_label(): line for line in ax.get_lines()}
    assert np.allclose(lines["a"].get_ydata(), 1e-16 / x)
    assert np.all(lines["zero"].get_ydata() == 1e-18)


@pytest.mark.parametrize(
    "x, curves, error",
    [
        ([1.0, 0.0], {"a": [1.0, 1.0]}, ValueError),  # x not positive
        ([1.0, 0.1], [1.0, 1.0], TypeError),  # curves not a dict
        ([1.0, 0.1], {"a": [1.0, -1.0]}, ValueError),  # negative error
        ([1.0, 0.1], {"a": [1.0, np.nan]}, ValueError),
        ([1.0, 0.1], {"a": [1.0, 1.0, 1.0]}, ValueError),  # shapes differ
    ],
)
def test_error_curves_reject_bad_input(x, curves, error):
    with pytest.raises(error):
        plot_error_curves(x, curves, "t", "x")


# plot_geodesic --------------------------------------------------------------------------------


@FAST
@given(st.integers(0, 2**31 - 1))
def test_geodesic_runs_at_constant_speed_from_R0_to_R1(seed):
    R0, R1 = so3.random_rotations(2, seed=seed)
    fig, ax, path = plot_geodesic(R0, R1, samples=9)
    plt.close(fig)
    ts = np.linspace(0, 1, 9)
    assert so3.is_rotation(path).all()
    assert np.allclose(path[0], R0, atol=1e-12) and np.allclose(path[-1], R1, atol=1e-12)
    total = so3.angle_between(R0, R1)
    assert np.allclose(so3.angle_between(R0, path), ts * total, atol=1e-9)


def test_geodesic_draws_three_tip_paths_and_the_frames_between():
    fig, ax, path = plot_geodesic(np.eye(3), so3.rot_x(1.0), steps=4, samples=5)
    assert len(ax.get_lines()) == 3  # one tip path per axis
    arrows = [a for a in ax.artists if isinstance(a, Arrow)] + [
        p for p in ax.patches if isinstance(p, Arrow)
    ]
    assert len(arrows) == 3 * (4 - 1) + 6  # 3 frames between, plus 2 ends
    assert {"$x_{0}$", "$x_{1}$"} <= set(_texts(ax)) and "$0$" not in _texts(ax)


def test_geodesic_rejects_non_rotations():
    with pytest.raises(ValueError, match="R1"):
        plot_geodesic(np.eye(3), 2 * np.eye(3))
    with pytest.raises(ValueError):
        plot_geodesic(np.eye(3), np.eye(3), steps=0)


# plot_rodrigues_circle ------------------------------------------------------------------------


@FAST
@given(st.integers(0, 2**31 - 1), st.floats(-2 * np.pi, 2 * np.pi))
def test_rodrigues_parts_rebuild_the_rotated_point(seed, th):
    w = so3.random_rotations(1, seed=seed)[0, :, 0]
    q = np.array([0.7, -0.4, 0.5])
    assume(np.linalg.norm(np.cross(w, q)) > 1e-3)  # q off the axis
    fig, ax, parts = plot_rodrigues_circle(w, q, th)
    plt.close(fig)
    geometric = parts["q_par"] + np.cos(th) * parts["q_perp"] + np.sin(th) * parts["w_x_q"]
    assert np.allclose(parts["Rq"], geometric, atol=1e-12)
    assert abs(parts["q_perp"] @ w) < 1e-12
    assert np.isclose(np.linalg.norm(parts["Rq"] - parts["q_par"]), np.linalg.norm(parts["q_perp"]))


def test_rodrigues_circle_is_drawn_about_the_axis():
    fig, ax, parts = plot_rodrigues_circle([0, 0, 1], [1, 0, 0.5], np.pi / 2)
    circle = max(ax.get_lines(), key=lambda line: len(line.get_xdata()))
    xs, ys, zs = (np.asarray(a) for a in circle.get_data_3d())
    assert np.allclose(np.hypot(xs, ys), 1.0) and np.allclose(zs, 0.5)
    assert {"$q$", r"$q_\perp$", r"$\omega\times q$", r"$e^{\hat\omega\theta}q$"} <= set(_texts(ax))


def test_rodrigues_circle_labels_q_perp_apart_from_q():
    # regression: q_perp ends where q ends, and both labels were written at that tip
    fig, ax, parts = plot_rodrigues_circle([0, 0, 1], [0.9, 0, 0.5], 2 * np.pi / 3)
    where = {t.get_text(): _position(t) for t in ax.texts}
    assert np.linalg.norm(where[r"$q_\perp$"] - where["$q$"]) > 0.3
    assert np.linalg.norm(where[r"$q_\parallel$"] - parts["q_par"]) > 0.05


def test_rodrigues_circle_names_the_dashed_terms_and_keeps_labels_apart(screen_box):
    # regression: e^{ω̂θ}q and ω×q were written on the arc and on each other's arrows, and the
    # dashed term cos θ q⊥ that the notebook's caption names carried no name
    fig, ax, parts = plot_rodrigues_circle([0, 0, 1], [0.9, 0, 0.5], 2 * np.pi / 3)
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert legend == [r"$\cos\theta\,q_\perp$", r"$\sin\theta\,\omega\times q$"]
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    boxes = {t.get_text(): screen_box(t, ax, renderer) for t in ax.texts}
    assert len(boxes) == 7  # ω, θ, q, q∥, q⊥, ω×q, e^{ω̂θ}q
    names = sorted(boxes)
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            assert not boxes[a].overlaps(boxes[b]), f"labels {a!r} and {b!r} overlap"


@pytest.mark.parametrize(
    "w, q",
    [
        ([0, 0, 2], [1, 0, 0]),  # not a unit axis
        ([0, 0, 1], [0, 0, 0.7]),  # q on the axis
        ([0, 0, 1], [1, 0]),  # wrong shape
        ([0, 0, 1], [np.inf, 0, 0]),
    ],
)
def test_rodrigues_circle_rejects_bad_input(w, q):
    with pytest.raises(ValueError):
        plot_rodrigues_circle(w, q, 1.0)


def test_rodrigues_circle_message_names_the_axis_point():
    with pytest.raises(ValueError, match=f"q lies on the axis.*TOL = {TOL:g}"):
        plot_rodrigues_circle([1, 0, 0], [2, 0, 0], 1.0)
