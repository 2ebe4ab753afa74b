r"""The explorers and the animation of the chapters on rotations and exponential coordinates.

==============================  ===============================================================
Widget / animation              What it draws (the maths is in :mod:`course_lib.rodrigues`)
==============================  ===============================================================
:func:`rotation_explorer`       :func:`draw_rotated_frame`: frames A and B = A turned by
(notebook 02)                   :math:`\theta` about :math:`\omega`
:func:`rodrigues_explorer`      :func:`draw_rodrigues_terms` and :func:`rodrigues_readout`:
(notebook 03)                   the three terms of Rodrigues' formula, tip to tail
:func:`spin_animation`          a body frame spinning at unit angular velocity
(notebook 03)
==============================  ===============================================================

The rotation axis is a unit vector :math:`\omega`, given to the sliders by two spherical
angles: the polar angle :math:`\varphi \in [0, \pi]` (measured from the z axis) and the azimuth
:math:`\lambda \in [-\pi, \pi]` (measured in the xy plane from the x axis). The rotation is the
notes' :math:`R(\omega, \theta) = e^{\hat\omega\theta}` (eq. 127), computed by
:func:`course_lib.so3.exp`; drawing uses the primitives of :mod:`course_lib.plotting`.

**Turn it with the mouse.** An explorer is three sliders above a live matplotlib figure drawn
by ``ipympl``, matplotlib's own Jupyter widget backend: drag the 3D view to look at it from
any side (the toolbar's home button goes back to the first view). Only the explorer's own
figure lives on an ipympl canvas; the notebook's backend and every other figure stay as they
are (static PNGs). Releasing a slider (``continuous_update=False``) redraws the figure in
place, keeping the camera the mouse chose.

**Stored output.** Displayed, an explorer gives the live widget view plus a PNG snapshot of
its first figure and a one-line text description, which pages without a kernel (the repository
viewer, a static site) show instead. The widget model ids are random on every run, so the
notebooks mark these cells ``NBVAL_IGNORE_OUTPUT``. Executed headless (nbval, nbconvert) no
browser ever attaches to the canvas, and nothing waits for one. There is no ``Output`` widget:
nbclient (nbconvert --execute) mimics that one by sending comm messages on the shell channel
from its output task while its reply task waits on the same socket, a race in which a cell can
wait for its reply until the timeout (jupyter/nbclient#312).
"""

import base64
import html
import io
import re
import tempfile
import warnings
from pathlib import Path

import ipywidgets
import matplotlib.pyplot as plt
import numpy as np
from matplotlib import animation
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from . import plotting, so3
from ._arrays import as_angles, as_count, as_direction, as_scalar, as_unit_axes, as_vector3
from .rodrigues import (
    axis_from_spherical,
    rodrigues_terms,
    rodrigues_vectors,
    spin_rotations,
    spin_times,
)
from .tolerance import TOL

__all__ = [
    "POLAR_RANGE",
    "AZIMUTH_RANGE",
    "THETA_RANGE",
    "Q0",
    "VIEW_ELEV",
    "VIEW_AZIM",
    "rodrigues_readout",
    "draw_rotated_frame",
    "draw_rodrigues_terms",
    "Explorer",
    "rotation_explorer",
    "rodrigues_explorer",
    "SPIN_PIXELS",
    "spin_animation",
]

#: Slider ranges, in radians: polar angle of the axis, its azimuth, and the rotation angle.
POLAR_RANGE = (0.0, np.pi)
AZIMUTH_RANGE = (-np.pi, np.pi)
THETA_RANGE = (0.0, 2.0 * np.pi)

#: The fixed point q0 that the Rodrigues explorer rotates (the tip of the world x axis).
Q0 = (1.0, 0.0, 0.0)

#: Default camera of the 3D views, in degrees (``view_init``): the view of ``plotting.axes3d``.
VIEW_ELEV = 20.0
VIEW_AZIM = -60.0

_SLIDER_STEP = 0.01
_EXPLORER_SIZE = (5.2, 4.8)  # inches at plotting.DPI: 520 x 480 px on the page
# Turned by the mouse to look from below, the cube's tick labels go to its top: a little
# smaller, it keeps them clear of the title at every camera.
_EXPLORER_ZOOM = 0.9
_SNAPSHOT_COLORS = 96  # stored snapshots and animation frames are palette PNGs: fewer bytes

#: The frame width of :func:`spin_animation` by default, in pixels: below it the title and the
#: labels cannot be read.
SPIN_PIXELS = 360
_TERM_COLORS = ("black", "tab:orange", "tab:purple")
_RESULT_COLOR = "tab:blue"
_AXIS_COLOR = "0.35"
_WORLD_AXES = ("x_A", "y_A", "z_A")
_RODRIGUES_LABELS = (
    r"$q_0$",
    r"$\sin\theta\,\hat\omega q_0$",
    r"$(1-\cos\theta)\,\hat\omega^2 q_0$",
    r"$e^{\hat\omega\theta}q_0$ (sum)",
)


