r"""Figures of chapter 04 (working with rotations): frames side by side, and the geodesic.

:func:`frame_panels` compares compositions side by side (a fixed axis against a body axis, the
order of two turns, a chain of frames, the active and passive readings of :math:`R_{ab}`);
:func:`plot_geodesic` draws the frames along the geodesic between two rotations.
"""

from __future__ import annotations

import numpy as np

from .. import so3
from .._arrays import as_count, as_matrix
from .axes import axes3d, axes_row
from .primitives import FRAME_COLORS, _axis_line, _frame, draw_curve, draw_vector
from .shapes import draw_box

__all__ = ["frame_panels", "plot_geodesic"]

_PANEL_KEYS = ("title", "frames", "vectors", "boxes", "axis")


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
    R0 = so3.check_rotation(as_matrix(R0, "R0", 3), name="R0")
    R1 = so3.check_rotation(as_matrix(R1, "R1", 3), name="R1")
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
