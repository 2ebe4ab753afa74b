r"""Exercises of the course notebooks and their checkers.

Every exercise of the three chapter notebooks is registered here, in :data:`EXERCISES`, with
its name, chapter (1 = §0.1.1 rigid body motion, 2 = §0.1.2 rotations, 3 = §0.1.3 exponential
coordinates), a title, a markdown statement for the notebook, its kind (``"symbolic"`` for a
sympy derivation, ``"numeric"`` for a number, vector or matrix) and a private expected answer.

A notebook shows an exercise with ``get(name)`` (it renders its statement as markdown) and
grades a student's answer with :func:`check`::

    answer_hat_squared = omega * omega.T - sp.eye(3)
    check("hat_squared", answer_hat_squared)        # ✓ hat_squared: correct.

Answers are compared for *equivalence*, never as strings. A symbolic answer is accepted when
its difference to the expected answer expands to zero (modulo the unit constraint
:math:`\omega_1^2 + \omega_2^2 + \omega_3^2 = 1` where the exercise says ω is a unit vector),
or, as a backstop for identities that expansion does not reach (trigonometric ones such as
:math:`1 - \cos\theta = 2\sin^2(\theta/2)`), when it agrees with the expected answer at several
seeded random points (unit ω, random θ) within the tolerance policy ``TOL`` of
:mod:`course_lib.tolerance`. An answer that cannot be evaluated at those points is decided by
:func:`course_lib.symbolic.unit_reduce` and ``trigsimp`` instead. A numeric answer is accepted when
its residual norm is at most ``TOL``. A wrong answer gets a hint (wrong entries, a sign, a
transpose, a constant factor, a known mistake) that never shows the expected answer.

Besides ``omega`` and ``theta`` of :mod:`course_lib.symbolic`, some exercises need symbols of
their own, defined here: the generic vectors :data:`x`, :data:`y`, the time :data:`t`, the
rate :data:`a`, the initial value :data:`x_0` and the generic matrix :data:`R_generic`.
"""

from __future__ import annotations

import html
import warnings
from dataclasses import dataclass, field
from typing import Callable

import numpy as np
import sympy as sp
from sympy.core.function import AppliedUndef

from .symbolic import hat, omega, rotation_symbols, theta, unit_reduce, vector
from .tolerance import TOL, check_tol

__all__ = [
    "EXERCISES",
    "CheckResult",
    "Exercise",
    "R_generic",
    "a",
    "check",
    "exercises",
    "get",
    "names",
    "t",
    "x",
    "x_0",
    "y",
]

# --------------------------------------------------------------------------------------------
# Symbols used by the exercises (besides omega and theta of course_lib.symbolic)
# --------------------------------------------------------------------------------------------

#: Generic real 3-vector :math:`x = (x_1, x_2, x_3)` as a 3x1 column.
x = vector("x")
#: Generic real 3-vector :math:`y = (y_1, y_2, y_3)` as a 3x1 column.
y = vector("y")
#: Real time symbol :math:`t`.
t = sp.Symbol("t", real=True)
#: Real rate symbol :math:`a` of the ODE :math:`\dot x = a x`.
a = sp.Symbol("a", real=True)
#: Real initial value :math:`x_0 = x(0)`.
x_0 = sp.Symbol("x_0", real=True)
#: Generic real 3x3 matrix with entries :math:`r_{ij}` (its columns are :math:`r_1, r_2, r_3`).
R_generic = rotation_symbols("r")

_W = tuple(omega)
_X = tuple(x)
_Y = tuple(y)
_R = tuple(R_generic)

#: How each group of symbols is named in messages and where it comes from.
_SYMBOL_SOURCES = (
    (_W, "ω₁, ω₂, ω₃ (`omega` from course_lib.symbolic)"),
    ((theta,), "θ (`theta` from course_lib.symbolic)"),
    (_X, "x₁, x₂, x₃ (`x` from course_lib.exercises)"),
    (_Y, "y₁, y₂, y₃ (`y` from course_lib.exercises)"),
    ((t,), "t (`t` from course_lib.exercises)"),
    ((a,), "a (`a` from course_lib.exercises)"),
    ((x_0,), "x₀ (`x_0` from course_lib.exercises)"),
    (_R, "r₁₁ … r₃₃ (`R_generic` from course_lib.exercises)"),
)

_SETUP_SYMBOLIC = "import sympy as sp\nfrom course_lib.symbolic import omega, theta, hat\n"
_SETUP_NUMERIC = "import numpy as np\n"
_SETUP_CHECK = "from course_lib.exercises import check\n"


# --------------------------------------------------------------------------------------------
# The registry
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Exercise:
    r"""One exercise of a chapter notebook.

    Parameters
    ----------
    name : str
        Unique identifier; the notebook assigns the answer to ``answer_<name>``.
    chapter : int
        1 (§0.1.1 rigid body motion), 2 (§0.1.2 rotations) or 3 (§0.1.3 exponential coordinates).
    number : int
        Position within the chapter; ``label`` is ``"<chapter>.<number>"``.
    title : str
        Short title.
    statement : str
        Markdown statement for the notebook (LaTeX between ``$...$``).
    kind : {"symbolic", "numeric"}
        A sympy derivation or a numeric answer.
    shape : tuple of int
        ``()`` for a scalar, ``(3,)`` for a 3-vector, ``(3, 3)`` for a matrix.
    symbols : tuple of sympy.Symbol
        The symbols a symbolic answer may contain.
    unit_omega : bool
        Whether ω is a unit vector in this exercise (answers are compared on the unit sphere).
    setup : str
        Python code a notebook runs before the solution cell (imports of the symbols used).
    tip : str
        A general pointer to the notes, added to the message of a wrong answer.

    Examples
    --------
    >>> ex = get("hat_squared")
    >>> ex.label, ex.kind, ex.shape
    ('3.3', 'symbolic', (3, 3))
    """

    name: str
    chapter: int
    number: int
    title: str
    statement: str
    kind: str
    shape: tuple
    symbols: tuple = ()
    unit_omega: bool = False
    setup: str = ""
    tip: str = ""
    _expected: Callable = field(default=None, repr=False, compare=False)
    _mistakes: tuple = field(default=(), repr=False, compare=False)
    _extra_hint: Callable = field(default=None, repr=False, compare=False)

    @property
    def label(self):
        """``"<chapter>.<number>"``, e.g. ``"3.3"``."""
        return f"{self.chapter}.{self.number}"

    @property
    def answer_variable(self):
        """Name of the notebook variable holding the answer: ``answer_<name>``."""
        return f"answer_{self.name}"

    def markdown(self):
        """The statement with a heading, as markdown for a notebook cell."""
        return (f"**Exercise {self.label} — {self.title}** (`{self.name}`)\n\n"
                f"{self.statement.strip()}\n\n"
                f"Assign your answer to `{self.answer_variable}` and run "
                f"`check(\"{self.name}\", {self.answer_variable})`.")

    def _repr_markdown_(self):
        return self.markdown()

    def __str__(self):
        return f"Exercise {self.label} ({self.name}): {self.title}"


