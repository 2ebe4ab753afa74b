r"""Numeric SO(3): the hat map, Rodrigues' formula, the logarithm and membership checks.

Notation follows the course notes (section 0.1): :math:`\hat{w}` is the skew matrix of
:math:`w` (Definition 5), :math:`e^{\hat\omega\theta}` the rotation by :math:`\theta` about the
unit axis :math:`\omega` (eq. 127, closed by Rodrigues' formula, eq. 159), and

.. math:: SO(3) = \{R \in \mathbb{R}^{3\times 3} \mid R^T R = I,\ \det R = 1\}.

Every function takes array-likes (lists too), computes in float64 and broadcasts over leading
axes: vectors have shape ``(..., 3)`` and matrices ``(..., 3, 3)``. Checks use the tolerance
policy of :mod:`course_lib.tolerance`.

Accuracy. ``exp`` and ``log`` are written to be accurate to a few units in the last place for
*every* angle, including the places where textbook implementations fail: angles within 1e-12 of
0 and of :math:`\pi`, and exactly :math:`\pi` about an axis with mixed signs. ``log`` takes the
angle from :math:`\operatorname{atan2}(\sin\theta, \cos\theta)`, never from an arccos, and for
angles above 150° takes the axis from the symmetric part of R (well conditioned there) and only
its sign from the skew part.

Speed. Batches are processed in cache-sized chunks with the nine matrix entries laid out as
contiguous rows, so a million rotations take a few tens of milliseconds
(``benchmarks/bench_so3.py`` measures this against scipy).
"""

import math
import warnings

import numpy as np

from ._arrays import (
    as_angles,
    as_count,
    as_float_array,
    as_matrices,
    as_square_matrices,
    as_unit_axes,
    as_vectors,
    broadcast_batch,
    frobenius_norm,
    small_floats,
    small_tol,
    vector_norm,
)
from .tolerance import TOL, check_tol, fmt_residual, tol_label

__all__ = [
    "hat",
    "vee",
    "exp",
    "log",
    "axis_angle",
    "exp_series",
    "rot_x",
    "rot_y",
    "rot_z",
    "is_rotation",
    "check_rotation",
    "random_rotations",
    "angle_between",
    "AccuracyWarning",
]

# Elements per chunk: 9 rows of this many float64 stay well inside the L2 cache.
_CHUNK = 8192
# Below this, sin θ is treated as 0 (θ / sin θ = 1); keeps every division finite.
_TINY = 1e-290
# log: beyond 150° (sin θ < 1/2) the axis comes from R + Rᵀ; up to it v / sin θ loses at most
# one bit, beyond it v / sin θ loses more and more digits as θ -> π.
_FAR = 5 * math.pi / 6
# Below this a sum of squares underflows (1e-150² < 1e-300): such norms are taken again, scaled.
_UNDERFLOW = 1e-150
# The most terms exp_series adds: beyond a few hundred every further term is below rounding
# for any matrix whose series can be summed accurately in float64.
_MAX_TERMS = 1000
# λ = 1 + cos θ. Below θ = π/2 − 1e-6 (λ > 1 + 1e-6) no entry of R comes within 5e-13 of ±1
# (R_ii ≥ cos θ > 0, and |R_ij| ≤ sin θ for i ≠ j since e_i ⊥ e_j), so rounding cannot pass ±1.
_NEAR_QUARTER = 1.0 + 1e-6
_F64 = np.dtype(np.float64)
_NUMBER = (float, int)


class AccuracyWarning(UserWarning):
    """A result is finite but rounding has made it less accurate than the tolerance policy."""


def hat(w):
    r"""The hat map (Definition 5): the skew-symmetric matrix of a 3-vector.

    .. math::

        \hat{w} = \begin{bmatrix} 0 & -w_3 & w_2 \\ w_3 & 0 & -w_1 \\ -w_2 & w_1 & 0
        \end{bmatrix}, \qquad \hat{w}\, v = w \times v.

    Parameters
    ----------
    w : array_like, shape (..., 3)
        One vector or a batch of vectors.

    Returns
    -------
    ndarray, shape (..., 3, 3)

    Raises
    ------
    ValueError
        If the last axis does not have length 3, or ``w`` holds NaN or infinity.
    TypeError
        If ``w`` is not numeric.

    Examples
    --------
    >>> hat([1, 2, 3])
    array([[ 0., -3.,  2.],
           [ 3.,  0., -1.],
           [-2.,  1.,  0.]])
    >>> v = np.array([4.0, 5.0, 6.0])
    >>> np.allclose(hat([1, 2, 3]) @ v, np.cross([1, 2, 3], v))
    True
    """
    xyz = small_floats(w, 3)
    if xyz is not None:
        x, y, z = xyz
        return np.array(((0.0, -z, y), (z, 0.0, -x), (-y, x, 0.0)))
    w = as_vectors(w, "w")
    W = np.zeros(w.shape + (3,))
    W[..., 0, 1] = -w[..., 2]
    W[..., 0, 2] = w[..., 1]
    W[..., 1, 0] = w[..., 2]
    W[..., 1, 2] = -w[..., 0]
    W[..., 2, 0] = -w[..., 1]
    W[..., 2, 1] = w[..., 0]
    return W


