r"""Symbolic (sympy) quaternions and Euler angles, for chapter 05's derivations.

The names mirror the numeric modules: ``quaternion_multiply``, ``quaternion_to_matrix``, ...
are :func:`course_lib.quaternion.multiply`, :func:`course_lib.quaternion.to_matrix`, ... on
sympy objects, and ``euler_to_matrix`` is :func:`course_lib.euler.to_matrix`. Quaternions are
4x1 columns, scalar first :math:`(w, x, y, z)`; products are Hamilton's.

The general-case checks the chapter shows (what vanished) are computed here too:
:func:`quaternion_rodrigues_residual` (:math:`R(q)` of :math:`q = (\cos\tfrac\theta2,
\omega\sin\tfrac\theta2)` against Rodrigues' formula), :func:`quaternion_rotate`
(:math:`q\,(0, v)\,q^*` against :math:`R(q)v`) and :func:`euler_rates_matrix`, whose
determinant vanishes at gimbal lock.

Like :mod:`course_lib.symbolic`, nothing here calls ``sp.simplify``: identities reduce to zero
under ``sp.expand`` and ``sp.trigsimp`` (see :func:`course_lib.symbolic.is_zero_matrix`).
"""

import sympy as sp

from .euler import _parse_seq
from .symbolic import _as_vector3, omega, rodrigues, theta

__all__ = [
    "quaternion_symbols",
    "quaternion_multiply",
    "quaternion_conjugate",
    "quaternion_to_matrix",
    "quaternion_from_axis_angle",
    "quaternion_rotate",
    "quaternion_rodrigues_residual",
    "euler_symbols",
    "elementary_rotation",
    "euler_to_matrix",
    "euler_rates_matrix",
]


def _as_quaternion(q, what="q"):
    """The four entries of a sympy quaternion (4x1/1x4 Matrix or 4 expressions), as a list."""
    if isinstance(q, (str, bytes)):
        raise TypeError(f"{what} must be a quaternion of sympy expressions, got a string {q!r}")
    try:
        entries = list(q)
    except TypeError:
        raise TypeError(
            f"{what} must be a quaternion (a 4x1 Matrix or 4 expressions), got {type(q).__name__}"
        ) from None
    if len(entries) != 4 or (isinstance(q, sp.MatrixBase) and 1 not in q.shape):
        raise ValueError(f"{what} must be a quaternion of 4 entries (w, x, y, z), got {q!r}")
    try:
        return [sp.sympify(e, strict=True) for e in entries]
    except (sp.SympifyError, TypeError):
        raise TypeError(f"{what} must hold sympy expressions or numbers, got {q!r}") from None


def quaternion_symbols(name="q"):
    r"""A quaternion of real symbols :math:`(q_w, q_x, q_y, q_z)^T` (no unit norm assumed).

    Examples
    --------
    >>> quaternion_symbols("p").T
    Matrix([[p_w, p_x, p_y, p_z]])
    """
    if not isinstance(name, str) or not name.isidentifier():
        raise ValueError(f"name must be a valid identifier such as 'q', got {name!r}")
    return sp.Matrix(sp.symbols(f"{name}_w {name}_x {name}_y {name}_z", real=True))


def quaternion_multiply(p, q):
    r"""Hamilton's product :math:`pq`, as :func:`course_lib.quaternion.multiply`.

    .. math:: (p_w, p_v)(q_w, q_v) = (p_w q_w - p_v\cdot q_v,\
        p_w q_v + q_w p_v + p_v \times q_v)

    Examples
    --------
    >>> i, j, k = [sp.Matrix([0, *e]) for e in sp.eye(3).tolist()]
    >>> quaternion_multiply(i, j).T, quaternion_multiply(j, i).T
    (Matrix([[0, 0, 0, 1]]), Matrix([[0, 0, 0, -1]]))
    """
    pw, *pv = _as_quaternion(p, "p")
    qw, *qv = _as_quaternion(q, "q")
    pv, qv = sp.Matrix(pv), sp.Matrix(qv)
    vector = pw * qv + qw * pv + pv.cross(qv)
    return sp.Matrix([pw * qw - pv.dot(qv), *vector]).applyfunc(sp.expand)