def _rot_z_sym(angle):
    c, s = sp.cos(angle), sp.sin(angle)
    return sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])


_S2 = np.sqrt(2.0)
_RAC = np.array([[1 / _S2, -1 / _S2, 0.0], [1 / _S2, 1 / _S2, 0.0], [0.0, 0.0, 1.0]])
_RX60 = np.array([[1.0, 0.0, 0.0],
                  [0.0, 0.5, -np.sqrt(3.0) / 2],
                  [0.0, np.sqrt(3.0) / 2, 0.5]])
_P_PROJ = np.array([1.0, 3.0, 2.0])
_VB = np.array([1.0, 1.0, 3.0])
_UNIT_HINT = ("ω is a unit vector here: use ω₁² + ω₂² + ω₃² = 1 "
              "(the term with ‖ω‖² does not vanish, it becomes 1).")

_EXERCISE_LIST = [
    # ---------------------------------------------------------------- chapter 1: §0.1.1
    Exercise(
        name="coords_by_projection", chapter=1, number=1,
        title="Coordinates by projection",
        kind="numeric", shape=(3,),
        statement=r"""
A right-handed orthonormal frame has the basis vectors (written in reference coordinates)
$e_1 = (1/\sqrt2,\ 1/\sqrt2,\ 0)$, $e_2 = (-1/\sqrt2,\ 1/\sqrt2,\ 0)$, $e_3 = (0,\ 0,\ 1)$.
The point $p$ has reference coordinates $(1,\ 3,\ 2)$.

Find the coordinates $(p \cdot e_1,\ p \cdot e_2,\ p \cdot e_3)$ of $p$ in the frame
$\{e_1, e_2, e_3\}$ (equations (3)–(5)). Give a 3-vector (list, numpy array or sympy Matrix).
""",
        setup=_SETUP_NUMERIC + _SETUP_CHECK,
        tip="Each coordinate is the projection of p onto one basis vector (equations (3)–(5)).",
        _expected=lambda: _RAC.T @ _P_PROJ,
        _mistakes=(
            (lambda: _RAC @ _P_PROJ,
             "you combined the basis vectors with p's entries as weights; a coordinate is a "
             "projection, the dot product of p with one basis vector."),
        ),
    ),
    Exercise(
        name="polarization", chapter=1, number=2,
        title="The polarization identity",
        kind="symbolic", shape=(), symbols=_X + _Y,
        statement=r"""
With the generic vectors `x` $= (x_1, x_2, x_3)$ and `y` $= (y_1, y_2, y_3)$, expand the
right-hand side of the polarization identity (17),
$\tfrac14\left(\lVert x+y\rVert^2 - \lVert x-y\rVert^2\right)$, in components and simplify it.
Give a scalar sympy expression in $x_1, \dots, y_3$.
""",
        setup=_SETUP_SYMBOLIC + "from course_lib.exercises import check, x, y\n",
        tip="Write ‖v‖² as vᵀv, expand both squares and collect what is left (equation (17)).",
        _expected=lambda: (x.T * y)[0, 0],
    ),
    Exercise(
        name="reflection_cross", chapter=1, number=3,
        title="A mirror flips the cross product",
        kind="symbolic", shape=(), symbols=_X + _Y,
        statement=r"""
The mirror $g(p) = \operatorname{diag}(1, 1, -1)\,p$ reflects space in the $xy$-plane.
It preserves lengths, but not orientation. For the generic vectors `x`, `y`, compute
$g(x) \times g(y)$ and $g(x \times y)$ with sympy and find the number $c$ such that
$g(x) \times g(y) = c\, g(x \times y)$ for all $x, y$ (compare with the counterexample after
equation (14)). Give $c$ (a sympy number or a plain number).
""",
        setup=_SETUP_SYMBOLIC + "from course_lib.exercises import check, x, y\n",
        tip="Compute both sides componentwise with `Matrix.cross` and compare them entry by entry.",
        _expected=lambda: sp.Integer(-1),
        _mistakes=(
            (lambda: sp.Integer(1),
             "that would make g preserve orientation; compute both sides for x = e₁, y = e₂ "
             "and compare their third components."),
        ),
    ),
    Exercise(
        name="trajectory_velocity", chapter=1, number=4,
        title="Velocity along a trajectory",
        kind="symbolic", shape=(3,), symbols=(t,),
        statement=r"""
A particle follows the helix $p(t) = \big(\cos 2t,\ \sin 2t,\ 3t\big)$ (a trajectory as in
equation (6)). Compute its velocity $\dot p(t)$ with sympy, using the time symbol `t`.
Give a 3-vector (a 3x1 sympy Matrix or a list of three expressions in $t$).
""",
        setup=_SETUP_SYMBOLIC + "from course_lib.exercises import check, t\n",
        tip="Differentiate each component with respect to t (`sp.diff`); mind the chain rule.",
        _expected=lambda: sp.Matrix([-2 * sp.sin(2 * t), 2 * sp.cos(2 * t), 3]),
        _mistakes=(
            (lambda: sp.Matrix([-sp.sin(2 * t), sp.cos(2 * t), 3]),
             "the chain rule: the inner derivative of cos 2t and sin 2t is missing."),
            (lambda: sp.Matrix([-sp.sin(2 * t), sp.cos(2 * t), 3 * t]),
             "differentiate every component, and mind the chain rule."),
            (lambda: sp.Matrix([sp.cos(2 * t), sp.sin(2 * t), 3 * t]),
             "this is the position p(t) itself; the velocity is its time derivative."),
        ),
    ),
    # ---------------------------------------------------------------- chapter 2: §0.1.2
    Exercise(
        name="rab_example", chapter=2, number=1,
        title="The rotation matrix R_ab of the first Example",
        kind="numeric", shape=(3, 3),
        statement=r"""
In the first Example of §0.1.2, frame $B$'s axes, written in the inertial frame $A$, are
$x_{ab} = (-1, 0, 0)$, $y_{ab} = (0, 1, 0)$ and $z_{ab} = (0, 0, -1)$.
Form the rotation matrix $R_{ab}$ of equation (26). Give a 3x3 array or matrix.
""",
        setup=_SETUP_NUMERIC + _SETUP_CHECK,
        tip="R_ab stacks the axes of B, written in A, as its columns (equation (26)).",
        _expected=lambda: np.diag([-1.0, 1.0, -1.0]),
    ),
    Exercise(
        name="rac_example", chapter=2, number=2,
        title="The rotation matrix R_ac of the first Example",
        kind="numeric", shape=(3, 3),
        statement=r"""
In the same Example, frame $C$'s axes, written in $A$, are
$x_{ac} = (1/\sqrt2,\ 1/\sqrt2,\ 0)$, $y_{ac} = (-1/\sqrt2,\ 1/\sqrt2,\ 0)$ and
$z_{ac} = (0, 0, 1)$. Form $R_{ac}$ and check that it is a rotation about $z$ by 45°.
Give a 3x3 array or matrix.
""",
        setup=_SETUP_NUMERIC + _SETUP_CHECK,
        tip="Stack the axes of C as columns, in the order x, y, z (equation (26)).",
        _expected=lambda: _RAC,
        _mistakes=(
            (lambda: _RAC.T,
             "you stacked the axes as rows; R_ac has the axes of C as its columns."),
        ),
    ),
    Exercise(
        name="va_example", chapter=2, number=3,
        title="A vector in two frames",
        kind="numeric", shape=(3,),
        statement=r"""
Frame $B$'s axes, written in $A$, are $x_{ab} = (1/\sqrt2,\ 1/\sqrt2,\ 0)$,
$y_{ab} = (-1/\sqrt2,\ 1/\sqrt2,\ 0)$, $z_{ab} = (0, 0, 1)$. A vector has the coordinates
$v_b = (1, 1, 3)$ in $B$. Find its coordinates $v_a$ in $A$ (equation (64)).
Give a 3-vector.
""",
        setup=_SETUP_NUMERIC + _SETUP_CHECK,
        tip="Build R_ab from the axes of B and use equation (64), v_a = R_ab v_b.",
        _expected=lambda: _RAC @ _VB,
        _mistakes=(
            (lambda: _RAC.T @ _VB,
             "you multiplied by R_abᵀ, which maps A-coordinates to B-coordinates; "
             "equation (64) goes the other way."),
        ),
    ),
    Exercise(
        name="rotation_inverse", chapter=2, number=4,
        title="The inverse of a rotation",
        kind="numeric", shape=(3, 3),
        statement=r"""
Let
$R = \begin{pmatrix} 1 & 0 & 0 \\ 0 & 1/2 & -\sqrt3/2 \\ 0 & \sqrt3/2 & 1/2 \end{pmatrix}$
(a rotation about $x$ by 60°). Find $R^{-1}$ without a numerical inverse, using the group
structure of SO(3) (Proposition 5). Give a 3x3 array or matrix.
""",
        setup=_SETUP_NUMERIC + _SETUP_CHECK,
        tip="Proposition 5 (item 3): for R in SO(3), RᵀR = I tells you what R⁻¹ is.",
        _expected=lambda: _RX60.T,
        _mistakes=(
            (lambda: _RX60,
             "this is R itself; its inverse undoes the rotation."),
        ),
    ),
    Exercise(
        name="det_triple_product", chapter=2, number=5,
        title="The determinant as a triple product",
        kind="symbolic", shape=(), symbols=_R,
        statement=r"""
Let `R_generic` be the generic matrix with entries $r_{ij}$ and columns
$r_1, r_2, r_3$ (`R_generic[:, 0]`, ...). Compute the triple product
$r_1^T (r_2 \times r_3)$ of equation (52) with sympy and expand it; compare with the cofactor
expansion (49)–(51). Give the scalar expression.
""",
        setup=_SETUP_SYMBOLIC + "from course_lib.exercises import check, R_generic\n",
        tip="Take the columns in the order r₁, r₂, r₃; `Matrix.cross` and `Matrix.dot` help.",
        _expected=lambda: R_generic.det(method="berkowitz").expand(),
        _mistakes=(
            (lambda: R_generic[:, 0].dot(R_generic[:, 2].cross(R_generic[:, 1])),
             "the order of the cross product matters: r₂ × r₃ = −(r₃ × r₂)."),
        ),
    ),
    Exercise(
        name="rotated_hat", chapter=2, number=6,
        title="Conjugating a hat matrix",
        kind="symbolic", shape=(3,), symbols=_W + (theta,),
        statement=r"""
Let $R = R_z(\theta) = \begin{pmatrix} \cos\theta & -\sin\theta & 0 \\ \sin\theta &
\cos\theta & 0 \\ 0 & 0 & 1 \end{pmatrix}$ and let $\omega$ be a general vector
(`omega`, not necessarily unit). Compute $R\,\hat\omega\,R^T$ with sympy and find the vector
$u$ with $R\,\hat\omega\,R^T = \hat u$ (Proposition 6, equation (74)).
Give $u$ as a 3-vector in $\omega_1, \omega_2, \omega_3, \theta$.
""",
        setup=_SETUP_SYMBOLIC + _SETUP_CHECK,
        tip="Read u off the entries of the skew-symmetric result (definition (72)), or use "
            "equation (74) directly.",
        _expected=lambda: _rot_z_sym(theta) * sp.Matrix(omega),
        _mistakes=(
            (lambda: _rot_z_sym(theta).T * sp.Matrix(omega),
             "this is the vector for Rᵀ ω̂ R, the conjugation the other way round."),
            (lambda: sp.Matrix(omega),
             "ω itself is only right when R = I; the rotation acts on the vector."),
        ),
    ),
    # ---------------------------------------------------------------- chapter 3: §0.1.3
    Exercise(
        name="ode_solution", chapter=3, number=1,
        title="The scalar ODE ẋ = a x",
        kind="symbolic", shape=(), symbols=(a, t, x_0),
        statement=r"""
Solve $\dot x(t) = a\,x(t)$ with the initial condition $x(0) = x_0$ (equations (95)–(106)),
by hand or with `sp.dsolve`. Give $x(t)$ as an expression in the symbols `a`, `t`, `x_0`
(from an `Eq` returned by `dsolve`, take its right-hand side `.rhs`).
""",
        setup=_SETUP_SYMBOLIC + "from course_lib.exercises import check, a, t, x_0\n",
        tip="Separate the variables and integrate from 0 to t (equations (98)–(106)).",
        _expected=lambda: x_0 * sp.exp(a * t),
        _mistakes=(
            (lambda: x_0 * sp.exp(-a * t), "check the sign in the exponent: ẋ must equal +a x."),
        ),
        _extra_hint=lambda ex, M, tol: _ode_hint(ex, M, tol),
    ),
    Exercise(
        name="pendulum_speed", chapter=3, number=2,
        title="The speed of a pendulum",
        kind="numeric", shape=(),
        statement=r"""
A pendulum of length $r = 2$ m swings with angle $\theta(t) = \frac{\pi}{6}\cos 3t$
(radians, $t$ in seconds). Using $\omega = \dot\theta$ (117) and $\lVert v\rVert = |r\omega|$
(118), find the speed of its tip at $t = \pi/6$ s, in m/s. Give a number.
""",
        setup=_SETUP_NUMERIC + _SETUP_CHECK,
        tip="The speed needs the angular velocity θ̇(t), not the angle θ(t) (equation (118)).",
        _expected=lambda: np.float64(np.pi),
        _mistakes=(
            (lambda: np.float64(0.0),
             "that is r θ(t); the speed uses the angular velocity ω = θ̇."),
            (lambda: np.float64(-np.pi),
             "a speed is a norm, |r ω|, never negative."),
            (lambda: np.float64(np.pi / 2),
             "the speed is |r ω|; did you forget the length r?"),
        ),
    ),
    Exercise(
        name="hat_squared", chapter=3, number=3,
        title="The square of a hat matrix",
        kind="symbolic", shape=(3, 3), symbols=_W, unit_omega=True,
        statement=r"""
Let $\omega$ (`omega`) be a **unit** vector. Compute $\hat\omega^2$ with sympy and write it
in terms of $\omega$, $\omega^T$ and the identity, without any hat (equations (136)–(141)).
Give the 3x3 sympy matrix.
""",
        setup=_SETUP_SYMBOLIC + _SETUP_CHECK,
        tip="Pull a multiple of the identity out of ω̂² (equation (139)) and recognise the rest.",
        _expected=lambda: sp.Matrix(omega) * sp.Matrix(omega).T - sp.eye(3),
        _mistakes=(
            (lambda: sp.Matrix(omega) * sp.Matrix(omega).T, _UNIT_HINT),
            (lambda: sp.Matrix(omega) * sp.Matrix(omega).T + sp.eye(3),
             "check the sign of the identity part, and " + _UNIT_HINT),
        ),
    ),
    Exercise(
        name="hat_cubed", chapter=3, number=4,
        title="The cube of a hat matrix",
        kind="symbolic", shape=(3, 3), symbols=_W, unit_omega=True,
        statement=r"""
For a **unit** vector $\omega$, simplify $\hat\omega^3$ to a multiple of a lower power of
$\hat\omega$ (equations (142)–(148)). Give the 3x3 sympy matrix, e.g. built with `hat(omega)`.
""",
        setup=_SETUP_SYMBOLIC + _SETUP_CHECK,
        tip="Write ω̂³ = ω̂² ω̂, use the previous exercise and ω × ω = 0.",
        _expected=lambda: -hat(omega),
        _mistakes=(
            (lambda: sp.Matrix(omega) * sp.Matrix(omega).T * hat(omega),
             "ωωᵀω̂ vanishes (ωᵀω̂ = −(ω × ω)ᵀ = 0); the other term of ω̂² ω̂ survives."),
        ),
    ),
    Exercise(
        name="hat_fourth", chapter=3, number=5,
        title="The fourth power of a hat matrix",
        kind="symbolic", shape=(3, 3), symbols=_W, unit_omega=True,
        statement=r"""
For a **unit** vector $\omega$, express $\hat\omega^4$ in terms of $\hat\omega^2$ and then
in terms of $\omega$, $\omega^T$ and the identity (equations (152)–(153)).
Give the 3x3 sympy matrix.
""",
        setup=_SETUP_SYMBOLIC + _SETUP_CHECK,
        tip="ω̂⁴ = ω̂³ ω̂; use the result for ω̂³, then the one for ω̂².",
        _expected=lambda: sp.eye(3) - sp.Matrix(omega) * sp.Matrix(omega).T,
        _mistakes=(
            (lambda: -sp.Matrix(omega) * sp.Matrix(omega).T, _UNIT_HINT),
        ),
    ),
    Exercise(
        name="rodrigues", chapter=3, number=6,
        title="Rodrigues' formula",
        kind="symbolic", shape=(3, 3), symbols=_W + (theta,), unit_omega=True,
        statement=r"""
For a **unit** axis $\omega$ and an angle $\theta$, sum the series (134) for
$e^{\hat\omega\theta}$ in closed form: group the odd and the even powers of $\hat\omega$ and
recognise two Taylor series (equations (151)–(159)). Give $e^{\hat\omega\theta}$ as a 3x3 sympy
matrix in $\omega$ (or `hat(omega)`) and $\theta$.
""",
        setup=_SETUP_SYMBOLIC + _SETUP_CHECK,
        tip="Compare the coefficients of ω̂ and ω̂² with the Taylor series of sin θ and cos θ "
            "(equation (158)).",
        _expected=lambda: (sp.eye(3) + sp.sin(theta) * hat(omega)
                           + (1 - sp.cos(theta)) * hat(omega) ** 2),
        _mistakes=(
            (lambda: (sp.eye(3) + sp.cos(theta) * hat(omega)
                      + (1 - sp.sin(theta)) * hat(omega) ** 2),
             "sin and cos are swapped: the odd powers of ω̂ carry the odd series."),
            (lambda: sp.eye(3) + sp.sin(theta) * hat(omega) + sp.cos(theta) * hat(omega) ** 2,
             "the even series starts at θ²/2!, so its sum is not cos θ itself (what is "
             "cos θ minus its first term?)."),
            (lambda: (sp.eye(3) + sp.sin(theta) * hat(omega)
                      - (1 - sp.cos(theta)) * hat(omega) ** 2),
             "check the sign of the ω̂² term."),
            (lambda: sp.eye(3) + theta * hat(omega) + theta ** 2 / 2 * hat(omega) ** 2,
             "that is the series cut after three terms; sum the whole series."),
            (lambda: sp.sin(theta) * hat(omega) + (1 - sp.cos(theta)) * hat(omega) ** 2,
             "the series starts with the identity (the A⁰ = I term)."),
        ),
    ),
]

