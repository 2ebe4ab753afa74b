"""Tests of course_lib.interactive: the readout, the drawings, the explorers, the animation.

(The maths behind them is tested in test_rodrigues.py.) Everything runs on the Agg backend and
closes its figures. The explorers are exercised without a browser: releasing a slider is
setting its value, and a mouse drag is the messages ipympl's canvas receives from the page.
"""

import base64
import html
import inspect
import io
import os
import re
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
import pytest
from mpl_toolkits.mplot3d import proj3d

from course_lib import interactive, plotting, so3
from course_lib.interactive import (
    AZIMUTH_RANGE,
    POLAR_RANGE,
    Q0,
    SPIN_PIXELS,
    THETA_RANGE,
    VIEW_AZIM,
    VIEW_ELEV,
    draw_rodrigues_terms,
    draw_rotated_frame,
    gimbal_explorer,
    rodrigues_explorer,
    rodrigues_readout,
    rotation_explorer,
    spin_animation,
)
from course_lib.plotting.display import figure_alt_and_png
from course_lib.rodrigues import (
    axis_from_spherical,
    rodrigues_terms,
    rodrigues_vectors,
    rotated_frame,
)
from course_lib.tolerance import TOL


@pytest.fixture(autouse=True)
def close_figures():
    """Every test starts with no open figure and closes what it opened, even when it fails."""
    plt.close("all")
    yield
    plt.close("all")


def unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def arrows_on(ax):
    """(start, end) of every arrow drawn on ``ax``, as an (n, 2, 3) array."""
    found = [np.stack([a.start, a.end]) for a in ax.get_children() if isinstance(a, plotting.Arrow)]
    return np.array(found)


def has_arrow(ax, start, end):
    segs = arrows_on(ax)
    target = np.stack([np.asarray(start, float), np.asarray(end, float)])
    return bool(np.any(np.linalg.norm(segs - target, axis=(1, 2)) <= 1e-12))


def lines_on(ax):
    """The 3D point arrays of every line drawn on ``ax``."""
    return [np.array(line.get_data_3d()).T for line in ax.get_lines()]


# --------------------------------------------------------------------------------------------
# rodrigues_readout
# --------------------------------------------------------------------------------------------


def matrices_in(tex):
    """The numeric matrices written in a LaTeX string, as (3, 3) arrays."""
    blocks = re.findall(r"\\begin\{bmatrix\}(.*?)\\end\{bmatrix\}", tex)
    return [
        np.array([[float(x) for x in row.split("&")] for row in b.split(r"\\")]) for b in blocks
    ]


@pytest.mark.parametrize(
    "polar, azimuth, theta", [(0.3, 1.0, 0.5), (2.0, -2.5, 4.0), (np.pi / 2, 0, np.pi)]
)
def test_rodrigues_readout_writes_the_terms_and_their_sum(polar, azimuth, theta):
    w = axis_from_spherical(polar, azimuth)
    tex = rodrigues_readout(w, theta, decimals=3)
    shown = matrices_in(tex)
    assert len(shown) == 4
    for written, exact in zip(shown, list(rodrigues_terms(w, theta)) + [so3.exp(w, theta)]):
        assert np.max(np.abs(written - exact)) <= 0.5e-3 + 1e-12
    assert np.max(np.abs(shown[0] + shown[1] + shown[2] - shown[3])) <= 3 * 0.5e-3


def test_rodrigues_readout_never_shows_negative_zero():
    # A half turn about x: sinθ ≈ 1.2e-16 makes entries like -1.2e-16 that round to -0.00.
    tex = rodrigues_readout([1, 0, 0], np.pi)
    assert "-0.00" not in tex


def test_rodrigues_readout_refuses_batches_and_bad_decimals():
    with pytest.raises(ValueError, match=r"axis must be one 3-vector of shape \(3,\)"):
        rodrigues_readout([[0, 0, 1], [1, 0, 0]], 1.0)
    with pytest.raises(ValueError, match="single angle"):
        rodrigues_readout([0, 0, 1], [1.0, 2.0])
    with pytest.raises(ValueError, match="between 0 and 6"):
        rodrigues_readout([0, 0, 1], 1.0, decimals=9)
    with pytest.raises(TypeError, match="decimals must be an integer"):
        rodrigues_readout([0, 0, 1], 1.0, decimals=2.0)
    with pytest.raises(ValueError, match=r"axis must be a unit vector: ‖axis‖ = 0\.5"):
        rodrigues_readout([0, 0, 0.5], 1.0)


# --------------------------------------------------------------------------------------------
# draw_rotated_frame and draw_rodrigues_terms: the geometry on the axes
# --------------------------------------------------------------------------------------------

