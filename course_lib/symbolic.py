r"""Symbolic (sympy) building blocks of the rotations course.

The names mirror :mod:`course_lib.so3`: ``hat``, ``vee`` and ``rodrigues`` here take and return
sympy objects, where their numeric twins take and return numpy arrays.

What lives here
---------------
- Symbols: :data:`omega` (a 3x1 column of real symbols :math:`\omega_1, \omega_2, \omega_3`),
  :data:`theta` (a real angle :math:`\theta`), general vectors :data:`w`, :data:`v` (or any
  other, through :func:`vector`) and a general 3x3 matrix of entries :math:`r_{ij}`
  (:func:`rotation_symbols`).
- The hat map (eq. 72) and its inverse, and the cross product (eq. 69).
- The hat-map identities of section 0.1.3, *computed* rather than typed in:
  :math:`\hat\omega^2 = \omega\omega^T - \|\omega\|^2 I` (eq. 140, eq. 141 for unit
  :math:`\omega`) and :math:`\hat\omega^3 = -\|\omega\|^2 \hat\omega` (eq. 148 for unit
  :math:`\omega`), together with :func:`unit_reduce`, which compares expressions "for unit
  :math:`\omega`".
- The truncated matrix exponential (Definition 6), the coefficients of its collapse onto
  :math:`I, \hat\omega, \hat\omega^2` (eqs. 151-158) and Rodrigues' formula (eq. 159).
- Showing a result as one line of math in a notebook: :func:`show` (and :func:`tex`, its
  LaTeX text).
- Small general-case proofs used by the notebooks: the determinant as a triple product (eq. 52),
  the polarization identity (eq. 17), the six constraints of :math:`R^T R = I`
  (eqs. 111-116) with the rank of their Jacobian, and the scalar ODE
  :math:`\dot x = a x` (eqs. 95-106).

The derivations themselves (multiplying out :math:`\hat\omega^2`, the power cycle, the
regrouping of the series) are done in visible notebook cells, as the notes do them; the
functions here repeat them so that tests and notebooks can *check* a derivation against an
independent computation.

Everything avoids ``sp.simplify``: the identities here reduce to zero under ``sp.expand``
(plus ``sp.trigsimp`` when sines and cosines appear), which is fast enough for notebooks run
under a time budget.
"""

from functools import cache
from math import factorial

import numpy as np
import sympy as sp

from .tolerance import TOL, fmt_residual, tol_label

__all__ = [
    "omega",
    "theta",
    "w",
    "v",
    "vector",
    "rotation_symbols",
    "hat",
    "vee",
    "cross",
    "is_zero_matrix",
    "unit_reduce",
    "hat_squared_identity",
    "hat_cubed_identity",
    "exp_series",
    "rodrigues_coefficients",
    "rodrigues",
    "det_triple_product_identity",
    "polarization_identity",
    "so3_constraints",
    "constraint_jacobian",
    "constraint_jacobian_rank",
    "solve_scalar_ode",
    "tex",
    "show",
]


# ---------------------------------------------------------------------------------------------
# Symbols
# ---------------------------------------------------------------------------------------------


def vector(name):
    r"""A 3x1 column of real symbols :math:`(n_1, n_2, n_3)^T` for a general vector.

    The symbols are called ``name_1``, ``name_2``, ``name_3`` so that they print as
    :math:`n_{1}, n_{2}, n_{3}` in LaTeX (``vector("omega")`` prints as
    :math:`\omega_{1}, \omega_{2}, \omega_{3}`).

    Parameters
    ----------
    name : str
        Base name of the symbols, a valid Python identifier (e.g. ``"x"``, ``"omega"``).

    Returns
    -------
    sympy.ImmutableMatrix
        Shape (3, 1), entries are real ``sympy.Symbol``.

    Raises
    ------
    TypeError
        If `name` is not a string.
    ValueError
        If `name` is not a valid identifier.

    Examples
    --------
    >>> vector("x")
    Matrix([
    [x_1],
    [x_2],
    [x_3]])
    >>> vector("x")[0].is_real
    True
    """
    if not isinstance(name, str):
        raise TypeError(f"vector name must be a str, got {type(name).__name__}")
    if not name.isidentifier():
        raise ValueError(f"vector name must be a valid identifier like 'x', got {name!r}")
    return sp.ImmutableMatrix(sp.symbols(f"{name}_1:4", real=True))


def rotation_symbols(name="r"):
    r"""A general 3x3 matrix of real symbols :math:`R = [r_{ij}]` (eq. 109).

    Nothing is assumed about the entries: use it for statements about *all* 3x3 matrices
    (e.g. eq. 52) or to write out the constraints that make it a rotation (eqs. 111-116).

    Parameters
    ----------
    name : str, optional
        Base name of the entries; entry :math:`(i, j)` is called ``f"{name}_{i}{j}"`` with
        1-based indices, printed as :math:`r_{ij}`.

    Returns
    -------
    sympy.ImmutableMatrix
        Shape (3, 3), entries are real ``sympy.Symbol``.

    Raises
    ------
    TypeError
        If `name` is not a string.
    ValueError
        If `name` is not a valid identifier.

    Examples
    --------
    >>> R = rotation_symbols()
    >>> R[0, 1], R.shape
    (r_12, (3, 3))
    """
    if not isinstance(name, str):
        raise TypeError(f"matrix name must be a str, got {type(name).__name__}")
    if not name.isidentifier():
        raise ValueError(f"matrix name must be a valid identifier like 'r', got {name!r}")
    return sp.ImmutableMatrix(3, 3, lambda i, j: sp.Symbol(f"{name}_{i + 1}{j + 1}", real=True))