#: All exercises by name, in notebook order (chapter, then number).
EXERCISES = {ex.name: ex for ex in sorted(_EXERCISE_LIST, key=lambda e: (e.chapter, e.number))}


def names(chapter=None):
    """Names of the registered exercises, in notebook order.

    Parameters
    ----------
    chapter : int, optional
        Only the exercises of this chapter (1, 2 or 3).

    Returns
    -------
    list of str

    Examples
    --------
    >>> names(3)[:2]
    ['ode_solution', 'pendulum_speed']
    """
    return [ex.name for ex in exercises(chapter)]


def exercises(chapter=None):
    """The registered exercises, in notebook order.

    Parameters
    ----------
    chapter : int, optional
        Only the exercises of this chapter (1, 2 or 3).

    Returns
    -------
    list of Exercise

    Raises
    ------
    ValueError
        If ``chapter`` is not 1, 2 or 3.

    Examples
    --------
    >>> [ex.label for ex in exercises(1)]
    ['1.1', '1.2', '1.3', '1.4']
    """
    if chapter is None:
        return list(EXERCISES.values())
    if chapter not in (1, 2, 3):
        raise ValueError(f"chapter must be 1, 2 or 3, got {chapter!r}")
    return [ex for ex in EXERCISES.values() if ex.chapter == chapter]