def _fmt(x, decimals):
    """A number rounded for display, without a minus sign on zero."""
    return f"{round(float(x), decimals) + 0.0:.{decimals}f}"


def _bmatrix(M, decimals):
    rows = [" & ".join(_fmt(x, decimals) for x in row) for row in np.asarray(M)]
    return r"\begin{bmatrix} " + r" \\ ".join(rows) + r" \end{bmatrix}"


def rodrigues_readout(axis, theta, decimals=2, tol=TOL):
    r"""LaTeX of Rodrigues' formula with numbers: the three matrices and their sum.

    .. math::

        e^{\hat\omega\theta} = I + \sin\theta\,\hat\omega + (1-\cos\theta)\,\hat\omega^2
        = \begin{bmatrix}\cdot\end{bmatrix} + \begin{bmatrix}\cdot\end{bmatrix}
        + \begin{bmatrix}\cdot\end{bmatrix} = \begin{bmatrix}\cdot\end{bmatrix}

    with the entries rounded to ``decimals`` places. The sum on the right is
    :func:`course_lib.so3.exp`, computed independently of the three terms.

    Parameters
    ----------
    axis : array_like, shape (3,)
        One unit rotation axis.
    theta : float
        Angle in radians.
    decimals : int, default 2
        Number of decimals shown (0 to 6).
    tol : float, default TOL
        Largest accepted :math:`|\|\omega\| - 1|`.

    Returns
    -------
    str
        A LaTeX display, ready for ``IPython.display.Math``.

    Raises
    ------
    ValueError
        If the axis is not a single unit 3-vector, ``theta`` is not a single finite number,
        or ``decimals`` is outside 0..6.
    TypeError
        If an input is not numeric, or ``decimals`` is not an integer.

    Examples
    --------
    >>> tex = rodrigues_readout([0, 0, 1], 0.0)
    >>> tex.count(r"\begin{bmatrix}")
    4
    >>> "1.00 & 0.00 & 0.00" in tex
    True
    """
    decimals = as_count(decimals, "decimals")
    if decimals > 6:
        raise ValueError(f"decimals must be between 0 and 6, got {decimals}")
    w = as_unit_axes(as_vector3(axis, "axis"), "axis", tol)
    theta = _scalar_angle(theta, "theta")
    terms = rodrigues_terms(w, theta, tol)
    R = so3.exp(w, theta)
    th = _fmt(theta, decimals)
    head = (
        rf"\omega = ({', '.join(_fmt(x, decimals) for x in w)}),\ \theta = {th}:\quad "
        r"e^{\hat\omega\theta} = I + \sin\theta\,\hat\omega + (1-\cos\theta)\,\hat\omega^2"
    )
    body = " + ".join(_bmatrix(T, decimals) for T in terms) + " = " + _bmatrix(R, decimals)
    return r"\begin{gathered} " + head + r" \\ " + body + r" \end{gathered}"


# --------------------------------------------------------------------------------------------
# Drawing onto given axes
# --------------------------------------------------------------------------------------------


def _single(x, name, what="angle (a number)"):
    """A single finite real number; the message says what kind of number ``name`` is."""
    a = as_angles(x, name)
    if a.shape != ():
        raise ValueError(f"{name} must be a single {what}, got shape {a.shape}")
    return float(a)


def _scalar_angle(x, name):
    return _single(x, name)


def _view_angle(x, name):
    """A camera angle in degrees: a single finite real number (any value, as ``view_init``)."""
    return _single(x, name, "viewing angle in degrees (a number)")


def _rotation_view(ax, func, polar, azimuth, theta, elev, azim):
    """Check the angles, point the camera; the axis, the angle and the rotation to draw.

    Only the view changes with ``(elev, azim)``, not what is drawn.
    """
    plotting._require_3d(ax, func)
    polar = _scalar_angle(polar, "polar")
    azimuth = _scalar_angle(azimuth, "azimuth")
    theta = _scalar_angle(theta, "theta")
    ax.view_init(elev=_view_angle(elev, "elev"), azim=_view_angle(azim, "azim"))
    w = axis_from_spherical(polar, azimuth)
    return w, theta, so3.exp(w, theta)


def _moving_axes(w):
    """The world axes e_i (with their colours) that a rotation about the unit axis w moves."""
    for i, color in enumerate(plotting.FRAME_COLORS):
        e = np.eye(3)[i]
        if np.linalg.norm(e - (w @ e) * w) > TOL:
            yield e, color


def _draw_axis_line(ax, w, length=1.4):
    """The rotation axis: a dashed line through the origin and the arrow omega."""
    drawn = []
    drawn.extend(
        plotting.draw_segment(ax, -length * w, length * w, color=_AXIS_COLOR, style="dashed")
    )
    drawn.extend(plotting.draw_vector(ax, w, label=r"$\omega$", color=_AXIS_COLOR))
    return drawn


