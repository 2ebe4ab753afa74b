r"""Matplotlib helpers that redraw the figures of the course notes (section 0.1).

The notes describe their figures with "Above: ..." captions. Every one of them is built here from
a small set of primitives, so that a notebook cell stays three to six lines long:

=====================================================  ============================================
Figure in the notes                                    Composition
=====================================================  ============================================
a particle in a reference frame                        :func:`axes3d`, :func:`draw_frame`,
                                                       :func:`draw_point`, :func:`draw_vector`
a trajectory :math:`p(t)`, eq. (6)                     :func:`draw_curve` (``arrow=True``)
a point seen from frames A and B                       two :func:`draw_frame` with different origins
a free vector :math:`v = p - q = r - s`, eq. (7)-(8)   :func:`draw_point`, :func:`draw_vector`
a rigid body made of particles                         :func:`draw_point` with an ``(n, 3)`` array
the phone before and after a rotation, eq. (9)         :func:`axes_row`, :func:`draw_box` (marks),
                                                       :func:`draw_segment`
rotation about z by 90° versus a reflection            :func:`axes_row`, :func:`draw_frame`
frames A, B, C of the :math:`R_{ab}, R_{ac}` example   :func:`draw_frame` with ``R=``
:math:`v` in frames A and B, eq. (64)                  :func:`draw_frame`, :func:`draw_vector`
:math:`a \times b` normal to the plane of a and b      :func:`draw_plane`, :func:`draw_vector`
a particle orbiting the origin about :math:`\omega`    :func:`draw_arc`, :func:`draw_vector`
the pendulum, :math:`\|v\| = |r\omega|`, eq. (118)     :func:`axes2d`, :func:`draw_pendulum`
unit angular velocity: angle = time, eq. (125)         :func:`draw_arc`, :func:`draw_point`
convergence of the series (124)/(126)                  :func:`plot_convergence`
=====================================================  ============================================

Conventions
-----------
* Figures are created by :func:`axes3d`, :func:`axes2d`, :func:`axes_row` or
  :func:`plot_convergence`; each sets a title and axis labels, a fixed size, dpi and font, and
  equal, fixed axis limits, so the same cell always gives the same picture. Nothing is random.
* Figures lay themselves out, so a notebook needs no ``fig.tight_layout()`` and can show the
  full canvas (``bbox_inches=None``): 2D figures use matplotlib's constrained layout, which
  makes room for long tick labels, tall axis labels, a legend or a colour bar when the figure is
  drawn. 3D figures get fixed margins instead (constrained layout does not measure the axis
  labels of 3D axes); those of :func:`axes_row` leave room for the tick labels at any camera
  elevation.
* ``draw_*`` functions work on 3D axes with 3-vectors and (where it makes sense) on 2D axes
  with 2-vectors. They return a :class:`Drawn`: the list of artists they added (iterate over it)
  and, in ``.points``, the geometry they drew in world coordinates, so that a notebook can
  compute with it (for example the distance between the two marked points on the phone).
* Bad input (wrong shape, NaN or inf, a zero axis, parallel vectors spanning no plane, a box
  orientation that is not a rotation) raises a ``ValueError``/``TypeError`` that names the
  failed property; degeneracy is judged with the package tolerance ``TOL``.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patches import FancyArrowPatch, Polygon
from mpl_toolkits.mplot3d import proj3d
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from . import so3
from ._arrays import as_count, as_direction, as_float_array, as_vector3, require_finite
from .tolerance import TOL, fmt_residual, tol_label

__all__ = [
    "DPI",
    "FONT_SIZE",
    "TITLE_SIZE",
    "FRAME_COLORS",
    "Arrow",
    "Drawn",
    "axes3d",
    "axes2d",
    "axes_row",
    "draw_frame",
    "draw_vector",
    "draw_point",
    "draw_segment",
    "draw_curve",
    "draw_plane",
    "draw_arc",
    "draw_box",
    "draw_pendulum",
    "plot_convergence",
]

#: Colours of the x, y and z axes of every frame (red, green, blue, as in the notes).
FRAME_COLORS = ("tab:red", "tab:green", "tab:blue")

#: Fixed figure geometry and fonts: same cell, same PNG. They are passed explicitly to every
#: figure, axes and text, never through rcParams: a ``plt.rc_context`` around figure creation
#: would also roll back what the notebook backend sets when the first figure is made
#: (interactive mode), and later figures would not be shown.
DPI = 90
FIGSIZE = (4.8, 4.8)
PANEL_SIZE = 4.2
FONT_SIZE = 11
TITLE_SIZE = 12
ARROW_HEAD = 12  # arrow head size in points (FancyArrowPatch mutation_scale)

# Margins (fractions of the figure) around the 3D panels of axes_row. The bottom margin leaves
# room for the x/y tick labels under the cube at every camera elevation: seen from about 30° to
# 60° above, the front corner of the cube and its tick labels reach lowest on the canvas. The
# top margin leaves room for the title, which sits above the (square) panel.
_ROW_MARGINS_3D = {"left": 0.02, "right": 0.95, "bottom": 0.1, "top": 0.92, "wspace": 0.1}

# Layout engine of the 2D figures made here: constrained layout sizes the margins to the tick
# labels, axis labels, legend and colour bar when the figure is drawn.
_LAYOUT_2D = "constrained"

_LINESTYLES = {"solid": "-", "dashed": "--", "dotted": ":", "dashdot": "-."}


# --------------------------------------------------------------------------------------------
# Small objects returned by the primitives
# --------------------------------------------------------------------------------------------


class Arrow(FancyArrowPatch):
    """An arrow from ``start`` to ``end`` in data coordinates, on 2D or 3D axes.

    The geometry is kept in the public attributes ``start`` and ``end`` (numpy arrays of length
    2 or 3). On 3D axes the arrow is re-projected each time the figure is drawn.
    """

    def __init__(self, start, end, **kwargs):
        self.start = np.array(start, dtype=float)
        self.end = np.array(end, dtype=float)
        kwargs.setdefault("arrowstyle", "-|>")
        kwargs.setdefault("mutation_scale", ARROW_HEAD)
        kwargs.setdefault("shrinkA", 0.0)
        kwargs.setdefault("shrinkB", 0.0)
        super().__init__(tuple(self.start[:2]), tuple(self.end[:2]), **kwargs)

    def do_3d_projection(self, renderer=None):
        """Project ``start`` and ``end`` with the 3D axes' current view; return the depth."""
        xs, ys, zs = proj3d.proj_transform(*np.stack([self.start, self.end]).T, self.axes.M)
        self.set_positions((xs[0], ys[0]), (xs[1], ys[1]))
        return float(np.min(zs))


class Drawn:
    """What a ``draw_*`` function added to an axes.

    Attributes
    ----------
    kind : str
        Name of the primitive (``"frame"``, ``"vector"``, ``"box"``, ...).
    artists : list of matplotlib.artist.Artist
        Everything that was added to the axes. Iterating over a ``Drawn`` iterates over these.
    points : numpy.ndarray, shape (k, d)
        The key geometry in world coordinates (documented by each function), e.g. the arrow tips
        of a frame, the points of an arc, the marked points of a box.
    **extra
        Further named results, documented by each function (e.g. ``corners``, ``velocity``).
    """

    def __init__(self, kind, artists, points, **extra):
        self.kind = kind
        self.artists = list(artists)
        self.points = np.asarray(points, dtype=float)
        for key, value in extra.items():
            setattr(self, key, value)

    def __iter__(self):
        return iter(self.artists)

    def __len__(self):
        return len(self.artists)

    def __repr__(self):
        return f"<Drawn {self.kind}: {len(self.artists)} artists, {len(self.points)} points>"


# --------------------------------------------------------------------------------------------
# Input validation
# --------------------------------------------------------------------------------------------


def _dim(ax):
    """2 or 3: the dimension of the space an axes draws."""
    if not hasattr(ax, "figure") or not hasattr(ax, "plot"):
        raise TypeError(f"ax must be a matplotlib Axes, got {type(ax).__name__}")
    return 3 if getattr(ax, "name", "") == "3d" else 2


def _require_3d(ax, func):
    if _dim(ax) != 3:
        raise TypeError(
            f"{func} needs a 3D axes (projection='3d', e.g. from axes3d); got a 2D axes"
        )


def _array(x, name):
    return require_finite(as_float_array(x, name), name)


def _vector(x, name, d):
    """One finite d-vector: :func:`course_lib._arrays.as_vector3` on a 3D axes."""
    if d == 3:
        return as_vector3(x, name)
    a = _array(x, name)
    if a.shape != (d,):
        raise ValueError(
            f"{name} must be a {d}-vector of shape ({d},) on a {d}D axes, got shape {a.shape}"
        )
    return a


def _points(x, name, d, min_count=1):
    """(d,) or (n, d) -> (n, d)."""
    a = _array(x, name)
    if a.ndim == 1:
        a = a[None, :]
    if a.ndim != 2 or a.shape[1] != d:
        raise ValueError(
            f"{name} must have shape ({d},) or (n, {d}) on a {d}D axes, got shape {np.shape(x)}"
        )
    if a.shape[0] < min_count:
        raise ValueError(f"{name} must hold at least {min_count} points, got {a.shape[0]}")
    return a