def get(name):
    """The exercise registered under ``name``.

    Parameters
    ----------
    name : str
        The exercise's name, e.g. ``"hat_squared"``.

    Returns
    -------
    Exercise
        Displayed in a notebook, it renders its statement as markdown.

    Raises
    ------
    KeyError
        If no exercise has this name; the message lists the known names.

    Examples
    --------
    >>> get("rodrigues").title
    "Rodrigues' formula"
    """
    if not isinstance(name, str) or name not in EXERCISES:
        raise KeyError(f"unknown exercise {name!r}; known exercises: {', '.join(EXERCISES)}")
    return EXERCISES[name]


# --------------------------------------------------------------------------------------------
# Check results
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class CheckResult:
    r"""The verdict of :func:`check` on one answer.

    Displays as ``✓ <name>: correct.`` or ``✗ <name>: <hint>`` in plain text and as a short
    coloured line in a notebook; both are deterministic (no ids, no addresses).

    Parameters
    ----------
    name : str
        The exercise's name.
    ok : bool
        Whether the answer is correct. ``bool(result)`` is ``result.ok``.
    message : str
        ``"correct."`` or a hint that does not reveal the expected answer.
    status : {"correct", "wrong", "malformed", "no answer"}
        What kind of verdict this is.

    Examples
    --------
    >>> r = CheckResult("hat_cubed", False, "no answer yet.", "no answer")
    >>> print(r)
    ✗ hat_cubed: no answer yet.
    >>> bool(r)
    False
    """

    name: str
    ok: bool
    message: str
    status: str

    def __bool__(self):
        return self.ok

    def __str__(self):
        return f"{'✓' if self.ok else '✗'} {self.name}: {self.message}"

    __repr__ = __str__

    def _repr_html_(self):
        color = "#1a7f37" if self.ok else "#b42318"
        text = html.escape(self.message)
        # `code` spans of the message become <code> elements.
        parts = text.split("`")
        text = "".join(p if i % 2 == 0 else f"<code>{p}</code>" for i, p in enumerate(parts))
        return (f'<div style="color: {color};"><b>{"✓" if self.ok else "✗"} '
                f"{html.escape(self.name)}</b>: {text}</div>")


