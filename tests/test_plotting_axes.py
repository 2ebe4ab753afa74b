"""Tests for course_lib.plotting.axes: figures and axes, their layout, their style."""

import matplotlib

matplotlib.use("Agg")

import io

import matplotlib.pyplot as plt
import numpy as np
import pytest
from hypothesis import settings
from plotting_helpers import (
    _axis_labels_3d,
    _decorations_2d,
    _outside_canvas,
    _render,
)

from course_lib import so3
from course_lib.plotting import (
    DPI,
    TITLE_SIZE,
    axes2d,
    axes3d,
    axes_row,
    draw_arc,
    draw_box,
    draw_frame,
    plot_convergence,
)

FAST = settings(max_examples=25, deadline=None)


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
