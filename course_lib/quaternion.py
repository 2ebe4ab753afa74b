r"""Unit quaternions, scalar first: :math:`q = (w, x, y, z) = (\cos\tfrac\theta2,
\ \omega \sin\tfrac\theta2)` is the rotation by :math:`\theta` about the unit axis :math:`\omega`.

The order is scalar first, as in most textbooks, Eigen's constructor and pytransform3d; ROS's
``geometry_msgs/Quaternion`` and scipy's ``Rotation.as_quat`` are scalar *last*
``(x, y, z, w)``: reorder with ``q[..., [3, 0, 1, 2]]``. Products are Hamilton's
(:math:`ij = k`), so ``multiply(p, q)`` is the rotation ``to_matrix(p) @ to_matrix(q)``: first
:math:`q`, then :math:`p`.

:math:`q` and :math:`-q` are the same rotation (the double cover of SO(3) by the unit sphere
:math:`S^3`). Functions that *choose* a quaternion (:func:`from_matrix`) return the canonical one
of the pair: :math:`w \ge 0`, and when :math:`w = 0` the first non-zero of :math:`x, y, z`
positive (scipy's ``canonical=True``). :func:`from_axis_angle` keeps the sign its angle gives.

Every function takes array-likes and broadcasts over leading axes: quaternions have shape
``(..., 4)``, vectors ``(..., 3)``, matrices ``(..., 3, 3)``. A quaternion argument must have norm
1 within :data:`~course_lib.tolerance.TOL` (``tol``); NaN, infinity or another norm get a
ValueError naming the argument, its norm and the batch index.
"""

import math

import numpy as np

from . import so3
from ._arrays import (
    as_angles,
    as_float_array,
    as_unit_axes,
    as_unit_quaternions,
    as_vectors,
    broadcast_batch,
    small_floats,
    small_tol,
    vector_norm,
)
from .tolerance import TOL, check_tol

__all__ = [
    "from_axis_angle",
    "to_axis_angle",
    "from_matrix",
    "to_matrix",
    "multiply",
    "conjugate",
    "rotate",
    "slerp",
]

_F64 = np.dtype(np.float64)
_CHUNK = 8192
# slerp: below this angle between q0 and q1 on S³, sin(tΩ)/sin Ω = t to within Ω²/6 < 1e-17.
_SLERP_LINEAR = 1e-8
# rotate: beyond this the partial sums v + 2w(u × v) + ... (up to 3‖v‖) could overflow.
_HUGE = 2.0**1020


def from_axis_angle(axis, angle, tol=TOL):
    r"""The unit quaternion of the rotation by ``angle`` about the unit ``axis``.

    .. math:: q = \left(\cos\tfrac\theta2,\ \omega\,\sin\tfrac\theta2\right)

    Not canonicalised: :math:`\theta` and :math:`\theta + 2\pi` give :math:`q` and :math:`-q`,
    the same rotation.

    Parameters
    ----------
    axis : array_like, shape (..., 3)
        Unit axes :math:`\omega` (norm 1 within ``tol``).
    angle : array_like, shape (...)
        Angles in radians, broadcast against the batch of ``axis``.
    tol : float

    Returns
    -------
    ndarray, shape (..., 4)

    Examples
    --------
    >>> from_axis_angle([0, 0, 1], np.pi / 2)
    array([0.70710678, 0.        , 0.        , 0.70710678])
    """
    axis = as_unit_axes(axis, "axis", check_tol(tol), "normalise it: axis / ‖axis‖")
    angle = as_angles(angle, "angle")
    batch = broadcast_batch(("axis", axis, 1), ("angle", angle, 0))
    half = 0.5 * angle
    q = np.empty(batch + (4,))
    q[..., 0] = np.cos(half)
    q[..., 1:] = np.sin(half)[..., None] * axis
    return q