class _Malformed(Exception):
    """An answer that cannot be compared (wrong type, shape, symbols); carries the message."""


# --------------------------------------------------------------------------------------------
# Reading an answer
# --------------------------------------------------------------------------------------------


def _describe_shape(shape):
    return {(): "a scalar", (3,): "a 3-vector", (3, 3): "a 3x3 matrix"}.get(
        shape, "x".join(map(str, shape)) + " array")


def _is_truth_value(obj):
    return isinstance(obj, (bool, np.bool_, sp.logic.boolalg.Boolean)) and not isinstance(
        obj, sp.Expr)                               # sympy symbols are Booleans too


def _contains(obj, test):
    """Whether obj, or an entry of a (nested) list, tuple or array, passes test."""
    if test(obj):
        return True
    if isinstance(obj, (list, tuple)):
        return any(_contains(o, test) for o in obj)
    if isinstance(obj, np.ndarray) and obj.dtype.kind in "OUSb":
        return any(_contains(o, test) for o in obj.ravel().tolist())
    return False


def _to_matrix(ex, answer):
    """The answer as an ImmutableMatrix of shape (1, 1), (3, 1) or (3, 3), or _Malformed."""
    what = "a sympy expression" if ex.kind == "symbolic" else "a number, list or array"
    if _contains(answer, lambda o: isinstance(o, str)):
        raise _Malformed(f"give {what}, not a string (answers are compared as objects, "
                         "strings are never evaluated).")
    if isinstance(answer, (list, tuple, np.ndarray)) and _contains(answer, _is_truth_value):
        raise _Malformed(f"an entry of your answer is a truth value (True/False); give {what}.")
    if _is_truth_value(answer):
        if isinstance(answer, sp.Rel):
            raise _Malformed("got an equation or relation; give the expression itself "
                             "(for an Eq from dsolve, its right-hand side `.rhs`).")
        raise _Malformed(f"got the truth value {answer!r}; give {what}, not a comparison.")
    if isinstance(answer, sp.MatrixExpr) and not isinstance(answer, sp.MatrixBase):
        answer = answer.as_explicit()
    if isinstance(answer, sp.NDimArray):
        answer = answer.tolist()
    if isinstance(answer, np.ndarray) and answer.ndim == 0:
        answer = answer.item()
    if isinstance(answer, (sp.MatrixBase, np.ndarray, list, tuple)):
        arr = None
        if not isinstance(answer, sp.MatrixBase):
            arr = np.asarray(answer, dtype=object)
            if arr.ndim >= 1 and any(isinstance(e, (list, tuple, np.ndarray))
                                     for e in arr.ravel().tolist()):
                raise _Malformed(f"could not read your answer as {_describe_shape(ex.shape)}: "
                                 "its rows have different lengths.")
        if arr is not None and arr.ndim > 2:
            raise _Malformed(f"expected {_describe_shape(ex.shape)}, got an array of shape "
                             f"{arr.shape}.")
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("error")      # e.g. sympy's non-Expr-in-Matrix warning
                M = sp.ImmutableMatrix(answer)
        except Exception:  # noqa: BLE001 - any failure to read becomes a message
            raise _Malformed(f"could not read your answer as {_describe_shape(ex.shape)}; "
                             "give a sympy Matrix, a numpy array or a list of numbers or "
                             "expressions.") from None
        got = f"a {M.rows}x{M.cols} matrix"
    elif isinstance(answer, (int, float, complex, np.number, sp.Expr)):
        M = sp.ImmutableMatrix([[sp.sympify(answer)]])
        got = "a scalar"
    else:
        raise _Malformed(f"expected {_describe_shape(ex.shape)} ({what}), got an object of "
                         f"type {type(answer).__name__}.")
    shape = M.shape
    if ex.shape == () and shape == (1, 1):
        pass
    elif ex.shape == (3,) and shape in ((3, 1), (1, 3)):
        M = M.reshape(3, 1)
    elif ex.shape == (3, 3) and shape == (3, 3):
        pass
    else:
        raise _Malformed(f"wrong shape: expected {_describe_shape(ex.shape)}, got {got}.")
    for e in M:
        if not isinstance(e, sp.Expr):
            raise _Malformed(f"an entry of your answer is a {type(e).__name__}, not an "
                             "expression or a number.")
        if e.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
            raise _Malformed("your answer contains nan or infinity.")
    if M.has(sp.Derivative, sp.Integral, sp.Sum, sp.Product):
        M = M.doit()
    funcs = M.atoms(AppliedUndef)
    if funcs:
        raise _Malformed("your answer contains the undefined function(s) "
                         f"{', '.join(sorted(map(str, funcs)))}; give an explicit expression.")
    return M