def draw_rotated_frame(ax, polar, azimuth, theta, *, elev=VIEW_ELEV, azim=VIEW_AZIM):
    r"""Draw the world frame A, the rotated body frame B and the axis of rotation.

    The body frame is :math:`R = e^{\hat\omega\theta}` (eq. 127): its axes are the columns of
    :math:`R`, the world axes carried about :math:`\omega` by :math:`\theta`. Each world axis
    tip travels along a dotted arc :math:`e^{\hat\omega t} e_i`, :math:`t \in [0, \theta]`,
    to the matching body axis tip (no arc is drawn for a world axis that lies on
    :math:`\omega`: it does not move). The camera is set to ``(elev, azim)``; it changes the
    view only, not the geometry drawn.

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.axes3d.Axes3D
        A 3D axes, e.g. from :func:`course_lib.plotting.axes3d`.
    polar, azimuth : float
        Spherical angles of the axis :math:`\omega`, see :func:`axis_from_spherical`.
    theta : float
        Rotation angle in radians.
    elev : float, keyword-only, default VIEW_ELEV = 20
        Camera elevation in degrees above the xy plane (matplotlib's ``view_init``). Not an
        angle of the rotation.
    azim : float, keyword-only, default VIEW_AZIM = -60
        Camera azimuth in degrees about the z axis. Not the azimuth :math:`\lambda` of
        :math:`\omega`.

    Returns
    -------
    course_lib.plotting.Drawn
        ``points``: the body axis tips, shape (3, 3), row i is :math:`R e_i`; ``R``: the
        rotation; ``axis``: :math:`\omega`; ``theta``; ``arcs``: the arc point arrays drawn
        (one per moving world axis).

    Raises
    ------
    ValueError
        If an angle (of the rotation or of the camera) is not a single finite number.
    TypeError
        If ``ax`` is not a 3D axes or an angle is not a real number.

    Examples
    --------
    >>> import numpy as np, matplotlib.pyplot as plt
    >>> from course_lib.plotting import axes3d
    >>> fig, ax = axes3d("Body frame")
    >>> drawn = draw_rotated_frame(ax, 0.0, 0.0, np.pi / 2)   # a quarter turn about z
    >>> np.round(drawn.points[0], 12)                        # body x axis = world y axis
    array([0., 1., 0.])
    >>> side = draw_rotated_frame(axes3d("Side")[1], 0.0, 0.0, np.pi / 2, elev=0, azim=-90)
    >>> side.points.tolist() == drawn.points.tolist()        # another camera, same frame
    True
    >>> plt.close("all")
    """
    w, theta, R = _rotation_view(ax, "draw_rotated_frame", polar, azimuth, theta, elev, azim)
    artists = []
    # World frame A: axis labels x_A, y_A, z_A but no name at the origin, where B's name goes.
    artists.extend(plotting.draw_frame(ax, label=None, style="dotted", axis_names=_WORLD_AXES))
    artists.extend(_draw_axis_line(ax, w))
    arcs = []
    moving = list(_moving_axes(w)) if theta != 0.0 else []  # a zero angle moves nothing
    for e, color in moving:
        arc = plotting.draw_arc(ax, w, e, theta, color=color, style="dotted", arrow=False)
        artists.extend(arc)
        arcs.append(arc.points)
    body = plotting.draw_frame(ax, R, label="B")
    artists.extend(body)
    return plotting.Drawn(
        "rotated_frame", artists, body.points, R=R, axis=w, theta=theta, arcs=arcs
    )


def _draw_orbit(ax, w, q0):
    """The dotted circle that q0 travels about the unit axis w, or None if q0 is on the axis."""
    center = (w @ q0) * w
    if np.linalg.norm(q0 - center) <= TOL:
        return None
    return plotting.draw_arc(
        ax,
        w,
        q0 - center,
        2.0 * np.pi,
        center=center,
        n=90,
        color="0.6",
        style="dotted",
        arrow=False,
    )


