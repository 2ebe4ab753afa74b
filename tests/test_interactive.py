"""Tests of course_lib.interactive: the pure functions, the drawings, the widgets, the animation.

Everything runs on the Agg backend and closes its figures. The widgets are exercised without a
browser: moving a slider is setting its value, and what would be displayed is intercepted.
"""

import inspect
import io
import re

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402
from scipy.spatial.transform import Rotation  # noqa: E402

from course_lib import interactive, plotting, so3  # noqa: E402
from course_lib.interactive import (  # noqa: E402
    AZIMUTH_RANGE,
    POLAR_RANGE,
    Q0,
    THETA_RANGE,
    VIEW_AZIM,
    VIEW_AZIM_RANGE,
    VIEW_ELEV,
    VIEW_ELEV_RANGE,
    axis_from_spherical,
    draw_rodrigues_terms,
    draw_rotated_frame,
    rodrigues_explorer,
    rodrigues_readout,
    rodrigues_terms,
    rodrigues_vectors,
    rotated_frame,
    rotation_explorer,
    spin_animation,
    spin_rotations,
    spin_times,
)
from course_lib.tolerance import TOL  # noqa: E402

polars = st.floats(*POLAR_RANGE)
azimuths = st.floats(*AZIMUTH_RANGE)
thetas = st.floats(*THETA_RANGE)
coords = st.floats(-2.0, 2.0)
points = st.tuples(coords, coords, coords)


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
# axis_from_spherical
# --------------------------------------------------------------------------------------------


@given(polars, azimuths)
def test_axis_from_spherical_is_unit(polar, azimuth):
    w = axis_from_spherical(polar, azimuth)
    assert w.shape == (3,) and w.dtype == np.float64
    assert abs(np.linalg.norm(w) - 1.0) <= TOL


@given(st.floats(0.01, np.pi - 0.01), st.floats(-np.pi + 0.01, np.pi - 0.01))
def test_axis_from_spherical_round_trips_through_arccos_and_atan2(polar, azimuth):
    x, y, z = axis_from_spherical(polar, azimuth)
    assert abs(np.arccos(np.clip(z, -1, 1)) - polar) <= 1e-7
    assert abs(np.arctan2(y, x) - azimuth) <= 1e-7


def test_axis_from_spherical_poles_and_equator():
    assert np.allclose(axis_from_spherical(0.0, 1.234), [0, 0, 1], atol=TOL, rtol=0)
    assert np.allclose(axis_from_spherical(np.pi, -0.5), [0, 0, -1], atol=TOL, rtol=0)
    assert np.allclose(axis_from_spherical(np.pi / 2, 0.0), [1, 0, 0], atol=TOL, rtol=0)
    assert np.allclose(axis_from_spherical(np.pi / 2, -np.pi / 2), [0, -1, 0], atol=TOL, rtol=0)


def test_axis_from_spherical_broadcasts():
    polar = np.linspace(0, np.pi, 4)[:, None]
    azimuth = np.linspace(-np.pi, np.pi, 5)[None, :]
    w = axis_from_spherical(polar, azimuth)
    assert w.shape == (4, 5, 3)
    assert np.allclose(w[2, 3], axis_from_spherical(polar[2, 0], azimuth[0, 3]))


def test_axis_from_spherical_refuses_nan_and_strings_and_mismatched_shapes():
    with pytest.raises(ValueError, match="polar contains NaN"):
        axis_from_spherical(np.nan, 0.0)
    with pytest.raises(TypeError, match="azimuth must be an array of real numbers"):
        axis_from_spherical(0.0, "east")
    with pytest.raises(ValueError, match="must broadcast together"):
        axis_from_spherical([0.1, 0.2], [0.1, 0.2, 0.3])


# --------------------------------------------------------------------------------------------
# rotated_frame
# --------------------------------------------------------------------------------------------


