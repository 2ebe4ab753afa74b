r"""Euler angles: a rotation as three turns about coordinate axes, in scipy's ``seq`` convention.

``seq`` is three letters of x, y, z, no letter twice in a row:

- all upper case (``"ZYX"``) are *intrinsic* turns, about the axes of the turning body:
  :math:`R = R_Z(\alpha)\,R_Y(\beta)\,R_X(\gamma)`, read left to right;
- all lower case (``"xyz"``) are *extrinsic* turns, about the fixed axes:
  :math:`R = R_z(\gamma)\,R_y(\beta)\,R_x(\alpha)`, the first turn rightmost.

So ``"ZYX"`` with angles (yaw, pitch, roll) and ``"xyz"`` with (roll, pitch, yaw) are the same
matrix (chapter 04's rule: turns about body axes compose in the reverse order of turns about
fixed axes). Sequences whose first and last letters are equal (``"zxz"``) are *proper* Euler
angles, the others (``"xyz"``) Tait-Bryan angles; 6 of each, 12 in all, times 2 conventions.

Ranges of :func:`from_matrix` (as scipy's): the first and third angle in :math:`[-\pi, \pi]`,
the middle one in :math:`[0, \pi]` for proper Euler angles and :math:`[-\pi/2, \pi/2]` for
Tait-Bryan angles.

Gimbal lock: when the middle angle is 0 or :math:`\pi` (proper) or :math:`\pm\pi/2`
(Tait-Bryan), the first and third axes line up and only the sum (or difference) of their
angles is determined. There :func:`from_matrix` sets the **third angle of seq to 0** and gives
the whole turn to the first, in both conventions, as scipy does; the triple reproduces R to
rounding. Lock is declared only within ``_LOCK`` = 1e-15 rad of it, where setting the third
angle to 0 moves R by less than 1e-14 (scipy declares it within 1e-7, moving R by up to
about 1e-7, and warns; this module does not warn).

Angles are in radians and every function broadcasts over leading axes: angle triples have
shape ``(..., 3)`` and matrices ``(..., 3, 3)``.
"""

import math

import numpy as np

from . import quaternion
from ._arrays import as_float_array, require_finite, small_floats
from .tolerance import TOL

__all__ = ["to_matrix", "from_matrix"]

# Gimbal lock is declared when the middle angle is within this of 0 or π (before the shift of
# Tait-Bryan angles by π/2): then R moves by at most about 2·_LOCK when the third angle is set
# to 0.
_LOCK = 1e-15
_CHUNK = 8192
_AXIS = {"x": 0, "y": 1, "z": 2}


def _parse_seq(seq):
    """(extrinsic axes i, j, k as 0..2, extrinsic: bool) of a scipy sequence, or a ValueError."""
    if not isinstance(seq, str):
        raise TypeError(f"seq must be a string such as 'xyz' or 'ZXZ', got {type(seq).__name__}")
    lower = seq.lower()
    if len(seq) != 3 or any(c not in _AXIS for c in lower):
        raise ValueError(
            f"seq must be 3 letters of x, y, z (e.g. 'xyz', 'ZXZ'), got {seq!r} of length "
            f"{len(seq)}"
        )
    if not (seq.islower() or seq.isupper()):
        raise ValueError(
            f"seq must be all lower case (extrinsic, fixed axes) or all upper case (intrinsic, "
            f"body axes), got {seq!r}"
        )
    if lower[0] == lower[1] or lower[1] == lower[2]:
        raise ValueError(
            f"seq must not repeat an axis in consecutive turns (two turns about one axis are "
            f"one turn), got {seq!r}"
        )
    axes = tuple(_AXIS[c] for c in lower)
    return axes, seq.islower()


def _as_angle_triples(angles):
    arr = as_float_array(angles, "angles")
    if arr.ndim == 0 or arr.shape[-1] != 3:
        raise ValueError(f"angles must have shape (..., 3) (angle triples), got shape {arr.shape}")
    return require_finite(arr, "angles")


def _two_turns(i, a, j, b):
    r"""Quaternions (..., 4) of the turn by ``a`` about axis ``i`` times the turn by ``b`` about
    axis ``j`` (:math:`i \ne j`): Hamilton's product of :math:`(\cos\frac a2, \sin\frac a2 e_i)`
    and :math:`(\cos\frac b2, \sin\frac b2 e_j)`, without the terms that are 0."""
    ca, sa, cb, sb = np.cos(0.5 * a), np.sin(0.5 * a), np.cos(0.5 * b), np.sin(0.5 * b)
    q = np.empty(ca.shape + (4,))
    q[..., 0] = ca * cb
    q[..., 1 + i] = sa * cb
    q[..., 1 + j] = ca * sb
    m = 3 - i - j  # e_i × e_j = ±e_m
    q[..., 1 + m] = sa * sb if (j - i) % 3 == 1 else -(sa * sb)
    return q