def _matrix(x, name, d):
    a = _array(x, name)
    if a.shape != (d, d):
        raise ValueError(f"{name} must be a {d}x{d} matrix on a {d}D axes, got shape {a.shape}")
    return a


def _scalar(x, name, positive=False):
    a = _array(x, name)
    if a.shape != ():
        raise ValueError(f"{name} must be a scalar, got shape {a.shape}")
    value = float(a)
    if positive and not value > 0:
        raise ValueError(f"{name} must be > 0, got {value!r}")
    return value


def _origin(origin, d):
    return np.zeros(d) if origin is None else _vector(origin, "origin", d)


def _linestyle(style):
    if not isinstance(style, str) or style not in _LINESTYLES:
        raise ValueError(f"style must be one of {sorted(_LINESTYLES)}, got {style!r}")
    return _LINESTYLES[style]


def _text_arg(x, name):
    if not isinstance(x, str):
        raise TypeError(f"{name} must be a str, got {type(x).__name__}")
    return x


def _limits(lim):
    """Scalar lim -> (-lim, lim); pair -> (lo, hi) with lo < hi."""
    a = _array(lim, "lim")
    if a.shape == ():
        if not a > 0:
            raise ValueError(f"lim must be > 0 (axes span [-lim, lim]), got {float(a)!r}")
        return -float(a), float(a)
    if a.shape == (2,) and a[0] < a[1]:
        return float(a[0]), float(a[1])
    raise ValueError(f"lim must be a positive number or a pair (lo, hi) with lo < hi, got {lim!r}")


def _labels(labels, n, name="labels"):
    if labels is None:
        return [None] * n
    if isinstance(labels, str):
        labels = [labels]
    labels = list(labels)
    if len(labels) != n:
        raise ValueError(f"{name} must hold one label per item: expected {n}, got {len(labels)}")
    for lab in labels:
        if lab is not None and not isinstance(lab, str):
            raise TypeError(f"each of {name} must be a str or None, got {type(lab).__name__}")
    return labels


# --------------------------------------------------------------------------------------------
# Low-level drawing on 2D or 3D axes
# --------------------------------------------------------------------------------------------


def _offset(ax):
    """Distance, in data units, between a point and its label: 5% of the x span."""
    lo, hi = ax.get_xlim()
    return 0.05 * abs(hi - lo)


def _text(ax, pos, s, color="black", **kwargs):
    kwargs.setdefault("ha", "center")
    kwargs.setdefault("va", "center")
    return ax.text(*pos, s, color=color, fontsize=FONT_SIZE, **kwargs)


def _arrow(ax, start, end, color, linestyle="-", linewidth=1.8):
    arrow = Arrow(start, end, color=color, linestyle=linestyle, linewidth=linewidth)
    if _dim(ax) == 3:
        ax.add_artist(arrow)
    else:
        ax.add_patch(arrow)
    return arrow


def _line(ax, pts, color, linestyle="-", linewidth=1.8):
    (line,) = ax.plot(*np.asarray(pts).T, color=color, linestyle=linestyle, linewidth=linewidth)
    return line


def _unit(v):
    n = np.linalg.norm(v)
    return v / n if n > 0 else v


# --------------------------------------------------------------------------------------------
# Figures and axes
# --------------------------------------------------------------------------------------------


def _setup3d(ax, title, lim, elev, azim, labels):
    lo, hi = _limits(lim)
    labels = _labels(labels, 3, "labels")
    ax.set_xlim(lo, hi)
    ax.set_ylim(lo, hi)
    ax.set_zlim(lo, hi)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=_scalar(elev, "elev"), azim=_scalar(azim, "azim"))
    for setter, lab in zip((ax.set_xlabel, ax.set_ylabel, ax.set_zlabel), labels):
        setter(lab or "", fontsize=FONT_SIZE)
    ax.tick_params(axis="both", labelsize=FONT_SIZE - 2)
    ax.set_title(_text_arg(title, "title"), fontsize=TITLE_SIZE)


def _setup2d(ax, title, lim, labels):
    lo, hi = _limits(lim)
    labels = _labels(labels, 2, "labels")
    ax.set_xlim(lo, hi)
    ax.set_ylim(lo, hi)
    ax.set_aspect("equal")
    ax.set_xlabel(labels[0] or "", fontsize=FONT_SIZE)
    ax.set_ylabel(labels[1] or "", fontsize=FONT_SIZE)
    ax.axhline(0.0, color="0.85", linewidth=0.8, zorder=0)
    ax.axvline(0.0, color="0.85", linewidth=0.8, zorder=0)
    ax.tick_params(axis="both", labelsize=FONT_SIZE - 2)
    ax.set_title(_text_arg(title, "title"), fontsize=TITLE_SIZE)


def axes3d(
    title, ax=None, lim=1.5, elev=20.0, azim=-60.0, labels=("$x$", "$y$", "$z$"), figsize=FIGSIZE
):
    r"""Create (or set up) a 3D axes: equal-aspect cube, labelled x/y/z axes and a title.

    The cube is :math:`[-\mathrm{lim}, \mathrm{lim}]^3` (or :math:`[lo, hi]^3`), so lengths and
    right angles look right: an orthonormal frame is drawn with three equal, perpendicular arrows.

    Parameters
    ----------
    title : str
        Title of the axes.
    ax : mpl_toolkits.mplot3d.axes3d.Axes3D, optional
        An existing 3D axes to set up; by default a new figure is created.
    lim : float or (float, float), default 1.5
        Half-width of the cube, or its ``(lo, hi)`` bounds (the same on all three axes).
    elev, azim : float, default 20, -60
        Viewing angles in degrees (matplotlib's ``view_init``).
    labels : sequence of 3 str
        Axis labels (mathtext allowed).
    figsize : (float, float)
        Figure size in inches, used only when a new figure is created (dpi is fixed at DPI = 90).

    Returns
    -------
    fig : matplotlib.figure.Figure
    ax : mpl_toolkits.mplot3d.axes3d.Axes3D

    Raises
    ------
    TypeError
        If ``ax`` is not a 3D axes or ``title`` is not a string.
    ValueError
        If ``lim`` is not positive (or not ``lo < hi``).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = axes3d("A frame")
    >>> ax.get_title(), ax.get_xlim() == (-1.5, 1.5)
    ('A frame', True)
    >>> plt.close(fig)
    """
    if ax is None:
        _text_arg(title, "title")
        _limits(lim)
        fig = plt.figure(figsize=figsize, dpi=DPI)
        fig.subplots_adjust(left=0.02, right=0.92, bottom=0.02, top=0.95)
        ax = fig.add_subplot(projection="3d")
    else:
        _require_3d(ax, "axes3d")
        fig = ax.figure
    _setup3d(ax, title, lim, elev, azim, labels)
    return fig, ax


def axes2d(title, ax=None, lim=1.5, labels=("$x$", "$y$"), figsize=FIGSIZE):
    r"""Create (or set up) a 2D axes with equal aspect, labelled axes and a title.

    Used for planar figures such as the pendulum of eq. (117)-(118). A new figure uses
    constrained layout: when it is drawn, its margins grow to fit the tick labels, the axis labels
    and the title (and a legend or colour bar added later), so nothing is cut off on the full
    canvas and no ``fig.tight_layout()`` is needed. An existing ``ax`` keeps its figure's layout.

    Parameters
    ----------
    title : str
        Title of the axes.
    ax : matplotlib.axes.Axes, optional
        An existing 2D axes to set up; by default a new figure is created.
    lim : float or (float, float), default 1.5
        Half-width of the square window, or its ``(lo, hi)`` bounds.
    labels : sequence of 2 str
        Axis labels (mathtext allowed).
    figsize : (float, float)
        Figure size in inches for a new figure (dpi is fixed at DPI = 90).

    Returns
    -------
    fig : matplotlib.figure.Figure
    ax : matplotlib.axes.Axes

    Raises
    ------
    TypeError
        If ``ax`` is a 3D axes or ``title`` is not a string.
    ValueError
        If ``lim`` is not positive (or not ``lo < hi``).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = axes2d("Pendulum", lim=(-1, 1))
    >>> ax.get_xlabel(), ax.get_ylim() == (-1, 1)
    ('$x$', True)
    >>> plt.close(fig)
    """
    if ax is None:
        _text_arg(title, "title")
        _limits(lim)
        fig, ax = plt.subplots(figsize=figsize, dpi=DPI, layout=_LAYOUT_2D)
    else:
        if _dim(ax) != 2:
            raise TypeError("axes2d needs a 2D axes; got a 3D axes (use axes3d)")
        fig = ax.figure
    _setup2d(ax, title, lim, labels)
    return fig, ax