def _check_symbols(ex, M):
    free = M.free_symbols
    if ex.kind == "numeric":
        if free:
            raise _Malformed("a number is expected here, but your answer contains the "
                             f"symbol(s) {', '.join(sorted(map(str, free)))}.")
        return
    extra = free - set(ex.symbols)
    if not extra:
        return
    allowed_by_name = {s.name: s for s in ex.symbols}
    lookalikes = sorted(s.name for s in extra if s.name in allowed_by_name)
    sources = [desc for group, desc in _SYMBOL_SOURCES if set(group) & set(ex.symbols)]
    if lookalikes:
        raise _Malformed(f"the symbol(s) {', '.join(lookalikes)} in your answer are not the "
                         "real symbols of the course (made with other assumptions, e.g. without "
                         f"real=True); build your answer from {' and '.join(sources)}.")
    raise _Malformed(f"your answer contains the symbol(s) {', '.join(sorted(map(str, extra)))}, "
                     f"which do not belong to this exercise; use only {' and '.join(sources)}.")


# --------------------------------------------------------------------------------------------
# Comparing
# --------------------------------------------------------------------------------------------

_NPOINTS = 6
_cache = {}


def _seed(name):
    return sum((i + 1) * ord(c) for i, c in enumerate(name)) + 20240


def _points(ex):
    """Seeded random values of the exercise's symbols (unit ω where the exercise says so)."""
    rng = np.random.default_rng(_seed(ex.name))
    pts = []
    for _ in range(_NPOINTS):
        v = {}
        w = rng.normal(size=3)
        w = w / np.linalg.norm(w) if ex.unit_omega else 1.5 * w
        v.update(zip(_W, w))
        v[theta] = rng.uniform(-3.0, 3.0)
        v[t] = rng.uniform(-2.0, 2.0)
        v[a] = rng.uniform(-1.5, 1.5)
        v[x_0] = rng.uniform(0.5, 2.0) * rng.choice([-1.0, 1.0])
        v.update(zip(_X + _Y + _R, rng.normal(size=15)))
        pts.append([v[s] for s in ex.symbols])
    return pts


