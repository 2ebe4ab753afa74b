r"""A rotation by an axis and an angle, taken apart: the maths behind the explorers.

The notes' rotation :math:`R(\omega, \theta) = e^{\hat\omega\theta}` (eq. 127) from three
angles a slider can set, the three terms of Rodrigues' formula (eq. 159) that add up to it, and
a body spinning at unit angular velocity, where the angle is the time (eq. 123-125). Pure
numpy functions on batched arrays, tested without any figure or widget; the explorers and the
animation of :mod:`course_lib.interactive` draw them.

==============================  ===============================================================
Function                        What it gives
==============================  ===============================================================
:func:`axis_from_spherical`     the unit axis :math:`\omega(\varphi, \lambda)`
:func:`rotated_frame`           :math:`e^{\hat\omega\theta}` from the spherical angles
:func:`rodrigues_terms`         :math:`I`, :math:`\sin\theta\,\hat\omega`,
                                :math:`(1-\cos\theta)\,\hat\omega^2`
:func:`rodrigues_vectors`       the same three terms applied to a point :math:`q_0`
:func:`spin_times`              the sample times of one turn, end point left out
:func:`spin_rotations`          :math:`R(t) = e^{\hat\omega t}` at unit angular velocity
==============================  ===============================================================

The axis is given by two spherical angles: the polar angle :math:`\varphi` (from the z axis)
and the azimuth :math:`\lambda` (in the xy plane, from the x axis).
"""

import numpy as np

from . import so3
from ._arrays import as_angles, as_count, as_direction, as_scalar, as_unit_axes, as_vectors
from .tolerance import TOL

__all__ = [
    "axis_from_spherical",
    "rotated_frame",
    "rodrigues_terms",
    "rodrigues_vectors",
    "spin_times",
    "spin_rotations",
]


def axis_from_spherical(polar, azimuth):
    r"""The unit rotation axis with the given polar angle and azimuth.

    .. math::

        \omega(\varphi, \lambda) = \begin{bmatrix} \sin\varphi\cos\lambda \\
        \sin\varphi\sin\lambda \\ \cos\varphi \end{bmatrix}, \qquad \|\omega\| = 1 .

    Parameters
    ----------
    polar : array_like
        Polar angle :math:`\varphi` in radians, measured from the z axis (any real value;
        the sliders use :math:`[0, \pi]`).
    azimuth : array_like
        Azimuth :math:`\lambda` in radians, measured in the xy plane from the x axis.
        Broadcast against ``polar``.

    Returns
    -------
    ndarray, shape (..., 3)
        Unit vectors, one per broadcast pair of angles.

    Raises
    ------
    ValueError
        If an angle is NaN or infinite, or the shapes do not broadcast.
    TypeError
        If an angle is not a real number.

    Examples
    --------
    >>> import numpy as np
    >>> np.round(axis_from_spherical(np.pi / 2, np.pi / 2), 12)
    array([0., 1., 0.])
    >>> axis_from_spherical([0.0, 1.0, 2.0], 0.3).shape
    (3, 3)
    """
    polar = as_angles(polar, "polar")
    azimuth = as_angles(azimuth, "azimuth")
    try:
        polar, azimuth = np.broadcast_arrays(polar, azimuth)
    except ValueError:
        raise ValueError(
            f"polar and azimuth must broadcast together, got shapes {np.shape(polar)} "
            f"and {np.shape(azimuth)}"
        ) from None
    s = np.sin(polar)
    return np.stack([s * np.cos(azimuth), s * np.sin(azimuth), np.cos(polar)], axis=-1)


