r"""Shapes drawn by course_lib.plotting: a patch of a plane, the arc of a rotation, a rigid box.

Like :mod:`.primitives`, every ``draw_*`` here validates through :mod:`course_lib._arrays`,
judges degeneracy with the one tolerance ``TOL`` and returns a :class:`~.primitives.Drawn`.
"""

from __future__ import annotations

import numpy as np
from matplotlib.patches import Polygon
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from .. import so3
from .._arrays import as_count, as_direction, as_matrix, as_points, as_scalar, as_str, as_vector
from ..tolerance import TOL, check_tol, fmt_residual, tol_label
from .axes import _dim, _require_3d
from .primitives import (
    Drawn,
    _arrow,
    _line,
    _linestyle,
    _offset,
    _origin,
    _text,
    _unit,
    draw_frame,
    draw_point,
)

__all__ = ["draw_plane", "draw_arc", "draw_box"]


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
    >>> from course_lib.plotting import axes3d
    >>> fig, ax = axes3d("Plane of a and b")
    >>> patch = draw_plane(ax, [1, 0, 0], [0.5, 1, 0])
    >>> patch.normal.tolist()
    [0.0, 0.0, 1.0]
    >>> plt.close(fig)
    """
    d = _dim(ax)
    a = as_vector(a, "a", d)
    b = as_vector(b, "b", d)
    o = _origin(origin, d)
    tol = check_tol(tol)
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
        artists.append(_text(ax, corners.mean(axis=0), as_str(label, "label"), color="black"))
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
    >>> from course_lib.plotting import axes3d
    >>> fig, ax = axes3d("Rotation about z")
    >>> arc = draw_arc(ax, [0, 0, 1], [1, 0, 0], np.pi / 2, label=r"$\theta$")
    >>> np.allclose(arc.points[-1], [0, 1, 0])
    True
    >>> plt.close(fig)
    """
    d = _dim(ax)
    s = as_vector(start, "start", d)
    c = _origin(center, d)
    theta = as_scalar(angle, "angle")
    tol = check_tol(tol)
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
        artists.append(_text(ax, pos, as_str(label, "label"), color=color))
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
    color="#0072B2",
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
    color : colour, default "#0072B2"
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
    >>> from course_lib.plotting import axes3d
    >>> fig, ax = axes3d("The phone")
    >>> marks = [[0.2, 0.4, 0.05], [-0.2, -0.4, 0.05]]
    >>> phone = draw_box(ax, marks=marks, mark_labels=["$p_1$", "$p_2$"])
    >>> round(float(np.linalg.norm(phone.points[0] - phone.points[1])), 6)
    0.894427
    >>> plt.close(fig)
    """
    _require_3d(ax, "draw_box")
    tol = check_tol(tol)
    if R is None:
        R = np.eye(3)
    else:
        R = as_matrix(R, "R", 3)
        so3.check_rotation(R, tol=tol)
    c = _origin(center, 3)
    size = as_vector(size, "size", 3)
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
        M = as_points(marks, "marks", 3)
        world = c + M @ R.T
        artists.extend(draw_point(ax, world, label=mark_labels, color="black").artists)
    if frame is not None:
        artists.extend(
            draw_frame(
                ax, R, origin=c, label=as_str(frame, "frame"), scale=0.6 * float(size.max())
            ).artists
        )
    return Drawn("box", artists, world, corners=corners)