def draw_rodrigues_terms(ax, polar, azimuth, theta, q0=Q0, *, elev=VIEW_ELEV, azim=VIEW_AZIM):
    r"""Draw Rodrigues' formula assembling :math:`e^{\hat\omega\theta} q_0` tip to tail.

    From the origin: :math:`q_0` (black), then from its tip :math:`\sin\theta\,\hat\omega q_0`
    (orange, tangent to the circle of :math:`q_0` about :math:`\omega`), then
    :math:`(1-\cos\theta)\,\hat\omega^2 q_0` (purple, towards the axis). The chain lands on
    :math:`e^{\hat\omega\theta} q_0` (blue arrow from the origin), a point of the dotted circle
    traced by :math:`q_0` about :math:`\omega` (eq. 125). The camera is set to
    ``(elev, azim)``; it changes the view only, not the geometry drawn.

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.axes3d.Axes3D
        A 3D axes, e.g. from :func:`course_lib.plotting.axes3d`.
    polar, azimuth : float
        Spherical angles of the axis :math:`\omega`, see :func:`axis_from_spherical`.
    theta : float
        Rotation angle in radians.
    q0 : array_like, shape (3,), default Q0
        The point being rotated.
    elev : float, keyword-only, default VIEW_ELEV = 20
        Camera elevation in degrees above the xy plane (matplotlib's ``view_init``). Not an
        angle of the rotation.
    azim : float, keyword-only, default VIEW_AZIM = -60
        Camera azimuth in degrees about the z axis. Not the azimuth :math:`\lambda` of
        :math:`\omega`.

    Returns
    -------
    course_lib.plotting.Drawn
        ``points``: the chain, shape (4, 3): :math:`0`, :math:`q_0`,
        :math:`q_0 + \sin\theta\,\hat\omega q_0` and the end of the third vector;
        ``terms``: the three vectors, shape (3, 3); ``q``: :math:`e^{\hat\omega\theta} q_0`
        from :func:`course_lib.so3.exp`; ``R``; ``axis``; ``theta``; ``circle``: the points of
        the dotted circle (``None`` when :math:`q_0` lies on the axis).

    Raises
    ------
    ValueError
        If an angle (of the rotation or of the camera) is not a single finite number or ``q0``
        is not a finite 3-vector.
    TypeError
        If ``ax`` is not a 3D axes or an input is not numeric.

    Examples
    --------
    >>> import numpy as np, matplotlib.pyplot as plt
    >>> from course_lib.plotting import axes3d
    >>> fig, ax = axes3d("Rodrigues")
    >>> drawn = draw_rodrigues_terms(ax, 0.7, 0.4, 2.0, elev=35, azim=-30)
    >>> np.allclose(drawn.points[-1], drawn.q)               # the chain lands on R q0
    True
    >>> float(ax.elev), float(ax.azim)                       # the camera asked for
    (35.0, -30.0)
    >>> plt.close(fig)
    """
    q0 = as_vector3(q0, "q0")
    w, theta, R = _rotation_view(ax, "draw_rodrigues_terms", polar, azimuth, theta, elev, azim)
    q = R @ q0
    terms = np.stack(rodrigues_vectors(w, theta, q0))
    chain = np.concatenate([np.zeros((1, 3)), np.cumsum(terms, axis=0)])
    artists = []
    artists.extend(_draw_axis_line(ax, w))
    circle = _draw_orbit(ax, w, q0)
    if circle is not None:
        artists.extend(circle)
        circle = circle.points
    for k in range(3):
        artists.extend(plotting.draw_vector(ax, terms[k], origin=chain[k], color=_TERM_COLORS[k]))
    artists.extend(plotting.draw_vector(ax, q, color=_RESULT_COLOR, linewidth=2.6))
    # A legend rather than labels at the tips: the last term and the result end at one point.
    handles = [Line2D([], [], color=c, linewidth=2.2) for c in _TERM_COLORS + (_RESULT_COLOR,)]
    artists.append(
        ax.legend(
            handles,
            _RODRIGUES_LABELS,
            loc="upper left",
            fontsize=plotting.FONT_SIZE - 2,
            frameon=False,
        )
    )
    return plotting.Drawn(
        "rodrigues", artists, chain, terms=terms, q=q, R=R, axis=w, theta=theta, circle=circle
    )


# --------------------------------------------------------------------------------------------
# Widgets
# --------------------------------------------------------------------------------------------


def _slider(value, bounds, description):
    lo, hi = bounds
    value = _scalar_angle(value, description)
    if not lo <= value <= hi:
        raise ValueError(
            f"{description} = {value:g} is outside the slider range [{lo:.4g}, {hi:.4g}] (radians)"
        )
    return ipywidgets.FloatSlider(
        value=value,
        min=lo,
        max=hi,
        step=_SLIDER_STEP,
        description=description,
        continuous_update=False,
        readout_format=".2f",
        style={"description_width": "8em"},
        layout=ipywidgets.Layout(width="30em"),
    )


def _ipympl_classes():
    """ipympl's canvas and figure manager, imported without switching pyplot's backend.

    ``import ipympl`` calls ``matplotlib.use("module://ipympl.backend_nbagg")`` when matplotlib
    is loaded: every later ``plt.show()`` of the notebook would then make a widget instead of
    a PNG. The backend the notebook had (or the unresolved default) is put back.
    (Switching backends closes pyplot's open figures, as ``import ipympl`` itself does.)
    """
    import sys

    if "ipympl.backend_nbagg" not in sys.modules:
        import matplotlib
        from matplotlib import rcsetup

        if "matplotlib.pyplot" in sys.modules:
            # Load the notebook's backend first: the inline backend hooks itself into IPython
            # when it is loaded as the current backend, and would not after the switch back.
            plt._get_backend_mod()
        backend = matplotlib.rcParams._get_backend_or_none()  # None: not chosen yet
        fallback = matplotlib.rcParams["backend_fallback"]
        import ipympl.backend_nbagg  # noqa: F401

        if backend is None:
            matplotlib.rcParams["backend"] = rcsetup._auto_backend_sentinel
        else:
            matplotlib.use(backend)
        matplotlib.rcParams["backend_fallback"] = fallback
    from ipympl.backend_nbagg import Canvas, FigureManager

    return Canvas, FigureManager