def _times_turn(q, k, c):
    r"""Quaternions (..., 4): ``q`` times the turn by ``c`` about axis ``k``,
    :math:`(w c' - v_k s',\ w s' e_k + c' v + s'\, v \times e_k)` with
    :math:`c' = \cos\frac c2, s' = \sin\frac c2`."""
    cc, sc = np.cos(0.5 * c), np.sin(0.5 * c)
    a, b = (k + 1) % 3, (k + 2) % 3  # (v × e_k)_a = v_b, (v × e_k)_b = −v_a
    w, va, vb, vk = q[..., 0], q[..., 1 + a], q[..., 1 + b], q[..., 1 + k]
    out = np.empty(q.shape)
    out[..., 0] = w * cc - vk * sc
    out[..., 1 + k] = w * sc + cc * vk
    out[..., 1 + a] = cc * va + sc * vb
    out[..., 1 + b] = cc * vb - sc * va
    return out


def _to_matrix_one(angles, axes, extrinsic):
    """to_matrix of one angle triple given as floats: the batch path's steps on floats."""
    q = []
    for angle, axis in zip(angles, axes):
        turn = [math.cos(0.5 * angle), 0.0, 0.0, 0.0]
        turn[1 + axis] = math.sin(0.5 * angle)
        q.append(turn)
    if extrinsic:
        q.reverse()
    product = quaternion._product_one(quaternion._product_one(q[0], q[1]), q[2])
    return quaternion.to_matrix(list(product))


def to_matrix(angles, seq):
    r"""The rotation matrix of Euler angles in scipy's ``seq`` convention.

    .. math:: \text{intrinsic } \mathtt{"IJK"}:\ R = R_I(\alpha)\,R_J(\beta)\,R_K(\gamma),
        \qquad \text{extrinsic } \mathtt{"ijk"}:\ R = R_k(\gamma)\,R_j(\beta)\,R_i(\alpha)

    with :math:`(\alpha, \beta, \gamma)` = ``angles`` and :math:`R_x, R_y, R_z` the turns of
    :func:`course_lib.so3.rot_x` etc. Computed as a product of unit quaternions.

    Parameters
    ----------
    angles : array_like, shape (..., 3)
        Angles in radians, in the order of ``seq``.
    seq : str
        Three letters of x, y, z, all upper case (intrinsic) or all lower case (extrinsic).

    Returns
    -------
    ndarray, shape (..., 3, 3)

    Raises
    ------
    ValueError
        For a bad ``seq`` (wrong letters, mixed case, an axis twice in a row) or angles that are
        not finite triples.

    Examples
    --------
    Roll-pitch-yaw: yaw 90° about the body's z after nothing else takes x to y.

    >>> np.round(to_matrix([np.pi / 2, 0, 0], "ZYX") @ [1, 0, 0], 12) + 0.0
    array([0., 1., 0.])
    >>> bool(np.allclose(to_matrix([0.1, 0.2, 0.3], "ZYX"), to_matrix([0.3, 0.2, 0.1], "xyz")))
    True
    """
    (i, j, k), extrinsic = _parse_seq(seq)
    one = small_floats(angles, 3)
    if one is not None:
        return _to_matrix_one(one, (i, j, k), extrinsic)
    angles = _as_angle_triples(angles)
    turns = [(axis, angles[..., n]) for n, axis in enumerate((i, j, k))]
    if extrinsic:
        turns.reverse()
    product = _times_turn(_two_turns(*turns[0], *turns[1]), *turns[2])
    return quaternion._matrices(product)  # a product of unit quaternions: unit to rounding


class _Arrays:
    """numpy's functions for the batch path of _angles; hypot as √(a² + b²), since np.hypot
    calls libm once per element (60 ns, 20 times np.arctan2). No overflow: |a|, |b| ≤ 2 here;
    squares underflow only where ‖(a, b)‖ < 1e-154, an angle of 0 to within 1e-154."""

    arctan2 = staticmethod(np.arctan2)
    where = staticmethod(np.where)

    @staticmethod
    def hypot(a, b):
        return np.sqrt(a * a + b * b)


class _Floats:
    """math's functions under numpy's names, for the single-rotation path of _angles."""

    arctan2 = staticmethod(math.atan2)
    hypot = staticmethod(math.hypot)

    @staticmethod
    def where(condition, a, b):
        return a if condition else b


