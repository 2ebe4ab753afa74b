r"""The explorer of chapter 05: the gimbal of yaw, pitch and roll, and how it locks.

Roll-pitch-yaw is :math:`R = R_z(\psi)R_y(\theta)R_x(\phi)`: yaw :math:`\psi` about the world's
:math:`z`, then pitch :math:`\theta` about the :math:`y` axis that yaw left, then roll
:math:`\phi` about the :math:`x` axis that pitch left. In world coordinates the three turns are
about

.. math:: a_\psi = e_3, \qquad a_\theta = R_z(\psi)\,e_2, \qquad
          a_\phi = R_z(\psi)R_y(\theta)\,e_1 ,

and the body's angular velocity is :math:`\omega_b = E\,(\dot\psi, \dot\theta, \dot\phi)^T`
with :math:`E = [\,R_x(\phi)^TR_y(\theta)^Te_3 \;\; R_x(\phi)^Te_2 \;\; e_1\,]`,
:math:`\det E = -\cos\theta`. At pitch :math:`\pm 90°` the roll axis lies on the yaw axis,
:math:`\det E = 0`: gimbal lock. The sliders are in degrees, as the chapter's angles are.
"""

import numpy as np

from .. import euler, plotting, so3
from .._arrays import as_count
from .widgets import Explorer, SliderSpec, _scalar_angle, _view_angle

__all__ = [
    "YAW_RANGE",
    "PITCH_RANGE",
    "ROLL_RANGE",
    "turn_axes",
    "rates_matrix",
    "gimbal_readout",
    "draw_gimbal",
    "gimbal_explorer",
]

#: Slider ranges, in degrees: yaw, pitch (up to the locks at ±90°) and roll.
YAW_RANGE = (-180.0, 180.0)
PITCH_RANGE = (-90.0, 90.0)
ROLL_RANGE = (-180.0, 180.0)

_TURNS = (("yaw", "#0072B2", 1.25), ("pitch", "#009E73", 1.05), ("roll", "#D55E00", 0.85))
#: The gimbal's first camera, in degrees: the pitch axis to the side, not behind the body.
GIMBAL_ELEV, GIMBAL_AZIM = 20.0, 45.0
_LOCKED = 1e-9  # |cos θ| below this: the pitch is ±90° (the slider steps by whole degrees)


def _angles(yaw, pitch, roll):
    """The three angles in degrees, checked, and in radians."""
    deg = [_scalar_angle(a, n) for a, n in zip((yaw, pitch, roll), ("yaw", "pitch", "roll"))]
    return deg, np.radians(deg)


def turn_axes(yaw, pitch):
    r"""The axes of the yaw, pitch and roll turns, in world coordinates (rows).

    .. math:: a_\psi = e_3, \qquad a_\theta = R_z(\psi)\,e_2, \qquad
              a_\phi = R_z(\psi)R_y(\theta)\,e_1

    Parameters
    ----------
    yaw, pitch : float
        In degrees (the roll does not move these axes).

    Returns
    -------
    numpy.ndarray, shape (3, 3)
        Rows: the yaw, pitch and roll axes.

    Examples
    --------
    >>> np.round(turn_axes(30, 90), 12)[2]  # at pitch 90° the roll axis points down
    array([ 0.,  0., -1.])
    """
    (_, _, _), (psi, theta, _) = _angles(yaw, pitch, 0.0)
    R_yaw = so3.rot_z(psi)
    return np.stack([np.array([0.0, 0.0, 1.0]), R_yaw[:, 1], R_yaw @ so3.rot_y(theta)[:, 0]])


