r"""Figures of chapter 03 (exponential coordinates): the pendulum and Rodrigues' circle.

:func:`draw_pendulum` draws the planar pendulum of the notes' angular velocity, eq. (117)-(118);
:func:`plot_rodrigues_circle` the geometry of Rodrigues' formula (a point turning on a circle
about the axis).
"""

from __future__ import annotations

import numpy as np
from matplotlib.lines import Line2D

from .. import so3
from .._arrays import as_positive, as_scalar, as_vector
from ..tolerance import TOL, fmt_residual, tol_label
from .axes import FONT_SIZE, _dim, axes3d
from .primitives import (
    Drawn,
    _axis_line,
    _offset,
    _origin,
    _screen_basis,
    _text,
    _unit,
    draw_point,
    draw_segment,
    draw_vector,
)
from .shapes import draw_arc

__all__ = ["draw_pendulum", "plot_rodrigues_circle"]


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
    >>> from course_lib.plotting import axes2d
    >>> fig, ax = axes2d("Pendulum")
    >>> pend = draw_pendulum(ax, np.pi / 6, r=1.2, omega=0.5)
    >>> round(float(np.linalg.norm(pend.velocity)), 12)
    0.6
    >>> plt.close(fig)
    """
    if _dim(ax) != 2:
        raise TypeError("draw_pendulum needs a 2D axes (e.g. from axes2d); got a 3D axes")
    th = as_scalar(theta, "theta")
    r = as_positive(r, "r")
    om = as_scalar(omega, "omega")
    vs = as_positive(velocity_scale, "velocity_scale")
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
        artists.extend(draw_vector(ax, vs * v, origin=bob, label="$v$", color="#009E73"))
    return Drawn("pendulum", artists, np.stack([c, bob]), velocity=v)


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
    w = as_vector(omega, "omega", 3)
    q = as_vector(q, "q", 3)
    th = as_scalar(theta, "theta")
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
    draw_vector(ax, q_perp, origin=q_par, color="#0072B2")
    _text(ax, q_par + q_perp / 2 - sv * pad * v, r"$q_\perp$", color="#0072B2")
    draw_vector(ax, w_x_q, origin=q_par, color="#009E73")
    _text(ax, q_par + w_x_q / 2 + 2.2 * pad * u, r"$\omega\times q$", color="#009E73")
    cos_part = np.cos(th) * q_perp
    draw_vector(ax, cos_part, origin=q_par, color="#0072B2", style="dashed")
    draw_vector(ax, np.sin(th) * w_x_q, origin=q_par + cos_part, color="#009E73", style="dashed")
    draw_vector(ax, Rq, color="#D55E00")
    out = 2.0 * _unit(Rq - q_par) + up  # outward from the circle, and up on the screen
    _text(ax, Rq + pad * out, r"$e^{\hat\omega\theta}q$", color="#D55E00", va="bottom")
    dashed = [
        Line2D([], [], color=c, linestyle="--", linewidth=1.8) for c in ("#0072B2", "#009E73")
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