ANGLES = [
    (0.0, 0.0, np.pi / 2),
    (np.pi / 4, np.pi / 4, np.pi / 3),
    (2.2, -1.3, 5.0),
    (np.pi / 2, 0.0, 0.0),
]


@pytest.mark.parametrize("polar, azimuth, theta", ANGLES)
def test_draw_rotated_frame_draws_world_frame_body_frame_and_axis(polar, azimuth, theta):
    fig, ax = plotting.axes3d("t")
    drawn = draw_rotated_frame(ax, polar, azimuth, theta)
    R = rotated_frame(polar, azimuth, theta)
    w = axis_from_spherical(polar, azimuth)
    assert np.linalg.norm(drawn.R - R) <= TOL and np.linalg.norm(drawn.axis - w) <= TOL
    assert np.linalg.norm(drawn.points - R.T) <= TOL
    origin = np.zeros(3)
    for i in range(3):
        assert has_arrow(ax, origin, np.eye(3)[i])  # world axis e_i
        assert has_arrow(ax, origin, R[:, i])  # body axis R e_i (eq. 26)
    assert has_arrow(ax, origin, w)  # the axis of rotation
    assert len(arrows_on(ax)) == 7
    plt.close(fig)


@pytest.mark.parametrize("polar, azimuth, theta", ANGLES)
def test_draw_rotated_frame_arcs_carry_world_axes_to_body_axes(polar, azimuth, theta):
    fig, ax = plotting.axes3d("t")
    drawn = draw_rotated_frame(ax, polar, azimuth, theta)
    R, w = drawn.R, drawn.axis
    moving = [i for i in range(3) if np.linalg.norm(np.eye(3)[i] - (w @ np.eye(3)[i]) * w) > TOL]
    assert len(drawn.arcs) == (len(moving) if theta != 0.0 else 0)
    drawn_lines = lines_on(ax)
    for arc, i in zip(drawn.arcs, moving):
        assert np.linalg.norm(arc[0] - np.eye(3)[i]) <= TOL
        assert np.linalg.norm(arc[-1] - R[:, i]) <= 1e-9
        radius = np.linalg.norm(arc - np.outer(arc @ w, w), axis=1)  # distance from the axis
        assert np.ptp(radius) <= 1e-9
        assert any(line.shape == arc.shape and np.allclose(line, arc) for line in drawn_lines)
    plt.close(fig)


def test_draw_rotated_frame_about_a_world_axis_draws_no_arc_for_that_axis():
    fig, ax = plotting.axes3d("t")
    drawn = draw_rotated_frame(ax, 0.0, 0.0, 1.0)  # about z: z_A does not move
    assert len(drawn.arcs) == 2
    plt.close(fig)


def test_draw_rotated_frame_refuses_2d_axes_and_arrays():
    fig, ax = plt.subplots()
    with pytest.raises(TypeError, match="needs a 3D axes"):
        draw_rotated_frame(ax, 0.1, 0.2, 0.3)
    plt.close(fig)
    fig, ax = plotting.axes3d("t")
    with pytest.raises(ValueError, match="theta must be a single angle"):
        draw_rotated_frame(ax, 0.1, 0.2, [0.3, 0.4])
    plt.close(fig)


@pytest.mark.parametrize("polar, azimuth, theta", ANGLES)
@pytest.mark.parametrize("q0", [Q0, (0.3, -0.8, 0.6)])
def test_draw_rodrigues_terms_chain_lands_on_the_rotated_point(polar, azimuth, theta, q0):
    fig, ax = plotting.axes3d("t")
    drawn = draw_rodrigues_terms(ax, polar, azimuth, theta, q0=q0)
    w = axis_from_spherical(polar, azimuth)
    q = so3.exp(w, theta) @ np.asarray(q0)
    expected_terms = np.stack(rodrigues_vectors(w, theta, q0))
    assert np.linalg.norm(drawn.terms - expected_terms) <= TOL
    assert np.linalg.norm(drawn.q - q) <= TOL
    chain = drawn.points
    assert np.linalg.norm(chain[0]) == 0.0 and np.linalg.norm(chain[-1] - q) <= TOL
    for k in range(3):  # each term drawn from the tip of the previous one
        if np.linalg.norm(expected_terms[k]) > 0:
            assert has_arrow(ax, chain[k], chain[k + 1])
    assert has_arrow(ax, np.zeros(3), q)  # the result, from the origin
    assert has_arrow(ax, np.zeros(3), w)  # the axis
    plt.close(fig)