def _canvas_figure(figsize):
    """A figure on an ipympl canvas of its own, outside pyplot (no backend is switched).

    The canvas is a widget: matplotlib's 3D mouse rotation runs in the kernel and the browser
    shows the redrawn image.
    """
    Canvas, FigureManager = _ipympl_classes()
    fig = Figure(figsize=figsize, dpi=plotting.DPI)
    canvas = Canvas(fig)
    with warnings.catch_warnings():
        # ipympl 0.10's own toolbar passes its canvas on to traitlets, which warns about it
        warnings.filterwarnings(
            "ignore", r"Passing unrecognized arguments to super\(Toolbar\)", DeprecationWarning
        )
        FigureManager(canvas, 0)  # not registered with pyplot: plt.show() never shows it again
    canvas.header_visible = False  # no "Figure 0" line above the figure
    canvas.footer_visible = False  # no "x pane=1.2, y=..." cursor read-out below it
    canvas.resizable = False
    return fig


def _explorer_figure():
    """(figure, None) on a live ipympl canvas, or (plain figure, why) where ipympl is missing."""
    try:
        return _canvas_figure(_EXPLORER_SIZE), None
    except ImportError as err:
        why = (
            f"A still picture: the live explorer needs {err.name or 'ipympl'}, which is not "
            "installed here (pip install ipympl, then restart the kernel)."
        )
        return Figure(figsize=_EXPLORER_SIZE, dpi=plotting.DPI), why


def _angles_line(w, theta):
    return rf"$\omega$ = ({w[0]:.2f}, {w[1]:.2f}, {w[2]:.2f}),  $\theta$ = {theta:.2f} rad"


class Explorer(ipywidgets.VBox):
    r"""Three sliders (axis polar angle, azimuth, angle) above a 3D view that turns with the mouse.

    Built by :func:`rotation_explorer` and :func:`rodrigues_explorer`. Releasing a slider
    redraws the figure in place with ``draw(ax, polar, azimuth, theta, elev=, azim=)``, at the
    camera the mouse left it at. ``result`` holds what the drawing computed (``pick(drawn)``).

    Attributes
    ----------
    sliders : dict of str to ipywidgets.FloatSlider
        The three sliders, by description.
    figure : matplotlib.figure.Figure
        The live figure; ``figure.canvas`` is the ipympl canvas widget.
    ax : mpl_toolkits.mplot3d.axes3d.Axes3D
    readout : ipywidgets.HTMLMath or None
        A formula below the figure, rewritten on every redraw.
    result : numpy.ndarray
        What the current drawing computed (the rotation, or the Rodrigues vectors).
    description : str
        One line saying what the explorer shows: the text pages without widgets display.
    """

    def __init__(self, draw, pick, title, description, angles, camera, lim, readout=None):
        names = ("axis polar φ", "axis azimuth λ", "angle θ")
        ranges = (POLAR_RANGE, AZIMUTH_RANGE, THETA_RANGE)
        self.sliders = {n: _slider(v, r, n) for n, v, r in zip(names, angles, ranges)}
        elev, azim = (_view_angle(a, n) for a, n in zip(camera, ("elev", "azim")))
        self.figure, self.why_still = _explorer_figure()
        self.figure.subplots_adjust(left=0.0, right=0.94, bottom=0.02, top=0.86)
        self.ax = self.figure.add_subplot(projection="3d")
        self._drawn = None
        self.description = description
        self._draw, self._pick, self._title, self._lim = draw, pick, title, lim
        self._readout = readout
        self.readout = ipywidgets.HTMLMath() if readout else None
        children = [*self.sliders.values(), self.figure.canvas] if self.live else []
        super().__init__(children=children + ([self.readout] if readout and self.live else []))
        self._redraw(elev, azim)
        self._update_readout()
        for slider in self.sliders.values():
            slider.observe(self._on_release, names="value")

    @property
    def live(self):
        """Whether the figure is a live widget (False: only its still picture can be shown)."""
        return self.why_still is None

    @property
    def values(self):
        """The current (polar, azimuth, theta) of the sliders, in radians."""
        return tuple(float(s.value) for s in self.sliders.values())

    def _redraw(self, elev, azim):
        """Replace the drawing (not the axes: its ticks and panes are costly to rebuild)."""
        polar, azimuth, theta = self.values
        w = axis_from_spherical(polar, azimuth)
        title = self._title + "\n" + _angles_line(w, theta)
        if self._drawn is None:
            plotting.axes3d(title, ax=self.ax, lim=self._lim)
            self.ax.set_box_aspect((1, 1, 1), zoom=_EXPLORER_ZOOM)
        else:
            for artist in self._drawn:
                artist.remove()
            self.ax.set_title(title, fontsize=plotting.TITLE_SIZE)
        self._drawn = self._draw(self.ax, polar, azimuth, theta, elev=elev, azim=azim)
        self.result = self._pick(self._drawn)

    def _update_readout(self):
        if self.readout is not None:
            polar, azimuth, theta = self.values
            w = axis_from_spherical(polar, azimuth)
            self.readout.value = "$$" + self._readout(w, theta) + "$$"

    def _on_release(self, change):
        self._redraw(self.ax.elev, self.ax.azim)
        # Render and send the image now: draw_idle() would first ask the browser for a redraw.
        # The readout comes after it: typesetting it would hold the browser up.
        self.figure.canvas.draw()
        self._update_readout()

    def snapshot(self):
        """The figure as it is now, as PNG bytes (a small palette image)."""
        return _palette_png(self.figure)

    def _repr_mimebundle_(self, **kwargs):
        png = base64.b64encode(self.snapshot()).decode("ascii")
        if not self.live:  # the still picture, and one line saying why
            alt = html.escape(self.description, quote=True)
            return {
                "text/plain": f"{self.description}\n{self.why_still}",
                "image/png": png,
                "text/html": f'<img src="data:image/png;base64,{png}" alt="{alt}">'
                f"<p><em>{html.escape(self.why_still)}</em></p>",
            }
        data = super()._repr_mimebundle_(**kwargs)
        data["text/plain"] = self.description
        data["image/png"] = png
        return data