def vee(W, tol=TOL):
    r"""The inverse of the hat map: the vector of a skew-symmetric matrix.

    .. math::

        \begin{bmatrix} 0 & -w_3 & w_2 \\ w_3 & 0 & -w_1 \\ -w_2 & w_1 & 0 \end{bmatrix}^\vee
        = \begin{bmatrix} w_1 \\ w_2 \\ w_3 \end{bmatrix}

    The entries are read from the skew part :math:`\tfrac12 (W - W^T)`.

    Parameters
    ----------
    W : array_like, shape (..., 3, 3)
        Skew-symmetric matrices, :math:`W^T = -W` within ``tol``.
    tol : float
        Allowed :math:`\|W + W^T\|_F`.

    Returns
    -------
    ndarray, shape (..., 3)

    Raises
    ------
    ValueError
        If a matrix is not skew-symmetric (the message gives :math:`\|W + W^T\|_F`), or the
        shape is not (..., 3, 3).

    Examples
    --------
    >>> vee(hat([1, 2, 3]))
    array([1., 2., 3.])
    """
    W = as_matrices(W, "W")
    tol = check_tol(tol)
    half = 0.5 * W  # ‖W + Wᵀ‖ would overflow for entries near 1e308: measure half of it
    with np.errstate(over="ignore"):  # beyond 1.8e308 it is inf, and fails
        sym = 2.0 * frobenius_norm(half + np.swapaxes(half, -1, -2))
    if not np.all(sym <= tol):
        worst = np.unravel_index(np.argmax(sym), sym.shape) if sym.ndim else ()
        raise ValueError(
            f"W is not skew-symmetric: ‖W + Wᵀ‖ = {fmt_residual(sym[worst], tol)} > "
            f"{tol_label(tol)}"
            + (f" (at batch index {tuple(int(i) for i in worst)})" if worst else "")
            + "; vee expects a matrix of so(3), Wᵀ = −W, such as hat(w)"
        )
    return _skew_vector(W)


def _skew_vector(W):
    """The vector of the skew part, (W − Wᵀ)^∨ / 2, without overflow near 1e308."""
    pairs = ((2, 1, 1, 2), (0, 2, 2, 0), (1, 0, 0, 1))
    with np.errstate(over="ignore"):
        v = 0.5 * np.stack([W[..., i, j] - W[..., k, m] for i, j, k, m in pairs], axis=-1)
    if not np.isfinite(v).all():  # a difference overflowed: halve first (exact at that size)
        halved = np.stack([0.5 * W[..., i, j] - 0.5 * W[..., k, m] for i, j, k, m in pairs], -1)
        v = np.where(np.isfinite(v), v, halved)
    return v


def _scaled_half_norm(x, y, z):
    """‖r‖ / 2 for rows whose squared norm under- or overflows: scaled by the largest entry."""
    r = np.stack([x, y, z])
    big = np.abs(r).max(axis=0)
    safe = np.where(big > 0, big, 1.0)
    return (0.5 * big) * np.sqrt(((r / safe) ** 2).sum(axis=0))


def _exp_rows(x, y, z, out):
    """Rodrigues' formula on rotation-vector rows, written into the 9 (strided) rows of ``out``.

    Written with the half angle h = θ/2 and the quaternion (cos h, sin h ω) scaled by
    1/cos h to (1, ṽ), ṽ = tan h ω, so that nothing cancels and only one (vectorised) tangent is
    needed (numpy's float64 sin and cos are not vectorised):
    R = I + λ(ṽ̂ + ṽ̂²) with λ = 2/(1 + t²), t = tan h, and ṽ̂² = ṽṽᵀ − ‖ṽ‖² I. Near θ = π,
    t ≈ 1/(π/2 − h) stays below 1e19 for every double h, so t² never overflows; R is
    orthogonal to the rounding of λ alone.
    """
    theta2 = x * x
    theta2 += y * y
    theta2 += z * z
    half = np.sqrt(theta2)
    half *= 0.5
    # θ² underflows below 1e-154 and overflows above 1e154: recompute those without squaring.
    # Two reductions tell whether any element needs it (a mask over all of them costs more).
    low, high = theta2.min(initial=np.inf), theta2.max(initial=0.0)
    if high == np.inf or low == 0.0:
        rare = (theta2 == np.inf) | ((theta2 == 0.0) & ((x != 0.0) | (y != 0.0) | (z != 0.0)))
        half[rare] = _scaled_half_norm(x[rare], y[rare], z[rare])
    t = np.tan(half)
    lam = np.multiply(t, t, out=theta2)
    lam += 1.0
    np.divide(2.0, lam, out=lam)  # λ = 2 / (1 + t²) = 2 cos² h
    if low == 0.0:
        half[half == 0.0] = 1.0  # there r = 0 and t = 0: keep the ratio finite
    a = np.divide(t, half, out=t)
    a *= 0.5  # ṽ = tan h ω = (t / θ) r
    vx, vy, vz = a * x, a * y, a * z
    ux, uy, uz = lam * vx, lam * vy, lam * vz  # u = λ ṽ
    _quaternion_rows((ux, uy, uz), (vx, vy, vz), out)


