"""Tests for course_lib.plotting.figures_composition: frame panels and the geodesic."""

import matplotlib

matplotlib.use("Agg")


import matplotlib.pyplot as plt
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from plotting_helpers import (
    _ax_texts,
    _position,
)

from course_lib import so3
from course_lib.plotting import (
    Arrow,
    frame_panels,
    plot_geodesic,
)

FAST = settings(max_examples=20, deadline=None)


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
    assert "$B$" in _ax_texts(axes[0]) and "$v$" in _ax_texts(axes[0])


def test_frame_panels_name_false_leaves_out_only_the_name():
    fig, axes, drawn = frame_panels([{"title": "t", "frames": [{"label": "B", "name": False}]}])
    texts = _ax_texts(axes[0])
    assert "$B$" not in texts  # no name at the origin
    assert {"$x_{B}$", "$y_{B}$", "$z_{B}$"} <= set(texts)  # the axis labels stay
    assert len(drawn[0][0].artists) == 6  # 3 arrows + 3 labels


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
    assert {"$x_{0}$", "$x_{1}$"} <= set(_ax_texts(ax)) and "$0$" not in _ax_texts(ax)


def test_geodesic_rejects_non_rotations():
    with pytest.raises(ValueError, match="R1"):
        plot_geodesic(np.eye(3), 2 * np.eye(3))
    with pytest.raises(ValueError):
        plot_geodesic(np.eye(3), np.eye(3), steps=0)