#: The angular-velocity / rotation-axis vector :math:`\omega = (\omega_1, \omega_2, \omega_3)^T`,
#: a 3x1 column of real symbols (eq. 120, eq. 128).
omega = vector("omega")
#: The rotation angle :math:`\theta`, a real symbol.
theta = sp.Symbol("theta", real=True)
#: A general vector :math:`w = (w_1, w_2, w_3)^T` of real symbols.
w = vector("w")
#: A general vector :math:`v = (v_1, v_2, v_3)^T` of real symbols.
v = vector("v")

# Symbols of the exercises (course_lib.exercises re-exports them). The matrix symbols stand for a
# whole matrix, so that an exercise can ask for an answer *in terms of* that matrix.
#: General vectors :math:`x, y, z` of real symbols (3x1 columns).
x, y, z = vector("x"), vector("y"), vector("z")
#: Real scalars: time :math:`t`, rate :math:`a`, initial value :math:`x_0`, angles.
t, a, x_0 = sp.symbols("t a x_0", real=True)
alpha, beta, phi = sp.symbols("alpha beta phi", real=True)
#: Stand-ins for :math:`x^T x`, :math:`y^T y`, :math:`x^T y` (an answer in these three numbers).
xx, yy, xy = sp.symbols("x·x y·y x·y", real=True)
#: Matrix symbols: ``W`` for :math:`\hat\omega`, ``u`` for :math:`\omega` as a 3x1 column,
#: ``X``, ``Y`` for :math:`x, y`, rotations ``A``, ``B``, ``R`` and a translation ``d``.
W = sp.MatrixSymbol("W", 3, 3)
u, X, Y, d = (sp.MatrixSymbol(n, 3, 1) for n in ("u", "X", "Y", "d"))
A, B, R = (sp.MatrixSymbol(n, 3, 3) for n in ("A", "B", "R"))
__all__ += [
    "x",
    "y",
    "z",
    "t",
    "a",
    "x_0",
    "alpha",
    "beta",
    "phi",
    "xx",
    "yy",
    "xy",
    "W",
    "u",
    "X",
    "Y",
    "d",
    "A",
    "B",
    "R",
]


# ---------------------------------------------------------------------------------------------
# Input handling
# ---------------------------------------------------------------------------------------------


def _as_vector3(a, what="a"):
    """Return the three entries of a sympy 3-vector as a list of sympy expressions."""
    if isinstance(a, (str, bytes)):
        raise TypeError(f"{what} must be a 3-vector of sympy expressions, got a string {a!r}")
    if isinstance(a, sp.MatrixBase):
        if a.shape not in ((3, 1), (1, 3)):
            raise ValueError(
                f"{what} must be a 3-vector (a 3x1 or 1x3 Matrix), got a Matrix of shape {a.shape}"
            )
        entries = list(a)
    elif isinstance(a, np.ndarray):
        if a.shape not in ((3,), (3, 1), (1, 3)):
            raise ValueError(f"{what} must be a 3-vector, got an array of shape {a.shape}")
        entries = list(a.reshape(-1))
    else:
        try:
            entries = list(a)
        except TypeError:
            raise TypeError(
                f"{what} must be a 3-vector (a 3x1/1x3 Matrix or a list of 3 expressions), "
                f"got {type(a).__name__}"
            ) from None
        if len(entries) != 3:
            raise ValueError(f"{what} must be a 3-vector (3 entries), got {len(entries)} entries")
    out = []
    for k, x in enumerate(entries):
        try:
            e = sp.sympify(x, strict=True)
        except (sp.SympifyError, TypeError):
            raise TypeError(
                f"{what}[{k}] must be a scalar sympy expression or number, got {x!r}"
            ) from None
        if not isinstance(e, sp.Expr) or isinstance(e, sp.MatrixBase):
            raise TypeError(f"{what}[{k}] must be a scalar expression, got {type(e).__name__}")
        out.append(e)
    return out


def _as_matrix(A, what="A", shape=None):
    """Return `A` as a sympy Matrix, checking it is square (or of the given shape)."""
    if isinstance(A, (str, bytes)):
        raise TypeError(f"{what} must be a sympy Matrix, got a string {A!r}")
    if not isinstance(A, sp.MatrixBase):
        try:
            A = sp.Matrix(A)
        except (TypeError, ValueError, sp.SympifyError) as exc:
            raise TypeError(
                f"{what} must be a sympy Matrix or a nested list, got {type(A).__name__}"
            ) from exc
    if shape is not None and A.shape != shape:
        raise ValueError(f"{what} must have shape {shape}, got shape {A.shape}")
    if A.rows != A.cols:
        raise ValueError(f"{what} must be square, got shape {A.shape}")
    return A


def _as_order(order):
    """Check a truncation order: a non-negative Python or sympy integer."""
    if isinstance(order, bool) or not isinstance(order, (int, np.integer, sp.Integer)):
        raise TypeError(f"order must be a non-negative integer, got {order!r}")
    order = int(order)
    if order < 0:
        raise ValueError(f"order must be a non-negative integer, got {order}")
    return order