def _quaternion_rows(u, v, out):
    """R = I + û + (u vᵀ − (u·v) I) from u = λṽ and ṽ, into the 9 rows of ``out``."""
    (ux, uy, uz), (vx, vy, vz) = u, v
    xx, yy, zz = ux * vx, uy * vy, uz * vz
    xy, xz, yz = ux * vy, ux * vz, uy * vz
    t = np.add(yy, zz, out=vx)
    np.subtract(1.0, t, out=out[0])
    np.subtract(xy, uz, out=out[1])
    np.add(xz, uy, out=out[2])
    np.add(xy, uz, out=out[3])
    np.add(xx, zz, out=t)
    np.subtract(1.0, t, out=out[4])
    np.subtract(yz, ux, out=out[5])
    np.subtract(xz, uy, out=out[6])
    np.add(yz, ux, out=out[7])
    np.add(xx, yy, out=t)
    np.subtract(1.0, t, out=out[8])
    # Every entry of a rotation lies in [−1, 1]; at θ = π about e1, λṽ² rounds to 2 + 4 ulp and
    # R_11 = 1 − λṽ² to −1.0000000000000009 (arccos of it is NaN): clipping only removes error.
    np.clip(out, -1.0, 1.0, out=out)


def _exp_rotvec(r):
    """exp of rotation vectors r (..., 3) -> (..., 3, 3), processed in chunks.

    Each chunk's results go straight into the strided columns of the (n, 9) output: a
    buffer and a transposed copy would cost one more pass over the result.
    """
    if r.shape == (3,):  # one vector, whatever its dtype was: the same digits as _exp_one
        return _exp_one(*r.tolist())
    batch = r.shape[:-1]
    flat = r.reshape(-1, 3)
    n = flat.shape[0]
    out = np.empty((n, 9))
    with np.errstate(over="ignore"):  # θ² may overflow: _exp_rows then takes the scaled path
        for start in range(0, n, _CHUNK):
            stop = min(start + _CHUNK, n)
            rows = flat[start:stop].T
            o = out[start:stop].T
            _exp_rows(rows[0], rows[1], rows[2], o)
    return out.reshape(batch + (3, 3))


def _exp_one(x, y, z):
    """exp of one rotation vector given as three finite floats: the formulas of _exp_rows."""
    half = 0.5 * math.hypot(x, y, z)  # no overflow: hypot scales
    if half == math.inf:
        half = math.hypot(0.5 * x, 0.5 * y, 0.5 * z)
    t = math.tan(half)
    lam = 2.0 / (1.0 + t * t)
    a = 0.5 * t / half if half else 0.0
    vx, vy, vz = a * x, a * y, a * z
    ux, uy, uz = lam * vx, lam * vy, lam * vz
    xx, yy, zz = ux * vx, uy * vy, uz * vz
    xy, xz, yz = ux * vy, ux * vz, uy * vz
    entries = (
        1.0 - (yy + zz),
        xy - uz,
        xz + uy,
        xy + uz,
        1.0 - (xx + zz),
        yz - ux,
        xz - uy,
        yz + ux,
        1.0 - (xx + yy),
    )
    if lam <= _NEAR_QUARTER:  # clipped to [−1, 1] as in _exp_rows, where rounding can pass ±1
        entries = [1.0 if e > 1.0 else -1.0 if e < -1.0 else e for e in entries]
    return np.array(entries).reshape(3, 3)


def _exp_single(w, theta, tol):
    """The small-input path of exp: one vector (and one angle), or None to take the batch path."""
    xyz = small_floats(w, 3)
    if xyz is None or small_tol(tol) is None:
        return None
    x, y, z = xyz
    if theta is None:
        return _exp_one(x, y, z)
    if type(theta) not in _NUMBER:
        return None
    theta = float(theta) if -1e300 < theta < 1e300 else None
    if theta is None or not abs(math.hypot(x, y, z) - 1.0) <= tol:
        return None  # the batch path raises the ValueError (or handles the huge angle)
    return _exp_one(x * theta, y * theta, z * theta)


def exp(w, theta=None, tol=TOL):
    r"""Rodrigues' formula: the rotation matrix :math:`e^{\hat\omega\theta}`.

    With ``theta``, ``w`` must be a unit axis :math:`\omega` and the result is the notes'

    .. math::

        R(\omega, \theta) = e^{\hat\omega\theta}
        = I + \sin\theta\,\hat\omega + (1-\cos\theta)\,\hat\omega^2 \qquad \text{(eq. 159)}.

    With one argument, ``w`` is a rotation vector :math:`r = \omega\theta`, the exponential
    coordinates of the rotation: the result is :math:`R(\omega, \theta)` for its unit axis
    :math:`\omega` and its angle :math:`\theta \ge 0` (and :math:`I` for :math:`r = 0`).

    Parameters
    ----------
    w : array_like, shape (..., 3)
        Rotation vectors, or unit axes when ``theta`` is given.
    theta : array_like, optional
        Angles in radians, broadcast against the batch shape of ``w``.
    tol : float, optional
        With ``theta``: how far ``‖w‖`` may be from 1, default :data:`~course_lib.tolerance.TOL`.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        Rotation matrices, orthogonal to a few machine epsilons, for every finite input (the
        norm is taken without squaring, so ``exp([2e154, 0, 0])`` is a rotation, not NaN).

    Raises
    ------
    ValueError
        If ``theta`` is given and an axis is not a unit vector (the message gives its norm),
        if a shape is wrong or the batches of ``w`` and ``theta`` do not broadcast, or an input
        holds NaN or infinity.

    Examples
    --------
    A quarter turn about z takes x to y:

    >>> R = exp([0, 0, 1], np.pi / 2)
    >>> np.round(R @ [1, 0, 0], 12)
    array([0., 1., 0.])
    >>> np.allclose(exp([0, 0, np.pi / 2]), R)
    True
    """
    if (
        theta is None
        and tol is TOL
        and type(w) is np.ndarray
        and w.shape == (3,)
        and w.dtype is _F64
    ):
        x, y, z = w.tolist()  # the common single call, inlined: validation is the next line
        if x - x == 0.0 and y - y == 0.0 and z - z == 0.0:
            return _exp_one(x, y, z)
    R = _exp_single(w, theta, tol)
    if R is not None:
        return R
    tol = check_tol(tol)
    if theta is None:
        return _exp_rotvec(as_vectors(w, "w"))
    w = as_unit_axes(
        w, "w", tol, "normalise the axis, w / ‖w‖, or pass the rotation vector w·theta alone"
    )
    theta = as_angles(theta, "theta")
    broadcast_batch(("w", w, 1), ("theta", theta, 0))
    with np.errstate(over="ignore"):
        r = w * theta[..., None]
    if not np.isfinite(r).all():
        raise ValueError(
            f"w·theta overflows float64 (|theta| up to {np.abs(theta).max():.3g}); reduce theta "
            f"modulo 2π first"
        )
    return _exp_rotvec(r)