@pytest.mark.parametrize("polar, azimuth, theta", ANGLES[:3])  # ANGLES[3]: the axis is q0
def test_draw_rodrigues_terms_circle_is_the_orbit_of_q0(polar, azimuth, theta):
    fig, ax = plotting.axes3d("t")
    drawn = draw_rodrigues_terms(ax, polar, azimuth, theta)
    w, q0 = drawn.axis, np.asarray(Q0)
    circle = drawn.circle
    assert circle is not None
    center = (w @ q0) * w
    radius = np.linalg.norm(q0 - center)
    assert np.max(np.abs(np.linalg.norm(circle - center, axis=1) - radius)) <= 1e-9
    assert np.max(np.abs((circle - center) @ w)) <= 1e-9  # in the plane normal to the axis
    # the rotated point lies on the drawn circle
    assert abs(np.linalg.norm(drawn.q - center) - radius) <= TOL
    assert abs((drawn.q - center) @ w) <= TOL
    plt.close(fig)


def test_draw_rodrigues_terms_with_q0_on_the_axis_draws_no_circle():
    fig, ax = plotting.axes3d("t")
    drawn = draw_rodrigues_terms(ax, np.pi / 2, 0.0, 1.0, q0=(1.0, 0.0, 0.0))  # axis = x = q0
    assert drawn.circle is None
    assert np.linalg.norm(drawn.terms[1:]) <= TOL
    plt.close(fig)


def test_draw_rodrigues_terms_refuses_bad_q0():
    fig, ax = plotting.axes3d("t")
    with pytest.raises(
        ValueError, match=r"q0 must be one 3-vector of shape \(3,\), got shape \(2, 3\)"
    ):
        draw_rodrigues_terms(ax, 0.1, 0.2, 0.3, q0=np.zeros((2, 3)))
    with pytest.raises(ValueError, match="q0 contains NaN"):
        draw_rodrigues_terms(ax, 0.1, 0.2, 0.3, q0=(np.nan, 0, 0))
    plt.close(fig)


# --------------------------------------------------------------------------------------------
# The camera of the drawings: elev/azim move the view, never the geometry
# --------------------------------------------------------------------------------------------

DRAWINGS = [draw_rotated_frame, draw_rodrigues_terms]
VIEWS = [
    (VIEW_ELEV, VIEW_AZIM),
    (0.0, -90.0),
    (90.0, 0.0),
    (-90.0, 180.0),
    (35.5, 12.25),
    (-30.0, -180.0),
]


def geometry(ax):
    """Everything drawn on ``ax``, in world coordinates: its arrows and its lines."""
    return arrows_on(ax), lines_on(ax)


def same_geometry(a, b):
    (arrows_a, lines_a), (arrows_b, lines_b) = a, b
    return (
        arrows_a.shape == arrows_b.shape
        and np.linalg.norm(arrows_a - arrows_b) <= TOL
        and len(lines_a) == len(lines_b)
        and all(
            x.shape == y.shape and np.linalg.norm(x - y) <= TOL for x, y in zip(lines_a, lines_b)
        )
    )


def test_same_geometry_sees_a_different_rotation():
    """The check used below is not vacuous: another angle gives another drawing."""
    fig, ax = plotting.axes3d("a")
    draw_rotated_frame(ax, 0.4, 0.3, 1.0)
    fig2, ax2 = plotting.axes3d("b")
    draw_rotated_frame(ax2, 0.4, 0.3, 1.0 + 1e-6)
    assert same_geometry(geometry(ax), geometry(ax))
    assert not same_geometry(geometry(ax), geometry(ax2))
    plt.close(fig)
    plt.close(fig2)


def test_view_defaults_are_the_fixed_view_of_axes3d():
    params = inspect.signature(plotting.axes3d).parameters
    assert (
        (VIEW_ELEV, VIEW_AZIM) == (params["elev"].default, params["azim"].default) == (20.0, -60.0)
    )
    for draw in DRAWINGS:
        params = inspect.signature(draw).parameters
        assert params["elev"].default == VIEW_ELEV and params["azim"].default == VIEW_AZIM
        # keyword-only: a fifth positional number cannot be taken for a camera angle
        assert params["elev"].kind is inspect.Parameter.KEYWORD_ONLY
        assert params["azim"].kind is inspect.Parameter.KEYWORD_ONLY


@pytest.mark.parametrize("draw", DRAWINGS)
def test_drawing_without_a_view_uses_the_default_camera(draw):
    fig, ax = plotting.axes3d("t", elev=60.0, azim=10.0)  # another camera before drawing
    draw(ax, 0.4, -1.0, 2.0)
    assert (ax.elev, ax.azim, ax.roll) == (VIEW_ELEV, VIEW_AZIM, 0.0)
    plt.close(fig)


