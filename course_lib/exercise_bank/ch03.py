r"""Exercises of chapter 3 (§0.1.3 exponential coordinates)."""

from course_lib.exercises._model import Exercise, Expr, Value, Variants
from course_lib.symbolic import W, omega, t, theta, u

CHAPTER = 3
SETUP = (
    "import numpy as np\nimport sympy as sp\n\n"
    "from course_lib.exercises import W, a, check, hat, omega, parameters, t, theta, u, x_0"
)

_W = tuple(omega)

#: What problem set 3 needs besides chapter 3 (its header says so).
READS = (
    "Read chapter 3 first. The exercises also use chapter 2's hat map $\\hat\\omega$, and 3.8 "
    "uses chapter 2's Proposition 6, $R\\hat\\omega R^T = (R\\omega)^\\wedge$."
)

EXERCISES = [
    Exercise(
        name="ode_shifted",
        chapter=3,
        number=1,
        level="warm-up",
        title="The scalar ODE from two measurements",
        statement=r"""
A quantity obeys $\dot x(t) = a\,x(t)$ with an unknown constant $a$ (equation (95)). It is
measured twice: $x(<<t1>>) = <<x1>>$ and $x(<<t2>>) = <<x2>>$. Using the solution (106), find
$a$ and the initial value $x(0)$. Give the pair $(a,\ x(0))$ (numbers; exact sympy values are fine).
""",
        answer=Value(shape=(2,)),
        tip="Write the solution (106) down twice, once at each measurement time. Which "
        "combination of the two equations no longer contains x(0)?",
        mistakes={
            "interval": "the ratio of the two measurements depends on the time between them: "
            "they are <<gap>> time units apart, not <<t2>>.",
            "at_zero": "x(<<t1>>) = <<x1>> is measured at t = <<t1>>, not at t = 0: put "
            "t = <<t1>> into (106) and solve for x(0).",
            "no_division": "the log of the ratio is a·(<<t2>> − <<t1>>), the rate times the "
            "time between the measurements: divide it by that time to get a.",
        },
        variants=Variants("ch03_growth", {"t1": 1, "x1": 3, "t2": 3, "x2": 12, "gap": 2}),
    ),
    Exercise(
        name="pendulum_speed",
        chapter=3,
        number=2,
        level="warm-up",
        title="The speed of a pendulum",
        statement=r"""
A pendulum of length $r = <<r>>$ m swings with the angle $\theta(t) = \frac{\pi}{<<n>>}\cos <<k>>t$
(radians, $t$ in seconds). Using $\omega = \dot\theta$ (117) and $\lVert v\rVert = |r\omega|$
(118), find the speed of its tip at $t = \pi/<<q>>$ s, in m/s. Give a number.
""",
        answer=Value(shape=()),
        tip="A speed comes from the rate of the angle, not from the angle: see how chapter 3 "
        "gets ‖v‖ of the pendulum from θ(t), (117)-(118).",
        mistakes={
            "angle": "that is r θ(t) at t = π/<<q>>, the arc length from the bottom: a length, "
            "not a speed; the speed uses the angular rate θ̇ (equation (117)).",
            "no_length": "that is the angular speed |θ̇| (rad/s); the tip moves with the speed "
            "|r θ̇| (equation (118)), and r = <<r>> m.",
            "no_chain": "the chain rule: d/dt cos <<k>>t = −<<k>> sin <<k>>t, so θ̇ has a factor "
            "<<k>>.",
            "signed": "that is the velocity r θ̇ with its sign; a speed is a length, "
            "‖v‖ = |r ω| (equation (118)), never negative.",
        },
        variants=Variants("ch03_pendulum", {"r": 2, "n": 6, "k": 3, "q": 6}),
    ),
    Exercise(
        name="hat_fifth",
        chapter=3,
        number=3,
        level="core",
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
        mistakes={
            "unit": "that holds for a unit ω only: redo ω̂³ for a general ω (what does "
            "ωᵀω equal when ‖ω‖ ≠ 1?) and follow that factor through the higher powers."
        },
    ),
    Exercise(
        name="half_turn",
        chapter=3,
        number=4,
        level="core",
        title="Rodrigues' formula at a half turn",
        statement=r"""
For a **unit** axis $\omega$, evaluate Rodrigues' formula (159) at $\theta = \pi$ and write
$e^{\hat\omega\pi}$ in terms of `u`, a 3x1 `MatrixSymbol` standing for $\omega$, and the
identity (`sp.Identity(3)` or `sp.eye(3)`); no hat. Give a 3x3 matrix expression.
""",
        answer=Expr(shape=(3, 3), domain=_W, allowed=(u,), unit_omega=True, matrix_degree=2),
        tip="Evaluate the two coefficients of (159) at θ = π first; then write ω̂² without a "
        "hat, using (140) for a unit ω.",
        mistakes={
            "mirror": "that matrix has det −1 (a mirror, not a rotation): check the sign of the "
            "ω̂² term of Rodrigues' formula at θ = π.",
            "inner": "ωᵀω is the inner product, a number (1 here); ω̂² needs the outer product "
            "ωωᵀ, a 3x3 matrix (u * u.T).",
        },
    ),
    Exercise(
        name="rodrigues_derivative",
        chapter=3,
        number=5,
        level="core",
        title="The derivative of Rodrigues' formula",
        statement=r"""
For a **unit** axis $\omega$, differentiate Rodrigues' formula (159) with respect to
$\theta$ and write $\frac{d}{d\theta} e^{\hat\omega\theta}$ as a polynomial of degree at most
2 in `W` (standing for $\hat\omega$) with coefficients in $\theta$. Then check that it equals
$\hat\omega\, e^{\hat\omega\theta}$. Give a matrix expression in `W` and `theta`.
""",
        answer=Expr(
            shape=(3, 3), domain=(*_W, theta), allowed=(W, theta), unit_omega=True, matrix_degree=2
        ),
        tip="Differentiate the coefficients of I, ω̂, ω̂²; to compare with ω̂R reduce ω̂³ = −ω̂.",
    ),
    Exercise(
        name="planar_ode",
        chapter=3,
        number=6,
        level="core",
        title="A linear ODE in the plane",
        statement=r"""
The solution of $\dot x = A x$ with $A = \begin{pmatrix} 0 & -a \\ a & 0 \end{pmatrix}$ and
$x(0) = (x_0, 0)$ (the two-dimensional case of equation (121)) passes through the point
$<<point>>$ at time $t = 1$. Solve the ODE for general $a$ and $x_0$ first, then find the
smallest $a > 0$ and the $x_0$ for which this happens. Give the pair $(a,\ x_0)$.
""",
        answer=Value(shape=(2,)),
        tip="Chapter 3 solves such an ODE with the matrix exponential (Definition 6 and the "
        "Result right after it). As in its section 'Closing the Exponential', look at the "
        "powers of A first: which simple matrix is A²?",
        mistakes={
            "direction": "check the direction of turning: ẋ₂(0) = a x₁(0) = a x₀, so for "
            "a > 0 the point turns counterclockwise.",
            "larger": "that a works, but a smaller positive a does too.",
            "next_turn": "that a works (a full turn more), but a smaller positive a does too.",
            "degrees": "a is a rate in radians per unit time, as everywhere in the notes: give "
            "it in radians, not degrees.",
        },
        variants=Variants("ch03_planar", {"point": [0, 2]}),
    ),
    Exercise(
        name="exp_general_axis",
        chapter=3,
        number=7,
        level="challenge",
        title="The exponential of a hat matrix, ω not unit",
        statement=r"""
For **any** nonzero $\omega$ (not a unit vector), sum the series (134) for
$e^{\hat\omega\theta}$ in closed form, $e^{\hat\omega\theta} = I + \alpha\,\hat\omega +
\beta\,\hat\omega^2$, with coefficients $\alpha, \beta$ in $\theta$ and
$\lVert\omega\rVert = \sqrt{\omega_1^2 + \omega_2^2 + \omega_3^2}$. Give a matrix expression of
degree at most 2 in `W` (standing for $\hat\omega$), e.g.
`sp.eye(3) + c1 * W + c2 * W**2` with your α and β as `c1` and `c2`.
""",
        answer=Expr(shape=(3, 3), domain=(*_W, theta), allowed=(W, theta, *_W), matrix_degree=2),
        tip="Rodrigues' formula (159) needs a unit axis: which unit axis and which angle "
        "give the same exponent ω̂θ?",
        mistakes={
            "unit": "that is Rodrigues' formula for a unit axis; here ω̂³ = −‖ω‖² ω̂, "
            "so redo the regrouping of the series with that factor."
        },
    ),
    Exercise(
        name="spatial_angular_velocity",
        chapter=3,
        number=8,
        level="challenge",
        title="The angular velocity of a composed motion",
        statement=r"""
A body turns with $R(t) = R_x(t)\,R_z(t)$ (unit rates about the $x$ axis and about $z$).
Its angular velocity $\omega(t)$ is defined by $\dot R R^T = \hat\omega$: a point fixed in the
body, $q(t) = R(t)q_0$, moves with $\dot q = \dot R R^T q$, which is (122) with this
$\hat\omega$. Here $\omega$ changes with $t$, so $R(t)$ is not $e^{\hat\omega t}$. Find
$\omega(t)$; give a 3-vector in `t`.
""",
        answer=Expr(shape=(3,), domain=(t,)),
        tip="Use the product rule on R = R_x R_z: ṘRᵀ splits into one term per turn. Chapter "
        "2's Proposition 6 turns each term into a hat.",
        mistakes={
            "body": "that is the body angular velocity (RᵀṘ = ω̂_b); the exercise asks for ṘRᵀ.",
            "sum": "the term of the turn about z is not the hat of e₃ alone: look again at what "
            "stands on either side of it in ṘRᵀ.",
        },
    ),
]
