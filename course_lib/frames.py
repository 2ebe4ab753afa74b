r"""Reference frames and rotation matrices (notes §0.1.1 "Reference Frames", §0.1.2 "Rotation
Matrices").

A frame is stored as a 3x3 matrix whose COLUMNS are its basis vectors,

.. math:: F = \begin{bmatrix} e_1 & e_2 & e_3 \end{bmatrix},

batched over leading axes as ``(..., 3, 3)``. The course always works with orthonormal
(eqs. 1-2), right-handed (:math:`e_1 \times e_2 = e_3`) frames. In such a frame a point has
coordinates obtained by projecting its position relative to the frame's origin (eqs. 3-5), the
body axes seen in the world frame stack into the rotation matrix
:math:`R_{ab} = [x_{ab}\; y_{ab}\; z_{ab}]` (eq. 26), and the same matrix changes coordinates,
:math:`v_a = R_{ab} v_b` (eq. 64).

Every check compares a residual norm with the one tolerance of the package,
:data:`course_lib.tolerance.TOL`.
"""

import math

import numpy as np

from . import so3
from ._arrays import (
    as_matrices,
    as_vectors,
    broadcast_batch,
    frobenius_norm,
    small_floats,
    vector_norm,
)
from .tolerance import TOL, check_tol, fmt_residual, tol_label

#: Below this largest |entry| of v_b, no sum of R_ab v_b can overflow float64 (3 × 1e307).
_NO_OVERFLOW = 1e307
#: Vectors per matrix product in change_frame (see _rotate_rows).
_ROWS = 16384

__all__ = [
    "is_orthonormal",
    "is_right_handed",
    "check_frame",
    "frame_from_vectors",
    "coordinates",
    "rotation_from_axes",
    "change_frame",
]

_BASIS_NAMES = ("e1", "e2", "e3")


# --------------------------------------------------------------------------------------------
# private helpers (also used by course_lib.rigid and course_lib.groups)
# --------------------------------------------------------------------------------------------


def _as_bool(result):
    """A Python bool for a single item, a bool array for a batch."""
    return bool(result) if np.ndim(result) == 0 else np.asarray(result, dtype=bool)


def _orthonormality_residual(frame):
    """‖FᵀF − I‖_F for each frame of a (..., 3, 3) stack (inf where it overflows)."""
    with np.errstate(over="ignore", invalid="ignore"):
        gram = np.swapaxes(frame, -1, -2) @ frame
        residual = frobenius_norm(gram - np.eye(3))
    return np.where(np.isnan(residual), np.inf, residual)


def _handedness_residual(frame):
    """‖e1 × e2 − e3‖ for each frame of a (..., 3, 3) stack (inf where it overflows)."""
    with np.errstate(over="ignore", invalid="ignore"):
        cross = np.cross(frame[..., :, 0], frame[..., :, 1])
        residual = vector_norm(cross - frame[..., :, 2])
    return np.where(np.isnan(residual), np.inf, residual)


def _orthonormality_problems(e, names, tol):
    """(size, text) for each property of eqs. (1)-(2) the columns e break, largest first."""
    problems = []
    for i in range(3):
        length = float(vector_norm(e[i]))
        off = abs(length - 1.0)
        problems.append(
            (
                off * (length + 1.0),  # |‖e‖² − 1|, without squaring a huge length
                f"{names[i]} is not a unit vector: ‖{names[i]}‖ = {length:.6g} "
                f"(|‖{names[i]}‖ − 1| = {fmt_residual(off, tol)}); divide it by its length",
            )
        )
    for i, j in ((0, 1), (0, 2), (1, 2)):
        with np.errstate(over="ignore", invalid="ignore"):
            dot = float(e[i] @ e[j])
        dot = dot if math.isfinite(dot) else math.inf
        shown = f"{dot:.1e}" if math.isfinite(dot) else "beyond ±1.8e308 (overflow)"
        problems.append(
            (
                abs(dot) * math.sqrt(2.0),  # inf when the dot product overflowed
                f"{names[i]} and {names[j]} are not orthogonal: {names[i]} · {names[j]} = "
                f"{shown}; make them perpendicular (e.g. Gram-Schmidt)",
            )
        )
    problems.sort(key=lambda item: -item[0])
    return [text for size, text in problems if size > tol] or [problems[0][1]]