def axes_row(titles, kind="3d", lim=1.5, elev=20.0, azim=-60.0, labels=None):
    r"""A figure with one panel per title, side by side, for before/after comparisons.

    For example the phone at time 0 and at time t, or the rotation about z by 90° next to the
    reflection that is not a rigid body transformation.

    3D panels share fixed margins with room below the cubes for the x/y tick labels at any
    elevation ``elev`` from 0° to 90° (they reach lowest on the canvas for a camera about 30° to
    60° above) and room above them for the titles; 2D panels use constrained layout, like
    :func:`axes2d`.

    Parameters
    ----------
    titles : sequence of str
        One title per panel (at least one).
    kind : {"3d", "2d"}
        Kind of the panels.
    lim : float or (float, float)
        Limits of every panel (see :func:`axes3d`).
    elev, azim : float
        Viewing angles of 3D panels.
    labels : sequence of str, optional
        Axis labels; defaults to ``$x$, $y$(, $z$)``.

    Returns
    -------
    fig : matplotlib.figure.Figure
    axes : list of Axes
        One axes per title, left to right.

    Raises
    ------
    TypeError
        If ``titles`` is a single string or holds non-strings.
    ValueError
        If ``titles`` is empty, ``kind`` is unknown or ``lim`` is invalid.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig, axes = axes_row(["time 0", "time t"])
    >>> [a.get_title() for a in axes]
    ['time 0', 'time t']
    >>> plt.close(fig)
    """
    if isinstance(titles, str):
        raise TypeError("titles must be a sequence of str (one per panel), got a single str")
    titles = list(titles)
    if not titles:
        raise ValueError("titles must hold at least one title (one per panel), got none")
    for t in titles:
        _text_arg(t, "each title")
    if kind not in ("3d", "2d"):
        raise ValueError(f"kind must be '3d' or '2d', got {kind!r}")
    _limits(lim)
    n = len(titles)
    if kind == "3d":
        fig = plt.figure(figsize=(PANEL_SIZE * n, PANEL_SIZE), dpi=DPI)
        fig.subplots_adjust(**_ROW_MARGINS_3D)
    else:
        fig = plt.figure(figsize=(PANEL_SIZE * n, PANEL_SIZE), dpi=DPI, layout=_LAYOUT_2D)
    axes = [
        fig.add_subplot(1, n, i + 1, projection="3d" if kind == "3d" else None) for i in range(n)
    ]
    for ax, title in zip(axes, titles):
        if kind == "3d":
            _setup3d(ax, title, lim, elev, azim, labels or ("$x$", "$y$", "$z$"))
        else:
            _setup2d(ax, title, lim, labels or ("$x$", "$y$"))
    return fig, axes


# --------------------------------------------------------------------------------------------
# Primitives
# --------------------------------------------------------------------------------------------


def draw_frame(
    ax,
    R=None,
    origin=None,
    label="A",
    scale=1.0,
    style="solid",
    colors=FRAME_COLORS,
    axis_names=("x", "y", "z"),
):
    r"""Draw a reference frame: the columns of ``R`` as arrows from ``origin``.

    The columns of :math:`R_{ab} = [x_{ab}\; y_{ab}\; z_{ab}]` (eq. 26) are the axes of frame B
    seen in frame A, so the i-th arrow goes from :math:`o` to

    .. math:: o + s\, R e_i, \qquad i = 1, 2, 3,

    and is labelled :math:`x_A, y_A, z_A` (subscript ``label``). ``R`` need not be a rotation:
    the notes' counterexample draws the frame after a reflection (use
    ``so3.check_rotation`` first when a rotation is required).

    Parameters
    ----------
    ax : Axes
        A 3D axes (or a 2D axes, with a 2x2 ``R`` and 2-vectors).
    R : array_like, shape (3, 3) or (2, 2), optional
        Matrix whose columns are the frame axes; identity by default.
    origin : array_like, shape (3,) or (2,), optional
        Origin of the frame; the zero vector by default.
    label : str or None, default "A"
        Frame name, used as subscript of the axis labels and written at the origin.
    scale : float, default 1
        Length factor of the arrows.
    style : {"solid", "dashed", "dotted", "dashdot"}
        Line style (e.g. dashed for the frame before a motion).
    colors : sequence of 3 (or 2) colours
        Colours of the x, y, z arrows.
    axis_names : sequence of 3 (or 2) str
        Names of the axes used in the labels.

    Returns
    -------
    Drawn
        ``artists``: the arrows, their labels, the frame name; ``points``: the arrow tips,
        shape (d, d), row i is :math:`o + s R e_i`; ``origin``: the origin.

    Raises
    ------
    ValueError
        If ``R`` or ``origin`` has the wrong shape or non-finite entries, a column of ``R`` has
        norm ``<= TOL`` (an axis of length zero), ``scale <= 0`` or ``style`` is unknown.
    TypeError
        If the inputs are not numeric, or labels are not strings.

    Examples
    --------
    >>> import numpy as np, matplotlib.pyplot as plt
    >>> fig, ax = axes3d("Frame B")
    >>> frame = draw_frame(ax, R=[[-1, 0, 0], [0, 1, 0], [0, 0, -1]], label="B")
    >>> np.allclose(frame.points[0], [-1, 0, 0])
    True
    >>> plt.close(fig)
    """
    d = _dim(ax)
    R = np.eye(d) if R is None else _matrix(R, "R", d)
    o = _origin(origin, d)
    s = _scalar(scale, "scale", positive=True)
    ls = _linestyle(style)
    colors = list(colors)
    names = list(axis_names)
    if len(colors) != d or len(names) != d:
        raise ValueError(
            f"colors and axis_names must hold {d} entries each, got {len(colors)} and {len(names)}"
        )
    if label is not None:
        _text_arg(label, "label")
    col_norms = np.linalg.norm(R, axis=0)
    for i, n in enumerate(col_norms):
        if n <= TOL:
            raise ValueError(
                f"R column {i} ({names[i]} axis) has zero length: "
                f"‖R e_{i + 1}‖ = {fmt_residual(n, TOL)} ≤ {tol_label(TOL)}"
            )
    tips = o + s * R.T
    artists = []
    pad = _offset(ax)
    for i in range(d):
        artists.append(_arrow(ax, o, tips[i], colors[i], ls))
        name = f"${names[i]}_{{{label}}}$" if label else f"${names[i]}$"
        artists.append(_text(ax, tips[i] + pad * _unit(R[:, i]), name, color=colors[i]))
    if label:
        away = -_unit(R.sum(axis=1))  # opposite the axes, so the name does not sit on an arrow
        artists.append(_text(ax, o + 1.2 * pad * away, f"${label}$"))
    return Drawn("frame", artists, tips, origin=o)


def draw_vector(ax, v, origin=None, label=None, color="black", style="solid", linewidth=1.8):
    r"""Draw the vector ``v`` as an arrow from ``origin`` to ``origin + v``.

    A vector is the difference of two points, :math:`v = p - q` (eq. 7); drawing it from
    different origins shows that it is a free vector (eq. 8).

    Parameters
    ----------
    ax : Axes
        A 3D axes (3-vectors) or a 2D axes (2-vectors).
    v : array_like, shape (3,) or (2,)
        The vector. A zero vector draws a dot at the origin.
    origin : array_like, optional
        Tail of the arrow; the zero vector by default.
    label : str, optional
        Text written just beyond the tip (mathtext allowed, e.g. ``"$v$"``).
    color : colour, default "black"
    style : {"solid", "dashed", "dotted", "dashdot"}
    linewidth : float, default 1.8

    Returns
    -------
    Drawn
        ``points``: shape (2, d), the tail and the tip.

    Raises
    ------
    ValueError
        If ``v`` or ``origin`` has the wrong shape or non-finite entries, or ``style`` is unknown.

    Examples
    --------
    >>> import numpy as np, matplotlib.pyplot as plt
    >>> fig, ax = axes3d("A free vector")
    >>> arrow = draw_vector(ax, [1, 1, 0], origin=[0, 0, 1], label="$v$")
    >>> np.allclose(arrow.points[1], [1, 1, 1]), len(arrow)
    (True, 2)
    >>> plt.close(fig)
    """
    d = _dim(ax)
    v = _vector(v, "v", d)
    o = _origin(origin, d)
    ls = _linestyle(style)
    lw = _scalar(linewidth, "linewidth", positive=True)
    tip = o + v
    if np.linalg.norm(v) == 0.0:
        artists = [ax.scatter(*o[:, None], color=color, s=12)]
    else:
        artists = [_arrow(ax, o, tip, color, ls, lw)]
    if label is not None:
        pos = tip + _offset(ax) * _unit(v)
        artists.append(_text(ax, pos, _text_arg(label, "label"), color=color))
    return Drawn("vector", artists, np.stack([o, tip]))


def draw_point(ax, p, label=None, color="black", size=30, marker="o"):
    r"""Draw one point or a set of points (e.g. the particles of a rigid body).

    Parameters
    ----------
    ax : Axes
        A 3D or 2D axes.
    p : array_like, shape (d,) or (n, d)
        The point(s), in the coordinates of the axes.
    label : str or sequence of str, optional
        One label per point, written next to it (``None`` entries are skipped).
    color : colour, default "black"
    size : float, default 30
        Marker area in points².
    marker : str, default "o"

    Returns
    -------
    Drawn
        ``points``: shape (n, d).

    Raises
    ------
    ValueError
        If ``p`` has the wrong shape or non-finite entries, or the number of labels differs from
        the number of points.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = axes3d("Particles")
    >>> body = draw_point(ax, [[0, 0, 0], [1, 0, 0], [0, 1, 0]], label=["$p_1$", "$p_2$", None])
    >>> body.points.shape, len(body)
    ((3, 3), 3)
    >>> plt.close(fig)
    """
    d = _dim(ax)
    P = _points(p, "p", d)
    labels = _labels(label, len(P), "label")
    s = _scalar(size, "size", positive=True)
    kwargs = {"depthshade": False} if d == 3 else {}
    artists = [ax.scatter(*P.T, color=color, s=s, marker=marker, **kwargs)]
    pad = _offset(ax)
    shift = np.full(d, pad / np.sqrt(d))
    for q, lab in zip(P, labels):
        if lab is not None:
            artists.append(_text(ax, q + shift, lab, color=color, ha="left", va="bottom"))
    return Drawn("point", artists, P)