def _residual_rows(X):
    """Squared ‖RᵀR − I‖_F and det R for the 9 contiguous entry rows of a chunk."""
    r00, r01, r02, r10, r11, r12, r20, r21, r22 = X
    g00 = r00 * r00 + r10 * r10 + r20 * r20 - 1.0
    g11 = r01 * r01 + r11 * r11 + r21 * r21 - 1.0
    g22 = r02 * r02 + r12 * r12 + r22 * r22 - 1.0
    g01 = r00 * r01 + r10 * r11 + r20 * r21
    g02 = r00 * r02 + r10 * r12 + r20 * r22
    g12 = r01 * r02 + r11 * r12 + r21 * r22
    orth2 = g00 * g00 + g11 * g11 + g22 * g22 + 2.0 * (g01 * g01 + g02 * g02 + g12 * g12)
    det = (
        r00 * (r11 * r22 - r21 * r12)
        - r10 * (r01 * r22 - r21 * r02)
        + r20 * (r01 * r12 - r11 * r02)
    )
    return orth2, det


def _rotation_error(R, index, tol, name):
    """The ValueError for the first failing matrix: what failed, by how much, what to do."""
    M = R[index]
    where = f" (at batch index {index})" if len(index) else ""
    if not np.all(np.isfinite(M)):
        return ValueError(f"{name} contains NaN or infinity{where}; expected a finite 3x3 matrix")
    with np.errstate(all="ignore"):  # entries near 1e308: inf, no warning
        orth = float(frobenius_norm(M.T @ M - np.eye(3)))
        det = float(np.linalg.det(M))
    if not (math.isfinite(det) and math.isfinite(orth)):
        return ValueError(
            f"{name} is not a rotation: its entries are so large{where} (up to "
            f"{np.abs(M).max():.3g}) that {name}ᵀ{name} overflows float64; a rotation has "
            f"entries in [−1, 1]"
        )
    if det < 0 and abs(det + 1.0) <= tol and orth <= tol:
        return ValueError(
            f"{name} is a reflection, not a rotation: det({name}) = {det:.6g}{where}; a rotation "
            f"has det = +1 (flip the sign of one column to make a right-handed frame)"
        )
    if orth > tol:
        return ValueError(
            f"{name} is not a rotation: ‖{name}ᵀ{name} − I‖ = {fmt_residual(orth, tol)} > "
            f"{tol_label(tol)}"
            f"{where} (det = {det:.6g}); its columns are not orthonormal. If it is a rotation "
            f"with rounded entries, re-orthonormalise it (e.g. U Vᵀ from its SVD) or pass a "
            f"larger tol"
        )
    return ValueError(
        f"{name} is not a rotation: det({name}) = {det:.6g}, "
        f"|det − 1| = {fmt_residual(abs(det - 1), tol)} > "
        f"{tol_label(tol)}{where}; a rotation has det = +1"
    )


_GRAM_PAIRS = ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))


def _residual_chunk(X):
    """_residual_rows for a chunk's 9 contiguous entry rows, with one einsum per dot product
    (a fused multiply-sum over the three rows: fewer passes than products and sums apart)."""
    cols = X.reshape(3, 3, -1)  # cols[i, j] = the entries r_ij
    G = np.empty((6, X.shape[1]))
    for row, (j, k) in zip(G, _GRAM_PAIRS):
        np.einsum("im,im->m", cols[:, j], cols[:, k], out=row)  # (RᵀR)_jk
    G[:3] -= 1.0
    orth2 = np.einsum("im,im->m", G[3:], G[3:])
    orth2 += orth2
    orth2 += np.einsum("im,im->m", G[:3], G[:3])
    r00, r01, r02, r10, r11, r12, r20, r21, r22 = X
    cof = G[:3]  # reused: the column-0 cofactors, det = Σ r_i0 C_i0
    np.subtract(r11 * r22, r21 * r12, out=cof[0])
    np.subtract(r21 * r02, r01 * r22, out=cof[1])
    np.subtract(r01 * r12, r11 * r02, out=cof[2])
    return orth2, np.einsum("im,im->m", cols[:, 0], cof)


def _check_chunk(R, X, start, tol, name):
    """Raise the ValueError of the first matrix of a chunk (entry rows X) not in SO(3)."""
    with np.errstate(over="ignore", invalid="ignore"):  # huge entries fail, without a warning
        orth2, det = _residual_chunk(X)
        ok = (orth2 <= tol * tol) & (np.abs(det - 1.0) <= tol)
    if not ok.all():
        bad = start + int(np.argmin(ok))
        index = np.unravel_index(bad, R.shape[:-2]) if R.ndim > 2 else ()
        raise _rotation_error(R, tuple(int(i) for i in index), tol, name)