@pytest.mark.parametrize("draw", DRAWINGS)
@pytest.mark.parametrize("elev, azim", VIEWS)
@pytest.mark.parametrize("polar, azimuth, theta", ANGLES[1:3])
def test_drawing_view_is_the_camera_asked_for_and_leaves_the_geometry_alone(
    draw, elev, azim, polar, azimuth, theta
):
    fig, ax = plotting.axes3d("default view")
    reference = draw(ax, polar, azimuth, theta)
    fig2, ax2 = plotting.axes3d("turned")
    drawn = draw(ax2, polar, azimuth, theta, elev=elev, azim=azim)
    assert (ax2.elev, ax2.azim, ax2.roll) == (elev, azim, 0.0)
    assert same_geometry(geometry(ax2), geometry(ax))
    assert np.linalg.norm(drawn.points - reference.points) <= TOL
    assert np.linalg.norm(drawn.R - rotated_frame(polar, azimuth, theta)) <= TOL
    # the limits (the equal-aspect cube) do not move with the camera either
    assert [ax2.get_xlim(), ax2.get_ylim(), ax2.get_zlim()] == [
        ax.get_xlim(),
        ax.get_ylim(),
        ax.get_zlim(),
    ]
    plt.close(fig)
    plt.close(fig2)


@pytest.mark.parametrize("draw", DRAWINGS)
def test_drawing_refuses_a_bad_camera_before_drawing_anything(draw):
    fig, ax = plotting.axes3d("t")
    before = len(ax.get_children())
    with pytest.raises(ValueError, match="elev contains NaN or infinity"):
        draw(ax, 0.1, 0.2, 0.3, elev=np.nan)
    with pytest.raises(ValueError, match="azim contains NaN or infinity"):
        draw(ax, 0.1, 0.2, 0.3, azim=np.inf)
    with pytest.raises(
        ValueError, match=r"azim must be a single viewing angle in degrees .* shape \(2,\)"
    ):
        draw(ax, 0.1, 0.2, 0.3, azim=[10.0, 20.0])
    with pytest.raises(TypeError, match="elev must be an array of real numbers"):
        draw(ax, 0.1, 0.2, 0.3, elev="top")
    assert len(ax.get_children()) == before  # nothing drawn ...
    assert (ax.elev, ax.azim) == (VIEW_ELEV, VIEW_AZIM)  # ... and the camera not moved
    plt.close(fig)


# --------------------------------------------------------------------------------------------
# The widgets: sliders above a live ipympl figure
# --------------------------------------------------------------------------------------------

EXPLORERS = [rotation_explorer, rodrigues_explorer]
SLIDERS = ["axis polar φ", "axis azimuth λ", "angle θ"]


def press_drag_release(canvas, start, end, steps=5):
    """Drag on the canvas with the left button as the browser would: the ipympl messages.

    ``start`` and ``end`` are in figure pixels from the top-left corner (the browser's
    convention); ipympl hands the events to matplotlib, whose 3D axes turn the camera.
    """

    def send(kind, xy, buttons):
        canvas._handle_message(
            canvas,
            {
                "type": kind,
                "x": xy[0],
                "y": xy[1],
                "button": 0,
                "buttons": buttons,
                "modifiers": [],
                "guiEvent": None,
            },
            [],
        )

    send("button_press", start, 1)
    for t in np.linspace(0, 1, steps)[1:]:
        send("motion_notify", (1 - t) * np.asarray(start) + t * np.asarray(end), 1)
    send("button_release", end, 0)


def axes_centre_from_top(ax):
    fig = ax.figure
    fig.canvas.draw()
    x, y = ax.bbox.x0 + ax.bbox.width / 2, ax.bbox.y0 + ax.bbox.height / 2
    return np.array([x, fig.bbox.height - y])


@pytest.mark.parametrize("make", EXPLORERS)
def test_explorer_has_three_release_only_sliders_above_an_ipympl_canvas(make):
    import ipywidgets

    widget = make()
    Canvas, _ = (
        interactive.widgets._ipympl_classes()
    )  # (a plain `import ipympl` switches the backend)
    assert list(widget.sliders) == SLIDERS
    for slider, (lo, hi) in zip(widget.sliders.values(), (POLAR_RANGE, AZIMUTH_RANGE, THETA_RANGE)):
        assert (slider.min, slider.max) == (lo, hi)
        assert slider.continuous_update is False  # one redraw per release, not per pixel
    # children[0]: the focus style (WCAG 2.4.7), then the sliders, the canvas, the line saying
    # what the keyboard does on the 3D view, the readout
    assert list(widget.children[1:][:3]) == list(widget.sliders.values())
    assert (
        isinstance(widget.children[1:][3], Canvas)
        and widget.children[1:][3] is widget.figure.canvas
    )
    assert (
        widget.figure.canvas.header_visible is False
        and widget.figure.canvas.footer_visible is False
    )
    assert widget.children[1:][4] is widget.key_help
    if make is rodrigues_explorer:
        assert (
            isinstance(widget.children[1:][5], ipywidgets.HTMLMath)
            and widget.readout is widget.children[1:][5]
        )
    else:
        assert len(widget.children) == 6 and widget.readout is None