def to_axis_angle(q, tol=TOL):
    r"""The unit axis :math:`\omega` and angle :math:`\theta \in [0, \pi]` of unit quaternions.

    With :math:`q` replaced by :math:`-q` where :math:`w < 0` (same rotation),

    .. math:: \theta = 2\operatorname{atan2}(\|v\|, w), \qquad \omega = v / \|v\|,
        \qquad q = (w, v),

    accurate for every angle (no arccos). For :math:`\theta = 0` every axis is right;
    :math:`e_3` is returned, as :func:`course_lib.so3.axis_angle` does.

    Parameters
    ----------
    q : array_like, shape (..., 4)
    tol : float

    Returns
    -------
    axis : ndarray, shape (..., 3)
    angle : ndarray, shape (...)

    Examples
    --------
    >>> axis, angle = to_axis_angle([0.0, 0.0, -1.0, 0.0])
    >>> axis, float(angle / np.pi)
    (array([ 0., -1.,  0.]), 1.0)
    """
    q = as_unit_quaternions(q, "q", tol)
    q = np.where(q[..., :1] < 0.0, -q, q)
    v = q[..., 1:]
    norm = vector_norm(v)
    angle = 2.0 * np.arctan2(norm, q[..., 0])
    big = np.abs(v).max(axis=-1, keepdims=True)  # scaled: ‖v‖ may be subnormal
    zero = big == 0.0
    u = v / np.where(zero, 1.0, big)
    u /= np.sqrt(np.sum(u * u, axis=-1, keepdims=True)) + zero
    u[..., 2:] += zero
    return u, angle


def _shepperd_one(X):
    """(w, x, y, z) of one rotation given as 9 Python floats: Shepperd's pivot, canonical sign."""
    r00, r01, r02, r10, r11, r12, r20, r21, r22 = X
    d = (1.0 + r00 + r11 + r22, 1.0 + r00 - r11 - r22, 1.0 - r00 + r11 - r22)
    d = d + (1.0 - r00 - r11 + r22,)
    sx, sy, sz = r21 - r12, r02 - r20, r10 - r01
    pxy, pxz, pyz = r01 + r10, r02 + r20, r12 + r21
    k = max(range(4), key=d.__getitem__)
    col = ((d[0], sx, sy, sz), (sx, d[1], pxy, pxz), (sy, pxy, d[2], pyz), (sz, pxz, pyz, d[3]))[k]
    norm = math.sqrt(col[0] ** 2 + col[1] ** 2 + col[2] ** 2 + col[3] ** 2)
    pivot = next((c for c in col if c != 0.0), 1.0)
    scale = math.copysign(1.0 / norm, col[0] if col[0] != 0.0 else pivot)
    return tuple(scale * c + 0.0 for c in col)


def _from_matrix_single(R, tol):
    """The small-input path of from_matrix: (w, x, y, z) as floats for one float64 3x3 rotation
    within tol, else None (the batch path then validates, and raises the ValueError)."""
    if type(R) is np.ndarray and R.shape == (3, 3) and R.dtype is _F64 and type(tol) is float:
        X = R.ravel().tolist()
        orth2, det = so3._residual_rows(X)  # the check of so3.check_rotation, on 9 floats
        if orth2 <= tol * tol and abs(det - 1.0) <= tol and 0.0 <= tol:  # NaN fails here
            return _shepperd_one(X)
    return None


def _shepperd_rows(X, out):
    """Shepperd's quaternions of the 9 entry rows X (3x3 rotations) into the 4 rows of out.

    4qqᵀ is a symmetric 4x4 matrix whose entries are sums of entries of R; its column of the
    largest diagonal entry (4q_k², at least 1) divided by its norm is ±q with no cancellation.
    """
    r00, r01, r02, r10, r11, r12, r20, r21, r22 = X
    d0 = 1.0 + r00 + r11 + r22
    d1 = 1.0 + r00 - r11 - r22
    d2 = 1.0 - r00 + r11 - r22
    d3 = 1.0 - r00 - r11 + r22
    sx, sy, sz = r21 - r12, r02 - r20, r10 - r01
    pxy, pxz, pyz = r01 + r10, r02 + r20, r12 + r21
    M = np.array(
        ((d0, sx, sy, sz), (sx, d1, pxy, pxz), (sy, pxy, d2, pyz), (sz, pxz, pyz, d3))
    )  # M[k] is column k of 4qqᵀ
    k = np.stack((d0, d1, d2, d3)).argmax(axis=0)
    col = np.take_along_axis(M, k[None, None, :], axis=0)[0]
    scale = np.sqrt(np.einsum("im,im->m", col, col))
    np.divide(1.0, scale, out=scale)
    np.copysign(scale, col[0], out=scale)  # w ≥ 0
    np.multiply(col, scale, out=out)
    _canonical_at_zero_w(out)