def _diagnose(frame, tol, names=_BASIS_NAMES):
    """Explain why one (3, 3) frame is not orthonormal and right-handed, or return None."""
    label = tol_label(tol)
    e = [frame[:, i] for i in range(3)]
    residual = float(_orthonormality_residual(frame))
    if residual > tol:
        # The decision uses the Frobenius residual (as is_orthonormal does); the details name the
        # individual properties of eqs. (1)-(2) that contribute to it, largest first.
        return (
            f"the frame is not orthonormal: ‖FᵀF − I‖ = {fmt_residual(residual, tol)} > {label} "
            f"(F = [{' '.join(names)}] as columns). "
            + "; ".join(_orthonormality_problems(e, names, tol))
            + "."
        )
    handed = float(_handedness_residual(frame))
    if handed > tol:
        a, b, c = names
        flipped = float(vector_norm(np.cross(e[0], e[1]) + e[2]))
        if flipped <= handed:
            return (
                f"the frame is left-handed: {a} × {b} = −{c} (‖{a} × {b} − {c}‖ = "
                f"{fmt_residual(handed, tol)} > {label}); negate one basis vector (e.g. use −{c}) "
                f"or swap two of them to make it right-handed."
            )
        return (
            f"the frame is not right-handed: ‖{a} × {b} − {c}‖ = {fmt_residual(handed, tol)} > "
            f"{label}; the third basis vector must be the cross product of the first two."
        )
    return None


# --------------------------------------------------------------------------------------------
# public API
# --------------------------------------------------------------------------------------------


def is_orthonormal(frame, tol=TOL):
    r"""Is the frame (basis vectors as columns) orthonormal?

    The columns :math:`e_1, e_2, e_3` are orthonormal when :math:`\|e_i\| = 1` (eq. 1) and
    :math:`e_i \cdot e_j = 0` for :math:`i \ne j` (eq. 2), i.e. when

    .. math:: \| F^\mathsf{T} F - I \|_F \le \mathrm{tol}, \qquad F = [e_1\; e_2\; e_3].

    Parameters
    ----------
    frame : array_like, shape (..., 3, 3)
        Basis vectors stored as the columns of each 3x3 matrix.
    tol : float, optional
        Absolute tolerance on the Frobenius residual, default :data:`~course_lib.tolerance.TOL`.

    Returns
    -------
    bool or ndarray of bool, shape (...)
        A Python bool for a single frame, a boolean array for a batch.

    Raises
    ------
    TypeError
        If ``frame`` is not numeric or ``tol`` is not a real number.
    ValueError
        If ``frame`` does not have shape (..., 3, 3), contains NaN/inf, or ``tol`` < 0.

    Examples
    --------
    >>> is_orthonormal(np.eye(3))
    True
    >>> is_orthonormal([[1, 1, 0], [0, 1, 0], [0, 0, 1]])   # e2 = (1, 1, 0) is not a unit vector
    False
    """
    tol = check_tol(tol)
    frame = as_matrices(frame, "frame")
    return _as_bool(_orthonormality_residual(frame) <= tol)


def is_right_handed(frame, tol=TOL):
    r"""Is the frame (basis vectors as columns) right-handed, :math:`e_1 \times e_2 = e_3`?

    This is the notes' definition taken literally,

    .. math:: \| e_1 \times e_2 - e_3 \| \le \mathrm{tol},

    so it also asks the lengths to match; for an orthonormal frame it is the same as
    :math:`\det F = +1`.

    Parameters
    ----------
    frame : array_like, shape (..., 3, 3)
        Basis vectors stored as the columns of each 3x3 matrix.
    tol : float, optional
        Absolute tolerance on the Euclidean residual, default :data:`~course_lib.tolerance.TOL`.

    Returns
    -------
    bool or ndarray of bool, shape (...)
        A Python bool for a single frame, a boolean array for a batch.

    Raises
    ------
    TypeError
        If ``frame`` is not numeric or ``tol`` is not a real number.
    ValueError
        If ``frame`` does not have shape (..., 3, 3), contains NaN/inf, or ``tol`` < 0.

    Examples
    --------
    >>> is_right_handed(np.eye(3))
    True
    >>> is_right_handed(np.diag([1.0, 1.0, -1.0]))   # e1 × e2 = −e3
    False
    """
    tol = check_tol(tol)
    frame = as_matrices(frame, "frame")
    return _as_bool(_handedness_residual(frame) <= tol)