def _validate_chunked(R, flat, tol, name):
    """Raise the ValueError of the first matrix that is not in SO(3) within ``tol``."""
    for start in range(0, flat.shape[0], _CHUNK):
        _check_chunk(R, np.ascontiguousarray(flat[start : start + _CHUNK].T), start, tol, name)


def _far_axes(X, c2, v, theta, want_axis):
    """Rotation vectors (or unit axes), shape (3, k), of the matrices beyond _FAR, given as
    their 9 entry rows X with 2 cos θ (c2), 2 sin θ ω (v) and θ.

    The dominant column of N = R + Rᵀ − 2cI = 2(1 − cos θ) ω ωᵀ, signed by v.
    """
    k = X.shape[1]
    N = X.reshape(3, 3, k) + X.reshape(3, 3, k).transpose(1, 0, 2)  # R + Rᵀ
    d0, d1, d2 = diagonal = N.reshape(9, k)[::4]  # a view of N_00, N_11, N_22
    diagonal -= c2
    first = (d0 >= d1) & (d0 >= d2)
    u = np.where(first, N[:, 0], np.where(d1 >= d2, N[:, 1], N[:, 2]))
    scale = np.sqrt(np.maximum(np.einsum("im,im->m", u, u), _TINY))
    np.divide(1.0 if want_axis else theta, scale, out=scale)
    np.copysign(scale, np.einsum("im,im->m", u, v), out=scale)  # v = +0 at exactly π: u's sign
    u *= scale
    return u


def _tiny_rows(v, s2, out, where, want_axis):
    """_log_rows for θ below _TINY: r = v / 2 (θ / sin θ = 1), the axis v / ‖v‖ (e3 for the
    identity, where every axis is right)."""
    if want_axis:  # v / ‖v‖ with ‖v‖ rounded to a subnormal is off by up to 15%: scale first
        big = np.abs(v).max(axis=0)
        zero = big == 0.0
        u = v / np.where(zero, 1.0, big)
        u /= np.sqrt(np.einsum("im,im->m", u, u))[None, :] + zero
        u[2, zero] = 1.0
    else:
        u = 0.5 * v
    out[:, where] = u


def _log_rows(X, v, out, theta, want_axis):
    """Rotation vectors (or unit axes) of the 9 entry rows X into the 3 (strided) rows of out,
    angles into theta; v is a (3, m) scratch buffer.

    Up to _FAR every element takes r = θ v / sin θ; the few beyond it are gathered and take
    the dominant column of R + Rᵀ (_far_axes), whose digits do not vanish with sin θ.
    """
    r00, r01, r02, r10, r11, r12, r20, r21, r22 = X
    c2 = r00 + r11
    c2 += r22
    c2 -= 1.0  # 2 cos θ
    np.subtract(r21, r12, out=v[0])
    np.subtract(r02, r20, out=v[1])
    np.subtract(r10, r01, out=v[2])  # v = 2 sin θ ω, the skew part of R twice
    s2 = np.sqrt(np.einsum("im,im->m", v, v))  # 2 sin θ
    small = s2 < _UNDERFLOW
    if small.any():  # θ below 1e-150: the squares underflowed
        s2[small] = vector_norm(v[:, small].T)
    np.arctan2(s2, c2, out=theta)
    np.multiply(v, np.divide(1.0 if want_axis else theta, np.maximum(s2, _TINY)), out=out)
    tiny = s2 < _TINY
    if tiny.any():  # θ below 1e-290, where 1 / sin θ overflows
        _tiny_rows(v[:, tiny], s2[tiny], out, tiny, want_axis)
    far = np.flatnonzero(theta > _FAR)
    if far.size:
        X, c2, v = np.take(X, far, axis=1), c2[far], np.take(v, far, axis=1)
        out[:, far] = _far_axes(X, c2, v, theta[far], want_axis)


def _unit_axis(v0, v1, v2):
    """v / ‖v‖ for a tiny (even subnormal) v, scaled first so that ‖v‖ is not rounded to a
    coarse subnormal; e3 for v = 0."""
    big = max(abs(v0), abs(v1), abs(v2))
    if big == 0.0:
        return 0.0, 0.0, 1.0
    v0, v1, v2 = v0 / big, v1 / big, v2 / big
    norm = math.sqrt(v0 * v0 + v1 * v1 + v2 * v2)
    return v0 / norm, v1 / norm, v2 / norm