def _canonical_at_zero_w(q):
    """Where w = 0 exactly, flip the sign so the first non-zero of x, y, z is positive (q: rows)."""
    zero = q[0] == 0.0
    if zero.any():
        sub = q[:, zero]
        first = np.where(sub[1] != 0.0, sub[1], np.where(sub[2] != 0.0, sub[2], sub[3]))
        sub *= np.where(first < 0.0, -1.0, 1.0)
        sub[0] = 0.0  # no −0.0
        q[:, zero] = sub


def from_matrix(R, tol=TOL):
    r"""The canonical unit quaternion of rotation matrices (Shepperd's method).

    :math:`4qq^T` has entries :math:`4w^2 = 1 + \operatorname{tr}R`,
    :math:`4x^2 = 1 + R_{11} - R_{22} - R_{33}` (and likewise :math:`4y^2, 4z^2`),
    :math:`4wx = R_{32} - R_{23}`, :math:`4xy = R_{12} + R_{21}`, ...; Shepperd takes the column
    of the largest diagonal entry, :math:`4q_k^2 \ge 1`, so nothing cancels at any angle (the
    textbook :math:`w = \tfrac12\sqrt{1 + \operatorname{tr} R}` loses every digit of the axis
    near 180°):

    .. math:: q = \pm\frac{(4qq^T)_{:,k}}{\|(4qq^T)_{:,k}\|}, \qquad
        k = \arg\max_k (4qq^T)_{kk}.

    The sign makes :math:`w \ge 0` (when :math:`w = 0`, the first non-zero of :math:`x, y, z`
    is positive).

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotations, checked as by :func:`course_lib.so3.check_rotation` within ``tol``.
    tol : float

    Returns
    -------
    ndarray, shape (..., 4)
        Unit quaternions, scalar first.

    Raises
    ------
    ValueError
        If a matrix is not a rotation (not orthogonal, or a reflection), naming what failed.

    Examples
    --------
    >>> from_matrix(np.diag([1.0, -1.0, -1.0]))          # 180° about x
    array([0., 1., 0., 0.])
    >>> from_matrix(so3.rot_z(np.pi / 2))
    array([0.70710678, 0.        , 0.        , 0.70710678])
    """
    one = _from_matrix_single(R, tol)
    if one is not None:
        return np.array(one)
    R = so3.check_rotation(R, tol)
    flat = R.reshape(-1, 9)
    out = np.empty((flat.shape[0], 4))
    for start in range(0, flat.shape[0], _CHUNK):
        chunk = slice(start, start + _CHUNK)
        _shepperd_rows(np.ascontiguousarray(flat[chunk].T), out[chunk].T)
    return out.reshape(R.shape[:-2] + (4,))


def _unit_one(q, tol):
    """One unit quaternion as four Python floats, or None (not one finite quaternion of norm 1
    within ``tol``: the batch path accepts or explains it). The norm as :func:`vector_norm`."""
    f = small_floats(q, 4)
    if f is None or small_tol(tol) is None:
        return None
    big = max(abs(f[0]), abs(f[1]), abs(f[2]), abs(f[3]))
    if not big > 0.0:
        return None
    a, b, c, d = f[0] / big, f[1] / big, f[2] / big, f[3] / big
    norm = big * math.sqrt(a * a + b * b + c * c + d * d)
    return f if abs(norm - 1.0) <= tol else None


def _matrix_one(w, x, y, z):
    """to_matrix of one quaternion given as four floats: the batch path's formulas, in order."""
    n = math.sqrt(w * w + x * x + y * y + z * z)
    w, x, y, z = w / n, x / n, y / n, z / n
    ww, xx, yy, zz = w * w, x * x, y * y, z * z
    x2, y2, z2 = x + x, y + y, z + z
    xy, xz, yz = x * y2, x * z2, y * z2
    wx, wy, wz = w * x2, w * y2, w * z2
    entries = (
        (ww + xx) - (yy + zz), xy - wz, xz + wy,
        xy + wz, (ww + yy) - (xx + zz), yz - wx,
        xz - wy, yz + wx, (ww + zz) - (xx + yy),
    )  # fmt: skip
    clipped = [1.0 if e > 1.0 else -1.0 if e < -1.0 else e for e in entries]  # as np.clip
    return np.array(clipped).reshape(3, 3)


