r"""Figures of chapter 05 (orientation in practice): Euler angles, gimbal lock, quaternions.

:func:`euler_steps` draws the three turns of an intrinsic Euler sequence one after the other;
:func:`gimbal_axes` the axes of the yaw, pitch and roll turns, which line up at pitch 90°;
:func:`double_cover` the scalar part of a turn's quaternion against its matrix as the angle
grows; :func:`slerp_speed` the angle turned along slerp and along a normalised linear average;
:func:`angle_streams` angles against time (an IMU's yaw, pitch and roll).
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.lines import Line2D

from .. import euler, quaternion, so3
from .._arrays import as_finite_array, as_labels, as_str, as_unit_quaternions
from .axes import _LAYOUT_2D, DPI
from .figures_composition import frame_panels

__all__ = ["euler_steps", "gimbal_axes", "double_cover", "slerp_speed", "angle_streams"]

_TURN = {"X": so3.rot_x, "Y": so3.rot_y, "Z": so3.rot_z}
_WORD = {0: "", 1: "the new ", 2: "the newest "}
_BEFORE = "0.35"  # the frame before a turn: dark grey (contrast 7.5:1 on white)


def euler_steps(angles, seq="ZYX", elev=25.0, azim=-30.0):
    r"""Three panels: the turns of an intrinsic sequence, each about the body's current axis.

    Panel :math:`k` shows the frame :math:`R_{k-1}` before the turn (grey, dashed, thick, three
    quarters long, unlabelled) and :math:`R_k = R_{k-1}R_{s_k}(\alpha_k)` after it (coloured,
    solid, axes labelled with subscript :math:`k`), where :math:`s_k` is the k-th letter of
    ``seq``: turns about body axes multiply on the right. The two frames differ in line style,
    length and colour, and a legend under the panels names them, so colour is never the only
    cue.

    Parameters
    ----------
    angles : array_like, shape (3,)
        The three angles, in radians, in the order of ``seq``.
    seq : str
        An intrinsic sequence (upper case), e.g. ``"ZYX"``.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> fig = euler_steps([0.7, 0.5, 0.9], "ZYX")
    >>> [ax.get_title().split(" ")[0] for ax in fig.axes]
    ['1.', '2.', '3.']
    >>> plt.close(fig)
    """
    angles = as_finite_array(angles, "angles")
    if angles.shape != (3,):
        raise ValueError(f"angles must be 3 angles of shape (3,), got shape {angles.shape}")
    seq = as_str(seq, "seq")
    euler.to_matrix(angles, seq)  # validates seq
    if not seq.isupper():
        raise ValueError(f"seq must be intrinsic (upper case) to draw body turns, got {seq!r}")
    frames, panels = [np.eye(3)], []
    for k, (axis, angle) in enumerate(zip(seq, angles)):
        frames.append(frames[-1] @ _TURN[axis](angle))
        title = f"{k + 1}. {np.degrees(angle):.0f}° about {_WORD[k]}${axis.lower()}$"
        panels.append(
            {
                "title": title,
                "frames": [
                    {
                        "R": frames[k],
                        "label": str(k),
                        "style": "dashed",
                        "scale": 0.75,
                        "colors": (_BEFORE,) * 3,
                    },
                    {"R": frames[k + 1], "label": str(k + 1), "name": False},
                ],
            }
        )
    fig, _, drawn = frame_panels(panels, lim=1.2, elev=elev, azim=azim)
    for before, _after in drawn:  # the frame before the turn: thick arrows only, no names
        for artist in before.artists:
            if hasattr(artist, "get_text"):
                artist.remove()
            elif hasattr(artist, "set_linewidth"):
                artist.set_linewidth(2.6)
    handles = [
        Line2D([], [], color=_BEFORE, linestyle="--", linewidth=2.6),
        Line2D([], [], color="#0072B2", linestyle="-", linewidth=2.0),
    ]
    labels = ["before the turn: grey, dashed, short", "after the turn: coloured, solid, labelled"]
    fig.legend(handles, labels, loc="lower center", ncol=2, frameon=False, handlelength=3.0)
    return fig


def gimbal_axes(pitches, yaw=0.5, elev=20.0, azim=20.0):
    r"""One panel per pitch: the axes of the yaw, pitch and roll turns of roll-pitch-yaw.

    For :math:`R = R_z(\psi)R_y(\theta)R_x(\phi)` the three turns are about the world's
    :math:`e_3` (yaw), :math:`R_z(\psi)e_2` (pitch) and :math:`R_z(\psi)R_y(\theta)e_1` (roll);
    at :math:`\theta = \pm 90°` the roll axis is :math:`\mp e_3`, on the yaw axis.

    Parameters
    ----------
    pitches : array_like, shape (n,)
        Pitch angles in radians, one panel each.
    yaw : float
        The yaw angle in radians.

    Examples
    --------
    >>> fig = gimbal_axes([0.5, np.pi / 2])
    >>> len(fig.axes)
    2
    >>> plt.close(fig)
    """
    pitches = as_finite_array(pitches, "pitches").reshape(-1)
    yaw = float(as_finite_array(yaw, "yaw"))
    panels = []
    for pitch in pitches:
        R_yaw = so3.rot_z(yaw)
        roll_axis = R_yaw @ so3.rot_y(pitch) @ [1.0, 0, 0]
        panels.append(
            {
                "title": f"pitch {np.degrees(pitch):.0f}°",
                "vectors": [
                    {"v": [0, 0, 1.0], "label": "yaw axis", "color": "#0072B2"},
                    {"v": R_yaw @ [0, 1.0, 0], "label": "pitch axis", "color": "#009E73"},
                    {"v": roll_axis, "label": "roll axis", "color": "#D55E00"},
                ],
            }
        )
    fig, _, _ = frame_panels(panels, lim=1.2, elev=elev, azim=azim)
    return fig


def double_cover(turns=2.0):
    r"""The scalar part :math:`w = \cos\frac\theta2` of the quaternion of a turn by
    :math:`\theta`, beside :math:`\cos\theta` of its matrix, for :math:`\theta` from 0 to
    ``turns`` full turns.

    Examples
    --------
    >>> fig = double_cover()
    >>> [line.get_label() for line in fig.axes[0].get_lines()][:2]
    ['quaternion: $w = \\cos(\\theta/2)$', 'matrix: $\\cos\\theta = (\\mathrm{tr}\\,R - 1)/2$']
    >>> plt.close(fig)
    """
    theta = np.linspace(0.0, 2 * np.pi * float(as_finite_array(turns, "turns")), 721)
    q = quaternion.from_axis_angle([0.0, 0.0, 1.0], theta)
    R = quaternion.to_matrix(q)
    fig, ax = plt.subplots(figsize=(6.4, 3.4), dpi=DPI, layout=_LAYOUT_2D)
    ax.plot(theta / np.pi, q[:, 0], color="#0072B2", label=r"quaternion: $w = \cos(\theta/2)$")
    cos_theta = (np.trace(R, axis1=1, axis2=2) - 1) / 2
    ax.plot(theta / np.pi, cos_theta, "--", color="#C04F00", label=_MATRIX_LABEL)
    for k in range(1, int(theta[-1] / (2 * np.pi)) + 1):
        ax.axvline(2 * k, color="0.45", linewidth=0.8)  # 4.7:1 (WCAG 1.4.11)
    ax.set_xlabel(r"angle $\theta$ (multiples of $\pi$)")
    ax.set_ylim(-1.15, 1.75)
    ax.set_title("A full turn brings $R$ back, the quaternion only to $-q$")
    ax.legend(loc="upper center", ncol=2)
    return fig


_MATRIX_LABEL = r"matrix: $\cos\theta = (\mathrm{tr}\,R - 1)/2$"


def slerp_speed(q0, q1, samples=201):
    r"""The angle turned from :math:`q_0` against :math:`t`, along slerp and along the
    normalised linear average :math:`(1-t)q_0 + tq_1` ("nlerp").

    Examples
    --------
    >>> fig = slerp_speed([1, 0, 0, 0], [0, 0, 0, 1])
    >>> len(fig.axes[0].get_lines())
    2
    >>> plt.close(fig)
    """
    q0, q1 = as_unit_quaternions(q0, "q0"), as_unit_quaternions(q1, "q1")
    if q0.shape != (4,) or q1.shape != (4,):
        raise ValueError(
            f"q0 and q1 must be single quaternions of shape (4,), got {q0.shape}, {q1.shape}"
        )
    t = np.linspace(0.0, 1.0, int(samples))
    along = {"slerp": quaternion.slerp(q0, q1, t)}
    q1_near = q1 if np.dot(q0, q1) >= 0 else -q1
    lerp = (1 - t)[:, None] * q0 + t[:, None] * q1_near
    along["normalised linear average"] = lerp / np.linalg.norm(lerp, axis=1, keepdims=True)
    fig, ax = plt.subplots(figsize=(5.6, 3.6), dpi=DPI, layout=_LAYOUT_2D)
    for (name, q), style in zip(along.items(), ("-", "--")):
        relative = quaternion.multiply(quaternion.conjugate(q0), q)
        angle = np.degrees(quaternion.to_axis_angle(relative)[1])
        ax.plot(t, angle, style, label=name)
    ax.set_xlabel("$t$")
    ax.set_ylabel(r"angle turned from $R_0$ (degrees)")
    ax.legend(loc="upper left")
    return fig


def angle_streams(times, values, names, ylabel="degrees", title=None):
    """Several angles against time, one line each (for example an IMU's yaw, pitch, roll).

    Parameters
    ----------
    times : array_like, shape (n,)
    values : array_like, shape (n, k)
    names : sequence of k str

    Examples
    --------
    >>> fig = angle_streams([0, 1, 2], [[0, 1], [1, 2], [2, 3]], ["a", "b"])
    >>> [line.get_label() for line in fig.axes[0].get_lines()]
    ['a', 'b']
    >>> plt.close(fig)
    """
    times = as_finite_array(times, "times").reshape(-1)
    values = as_finite_array(values, "values")
    if values.ndim != 2 or values.shape[0] != times.size:
        raise ValueError(
            f"values must have shape ({times.size}, k), one row per time, got {values.shape}"
        )
    names = as_labels(names, values.shape[1], "names")
    fig, ax = plt.subplots(figsize=(6.4, 3.6), dpi=DPI, layout=_LAYOUT_2D)
    for column, name in zip(values.T, names):
        ax.plot(times, column, label=name)
    ax.set_xlabel("time $t$ (s)")
    ax.set_ylabel(as_str(ylabel, "ylabel"))
    if title is not None:
        ax.set_title(as_str(title, "title"))
    ax.legend(loc="best")
    return fig