@pytest.mark.parametrize("make", EXPLORERS)
def test_explorer_has_no_output_widget_for_nbclient_to_mimic(make):
    """Regression: headless nbconvert of chapter 03 sat 300 s after the explorer cell. nbclient
    mimics an Output widget by sending its state on the shell channel while it waits there for
    the cell's reply; the explorers were an ipywidgets.interactive with an Output widget."""
    import ipywidgets

    def descendants(widget):
        yield widget
        for child in getattr(widget, "children", ()):
            yield from descendants(child)

    widget = make()
    assert not any(isinstance(w, ipywidgets.Output) for w in descendants(widget))


@pytest.mark.parametrize("make", EXPLORERS)
def test_explorer_figure_is_not_a_pyplot_figure(make):
    # A pyplot figure would be shown once more (as a PNG) at the end of the cell.
    make()
    assert plt.get_fignums() == []


def test_making_an_explorer_leaves_the_notebook_backend_inline():
    """Regression: ``import ipympl`` switched pyplot to the widget backend, so every figure of
    the notebook after the Explore cell became a widget (and the inline PNG formatter was never
    hooked in). Run in a fresh IPython shell, as in a kernel."""
    code = "\n".join(
        [
            "from IPython.core.interactiveshell import InteractiveShell",
            "import matplotlib, matplotlib.figure",
            "ip = InteractiveShell.instance()",
            "ip.run_cell('import matplotlib; matplotlib.use(\"module://matplotlib_inline.backend_inline\")')",
            "ip.run_cell('import matplotlib.pyplot as plt')",
            "ip.run_cell('from course_lib.interactive import rotation_explorer')",
            "ip.run_cell('w = rotation_explorer()')",
            "ip.run_cell('fig, ax = plt.subplots()')",
            "png = ip.display_formatter.formatters['image/png']",
            "canvas = type(ip.user_ns['fig'].canvas).__module__",
            "hooked = bool(png.lookup_by_type(matplotlib.figure.Figure))",
            "print(matplotlib.get_backend(), canvas, hooked)",
        ]
    )
    out = subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        timeout=120,
        env={**os.environ, "MPLBACKEND": ""},
    )
    assert out.returncode == 0, out.stderr
    # (the shell prints the inline figure's text form first: it has no notebook to show it in)
    assert out.stdout.splitlines()[-1].split() == [
        "module://matplotlib_inline.backend_inline",
        "matplotlib.backends.backend_agg",
        "True",
    ]


def test_releasing_a_slider_redraws_the_same_figure_in_place():
    widget = rotation_explorer(polar=0.5, azimuth=0.2, theta=1.0)
    fig, ax = widget.figure, widget.ax
    assert np.linalg.norm(widget.result - rotated_frame(0.5, 0.2, 1.0)) <= TOL
    widget.sliders["angle θ"].value = 2.5
    assert np.linalg.norm(widget.result - rotated_frame(0.5, 0.2, 2.5)) <= TOL
    widget.sliders["axis polar φ"].value = 1.5
    assert np.linalg.norm(widget.result - rotated_frame(1.5, 0.2, 2.5)) <= TOL
    assert widget.figure is fig and fig.axes == [ax]
    assert r"$\theta$ = 2.50 rad" in ax.get_title()


@pytest.mark.parametrize("make", EXPLORERS)
def test_redraws_replace_the_drawing_instead_of_piling_it_up(make):
    widget = make()
    count = len(widget.ax.get_children())
    for theta in (0.5, 3.0, 6.0, 1.2):
        widget.sliders["angle θ"].value = theta
        assert len(widget.ax.get_children()) == count
    fresh = make(theta=1.2)
    assert same_geometry(geometry(widget.ax), geometry(fresh.ax))
    assert widget.ax.get_title() == fresh.ax.get_title()
    assert [t.get_text() for t in widget.ax.texts] == [t.get_text() for t in fresh.ax.texts]
    assert widget.snapshot() == fresh.snapshot()  # the same picture, pixel for pixel


def test_rodrigues_explorer_redraws_the_terms_and_the_readout():
    widget = rodrigues_explorer(theta=0.7)
    widget.sliders["axis azimuth λ"].value = -2.0
    w = axis_from_spherical(np.pi / 3, -2.0)
    assert np.linalg.norm(widget.result - np.stack(rodrigues_vectors(w, 0.7, Q0))) <= TOL
    assert np.linalg.norm(widget.result.sum(axis=0) - so3.exp(w, 0.7) @ Q0) <= TOL
    assert widget.readout.value == "$$" + rodrigues_readout(w, 0.7) + "$$"