def quaternion_conjugate(q):
    r"""The conjugate :math:`q^* = (w, -v)`.

    Examples
    --------
    >>> quaternion_conjugate(quaternion_symbols()).T
    Matrix([[q_w, -q_x, -q_y, -q_z]])
    """
    w, x, y, z = _as_quaternion(q)
    return sp.Matrix([w, -x, -y, -z])


def quaternion_to_matrix(q):
    r"""The rotation matrix of a *unit* quaternion :math:`q = (w, v)`, as
    :func:`course_lib.quaternion.to_matrix`.

    .. math:: R(q) = I + 2w\,\hat v + 2\hat v^2

    (for a quaternion that is not unit this is not a rotation; symbols cannot be checked).

    Examples
    --------
    >>> quaternion_to_matrix([sp.cos(theta / 2), 0, 0, sp.sin(theta / 2)])[0, :]
    Matrix([[1 - 2*sin(theta/2)**2, -2*sin(theta/2)*cos(theta/2), 0]])
    """
    w, x, y, z = _as_quaternion(q)
    V = sp.Matrix([[0, -z, y], [z, 0, -x], [-y, x, 0]])
    return (sp.eye(3) + 2 * w * V + 2 * V * V).applyfunc(sp.expand)


def quaternion_from_axis_angle(axis=omega, th=theta):
    r"""The quaternion :math:`(\cos\tfrac\theta2,\ \omega\sin\tfrac\theta2)` of the rotation by
    ``th`` about the unit ``axis``.

    Examples
    --------
    >>> quaternion_from_axis_angle([0, 0, 1]).T
    Matrix([[cos(theta/2), 0, 0, sin(theta/2)]])
    """
    axis = _as_vector3(axis, "axis")
    th = sp.sympify(th)
    return sp.Matrix([sp.cos(th / 2), *[sp.sin(th / 2) * a for a in axis]])


def quaternion_rotate(q, v):
    r"""The vector part of :math:`q\,(0, v)\,q^*`: for a unit :math:`q`, :math:`R(q)\,v`.

    Examples
    --------
    >>> q = quaternion_from_axis_angle([0, 0, 1], sp.pi / 2)
    >>> quaternion_rotate(q, [1, 0, 0]).T
    Matrix([[0, 1, 0]])
    """
    v = _as_vector3(v, "v")
    product = quaternion_multiply(quaternion_multiply(q, [0, *v]), quaternion_conjugate(q))
    return sp.Matrix(product[1:]).applyfunc(lambda e: sp.expand(sp.trigsimp(e)))


def quaternion_rodrigues_residual(axis=omega, th=theta):
    r""":math:`R(q) - e^{\hat\omega\theta}` for :math:`q = (\cos\tfrac\theta2,
    \omega\sin\tfrac\theta2)`, with the half angle written out: it vanishes identically (both
    are :math:`I + \sin\theta\,\hat\omega + (1 - \cos\theta)\,\hat\omega^2`; they are
    rotations when :math:`\|\omega\| = 1`).

    With :math:`\sin\theta = 2\sin\tfrac\theta2\cos\tfrac\theta2` and
    :math:`1 - \cos\theta = 2\sin^2\tfrac\theta2`,

    .. math:: R(q) = I + 2\cos\tfrac\theta2\sin\tfrac\theta2\,\hat\omega
        + 2\sin^2\tfrac\theta2\,\hat\omega^2 = I + \sin\theta\,\hat\omega
        + (1 - \cos\theta)\,\hat\omega^2 .

    Examples
    --------
    >>> from course_lib.symbolic import is_zero_matrix
    >>> is_zero_matrix(quaternion_rodrigues_residual())
    True
    """
    th = sp.sympify(th)
    half = sp.Dummy("h", real=True)
    R_q = quaternion_to_matrix(quaternion_from_axis_angle(axis, 2 * half))
    R_rodrigues = rodrigues(axis, 2 * half).applyfunc(lambda e: sp.expand(sp.expand_trig(e)))
    return (R_q - R_rodrigues).applyfunc(sp.expand).subs(half, th / 2)


def euler_symbols():
    r"""The three angles :math:`(\alpha, \beta, \gamma)` as real symbols.

    >>> euler_symbols()
    (alpha, beta, gamma)
    """
    return sp.symbols("alpha beta gamma", real=True)