def check_frame(frame, tol=TOL):
    r"""Return the frame if it is orthonormal and right-handed, otherwise raise a ValueError.

    The frame :math:`F = [e_1\; e_2\; e_3]` passes when

    .. math:: \| F^\mathsf{T} F - I \|_F \le \mathrm{tol}
              \quad\text{and}\quad \| e_1 \times e_2 - e_3 \| \le \mathrm{tol}.

    Parameters
    ----------
    frame : array_like, shape (..., 3, 3)
        Basis vectors stored as the columns of each 3x3 matrix.
    tol : float, optional
        Absolute tolerance, default :data:`~course_lib.tolerance.TOL`.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        The frame as a float64 array.

    Raises
    ------
    ValueError
        If a frame fails: the message names which vectors are not unit and by how much, which
        pair is not orthogonal and its dot product, or that :math:`e_1 \times e_2 = -e_3`
        (left-handed), and says how to fix it. For a batch, the first failing frame is named.
        Also for a wrong shape, NaN/inf or a negative ``tol``.
    TypeError
        If ``frame`` is not numeric.

    Examples
    --------
    >>> check_frame(np.eye(3)).shape
    (3, 3)
    >>> check_frame(np.diag([1.0, 1.0, -1.0]))
    Traceback (most recent call last):
        ...
    ValueError: the frame is left-handed: e1 × e2 = −e3 (‖e1 × e2 − e3‖ = 2.0e+00 > TOL = 1e-09);
    negate one basis vector (e.g. use −e3) or swap two of them to make it right-handed.
    """
    tol = check_tol(tol)
    frame = as_matrices(frame, "frame")
    bad = (_orthonormality_residual(frame) > tol) | (_handedness_residual(frame) > tol)
    if np.any(bad):
        index = tuple(int(i) for i in np.argwhere(bad)[0]) if frame.ndim > 2 else ()
        reason = _diagnose(frame[index], tol)
        if frame.ndim > 2:
            count = int(np.count_nonzero(bad))
            reason = f"frame{list(index)} ({count} of {bad.size} frames fail): {reason}"
        raise ValueError(reason)
    return frame


def frame_from_vectors(e1, e2, e3):
    r"""Stack three basis vectors as the columns of a frame matrix.

    .. math:: F = \begin{bmatrix} e_1 & e_2 & e_3 \end{bmatrix}

    The vectors are broadcast against each other, so a batch of frames can be built from
    batches of vectors. No orthonormality is assumed: use :func:`check_frame` for that.

    Parameters
    ----------
    e1, e2, e3 : array_like, shape (..., 3)
        The basis vectors (batches broadcast together).

    Returns
    -------
    ndarray, shape (..., 3, 3)
        The frame, with ``F[..., :, i]`` equal to the i-th vector.

    Raises
    ------
    TypeError
        If a vector is not numeric.
    ValueError
        If a vector does not have shape (..., 3), contains NaN/inf, or the batches do not
        broadcast.

    Examples
    --------
    >>> frame_from_vectors([1, 0, 0], [0, 0, 1], [0, -1, 0])
    array([[ 1.,  0.,  0.],
           [ 0.,  0., -1.],
           [ 0.,  1.,  0.]])
    """
    return _stack_columns((e1, e2, e3), _BASIS_NAMES)


def _stack_columns(vectors, names):
    """Three (..., 3) vectors as the columns of (..., 3, 3) frames; batches must broadcast."""
    vectors = [as_vectors(v, name) for v, name in zip(vectors, names)]
    batch = broadcast_batch(*((name, v, 1) for name, v in zip(names, vectors)))
    return np.stack([np.broadcast_to(v, batch + (3,)) for v in vectors], axis=-1)


