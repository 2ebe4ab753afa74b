"""Tests of course_lib.interactive.gimbal: the turn axes of roll-pitch-yaw, the rates matrix E,
gimbal lock at pitch ±90°, the drawing and the explorer of chapter 05.

Everything runs on the Agg backend and closes its figures; releasing a slider is setting its
value (as in test_interactive.py).
"""

import base64

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib import euler, interactive, plotting
from course_lib import symbolic_orientation as so
from course_lib.interactive import (
    PITCH_RANGE,
    ROLL_RANGE,
    YAW_RANGE,
    draw_gimbal,
    gimbal_explorer,
    gimbal_readout,
    rates_matrix,
    turn_axes,
)
from course_lib.plotting.display import figure_alt_and_png

degrees = st.floats(-180.0, 180.0, allow_nan=False)
pitches = st.floats(-90.0, 90.0, allow_nan=False)


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


def test_turn_axes_of_zero_angles_are_z_y_x():
    assert np.array_equal(turn_axes(0, 0), [[0, 0, 1], [0, 1, 0], [1, 0, 0]])


@settings(max_examples=60, deadline=None)
@given(degrees, pitches, degrees)
def test_columns_of_E_are_the_turn_axes_in_body_coordinates(yaw, pitch, roll):
    R = euler.to_matrix(np.radians([yaw, pitch, roll]), "ZYX")
    assert np.allclose(rates_matrix(pitch, roll), R.T @ turn_axes(yaw, pitch).T, atol=1e-14)


@settings(max_examples=60, deadline=None)
@given(pitches, degrees)
def test_det_E_is_minus_cos_pitch(pitch, roll):
    det = np.linalg.det(rates_matrix(pitch, roll))
    assert det == pytest.approx(-np.cos(np.radians(pitch)), abs=1e-14)


def test_rates_matrix_is_the_symbolic_E_of_the_chapter():
    E = so.euler_rates_matrix("ZYX")
    a, b, c = so.euler_symbols()
    for yaw, pitch, roll in [(10, 20, 30), (-170, 89, -45), (0, -90, 120)]:
        at = {a: sp.rad(yaw), b: sp.rad(pitch), c: sp.rad(roll)}
        expected = np.array(E.subs(at).evalf(), dtype=float)
        assert np.allclose(rates_matrix(pitch, roll), expected, atol=1e-15)


def test_E_times_the_rates_is_the_angular_velocity_of_the_moving_body():
    # omega_b = vee(R^T dR/dt), dR/dt by central differences along the angle rates.
    angles, rates, h = np.array([25.0, 40.0, -60.0]), np.array([3.0, -2.0, 5.0]), 1e-6
    R = lambda t: euler.to_matrix(np.radians(angles + t * rates), "ZYX")  # noqa: E731
    W = R(0).T @ (R(h) - R(-h)) / (2 * h)
    omega_b = np.array([W[2, 1], W[0, 2], W[1, 0]])
    assert np.allclose(rates_matrix(*angles[1:]) @ np.radians(rates), omega_b, atol=1e-8)


@pytest.mark.parametrize("pitch", [90.0, -90.0])
def test_at_pitch_plus_or_minus_90_roll_turns_about_the_yaw_line(pitch):
    yaw_axis, _, roll_axis = turn_axes(35.0, pitch)
    assert yaw_axis @ roll_axis == pytest.approx(-np.sign(pitch), abs=1e-15)
    assert np.linalg.matrix_rank(rates_matrix(pitch, 17.0), tol=1e-12) == 2


def test_readout_says_gimbal_lock_only_at_the_lock():
    assert "gimbal lock" in gimbal_readout(10, 90, 0)
    assert "gimbal lock" in gimbal_readout(10, -90, 0)
    assert r"\det E = -\cos\theta = -0.50" in gimbal_readout(0, 60, 0)
    assert "gimbal lock" not in gimbal_readout(10, 89, 0)
    assert "-0.00" not in gimbal_readout(0, 90, 0)  # no minus sign on a zero
    with pytest.raises(ValueError, match="decimals must be between 0 and 6"):
        gimbal_readout(0, 0, 0, decimals=9)


def test_draw_gimbal_draws_three_axes_and_their_circles():
    fig, ax = plotting.axes3d("Gimbal")
    drawn = draw_gimbal(ax, 30, 90, 10)
    labels = sorted(t.get_text() for t in ax.texts)
    assert labels == ["pitch", "roll", "yaw"]
    assert np.allclose(drawn.points, turn_axes(30, 90))
    assert np.allclose(drawn.R, euler.to_matrix(np.radians([30, 90, 10]), "ZYX"))
    for circle, axis, radius in zip(drawn.circles, drawn.points, [1.25, 1.05, 0.85]):
        assert np.allclose(circle @ axis, 0.0, atol=1e-14)  # about its own axis
        assert np.allclose(np.linalg.norm(circle, axis=1), radius)
    # at the lock the roll circle lies in the plane of the yaw circle (z = 0)
    assert np.allclose(drawn.circles[2][:, 2], 0.0, atol=1e-15)
    assert drawn.det == pytest.approx(0.0, abs=1e-15)