def _product_one(p, q):
    """Hamilton's product of two quaternions given as float tuples (the formulas of _product)."""
    pw, px, py, pz = p
    qw, qx, qy, qz = q
    return (
        pw * qw - px * qx - py * qy - pz * qz,
        pw * qx + px * qw + py * qz - pz * qy,
        pw * qy - px * qz + py * qw + pz * qx,
        pw * qz + px * qy - py * qx + pz * qw,
    )


def to_matrix(q, tol=TOL):
    r"""The rotation matrix of unit quaternions :math:`q = (w, v)`.

    .. math:: R = I + 2w\,\hat v + 2\hat v^2 =
        \begin{bmatrix} w^2 + x^2 - y^2 - z^2 & 2(xy - wz) & 2(xz + wy) \\
        2(xy + wz) & w^2 - x^2 + y^2 - z^2 & 2(yz - wx) \\
        2(xz - wy) & 2(yz + wx) & w^2 - x^2 - y^2 + z^2 \end{bmatrix}

    ``q`` is checked to have norm 1 within ``tol`` and then divided by its norm, so R is
    orthogonal to rounding; entries are clipped to [−1, 1], which rounding could pass.
    ``to_matrix(-q)`` equals ``to_matrix(q)``.

    Parameters
    ----------
    q : array_like, shape (..., 4)
    tol : float

    Returns
    -------
    ndarray, shape (..., 3, 3)

    Examples
    --------
    >>> np.round(to_matrix([np.cos(np.pi / 4), 0, 0, np.sin(np.pi / 4)]), 12) + 0.0
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  0.],
           [ 0.,  0.,  1.]])
    """
    one = _unit_one(q, tol)
    if one is not None:
        return _matrix_one(*one)
    return _matrices(as_unit_quaternions(q, "q", tol))


def _matrices(q):
    """to_matrix of a float array of quaternions (..., 4) of norm 1 to rounding, unchecked."""
    q = q / np.sqrt(np.sum(q * q, axis=-1, keepdims=True))
    w, x, y, z = np.moveaxis(q, -1, 0)
    ww, xx, yy, zz = w * w, x * x, y * y, z * z
    x2, y2, z2 = x + x, y + y, z + z
    xy, xz, yz = x * y2, x * z2, y * z2
    wx, wy, wz = w * x2, w * y2, w * z2
    R = np.empty(w.shape + (3, 3))
    # the diagonal as w² + x² − y² − z²: exactly 0 for q = (1, 0, 0, 1)/√2
    np.subtract(ww + xx, yy + zz, out=R[..., 0, 0])
    np.subtract(xy, wz, out=R[..., 0, 1])
    np.add(xz, wy, out=R[..., 0, 2])
    np.add(xy, wz, out=R[..., 1, 0])
    np.subtract(ww + yy, xx + zz, out=R[..., 1, 1])
    np.subtract(yz, wx, out=R[..., 1, 2])
    np.subtract(xz, wy, out=R[..., 2, 0])
    np.add(yz, wx, out=R[..., 2, 1])
    np.subtract(ww + zz, xx + yy, out=R[..., 2, 2])
    return np.clip(R, -1.0, 1.0, out=R)  # rounding can pass ±1 (as in so3.exp); R's entries can't


def _product(p, q):
    """Hamilton's product of two float arrays (..., 4), no validation."""
    pw, px, py, pz = np.moveaxis(p, -1, 0)
    qw, qx, qy, qz = np.moveaxis(q, -1, 0)
    return np.stack(
        (
            pw * qw - px * qx - py * qy - pz * qz,
            pw * qx + px * qw + py * qz - pz * qy,
            pw * qy - px * qz + py * qw + pz * qx,
            pw * qz + px * qy - py * qx + pz * qw,
        ),
        axis=-1,
    )


