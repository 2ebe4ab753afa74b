"""Tests for course_lib.plotting as a package: what it re-exports, its modules, a whole scene."""

import matplotlib

matplotlib.use("Agg")

import importlib
import inspect
import io
from pathlib import Path

import numpy as np
import pytest
from plotting_helpers import _arrows, _render

from course_lib import _arrays, plotting, so3
from course_lib.plotting import (
    axes2d,
    axes3d,
    axes_row,
    draw_arc,
    draw_box,
    draw_curve,
    draw_frame,
    draw_plane,
    draw_point,
    draw_vector,
)
from course_lib.tolerance import check_tol

# Every public name of the single module plotting.py (its __all__ and its other constants).
OLD_NAMES = [
    "DPI", "FONT_SIZE", "TITLE_SIZE", "FRAME_COLORS", "FIGSIZE", "PANEL_SIZE", "ARROW_HEAD",
    "Arrow", "Drawn", "axes3d", "axes2d", "axes_row", "draw_frame", "draw_vector", "draw_point",
    "draw_segment", "draw_curve", "draw_plane", "draw_arc", "draw_box", "draw_pendulum",
    "plot_convergence", "frame_panels", "plot_error_curves", "plot_geodesic",
    "plot_rodrigues_circle",
]  # fmt: skip
MODULES = [
    "axes",
    "primitives",
    "shapes",
    "figures_exponential",
    "figures_accuracy",
    "figures_composition",
]


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


# --- the package: names, modules, one validation layer -----------------------------------------


def test_every_name_of_the_old_module_is_still_on_plotting():
    missing = [name for name in OLD_NAMES if not hasattr(plotting, name)]
    assert missing == []
    # beyond the old module's names: only the figures of chapter 05, added after the split,
    # chapter 03's orbit and spinning body (issue 37: one helper call per figure cell),
    # display.show, which hands a figure to the notebook as an image with alt text, and
    # colours.readable, a label's colour at 4.5:1
    new = importlib.import_module("course_lib.plotting.figures_orientation").__all__
    new = [*new, "plot_orbit", "plot_spinning_body"]
    new = [*new, *importlib.import_module("course_lib.plotting.display").__all__]
    new = [*new, "readable"]
    assert set(plotting.__all__) <= set(OLD_NAMES) | set(new)
    # interactive.py checks its axes with the package's _require_3d
    assert plotting._require_3d is importlib.import_module("course_lib.plotting.axes")._require_3d


@pytest.mark.parametrize("module", MODULES)
def test_each_module_is_one_concern_under_600_lines_and_its_names_are_the_packages(module):
    mod = importlib.import_module(f"course_lib.plotting.{module}")
    assert len(Path(mod.__file__).read_text().splitlines()) < 600
    for name in mod.__all__:
        assert getattr(plotting, name) is getattr(mod, name), name
        obj = getattr(mod, name)
        if inspect.isfunction(obj) or inspect.isclass(obj):
            assert obj.__module__ == mod.__name__  # defined there, not re-exported from elsewhere


STYLES = ("solid", "dashed", "dotted", "dashdot")


@pytest.mark.parametrize(
    ("draw", "check"),
    [
        (lambda ax: draw_vector(ax, [1, 2, 3]), lambda: _arrays.as_vector([1, 2, 3], "v", 2)),
        (lambda ax: draw_point(ax, [[1, 2, 3]]), lambda: _arrays.as_points([[1, 2, 3]], "p", 2)),
        (lambda ax: draw_frame(ax, R=np.eye(3)), lambda: _arrays.as_matrix(np.eye(3), "R", 2)),
        (
            lambda ax: draw_vector(ax, [1, 0], linewidth=0),
            lambda: _arrays.as_positive(0, "linewidth"),
        ),
        (lambda ax: draw_vector(ax, [1, 0], label=1), lambda: _arrays.as_str(1, "label")),
        (
            lambda ax: draw_vector(ax, [1, 0], style="wavy"),
            lambda: _arrays.as_choice("wavy", "style", STYLES),
        ),
        (lambda ax: draw_plane(ax, [1, 0], [0, 1], tol=-1.0), lambda: check_tol(-1.0)),
    ],
)
def test_plotting_refuses_bad_input_with_the_message_of_the_one_validation_layer(draw, check):
    _, ax = axes2d("t")
    with pytest.raises((ValueError, TypeError)) as expected:
        check()
    with pytest.raises(type(expected.value)) as got:
        draw(ax)
    assert str(got.value) == str(expected.value)


def test_a_bool_is_not_a_line_width_and_a_bool_tol_is_not_a_tolerance():
    # regression: plotting's own _scalar read True as 1.0; as_positive and check_tol refuse it
    _, ax = axes3d("t")
    with pytest.raises(TypeError, match="linewidth must be a real number, got bool"):
        draw_vector(ax, [1, 0, 0], linewidth=True)
    with pytest.raises(TypeError, match="tol must be a real number"):
        draw_arc(ax, [0, 0, 1], [1, 0, 0], 1.0, tol=True)