def rotation_explorer(
    polar=np.pi / 4, azimuth=3 * np.pi / 4, theta=2 * np.pi / 3, *, elev=VIEW_ELEV, azim=VIEW_AZIM
):
    r"""Sliders for an axis and an angle, redrawing the body frame :math:`e^{\hat\omega\theta}`.

    Three sliders (polar angle :math:`\varphi` and azimuth :math:`\lambda` of the unit axis
    :math:`\omega`, rotation angle :math:`\theta`) redraw :func:`draw_rotated_frame`: the world
    frame A (dotted), the axis :math:`\omega`, and the body frame B with

    .. math:: R_{ab} = e^{\hat\omega\theta}, \qquad
              \omega = (\sin\varphi\cos\lambda, \sin\varphi\sin\lambda, \cos\varphi).

    Drag the figure with the mouse to look at the frames from another side; that moves the
    camera only, never the rotation.

    Parameters
    ----------
    polar : float, default π/4
        Initial polar angle, in ``POLAR_RANGE`` = [0, π].
    azimuth : float, default 3π/4
        Initial azimuth, in ``AZIMUTH_RANGE`` = [−π, π].
    theta : float, default 2π/3
        Initial rotation angle, in ``THETA_RANGE`` = [0, 2π].
    elev, azim : float, keyword-only, default VIEW_ELEV = 20, VIEW_AZIM = −60
        Initial camera, in degrees (matplotlib's ``view_init``).

    Returns
    -------
    Explorer
        The sliders and the live figure; ``.result`` holds the current rotation matrix
        :math:`R`.

    Raises
    ------
    ValueError
        If an initial angle is not a finite number inside its slider's range, or a camera
        angle is not a finite number.

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib.rodrigues import rotated_frame
    >>> w = rotation_explorer()
    >>> list(w.sliders)
    ['axis polar φ', 'axis azimuth λ', 'angle θ']
    >>> np.allclose(w.result, rotated_frame(np.pi / 4, 3 * np.pi / 4, 2 * np.pi / 3))
    True
    """
    return Explorer(
        draw_rotated_frame,
        lambda drawn: drawn.R,
        r"Body frame B: $R_{ab} = e^{\hat\omega\theta}$",
        "Rotation explorer: sliders for the axis ω (polar angle φ, azimuth λ) and the angle θ "
        "redraw frame B, frame A turned by θ about ω; drag the 3D view to turn it.",
        (polar, azimuth, theta),
        (elev, azim),
        lim=1.2,
    )