def _screen_basis(ax, d):
    """World vectors (right, up) that point right and up on the screen.

    On a 2D axes these are the x and y directions. On a 3D axes they are built from the current
    view (``ax.elev`` = e, ``ax.azim`` = a): the camera looks at the cube from the direction
    c = (cos e cos a, cos e sin a, sin e), the screen's right is (−sin a, cos a, 0) and its up
    is c × right.
    """
    if d == 2:
        return np.array([1.0, 0.0]), np.array([0.0, 1.0])
    e, a = np.radians(ax.elev), np.radians(ax.azim)
    camera = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
    right = np.array([-np.sin(a), np.cos(a), 0.0])
    return right, np.cross(camera, right)


def _beside(ax, d, direction):
    """Where to put a label beside a line: (unit offset n in world coordinates, ha, va).

    ``n`` is perpendicular to ``direction`` as seen on the screen (and in space) and points up
    on the screen as far as possible (right beside a vertical line); the text is anchored on its
    side facing the line, so it grows away from the line.
    """
    right, up = _screen_basis(ax, d)
    along = np.array([direction @ right, direction @ up])
    if np.linalg.norm(along) <= TOL:  # the line points at the viewer: go straight up
        n2 = np.array([0.0, 1.0])
    else:
        n2 = np.array([-along[1], along[0]]) / np.linalg.norm(along)
        if n2[1] < 0 or (n2[1] == 0 and n2[0] < 0):
            n2 = -n2
    ha = "left" if n2[0] > 0.4 else ("right" if n2[0] < -0.4 else "center")
    va = "bottom" if n2[1] > 0.4 else "center"
    return n2[0] * right + n2[1] * up, ha, va


def draw_segment(ax, p, q, label=None, color="black", style="dashed", linewidth=1.2, label_at=0.65):
    r"""Draw the segment from ``p`` to ``q``, e.g. the distance :math:`\|p_1 - p_2\|` of eq. (9).

    The label is written beside the point at the fraction :math:`t` = ``label_at`` of the way
    from ``p`` to ``q``, moved off the line by the label gap :math:`\delta` of the axes (5% of
    the x span) perpendicular to the segment:

    .. math:: \ell = p + t\,(q - p) + \delta\, n, \qquad n \perp (q - p),\ \|n\| = 1,

    where :math:`n` is perpendicular to the segment as seen on the screen (on a 3D axes, for the
    view at the time of drawing: :math:`n` lies in the plane of the screen) and points up on the
    screen as far as possible; the text is anchored on its side facing the segment, so it grows
    away from the line. The default :math:`t = 0.65` keeps the label off the midpoint, where marks
    placed symmetrically on a body (as on the phone of :func:`draw_box`) have the body's centre
    and, with ``frame=...``, its frame and the frame's name, and leaves room near the end points
    for the labels :func:`draw_point` writes there. In a crowded figure choose ``label_at``
    (0.5 for the midpoint).

    Parameters
    ----------
    ax : Axes
        A 3D or 2D axes.
    p, q : array_like, shape (d,)
        End points.
    label : str, optional
        Text written beside the segment (e.g. ``f"{d:.2f}"``).
    color : colour, default "black"
    style : {"dashed", "solid", "dotted", "dashdot"}
    linewidth : float, default 1.2
    label_at : float in [0, 1], default 0.65
        Where along the segment the label goes: 0 at ``p``, 0.5 at the midpoint, 1 at ``q``.

    Returns
    -------
    Drawn
        ``points``: shape (2, d), ``p`` and ``q``; ``length``: :math:`\|p - q\|`;
        ``label_position``: :math:`\ell`, shape (d,), or ``None`` without a label.

    Raises
    ------
    ValueError
        If ``p`` or ``q`` has the wrong shape or non-finite entries, ``style`` is unknown, or
        ``label_at`` is not a number in [0, 1].
    TypeError
        If ``label`` is not a string.

    Examples
    --------
    >>> import numpy as np, matplotlib.pyplot as plt
    >>> fig, ax = axes3d("Distance")
    >>> seg = draw_segment(ax, [0, 0, 0], [0, 3, 4], label="5")
    >>> float(seg.length)
    5.0
    >>> gap = seg.label_position - [0, 1.95, 2.6]   # 0.65 of the way from p to q, then across
    >>> bool(np.isclose(gap @ [0, 3, 4], 0.0))        # the segment, perpendicular to it
    True
    >>> plt.close(fig)
    """
    d = _dim(ax)
    p = _vector(p, "p", d)
    q = _vector(q, "q", d)
    ls = _linestyle(style)
    lw = _scalar(linewidth, "linewidth", positive=True)
    t = _scalar(label_at, "label_at")
    if not 0.0 <= t <= 1.0:
        raise ValueError(
            f"label_at must be a fraction of the segment in [0, 1] (0 at p, 1 at q), got {t!r}"
        )
    artists = [_line(ax, [p, q], color, ls, lw)]
    pos = None
    if label is not None:
        text = _text_arg(label, "label")
        n, ha, va = _beside(ax, d, _unit(q - p))
        pos = p + t * (q - p) + _offset(ax) * n
        artists.append(_text(ax, pos, text, color=color, ha=ha, va=va))
    return Drawn(
        "segment",
        artists,
        np.stack([p, q]),
        length=float(np.linalg.norm(p - q)),
        label_position=pos,
    )


def draw_curve(ax, points, label=None, color="black", style="solid", arrow=False, linewidth=1.8):
    r"""Draw a curve through ``points``: a trajectory :math:`p(t)` (eq. 6) or an orbit.

    Parameters
    ----------
    ax : Axes
        A 3D or 2D axes.
    points : array_like, shape (n, d), n >= 2
        Samples of the curve, in order (e.g. :math:`p(t_k)`).
    label : str, optional
        Text written next to the last point.
    color : colour, default "black"
    style : {"solid", "dashed", "dotted", "dashdot"}
    arrow : bool, default False
        Put an arrow head at the last point to show the direction of motion.
    linewidth : float, default 1.8

    Returns
    -------
    Drawn
        ``points``: the samples, shape (n, d).

    Raises
    ------
    ValueError
        If ``points`` is not (n, d) with n >= 2 or has non-finite entries.

    Examples
    --------
    >>> import numpy as np, matplotlib.pyplot as plt
    >>> fig, ax = axes3d("A trajectory")
    >>> t = np.linspace(0, 1, 50)
    >>> p = np.stack([np.cos(t), np.sin(t), t], axis=-1)
    >>> curve = draw_curve(ax, p, label="$p(t)$", arrow=True)
    >>> curve.points.shape, len(curve)
    ((50, 3), 3)
    >>> plt.close(fig)
    """
    d = _dim(ax)
    P = _points(points, "points", d, min_count=2)
    ls = _linestyle(style)
    lw = _scalar(linewidth, "linewidth", positive=True)
    artists = [_line(ax, P, color, ls, lw)]
    if arrow:
        # the last step with non-zero length gives the direction of motion
        steps = np.linalg.norm(np.diff(P, axis=0), axis=1)
        moving = np.nonzero(steps > 0)[0]
        if moving.size:
            k = moving[-1]
            artists.append(_arrow(ax, P[k], P[k + 1], color, "-", lw))
    if label is not None:
        pos = P[-1] + np.full(d, _offset(ax) / np.sqrt(d))
        text = _text_arg(label, "label")
        artists.append(_text(ax, pos, text, color=color, ha="left", va="bottom"))
    return Drawn("curve", artists, P)