def _is_zero_expr(e):
    """Decide whether a scalar expression is identically zero, without ``sp.simplify``."""
    e = sp.expand(e)
    if e == 0:
        return True
    if e.has(sp.sin, sp.cos, sp.tan):
        e = sp.expand(sp.trigsimp(e))
    return e == 0


# ---------------------------------------------------------------------------------------------
# Hat map, vee map, cross product
# ---------------------------------------------------------------------------------------------


def hat(a):
    r"""The hat map :math:`\wedge: \mathbb{R}^3 \to so(3)` (Definition 5, eq. 72).

    .. math::

        \hat a = \begin{bmatrix} 0 & -a_3 & a_2 \\ a_3 & 0 & -a_1 \\ -a_2 & a_1 & 0
        \end{bmatrix}, \qquad \hat a\, b = a \times b \quad \text{(eq. 73)}.

    Parameters
    ----------
    a : sympy Matrix of shape (3, 1) or (1, 3), or a sequence of 3 expressions
        The vector; entries may be symbols, numbers or any scalar expressions.

    Returns
    -------
    sympy.Matrix
        The 3x3 skew-symmetric matrix :math:`\hat a`.

    Raises
    ------
    ValueError
        If `a` does not have exactly 3 entries (e.g. a 2-vector or a 3x3 matrix).
    TypeError
        If `a` is not a sequence/Matrix, or an entry is not a scalar expression.

    Examples
    --------
    >>> hat(omega)
    Matrix([
    [       0, -omega_3,  omega_2],
    [ omega_3,        0, -omega_1],
    [-omega_2,  omega_1,        0]])
    >>> hat([1, 2, 3]) * sp.Matrix([4, 5, 6]) == cross([1, 2, 3], [4, 5, 6])
    True
    """
    a1, a2, a3 = _as_vector3(a, "a")
    return sp.Matrix([[0, -a3, a2], [a3, 0, -a1], [-a2, a1, 0]])


def vee(W):
    r"""The vee map :math:`\vee: so(3) \to \mathbb{R}^3`, inverse of :func:`hat`.

    .. math::

        \begin{bmatrix} 0 & -a_3 & a_2 \\ a_3 & 0 & -a_1 \\ -a_2 & a_1 & 0
        \end{bmatrix}^\vee = \begin{bmatrix} a_1 \\ a_2 \\ a_3 \end{bmatrix},
        \qquad \text{defined only when } W^T = -W \text{ (eq. 130)}.

    Parameters
    ----------
    W : sympy Matrix (or nested list) of shape (3, 3)
        A skew-symmetric matrix.

    Returns
    -------
    sympy.Matrix
        The 3x1 column :math:`(W_{32}, W_{13}, W_{21})^T`.

    Raises
    ------
    ValueError
        If `W` is not 3x3, or is not skew-symmetric (:math:`W + W^T` does not expand to
        zero); the message names the offending entries.
    TypeError
        If `W` cannot be read as a matrix.

    Examples
    --------
    >>> vee(hat(omega)).T
    Matrix([[omega_1, omega_2, omega_3]])
    >>> vee(sp.eye(3))
    Traceback (most recent call last):
    ...
    ValueError: W is not skew-symmetric: W + Wᵀ ≠ 0, entry (0, 0) of W + Wᵀ is 2 (expected 0)
    """
    W = _as_matrix(W, "W", shape=(3, 3))
    S = W + W.T
    for i in range(3):
        for j in range(i, 3):
            if not _is_zero_expr(S[i, j]):
                raise ValueError(
                    f"W is not skew-symmetric: W + Wᵀ ≠ 0, entry ({i}, {j}) of W + Wᵀ "
                    f"is {sp.expand(S[i, j])} (expected 0)"
                )
    return sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])


def cross(a, b):
    r"""Cross product of two 3-vectors, written out componentwise (eq. 69).

    .. math::

        a \times b = \begin{bmatrix} a_2 b_3 - a_3 b_2 \\ a_3 b_1 - a_1 b_3 \\
        a_1 b_2 - a_2 b_1 \end{bmatrix}

    It is deliberately *not* computed as :math:`\hat a b`, so that eq. 73
    (:math:`a \times b = \hat a b`) is something one can check.

    Parameters
    ----------
    a, b : sympy Matrix of shape (3, 1) or (1, 3), or sequences of 3 expressions

    Returns
    -------
    sympy.Matrix
        The 3x1 column :math:`a \times b`.

    Raises
    ------
    ValueError, TypeError
        As for :func:`hat`, if either argument is not a 3-vector.

    Examples
    --------
    >>> cross([1, 0, 0], [0, 1, 0]).T
    Matrix([[0, 0, 1]])
    >>> is_zero_matrix(cross(w, v) - hat(w) * v)
    True
    """
    a1, a2, a3 = _as_vector3(a, "a")
    b1, b2, b3 = _as_vector3(b, "b")
    return sp.Matrix([a2 * b3 - a3 * b2, a3 * b1 - a1 * b3, a1 * b2 - a2 * b1])


# ---------------------------------------------------------------------------------------------
# Deciding equality: general and "for unit omega"
# ---------------------------------------------------------------------------------------------