def multiply(p, q, tol=TOL):
    r"""Hamilton's product :math:`pq`: the rotation :math:`R(p)R(q)` (first :math:`q`, then
    :math:`p`).

    .. math:: (p_w, p_v)(q_w, q_v) = (p_w q_w - p_v\cdot q_v,\
        p_w q_v + q_w p_v + p_v \times q_v)

    Not commutative: :math:`pq \ne qp` unless the axes are parallel.

    Parameters
    ----------
    p, q : array_like, shape (..., 4)
        Unit quaternions, broadcast against each other.
    tol : float

    Returns
    -------
    ndarray, shape (..., 4)

    Examples
    --------
    Two quarter turns about z make a half turn:

    >>> qz = from_axis_angle([0, 0, 1], np.pi / 2)
    >>> np.round(multiply(qz, qz), 12) + 0.0
    array([0., 0., 0., 1.])
    """
    p1, q1 = _unit_one(p, tol), _unit_one(q, tol)
    if p1 is not None and q1 is not None:
        return np.array(_product_one(p1, q1))
    p = as_unit_quaternions(p, "p", tol)
    q = as_unit_quaternions(q, "q", tol)
    broadcast_batch(("p", p, 1), ("q", q, 1))
    return _product(p, q)


def conjugate(q, tol=TOL):
    r"""The conjugate :math:`q^* = (w, -v)`, the inverse of a unit quaternion: the rotation
    :math:`R(q)^T`.

    Parameters
    ----------
    q : array_like, shape (..., 4)
    tol : float

    Returns
    -------
    ndarray, shape (..., 4)

    Examples
    --------
    >>> conjugate([0.5, 0.5, -0.5, 0.5])
    array([ 0.5, -0.5,  0.5, -0.5])
    """
    q = as_unit_quaternions(q, "q", tol)
    return q * np.array([1.0, -1.0, -1.0, -1.0])


def rotate(q, v, tol=TOL):
    r"""Rotate vectors: the vector part of :math:`q\,(0, v)\,q^*`, that is :math:`R(q)\,v`.

    .. math:: q\,(0, v)\,q^* = \left(0,\ v + 2w\,(u \times v) + 2\,u \times (u \times v)\right),
        \qquad q = (w, u)

    Parameters
    ----------
    q : array_like, shape (..., 4)
        Unit quaternions.
    v : array_like, shape (..., 3)
        Vectors, broadcast against the batch of ``q``.
    tol : float

    Returns
    -------
    ndarray, shape (..., 3)

    Examples
    --------
    >>> q = from_axis_angle([0, 0, 1], np.pi / 2)
    >>> np.round(rotate(q, [1, 0, 0]), 12) + 0.0
    array([0., 1., 0.])
    """
    one, v1 = _unit_one(q, tol), small_floats(v, 3)
    if one is not None and v1 is not None and max(map(abs, v1)) <= _HUGE:
        return np.array(_rotate_one(one, v1))
    q = as_unit_quaternions(q, "q", tol)
    v = as_vectors(v, "v")
    broadcast_batch(("q", q, 1), ("v", v, 1))
    if np.abs(v).max(initial=0.0) > _HUGE:  # ‖R v‖ = ‖v‖ fits; the sums on the way may not
        with np.errstate(over="ignore"):
            out = _rotate(q, v * 0.0625) * 16.0  # powers of two: exact
        if not np.isfinite(out).all():
            raise ValueError(
                f"v is too long to rotate in float64: a rotated entry passes 1.8e308 "
                f"(‖v‖ up to {float(np.max(vector_norm(v))):.3g}); scale v down first"
            )
        return out
    return _rotate(q, v)


def _rotate(q, v):
    w, u = q[..., :1], q[..., 1:]
    t = np.cross(u, v)
    t += t
    return v + w * t + np.cross(u, t)


def _rotate_one(q, v):
    """_rotate of one quaternion and one vector given as float tuples (the same formulas)."""
    w, ux, uy, uz = q
    vx, vy, vz = v
    tx, ty, tz = uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx
    tx, ty, tz = tx + tx, ty + ty, tz + tz
    return (
        vx + w * tx + (uy * tz - uz * ty),
        vy + w * ty + (uz * tx - ux * tz),
        vz + w * tz + (ux * ty - uy * tx),
    )