def rates_matrix(pitch, roll):
    r"""The matrix :math:`E` of roll-pitch-yaw: :math:`\omega_b = E\,(\dot\psi, \dot\theta,
    \dot\phi)^T`, the body's angular velocity from the angle rates.

    .. math:: E = \begin{bmatrix} R_x(\phi)^TR_y(\theta)^Te_3 & R_x(\phi)^Te_2 & e_1
              \end{bmatrix}, \qquad \det E = -\cos\theta

    Parameters
    ----------
    pitch, roll : float
        In degrees (the yaw does not enter :math:`E`).

    Returns
    -------
    numpy.ndarray, shape (3, 3)
        Columns: what a unit rate of yaw, of pitch and of roll gives :math:`\omega_b`.

    Examples
    --------
    >>> round(float(np.linalg.det(rates_matrix(60, 20))), 12)  # -cos 60°
    -0.5
    """
    (_, _, _), (_, theta, phi) = _angles(0.0, pitch, roll)
    Rx_T, Ry_T = so3.rot_x(phi).T, so3.rot_y(theta).T
    return np.stack([Rx_T @ Ry_T[:, 2], Rx_T[:, 1], np.array([1.0, 0.0, 0.0])], axis=1)


def gimbal_readout(yaw, pitch, roll, decimals=2):
    r"""LaTeX of :math:`E` with numbers, its determinant, and whether the gimbal is locked.

    Parameters
    ----------
    yaw, pitch, roll : float
        In degrees.
    decimals : int, default 2
        Number of decimals shown (0 to 6).

    Returns
    -------
    str
        A LaTeX display, ready for ``IPython.display.Math``.

    Examples
    --------
    >>> tex = gimbal_readout(10, 90, 0)
    >>> r"\det E = -\cos\theta = 0.00" in tex, "gimbal lock" in tex
    (True, True)
    """
    decimals = as_count(decimals, "decimals")
    if decimals > 6:
        raise ValueError(f"decimals must be between 0 and 6, got {decimals}")
    (_, th, _), (_, theta, _) = _angles(yaw, pitch, roll)
    E = rates_matrix(pitch, roll)
    rows = [" & ".join(f"{round(x, decimals) + 0.0:.{decimals}f}" for x in row) for row in E]
    det = round(-np.cos(theta), decimals) + 0.0
    verdict = (
        r"\text{gimbal lock: yaw and roll turn about one line}"
        if abs(np.cos(theta)) < _LOCKED
        else r"\text{every }\omega_b\text{ has rates}"
    )
    return (
        rf"\theta = {th:g}°:\quad E = \begin{{bmatrix}} " + r" \\ ".join(rows) + r" \end{bmatrix},"
        rf"\quad \det E = -\cos\theta = {det:.{decimals}f}\quad" + verdict
    )


def draw_gimbal(ax, yaw, pitch, roll, *, elev=GIMBAL_ELEV, azim=GIMBAL_AZIM):
    r"""Draw the body of roll-pitch-yaw (a flat box), the three turn axes and their circles.

    Each axis is an arrow from the origin with a dashed circle about it (the circle its turn
    moves points along, eq. 125): blue for yaw (radius 1.25), green for pitch (1.05), red for
    roll (0.85). At pitch :math:`\pm 90°` the red circle lies in the plane of the blue one.

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.axes3d.Axes3D
    yaw, pitch, roll : float
        In degrees.
    elev, azim : float, keyword-only, default GIMBAL_ELEV = 20, GIMBAL_AZIM = 45
        The camera, in degrees.

    Returns
    -------
    course_lib.plotting.Drawn
        ``points``: the three turn axes (rows: yaw, pitch, roll); ``R``; ``E``
        (:func:`rates_matrix`); ``det``: :math:`\det E`; ``circles``: the points of the
        three circles, each of shape (90, 3).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plotting.axes3d("Gimbal")
    >>> drawn = draw_gimbal(ax, 30, 90, 10)
    >>> round(float(drawn.det), 12), float(drawn.points[0] @ drawn.points[2])  # roll = -yaw
    (-0.0, -1.0)
    >>> plt.close(fig)
    """
    plotting._require_3d(ax, "draw_gimbal")
    deg, rad = _angles(yaw, pitch, roll)
    ax.view_init(elev=_view_angle(elev, "elev"), azim=_view_angle(azim, "azim"))
    axes = turn_axes(deg[0], deg[1])
    R = euler.to_matrix(rad, "ZYX")
    E = rates_matrix(deg[1], deg[2])
    # The body: a flat box, long along its roll axis (body x), its nose marked.
    artists = list(plotting.draw_box(ax, R, size=(1.1, 0.6, 0.12), color="0.5", alpha=0.3))
    circles = []
    for a, (name, color, radius) in zip(axes, _TURNS):
        start = np.cross(a, [1.0, 0, 0] if abs(a[0]) < 0.9 else [0, 1.0, 0])
        start *= radius / np.linalg.norm(start)
        arc = plotting.draw_arc(
            ax, a, start, 2 * np.pi, n=90, color=color, style="dashed", arrow=False
        )
        artists.extend(arc)
        circles.append(arc.points)
        artists.extend(plotting.draw_vector(ax, radius * a, label=name, color=color))
    return plotting.Drawn("gimbal", artists, axes, R=R, E=E, det=np.linalg.det(E), circles=circles)