def draw_plane(ax, a, b, origin=None, label=None, color="tab:gray", alpha=0.25, tol=TOL):
    r"""Shade the parallelogram spanned by ``a`` and ``b`` (a patch of the plane of a and b).

    Its corners are :math:`o,\; o + a,\; o + a + b,\; o + b`. Drawn together with
    :math:`a \times b`, it shows that the cross product is normal to the whole plane.

    Parameters
    ----------
    ax : Axes
        A 3D or 2D axes.
    a, b : array_like, shape (d,)
        Spanning vectors; they must not be parallel.
    origin : array_like, shape (d,), optional
        Common tail of ``a`` and ``b``; zero by default.
    label : str, optional
        Text written at the centre of the patch.
    color : colour, default "tab:gray"
    alpha : float, default 0.25
        Opacity of the patch.
    tol : float, default TOL
        ``a`` and ``b`` are parallel when :math:`\|a \times b\| \le` tol (in 2D,
        :math:`|a_1 b_2 - a_2 b_1| \le` tol).

    Returns
    -------
    Drawn
        ``points``: the four corners, shape (4, d), in the order above; ``normal``:
        :math:`a \times b` (3D only, else ``None``).

    Raises
    ------
    ValueError
        If ``a`` and ``b`` are parallel (they span no plane), or have the wrong shape or
        non-finite entries.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = axes3d("Plane of a and b")
    >>> patch = draw_plane(ax, [1, 0, 0], [0.5, 1, 0])
    >>> patch.normal.tolist()
    [0.0, 0.0, 1.0]
    >>> plt.close(fig)
    """
    d = _dim(ax)
    a = _vector(a, "a", d)
    b = _vector(b, "b", d)
    o = _origin(origin, d)
    tol = _scalar(tol, "tol", positive=True)
    if d == 3:
        normal = np.cross(a, b)
        area = float(np.linalg.norm(normal))
    else:
        normal = None
        area = float(abs(a[0] * b[1] - a[1] * b[0]))
    if area <= tol:
        raise ValueError(
            f"a and b are parallel and span no plane: ‖a × b‖ = {fmt_residual(area, tol)} "
            f"≤ {tol_label(tol)}"
        )
    corners = np.stack([o, o + a, o + a + b, o + b])
    if d == 3:
        patch = Poly3DCollection([corners], facecolor=color, edgecolor=color, alpha=alpha)
        ax.add_collection3d(patch)
    else:
        patch = Polygon(corners, closed=True, facecolor=color, edgecolor=color, alpha=alpha)
        ax.add_patch(patch)
    artists = [patch]
    if label is not None:
        artists.append(_text(ax, corners.mean(axis=0), _text_arg(label, "label"), color="black"))
    return Drawn("plane", artists, corners, normal=normal)


def _rotate_about(k, thetas, v):
    """Rotate v about the unit axis k by each angle: rows e^{k̂ θ_j} v (Rodrigues, eq. 159)."""
    return so3.exp(thetas[:, None] * k) @ v