def _norm_one(v):
    """:func:`vector_norm` of one vector given as a float tuple (the same steps)."""
    big = max(map(abs, v))
    if not 0.0 < big < math.inf:
        return big
    return big * math.sqrt(sum((e / big) * (e / big) for e in v))


def _slerp_one(q0, q1, t):
    """slerp of two quaternions and one fraction given as floats (the batch path's formulas)."""
    if sum(a * b for a, b in zip(q0, q1)) < 0.0:
        q1 = tuple(-b for b in q1)
    diff = _norm_one(tuple(b - a for a, b in zip(q0, q1)))
    omega = 2.0 * math.atan2(diff, _norm_one(tuple(b + a for a, b in zip(q0, q1))))
    if omega < _SLERP_LINEAR:
        a, b = 1.0 - t, t
    else:
        sin_omega = math.sin(omega)
        a, b = math.sin((1.0 - t) * omega) / sin_omega, math.sin(t * omega) / sin_omega
    q = tuple(a * x + b * y for x, y in zip(q0, q1))
    norm = _norm_one(q)
    return np.array([x / norm for x in q])


def slerp(q0, q1, t, tol=TOL):
    r"""Spherical linear interpolation from ``q0`` (t = 0) to ``q1`` (t = 1), along the shorter
    arc: the geodesic of SO(3) at constant angular speed.

    With :math:`q_1` replaced by :math:`-q_1` where :math:`q_0 \cdot q_1 < 0` (the same rotation,
    nearer on :math:`S^3`) and :math:`\Omega = 2\operatorname{atan2}(\|q_1 - q_0\|,
    \|q_1 + q_0\|) \in [0, \pi/2]` the angle between them on :math:`S^3`:

    .. math:: \operatorname{slerp}(q_0, q_1, t) = \frac{\sin((1-t)\Omega)}{\sin\Omega}\,q_0
        + \frac{\sin(t\Omega)}{\sin\Omega}\,q_1 = q_0\,(q_0^* q_1)^t .

    The rotation turns by :math:`2\Omega t` about a fixed axis (chapter 04's geodesic
    :math:`R_0 e^{\hat\omega\theta t}`). Below :math:`\Omega = 10^{-8}` the coefficients are
    :math:`1 - t` and :math:`t` (exact to rounding there); the result is normalised.

    Parameters
    ----------
    q0, q1 : array_like, shape (..., 4)
        Unit quaternions, broadcast against each other.
    t : array_like, shape (...)
        Fractions; 0 gives ``q0``, 1 gives ``q1`` (or ``-q1``), values outside [0, 1]
        extrapolate along the same geodesic.
    tol : float

    Returns
    -------
    ndarray, shape (..., 4)

    Examples
    --------
    Half way from the identity to a half turn about z is a quarter turn:

    >>> slerp([1, 0, 0, 0], [0, 0, 0, 1], 0.5)
    array([0.70710678, 0.        , 0.        , 0.70710678])
    """
    p0, p1 = _unit_one(q0, tol), _unit_one(q1, tol)
    if p0 is not None and p1 is not None and type(t) in (float, int) and abs(t) < 1e300:
        return _slerp_one(p0, p1, float(t))
    q0 = as_unit_quaternions(q0, "q0", tol)
    q1 = as_unit_quaternions(q1, "q1", tol)
    t = as_angles(as_float_array(t, "t"), "t")
    broadcast_batch(("q0", q0, 1), ("q1", q1, 1), ("t", t, 0))
    q1 = np.where(np.sum(q0 * q1, axis=-1, keepdims=True) < 0.0, -q1, q1)
    omega = 2.0 * np.arctan2(vector_norm(q1 - q0), vector_norm(q1 + q0))[..., None]
    t = t[..., None]
    linear = omega < _SLERP_LINEAR
    sin_omega = np.where(linear, 1.0, np.sin(omega))
    a = np.where(linear, 1.0 - t, np.sin((1.0 - t) * omega) / sin_omega)
    b = np.where(linear, t, np.sin(t * omega) / sin_omega)
    q = a * q0 + b * q1
    return q / vector_norm(q)[..., None]