@given(polars, azimuths, thetas)
@settings(max_examples=50)
def test_rotated_frame_matches_scipy_rotvec(polar, azimuth, theta):
    w = axis_from_spherical(polar, azimuth)
    R = rotated_frame(polar, azimuth, theta)
    assert so3.is_rotation(R)
    assert np.linalg.norm(R - Rotation.from_rotvec(w * theta).as_matrix()) <= TOL
    assert np.linalg.norm(R @ w - w) <= TOL  # the axis does not move


def test_rotated_frame_batches_over_angles():
    theta = np.linspace(0, 2 * np.pi, 7)
    R = rotated_frame(0.3, 1.1, theta)
    assert R.shape == (7, 3, 3)
    assert np.allclose(R[3], rotated_frame(0.3, 1.1, theta[3]))


# --------------------------------------------------------------------------------------------
# rodrigues_terms and rodrigues_vectors
# --------------------------------------------------------------------------------------------


@given(polars, azimuths, st.floats(-10.0, 10.0))
@settings(max_examples=60)
def test_rodrigues_terms_sum_to_exp(polar, azimuth, theta):
    w = axis_from_spherical(polar, azimuth)
    identity, sin_term, cos_term = rodrigues_terms(w, theta)
    R = so3.exp(w, theta)
    assert np.linalg.norm(identity + sin_term + cos_term - R) <= TOL
    assert np.linalg.norm(identity - np.eye(3)) == 0.0
    assert np.linalg.norm(sin_term + sin_term.T) <= TOL  # sinθ ω̂ is skew: the odd part of R
    assert np.linalg.norm(cos_term - cos_term.T) <= TOL  # (1 − cosθ) ω̂² is symmetric


@given(polars, azimuths, st.floats(-10.0, 10.0))
@settings(max_examples=40)
def test_rodrigues_terms_match_the_series_split_of_eq_158(polar, azimuth, theta):
    """Term 1 is the odd powers of the series, term 2 the even powers above zero."""
    w = axis_from_spherical(polar, azimuth)
    W = so3.hat(w)
    _, sin_term, cos_term = rodrigues_terms(w, theta)
    # Even and odd parts of e^{ŵθ}: (R − Rᵀ)/2 = sinθ ŵ, (R + Rᵀ)/2 − I = (1 − cosθ) ŵ².
    R = Rotation.from_rotvec(w * theta).as_matrix()
    assert np.linalg.norm(sin_term - (R - R.T) / 2) <= TOL
    assert np.linalg.norm(cos_term - ((R + R.T) / 2 - np.eye(3))) <= TOL
    assert np.linalg.norm(sin_term - np.sin(theta) * W) <= TOL


def test_rodrigues_terms_batch_shapes_broadcast():
    axes = axis_from_spherical(np.linspace(0, np.pi, 5), 0.4)  # (5, 3)
    theta = np.linspace(0, 3, 5)
    terms = rodrigues_terms(axes, theta)
    assert [t.shape for t in terms] == [(5, 3, 3)] * 3
    assert np.allclose(sum(terms), so3.exp(axes, theta))
    terms = rodrigues_terms([0, 0, 1], np.zeros((2, 4)))
    assert [t.shape for t in terms] == [(2, 4, 3, 3)] * 3


def test_rodrigues_terms_refuses_non_unit_axis_instead_of_returning_a_wrong_sum():
    with pytest.raises(ValueError, match=r"axis is not a unit vector: ‖axis‖ = 2, .* > TOL = 1e-09"):
        rodrigues_terms([0, 0, 2], 1.0)
    with pytest.raises(ValueError, match=r"at batch index \(1,\)"):
        rodrigues_terms([[0, 0, 1], [0, 1e-3, 1]], 1.0)