def rotated_frame(polar, azimuth, theta):
    r"""The rotation by ``theta`` about the axis with spherical angles ``(polar, azimuth)``.

    .. math:: R = e^{\hat\omega\theta}, \qquad \omega = \omega(\varphi, \lambda)

    (eq. 127); its columns are the axes of the rotated body frame seen in the world frame
    (eq. 26).

    Parameters
    ----------
    polar, azimuth : array_like
        Spherical angles of the axis, see :func:`axis_from_spherical`.
    theta : array_like
        Rotation angle in radians, broadcast against the angles of the axis.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        Rotation matrices.

    Raises
    ------
    ValueError
        If an input is NaN or infinite, or the shapes do not broadcast.
    TypeError
        If an input is not a real number.

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib import so3
    >>> R = rotated_frame(0.0, 0.0, np.pi / 2)      # polar angle 0: the z axis
    >>> np.allclose(R, so3.rot_z(np.pi / 2))
    True
    """
    axis = axis_from_spherical(polar, azimuth)
    theta = as_angles(theta, "theta")
    return so3.exp(axis, theta)


def rodrigues_terms(axis, theta, tol=TOL):
    r"""The three terms of Rodrigues' formula, whose sum is :math:`e^{\hat\omega\theta}`.

    .. math::

        e^{\hat\omega\theta} = \underbrace{I}_{\text{term 0}}
        + \underbrace{\sin\theta\,\hat\omega}_{\text{term 1}}
        + \underbrace{(1-\cos\theta)\,\hat\omega^2}_{\text{term 2}}
        \qquad \text{(eq. 159)} .

    Parameters
    ----------
    axis : array_like, shape (..., 3)
        Unit rotation axes :math:`\omega`.
    theta : array_like
        Angles in radians, broadcast against the batch shape of ``axis``.
    tol : float, default TOL
        Largest accepted :math:`|\|\omega\| - 1|`.

    Returns
    -------
    identity, sin_term, cos_term : ndarray, shape (..., 3, 3)
        :math:`I`, :math:`\sin\theta\,\hat\omega` and :math:`(1-\cos\theta)\,\hat\omega^2`.

    Raises
    ------
    ValueError
        If an axis is not a unit vector (the message gives its norm), a shape is wrong, or an
        input is NaN or infinite.
    TypeError
        If an input is not a real number.

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib import so3
    >>> I, S, C = rodrigues_terms([0, 0, 1], np.pi / 2)
    >>> np.round(S, 12) + 0.0                       # + 0.0 turns -0. into 0.
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  0.],
           [ 0.,  0.,  0.]])
    >>> np.allclose(I + S + C, so3.exp([0, 0, 1], np.pi / 2))
    True
    """
    w = as_unit_axes(axis, "axis", tol)
    theta = as_angles(theta, "theta")
    W = so3.hat(w)
    W2 = W @ W
    try:
        shape = np.broadcast_shapes(w.shape[:-1], theta.shape)
    except ValueError:
        raise ValueError(
            f"theta of shape {theta.shape} does not broadcast against the batch shape "
            f"{w.shape[:-1]} of axis"
        ) from None
    s = np.sin(theta)[..., None, None]
    c = (1.0 - np.cos(theta))[..., None, None]
    identity = np.broadcast_to(np.eye(3), shape + (3, 3)).copy()
    sin_term = np.broadcast_to(s * W, shape + (3, 3)).copy()
    cos_term = np.broadcast_to(c * W2, shape + (3, 3)).copy()
    return identity, sin_term, cos_term