def _title(yaw, pitch, roll):
    return (
        r"Roll-pitch-yaw: $R = R_z(\psi)R_y(\theta)R_x(\phi)$"
        + "\n"
        + rf"$\psi$ = {yaw:.0f}°, $\theta$ = {pitch:.0f}°, $\phi$ = {roll:.0f}°"
    )


def _alt(yaw, pitch, roll):
    """What the gimbal explorer shows at these slider values, in words (its alt text)."""
    locked = abs(abs(pitch) - 90.0) < 0.5
    deg = [f"{a:.0f}".replace("-", "−") for a in (yaw, pitch, roll)]
    return (
        f"Frame B turned by yaw ψ = {deg[0]}°, pitch θ = {deg[1]}°, roll φ = {deg[2]}° "
        "(R = Rz(ψ) Ry(θ) Rx(φ)), with the yaw, pitch and roll axes and the circles each turn "
        "moves along; "
        + (
            "at this pitch the roll axis lies on the yaw axis (gimbal lock, det E = 0)."
            if locked
            else "the roll axis is apart from the yaw axis (no gimbal lock)."
        )
    )


def gimbal_explorer(yaw=30.0, pitch=60.0, roll=20.0, *, elev=GIMBAL_ELEV, azim=GIMBAL_AZIM):
    r"""Sliders for yaw, pitch and roll (degrees), redrawing the gimbal of :func:`draw_gimbal`.

    Move pitch to :math:`\pm 90°`: the roll axis swings onto the yaw axis, the red circle lies
    in the plane of the blue one, and the readout below shows :math:`\det E = -\cos\theta = 0`.

    Parameters
    ----------
    yaw : float, default 30
        In ``YAW_RANGE`` = [−180, 180] degrees.
    pitch : float, default 60
        In ``PITCH_RANGE`` = [−90, 90] degrees.
    roll : float, default 20
        In ``ROLL_RANGE`` = [−180, 180] degrees.
    elev, azim : float, keyword-only, default GIMBAL_ELEV = 20, GIMBAL_AZIM = 45
        Initial camera, in degrees.

    Returns
    -------
    Explorer
        ``.result`` holds the three turn axes (rows: yaw, pitch, roll).

    Raises
    ------
    ValueError
        If an angle is not a finite number inside its slider's range.

    Examples
    --------
    >>> w = gimbal_explorer(pitch=90)
    >>> list(w.sliders)
    ['yaw ψ', 'pitch θ', 'roll φ']
    >>> float(np.round(w.result[0] @ w.result[2], 12))  # the roll axis on the yaw axis
    -1.0
    """
    names = ("yaw ψ", "pitch θ", "roll φ")
    ranges = (YAW_RANGE, PITCH_RANGE, ROLL_RANGE)
    values = (yaw, pitch, roll)
    sliders = [
        SliderSpec(n, v, r, step=1.0, unit="degrees", readout_format=".0f")
        for n, v, r in zip(names, values, ranges)
    ]
    return Explorer(
        draw_gimbal,
        lambda drawn: drawn.points,
        _title,
        "Gimbal explorer: sliders for yaw ψ, pitch θ and roll φ (degrees) redraw frame B and "
        "the axes of the three turns with the circles they turn along; at pitch ±90° the roll "
        "axis lies on the yaw axis and det E = −cos θ = 0; drag the 3D view to turn it.",
        sliders,
        (elev, azim),
        lim=1.3,
        readout=gimbal_readout,
        alt=_alt,
    )
