r"""Figures of chapter 03 (exponential coordinates): the pendulum, a particle's orbit, a
spinning body and Rodrigues' circle.

:func:`draw_pendulum` draws the planar pendulum of the notes' angular velocity, eq. (117)-(118);
:func:`plot_orbit` a particle orbiting an axis, eq. (119); :func:`plot_spinning_body` a body
spinning about an axis in a fixed frame, eq. (121); :func:`plot_rodrigues_circle` the geometry
of Rodrigues' formula (a point turning on a circle about the axis).
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
    draw_frame,
    draw_point,
    draw_segment,
    draw_vector,
)
from .shapes import draw_arc, draw_box

__all__ = ["draw_pendulum", "plot_orbit", "plot_rodrigues_circle", "plot_spinning_body"]


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


def plot_orbit(omega, height=0.6, rho=0.9, phase=-0.6, lim=1.2, elev=35.0, azim=-60.0):
    r"""A particle :math:`p` orbiting the origin about the axis :math:`\omega`, eq. (119).

    The point sits at ``height`` along the axis and at the distance ``rho`` from it, ``phase``
    radians round the axis from the screen's right. The figure draws the axis (grey line, blue
    arrow :math:`\omega`), the position vector :math:`r` of :math:`p`, the dotted circle that
    :math:`p` travels on, its radius :math:`\rho` (purple) and the velocity
    :math:`v = \omega\times r` (green), tangent to the circle.

    Parameters
    ----------
    omega : array_like, shape (3,)
        The angular velocity (nonzero); its length is the rate of turning.
    height, rho : float
        The point's coordinate along the axis, and its distance from the axis (> 0).
    phase : float
        Where the point sits round the axis, in radians from the screen's right.
    lim, elev, azim : float
        Limits and viewing angles (see :func:`axes3d`).

    Returns
    -------
    fig : matplotlib.figure.Figure
    ax : mpl_toolkits.mplot3d.axes3d.Axes3D
    parts : dict
        ``"p"`` and ``"centre"`` (the centre of the circle, on the axis), ``"v"``
        (:math:`\omega\times p`), arrays of shape (3,); ``"rho"``, the radius as drawn.

    Raises
    ------
    ValueError
        If ``omega`` is zero, ``rho <= 0`` or an input is not finite or has the wrong shape.

    Examples
    --------
    >>> import numpy as np, matplotlib.pyplot as plt
    >>> fig, ax, parts = plot_orbit([0, 0, 2.0], height=0.5, rho=0.8)
    >>> round(float(np.linalg.norm(parts["v"])), 12), round(parts["rho"], 12)  # ‖v‖ = ‖ω‖ρ
    (1.6, 0.8)
    >>> plt.close(fig)
    """
    w_vec = as_vector(omega, "omega", 3)
    w_dir = _unit(w_vec)
    height, phase = as_scalar(height, "height"), as_scalar(phase, "phase")
    rho = as_positive(rho, "rho")
    right = np.array([-np.sin(np.radians(azim)), np.cos(np.radians(azim)), 0.0])
    e1 = _unit(right - (right @ w_dir) * w_dir)  # across the axis, towards the screen's right
    e2 = np.cross(w_dir, e1)
    p0 = height * w_dir + rho * (np.cos(phase) * e1 + np.sin(phase) * e2)
    centre = (p0 @ w_dir) * w_dir
    fig, ax = axes3d(
        r"A particle $p$ orbiting the origin: $v = \omega \times r$ (119)",
        lim=lim,
        elev=elev,
        azim=azim,
    )
    orbit = draw_arc(ax, w_vec, p0, 2 * np.pi, style="dotted", arrow=False)
    draw_segment(ax, -1.1 * w_dir, 1.3 * w_dir, color="0.5")
    draw_vector(ax, w_vec, label=r"$\omega$", color="tab:blue")
    draw_vector(ax, p0)
    draw_point(ax, p0, label="$p$")
    ax.text(*(0.5 * p0 + [0.1, 0.0, -0.2]), "$r$", fontsize=13)
    draw_segment(ax, centre, p0, style="solid", color="tab:purple", linewidth=2.5)
    ax.text(*(0.5 * (centre + p0) + [0.0, 0.0, 0.1]), r"$\rho$", color="tab:purple", fontsize=15)
    v = np.cross(w_vec, p0)
    draw_vector(ax, v, origin=p0, label="$v$", color="tab:green")
    return fig, ax, {"p": p0, "centre": centre, "v": v, "rho": float(orbit.radius)}


def plot_spinning_body(R, lim=1.2, elev=25.0, azim=-60.0):
    r"""A body :math:`B` (a plate) spinning about a unit :math:`\omega` in the fixed frame
    :math:`A`, eq. (121).

    The plate has the orientation ``R``; its normal :math:`\omega = Re_3` is the axis, and its
    centre sits on the axis at distance 1 from the origin. The figure draws the frame
    :math:`A` (dotted), the axis :math:`\omega` (blue), the plate (orange) with a marked corner
    :math:`q`, the dotted circle that :math:`q` travels on and the velocity
    :math:`\dot q = \omega\times q` (green), tangent to it.

    Parameters
    ----------
    R : array_like, shape (3, 3)
        The plate's orientation (a rotation matrix).
    lim, elev, azim : float
        Limits and viewing angles (see :func:`axes3d`).

    Returns
    -------
    fig : matplotlib.figure.Figure
    ax : mpl_toolkits.mplot3d.axes3d.Axes3D
    parts : dict of str -> ndarray, shape (3,)
        ``"omega"`` (the unit axis), ``"q"`` (the marked corner) and ``"q_dot"``
        (:math:`\omega\times q`).

    Raises
    ------
    ValueError
        If ``R`` is not a rotation matrix.

    Examples
    --------
    >>> import numpy as np, matplotlib.pyplot as plt
    >>> fig, ax, parts = plot_spinning_body(np.eye(3))
    >>> parts["omega"], parts["q"], parts["q_dot"]
    (array([0., 0., 1.]), array([-0.55, -0.55,  1.  ]), array([ 0.55, -0.55,  0.  ]))
    >>> plt.close(fig)
    """
    R = np.asarray(R, dtype=float)
    if R.shape != (3, 3) or not so3.is_rotation(R):
        raise ValueError("R must be a 3x3 rotation matrix (RᵀR = I, det R = 1)")
    w_B = R[:, 2]
    fig, ax = axes3d(
        r"Body $B$ spinning about $\omega$ in the fixed frame $A$ (121)",
        lim=lim,
        elev=elev,
        azim=azim,
    )
    frame_A = draw_frame(ax, label="A", scale=0.55, style="dotted")
    for frame_label in frame_A.artists[1::2] + frame_A.artists[-1:]:  # x_A, y_A, z_A and A
        frame_label.set_fontsize(13)
    draw_vector(ax, 1.4 * w_B, label=r"$\omega$", color="tab:blue")
    plate = draw_box(
        ax, R, center=w_B, size=(1.1, 1.1, 0.05), marks=[-0.55, -0.55, 0.0], color="tab:orange"
    )
    q_B = plate.points[0]
    ax.text(*(q_B + [-0.05, -0.1, 0.08]), "$q$", fontsize=13, ha="right", va="center")
    draw_arc(ax, w_B, q_B - w_B, 2 * np.pi, center=w_B, style="dotted", color="0.3", arrow=False)
    ax.text(*(w_B + [-0.75, -0.2, 0.05]), "$B$", fontsize=13)
    q_dot = np.cross(w_B, q_B)
    draw_vector(ax, q_dot, origin=q_B, label=r"$\dot q = \omega \times q$", color="tab:green")
    return fig, ax, {"omega": w_B, "q": q_B, "q_dot": q_dot}
