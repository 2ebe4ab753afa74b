"""Tests for course_lib.plotting.figures_exponential: the pendulum and Rodrigues' circle."""

import matplotlib

matplotlib.use("Agg")


import matplotlib.pyplot as plt
import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from plotting_helpers import (
    _arrows,
    _ax_texts,
    _position,
    _render,
    _signed_angle,
    _texts,
    angles,
    finite,
)

from course_lib import so3
from course_lib.plotting import (
    axes2d,
    axes3d,
    draw_pendulum,
    plot_orbit,
    plot_rodrigues_circle,
    plot_spinning_body,
)
from course_lib.tolerance import TOL

FAST = settings(max_examples=25, deadline=None)


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
        if matplotlib.colors.to_hex(a.get_edgecolor()) == matplotlib.colors.to_hex("#009E73")
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
    assert {"$q$", r"$q_\perp$", r"$\omega\times q$", r"$e^{\hat\omega\theta}q$"} <= set(
        _ax_texts(ax)
    )


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


# --- plot_orbit and plot_spinning_body (chapter 3's figures of eq. 119 and 121) ---------------

FIGURES = settings(max_examples=10, deadline=None)  # each example draws a whole figure


@FIGURES
@given(
    seed=st.integers(0, 2**31 - 1),
    speed=st.floats(0.2, 2.0),
    height=st.floats(-0.8, 0.8),
    rho=st.floats(0.1, 1.0),
    phase=angles,
)
def test_orbit_velocity_is_tangent_with_speed_omega_times_rho(seed, speed, height, rho, phase):
    w = speed * so3.random_rotations(1, seed=seed)[0][:, 0]
    fig, _, parts = plot_orbit(w, height=height, rho=rho, phase=phase)
    plt.close(fig)
    p, centre, v = parts["p"], parts["centre"], parts["v"]
    assert np.isclose(np.linalg.norm(p - centre), rho) and np.isclose(parts["rho"], rho)
    assert np.allclose(np.cross(centre, w), 0.0, atol=TOL)  # the centre lies on the axis
    assert np.isclose((p - centre) @ w, 0.0, atol=TOL)  # the radius is across the axis
    assert np.isclose(np.linalg.norm(v), speed * rho)  # eq. (118) with rho for r
    assert np.isclose(v @ (p - centre), 0.0, atol=TOL) and np.isclose(v @ w, 0.0, atol=TOL)


def test_orbit_labels_every_part_it_draws():
    fig, ax, _ = plot_orbit([0.2, 0.3, 1.0])
    _render(fig)
    labels = set(_ax_texts(ax))
    plt.close(fig)
    assert {r"$\omega$", "$p$", "$r$", r"$\rho$", "$v$"} <= labels


@pytest.mark.parametrize("w, rho", [([0, 0, 0], 0.9), ([0, 0, 1], 0.0), ([0, 0, np.nan], 0.9)])
def test_orbit_rejects_a_zero_axis_a_zero_radius_and_nan(w, rho):
    with pytest.raises(ValueError):
        plot_orbit(w, rho=rho)
    plt.close("all")


@FIGURES
@given(seed=st.integers(0, 2**31 - 1))
def test_spinning_body_turns_its_corner_about_the_plate_normal(seed):
    R = so3.random_rotations(1, seed=seed)[0]
    fig, ax, parts = plot_spinning_body(R)
    plt.close(fig)
    assert np.allclose(parts["omega"], R[:, 2])
    assert np.allclose(parts["q_dot"], np.cross(R[:, 2], parts["q"]))
    # the corner is on the plate: its offset from the centre lies in the plate's plane
    assert np.isclose((parts["q"] - R[:, 2]) @ R[:, 2], 0.0, atol=TOL)


def test_spinning_body_labels_frame_axis_body_and_point():
    fig, ax, _ = plot_spinning_body(so3.exp([0.5, -np.sqrt(0.75), 0.0], 0.45))
    _render(fig)
    labels = set(_ax_texts(ax))
    plt.close(fig)
    assert {r"$\omega$", "$q$", "$B$", r"$\dot q = \omega \times q$"} <= labels


def test_spinning_body_refuses_a_matrix_that_is_not_a_rotation():
    with pytest.raises(ValueError, match="rotation"):
        plot_spinning_body(np.diag([1.0, 1.0, -1.0]))