def coordinates(p, frame, origin=(0, 0, 0)):
    r"""Coordinates of the point ``p`` in an orthonormal right-handed frame, by projection.

    Each coordinate is the projection, onto one basis vector, of the vector from the frame's
    origin :math:`o` to the point (eqs. 3-5):

    .. math:: p_x = (p - o) \cdot e_1, \quad p_y = (p - o) \cdot e_2, \quad p_z = (p - o) \cdot e_3,
              \qquad\text{i.e.}\quad
              \begin{bmatrix} p_x \\ p_y \\ p_z \end{bmatrix} = F^\mathsf{T} (p - o),

    so that :math:`p = o + p_x e_1 + p_y e_2 + p_z e_3`. The notes' eqs. 3-5 project
    :math:`p` itself, which is the case :math:`o = 0` (the default): right only when the frame's
    origin is the point the positions are measured from. A point cannot be dotted with a basis
    vector, only the free vector :math:`p - o` can.

    Parameters
    ----------
    p : array_like, shape (..., 3)
        The point, written in the coordinates in which the basis vectors are given.
    frame : array_like, shape (..., 3, 3)
        Basis vectors as columns; checked with :func:`check_frame`. Batches broadcast with ``p``.
    origin : array_like, shape (..., 3), default (0, 0, 0)
        The frame's origin, written in the same coordinates as ``p``. Batches broadcast with
        ``p`` and ``frame``.

    Returns
    -------
    ndarray, shape (..., 3)
        ``((p − o) · e1, (p − o) · e2, (p − o) · e3)``.

    Raises
    ------
    ValueError
        If the frame is not orthonormal and right-handed (see :func:`check_frame`), shapes are
        wrong or do not broadcast, or inputs hold NaN/inf.
    TypeError
        If an input is not numeric.

    Examples
    --------
    >>> s = 1 / np.sqrt(2)
    >>> frame = frame_from_vectors([s, s, 0], [-s, s, 0], [0, 0, 1])   # 45° about z
    >>> np.round(coordinates([1, 1, 3], frame), 6) + 0.0
    array([1.414214, 0.      , 3.      ])

    The same frame with its origin at :math:`o = (1, 1, 1)`: the point :math:`o + 2 e_1 + e_3`
    has coordinates (2, 0, 1), which projecting the point itself does not give.

    >>> o = np.array([1.0, 1.0, 1.0])
    >>> p = o + 2 * frame[:, 0] + frame[:, 2]
    >>> np.round(coordinates(p, frame, origin=o), 6) + 0.0
    array([2., 0., 1.])
    >>> np.round(coordinates(p, frame), 6) + 0.0
    array([3.414214, 0.      , 2.      ])
    """
    p = as_vectors(p, "p")
    o = as_vectors(origin, "origin")
    frame = check_frame(frame)
    broadcast_batch(("p", p, 1), ("frame", frame, 2), ("origin", o, 1))
    with np.errstate(over="ignore", invalid="ignore"):
        rel = p - o
        out = (np.swapaxes(frame, -1, -2) @ rel[..., None])[..., 0]
    if not np.isfinite(out).all():
        raise ValueError(
            "p − origin or its coordinates overflow float64 (beyond 1.8e308): the point is too "
            "far from the origin to be written in this frame"
        )
    return out


def rotation_from_axes(x_ab, y_ab, z_ab):
    r"""The rotation matrix of frame B relative to frame A from B's axes seen in A (eq. 26).

    .. math:: R_{ab} = \begin{bmatrix} x_{ab} & y_{ab} & z_{ab} \end{bmatrix}

    where :math:`x_{ab}, y_{ab}, z_{ab}` are the body axes written in world (A) coordinates.
    The result is checked with :func:`course_lib.so3.check_rotation`, so axes that are not an
    orthonormal right-handed frame raise a clear error.

    Parameters
    ----------
    x_ab, y_ab, z_ab : array_like, shape (..., 3)
        The body frame's axes in world coordinates (batches broadcast together).

    Returns
    -------
    ndarray, shape (..., 3, 3)
        :math:`R_{ab} \in SO(3)`.

    Raises
    ------
    ValueError
        If the axes do not form a rotation matrix; the message says which axis or pair fails
        (not unit, not orthogonal, left-handed) and by how much. Also for wrong shapes or NaN.
    TypeError
        If an axis is not numeric.

    Examples
    --------
    Eq. (27): B is A turned 180° about y.

    >>> rotation_from_axes([-1, 0, 0], [0, 1, 0], [0, 0, -1])
    array([[-1.,  0.,  0.],
           [ 0.,  1.,  0.],
           [ 0.,  0., -1.]])

    Eq. (28): C is A turned 45° about z.

    >>> s = 1 / np.sqrt(2)
    >>> R_ac = rotation_from_axes([s, s, 0], [-s, s, 0], [0, 0, 1])
    >>> np.round(R_ac, 4) + 0.0
    array([[ 0.7071, -0.7071,  0.    ],
           [ 0.7071,  0.7071,  0.    ],
           [ 0.    ,  0.    ,  1.    ]])
    """
    names = ("x_ab", "y_ab", "z_ab")
    R = _stack_columns((x_ab, y_ab, z_ab), names)
    try:
        return so3.check_rotation(R, name="R_ab")
    except ValueError as err:
        bad = (_orthonormality_residual(R) > TOL) | (_handedness_residual(R) > TOL)
        detail = ""
        if np.any(bad):
            index = tuple(int(i) for i in np.argwhere(bad)[0]) if R.ndim > 2 else ()
            where = f" (R_ab{list(index)})" if R.ndim > 2 else ""
            detail = f" Diagnosis{where}: {_diagnose(R[index], TOL, names)}"
        raise ValueError(
            f"the axes x_ab, y_ab, z_ab do not form a rotation matrix R_ab = [x_ab y_ab z_ab]: "
            f"{str(err).rstrip('.')}.{detail}"
        ) from err