def is_zero_matrix(M, unit=False, w=omega):
    r"""Decide whether every entry of a symbolic matrix (or a scalar) is identically zero.

    Each entry is expanded (and, if it contains sines or cosines, passed through
    ``sp.trigsimp``); with ``unit=True`` it is first reduced modulo
    :math:`w_1^2 + w_2^2 + w_3^2 = 1` by :func:`unit_reduce`, so the answer means
    ":math:`M = 0` for every unit vector :math:`w`".

    .. math::

        M = 0 \iff \operatorname{expand}(M_{ij}) = 0 \ \ \forall i, j

    Parameters
    ----------
    M : sympy Matrix, nested list, or scalar expression
    unit : bool, optional
        If True, impose :math:`\|w\| = 1` before deciding.
    w : 3-vector of symbols, optional
        The vector whose norm is constrained when ``unit=True`` (default :data:`omega`).

    Returns
    -------
    bool

    Raises
    ------
    ValueError
        From :func:`unit_reduce`, if ``unit=True`` and an entry is not polynomial in `w`.

    Examples
    --------
    >>> is_zero_matrix(hat(omega).T + hat(omega))
    True
    >>> is_zero_matrix(sp.sin(theta)**2 + sp.cos(theta)**2 - 1)
    True
    >>> is_zero_matrix(omega.T * omega - sp.Matrix([1]), unit=True)
    True
    """
    if isinstance(M, sp.MatrixBase):
        entries = list(M)
    elif isinstance(M, (list, tuple)):
        entries = list(sp.Matrix(M))
    else:
        entries = [sp.sympify(M)]
    for e in entries:
        if unit:
            e = unit_reduce(e, w)
        if not _is_zero_expr(e):
            return False
    return True


def _multinomial_one_minus_squares(m):
    """Expansion of (1 - x**2 - y**2)**m as {(x_power, y_power): integer coefficient}."""
    out = {}
    for b in range(m + 1):
        for c in range(m + 1 - b):
            a = m - b - c
            coeff = factorial(m) // (factorial(a) * factorial(b) * factorial(c))
            out[(2 * b, 2 * c)] = (-1) ** (b + c) * coeff
    return out


def _reduce_poly(expr, gens):
    """Normal form of a polynomial in gens modulo g1**2 + g2**2 + g3**2 - 1 (g3 eliminated)."""
    g1, g2, g3 = gens
    poly = sp.Poly(expr, *gens)
    acc = {}
    for (i, j, k), c in poly.terms():
        m, r = divmod(k, 2)
        for (di, dj), n in _multinomial_one_minus_squares(m).items():
            key = (i + di, j + dj, r)
            acc[key] = acc.get(key, 0) + n * c
    result = sp.Integer(0)
    for (i, j, r), c in acc.items():
        c = sp.expand(c)
        if c != 0 and c.has(sp.sin, sp.cos, sp.tan):
            c = sp.expand(sp.trigsimp(c))
        if c != 0:
            result += c * g1**i * g2**j * g3**r
    return result


def unit_reduce(expr, w=omega):
    r"""Rewrite an expression using the unit constraint :math:`w_1^2 + w_2^2 + w_3^2 = 1`.

    Every power :math:`w_3^k` with :math:`k \ge 2` is replaced through

    .. math::

        w_3^{2m + r} = (1 - w_1^2 - w_2^2)^m \, w_3^r, \qquad r \in \{0, 1\},

    and the coefficients are collected. The result is the unique normal form
    :math:`p_0(w_1, w_2) + w_3\, p_1(w_1, w_2)` of the expression modulo the unit sphere, so a
    polynomial in :math:`w` that vanishes on the unit sphere is turned into exactly ``0``. The
    coefficients may be any expressions free of :math:`w` (e.g. in :math:`\theta`,
    :math:`\sin\theta`, :math:`\cos\theta`); they are expanded, and trigonometric ones are
    trig-simplified. Any literal :math:`w_1^2 + w_2^2 + w_3^2` (also inside a square root) is
    first replaced by 1; rational functions of :math:`w` are reduced in numerator and
    denominator. Matrices are reduced entry by entry.

    Parameters
    ----------
    expr : sympy expression or Matrix
        Polynomial (or rational function) in the entries of `w`.
    w : 3-vector of symbols, optional
        The unit vector (default :data:`omega`).

    Returns
    -------
    sympy expression or sympy.Matrix
        The reduced expression (a Matrix of reduced entries for a Matrix input).

    Raises
    ------
    ValueError
        If the expression is not a rational function of the entries of `w` (e.g.
        :math:`\sin\omega_1`), or `w` does not consist of three distinct symbols.

    Examples
    --------
    >>> unit_reduce(omega[0]**2 + omega[1]**2 + omega[2]**2)
    1
    >>> unit_reduce(sp.sin(theta) * (omega.T * omega)[0] - sp.sin(theta))
    0
    >>> unit_reduce(omega[2]**3)
    -omega_1**2*omega_3 - omega_2**2*omega_3 + omega_3
    """
    gens = _as_vector3(w, "w")
    if not all(isinstance(g, sp.Symbol) for g in gens) or len(set(gens)) != 3:
        raise ValueError(f"w must consist of three distinct symbols, got {gens}")
    if isinstance(expr, sp.MatrixBase):
        return sp.Matrix(expr.shape[0], expr.shape[1], [unit_reduce(e, gens) for e in expr])
    expr = sp.sympify(expr)
    if isinstance(expr, (list, tuple)):
        return sp.Matrix(expr).applyfunc(lambda e: unit_reduce(e, gens))
    g1, g2, g3 = gens
    expr = expr.xreplace({g1**2 + g2**2 + g3**2: sp.Integer(1)})
    expanded = sp.expand(expr)
    try:
        return _reduce_poly(expanded, gens)
    except sp.PolynomialError:
        pass
    num, den = sp.fraction(sp.cancel(sp.together(expanded)))
    try:
        num_r = _reduce_poly(sp.expand(num), gens)
        den_r = _reduce_poly(sp.expand(den), gens)
    except sp.PolynomialError:
        raise ValueError(
            f"unit_reduce needs a polynomial (or rational function) in {g1}, {g2}, {g3}; got {expr}"
        ) from None
    if den_r == 0:
        raise ValueError(f"the denominator of {expr} vanishes on the unit sphere")
    return num_r / den_r