def draw_arc(
    ax,
    axis,
    start,
    angle,
    center=None,
    n=60,
    label=None,
    color="black",
    style="solid",
    arrow=True,
    tol=TOL,
):
    r"""Draw the arc swept by the vector ``start`` rotating about ``axis`` by ``angle``.

    The arc is the set of points

    .. math:: c + e^{\hat\omega \theta} s, \qquad \theta \in [0, \mathrm{angle}],

    with :math:`\omega = \mathrm{axis}/\|\mathrm{axis}\|` (eq. 125): every point stays at the
    same distance from the axis, and the swept angle is ``angle`` (positive is counterclockwise
    seen from the tip of the axis, by the right hand rule). On a 2D axes the rotation is in the
    plane about ``center`` and ``axis`` must be ``None``.

    Parameters
    ----------
    ax : Axes
        A 3D axes, or a 2D axes with ``axis=None``.
    axis : array_like, shape (3,), or None
        Direction of the axis of rotation (need not be unit).
    start : array_like, shape (d,)
        Vector from ``center`` to the first point of the arc.
    angle : float
        Swept angle in radians (any sign; 0 gives a single point).
    center : array_like, shape (d,), optional
        A point on the axis (3D) or the centre of the arc (2D); zero by default.
    n : int, default 60
        Number of points on the arc (>= 2).
    label : str, optional
        Text written at the middle of the arc (e.g. ``r"$\theta$"``).
    color : colour, default "black"
    style : {"solid", "dashed", "dotted", "dashdot"}
    arrow : bool, default True
        Put an arrow head at the end of the arc.
    tol : float, default TOL
        ``axis`` is zero when its norm is <= tol; ``start`` lies on the axis when its distance
        from the axis is <= tol.

    Returns
    -------
    Drawn
        ``points``: the arc, shape (n, d); ``axis``: the unit axis (3D) or ``None``;
        ``radius``: distance of the arc from the axis (centre).

    Raises
    ------
    ValueError
        If ``axis`` is zero, ``start`` lies on the axis, ``n < 2``, or an input has the wrong
        shape or non-finite entries.
    TypeError
        If ``axis`` is given on a 2D axes or missing on a 3D axes.

    Examples
    --------
    >>> import numpy as np, matplotlib.pyplot as plt
    >>> fig, ax = axes3d("Rotation about z")
    >>> arc = draw_arc(ax, [0, 0, 1], [1, 0, 0], np.pi / 2, label=r"$\theta$")
    >>> np.allclose(arc.points[-1], [0, 1, 0])
    True
    >>> plt.close(fig)
    """
    d = _dim(ax)
    s = _vector(start, "start", d)
    c = _origin(center, d)
    theta = _scalar(angle, "angle")
    tol = _scalar(tol, "tol", positive=True)
    n = as_count(n, "n (number of points on the arc)", minimum=2)
    ls = _linestyle(style)
    thetas = np.linspace(0.0, theta, n)
    arc_points = _arc_points_3d if d == 3 else _arc_points_2d
    k, radius, pts = arc_points(axis, s, thetas, tol)
    pts = c + pts
    artists = [_line(ax, pts, color, ls)]
    if arrow and theta != 0.0:
        artists.append(_arrow(ax, pts[-2], pts[-1], color))
    if label is not None:
        mid = pts[len(pts) // 2]
        if d == 3:
            out = mid - c - (k @ (mid - c)) * k  # away from the axis
        else:
            out = mid - c
        pos = mid + _offset(ax) * _unit(out)
        artists.append(_text(ax, pos, _text_arg(label, "label"), color=color))
    return Drawn("arc", artists, pts, axis=k, radius=radius)


def _arc_points_3d(axis, s, thetas, tol):
    """The unit axis k, the radius and the points e^(k̂θ) s of an arc about the origin."""
    if axis is None:
        raise TypeError("draw_arc on a 3D axes needs an axis of rotation, got None")
    k = as_direction(axis, "axis", tol)
    radius = float(np.linalg.norm(s - (k @ s) * k))
    if radius <= tol:
        raise ValueError(
            f"start lies on the axis, so the arc is a single point: "
            f"distance from the axis = {fmt_residual(radius, tol)} ≤ {tol_label(tol)}"
        )
    return k, radius, _rotate_about(k, thetas, s)


def _arc_points_2d(axis, s, thetas, tol):
    """No axis (the plane's normal), the radius and the points of s turned by each θ."""
    if axis is not None:
        raise TypeError("draw_arc on a 2D axes rotates in the plane: pass axis=None")
    radius = float(np.linalg.norm(s))
    if radius <= tol:
        raise ValueError(
            f"start must be non-zero: ‖start‖ = {fmt_residual(radius, tol)} ≤ {tol_label(tol)}"
        )
    cos, sin = np.cos(thetas), np.sin(thetas)
    return None, radius, np.stack([cos * s[0] - sin * s[1], sin * s[0] + cos * s[1]], axis=-1)


_BOX_FACES = ((0, 1, 3, 2), (4, 5, 7, 6), (0, 1, 5, 4), (2, 3, 7, 6), (0, 2, 6, 4), (1, 3, 7, 5))


def draw_box(
    ax,
    R=None,
    center=None,
    size=(0.5, 1.0, 0.1),
    marks=None,
    mark_labels=None,
    frame=None,
    color="tab:blue",
    alpha=0.25,
    tol=TOL,
):
    r"""Draw a rigid box (e.g. the phone of eq. 9) with orientation ``R`` about ``center``.

    A point with body coordinates :math:`m` (relative to the box centre) is drawn at the world
    position

    .. math:: p = c + R\, m,

    so the distances between marked points do not change under rotation (Proposition 7).

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.axes3d.Axes3D
        A 3D axes.
    R : array_like, shape (3, 3), optional
        Orientation of the box; must be a rotation (identity by default).
    center : array_like, shape (3,), optional
        World position of the box centre; zero by default.
    size : array_like, shape (3,), default (0.5, 1.0, 0.1)
        Edge lengths along the body x, y, z axes (all > 0).
    marks : array_like, shape (3,) or (k, 3), optional
        Points on the body, in body coordinates relative to the centre.
    mark_labels : str or sequence of str, optional
        One label per mark (e.g. ``["$p_1$", "$p_2$"]``).
    frame : str, optional
        If given, also draw the body frame at the centre with this name.
    color : colour, default "tab:blue"
    alpha : float, default 0.25
        Opacity of the faces.
    tol : float, default TOL
        Tolerance of the rotation check on ``R``.

    Returns
    -------
    Drawn
        ``points``: world coordinates of the marks, shape (k, 3) (k = 0 without marks);
        ``corners``: the 8 world corners, shape (8, 3).

    Raises
    ------
    ValueError
        If ``R`` is not a rotation (``so3.check_rotation``), ``size`` is not positive, or an
        input has the wrong shape or non-finite entries.
    TypeError
        If ``ax`` is a 2D axes.

    Examples
    --------
    >>> import numpy as np, matplotlib.pyplot as plt
    >>> fig, ax = axes3d("The phone")
    >>> marks = [[0.2, 0.4, 0.05], [-0.2, -0.4, 0.05]]
    >>> phone = draw_box(ax, marks=marks, mark_labels=["$p_1$", "$p_2$"])
    >>> round(float(np.linalg.norm(phone.points[0] - phone.points[1])), 6)
    0.894427
    >>> plt.close(fig)
    """
    _require_3d(ax, "draw_box")
    tol = _scalar(tol, "tol", positive=True)
    if R is None:
        R = np.eye(3)
    else:
        R = _matrix(R, "R", 3)
        so3.check_rotation(R, tol=tol)
    c = _origin(center, 3)
    size = _vector(size, "size", 3)
    if not np.all(size > 0):
        raise ValueError(f"size must have three positive edge lengths, got {size.tolist()}")
    half = size / 2
    signs = (-1.0, 1.0)
    body_corners = np.array([[sx, sy, sz] for sx in signs for sy in signs for sz in signs]) * half
    corners = c + body_corners @ R.T
    faces = [corners[list(f)] for f in _BOX_FACES]
    box = Poly3DCollection(faces, facecolor=color, edgecolor="0.25", linewidth=0.8, alpha=alpha)
    ax.add_collection3d(box)
    artists = [box]
    if marks is None:
        world = np.zeros((0, 3))
        if mark_labels is not None:
            raise ValueError("mark_labels given without marks")
    else:
        M = _points(marks, "marks", 3)
        world = c + M @ R.T
        artists.extend(draw_point(ax, world, label=mark_labels, color="black").artists)
    if frame is not None:
        artists.extend(
            draw_frame(
                ax, R, origin=c, label=_text_arg(frame, "frame"), scale=0.6 * float(size.max())
            ).artists
        )
    return Drawn("box", artists, world, corners=corners)


def draw_pendulum(ax, theta, r=1.0, omega=1.0, pivot=None, velocity_scale=1.0):
    r"""Draw the planar pendulum of eq. (117)-(118): rod, bob, angle and velocity.

    With the angle :math:`\theta` measured from the downward vertical, the bob is at
    :math:`c + r(\sin\theta, -\cos\theta)` and its velocity is

    .. math:: v = r\omega\,(\cos\theta, \sin\theta), \qquad \|v\| = |r\omega|,

    drawn in green from the bob (times ``velocity_scale``, for display only).

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        A 2D axes (e.g. from :func:`axes2d`).
    theta : float
        Angle from the downward vertical, in radians.
    r : float, default 1
        Rod length (> 0).
    omega : float, default 1
        Angular velocity :math:`\dot\theta` in rad/s (0 draws no velocity arrow).
    pivot : array_like, shape (2,), optional
        Point of attachment; zero by default.
    velocity_scale : float, default 1
        Display factor of the velocity arrow (> 0).

    Returns
    -------
    Drawn
        ``points``: the pivot and the bob, shape (2, 2); ``velocity``: :math:`v` (unscaled).

    Raises
    ------
    ValueError
        If ``r <= 0``, ``velocity_scale <= 0`` or an input is not finite.
    TypeError
        If ``ax`` is a 3D axes.

    Examples
    --------
    >>> import numpy as np, matplotlib.pyplot as plt
    >>> fig, ax = axes2d("Pendulum")
    >>> pend = draw_pendulum(ax, np.pi / 6, r=1.2, omega=0.5)
    >>> round(float(np.linalg.norm(pend.velocity)), 12)
    0.6
    >>> plt.close(fig)
    """
    if _dim(ax) != 2:
        raise TypeError("draw_pendulum needs a 2D axes (e.g. from axes2d); got a 3D axes")
    th = _scalar(theta, "theta")
    r = _scalar(r, "r", positive=True)
    om = _scalar(omega, "omega")
    vs = _scalar(velocity_scale, "velocity_scale", positive=True)
    c = _origin(pivot, 2)
    bob = c + r * np.array([np.sin(th), -np.cos(th)])
    v = r * om * np.array([np.cos(th), np.sin(th)])
    artists = []
    artists.extend(draw_segment(ax, c, c + np.array([0.0, -r]), color="0.5", style="dotted"))
    artists.extend(draw_segment(ax, c, bob, style="solid", linewidth=2.0))
    beside_rod = _offset(ax) * np.array([np.cos(th), np.sin(th)])
    artists.append(_text(ax, (c + bob) / 2 + beside_rod, "$r$"))
    artists.extend(draw_point(ax, c, color="black", size=20, marker="s"))
    artists.extend(draw_point(ax, bob, color="black", size=120))
    if th != 0.0:
        artists.extend(
            draw_arc(ax, None, [0.0, -0.3 * r], th, center=c, label=r"$\theta$", arrow=False)
        )
    if om != 0.0:
        artists.extend(draw_vector(ax, vs * v, origin=bob, label="$v$", color="tab:green"))
    return Drawn("pendulum", artists, np.stack([c, bob]), velocity=v)


def _error_series(series, shape):
    """The error curves by name, each of ``shape``, >= 0; zeros become gaps (NaN) on a log scale."""
    ys = {}
    for name, err in series.items():
        y = _array(err, "errors" if name is None else f"errors[{name!r}]")
        if y.shape != shape:
            raise ValueError(f"errors must have the shape of terms {shape}, got {y.shape}")
        if (y < 0).any():
            raise ValueError(f"errors must be >= 0 (they are norms), got min {y.min():.3g}")
        if not (y > 0).any():
            raise ValueError("no error is positive: nothing to show on a log scale")
        ys[name] = np.where(y > 0, y, np.nan)
    return ys


def _reference_curves(references, shape):
    """The reference curves by name, each positive and of ``shape``."""
    refs = {}
    for name, ref in references.items():
        y = _array(ref, f"references[{name!r}]")
        if y.shape != shape or not (y > 0).all():
            raise ValueError(
                f"references[{name!r}] must be positive with the shape of terms "
                f"{shape}, got shape {y.shape}"
            )
        refs[name] = y
    return refs


def plot_convergence(
    terms,
    errors,
    title="Convergence of the series",
    ax=None,
    label=None,
    show_tol=True,
    xlabel="number of terms $N$",
    ylabel=r"error $\|\cdot\|_F$ (log scale)",
    references=None,
    logx=False,
):
    r"""Semilog plot of an approximation error against the number of series terms.

    Made for the truncated series of the matrix exponential (eq. 124, 126),

    .. math:: \Big\| \sum_{n=0}^{N-1} \frac{A^n}{n!} - e^{A} \Big\|_F,

    but any non-negative errors can be plotted. Exact zeros cannot be shown on a log axis and
    are left out of the line; a dotted line marks the tolerance ``TOL``. A new figure uses
    constrained layout (see :func:`axes2d`): long tick labels such as :math:`10^{-16}` and a
    tall y label fit on the canvas without ``fig.tight_layout()``.

    Parameters
    ----------
    terms : array_like, shape (k,)
        Numbers of terms (the x values).
    errors : array_like, shape (k,), or dict of str -> array_like
        Errors for each entry of ``terms``; a dict plots one labelled line per entry.
    title : str
        Title of the axes.
    ax : matplotlib.axes.Axes, optional
        A 2D axes to draw into; a new figure by default.
    label : str, optional
        Legend label of a single error array.
    show_tol : bool, default True
        Draw the horizontal line ``y = TOL``.
    xlabel, ylabel : str
        Axis labels.
    references : dict of str -> array_like, optional
        Reference curves (a bound, a slope :math:`N^{-p}`), each of the shape of ``terms``,
        drawn as thin dashed black lines with their label.
    logx : bool, default False
        Log scale on the x axis too (for convergence orders: a power law is a straight line).

    Returns
    -------
    fig : matplotlib.figure.Figure
    ax : matplotlib.axes.Axes

    Raises
    ------
    ValueError
        If shapes differ, an error is negative or non-finite, or no error is positive; or a
        reference curve does not have the shape of ``terms`` or is not positive.
    TypeError
        If ``ax`` is a 3D axes.

    Examples
    --------
    >>> import math, matplotlib.pyplot as plt
    >>> n = [1, 2, 3, 4, 5]
    >>> errors = [abs(math.e - sum(1 / math.factorial(j) for j in range(k))) for k in n]
    >>> fig, ax = plot_convergence(n, errors)
    >>> ax.get_yscale(), len(ax.get_lines())
    ('log', 2)
    >>> plt.close(fig)
    >>> fig, ax = plot_convergence(n, errors, show_tol=False, logx=True,
    ...                            references={"bound": [2 * e for e in errors]})
    >>> ax.get_xscale(), ax.get_lines()[-1].get_label(), ax.get_lines()[-1].get_linestyle()
    ('log', 'bound', '--')
    >>> plt.close(fig)
    """
    x = _array(terms, "terms")
    if x.ndim != 1 or x.size == 0:
        raise ValueError(f"terms must be a non-empty 1-D array, got shape {x.shape}")
    ys = _error_series(errors if isinstance(errors, dict) else {label: errors}, x.shape)
    refs = _reference_curves(references or {}, x.shape)
    if ax is None:
        _text_arg(title, "title")
        fig, ax = plt.subplots(figsize=(5.6, 4.0), dpi=DPI, layout=_LAYOUT_2D)
    else:
        if _dim(ax) != 2:
            raise TypeError("plot_convergence needs a 2D axes; got a 3D axes")
        fig = ax.figure
    for name, y in ys.items():
        ax.plot(x, y, marker="o", markersize=4, linewidth=1.8, label=name)
    for name, y in refs.items():
        ax.plot(x, y, color="black", linestyle="--", linewidth=1.0, label=name)
    ax.set_yscale("log")
    if logx:
        ax.set_xscale("log")
    if show_tol:
        ax.axhline(TOL, color="0.4", linestyle=":", linewidth=1.2, label=tol_label(TOL))
    ax.set_xlabel(_text_arg(xlabel, "xlabel"), fontsize=FONT_SIZE)
    ax.set_ylabel(_text_arg(ylabel, "ylabel"), fontsize=FONT_SIZE)
    ax.set_title(_text_arg(title, "title"), fontsize=TITLE_SIZE)
    ax.tick_params(axis="both", labelsize=FONT_SIZE - 2)
    ax.grid(True, which="major", color="0.9")
    if any(name is not None for name in ys) or show_tol or refs:
        ax.legend(fontsize=FONT_SIZE - 1)
    return fig, ax


# --------------------------------------------------------------------------------------------
# Chapter 04: composing, interpolating and reading rotations
# --------------------------------------------------------------------------------------------

__all__ += ["frame_panels", "plot_error_curves", "plot_geodesic", "plot_rodrigues_circle"]

_PANEL_KEYS = ("title", "frames", "vectors", "boxes", "axis")


def _axis_line(ax, direction, label=None, origin=None, color="0.45"):
    """A dashed line through ``origin`` along ±``direction`` (length 1.2), labelled at its tip."""
    k = as_direction(direction, "direction")
    o = _origin(origin, 3)
    artists = [_line(ax, [o - 1.2 * k, o + 1.2 * k], color, "--", 1.2)]
    if label is not None:
        artists.append(
            _text(ax, o + (1.2 + _offset(ax)) * k, _text_arg(label, "label"), color=color)
        )
    return Drawn("axis", artists, np.stack([o - 1.2 * k, o + 1.2 * k]))


def _frame(ax, name=True, labels="tip", **kwargs):
    """:func:`draw_frame`; with ``name=False`` the frame's name at its origin is left out.

    The axis labels keep the name as subscript. Two frames with a common origin would
    otherwise write their names on top of each other. With ``labels="beside"`` each axis
    label moves from beyond the arrow's tip to the side of the tip: a short frame "before" a
    motion then keeps its labels off the longer arrows of a frame that shares its axes (a turn
    about z leaves z in place).
    """
    if labels not in ("tip", "beside"):
        raise ValueError(f"labels must be 'tip' or 'beside', got {labels!r}")
    drawn = draw_frame(ax, **kwargs)
    if not name and kwargs.get("label", "A"):
        drawn.artists.pop().remove()  # draw_frame writes the name last
    if labels == "beside":
        for tip, text in zip(drawn.points, drawn.artists[1:7:2]):  # arrow, label, arrow, ...
            n, ha, va = _beside(ax, 3, tip - drawn.origin)
            text.set_position_3d(tip + 0.6 * _offset(ax) * n)
            text.set_horizontalalignment(ha)
            text.set_verticalalignment(va)
    return drawn


def _panel_items(panel, key):
    items = panel.get(key, ())
    if isinstance(items, dict):
        items = [items]
    for item in items:
        if not isinstance(item, dict):
            raise TypeError(
                f"panel[{key!r}] must hold dicts of keyword arguments, got {type(item).__name__}"
            )
    return items


def frame_panels(panels, lim=1.3, elev=22.0, azim=-55.0):
    r"""Side-by-side 3D panels of frames, vectors, boxes and rotation axes.

    Made for the comparisons of chapter 04: rotating about a fixed axis versus a body axis
    (:math:`R\,R_{ab}` versus :math:`R_{ab}R`), :math:`R_x(\alpha)R_z(\beta)` versus
    :math:`R_z(\beta)R_x(\alpha)`, a chain of frames, the active and passive readings of
    :math:`R_{ab}` and the frames of a pan-tilt camera. Every frame is drawn by
    :func:`draw_frame`, so its arrows end at :math:`o + s\,R e_i`.

    Parameters
    ----------
    panels : sequence of dict
        One dict per panel, with the keys

        * ``"title"`` (str, required);
        * ``"frames"``: dicts of keyword arguments of :func:`draw_frame` (``R``, ``label``,
          ``origin``, ``style``, ``scale``), plus ``"name": False`` to leave out the frame's
          name at its origin (the axis labels still carry it as subscript) and
          ``"labels": "beside"`` to write the axis labels to the side of the arrows' tips
          instead of beyond them (for a short frame whose axes another frame shares);
        * ``"vectors"``: dicts of keyword arguments of :func:`draw_vector` (``v``, ``origin``,
          ``label``, ``color``, ``style``);
        * ``"boxes"``: dicts of keyword arguments of :func:`draw_box`;
        * ``"axis"``: a dict ``{"direction": (3,), "label": str, "origin": (3,)}``, a dashed
          line along a rotation axis.

    lim : float or (float, float), default 1.3
        Limits of every panel (see :func:`axes3d`).
    elev, azim : float
        Viewing angles in degrees.

    Returns
    -------
    fig : matplotlib.figure.Figure
    axes : list of Axes
        One 3D axes per panel, left to right.
    drawn : list of list of Drawn
        What was drawn in each panel, in the order frames, vectors, boxes, axis.

    Raises
    ------
    TypeError
        If a panel is not a dict, has no string title or holds items that are not dicts, or an
        item has keyword arguments its primitive does not take.
    ValueError
        If a panel has an unknown key, or an item fails the checks of its primitive (for
        example a box orientation that is not a rotation).

    Examples
    --------
    >>> import numpy as np, matplotlib.pyplot as plt
    >>> from course_lib import so3
    >>> fig, axes, drawn = frame_panels([
    ...     {"title": "before", "frames": [{"label": "A"}]},
    ...     {"title": "after", "frames": [{"R": so3.rot_z(np.pi / 2), "label": "B"}]}])
    >>> [a.get_title() for a in axes], np.allclose(drawn[1][0].points[0], [0, 1, 0])
    (['before', 'after'], True)
    >>> plt.close(fig)
    """
    if isinstance(panels, dict):
        panels = [panels]
    panels = list(panels)
    for i, panel in enumerate(panels):
        if not isinstance(panel, dict):
            raise TypeError(f"panels[{i}] must be a dict, got {type(panel).__name__}")
        unknown = sorted(set(panel) - set(_PANEL_KEYS))
        if unknown:
            raise ValueError(
                f"panels[{i}] has unknown keys {unknown}; allowed are {list(_PANEL_KEYS)}"
            )
        if "title" not in panel:
            raise TypeError(f"panels[{i}] needs a 'title' (str)")
    fig, axes = axes_row([p["title"] for p in panels], lim=lim, elev=elev, azim=azim)
    drawn = []
    for ax, panel in zip(axes, panels):
        here = [_frame(ax, **kw) for kw in _panel_items(panel, "frames")]
        here += [draw_vector(ax, **kw) for kw in _panel_items(panel, "vectors")]
        here += [draw_box(ax, **kw) for kw in _panel_items(panel, "boxes")]
        if panel.get("axis") is not None:
            here.append(_axis_line(ax, **_panel_items(panel, "axis")[0]))
        drawn.append(here)
    return fig, axes, drawn


def plot_error_curves(
    x, curves, title, xlabel, ylabel="error (log scale)", floor=1e-17, show_tol=True, reverse_x=True
):
    r"""Log-log plot of errors against a small parameter, e.g. :math:`\pi - \theta`.

    Drawn with :func:`plot_convergence` on a logarithmic x axis. Errors below ``floor``
    (exact zeros included, which a log axis cannot show) are drawn at ``floor``, so a method
    that is exact still shows as a line at the bottom of the plot.

    Parameters
    ----------
    x : array_like, shape (k,)
        Positive values of the parameter (the x values).
    curves : dict of str -> array_like, shape (k,)
        One labelled error curve per entry (errors >= 0).
    title, xlabel, ylabel : str
        Title and axis labels.
    floor : float, default 1e-17
        Smallest error drawn (> 0).
    show_tol : bool, default True
        Draw the horizontal line ``y = TOL``.
    reverse_x : bool, default True
        Let x decrease to the right, so that "approaching the limit" reads left to right.

    Returns
    -------
    fig : matplotlib.figure.Figure
    ax : matplotlib.axes.Axes

    Raises
    ------
    ValueError
        If an x value is not positive, shapes differ, an error is negative or non-finite, or
        ``floor`` is not positive.
    TypeError
        If ``curves`` is not a dict.

    Examples
    --------
    >>> import numpy as np, matplotlib.pyplot as plt
    >>> gaps = np.logspace(-1, -8, 8)
    >>> fig, ax = plot_error_curves(gaps, {"1e-16/gap": 1e-16 / gaps, "exact": 0 * gaps},
    ...                             "Errors", "gap")
    >>> ax.get_xscale(), bool(ax.xaxis_inverted()), float(ax.get_lines()[1].get_ydata().min())
    ('log', True, 1e-17)
    >>> plt.close(fig)
    """
    xs = _array(x, "x")
    if xs.ndim != 1 or not (xs > 0).all():
        raise ValueError(f"x must be a 1-D array of positive values (log axis), got {x!r}")
    if not isinstance(curves, dict):
        raise TypeError(f"curves must be a dict of label -> errors, got {type(curves).__name__}")
    low = _scalar(floor, "floor", positive=True)
    clipped = {}
    for name, err in curves.items():
        y = _array(err, f"curves[{name!r}]")
        if (y < 0).any():
            raise ValueError(f"curves[{name!r}] must be >= 0 (errors), got min {y.min():.3g}")
        clipped[name] = np.maximum(y, low)
    fig, ax = plot_convergence(
        xs, clipped, title=title, show_tol=show_tol, xlabel=xlabel, ylabel=ylabel
    )
    ax.set_xscale("log")
    if reverse_x:
        ax.invert_xaxis()
    return fig, ax


def plot_geodesic(
    R0,
    R1,
    steps=4,
    samples=61,
    title="Interpolating along the geodesic",
    lim=1.2,
    elev=22.0,
    azim=-50.0,
):
    r"""Frames along the geodesic from ``R0`` to ``R1`` and the paths of their axis tips.

    The geodesic is

    .. math:: R(t) = R_0\, e^{t \log(R_0^T R_1)}, \qquad t \in [0, 1],

    a rotation about one fixed axis at constant angular speed. The frames at ``steps`` + 1
    equally spaced times are drawn (the two ends labelled :math:`0` and :math:`1`, the ones
    between thin and dotted) and the tip of each axis traces an arc of a circle.

    Parameters
    ----------
    R0, R1 : array_like, shape (3, 3)
        Rotations at t = 0 and t = 1.
    steps : int, default 4
        Number of intervals between the drawn frames (>= 1).
    samples : int, default 61
        Number of times at which the tip paths are sampled (>= 2).
    title : str
        Title of the axes.
    lim, elev, azim : float
        Limits and viewing angles (see :func:`axes3d`).

    Returns
    -------
    fig : matplotlib.figure.Figure
    ax : mpl_toolkits.mplot3d.axes3d.Axes3D
    path : ndarray, shape (samples, 3, 3)
        :math:`R(t)` at the sampled times ``np.linspace(0, 1, samples)``.

    Raises
    ------
    ValueError
        If ``R0`` or ``R1`` is not a rotation, or ``steps``/``samples`` is too small.

    Examples
    --------
    >>> import numpy as np, matplotlib.pyplot as plt
    >>> from course_lib import so3
    >>> fig, ax, path = plot_geodesic(np.eye(3), so3.rot_z(np.pi / 2), samples=3)
    >>> np.allclose(path[1], so3.rot_z(np.pi / 4)), np.allclose(path[-1], so3.rot_z(np.pi / 2))
    (True, True)
    >>> plt.close(fig)
    """
    R0 = so3.check_rotation(_matrix(R0, "R0", 3), name="R0")
    R1 = so3.check_rotation(_matrix(R1, "R1", 3), name="R1")
    steps = as_count(steps, "steps", minimum=1)
    samples = as_count(samples, "samples", minimum=2)
    r = so3.log(R0.T @ R1)
    ts = np.linspace(0.0, 1.0, samples)
    path = R0 @ so3.exp(ts[:, None] * r)
    fig, ax = axes3d(title, lim=lim, elev=elev, azim=azim)
    for i, color in enumerate(FRAME_COLORS):
        draw_curve(ax, path[:, :, i], color=color, style="solid", linewidth=1.0)
    for t in np.linspace(0.0, 1.0, steps + 1)[1:-1]:
        Rt = R0 @ so3.exp(t * r)
        for i, color in enumerate(FRAME_COLORS):
            draw_vector(ax, Rt[:, i], color=color, style="dotted", linewidth=1.0)
    _frame(ax, R=R0, label="0", style="dashed", name=False)
    _frame(ax, R=R1, label="1", name=False)
    return fig, ax, path


def plot_rodrigues_circle(
    omega, q, theta, title="Rodrigues' formula, seen in space", lim=1.2, elev=30.0, azim=-40.0
):
    r"""The geometry of Rodrigues' formula: a point turning on a circle about the axis.

    With a unit axis :math:`\omega`, the point :math:`q` splits into a part along the axis and a
    part across it, :math:`q_\parallel = (\omega\cdot q)\,\omega` and
    :math:`q_\perp = q - q_\parallel`, and

    .. math:: e^{\hat\omega\theta} q = q_\parallel + \cos\theta\, q_\perp
              + \sin\theta\, \omega\times q,

    a point of the circle of radius :math:`\|q_\perp\|` about the axis, centred at
    :math:`q_\parallel`. The figure draws the axis, :math:`q`, :math:`q_\parallel`, the circle
    (dotted), :math:`q_\perp` and :math:`\omega\times q` from the centre, the two terms
    :math:`\cos\theta\,q_\perp` and :math:`\sin\theta\,\omega\times q` tip to tail (dashed, named
    in a legend) and the rotated point. The labels of the arrows that end on the circle sit off
    the circle and the arc: :math:`q_\perp` and :math:`\omega\times q` at their middles, the
    rotated point outside the circle.

    Parameters
    ----------
    omega : array_like, shape (3,)
        Unit axis.
    q : array_like, shape (3,)
        The point; it must not lie on the axis.
    theta : float
        Angle in radians.
    title : str
        Title of the axes.
    lim, elev, azim : float
        Limits and viewing angles (see :func:`axes3d`).

    Returns
    -------
    fig : matplotlib.figure.Figure
    ax : mpl_toolkits.mplot3d.axes3d.Axes3D
    parts : dict of str -> ndarray, shape (3,)
        ``"q_par"``, ``"q_perp"``, ``"w_x_q"`` (:math:`\omega\times q`) and ``"Rq"``
        (:math:`e^{\hat\omega\theta}q`, from :func:`course_lib.so3.exp`).

    Raises
    ------
    ValueError
        If ``omega`` is not a unit vector, ``q`` lies on the axis, or an input has the wrong
        shape or non-finite entries.

    Examples
    --------
    >>> import numpy as np, matplotlib.pyplot as plt
    >>> fig, ax, parts = plot_rodrigues_circle([0, 0, 1], [1, 0, 0.5], np.pi / 2)
    >>> np.round(parts["Rq"], 12), parts["q_par"]
    (array([0. , 1. , 0.5]), array([0. , 0. , 0.5]))
    >>> plt.close(fig)
    """
    w = _vector(omega, "omega", 3)
    q = _vector(q, "q", 3)
    th = _scalar(theta, "theta")
    Rq = so3.exp(w, th) @ q  # checks that omega is a unit vector
    q_par = (w @ q) * w
    q_perp = q - q_par
    if np.linalg.norm(q_perp) <= TOL:
        raise ValueError(
            f"q lies on the axis (‖q_perp‖ = {fmt_residual(np.linalg.norm(q_perp), TOL)} ≤ "
            f"{tol_label(TOL)}): it does not move, there is no circle to draw"
        )
    w_x_q = np.cross(w, q)
    fig, ax = axes3d(title, lim=lim, elev=elev, azim=azim)
    _axis_line(ax, w, label=r"$\omega$")
    draw_arc(ax, w, q_perp, 2 * np.pi, center=q_par, style="dotted", color="0.35", arrow=False)
    draw_arc(ax, w, q_perp, th, center=q_par, color="tab:purple", label=r"$\theta$")
    draw_vector(ax, q, label="$q$")
    draw_point(ax, q_par)
    right, up = _screen_basis(ax, 3)  # label q_par below left, clear of the arrows above it
    pad = _offset(ax)
    _text(ax, q_par - 0.5 * pad * (right + up), r"$q_\parallel$", ha="right", va="top")
    # The other labels sit in the plane of the circle, on the side of their arrow that the other
    # arrows leave free (u along q_perp, v along w x q: the turn goes from u towards v). q_perp
    # and w x q end on the circle, where q and the arc are: they are labelled at their middles,
    # the rotated point just outside the circle. The two dashed terms are named in a legend.
    u, v = _unit(q_perp), _unit(w_x_q)
    sv = 1.0 if np.sin(th) >= 0 else -1.0
    draw_vector(ax, q_perp, origin=q_par, color="tab:blue")
    _text(ax, q_par + q_perp / 2 - sv * pad * v, r"$q_\perp$", color="tab:blue")
    draw_vector(ax, w_x_q, origin=q_par, color="tab:green")
    _text(ax, q_par + w_x_q / 2 + 2.2 * pad * u, r"$\omega\times q$", color="tab:green")
    cos_part = np.cos(th) * q_perp
    draw_vector(ax, cos_part, origin=q_par, color="tab:blue", style="dashed")
    draw_vector(ax, np.sin(th) * w_x_q, origin=q_par + cos_part, color="tab:green", style="dashed")
    draw_vector(ax, Rq, color="tab:red")
    out = 2.0 * _unit(Rq - q_par) + up  # outward from the circle, and up on the screen
    _text(ax, Rq + pad * out, r"$e^{\hat\omega\theta}q$", color="tab:red", va="bottom")
    dashed = [
        Line2D([], [], color=c, linestyle="--", linewidth=1.8) for c in ("tab:blue", "tab:green")
    ]
    ax.legend(
        dashed,
        [r"$\cos\theta\,q_\perp$", r"$\sin\theta\,\omega\times q$"],
        loc="upper left",
        fontsize=FONT_SIZE - 1,
        frameon=False,
        handlelength=2.5,
    )
    return fig, ax, {"q_par": q_par, "q_perp": q_perp, "w_x_q": w_x_q, "Rq": Rq}