@pytest.mark.parametrize("make", EXPLORERS)
def test_dragging_the_figure_turns_the_camera_but_not_the_geometry(make):
    widget = make()
    ax = widget.ax
    before = geometry(ax)
    assert (ax.elev, ax.azim) == (VIEW_ELEV, VIEW_AZIM)
    centre = axes_centre_from_top(ax)
    press_drag_release(widget.figure.canvas, centre, centre + [80, 40])
    assert abs(ax.azim - VIEW_AZIM) > 5 and abs(ax.elev - VIEW_ELEV) > 5
    assert same_geometry(geometry(ax), before)
    # a slider released afterwards redraws at the camera the mouse chose
    camera = (ax.elev, ax.azim)
    widget.sliders["angle θ"].value = 1.0
    assert (ax.elev, ax.azim) == camera


@pytest.mark.parametrize("make", EXPLORERS)
def test_explorer_stores_a_small_png_snapshot_with_alt_text_and_a_description(make):
    widget = make()
    data = widget._repr_mimebundle_()
    assert set(data) == {"application/vnd.jupyter.widget-view+json", "text/html", "text/plain"}
    assert data["text/plain"] == widget.description and "drag the 3D view" in widget.description
    alt, png = figure_alt_and_png(data["text/html"])
    assert alt == widget.alt_text() and alt.endswith("azimuth −60°.") and "θ = " in alt
    png = base64.b64decode(png)
    assert png.startswith(b"\x89PNG") and len(png) < 40_000
    from PIL import Image

    width, height = widget.figure.get_size_inches() * widget.figure.dpi
    assert Image.open(io.BytesIO(png)).size == (round(width), round(height))


@pytest.mark.parametrize("make, count", [(rotation_explorer, 8), (rodrigues_explorer, 1)])
def test_explorer_labels_do_not_overlap_at_the_first_view(make, count, screen_box):
    # x_A ... z_B, ω and B: eight labels in the rotation explorer (the Rodrigues terms are
    # named in a legend)
    ax = make().ax
    ax.figure.canvas.draw()
    renderer = ax.figure.canvas.get_renderer()
    boxes = {t.get_text(): screen_box(t, ax, renderer) for t in ax.texts if t.get_text()}
    assert len(boxes) == count
    names = sorted(boxes)
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            assert not boxes[a].overlaps(boxes[b]), f"labels {a!r} and {b!r} overlap"


def test_rodrigues_terms_are_large_enough_to_see_at_the_first_view():
    widget = rodrigues_explorer()
    ax = widget.ax
    ax.figure.canvas.draw()
    chain = np.concatenate([np.zeros((1, 3)), np.cumsum(widget.result, axis=0)])
    x, y, _ = proj3d.proj_transform(*chain.T, ax.get_proj())
    screen = ax.transData.transform(np.column_stack([x, y]))
    lengths = np.linalg.norm(np.diff(screen, axis=0), axis=1)  # pixels
    assert np.all(lengths >= 50), lengths  # at the old defaults two terms were 25 px long


@pytest.mark.parametrize("make", EXPLORERS)
@pytest.mark.parametrize(
    "elev, azim",
    [
        (VIEW_ELEV, VIEW_AZIM),
        (-45.0, 120.0),
        (-30.0, -60.0),
        (-90.0, 0.0),
        (45.0, -150.0),
        (90.0, 90.0),
    ],
)
def test_explorer_labels_stay_inside_the_figure_and_clear_of_the_title_at_any_camera(
    make, elev, azim
):
    # The mouse can look from below, where the x/y tick labels go to the top of the cube.
    ax = make(polar=2.5, azimuth=0.8, theta=1.0, elev=elev, azim=azim).ax
    fig = ax.figure
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    title = ax.title.get_window_extent(renderer)
    labels = [
        t.get_window_extent(renderer)
        for axis in (ax.xaxis, ax.yaxis, ax.zaxis)
        for t in axis.get_ticklabels() + [axis.label]
        if t.get_visible() and t.get_text()
    ]
    assert labels
    for box in labels:
        assert not box.overlaps(title)
        assert fig.bbox.y0 <= box.y0 and box.y1 <= fig.bbox.y1


def test_explorer_outside_ipython_prints_nothing(capsys):
    widget = rotation_explorer()
    widget.sliders["angle θ"].value = 0.5
    captured = capsys.readouterr()
    assert captured.out == "" and captured.err == ""


@pytest.mark.parametrize("make", EXPLORERS)
def test_explorer_refuses_initial_values_outside_the_sliders(make):
    with pytest.raises(ValueError, match=r"angle θ = 7 is outside the slider range \[0, 6.283\]"):
        make(theta=7.0)
    with pytest.raises(ValueError, match="axis polar φ"):
        make(polar=-0.1)
    with pytest.raises(ValueError, match="contains NaN"):
        make(azimuth=np.nan)
    with pytest.raises(ValueError, match="elev contains NaN or infinity"):
        make(elev=np.nan)
    with pytest.raises(TypeError, match="azim must be an array of real numbers"):
        make(azim="left")