def _change_frame_one(R_ab, v_b):
    """change_frame of one float64 rotation and one vector, on floats; None to take the batch
    path (anything else, not a rotation within TOL, or an overflow: it explains)."""
    if type(R_ab) is not np.ndarray or R_ab.shape != (3, 3) or R_ab.dtype != np.float64:
        return None
    v = small_floats(v_b, 3)
    if v is None:
        return None
    X = R_ab.ravel().tolist()
    orth2, det = so3._residual_rows(X)
    if not (orth2 <= TOL * TOL and abs(det - 1.0) <= TOL):  # NaN fails here too
        return None
    r00, r01, r02, r10, r11, r12, r20, r21, r22 = X
    v0, v1, v2 = v
    out = (r00 * v0 + r01 * v1 + r02 * v2, r10 * v0 + r11 * v1 + r12 * v2)
    out += (r20 * v0 + r21 * v1 + r22 * v2,)
    return np.array(out) if all(e - e == 0.0 for e in out) else None


def _rotate_rows(R_ab, v_b):
    """One rotation times many vectors, as matrix products of :data:`_ROWS` rows at a time: a
    product that small runs on one thread (a multi-threaded BLAS on a busy machine spends more
    CPU waiting than multiplying)."""
    flat = v_b.reshape(-1, 3)
    out = np.empty(flat.shape)
    for start in range(0, flat.shape[0], _ROWS):
        np.matmul(flat[start : start + _ROWS], R_ab.T, out=out[start : start + _ROWS])
    return out.reshape(v_b.shape)


def _product(R_ab, v_b):
    """R_ab v_b over broadcast batches."""
    if R_ab.ndim == 2:
        return _rotate_rows(R_ab, v_b)
    return (R_ab @ v_b[..., None])[..., 0]


def change_frame(R_ab, v_b):
    r"""Rewrite a vector given in frame B in frame A coordinates (eq. 64).

    .. math:: v_a = R_{ab}\, v_b = v_{bx} x_{ab} + v_{by} y_{ab} + v_{bz} z_{ab}

    Parameters
    ----------
    R_ab : array_like, shape (..., 3, 3)
        Rotation of B relative to A; checked with :func:`course_lib.so3.check_rotation`.
    v_b : array_like, shape (..., 3)
        The vector in B coordinates. Batches broadcast with ``R_ab``.

    Returns
    -------
    ndarray, shape (..., 3)
        :math:`v_a`.

    Raises
    ------
    ValueError
        If ``R_ab`` is not a rotation, shapes are wrong or do not broadcast, or inputs hold NaN.
    TypeError
        If an input is not numeric.

    Examples
    --------
    The notes' example (eqs. 65-68): :math:`v_b = (1, 1, 3)` and B turned 45° about z.

    >>> s = 1 / np.sqrt(2)
    >>> R_ab = [[s, -s, 0], [s, s, 0], [0, 0, 1]]
    >>> v_a = change_frame(R_ab, [1, 1, 3])
    >>> np.allclose(v_a, [0, np.sqrt(2), 3])
    True
    """
    one = _change_frame_one(R_ab, v_b)
    if one is not None:
        return one
    R_ab = so3.check_rotation(R_ab, name="R_ab")
    if R_ab.ndim == 2 and type(v_b) is np.ndarray and v_b.dtype == np.float64 and v_b.size:
        # one rotation, many vectors: within ±1e307 they are finite and nothing overflows
        if v_b.shape[-1] == 3 and v_b.max() < _NO_OVERFLOW and v_b.min() > -_NO_OVERFLOW:
            return _rotate_rows(R_ab, v_b)
    v_b = as_vectors(v_b, "v_b")
    broadcast_batch(("R_ab", R_ab, 2), ("v_b", v_b, 1))
    if np.abs(v_b).max(initial=0.0) < _NO_OVERFLOW:  # |(R v)_i| <= 3 max|v|: nothing overflows
        return _product(R_ab, v_b)
    with np.errstate(over="ignore", invalid="ignore"):  # numpy's matmul is slow under errstate
        v_a = _product(R_ab, v_b)
    if not np.isfinite(v_a).all():
        raise ValueError(
            "R_ab v_b overflows float64: v_b is too long (a component of v_a would exceed 1.8e308)"
        )
    return v_a
