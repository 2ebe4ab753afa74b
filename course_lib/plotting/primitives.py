r"""Drawing primitives on 2D or 3D axes: frames, vectors, points, segments and curves.

Each ``draw_*`` function checks its input through :mod:`course_lib._arrays`, adds artists to the
axes and returns a :class:`Drawn`: the artists and the geometry drawn, in world coordinates.
The low-level helpers here (text, arrows, lines, where a label goes beside a line) are shared
by :mod:`.shapes` and the chapters' figures.
"""

from __future__ import annotations

import numpy as np
from matplotlib.patches import FancyArrowPatch
from mpl_toolkits.mplot3d import proj3d

from .._arrays import (
    as_choice,
    as_direction,
    as_labels,
    as_matrix,
    as_points,
    as_positive,
    as_scalar,
    as_str,
    as_vector,
)
from ..tolerance import TOL, fmt_residual, tol_label
from .axes import FONT_SIZE, _dim
from .colours import readable

__all__ = [
    "FRAME_COLORS",
    "Arrow",
    "Drawn",
    "draw_frame",
    "draw_vector",
    "draw_point",
    "draw_segment",
    "draw_curve",
]

#: Colours of the x, y and z axes of every frame: red, green, blue as in the notes, in the
#: colour-blind-safe shades of Okabe & Ito (vermillion, bluish green, blue), each 3:1 or more on
#: white (WCAG 1.4.11); tests/test_a11y_colour.py checks them under protanopia and deuteranopia.
FRAME_COLORS = ("#D55E00", "#009E73", "#0072B2")

ARROW_HEAD = 12  # arrow head size in points (FancyArrowPatch mutation_scale)

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
# Input with a default, and line styles
# --------------------------------------------------------------------------------------------


def _origin(origin, d):
    """The zero vector when ``origin`` is None, else ``origin`` as one finite d-vector."""
    return np.zeros(d) if origin is None else as_vector(origin, "origin", d)


def _linestyle(style):
    """Matplotlib's line style for a style name: ``"dashed"`` -> ``"--"``."""
    return _LINESTYLES[as_choice(style, "style", tuple(_LINESTYLES))]


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
    return ax.text(*pos, s, color=readable(color), fontsize=FONT_SIZE, **kwargs)


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
    >>> from course_lib.plotting import axes3d
    >>> fig, ax = axes3d("Frame B")
    >>> frame = draw_frame(ax, R=[[-1, 0, 0], [0, 1, 0], [0, 0, -1]], label="B")
    >>> np.allclose(frame.points[0], [-1, 0, 0])
    True
    >>> plt.close(fig)
    """
    d = _dim(ax)
    R = np.eye(d) if R is None else as_matrix(R, "R", d)
    o = _origin(origin, d)
    s = as_positive(scale, "scale")
    ls = _linestyle(style)
    colors = list(colors)
    names = list(axis_names)
    if len(colors) != d or len(names) != d:
        raise ValueError(
            f"colors and axis_names must hold {d} entries each, got {len(colors)} and {len(names)}"
        )
    if label is not None:
        as_str(label, "label")
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
    >>> from course_lib.plotting import axes3d
    >>> fig, ax = axes3d("A free vector")
    >>> arrow = draw_vector(ax, [1, 1, 0], origin=[0, 0, 1], label="$v$")
    >>> np.allclose(arrow.points[1], [1, 1, 1]), len(arrow)
    (True, 2)
    >>> plt.close(fig)
    """
    d = _dim(ax)
    v = as_vector(v, "v", d)
    o = _origin(origin, d)
    ls = _linestyle(style)
    lw = as_positive(linewidth, "linewidth")
    tip = o + v
    if np.linalg.norm(v) == 0.0:
        artists = [ax.scatter(*o[:, None], color=color, s=12)]
    else:
        artists = [_arrow(ax, o, tip, color, ls, lw)]
    if label is not None:
        pos = tip + _offset(ax) * _unit(v)
        artists.append(_text(ax, pos, as_str(label, "label"), color=color))
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
    >>> from course_lib.plotting import axes3d
    >>> fig, ax = axes3d("Particles")
    >>> body = draw_point(ax, [[0, 0, 0], [1, 0, 0], [0, 1, 0]], label=["$p_1$", "$p_2$", None])
    >>> body.points.shape, len(body)
    ((3, 3), 3)
    >>> plt.close(fig)
    """
    d = _dim(ax)
    P = as_points(p, "p", d)
    labels = as_labels(label, len(P), "label")
    s = as_positive(size, "size")
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
    >>> from course_lib.plotting import axes3d
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
    p = as_vector(p, "p", d)
    q = as_vector(q, "q", d)
    ls = _linestyle(style)
    lw = as_positive(linewidth, "linewidth")
    t = as_scalar(label_at, "label_at")
    if not 0.0 <= t <= 1.0:
        raise ValueError(
            f"label_at must be a fraction of the segment in [0, 1] (0 at p, 1 at q), got {t!r}"
        )
    artists = [_line(ax, [p, q], color, ls, lw)]
    pos = None
    if label is not None:
        text = as_str(label, "label")
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
    >>> from course_lib.plotting import axes3d
    >>> fig, ax = axes3d("A trajectory")
    >>> t = np.linspace(0, 1, 50)
    >>> p = np.stack([np.cos(t), np.sin(t), t], axis=-1)
    >>> curve = draw_curve(ax, p, label="$p(t)$", arrow=True)
    >>> curve.points.shape, len(curve)
    ((50, 3), 3)
    >>> plt.close(fig)
    """
    d = _dim(ax)
    P = as_points(points, "points", d, min_count=2)
    ls = _linestyle(style)
    lw = as_positive(linewidth, "linewidth")
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
        text = as_str(label, "label")
        artists.append(_text(ax, pos, text, color=color, ha="left", va="bottom"))
    return Drawn("curve", artists, P)


# --------------------------------------------------------------------------------------------
# Helpers of the chapters' figures: a rotation axis, a frame with its labels placed
# --------------------------------------------------------------------------------------------


def _axis_line(ax, direction, label=None, origin=None, color="0.45"):
    """A dashed line through ``origin`` along ±``direction`` (length 1.2), labelled at its tip."""
    k = as_direction(direction, "direction")
    o = _origin(origin, 3)
    artists = [_line(ax, [o - 1.2 * k, o + 1.2 * k], color, "--", 1.2)]
    if label is not None:
        artists.append(_text(ax, o + (1.2 + _offset(ax)) * k, as_str(label, "label"), color=color))
    return Drawn("axis", artists, np.stack([o - 1.2 * k, o + 1.2 * k]))


def _frame(ax, name=True, labels="tip", **kwargs):
    """:func:`draw_frame`; with ``name=False`` the frame's name at its origin is left out.

    The axis labels keep the name as subscript. Two frames with a common origin would
    otherwise write their names on top of each other. With ``labels="beside"`` each axis
    label moves from beyond the arrow's tip to the side of the tip: a short frame "before" a
    motion then keeps its labels off the longer arrows of a frame that shares its axes (a turn
    about z leaves z in place).
    """
    as_choice(labels, "labels", ("tip", "beside"))
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