def test_rodrigues_explorer_refuses_bad_q0():
    with pytest.raises(
        ValueError, match=r"q0 must be one 3-vector of shape \(3,\), got shape \(2, 3\)"
    ):
        rodrigues_explorer(q0=np.zeros((2, 3)))
    with pytest.raises(ValueError, match=r"q0 must be one 3-vector .* got shape \(4,\)"):
        rodrigues_explorer(q0=[1.0, 2.0, 3.0, 4.0])


# --------------------------------------------------------------------------------------------
# Spinning at unit angular velocity: the animation
# --------------------------------------------------------------------------------------------


def frames_of(html):
    """The embedded frames of the player, as PIL images."""
    from PIL import Image

    found = re.findall(r'frames\[\d+\] = "data:image/png;base64,([^"]+)"', html)
    return [Image.open(io.BytesIO(base64.b64decode(f.replace("\\n", "")))) for f in found]


def test_spin_animation_embeds_one_png_per_frame_at_real_time_speed():
    html = spin_animation(axis=(1, 1, 0), frames=4).data
    assert len(frames_of(html)) == 4
    # the player advances one frame per 2π/4 s: one radian per second
    interval = re.search(r"new Animation\(frames,\s*img_id,\s*slider_id,\s*([0-9.]+)", html)
    assert interval is not None
    assert abs(float(interval.group(1)) - 1000 * 2 * np.pi / 4) < 1.0  # whole milliseconds


def test_spin_animation_frames_are_large_enough_to_read():
    """Regression: the notebook's animation had 100 x 100 px frames (title cut, labels
    unreadable); the defaults give 360 px."""
    frames = frames_of(spin_animation(frames=2).data)
    assert [f.size for f in frames] == [(SPIN_PIXELS, SPIN_PIXELS)] * 2 == [(360, 360)] * 2


def test_spin_animation_title_fits_in_the_frame():
    html = spin_animation(frames=2).data
    first = np.asarray(frames_of(html)[0].convert("L"))
    assert first.shape == (360, 360)
    # the title row: dark pixels in the top band, none touching the left or right edge
    band = first[:40] < 128
    assert band.any() and not band[:, :3].any() and not band[:, -3:].any()


def test_spin_animation_closes_its_figure_so_it_is_not_shown_twice():
    before = plt.get_fignums()
    spin_animation(frames=2)
    assert plt.get_fignums() == before


def test_spin_animation_default_stays_small_enough_for_a_committed_notebook():
    html = spin_animation().data
    assert len(frames_of(html)) == 16
    assert len(html) < 200_000  # palette frames: 360 px at about 9 KB each


def test_regression_spin_animation_loads_nothing_from_a_cdn():
    """Issue 16: the player linked Font Awesome from a CDN for its button icons."""
    html = spin_animation(frames=2).data
    assert not re.search(r"https?://|(src|href)=\"//", html), "a URL in the player"
    assert "font-awesome" not in html and 'class="fa ' not in html
    buttons = re.findall(r"<button[^>]*>\s*<span aria-hidden=\"true\">([^<]+)</span>", html)
    assert len(buttons) == 9 and all(b.strip() for b in buttons)


def test_spin_animation_shows_its_first_frame_without_running_a_script():
    html = spin_animation(frames=3).data
    img = re.search(r'<img id="_anim_img[0-9a-f]+" src="data:image/png;base64,([^"]+)"', html)
    assert img is not None, "the player's <img> has no src: blank until a script runs"
    first = re.search(r'frames\[0\] = "data:image/png;base64,([^"]+)"', html).group(1)
    assert img.group(1) == first.replace("\\\n", "")
    assert "\\" not in img.group(1)


def test_spin_animation_refuses_bad_sizes():
    with pytest.raises(ValueError, match="at most 120"):
        spin_animation(frames=500)
    with pytest.raises(ValueError, match="dpi must be between 20 and 150"):
        spin_animation(dpi=300)
    with pytest.raises(ValueError, match="size must be between 1 and 8"):
        spin_animation(size=20)
    with pytest.raises(ValueError, match="axis must be non-zero to define a direction"):
        spin_animation(axis=(0, 0, 0))


# --------------------------------------------------------------------------------------------
# Without ipympl: the still picture and one line saying why
# --------------------------------------------------------------------------------------------


