r"""Exercises of chapter 3 (§0.1.3 exponential coordinates)."""

import sympy as sp

from course_lib.exercises._model import Exercise, Expr, Value
from course_lib.symbolic import W, a, omega, t, theta, u, x_0

CHAPTER = 3
SETUP = ("import numpy as np\nimport sympy as sp\n"
         "from course_lib.exercises import check, hat, omega, theta, W, u, a, t, x_0")

_W = tuple(omega)
_ODE_PROPERTIES = (
    (lambda M: M[0].subs(t, 1) - x_0, "the initial condition fails: your x(1) is not x₀."),
    (lambda M: M[0].diff(t) - a * M[0],
     "x(1) = x₀ holds, but your x(t) does not satisfy ẋ = a x."),
)
_PLANAR_PROPERTIES = (
    (lambda M: M.subs(t, 0) - sp.Matrix([x_0, 0]),
     "the initial condition fails: your x(0) is not (x₀, 0)."),
    (lambda M: M.diff(t) - sp.Matrix([[0, -a], [a, 0]]) * M,
     "x(0) = (x₀, 0) holds, but your x(t) does not satisfy ẋ = A x."),
)

EXERCISES = [
    Exercise(
        name="ode_shifted", chapter=3, number=1, level="warm-up",
        title="The scalar ODE with a later start",
        statement=r"""
Solve $\dot x(t) = a\,x(t)$ with the condition $x(1) = x_0$ given at time $t = 1$ (not at
$t = 0$; compare equations (95)–(106)). Give $x(t)$ as an expression in `a`, `t`, `x_0`.
""",
        answer=Expr(shape=(), domain=(a, t, x_0)),
        tip="Every solution is C e^{at}; choose the constant C so that x(1) = x₀.",
        mistakes={"at_zero": "that solution has x(0) = x₀; here the condition is given at "
                             "t = 1."},
        properties=_ODE_PROPERTIES,
    ),
    Exercise(
        name="pendulum_speed", chapter=3, number=2, level="warm-up",
        title="The speed of a pendulum",
        statement=r"""
A pendulum of length $r = 2$ m swings with the angle $\theta(t) = \frac{\pi}{6}\cos 3t$
(radians, $t$ in seconds). Using $\omega = \dot\theta$ (117) and $\lVert v\rVert = |r\omega|$
(118), find the speed of its tip at $t = \pi/6$ s, in m/s. Give a number.
""",
        answer=Value(shape=()),
        tip="Differentiate θ(t) (chain rule: the 3 comes out), then evaluate at t = π/6.",
        mistakes={"angle": "that is r θ(t), a length; the speed uses the angular rate θ̇ "
                           "(equation (117))."},
    ),
    Exercise(
        name="hat_fifth", chapter=3, number=3, level="core",
        title="The fifth power of a hat matrix, ω not unit",
        statement=r"""
Here $\omega$ (`omega`) is **any** nonzero vector, not a unit one. Let `W` stand for
$\hat\omega$ (a `MatrixSymbol`). Reduce $\hat\omega^5$ to a polynomial of degree at most 2 in
`W` whose coefficients are expressions in $\omega_1, \omega_2, \omega_3$ (first find
$\hat\omega^3$ for a general $\omega$, as in equations (142)–(148)). Give a matrix expression
in `W`.
""",
        answer=Expr(shape=(3, 3), domain=_W, allowed=(W, *_W), matrix_degree=2),
        tip="For a general ω, ω̂³ = ω̂ω̂² with ω̂² = ωωᵀ − ‖ω‖²I (eq. 140 before ‖ω‖ = 1).",
        mistakes={"unit": "that holds for a unit ω only; for a general one ω̂³ = −‖ω‖² ω̂, "
                          "and the factor ‖ω‖² comes back at every second power."},
    ),
    Exercise(
        name="half_turn", chapter=3, number=4, level="core",
        title="Rodrigues' formula at a half turn",
        statement=r"""
For a **unit** axis $\omega$, evaluate Rodrigues' formula (159) at $\theta = \pi$ and write
$e^{\hat\omega\pi}$ in terms of `u`, a 3x1 `MatrixSymbol` standing for $\omega$, and the
identity (`sp.Identity(3)` or `sp.eye(3)`); no hat. Give a 3x3 matrix expression.
""",
        answer=Expr(shape=(3, 3), domain=_W, allowed=(u,), unit_omega=True, matrix_degree=2),
        tip="At θ = π, sin θ = 0 and 1 − cos θ = 2; then use ω̂² = ωωᵀ − I for a unit ω.",
        mistakes={
            "mirror": "that matrix has det −1 (a mirror, not a rotation): check the sign of the "
                      "ω̂² term of Rodrigues' formula at θ = π.",
            "inner": "ωᵀω is the inner product, a number (1 here); ω̂² needs the outer product "
                     "ωωᵀ, a 3x3 matrix (u * u.T).",
        },
    ),
    Exercise(
        name="rodrigues_derivative", chapter=3, number=5, level="core",
        title="The derivative of Rodrigues' formula",
        statement=r"""
For a **unit** axis $\omega$, differentiate Rodrigues' formula (159) with respect to
$\theta$ and write $\frac{d}{d\theta} e^{\hat\omega\theta}$ as a polynomial of degree at most
2 in `W` (standing for $\hat\omega$) with coefficients in $\theta$. Then check that it equals
$\hat\omega\, e^{\hat\omega\theta}$. Give a matrix expression in `W` and `theta`.
""",
        answer=Expr(shape=(3, 3), domain=(*_W, theta), allowed=(W, theta), unit_omega=True,
                    matrix_degree=2),
        tip="Differentiate the coefficients of I, ω̂, ω̂²; to compare with ω̂R reduce ω̂³ = −ω̂.",
    ),
    Exercise(
        name="planar_ode", chapter=3, number=6, level="core",
        title="A linear ODE in the plane",
        statement=r"""
Solve $\dot x = A x$ with $A = \begin{pmatrix} 0 & -a \\ a & 0 \end{pmatrix}$ and
$x(0) = (x_0, 0)$ (the two-dimensional case of equation (121)). Give $x(t)$ as a 2-vector of
expressions in `a`, `t`, `x_0`, and check that it satisfies both conditions.
""",
        answer=Expr(shape=(2,), domain=(a, t, x_0)),
        tip="Differentiate the first equation once more: ẍ₁ = −a² x₁.",
        mistakes={"direction": "check the direction of turning: ẋ₂(0) = a x₁(0) = a x₀."},
        properties=_PLANAR_PROPERTIES,
    ),
    Exercise(
        name="exp_general_axis", chapter=3, number=7, level="challenge",
        title="The exponential of a hat matrix, ω not unit",
        statement=r"""
For **any** nonzero $\omega$ (not a unit vector), sum the series (134) for
$e^{\hat\omega\theta}$ in closed form, $e^{\hat\omega\theta} = I + \alpha\,\hat\omega +
\beta\,\hat\omega^2$, with coefficients $\alpha, \beta$ in $\theta$ and
$\lVert\omega\rVert = \sqrt{\omega_1^2 + \omega_2^2 + \omega_3^2}$. Give a matrix expression of
degree at most 2 in `W` (standing for $\hat\omega$), e.g.
`sp.eye(3) + c1 * W + c2 * W**2` with your α and β as `c1` and `c2`.
""",
        answer=Expr(shape=(3, 3), domain=(*_W, theta), allowed=(W, theta, *_W),
                    matrix_degree=2),
        tip="Write ω = ‖ω‖ n with a unit n: then ω̂θ = n̂ (‖ω‖θ).",
        mistakes={"unit": "that is Rodrigues' formula for a unit axis; here ω̂³ = −‖ω‖² ω̂, "
                          "so redo the regrouping of the series with that factor."},
    ),
    Exercise(
        name="spatial_angular_velocity", chapter=3, number=8, level="challenge",
        title="The angular velocity of a composed motion",
        statement=r"""
A body turns with $R(t) = R_x(t)\,R_z(t)$ (unit rates about the $x$ axis and about $z$).
Find its angular velocity $\omega(t)$ with $\dot R R^T = \hat\omega$ (compare equations
(120)–(125)). Give a 3-vector in `t`.
""",
        answer=Expr(shape=(3,), domain=(t,)),
        tip="Ṙ = Ṙ_x R_z + R_x Ṙ_z; then R_x ẑ R_xᵀ is the hat of R_x e₃ (Proposition 6).",
        mistakes={
            "body": "that is the body angular velocity (RᵀṘ = ω̂_b); the exercise asks for "
                    "ṘRᵀ.",
            "sum": "the z axis is turned by the first rotation: the second term is the hat of "
                   "R_x(t) e₃, not of e₃.",
        },
    ),
]