def _evaluate(ex, M):
    """Values of a symbolic matrix at the exercise's points: array (npoints, *shape)."""
    pts = _points(ex) if ex.symbols else [[]]
    out = []
    try:
        f = sp.lambdify(ex.symbols, M, modules="numpy")
        with np.errstate(all="ignore"):
            for p in pts:
                out.append(np.asarray(f(*[complex(v) for v in p]), dtype=complex))
    except Exception:  # noqa: BLE001 - fall back to sympy's own evaluation
        out = []
        for p in pts:
            val = M.xreplace(dict(zip(ex.symbols, map(sp.Float, p)))).evalf()
            try:
                out.append(np.asarray(val.tolist(), dtype=complex))
            except TypeError:
                raise _Malformed("could not evaluate your answer numerically; give an explicit "
                                 "expression.") from None
    vals = np.array([o.reshape(ex.shape) for o in out])
    if not np.all(np.isfinite(vals)):
        raise _Malformed("your answer is undefined (division by zero or nan) at some values of "
                         "the symbols.")
    if np.max(np.abs(vals.imag), initial=0.0) > TOL:
        raise _Malformed("your answer is complex-valued; a real answer is expected "
                         "(check square roots of negative quantities and stray factors of I).")
    return vals.real


def _numeric_value(ex, M):
    try:
        vals = np.array([complex(e.evalf()) for e in M], dtype=complex)
    except TypeError:
        raise _Malformed("could not read your answer as numbers.") from None
    if not np.all(np.isfinite(vals)):
        raise _Malformed("your answer contains nan or infinity.")
    if np.max(np.abs(vals.imag), initial=0.0) > TOL:
        raise _Malformed("your answer is complex; a real answer is expected.")
    return vals.real.reshape((1,) + ex.shape)


def _as_column(ex, value):
    """A reference value as an ImmutableMatrix of shape (1, 1), (3, 1) or (3, 3)."""
    if ex.shape == ():
        return sp.ImmutableMatrix([[sp.sympify(value)]])
    return sp.ImmutableMatrix(value).reshape(*{(3,): (3, 1), (3, 3): (3, 3)}[ex.shape])


def _reference(ex):
    """Expected values and the values of the known mistakes, cached per exercise."""
    if ex.name not in _cache:
        if ex.kind == "numeric":
            E = np.asarray(ex._expected(), dtype=float).reshape((1,) + ex.shape)
            mistakes = [(np.asarray(m(), dtype=float).reshape((1,) + ex.shape), h)
                        for m, h in ex._mistakes]
            expected = None
        else:
            expected = _as_column(ex, ex._expected())
            E = _evaluate(ex, expected)
            mistakes = [(_evaluate(ex, _as_column(ex, m())), h) for m, h in ex._mistakes]
        _cache[ex.name] = (expected, E, mistakes)
    return _cache[ex.name]


def _close(A, B, tol=TOL):
    """Residual norm (Euclidean / Frobenius) at most tol at every point."""
    return all(np.linalg.norm(np.ravel(p - q)) <= tol for p, q in zip(A, B))