def _log_one(X, tol, want_axis):
    """log (or axis, angle) of one matrix given as its 9 entries, Python floats; None if it is
    not a rotation within tol (the batch path then raises the ValueError). Same formulas as
    _residual_rows and _log_rows."""
    orth2, det = _residual_rows(X)  # plain arithmetic: the same code on 9 floats
    r00, r01, r02, r10, r11, r12, r20, r21, r22 = X
    if not (orth2 <= tol * tol and abs(det - 1.0) <= tol):  # NaN fails here too
        return None
    c = 0.5 * (r00 + r11 + r22 - 1.0)
    v0, v1, v2 = 0.5 * (r21 - r12), 0.5 * (r02 - r20), 0.5 * (r10 - r01)
    s = math.sqrt(v0 * v0 + v1 * v1 + v2 * v2)
    if s < _UNDERFLOW:  # θ below 1e-150: the squares underflowed
        s = float(vector_norm(np.array([v0, v1, v2])))  # as the batch path does it
    theta = math.atan2(s, c)
    if theta <= _FAR:  # up to 150°: r = θ v / sin θ
        if s < _TINY:  # 1 / sin θ overflows: θ / sin θ = 1; the identity's axis is e3
            if want_axis:
                return _unit_axis(v0, v1, v2), theta
            return (v0, v1, v2), theta
        k = (1.0 if want_axis else theta) / s
        return (k * v0, k * v1, k * v2), theta
    # beyond 150°: the dominant column of N = R + Rᵀ − 2cI, signed by v
    d0, d1, d2 = r00 - c, r11 - c, r22 - c
    n01, n02, n12 = r01 + r10, r02 + r20, r12 + r21
    if d0 >= d1 and d0 >= d2:
        u = (d0 + d0, n01, n02)
    elif d1 >= d2:
        u = (n01, d1 + d1, n12)
    else:
        u = (n02, n12, d2 + d2)
    norm = math.sqrt(max(u[0] * u[0] + u[1] * u[1] + u[2] * u[2], _TINY))
    k = math.copysign((1.0 if want_axis else theta) / norm, u[0] * v0 + u[1] * v1 + u[2] * v2)
    return (k * u[0], k * u[1], k * u[2]), theta


def _log_impl(R, tol, name, want_axis):
    if type(R) is np.ndarray and R.shape == (3, 3) and R.dtype is _F64 and type(tol) is float:
        one = _log_one(R.ravel().tolist(), tol, want_axis)
        if one is not None:
            return np.array(one[0]), np.float64(one[1])
    R = as_matrices(R, name, finite=False)  # NaN and infinity fail the residual check below
    tol = check_tol(tol)
    batch = R.shape[:-2]
    flat = R.reshape(-1, 9)
    n = flat.shape[0]
    vec = np.empty((n, 3))
    angle = np.empty(n)
    buf = np.empty((3, min(n, _CHUNK)))
    for start in range(0, n, _CHUNK):
        stop = min(start + _CHUNK, n)
        X = np.ascontiguousarray(flat[start:stop].T)
        _check_chunk(R, X, start, tol, name)  # validation in the same pass, while X is in cache
        _log_rows(X, buf[:, : stop - start], vec[start:stop].T, angle[start:stop], want_axis)
    return vec.reshape(batch + (3,)), angle.reshape(batch)


def log(R, tol=TOL):
    r"""The rotation vector :math:`r = \omega\theta` of a rotation, :math:`e^{\hat r} = R`.

    The angle :math:`\theta \in [0, \pi]` is
    :math:`\operatorname{atan2}(\|v\|, \tfrac12(\operatorname{tr}R - 1))` with
    :math:`\hat v = \tfrac12 (R - R^T) = \sin\theta\,\hat\omega`. Up to 150° the axis is
    :math:`v / \sin\theta`; beyond, where that quotient loses digits, it is the dominant column of
    :math:`\tfrac12 (R + R^T) - \cos\theta\, I = (1 - \cos\theta)\,\omega\omega^T`, with the
    sign that makes :math:`\omega \cdot v \ge 0`. At :math:`\pi` both signs are correct;
    when the skew part vanishes exactly, the one returned has a positive dominant component.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation matrices.
    tol : float
        The input must satisfy :math:`\|R^TR - I\|_F \le` tol and :math:`|\det R - 1| \le` tol.

    Returns
    -------
    ndarray, shape (..., 3)
        Rotation vectors with norm (the angle) in :math:`[0, \pi]`.

    Raises
    ------
    ValueError
        If a matrix is not a rotation (not orthogonal, or a reflection with det = −1): the
        message names what failed and by how much. Also for NaN, infinity and wrong shapes.

    Examples
    --------
    >>> r = log(exp([0.1, -0.2, 0.3]))
    >>> np.round(r, 12)
    array([ 0.1, -0.2,  0.3])
    >>> np.round(log(np.diag([-1.0, 1.0, -1.0])), 12)   # 180° about y (the notes' R_ab)
    array([0.        , 3.14159265, 0.        ])
    """
    return _log_impl(R, tol, "R", want_axis=False)[0]


def axis_angle(R, tol=TOL):
    r"""The unit axis :math:`\omega` and angle :math:`\theta \in [0, \pi]` of a rotation.

    :math:`R = e^{\hat\omega\theta}`, computed as in :func:`log`. For the identity
    (:math:`\theta = 0`) every axis is correct; :math:`e_3 = (0, 0, 1)` is returned.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
    tol : float
        Membership tolerance, as in :func:`log`.

    Returns
    -------
    axis : ndarray, shape (..., 3)
        Unit vectors.
    angle : ndarray, shape (...)
        Angles in radians, in :math:`[0, \pi]`.

    Raises
    ------
    ValueError
        If a matrix is not a rotation, as in :func:`log`.

    Examples
    --------
    >>> axis, angle = axis_angle(rot_x(0.5))
    >>> axis, round(float(angle), 12)
    (array([1., 0., 0.]), 0.5)
    """
    return _log_impl(R, tol, "R", want_axis=True)