# ---------------------------------------------------------------------------------------------
# Hat-map identities (eqs. 136-150)
# ---------------------------------------------------------------------------------------------


def _norm_squared(a):
    a1, a2, a3 = a
    return a1**2 + a2**2 + a3**2


@cache
def _hat_power_identity(wt, power, unit):
    wcol = sp.Matrix(wt)
    W = hat(wcol)
    lhs = (W**power).applyfunc(sp.expand)
    n2 = 1 if unit else _norm_squared(wt)
    if power == 2:
        rhs = wcol * wcol.T - n2 * sp.eye(3)
    else:
        rhs = -n2 * W
    diff = lhs - rhs
    if not is_zero_matrix(diff, unit=unit, w=wcol):  # pragma: no cover - the maths is right
        raise RuntimeError(f"hat power identity failed for power {power}, unit={unit}")
    return sp.ImmutableMatrix(lhs), sp.ImmutableMatrix(rhs)


def hat_squared_identity(a=omega, unit=False):
    r"""Compute :math:`\hat a^2` and the closed form it equals (eqs. 136-141).

    .. math::

        \hat a^2 = a a^T - \|a\|^2 I \quad \text{(eq. 140)}, \qquad
        \hat a^2 = a a^T - I \ \text{ if } \|a\| = 1 \quad \text{(eq. 141)}.

    The left-hand side is the matrix product ``hat(a)**2`` with entries expanded (eq. 137); the
    function checks that it equals the right-hand side (exactly, or modulo
    :math:`\|a\| = 1` through :func:`unit_reduce` when ``unit=True``) before returning both.

    Parameters
    ----------
    a : 3-vector of symbols, optional
        Default :data:`omega`. With ``unit=True`` its entries must be symbols.
    unit : bool, optional
        Use the unit-vector form (eq. 141).

    Returns
    -------
    (lhs, rhs) : tuple of sympy.Matrix
        ``lhs`` = :math:`\hat a^2` computed by multiplication, ``rhs`` the closed form.

    Raises
    ------
    ValueError, TypeError
        If `a` is not a 3-vector (see :func:`hat`).

    Examples
    --------
    >>> lhs, rhs = hat_squared_identity()
    >>> lhs[0, 0]
    -omega_2**2 - omega_3**2
    >>> is_zero_matrix(lhs - rhs)
    True
    >>> lhs, rhs = hat_squared_identity(unit=True)
    >>> rhs[0, 0], is_zero_matrix(lhs - rhs, unit=True), is_zero_matrix(lhs - rhs)
    (omega_1**2 - 1, True, False)
    """
    lhs, rhs = _hat_power_identity(tuple(_as_vector3(a, "a")), 2, bool(unit))
    return sp.Matrix(lhs), sp.Matrix(rhs)


def hat_cubed_identity(a=omega, unit=False):
    r"""Compute :math:`\hat a^3` and the closed form it equals (eqs. 142-148).

    .. math::

        \hat a^3 = -\|a\|^2 \hat a, \qquad \hat a^3 = -\hat a \ \text{ if } \|a\| = 1
        \quad \text{(eq. 148)}.

    The left-hand side is ``hat(a)**3`` with entries expanded; the function checks that it
    equals the right-hand side (modulo :math:`\|a\| = 1` when ``unit=True``) before returning.

    Parameters
    ----------
    a : 3-vector of symbols, optional
        Default :data:`omega`.
    unit : bool, optional
        Use the unit-vector form.

    Returns
    -------
    (lhs, rhs) : tuple of sympy.Matrix

    Raises
    ------
    ValueError, TypeError
        If `a` is not a 3-vector (see :func:`hat`).

    Examples
    --------
    >>> lhs, rhs = hat_cubed_identity(unit=True)
    >>> rhs == -hat(omega), is_zero_matrix(lhs - rhs, unit=True)
    (True, True)
    >>> lhs, rhs = hat_cubed_identity()
    >>> is_zero_matrix(lhs - rhs)
    True
    """
    lhs, rhs = _hat_power_identity(tuple(_as_vector3(a, "a")), 3, bool(unit))
    return sp.Matrix(lhs), sp.Matrix(rhs)


# ---------------------------------------------------------------------------------------------
# Matrix exponential and Rodrigues' formula (Definition 6, eqs. 124-159)
# ---------------------------------------------------------------------------------------------