def _angles(w, q, axes, extrinsic, xp):
    """Euler angles (first, middle, third) of unit quaternions (w, q[0], q[1], q[2]).

    The method of Bernardes & Viollet (2022, PLOS ONE 17(11): e0276302), which scipy uses:
    the extrinsic sequence i, j, k (an intrinsic one is the reversed extrinsic one with the
    angles reversed) permutes q so that the middle angle is 2 atan2(‖(c, d)‖, ‖(a, b)‖) and the
    half sum and half difference of the other two are atan2(b, a) and atan2(d, c): no arcsin,
    no division, accurate at every angle. ``xp`` is _Arrays or _Floats (Python floats).
    """
    i, j, k = axes if extrinsic else axes[::-1]
    proper = i == k
    if proper:
        k = 3 - i - j
    sign = (i - j) * (j - k) * (k - i) // 2  # +1 for an even permutation of x, y, z
    if proper:
        a, b, c, d = w, q[i], q[j], sign * q[k]
    else:
        a, b, c, d = w - q[j], q[i] + sign * q[k], q[j] + w, sign * q[k] - q[i]
    middle = 2.0 * xp.arctan2(xp.hypot(c, d), xp.hypot(a, b))
    half_sum, half_diff = xp.arctan2(b, a), xp.arctan2(d, c)
    at_zero, at_pi = abs(middle) <= _LOCK, abs(middle - math.pi) <= _LOCK
    locked = at_zero | at_pi
    first = xp.where(at_zero, 2.0 * half_sum, 2.0 * half_diff * (-1.0 if extrinsic else 1.0))
    first = xp.where(locked, first, half_sum - half_diff)  # in the extrinsic order
    third = xp.where(locked, 0.0, half_sum + half_diff)
    if not extrinsic:  # back to the order of seq; when locked the third of seq is 0
        first, third = xp.where(locked, first, third), xp.where(locked, 0.0, first)
    if not proper:
        if extrinsic:
            third = sign * third
        else:
            first = sign * first
        middle = middle - 0.5 * math.pi
    return tuple(_wrap(angle, xp) for angle in (first, middle, third))


def _wrap(angle, xp):
    """Into [−π, π] (angles come within one turn of it)."""
    two_pi = 2.0 * math.pi
    wrapped = xp.where(angle > math.pi, angle - two_pi, angle)
    return xp.where(angle < -math.pi, angle + two_pi, wrapped) + 0.0  # + 0.0: no −0.0


def from_matrix(R, seq, tol=TOL):
    r"""The Euler angles of rotation matrices in scipy's ``seq`` convention: the inverse of
    :func:`to_matrix`.

    For the extrinsic sequence :math:`i, j, k` (an intrinsic ``seq`` is handled as the reversed
    extrinsic one, angles reversed) and the canonical quaternion
    :math:`q = (w, q_x, q_y, q_z)` of R (:func:`course_lib.quaternion.from_matrix`, Shepperd),
    proper Euler angles (:math:`k = i`, :math:`l` the third axis, :math:`\epsilon = \pm 1` the
    parity of :math:`(i, j, l)`) take :math:`(a, b, c, d) = (w, q_i, q_j, \epsilon q_l)` and
    Tait-Bryan angles :math:`(a, b, c, d) = (w - q_j,\ q_i + \epsilon q_k,\ q_j + w,\
    \epsilon q_k - q_i)`; then

    .. math:: \beta = 2\operatorname{atan2}\left(\sqrt{c^2 + d^2}, \sqrt{a^2 + b^2}\right),
        \qquad \alpha, \gamma = \operatorname{atan2}(b, a) \mp \operatorname{atan2}(d, c)

    (Bernardes & Viollet 2022, as in scipy), with :math:`\gamma` times :math:`\epsilon` and
    :math:`\beta` less :math:`\pi/2` for Tait-Bryan angles. No arcsin: accurate at every
    angle, also next to gimbal lock. At gimbal lock (see the module's notes) the third angle
    of ``seq`` is 0.

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotations, checked as by :func:`course_lib.so3.check_rotation` within ``tol``.
    seq : str
        Three letters of x, y, z, all upper case (intrinsic) or all lower case (extrinsic).
    tol : float

    Returns
    -------
    ndarray, shape (..., 3)
        Angles in the order of ``seq``: first and third in :math:`[-\pi, \pi]`, the middle in
        :math:`[0, \pi]` (proper) or :math:`[-\pi/2, \pi/2]` (Tait-Bryan).

    Raises
    ------
    ValueError
        For a bad ``seq``, or a matrix that is not a rotation.

    Examples
    --------
    Yaw, pitch and roll back from their matrix:

    >>> from_matrix(to_matrix([0.3, -0.2, 0.1], "ZYX"), "ZYX")
    array([ 0.3, -0.2,  0.1])

    Gimbal lock: pitch 90° lines up roll and yaw; the third angle is set to 0.

    >>> np.round(from_matrix(to_matrix([0.3, np.pi / 2, 0.5], "ZYX"), "ZYX"), 12)
    array([-0.2       ,  1.57079633,  0.        ])
    """
    axes, extrinsic = _parse_seq(seq)
    one = quaternion._from_matrix_single(R, tol)
    if one is not None:
        return np.array(_angles(one[0], one[1:], axes, extrinsic, _Floats))
    q = quaternion.from_matrix(R, tol)
    flat = q.reshape(-1, 4)
    out = np.empty((flat.shape[0], 3))
    for start in range(0, flat.shape[0], _CHUNK):  # chunks stay in cache: 3x faster on 10^6
        rows = np.ascontiguousarray(flat[start : start + _CHUNK].T)
        angles = _angles(rows[0], rows[1:], axes, extrinsic, _Arrays)
        out[start : start + _CHUNK] = np.stack(angles, axis=-1)
    return out.reshape(q.shape[:-1] + (3,))