def exp_series(A, terms):
    r"""The truncated Taylor series of the matrix exponential (Definition 6).

    .. math:: e^{A} \approx \sum_{n=0}^{N-1} \frac{A^n}{n!}, \qquad A^0 = I,

    with :math:`N` = ``terms``. Works for any square matrices; meant for teaching how the
    series converges, not for speed (use :func:`exp` for rotations).

    Parameters
    ----------
    A : array_like, shape (..., n, n)
    terms : int
        Number of terms kept, at least 1 (``terms=1`` gives :math:`I`).

    Returns
    -------
    ndarray, shape (..., n, n)

    Raises
    ------
    ValueError
        If ``terms`` is not between 1 and 1000, ``A`` is not square, or the sum overflows.

    Warns
    -----
    AccuracyWarning
        When the terms grow so large before they shrink that rounding alone leaves an error
        above ``TOL`` (e.g. ``hat([0, 0, 30])``, whose largest term is about 8e11).

    Examples
    --------
    >>> W = hat([0, 0, np.pi / 2])
    >>> bool(np.abs(exp_series(W, 25) - exp([0, 0, np.pi / 2])).max() < 1e-15)
    True
    >>> exp_series([[0.0, 1.0], [0.0, 0.0]], 2)      # I + A: nilpotent, exact
    array([[1., 1.],
           [0., 1.]])
    """
    A = as_square_matrices(A, "A")
    terms = as_count(terms, "terms", minimum=1, maximum=_MAX_TERMS)
    n = A.shape[-1]
    term = np.broadcast_to(np.eye(n), A.shape).copy()
    total = term.copy()
    largest = 1.0  # the largest ‖term‖_F: rounding leaves about eps times it in the sum
    with np.errstate(over="ignore", invalid="ignore"):
        for k in range(1, terms):
            term = term @ A / k
            total += term
            largest = max(largest, float(np.max(frobenius_norm(term), initial=0.0)))
    if not np.isfinite(total).all():
        raise ValueError(
            f"the series of A overflows float64 within {terms} terms (‖A‖_F up to "
            f"{float(np.max(frobenius_norm(A), initial=0.0)):.3g}); use exp for rotations, or "
            f"scale A down"
        )
    lost = np.finfo(np.float64).eps * largest * n
    if lost > TOL:
        warnings.warn(
            f"exp_series: the largest term has ‖A^k/k!‖_F = {largest:.3g}, so rounding alone "
            f"leaves errors up to about {lost:.1e} > {tol_label(TOL)} in the sum, however many "
            f"terms are added (cancellation); for a rotation use exp, which is accurate",
            AccuracyWarning,
            stacklevel=2,
        )
    return total


def _rot(theta, i, j):
    theta = as_angles(theta, "theta")
    R = np.zeros(theta.shape + (3, 3))
    c, s = np.cos(theta), np.sin(theta)
    k = 3 - i - j
    R[..., k, k] = 1.0
    R[..., i, i] = c
    R[..., j, j] = c
    R[..., i, j] = -s
    R[..., j, i] = s
    return R


def rot_x(theta):
    r"""Rotation by ``theta`` about the x axis, :math:`e^{\hat e_1 \theta}`.

    .. math::
        R_x(\theta) = \begin{bmatrix} 1 & 0 & 0 \\ 0 & \cos\theta & -\sin\theta \\
        0 & \sin\theta & \cos\theta \end{bmatrix}

    Parameters
    ----------
    theta : array_like
        Angles in radians; the result has shape ``theta.shape + (3, 3)``.

    Returns
    -------
    ndarray, shape (..., 3, 3)

    Examples
    --------
    >>> np.round(rot_x(np.pi / 2) @ [0, 1, 0], 12)
    array([0., 0., 1.])
    """
    return _rot(theta, 1, 2)


def rot_y(theta):
    r"""Rotation by ``theta`` about the y axis, :math:`e^{\hat e_2 \theta}`.

    .. math::
        R_y(\theta) = \begin{bmatrix} \cos\theta & 0 & \sin\theta \\ 0 & 1 & 0 \\
        -\sin\theta & 0 & \cos\theta \end{bmatrix}

    Parameters
    ----------
    theta : array_like
        Angles in radians.

    Returns
    -------
    ndarray, shape (..., 3, 3)

    Examples
    --------
    The notes' :math:`R_{ab}` (eq. 27) is 180° about y:

    >>> np.round(rot_y(np.pi), 12) + 0.0
    array([[-1.,  0.,  0.],
           [ 0.,  1.,  0.],
           [ 0.,  0., -1.]])
    """
    return _rot(theta, 2, 0)


def rot_z(theta):
    r"""Rotation by ``theta`` about the z axis, :math:`e^{\hat e_3 \theta}`.

    .. math::
        R_z(\theta) = \begin{bmatrix} \cos\theta & -\sin\theta & 0 \\
        \sin\theta & \cos\theta & 0 \\ 0 & 0 & 1 \end{bmatrix}

    Parameters
    ----------
    theta : array_like
        Angles in radians.

    Returns
    -------
    ndarray, shape (..., 3, 3)

    Examples
    --------
    The notes' :math:`R_{ac}` (eq. 28) is 45° about z:

    >>> np.allclose(rot_z(np.pi / 4)[:, 0], [1 / np.sqrt(2), 1 / np.sqrt(2), 0])
    True
    """
    return _rot(theta, 0, 1)