def rodrigues_explorer(
    polar=np.pi / 3, azimuth=np.pi / 2, theta=np.pi / 2, q0=Q0, *, elev=VIEW_ELEV, azim=VIEW_AZIM
):
    r"""Sliders for an axis and an angle, showing Rodrigues' formula assemble the rotation.

    The figure is :func:`draw_rodrigues_terms`: :math:`q_0`, :math:`\sin\theta\,\hat\omega q_0`
    and :math:`(1-\cos\theta)\,\hat\omega^2 q_0` drawn tip to tail, landing on
    :math:`e^{\hat\omega\theta} q_0`; below it, :func:`rodrigues_readout` writes the matrices

    .. math:: e^{\hat\omega\theta} = I + \sin\theta\,\hat\omega + (1-\cos\theta)\,\hat\omega^2

    with numbers (eq. 159). Drag the figure with the mouse to turn the 3D view.

    Parameters
    ----------
    polar : float, default π/3
        Initial polar angle of the axis, in [0, π].
    azimuth : float, default π/2
        Initial azimuth of the axis, in [−π, π] (π/2: the axis is perpendicular to
        ``Q0``, whose circle is then as large as it can be).
    theta : float, default π/2
        Initial rotation angle, in [0, 2π].
    q0 : array_like, shape (3,), default Q0
        The point being rotated.
    elev, azim : float, keyword-only, default VIEW_ELEV = 20, VIEW_AZIM = −60
        Initial camera, in degrees.

    Returns
    -------
    Explorer
        The sliders, the live figure and the readout; ``.result`` holds the three vectors of
        :func:`course_lib.rodrigues.rodrigues_vectors`, shape (3, 3).

    Raises
    ------
    ValueError
        If an initial value is outside its slider's range, or ``q0`` is not a finite 3-vector.

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib import so3
    >>> from course_lib.rodrigues import axis_from_spherical
    >>> w = rodrigues_explorer(theta=1.0)
    >>> axis = axis_from_spherical(np.pi / 3, np.pi / 2)
    >>> np.allclose(w.result.sum(axis=0), so3.exp(axis, 1.0) @ Q0)
    True
    """
    q0 = as_vector3(q0, "q0")

    def draw(ax, polar, azimuth, theta, elev, azim):
        return draw_rodrigues_terms(ax, polar, azimuth, theta, q0, elev=elev, azim=azim)

    return Explorer(
        draw,
        lambda drawn: drawn.terms,
        r"Rodrigues' formula applied to $q_0$",
        "Rodrigues explorer: sliders for the axis ω and the angle θ; q0, sinθ ω̂q0 and "
        "(1 − cosθ) ω̂²q0 drawn tip to tail land on e^(ω̂θ) q0; the matrices below, with "
        "numbers; drag the 3D view to turn it.",
        (polar, azimuth, theta),
        (elev, azim),
        lim=1.3,
        readout=rodrigues_readout,
    )


# --------------------------------------------------------------------------------------------
# Animation
# --------------------------------------------------------------------------------------------


def _palette_png(fig, colors=_SNAPSHOT_COLORS, **savefig_kwargs):
    """The figure as a palette PNG: the same picture in a third of the bytes or less."""
    from PIL import Image

    buf = io.BytesIO()
    fig.savefig(buf, format="png", **savefig_kwargs)
    out = io.BytesIO()
    Image.open(buf).convert("RGB").quantize(colors).save(out, format="png", optimize=True)
    return out.getvalue()


class _PaletteHTMLWriter(animation.HTMLWriter):
    """matplotlib's JavaScript player, with palette PNG frames (the HTML is stored)."""

    def grab_frame(self, **savefig_kwargs):
        png = _palette_png(self.fig, dpi=self.dpi, **savefig_kwargs)
        self._saved_frames.append(base64.encodebytes(png).decode("ascii"))