def exp_series(A, terms):
    r"""Truncated Taylor series of the matrix exponential (Definition 6, eq. 124).

    The symbolic twin of :func:`course_lib.so3.exp_series`, with the same meaning of ``terms``:

    .. math::

        e^A \approx \sum_{n=0}^{N-1} \frac{A^n}{n!} = I + A + \frac{A^2}{2!} + \dots
        + \frac{A^{N-1}}{(N-1)!}, \qquad A^0 = I, \quad N = \text{terms}.

    Parameters
    ----------
    A : sympy Matrix (or nested list), square
    terms : int
        Number of terms kept, :math:`N \ge 1` (``terms=1`` gives :math:`I`).

    Returns
    -------
    sympy.Matrix
        The partial sum, entries expanded.

    Raises
    ------
    ValueError
        If `A` is not square or `terms` < 1.
    TypeError
        If `terms` is not an integer or `A` is not a matrix.

    Examples
    --------
    >>> exp_series(sp.Matrix([[0, 1], [0, 0]]), 6)
    Matrix([
    [1, 1],
    [0, 1]])
    >>> a = sp.Symbol("a")
    >>> exp_series(sp.Matrix([[a]]), 4)
    Matrix([[a**3/6 + a**2/2 + a + 1]])
    """
    A = _as_matrix(A, "A")
    if isinstance(terms, bool) or not isinstance(terms, (int, np.integer, sp.Integer)):
        raise TypeError(f"terms must be an integer >= 1, got {terms!r}")
    if int(terms) < 1:
        raise ValueError(f"terms must be an integer >= 1, got {terms}")
    term = sp.eye(A.rows)
    total = sp.eye(A.rows)
    for n in range(1, int(terms)):
        term = (term * A / n).applyfunc(sp.expand)
        total += term
    return total.applyfunc(sp.expand)


@cache
def _rodrigues_coefficients(order, th):
    # Coefficients (c0, c1, c2) of hat(w)**n in the basis I, hat(w), hat(w)**2 for unit w.
    # Multiplying by hat(w): c0 I + c1 W + c2 W**2 -> c0 W + c1 W**2 + c2 W**3, W**3 = -W.
    c = (sp.Integer(1), sp.Integer(0), sp.Integer(0))
    acc = [sp.Integer(0)] * 3
    for n in range(order + 1):
        if n > 0:
            c = (sp.Integer(0), c[0] - c[2], c[1])
        weight = th**n / sp.factorial(n)
        acc = [acc[k] + c[k] * weight for k in range(3)]
    identity_coeff, a, b = (sp.expand(x) for x in acc)
    if identity_coeff != 1:  # pragma: no cover - only the n = 0 term contributes to I
        raise RuntimeError(f"coefficient of I is {identity_coeff}, expected 1")
    return a, b


def rodrigues_coefficients(order, th=theta):
    r"""Collapse the truncated series of :math:`e^{\hat\omega\theta}` onto :math:`I, \hat\omega,
    \hat\omega^2` for unit :math:`\omega` (eqs. 151-158).

    Powers of :math:`\hat\omega` are tracked as coefficient triples in the basis
    :math:`(I, \hat\omega, \hat\omega^2)` through the recursion
    :math:`\hat\omega^{n+1} = \hat\omega^n \hat\omega` with :math:`\hat\omega^3 = -\hat\omega`
    (eq. 148); no 3x3 matrix is multiplied. Summing :math:`(\hat\omega\theta)^n / n!` gives

    .. math::

        \sum_{n=0}^{N} \frac{(\hat\omega\theta)^n}{n!} = I + a_N(\theta)\,\hat\omega
        + b_N(\theta)\,\hat\omega^2,

    where :math:`a_N` and :math:`b_N` turn out to be the degree-:math:`N` Taylor polynomials of
    :math:`\sin\theta` and :math:`1 - \cos\theta` (eq. 158), which is how eq. 159 arises.

    Parameters
    ----------
    order : int
        The highest power :math:`N \ge 0` kept.
    th : sympy expression, optional
        The angle (default :data:`theta`).

    Returns
    -------
    (a, b) : tuple of sympy expressions
        Polynomials in `th`: the coefficients of :math:`\hat\omega` and :math:`\hat\omega^2`.

    Raises
    ------
    ValueError
        If `order` is negative.
    TypeError
        If `order` is not an integer.

    Examples
    --------
    >>> rodrigues_coefficients(5)
    (theta**5/120 - theta**3/6 + theta, -theta**4/24 + theta**2/2)
    >>> rodrigues_coefficients(0)
    (0, 0)
    """
    return _rodrigues_coefficients(_as_order(order), sp.sympify(th))


def rodrigues(a=omega, th=theta):
    r"""Rodrigues' formula (eq. 159), the closed form of :math:`e^{\hat\omega\theta}`.

    .. math::

        e^{\hat\omega\theta} = I + \sin\theta\,\hat\omega + (1 - \cos\theta)\,\hat\omega^2,
        \qquad \|\omega\| = 1.

    The formula is only a rotation by `th` about `a` when `a` is a unit vector; it is returned
    for whatever `a` is passed (symbols cannot be checked for unit length).

    Parameters
    ----------
    a : 3-vector, optional
        The unit rotation axis (default :data:`omega`).
    th : sympy expression, optional
        The angle (default :data:`theta`).

    Returns
    -------
    sympy.Matrix
        The 3x3 matrix, entries expanded.

    Raises
    ------
    ValueError, TypeError
        If `a` is not a 3-vector (see :func:`hat`).

    Examples
    --------
    >>> rodrigues([0, 0, 1])
    Matrix([
    [cos(theta), -sin(theta), 0],
    [sin(theta),  cos(theta), 0],
    [         0,           0, 1]])
    >>> rodrigues([1, 0, 0], sp.pi / 2)
    Matrix([
    [1, 0,  0],
    [0, 0, -1],
    [0, 1,  0]])
    """
    W = hat(a)
    th = sp.sympify(th)
    R = sp.eye(3) + sp.sin(th) * W + (1 - sp.cos(th)) * W**2
    return R.applyfunc(sp.expand)