@pytest.mark.parametrize("make", [rotation_explorer, rodrigues_explorer, gimbal_explorer])
def test_explorer_without_ipympl_falls_back_to_its_still_picture_with_one_line(make, monkeypatch):
    def missing():
        raise ModuleNotFoundError("No module named 'ipympl'", name="ipympl")

    monkeypatch.setattr(interactive.widgets, "_ipympl_classes", missing)
    explorer = make()
    assert not explorer.live and explorer.children == ()
    bundle = explorer._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" not in bundle
    alt, png = figure_alt_and_png(bundle["text/html"].split("<p>")[0])
    png = base64.b64decode(png)
    assert png.startswith(b"\x89PNG") and len(png) > 5_000  # the figure, drawn
    assert alt == explorer.alt_text()
    why = explorer.why_still
    assert "ipympl" in why and "pip install ipympl" in why and "\n" not in why
    assert bundle["text/html"].count("<img") == 1 and why in bundle["text/html"]
    assert bundle["text/plain"].splitlines()[-1] == why


# --------------------------------------------------------------------------------------------
# The 3D view from the keyboard (WCAG 2.1.1, 2.1.2): arrow keys turn it, + and − zoom
# --------------------------------------------------------------------------------------------


def _key(widget, key):
    """The key as ipympl delivers it: a matplotlib key_press_event on the explorer's canvas."""
    from matplotlib.backend_bases import KeyEvent

    KeyEvent("key_press_event", widget.figure.canvas, key, 10, 10)._process()


@pytest.mark.parametrize("make", EXPLORERS)
def test_the_3d_view_turns_with_the_arrow_keys_and_zooms_with_plus_and_minus(make):
    widget = make()
    before = widget.snapshot()
    _key(widget, "right")
    assert (widget.ax.elev, widget.ax.azim) == (VIEW_ELEV, VIEW_AZIM + 10)
    _key(widget, "up")
    assert widget.ax.elev == VIEW_ELEV + 10
    assert widget.snapshot() != before  # redrawn
    assert "elevation 30°, azimuth −50°" in widget.alt_text()  # the name says the new camera
    zoom = widget._zoom
    _key(widget, "+")
    assert widget._zoom > zoom
    _key(widget, "-")
    _key(widget, "-")
    assert widget._zoom < zoom
    for _ in range(8):  # the zoom stays in its range (0.9 / 1.15**8 < 0.5), the elevation at 90
        _key(widget, "-")
        _key(widget, "up")
    assert widget._zoom >= 0.5 and widget.ax.elev == 90


def test_the_3d_view_documents_its_keys_and_ignores_matplotlibs_own(tmp_path, monkeypatch):
    """Regression: matplotlib's key map on the canvas ("s" saves a file, "q" closes, "l" turns
    on a log scale) went on receiving the keys ipympl sends."""
    monkeypatch.chdir(tmp_path)
    widget = rotation_explorer()
    assert interactive.widgets.KEYS_HELP in widget.key_help.value
    assert "arrow keys turn it" in widget.key_help.value and "Tab" in widget.key_help.value
    assert f'data-state="{html.escape(widget.alt_text(), quote=True)}"' in widget.key_help.value
    camera = (widget.ax.elev, widget.ax.azim)
    for key in ("s", "q", "l", "k", "g", "tab", "escape"):
        _key(widget, key)
    assert list(tmp_path.iterdir()) == [] and (widget.ax.elev, widget.ax.azim) == camera
    assert widget.ax.get_xscale() == "linear"


def test_the_page_script_lets_tab_and_escape_leave_the_3d_view():
    """Regression (WCAG 2.1.2, keyboard trap): ipympl's canvas calls preventDefault() on every
    keydown; the explorer's script stops Tab and Escape in the capture phase, before it."""
    js = interactive.widgets._SLIDER_NAMES_JS
    assert "addEventListener('keydown', keys, true)" in js
    assert "event.key === 'Tab'" in js and "event.key === 'Escape'" in js
    assert "preventDefault" not in js  # Tab keeps its default: the next focusable element


def test_regression_the_players_repetition_mode_is_a_radio_group_not_a_form():
    """HTML_CodeSniffer (WCAG 3.2.2, H32.2): matplotlib's player put Once/Loop/Reflect in a
    <form> without a submit button; a radio group with its own radio names, read by id."""
    html = spin_animation(frames=3).data
    assert "<form" not in html and html.count('role="radiogroup"') == 1
    group = re.search(r'<div role="radiogroup" aria-label="Repetition mode" id="(\w+)"', html)
    assert html.count(f'name="{group.group(1)}_state"') == 3  # not "state": page-wide by name
    assert "document[this.loop_select_id]" not in html
    assert "getElementById(this.loop_select_id).querySelectorAll('input[type=radio]')" in html
    # each radio inside its label (IBM's engine in JupyterLab: no label found by for= alone)
    wrapped = r'<label for="[^"]+"><input type="radio"[^>]* aria-label="(\w+)"> (\w+)</label>'
    names = re.findall(wrapped, html)
    assert names == [("Once", "Once"), ("Loop", "Loop"), ("Reflect", "Reflect")]