def elementary_rotation(axis, angle):
    r"""The turn :math:`R_x, R_y` or :math:`R_z` by ``angle`` about a coordinate ``axis``
    (``"x"``, ``"y"`` or ``"z"``), as :func:`course_lib.so3.rot_x` etc.

    Examples
    --------
    >>> elementary_rotation("z", theta)
    Matrix([
    [cos(theta), -sin(theta), 0],
    [sin(theta),  cos(theta), 0],
    [         0,           0, 1]])
    """
    if axis not in ("x", "y", "z"):
        raise ValueError(f"axis must be 'x', 'y' or 'z', got {axis!r}")
    return rodrigues(sp.eye(3)[:, "xyz".index(axis)], angle)


def euler_to_matrix(angles=None, seq="ZYX"):
    r"""The rotation matrix of Euler angles, as :func:`course_lib.euler.to_matrix` (scipy's
    ``seq``: upper case intrinsic, lower case extrinsic).

    .. math:: \mathtt{"IJK"}:\ R_I(\alpha)R_J(\beta)R_K(\gamma), \qquad
        \mathtt{"ijk"}:\ R_k(\gamma)R_j(\beta)R_i(\alpha)

    Examples
    --------
    >>> a, b, c = euler_symbols()
    >>> euler_to_matrix((a, b, c), "ZYX") == euler_to_matrix((c, b, a), "xyz")
    True
    """
    (i, j, k), extrinsic = _parse_seq(seq)
    angles = euler_symbols() if angles is None else [sp.sympify(a) for a in angles]
    if len(angles) != 3:
        raise ValueError(f"angles must be 3 expressions, got {len(angles)}")
    turns = [elementary_rotation("xyz"[n], t) for n, t in zip((i, j, k), angles)]
    if extrinsic:
        turns.reverse()
    return (turns[0] * turns[1] * turns[2]).applyfunc(sp.expand)


def euler_rates_matrix(seq="ZYX", angles=None, frame="body"):
    r"""The matrix :math:`E` with :math:`\omega = E\,(\dot\alpha, \dot\beta, \dot\gamma)^T`:
    the angular velocity of a body whose Euler angles change at those rates.

    For the intrinsic ``"IJK"``, :math:`R = R_I(\alpha)R_J(\beta)R_K(\gamma)`; each rate turns
    the body about its axis at the moment it acts, so in body coordinates

    .. math:: \omega_b = R_K^T R_J^T e_I\,\dot\alpha + R_K^T e_J\,\dot\beta + e_K\,\dot\gamma,
        \qquad \omega_s = R\,\omega_b .

    An extrinsic ``"ijk"`` is the intrinsic ``"KJI"`` with the angles reversed. Where
    :math:`\det E = 0` (:math:`\cos\beta = 0` for Tait-Bryan, :math:`\sin\beta = 0` for proper
    Euler angles) two columns are parallel: gimbal lock, where no rates give some
    :math:`\omega`.

    Parameters
    ----------
    seq : str
    angles : 3 sympy expressions, optional
        Default :func:`euler_symbols`.
    frame : {"body", "space"}

    Examples
    --------
    >>> a, b, c = euler_symbols()
    >>> E = euler_rates_matrix("ZYX")
    >>> E
    Matrix([
    [          -sin(beta),           0, 1],
    [sin(gamma)*cos(beta),  cos(gamma), 0],
    [cos(beta)*cos(gamma), -sin(gamma), 0]])
    >>> sp.trigsimp(E.det())
    -cos(beta)
    """
    (i, j, k), extrinsic = _parse_seq(seq)
    if frame not in ("body", "space"):
        raise ValueError(f"frame must be 'body' or 'space', got {frame!r}")
    angles = list(euler_symbols() if angles is None else [sp.sympify(a) for a in angles])
    axes = [i, j, k]
    if extrinsic:  # the intrinsic sequence k, j, i with the angles reversed
        axes, angles = axes[::-1], angles[::-1]
    turns = [elementary_rotation("xyz"[n], t) for n, t in zip(axes, angles)]
    e = [sp.eye(3)[:, n] for n in axes]
    columns = [
        turns[2].T * turns[1].T * e[0],
        turns[2].T * e[1],
        e[2],
    ]
    E = sp.Matrix.hstack(*columns)
    if frame == "space":
        E = turns[0] * turns[1] * turns[2] * E
    if extrinsic:  # back to the rates in the order of seq
        E = E[:, ::-1]
    return E.applyfunc(lambda x: sp.trigsimp(sp.expand(x)))