# ---------------------------------------------------------------------------------------------
# General-case identities for the notebooks' proofs
# ---------------------------------------------------------------------------------------------


def det_triple_product_identity(R=None):
    r"""The determinant of a 3x3 matrix as a scalar triple product of its columns (eq. 52).

    .. math::

        \det R = r_{11}(r_{22}r_{33} - r_{23}r_{32}) - r_{12}(r_{21}r_{33} - r_{23}r_{31})
        + r_{13}(r_{21}r_{32} - r_{22}r_{31}) = r_1^T (r_2 \times r_3),

    with :math:`r_1, r_2, r_3` the columns of :math:`R` (eq. 29). Holds for *every* 3x3
    matrix, so it is shown for a matrix of free symbols.

    Parameters
    ----------
    R : sympy Matrix (3, 3), optional
        Default :func:`rotation_symbols` ``()``.

    Returns
    -------
    (lhs, rhs) : tuple of sympy expressions
        ``lhs`` = :math:`\det R` by cofactor expansion (eqs. 49-51), ``rhs`` =
        :math:`r_1 \cdot (r_2 \times r_3)`, both expanded.

    Raises
    ------
    ValueError
        If `R` is not 3x3.

    Examples
    --------
    >>> lhs, rhs = det_triple_product_identity()
    >>> sp.expand(lhs - rhs)
    0
    >>> len(sp.Add.make_args(lhs))
    6
    """
    R = rotation_symbols() if R is None else _as_matrix(R, "R", shape=(3, 3))
    lhs = sp.expand(R.det(method="berkowitz"))
    r1, r2, r3 = R[:, 0], R[:, 1], R[:, 2]
    rhs = sp.expand((r1.T * cross(r2, r3))[0, 0])
    return lhs, rhs


def polarization_identity(x=None, y=None):
    r"""The polarization identity (eq. 17): inner products from norms.

    .. math::

        x^T y = \tfrac14 \left( \|x + y\|^2 - \|x - y\|^2 \right),
        \qquad \|u\|^2 = u^T u.

    Parameters
    ----------
    x, y : 3-vectors, optional
        Default :data:`w` and :data:`v` (general vectors of symbols).

    Returns
    -------
    (lhs, rhs) : tuple of sympy expressions
        :math:`x^T y` and the right-hand side, both expanded.

    Raises
    ------
    ValueError, TypeError
        If `x` or `y` is not a 3-vector.

    Examples
    --------
    >>> lhs, rhs = polarization_identity()
    >>> lhs
    v_1*w_1 + v_2*w_2 + v_3*w_3
    >>> sp.expand(lhs - rhs)
    0
    """
    x = sp.Matrix(_as_vector3(w if x is None else x, "x"))
    y = sp.Matrix(_as_vector3(v if y is None else y, "y"))
    lhs = sp.expand((x.T * y)[0, 0])
    s, d = x + y, x - y
    rhs = sp.expand(sp.Rational(1, 4) * ((s.T * s)[0, 0] - (d.T * d)[0, 0]))
    return lhs, rhs


# Entries of R^T R - I in the order of eqs. (111)-(116): three orthogonality, three unit norms.
_CONSTRAINT_ENTRIES = ((0, 1), (0, 2), (1, 2), (0, 0), (1, 1), (2, 2))


def so3_constraints(R=None):
    r"""The six polynomial constraints :math:`R^T R = I` imposes on a 3x3 matrix (eqs. 111-116).

    They are read off the upper triangle of :math:`R^T R - I` (symmetric, so the lower triangle
    repeats them), each as an expression that must equal zero:

    .. math::

        r_1^T r_2 = r_1^T r_3 = r_2^T r_3 = 0, \qquad
        r_1^T r_1 - 1 = r_2^T r_2 - 1 = r_3^T r_3 - 1 = 0.

    Parameters
    ----------
    R : sympy Matrix (3, 3), optional
        Default :func:`rotation_symbols` ``()``.

    Returns
    -------
    list of 6 sympy expressions
        In the order of eqs. (111), (112), (113), (114), (115), (116).

    Raises
    ------
    ValueError
        If `R` is not 3x3.

    Examples
    --------
    >>> c = so3_constraints()
    >>> c[0]
    r_11*r_12 + r_21*r_22 + r_31*r_32
    >>> c[3]
    r_11**2 + r_21**2 + r_31**2 - 1
    """
    R = rotation_symbols() if R is None else _as_matrix(R, "R", shape=(3, 3))
    G = R.T * R - sp.eye(3)
    return [sp.expand(G[i, j]) for i, j in _CONSTRAINT_ENTRIES]


@cache
def _constraint_jacobian():
    R = rotation_symbols()
    return sp.ImmutableMatrix(sp.Matrix(so3_constraints(R)).jacobian(list(R)))


