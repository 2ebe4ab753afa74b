r"""Setting up the figures of course_lib.plotting: 3D and 2D axes, views, limits, fonts.

Every figure of the package is created here (or by :func:`~course_lib.plotting.plot_convergence`,
which uses the same constants): a fixed size, dpi and font, a title, labelled axes and equal, fixed
limits, so the same cell always gives the same picture. 3D figures get fixed margins; 2D figures
use matplotlib's constrained layout.
"""

from __future__ import annotations

import matplotlib.pyplot as plt

from .._arrays import as_choice, as_finite_array, as_labels, as_scalar, as_str

__all__ = ["DPI", "FONT_SIZE", "TITLE_SIZE", "axes3d", "axes2d", "axes_row"]

#: Fixed figure geometry and fonts: same cell, same PNG. They are passed explicitly to every
#: figure, axes and text, never through rcParams: a ``plt.rc_context`` around figure creation
#: would also roll back what the notebook backend sets when the first figure is made
#: (interactive mode), and later figures would not be shown.
DPI = 90
FIGSIZE = (4.8, 4.8)
PANEL_SIZE = 4.2
FONT_SIZE = 11
TITLE_SIZE = 12

# Margins (fractions of the figure) around the 3D panels of axes_row. The bottom margin leaves
# room for the x/y tick labels under the cube at every camera elevation: seen from about 30° to
# 60° above, the front corner of the cube and its tick labels reach lowest on the canvas. The
# top margin leaves room for the title, which sits above the (square) panel.
_ROW_MARGINS_3D = {"left": 0.02, "right": 0.95, "bottom": 0.1, "top": 0.92, "wspace": 0.1}

# Layout engine of the 2D figures made here: constrained layout sizes the margins to the tick
# labels, axis labels, legend and colour bar when the figure is drawn.
_LAYOUT_2D = "constrained"


# --------------------------------------------------------------------------------------------
# The kind of axes and its limits
# --------------------------------------------------------------------------------------------


def _dim(ax):
    """2 or 3: the dimension of the space an axes draws."""
    if not hasattr(ax, "figure") or not hasattr(ax, "plot"):
        raise TypeError(f"ax must be a matplotlib Axes, got {type(ax).__name__}")
    return 3 if getattr(ax, "name", "") == "3d" else 2


def _require_3d(ax, func):
    """A TypeError naming ``func`` unless ``ax`` is a 3D axes."""
    if _dim(ax) != 3:
        raise TypeError(
            f"{func} needs a 3D axes (projection='3d', e.g. from axes3d); got a 2D axes"
        )


def _limits(lim):
    """Scalar lim -> (-lim, lim); pair -> (lo, hi) with lo < hi."""
    a = as_finite_array(lim, "lim")
    if a.shape == ():
        if not a > 0:
            raise ValueError(f"lim must be > 0 (axes span [-lim, lim]), got {float(a)!r}")
        return -float(a), float(a)
    if a.shape == (2,) and a[0] < a[1]:
        return float(a[0]), float(a[1])
    raise ValueError(f"lim must be a positive number or a pair (lo, hi) with lo < hi, got {lim!r}")


# --------------------------------------------------------------------------------------------
# Figures and axes
# --------------------------------------------------------------------------------------------


def _setup3d(ax, title, lim, elev, azim, labels):
    lo, hi = _limits(lim)
    labels = as_labels(labels, 3, "labels")
    ax.set_xlim(lo, hi)
    ax.set_ylim(lo, hi)
    ax.set_zlim(lo, hi)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=as_scalar(elev, "elev"), azim=as_scalar(azim, "azim"))
    for setter, lab in zip((ax.set_xlabel, ax.set_ylabel, ax.set_zlabel), labels):
        setter(lab or "", fontsize=FONT_SIZE)
    ax.tick_params(axis="both", labelsize=FONT_SIZE - 2)
    ax.set_title(as_str(title, "title"), fontsize=TITLE_SIZE)


def _setup2d(ax, title, lim, labels):
    lo, hi = _limits(lim)
    labels = as_labels(labels, 2, "labels")
    ax.set_xlim(lo, hi)
    ax.set_ylim(lo, hi)
    ax.set_aspect("equal")
    ax.set_xlabel(labels[0] or "", fontsize=FONT_SIZE)
    ax.set_ylabel(labels[1] or "", fontsize=FONT_SIZE)
    ax.axhline(0.0, color="0.85", linewidth=0.8, zorder=0)
    ax.axvline(0.0, color="0.85", linewidth=0.8, zorder=0)
    ax.tick_params(axis="both", labelsize=FONT_SIZE - 2)
    ax.set_title(as_str(title, "title"), fontsize=TITLE_SIZE)


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
        as_str(title, "title")
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
        as_str(title, "title")
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
        as_str(t, "each title")
    as_choice(kind, "kind", ("3d", "2d"))
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