def spin_animation(axis=(0.0, 0.0, 1.0), frames=16, duration=2.0 * np.pi, dpi=100, size=3.6):
    r"""An HTML animation of a body frame spinning at unit angular velocity about ``axis``.

    Frame :math:`k` shows the body frame :math:`R(t_k) = e^{\hat\omega t_k}` at time
    :math:`t_k` (:func:`course_lib.rodrigues.spin_times`,
    :func:`course_lib.rodrigues.spin_rotations`), the world frame (dotted), the axis and the
    circles that the body axis tips travel on. The player advances at one frame per
    :math:`T/N` seconds, so the picture turns at one radian per second: the angle is the time
    (eq. 125).

    Built with matplotlib's JavaScript player (``HTMLWriter``: the frames are palette PNGs
    embedded in the page, no ffmpeg); the figure is closed so no static copy is displayed as
    well. The player loads nothing from outside the page (its buttons are characters, not
    Font Awesome icons from a CDN) and shows the first frame before any script runs. The
    default frames are :data:`SPIN_PIXELS` = 360 pixels wide, the smallest at which the title
    and the labels can be read.

    Parameters
    ----------
    axis : array_like, shape (3,), default (0, 0, 1)
        Direction of the angular velocity (normalised).
    frames : int, default 16
        Number of frames (2 to 120).
    duration : float, default 2π
        Time covered, in seconds (= radians turned).
    dpi : int, default 100
        Resolution of the embedded frames (20 to 150).
    size : float, default 3.6
        Figure width and height in inches (1 to 8); ``size * dpi`` is the frame width in
        pixels (360 by default).

    Returns
    -------
    IPython.display.HTML
        The JavaScript player; its ``.data`` is the HTML text.

    Raises
    ------
    ValueError
        If ``axis`` is zero or not a 3-vector, or a size parameter is out of range.
    TypeError
        If ``frames`` or ``dpi`` is not an integer.

    Examples
    --------
    >>> html = spin_animation(frames=3)
    >>> html.data.count("data:image/png;base64")  # the three frames, and the first as the still
    4
    >>> "font-awesome" in html.data or "https://" in html.data  # nothing from outside the page
    False
    """
    from IPython.display import HTML

    frames = as_count(frames, "frames", minimum=2)
    if frames > 120:
        raise ValueError(
            f"frames must be at most 120 (the frames are stored in the notebook), got {frames}"
        )
    dpi = as_count(dpi, "dpi", minimum=20)
    if dpi > 150:
        raise ValueError(f"dpi must be between 20 and 150, got {dpi}")
    size = as_scalar(size, "size")
    if not 1.0 <= size <= 8.0:
        raise ValueError(f"size must be between 1 and 8 inches, got {size:g}")
    times = spin_times(frames, duration)
    rotations = spin_rotations(axis, times)
    fig, ax, clock = _spin_scene(as_direction(axis, "axis"), size)
    body = []

    def update(k):
        for artist in body:
            artist.remove()
        body.clear()
        body.extend(plotting.draw_frame(ax, rotations[k], label="B"))
        clock.set_text(rf"$t = \theta = {times[k]:.2f}$")
        return body + [clock]

    interval_ms = 1000.0 * float(times[1] - times[0])
    anim = animation.FuncAnimation(fig, update, frames=frames, interval=interval_ms, blit=False)
    try:
        return HTML(_html_player(anim, 1000.0 / interval_ms, dpi))
    finally:
        plt.close(fig)


def _spin_scene(w, size):
    """What stays still in the spin animation: world frame, axis, circles; and the clock text."""
    fig, ax = plotting.axes3d(r"Spinning at $\|\omega\| = 1$ rad/s", lim=1.1, figsize=(size, size))
    ax.set_axis_off()  # panes and ticks would change nothing but triple the stored size
    fig.subplots_adjust(left=0.0, right=1.0, bottom=0.0, top=0.92)
    plotting.draw_frame(ax, label=None, style="dotted", axis_names=_WORLD_AXES)
    _draw_axis_line(ax, w)
    for e, color in _moving_axes(w):
        plotting.draw_arc(ax, w, e, 2.0 * np.pi, color=color, style="dotted", arrow=False, n=72)
    clock = ax.text2D(0.5, 0.02, "", transform=ax.transAxes, ha="center")
    return fig, ax, clock


def _html_player(anim, fps, dpi):
    """The HTML text of matplotlib's JavaScript player for ``anim``, palette PNG frames inside."""
    writer = _PaletteHTMLWriter(fps=fps, embed_frames=True, default_mode="loop")
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp, "spin.html")
        anim.save(str(path), writer=writer, dpi=dpi)
        return _offline_player(path.read_text())


# matplotlib's player draws its buttons with Font Awesome icons, linked from a CDN: a page that
# shows it would ask a server outside the course. The same buttons as plain characters.
_ICONS = {
    "fa-minus": "&minus;",
    "fa-plus": "+",
    "fa-fast-backward": "&#x23EE;",
    "fa-step-backward": "&#x23F4;&#x2223;",
    "fa-play fa-flip-horizontal": "&#x23F4;",
    "fa-pause": "&#x23F8;",
    "fa-play": "&#x23F5;",
    "fa-step-forward": "&#x2223;&#x23F5;",
    "fa-fast-forward": "&#x23ED;",
}
_FA_LINK = re.compile(r"<link[^>]*font-awesome[^>]*>\s*", re.S)
_FA_ICON = re.compile(r'<i class="fa (fa-[a-z-]+(?: fa-flip-horizontal)?)"></i>')
_FIRST_FRAME = re.compile(r'frames\[0\] = "(data:image/png;base64,[A-Za-z0-9+/=\\\n]+)"')
_PLAYER_IMG = re.compile(r'<img id="(_anim_img[0-9a-f]+)">')


def _offline_player(html):
    """The player with no request outside the page, showing its first frame before any script.

    The Font Awesome link goes, its icons become characters (:data:`_ICONS`); the ``<img>``
    gets frame 0 as its ``src``, so the picture is there where scripts do not run (an untrusted
    notebook, a viewer) and before the player starts.
    """
    html = _FA_LINK.sub("", html)
    html = _FA_ICON.sub(lambda m: f'<span aria-hidden="true">{_ICONS[m.group(1)]}</span>', html)
    first = _FIRST_FRAME.search(html)
    if first:
        src = first.group(1).replace("\\\n", "")
        html = _PLAYER_IMG.sub(lambda m: f'<img id="{m.group(1)}" src="{src}" alt="">', html)
    return html