def constraint_jacobian():
    r"""Jacobian of the six constraints (eqs. 111-116) with respect to the nine entries.

    .. math::

        J_{k, (i,j)} = \frac{\partial f_k}{\partial r_{ij}}, \qquad
        f = (f_1, \dots, f_6) \text{ from } R^T R - I,

    with the columns ordered row by row: :math:`r_{11}, r_{12}, r_{13}, r_{21}, \dots, r_{33}`.

    Returns
    -------
    sympy.Matrix
        Shape (6, 9), entries linear in the :math:`r_{ij}`.

    Examples
    --------
    >>> J = constraint_jacobian()
    >>> J.shape, J[3, 0]
    ((6, 9), 2*r_11)
    """
    return sp.Matrix(_constraint_jacobian())


def constraint_jacobian_rank(point=None, tol=TOL):
    r"""Rank of the constraint Jacobian at a point of SO(3); :math:`\dim SO(3) = 9 - \text{rank}`.

    Six independent constraints (rank 6) cut the 9-dimensional space of 3x3 matrices down to a
    :math:`9 - 6 = 3`-dimensional set, the three parameters of exponential coordinates.

    .. math::

        \operatorname{rank} J(R_0), \qquad
        J = \frac{\partial (f_1, \dots, f_6)}{\partial (r_{11}, \dots, r_{33})}.

    Exact points (integers, rationals, radicals, e.g. the default :math:`I`) are ranked exactly
    by sympy; floating-point points are ranked by singular values larger than `tol`.

    Parameters
    ----------
    point : 3x3 array-like or sympy Matrix, optional
        Where to evaluate; default the identity. It must satisfy the constraints:
        :math:`\|R_0^T R_0 - I\|_F \le` `tol`.
    tol : float, optional
        Tolerance for the constraint check and the numeric rank (default ``TOL``).

    Returns
    -------
    int
        The rank (6 at every point of SO(3)).

    Raises
    ------
    ValueError
        If `point` is not 3x3, or does not satisfy the constraints (the message gives
        :math:`\|R_0^T R_0 - I\|_F`).
    TypeError
        If `point` cannot be read as a matrix of numbers.

    Examples
    --------
    >>> constraint_jacobian_rank()
    6
    >>> 9 - constraint_jacobian_rank(rodrigues([0, 0, 1], sp.pi / 3))
    3
    """
    P = sp.eye(3) if point is None else _as_matrix(sp.Matrix(point), "point", shape=(3, 3))
    if P.free_symbols:
        raise TypeError(f"point must be a matrix of numbers, got symbols {P.free_symbols}")
    try:
        Pn = np.array(P.evalf(), dtype=np.float64)
    except TypeError as exc:
        raise TypeError("point must be a matrix of real numbers") from exc
    residual = float(np.linalg.norm(Pn.T @ Pn - np.eye(3)))
    if not residual <= tol:
        raise ValueError(
            f"point is not orthogonal: ‖RᵀR − I‖ = {fmt_residual(residual, tol)} > "
            f"{tol_label(tol)}; "
            "the rank is only meaningful on SO(3)"
        )
    R = rotation_symbols()
    J = _constraint_jacobian().subs(dict(zip(list(R), list(P))))
    if not P.has(sp.Float):
        return int(J.rank(simplify=True))
    return int(np.linalg.matrix_rank(np.array(J.evalf(), dtype=np.float64), tol=tol))


@cache
def solve_scalar_ode():
    r"""Solve :math:`\dot x(t) = a\,x(t)`, :math:`x(0) = x_0` with ``sp.dsolve`` (eqs. 95-106).

    .. math::

        \dot x = a x, \quad x(0) = x_0 \implies x(t) = x_0 e^{a t}.

    The symbols are real: ``t``, ``a``, ``x_0``; ``x`` is an undefined function.

    Returns
    -------
    sympy.Eq
        ``Eq(x(t), x_0*exp(a*t))``, initial condition applied.

    Examples
    --------
    >>> sol = solve_scalar_ode()
    >>> sol
    Eq(x(t), x_0*exp(a*t))
    >>> t = sp.Symbol("t", real=True)
    >>> sp.expand(sol.rhs.diff(t) - sp.Symbol("a", real=True) * sol.rhs)
    0
    """
    t, a, x0 = sp.symbols("t a x_0", real=True)
    x = sp.Function("x")
    return sp.dsolve(sp.Eq(x(t).diff(t), a * x(t)), x(t), ics={x(0): x0})


# ---------------------------------------------------------------------------------------------
# Showing results
# ---------------------------------------------------------------------------------------------


def tex(*parts):
    r"""The LaTeX of ``parts``, joined: strings are LaTeX already, the rest goes through sp.latex.

    Examples
    --------
    >>> x = sp.Symbol("x")
    >>> tex("x \\cdot x = ", x * x, ", ", "x + 1 = ", x + 1)
    'x \\cdot x = x^{2}, x + 1 = x + 1'
    """
    return "".join(p if isinstance(p, str) else sp.latex(p) for p in parts)


def show(*parts):
    r"""Display ``parts`` as one line of math in a notebook: ``display(Math(tex(*parts)))``.

    ``show(r"R^TR = ", R.T * R)`` is ``display(Math(r"R^TR = " + sp.latex(R.T * R)))``.
    """
    from IPython.display import Math, display

    display(Math(tex(*parts)))