def test_rodrigues_terms_refuses_bad_shapes_and_values():
    with pytest.raises(ValueError, match=r"shape \(\.\.\., 3\)"):
        rodrigues_terms([1, 0], 1.0)
    with pytest.raises(ValueError, match="does not broadcast"):
        rodrigues_terms([[0, 0, 1], [1, 0, 0]], [1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="theta contains NaN"):
        rodrigues_terms([0, 0, 1], np.inf)


@given(polars, azimuths, thetas, points)
@settings(max_examples=60)
def test_rodrigues_vectors_add_up_to_the_rotated_point(polar, azimuth, theta, q0):
    w = axis_from_spherical(polar, azimuth)
    first, sin_vec, cos_vec = rodrigues_vectors(w, theta, q0)
    assert np.array_equal(first, np.asarray(q0, float))
    assert np.linalg.norm(first + sin_vec + cos_vec - so3.exp(w, theta) @ q0) <= TOL
    # sinθ ω̂q0 = sinθ (ω × q0) is orthogonal to the axis and to q0 ...
    assert abs(sin_vec @ w) <= TOL and abs(sin_vec @ np.asarray(q0)) <= TOL
    # ... and (1 − cosθ) ω̂²q0 = (1 − cosθ)(ω ωᵀq0 − q0) (eq. 141) points at the axis.
    expected = (1 - np.cos(theta)) * ((w @ q0) * w - np.asarray(q0))
    assert np.linalg.norm(cos_vec - expected) <= TOL


def test_rodrigues_vectors_vanish_for_a_point_on_the_axis():
    w = unit([1, 2, 2])
    q0, sin_vec, cos_vec = rodrigues_vectors(w, 2.5, 3 * w)
    assert np.linalg.norm(sin_vec) <= TOL and np.linalg.norm(cos_vec) <= TOL


def test_rodrigues_vectors_broadcast_points_against_angles():
    parts = rodrigues_vectors([0, 0, 1], np.array([0.0, np.pi]), [[1, 0, 0], [0, 1, 0]])
    assert [p.shape for p in parts] == [(2, 3)] * 3
    assert np.allclose(sum(parts), [[1, 0, 0], [0, -1, 0]])
    with pytest.raises(ValueError, match="q0 of shape"):
        rodrigues_vectors([0, 0, 1], np.zeros(2), np.zeros((3, 3)))


# --------------------------------------------------------------------------------------------
# rodrigues_readout
# --------------------------------------------------------------------------------------------


def matrices_in(tex):
    """The numeric matrices written in a LaTeX string, as (3, 3) arrays."""
    blocks = re.findall(r"\\begin\{bmatrix\}(.*?)\\end\{bmatrix\}", tex)
    return [np.array([[float(x) for x in row.split("&")] for row in b.split(r"\\")]) for b in blocks]


@pytest.mark.parametrize("polar, azimuth, theta", [(0.3, 1.0, 0.5), (2.0, -2.5, 4.0), (np.pi / 2, 0, np.pi)])
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
    with pytest.raises(ValueError, match=r"single 3-vector"):
        rodrigues_readout([[0, 0, 1], [1, 0, 0]], 1.0)
    with pytest.raises(ValueError, match="single angle"):
        rodrigues_readout([0, 0, 1], [1.0, 2.0])
    with pytest.raises(ValueError, match="between 0 and 6"):
        rodrigues_readout([0, 0, 1], 1.0, decimals=9)
    with pytest.raises(TypeError, match="decimals must be an integer"):
        rodrigues_readout([0, 0, 1], 1.0, decimals=2.0)
    with pytest.raises(ValueError, match="not a unit vector"):
        rodrigues_readout([0, 0, 0.5], 1.0)


# --------------------------------------------------------------------------------------------
# draw_rotated_frame and draw_rodrigues_terms: the geometry on the axes
# --------------------------------------------------------------------------------------------

ANGLES = [(0.0, 0.0, np.pi / 2), (np.pi / 4, np.pi / 4, np.pi / 3), (2.2, -1.3, 5.0), (np.pi / 2, 0.0, 0.0)]


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
    with pytest.raises(ValueError, match=r"q0 must be a single 3-vector"):
        draw_rodrigues_terms(ax, 0.1, 0.2, 0.3, q0=np.zeros((2, 3)))
    with pytest.raises(ValueError, match="q0 contains NaN"):
        draw_rodrigues_terms(ax, 0.1, 0.2, 0.3, q0=(np.nan, 0, 0))
    plt.close(fig)


# --------------------------------------------------------------------------------------------
# The camera of the drawings: elev/azim move the view, never the geometry
# --------------------------------------------------------------------------------------------

DRAWINGS = [draw_rotated_frame, draw_rodrigues_terms]
VIEWS = [(VIEW_ELEV, VIEW_AZIM), (0.0, -90.0), (90.0, 0.0), (-90.0, 180.0), (35.5, 12.25), (-30.0, -180.0)]


def geometry(ax):
    """Everything drawn on ``ax``, in world coordinates: its arrows and its lines."""
    return arrows_on(ax), lines_on(ax)


def same_geometry(a, b):
    (arrows_a, lines_a), (arrows_b, lines_b) = a, b
    return (
        arrows_a.shape == arrows_b.shape
        and np.linalg.norm(arrows_a - arrows_b) <= TOL
        and len(lines_a) == len(lines_b)
        and all(x.shape == y.shape and np.linalg.norm(x - y) <= TOL for x, y in zip(lines_a, lines_b))
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
    assert (VIEW_ELEV, VIEW_AZIM) == (params["elev"].default, params["azim"].default) == (20.0, -60.0)
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
def test_drawing_view_is_the_camera_asked_for_and_leaves_the_geometry_alone(draw, elev, azim, polar,
                                                                             azimuth, theta):
    fig, ax = plotting.axes3d("default view")
    reference = draw(ax, polar, azimuth, theta)
    fig2, ax2 = plotting.axes3d("turned")
    drawn = draw(ax2, polar, azimuth, theta, elev=elev, azim=azim)
    assert (ax2.elev, ax2.azim, ax2.roll) == (elev, azim, 0.0)
    assert same_geometry(geometry(ax2), geometry(ax))
    assert np.linalg.norm(drawn.points - reference.points) <= TOL
    assert np.linalg.norm(drawn.R - rotated_frame(polar, azimuth, theta)) <= TOL
    # the limits (the equal-aspect cube) do not move with the camera either
    assert [ax2.get_xlim(), ax2.get_ylim(), ax2.get_zlim()] == [ax.get_xlim(), ax.get_ylim(), ax.get_zlim()]
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
    with pytest.raises(ValueError, match=r"azim must be a single viewing angle in degrees .* shape \(2,\)"):
        draw(ax, 0.1, 0.2, 0.3, azim=[10.0, 20.0])
    with pytest.raises(TypeError, match="elev must be an array of real numbers"):
        draw(ax, 0.1, 0.2, 0.3, elev="top")
    assert len(ax.get_children()) == before  # nothing drawn ...
    assert (ax.elev, ax.azim) == (VIEW_ELEV, VIEW_AZIM)  # ... and the camera not moved
    plt.close(fig)


# --------------------------------------------------------------------------------------------
# The widgets
# --------------------------------------------------------------------------------------------


class Shown(list):
    """The display calls of a widget (``"clear"`` or the type names shown), and in ``figures``
    the figures themselves, in order."""

    def __init__(self):
        super().__init__()
        self.figures = []


@pytest.fixture
def shown(monkeypatch):
    """Pretend to be in IPython and record what the widgets would display."""
    import IPython.display

    calls = Shown()
    monkeypatch.setattr(interactive, "_in_ipython", lambda: True)
    monkeypatch.setattr(IPython.display, "clear_output", lambda wait=False: calls.append("clear"))

    def fake_display(*objs):
        # Render figures now: a figure that is already closed still saves to PNG.
        calls.append([type(o).__name__ for o in objs])
        for obj in objs:
            if isinstance(obj, matplotlib.figure.Figure):
                assert obj.axes and obj.axes[0].get_title()
                calls.figures.append(obj)

    monkeypatch.setattr(IPython.display, "display", fake_display)
    return calls


def sliders_of(widget):
    import ipywidgets

    return {s.description: s for s in widget.children if isinstance(s, ipywidgets.FloatSlider)}


ROTATION_SLIDERS = ["axis polar φ", "axis azimuth λ", "angle θ"]
VIEW_SLIDERS = ["view elev (°)", "view azim (°)"]


@pytest.mark.parametrize("make", [rotation_explorer, rodrigues_explorer])
def test_explorer_has_five_release_only_sliders_with_the_documented_ranges(make):
    import ipywidgets

    widget = make()
    assert isinstance(widget, ipywidgets.interactive)
    sliders = sliders_of(widget)
    # three for the rotation (radians), then two for the camera (degrees), labelled "view"
    assert list(sliders) == ROTATION_SLIDERS + VIEW_SLIDERS
    ranges = (POLAR_RANGE, AZIMUTH_RANGE, THETA_RANGE, VIEW_ELEV_RANGE, VIEW_AZIM_RANGE)
    assert VIEW_ELEV_RANGE == (-90.0, 90.0) and VIEW_AZIM_RANGE == (-180.0, 180.0)
    for slider, (lo, hi) in zip(sliders.values(), ranges):
        assert (slider.min, slider.max) == (lo, hi)
        assert slider.continuous_update is False  # one redraw per release, not per pixel
    assert [sliders[d].step for d in VIEW_SLIDERS] == [1.0, 1.0]  # whole degrees
    assert [sliders[d].readout_format for d in VIEW_SLIDERS] == [".0f", ".0f"]
    # the camera starts at the fixed view the figures had before it could be turned
    assert (sliders["view elev (°)"].value, sliders["view azim (°)"].value) == (VIEW_ELEV, VIEW_AZIM)
    assert isinstance(widget.children[-1], ipywidgets.Output)


@pytest.mark.parametrize("make", [rotation_explorer, rodrigues_explorer])
def test_explorer_takes_an_initial_camera(make):
    sliders = sliders_of(make(elev=-45.0, azim=150.0))
    assert (sliders["view elev (°)"].value, sliders["view azim (°)"].value) == (-45.0, 150.0)


def rendered(fig):
    """The PNG bytes of a figure (closed figures still render)."""
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    return buf.getvalue()


@pytest.mark.parametrize("make", [rotation_explorer, rodrigues_explorer])
def test_moving_a_view_slider_turns_the_camera_but_not_the_geometry(make, shown):
    widget = make(polar=1.1, azimuth=-0.4, theta=2.0)
    result = np.array(widget.result)
    sliders = sliders_of(widget)
    sliders["view azim (°)"].value = 30.0
    sliders["view elev (°)"].value = -45.0
    assert len(shown.figures) == 3  # the first figure, then one redraw per slider moved
    first, turned, tilted = shown.figures
    cameras = [(f.axes[0].elev, f.axes[0].azim) for f in shown.figures]
    assert cameras == [(VIEW_ELEV, VIEW_AZIM), (VIEW_ELEV, 30.0), (-45.0, 30.0)]
    # the drawn geometry, the titles (axis and angle) and the result stay as they were
    for fig in (turned, tilted):
        assert same_geometry(geometry(fig.axes[0]), geometry(first.axes[0]))
        assert fig.axes[0].get_title() == first.axes[0].get_title()
    assert np.linalg.norm(widget.result - result) <= TOL
    # ... while the picture does change (what the browser test sees when a slider is dragged)
    pngs = [rendered(f) for f in shown.figures]
    assert pngs[0] != pngs[1] and pngs[1] != pngs[2]


def test_rotation_explorer_redraws_when_a_slider_moves():
    widget = rotation_explorer(polar=0.5, azimuth=0.2, theta=1.0)
    assert np.linalg.norm(widget.result - rotated_frame(0.5, 0.2, 1.0)) <= TOL
    sliders = sliders_of(widget)
    sliders["angle θ"].value = 2.5
    assert np.linalg.norm(widget.result - rotated_frame(0.5, 0.2, 2.5)) <= TOL
    sliders["axis polar φ"].value = 1.5
    assert np.linalg.norm(widget.result - rotated_frame(1.5, 0.2, 2.5)) <= TOL


def test_rodrigues_explorer_redraws_when_a_slider_moves():
    widget = rodrigues_explorer(theta=0.7)
    sliders = sliders_of(widget)
    sliders["axis azimuth λ"].value = -2.0
    w = axis_from_spherical(np.pi / 4, -2.0)
    assert np.linalg.norm(widget.result - np.stack(rodrigues_vectors(w, 0.7, Q0))) <= TOL
    assert np.linalg.norm(widget.result.sum(axis=0) - so3.exp(w, 0.7) @ Q0) <= TOL


def test_explorer_displays_exactly_one_figure_per_redraw_and_leaves_none_open(shown):
    # Under the inline backend an unclosed figure is shown a second time at the end of the cell.
    widget = rotation_explorer()
    sliders_of(widget)["angle θ"].value = 1.5
    assert shown == ["clear", ["Figure"], "clear", ["Figure"]]
    assert plt.get_fignums() == []


@pytest.mark.parametrize("make", [rotation_explorer, rodrigues_explorer])
@pytest.mark.parametrize("elev, azim", [(VIEW_ELEV, VIEW_AZIM), (-45.0, 120.0), (-30.0, -60.0),
                                        (-90.0, 0.0), (45.0, -150.0), (90.0, 90.0)])
def test_explorer_labels_stay_clear_of_the_title_at_any_camera(make, elev, azim, shown):
    # Seen from below, the x/y tick labels move to the top of the cube, towards the title.
    make(polar=2.5, azimuth=0.8, theta=1.0, elev=elev, azim=azim)
    (fig,) = shown.figures
    ax = fig.axes[0]
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    title = ax.title.get_window_extent(renderer)
    labels = [t.get_window_extent(renderer) for axis in (ax.xaxis, ax.yaxis, ax.zaxis)
              for t in axis.get_ticklabels() + [axis.label] if t.get_visible() and t.get_text()]
    assert labels
    for box in labels:
        assert not box.overlaps(title)
        assert fig.bbox.y0 <= box.y0 and box.y1 <= fig.bbox.y1


def test_rodrigues_explorer_displays_the_figure_and_the_matrix_readout(shown):
    rodrigues_explorer()
    assert shown == ["clear", ["Figure", "Math"]]
    assert plt.get_fignums() == []


def test_explorer_outside_ipython_prints_nothing(capsys):
    widget = rotation_explorer()
    sliders_of(widget)["angle θ"].value = 0.5
    captured = capsys.readouterr()
    assert captured.out == "" and captured.err == ""


@pytest.mark.parametrize("make", [rotation_explorer, rodrigues_explorer])
def test_explorer_refuses_initial_values_outside_the_sliders(make):
    with pytest.raises(ValueError, match=r"angle θ = 7 is outside the slider range \[0, 6.283\]"):
        make(theta=7.0)
    with pytest.raises(ValueError, match="axis polar φ"):
        make(polar=-0.1)
    with pytest.raises(ValueError, match="contains NaN"):
        make(azimuth=np.nan)
    out_of_range = r"view elev \(°\) = 100 is outside the slider range \[-90, 90\] \(degrees\)"
    with pytest.raises(ValueError, match=out_of_range):
        make(elev=100.0)
    with pytest.raises(ValueError, match=r"view azim \(°\) = -200 is outside .* \[-180, 180\]"):
        make(azim=-200.0)
    with pytest.raises(ValueError, match=r"view azim \(°\) contains NaN"):
        make(azim=np.nan)


def test_rodrigues_explorer_refuses_bad_q0():
    with pytest.raises(ValueError, match="q0 must be a single 3-vector"):
        rodrigues_explorer(q0=np.zeros((2, 3)))
    with pytest.raises(ValueError, match=r"q0 must have shape \(\.\.\., 3\)"):
        rodrigues_explorer(q0=[1.0, 2.0, 3.0, 4.0])


# --------------------------------------------------------------------------------------------
# Spinning at unit angular velocity: the animation
# --------------------------------------------------------------------------------------------


def test_spin_times_are_equal_steps_without_the_end_point():
    t = spin_times(8)
    assert t.shape == (8,) and t[0] == 0.0
    assert np.allclose(np.diff(t), 2 * np.pi / 8)
    assert t[-1] < 2 * np.pi
    with pytest.raises(ValueError, match="frames must be >= 2"):
        spin_times(1)
    with pytest.raises(TypeError, match="frames must be an integer"):
        spin_times(5.0)
    with pytest.raises(ValueError, match="duration must be > 0"):
        spin_times(5, duration=-1.0)


@given(points.filter(lambda p: np.linalg.norm(p) > 0.1), st.floats(0.0, 3.1))
@settings(max_examples=50)
def test_spin_rotations_turn_one_radian_per_second(axis, t):
    w = unit(axis)
    R = spin_rotations(axis, t)
    axis_out, angle = so3.axis_angle(R)
    assert abs(angle - t) <= 1e-8  # θ = t (eq. 125)
    if t > 1e-3:
        assert np.linalg.norm(axis_out - w) <= 1e-6
    # q̇ = ω̂ q (eq. 122): a central difference of R(t) q0 matches ω × R(t) q0
    h = 1e-5
    q0 = np.array([0.3, -0.4, 0.8])
    q_dot = (spin_rotations(axis, t + h) - spin_rotations(axis, t - h)) @ q0 / (2 * h)
    assert np.linalg.norm(q_dot - np.cross(w, R @ q0)) <= 1e-8


def test_spin_rotations_refuses_a_zero_axis():
    with pytest.raises(ValueError, match=r"axis must be non-zero .* ‖axis‖ = 0.0e\+00 <= TOL"):
        spin_rotations([0, 0, 0], 1.0)
    with pytest.raises(ValueError, match="single 3-vector"):
        spin_rotations([[0, 0, 1]], 1.0)


def test_spin_animation_embeds_one_png_per_frame_at_real_time_speed():
    html = spin_animation(axis=(1, 1, 0), frames=4, dpi=20, size=2.0).data
    assert html.count("data:image/png;base64") == 4
    # the player advances one frame per 2π/4 s: one radian per second
    interval = re.search(r"new Animation\(frames,\s*img_id,\s*slider_id,\s*([0-9.]+)", html)
    assert interval is not None
    assert abs(float(interval.group(1)) - 1000 * 2 * np.pi / 4) < 1.0  # whole milliseconds


def test_spin_animation_closes_its_figure_so_it_is_not_shown_twice():
    before = plt.get_fignums()
    spin_animation(frames=2, dpi=20, size=1.5)
    assert plt.get_fignums() == before


def test_spin_animation_default_stays_small_enough_for_a_committed_notebook():
    html = spin_animation().data
    assert html.count("data:image/png;base64") == 20
    assert len(html) < 400_000


def test_spin_animation_refuses_bad_sizes():
    with pytest.raises(ValueError, match="at most 120"):
        spin_animation(frames=500)
    with pytest.raises(ValueError, match="dpi must be between 20 and 150"):
        spin_animation(dpi=300)
    with pytest.raises(ValueError, match="size must be between 1 and 8"):
        spin_animation(size=20)
    with pytest.raises(ValueError, match="axis must be non-zero"):
        spin_animation(axis=(0, 0, 0))