@pytest.mark.parametrize(
    "args, error, message",
    [
        ((np.nan, 0, 0), ValueError, "yaw contains NaN"),
        ((0, "up", 0), TypeError, "pitch must be an array of real numbers"),
        ((0, 0, [1, 2]), ValueError, r"roll must be a single angle"),
    ],
)
def test_draw_gimbal_refuses_bad_angles(args, error, message):
    _, ax = plotting.axes3d("Gimbal")
    with pytest.raises(error, match=message):
        draw_gimbal(ax, *args)


def test_draw_gimbal_refuses_2d_axes():
    _, ax = plotting.axes2d("flat")
    with pytest.raises(TypeError, match="draw_gimbal"):
        draw_gimbal(ax, 0, 0, 0)


def test_gimbal_explorer_has_three_degree_sliders_over_their_ranges():
    widget = gimbal_explorer()
    assert list(widget.sliders) == ["yaw ψ", "pitch θ", "roll φ"]
    for slider, (lo, hi) in zip(widget.sliders.values(), (YAW_RANGE, PITCH_RANGE, ROLL_RANGE)):
        assert (slider.min, slider.max, slider.step) == (lo, hi, 1.0)
        assert slider.continuous_update is False
    assert widget.readout is widget.children[-1]
    assert "drag the 3D view" in widget.description


def test_moving_pitch_to_90_locks_the_gimbal_in_place():
    widget = gimbal_explorer()
    ax = widget.ax
    assert "gimbal lock" not in widget.readout.value
    widget.sliders["pitch θ"].value = 90.0
    assert widget.ax is ax  # redrawn in place
    yaw_axis, _, roll_axis = widget.result
    assert yaw_axis @ roll_axis == pytest.approx(-1.0, abs=1e-15)
    assert "gimbal lock" in widget.readout.value and r"\theta$ = 90°" in ax.get_title()
    n_artists = len(ax.get_children())
    widget.sliders["roll φ"].value = 45.0  # a redraw replaces the drawing, no pile-up
    assert len(ax.get_children()) == n_artists


def test_gimbal_explorer_refuses_angles_outside_its_sliders():
    with pytest.raises(
        ValueError, match=r"pitch θ = 95 is outside the slider range \[-90, 90\] \(degrees\)"
    ):
        gimbal_explorer(pitch=95)
    with pytest.raises(ValueError, match="yaw ψ contains NaN"):
        gimbal_explorer(yaw=np.nan)


def test_gimbal_explorer_without_ipympl_shows_its_still_picture(monkeypatch):
    def missing():
        raise ModuleNotFoundError("No module named 'ipympl'", name="ipympl")

    monkeypatch.setattr(interactive.widgets, "_ipympl_classes", missing)
    widget = gimbal_explorer(pitch=90)
    assert not widget.live and widget.children == ()
    bundle = widget._repr_mimebundle_()
    alt, png = figure_alt_and_png(bundle["text/html"].split("<p>")[0])
    png = base64.b64decode(png)
    assert png.startswith(b"\x89PNG") and len(png) > 5_000
    assert "pitch θ = 90°" in alt and "gimbal lock" in alt
    assert bundle["text/plain"].splitlines() == [widget.description, widget.why_still]


@pytest.mark.parametrize("pitch", [60.0, 90.0])
@pytest.mark.parametrize("elev, azim", [(20.0, 45.0), (-45.0, 120.0), (90.0, 90.0)])
def test_gimbal_labels_stay_inside_the_figure_apart_and_clear_of_the_title(
    pitch, elev, azim, screen_box
):
    ax = gimbal_explorer(pitch=pitch, elev=elev, azim=azim).ax
    fig = ax.figure
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    title = ax.title.get_window_extent(renderer)
    boxes = {t.get_text(): screen_box(t, ax, renderer) for t in ax.texts}
    assert sorted(boxes) == ["pitch", "roll", "yaw"]
    for name, box in boxes.items():
        assert not box.overlaps(title), name
        assert fig.bbox.x0 <= box.x0 and box.x1 <= fig.bbox.x1, name
        assert fig.bbox.y0 <= box.y0 and box.y1 <= fig.bbox.y1, name
    if (elev, azim) == (20.0, 45.0):  # the first view: no label on another
        names = sorted(boxes)
        for i, a in enumerate(names):
            for b in names[i + 1 :]:
                assert not boxes[a].overlaps(boxes[b]), f"labels {a!r} and {b!r} overlap"