def rodrigues_vectors(axis, theta, q0, tol=TOL):
    r"""Rodrigues' formula applied to a point: three vectors that add up to the rotated point.

    .. math::

        e^{\hat\omega\theta} q_0 = q_0 + \sin\theta\,\hat\omega q_0
        + (1-\cos\theta)\,\hat\omega^2 q_0 ,

    where :math:`\hat\omega q_0 = \omega \times q_0` is tangent to the circle that
    :math:`q_0` travels about the axis and :math:`\hat\omega^2 q_0 = \omega\,\omega^T q_0 - q_0`
    (eq. 141) points from :math:`q_0` towards the axis. Drawn tip to tail, the three vectors
    land on :math:`e^{\hat\omega\theta} q_0`.

    Parameters
    ----------
    axis : array_like, shape (..., 3)
        Unit rotation axes.
    theta : array_like
        Angles in radians.
    q0 : array_like, shape (..., 3)
        The point being rotated.
    tol : float, default TOL
        Largest accepted :math:`|\|\omega\| - 1|`.

    Returns
    -------
    q0, sin_vec, cos_vec : ndarray, shape (..., 3)
        :math:`q_0`, :math:`\sin\theta\,\hat\omega q_0` and
        :math:`(1-\cos\theta)\,\hat\omega^2 q_0`, broadcast to a common shape.

    Raises
    ------
    ValueError
        If an axis is not a unit vector, a shape is wrong, or an input is NaN or infinite.
    TypeError
        If an input is not a real number.

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib import so3
    >>> parts = rodrigues_vectors([0, 0, 1], np.pi / 2, q0=[1, 0, 0])
    >>> [np.round(p, 12).tolist() for p in parts]
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]]
    >>> np.allclose(sum(parts), so3.exp([0, 0, 1], np.pi / 2) @ [1, 0, 0])
    True
    """
    q0 = as_vectors(q0, "q0")
    identity, sin_term, cos_term = rodrigues_terms(axis, theta, tol)
    try:
        shape = np.broadcast_shapes(identity.shape[:-2], q0.shape[:-1])
    except ValueError:
        raise ValueError(
            f"q0 of shape {q0.shape} does not broadcast against the batch shape "
            f"{identity.shape[:-2]} of axis and theta"
        ) from None
    q = np.broadcast_to(q0, shape + (3,))
    return (
        q.copy(),
        np.einsum("...ij,...j->...i", sin_term, q),
        np.einsum("...ij,...j->...i", cos_term, q),
    )


def spin_times(frames, duration=2.0 * np.pi):
    r"""The sample times of a spin animation: ``frames`` equal steps over ``duration``.

    .. math:: t_k = k\,\frac{T}{N}, \qquad k = 0, \dots, N-1,

    the end point :math:`T` left out so that a full turn (:math:`T = 2\pi`) loops without a
    repeated frame. With unit angular velocity the angle equals the time, :math:`\theta = t`.

    Parameters
    ----------
    frames : int
        Number of frames :math:`N` (at least 2).
    duration : float, default 2π
        Total time :math:`T` in seconds (> 0).

    Returns
    -------
    ndarray, shape (frames,)

    Raises
    ------
    ValueError
        If ``frames < 2`` or ``duration`` is not a positive finite number.
    TypeError
        If ``frames`` is not an integer.

    Examples
    --------
    >>> spin_times(4, duration=2.0)
    array([0. , 0.5, 1. , 1.5])
    """
    frames = as_count(frames, "frames", minimum=2)
    duration = as_scalar(duration, "duration")
    if not duration > 0:
        raise ValueError(f"duration must be > 0 seconds, got {duration:g}")
    return np.arange(frames) * (duration / frames)


def spin_rotations(axis, t):
    r"""Orientation of a body spinning at unit angular velocity about ``axis``, at times ``t``.

    With :math:`\omega = \mathrm{axis}/\|\mathrm{axis}\|` (unit magnitude: one radian per
    second), a point of the body moves as :math:`q(t) = e^{\hat\omega t} q_0` (eq. 123), so the
    body frame at time :math:`t` is

    .. math:: R(t) = e^{\hat\omega t}, \qquad \theta = t \quad \text{(eq. 125)} .

    Parameters
    ----------
    axis : array_like, shape (3,)
        Direction of the angular velocity (any non-zero length; it is normalised).
    t : array_like
        Times in seconds.

    Returns
    -------
    ndarray, shape t.shape + (3, 3)

    Raises
    ------
    ValueError
        If ``axis`` is not a 3-vector, has norm ``<= TOL``, or an input is not finite.
    TypeError
        If an input is not numeric.

    Examples
    --------
    >>> import numpy as np
    >>> R = spin_rotations([0, 0, 2], [0.0, np.pi / 2])   # the length of axis is ignored
    >>> np.round(R[1] @ [1, 0, 0], 12)
    array([0., 1., 0.])
    """
    w = as_direction(axis, "axis")
    t = as_angles(t, "t")
    return so3.exp(w, t)