def is_rotation(R, tol=TOL):
    r"""Is R in SO(3): :math:`\|R^TR - I\|_F \le` tol and :math:`|\det R - 1| \le` tol?

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
    tol : float

    Returns
    -------
    bool or ndarray of bool
        A bool for one matrix, an array of the batch shape for a batch. Matrices holding NaN
        or infinity are not rotations.

    Raises
    ------
    ValueError, TypeError
        If the input is not numeric or not of shape (..., 3, 3): that is a usage error, not a
        "no".

    Examples
    --------
    >>> is_rotation(rot_z(0.3)), is_rotation(np.diag([1, 1, -1])), is_rotation(2 * np.eye(3))
    (True, False, False)
    """
    R = as_float_array(R, "R")
    if R.ndim < 2 or R.shape[-2:] != (3, 3):
        raise ValueError(f"R must have shape (..., 3, 3), got shape {R.shape}")
    tol = check_tol(tol)
    flat = R.reshape(-1, 9)
    X = np.ascontiguousarray(flat.T)
    with np.errstate(invalid="ignore", over="ignore"):
        orth2, det = _residual_rows(X)
        ok = (orth2 <= tol * tol) & (np.abs(det - 1.0) <= tol)
    if R.ndim == 2:
        return bool(ok[0])
    return ok.reshape(R.shape[:-2])


def check_rotation(R, tol=TOL, name="R"):
    r"""Return R as a float array if it is in SO(3), else raise a ValueError that explains.

    Checks :math:`\|R^TR - I\|_F \le` tol (orthonormal columns, Proposition 3) and
    :math:`|\det R - 1| \le` tol (right-handed, Proposition 4).

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
    tol : float
    name : str
        How to call the matrix in the message.

    Returns
    -------
    ndarray, shape (..., 3, 3)

    Raises
    ------
    ValueError
        Naming what failed and by how much, e.g. ``‖RᵀR − I‖ = 3.2e-02 > TOL = 1e-09`` or
        ``det(R) = -1: a reflection, not a rotation``, with the batch index of the first
        failure and a suggestion.

    Examples
    --------
    >>> check_rotation(np.diag([1.0, 1.0, -1.0]))
    Traceback (most recent call last):
    ...
    ValueError: R is a reflection, not a rotation: det(R) = -1; a rotation has det = +1
    (flip the sign of one column to make a right-handed frame)
    """
    R = as_matrices(R, name)
    tol = check_tol(tol)
    _validate_chunked(R, R.reshape(-1, 9), tol, name)
    return R


def random_rotations(n, seed=None):
    r"""``n`` rotations drawn uniformly from SO(3) (the Haar measure).

    A unit quaternion :math:`q = g / \|g\|` with :math:`g \sim N(0, I_4)` is uniform on the
    3-sphere, and :math:`q \mapsto R(q)` maps that to the uniform distribution on SO(3):

    .. math::
        R = I + 2 q_0 \hat u + 2 \hat u^2, \qquad q = (q_0, u).

    Parameters
    ----------
    n : int
        How many.
    seed : int, numpy.random.Generator or None
        Seed for reproducible draws (notebooks always pass one).

    Returns
    -------
    ndarray, shape (n, 3, 3)

    Examples
    --------
    >>> Rs = random_rotations(1000, seed=0)
    >>> Rs.shape, bool(is_rotation(Rs).all())
    ((1000, 3, 3), True)
    """
    n = as_count(n, "n")
    rng = np.random.default_rng(seed)
    q = rng.standard_normal((n, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    q0, u = q[:, 0], q[:, 1:]
    U = hat(u)
    return np.eye(3) + 2.0 * q0[:, None, None] * U + 2.0 * U @ U


def angle_between(R1, R2, tol=TOL):
    r"""The geodesic angle between two rotations: the angle of :math:`R_1^T R_2`, in [0, π].

    For small angles it uses :math:`\|R_1 - R_2\|_F = 2\sqrt2 \sin(\theta/2)`, which keeps full
    relative accuracy down to the tiniest angles (no :math:`\arccos` near 1); above 90° it uses
    the angle of :math:`R_1^TR_2` as :func:`log` does.

    Parameters
    ----------
    R1, R2 : array_like, shape (..., 3, 3)
        Rotations (validated), broadcast against each other.
    tol : float

    Returns
    -------
    ndarray or float
        Angles in radians, of the broadcast batch shape (a float for two single matrices).

    Examples
    --------
    >>> float(angle_between(np.eye(3), rot_z(1e-12)))
    1e-12
    >>> float(angle_between(np.eye(3), rot_z(1e-170)))   # no arccos: no loss near 0
    1e-170
    >>> round(float(angle_between(np.eye(3), rot_x(np.pi))), 12)
    3.14159265359
    """
    R1 = check_rotation(R1, tol, "R1")
    R2 = check_rotation(R2, tol, "R2")
    broadcast_batch(("R1", R1, 2), ("R2", R2, 2))
    d = frobenius_norm(R1 - R2) / (2.0 * np.sqrt(2.0))
    small = 2.0 * np.arcsin(np.minimum(d, 1.0))
    M = np.swapaxes(R1, -1, -2) @ R2
    c = 0.5 * (np.trace(M, axis1=-2, axis2=-1) - 1.0)
    v = 0.5 * np.stack(
        [M[..., 2, 1] - M[..., 1, 2], M[..., 0, 2] - M[..., 2, 0], M[..., 1, 0] - M[..., 0, 1]],
        axis=-1,
    )
    large = np.arctan2(np.linalg.norm(v, axis=-1), c)
    angle = np.where(small < 0.5 * np.pi, small, large)
    return float(angle) if angle.ndim == 0 else angle