def _reduce_unit_fast(e):
    """Expand and rewrite ω₃^k, k ≥ 2, through ω₃² = 1 − ω₁² − ω₂² (no simplification).

    This is the polynomial normal form modulo the unit sphere; unlike
    :func:`course_lib.symbolic.unit_reduce` it does not trig-simplify the coefficients, which
    keeps a check fast even for answers full of floats.
    """
    w1, w2, w3 = _W
    e = sp.expand(e.xreplace({w1 ** 2 + w2 ** 2 + w3 ** 2: sp.Integer(1)}))
    e = e.replace(lambda z: z.is_Pow and z.base == w3 and z.exp.is_Integer and z.exp >= 2,
                  lambda z: w3 ** (z.exp % 2) * (1 - w1 ** 2 - w2 ** 2) ** (z.exp // 2))
    return sp.expand(e)


def _expanded_equal(ex, M, expected):
    """Fast exact test: the difference expands to zero (modulo ‖ω‖ = 1 where ω is unit)."""
    for d in M - expected:
        d = sp.expand(d)
        if d != 0 and ex.unit_omega:
            d = _reduce_unit_fast(d)
        if d != 0:
            return False
    return True


def _simplified_equal(ex, M, expected):
    """Slower exact test, used only when the answer cannot be evaluated at the sample points:
    :func:`course_lib.symbolic.unit_reduce` (rational functions of ω, trig coefficients) and
    ``trigsimp`` on small leftovers. ``False`` means "not shown equal"."""
    for d in M - expected:
        d = sp.expand(sp.expand_trig(d))
        if d != 0 and ex.unit_omega:
            try:
                d = sp.expand(unit_reduce(d))
            except (ValueError, sp.PolynomialError):
                return False
        if d != 0 and sp.count_ops(d) <= 60:
            d = sp.expand(sp.trigsimp(d))
        if d != 0:
            return False
    return True


def _join(items):
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def _positions(ex, A, E, tol=TOL):
    """Which entries are wrong (1-based), never their right values."""
    if ex.shape == ():
        varies = not _close(E, np.broadcast_to(E[:1], E.shape), tol)
        if ex.kind == "symbolic" and varies:
            return "your expression is not equal to the right one."
        return "the value is not right."
    bad = np.zeros(ex.shape, dtype=bool)
    for p, q in zip(A, E):
        bad |= np.abs(p - q) > tol / 3
    if ex.shape == (3,):
        idx = [str(i + 1) for i in np.flatnonzero(bad)]
        noun, verb = ("components", "are") if len(idx) > 1 else ("component", "is")
    else:
        idx = [f"({i + 1}, {j + 1})" for i, j in zip(*np.nonzero(bad))]
        noun, verb = ("entries", "are") if len(idx) > 1 else ("entry", "is")
    return f"{noun} {_join(idx)} {verb} wrong."


def _diagnose(ex, M, A, E, mistakes, tol=TOL):
    """A hint for a wrong answer that never shows the expected answer."""
    for values, hint in mistakes:
        if _close(A, values, tol):
            return hint
    if ex._extra_hint is not None and M is not None:
        try:
            hint = ex._extra_hint(ex, M, tol)
        except _Malformed:
            hint = None
        if hint:
            return hint
    nonzero = any(np.linalg.norm(np.ravel(q)) > tol for q in E)
    if nonzero and _close(A, -E, tol):
        return "your answer is the negative of the right one: check the signs."
    if ex.shape == (3, 3) and _close(A, np.swapaxes(E, -1, -2), tol) and not _close(
            E, np.swapaxes(E, -1, -2), tol):
        return "your answer is the transpose of the right one (rows and columns swapped)."
    if nonzero and _close(A, np.zeros_like(A), tol):
        return "your answer is zero, the right one is not."
    varies = ex.shape != () or not _close(E, np.broadcast_to(E[:1], E.shape), tol)
    if nonzero and varies:
        c = float(np.sum(A * E) / np.sum(E * E))
        if abs(c - 1) > 1e-6 and abs(c + 1) > 1e-6 and _close(A, c * E, tol):
            return ("your answer is a constant multiple of the right one: check the numerical "
                    "factors.")
    if ex.shape == (3, 3):
        D = A - E
        s = np.trace(D, axis1=-2, axis2=-1) / 3
        if _close(D, s[:, None, None] * np.eye(3), tol):
            msg = "your answer differs from the right one by a multiple of the identity."
            return msg + (" " + _UNIT_HINT if ex.unit_omega else "")
    return _positions(ex, A, E, tol)


def _ode_hint(ex, M, tol=TOL):
    """Initial condition and the equation itself, checked separately."""
    expr = M[0]
    at0 = _evaluate(ex, sp.ImmutableMatrix([[expr.subs(t, 0) - x_0]]))
    if not _close(at0, np.zeros_like(at0), tol):
        return "the initial condition fails: your x(0) is not x₀."
    res = _evaluate(ex, sp.ImmutableMatrix([[sp.diff(expr, t) - a * expr]]))
    if not _close(res, np.zeros_like(res), tol):
        return "x(0) = x₀ holds, but your x(t) does not satisfy ẋ = a x."
    return None


def check(name, answer, tol=TOL):
    r"""Check a student's answer to the exercise ``name``.

    Symbolic answers are accepted when they are *equivalent* to the expected answer: the
    difference :math:`D` (entrywise) expands to zero, modulo the unit constraint
    :math:`\omega_1^2 + \omega_2^2 + \omega_3^2 = 1` for exercises with a unit ω, or, as a
    backstop (trigonometric identities), satisfies :math:`\lVert D(p_k)\rVert \le \mathrm{TOL}`
    at six seeded random points :math:`p_k` (unit ω where the exercise says so).
    Numeric answers are accepted when :math:`\lVert A - E\rVert \le \mathrm{TOL}` (Euclidean
    for vectors, Frobenius for matrices).

    Parameters
    ----------
    name : str
        The exercise's name (see :func:`names`).
    answer : object
        A sympy expression or Matrix (symbolic exercises); a number, list, tuple, numpy array
        or sympy Matrix (numeric exercises); ``None`` when there is no answer yet.
    tol : float, default TOL
        Tolerance on the residual norms (the package policy, :data:`course_lib.tolerance.TOL`).

    Returns
    -------
    CheckResult
        ``.ok`` and ``.message``; a wrong or malformed answer gives ``ok=False`` and a hint
        that does not reveal the expected answer. Never raises for a bad answer.

    Raises
    ------
    KeyError
        If ``name`` is not a registered exercise; the message lists the known names.
    TypeError, ValueError
        If ``tol`` is not a finite real number >= 0.

    Examples
    --------
    >>> import sympy as sp
    >>> from course_lib.symbolic import omega, hat
    >>> check("hat_squared", omega * omega.T - sp.eye(3))
    ✓ hat_squared: correct.
    >>> check("hat_cubed", hat(omega))
    ✗ hat_cubed: your answer is the negative of the right one: check the signs.
    Hint: Write ω̂³ = ω̂² ω̂, use the previous exercise and ω × ω = 0.
    >>> check("rab_example", None).ok
    False
    """
    ex = get(name)
    tol = check_tol(tol)
    if answer is None:
        return CheckResult(name, False, f"no answer yet: assign your answer to "
                           f"`{ex.answer_variable}` (it is still None).", "no answer")
    try:
        return _check(ex, answer, tol)
    except Exception as err:  # noqa: BLE001 - a bad answer must never raise from deep inside
        return CheckResult(name, False, "could not check your answer "
                           f"({type(err).__name__}: {err}); give {_describe_shape(ex.shape)} "
                           "as a sympy expression, number, list or array.", "malformed")


def _check(ex, answer, tol):
    name = ex.name
    try:
        M = _to_matrix(ex, answer)
        _check_symbols(ex, M)
        expected, E, mistakes = _reference(ex)
        if ex.kind == "numeric":
            A = _numeric_value(ex, M)
        else:
            if _expanded_equal(ex, M, expected):
                return CheckResult(name, True, "correct.", "correct")
            try:
                A = _evaluate(ex, M)
            except _Malformed:
                if _simplified_equal(ex, M, expected):
                    return CheckResult(name, True, "correct.", "correct")
                raise
    except _Malformed as err:
        return CheckResult(name, False, str(err), "malformed")
    if _close(A, E, tol):
        return CheckResult(name, True, "correct.", "correct")
    hint = _diagnose(ex, M if ex.kind == "symbolic" else None, A, E, mistakes, tol)
    if ex.tip and ex.tip not in hint:
        hint = f"{hint} Hint: {ex.tip}"
    return CheckResult(name, False, hint, "wrong")
