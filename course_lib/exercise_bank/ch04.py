r"""Exercises of chapter 4 (working with rotations: composition, axis and angle, logarithm)."""

from course_lib.exercises._model import Exercise, Expr, Value, Variants
from course_lib.symbolic import alpha, beta

CHAPTER = 4
SETUP = (
    "import numpy as np\nimport sympy as sp\n\n"
    "from course_lib.exercises import alpha, beta, check, parameters"
)

_FRAMES = r"""Frame $B$'s axes, written in $A$, are $x_{ab} = <<x_ab>>$, $y_{ab} = <<y_ab>>$,
$z_{ab} = <<z_ab>>$; frame $C$'s axes, written in $B$, are $x_{bc} = <<x_bc>>$,
$y_{bc} = <<y_bc>>$, $z_{bc} = <<z_bc>>$."""
#: The numbers of exercises 4.1 and 4.2, which share them (variant 0: the course's own).
_FRAMES_VARIANTS = Variants(
    "ch04_frames",
    {"x_ab": [0, 0, -1], "y_ab": [0, 1, 0], "z_ab": [1, 0, 0], "x_bc": [0, 0, 1],
     "y_bc": [1, 0, 0], "z_bc": [0, 1, 0], "v_c": [1, 2, 3]},
)  # fmt: skip

EXERCISES = [
    Exercise(
        name="compose_frames",
        chapter=4,
        number=1,
        level="warm-up",
        title="Composing two frames",
        statement=_FRAMES
        + r"""
Find $R_{ac}$, the axes of $C$ written in $A$. Give a 3x3 array or matrix.
""",
        answer=Value(shape=(3, 3), rotation=True),
        tip="Form R_ab and R_bc from the axes (as columns) and let the subscripts cancel.",
        mistakes={
            "order": "the subscripts must cancel: R_ac = R_ab R_bc (the two inner b's "
            "meet), not R_bc R_ab.",
            "rows": "the axes of a frame are the columns of its rotation matrix, not its "
            "rows: R_ab = [x_ab y_ab z_ab].",
        },
        variants=_FRAMES_VARIANTS,
    ),
    Exercise(
        name="chain_vector",
        chapter=4,
        number=2,
        level="warm-up",
        title="A vector through a chain of frames",
        statement=r"""With the frames of exercise 4.1, a vector has the coordinates
$v_c = <<v_c>>$ in $C$. Find its coordinates $v_a$ in $A$. Give a 3-vector.
""",
        answer=Value(shape=(3,)),
        tip="v_b = R_bc v_c, then v_a = R_ab v_b.",
        mistakes={
            "order": "the frames are passed in the wrong order: first C to B (R_bc), then B to "
            "A (R_ab).",
            "inverse": "that goes from A to C; the exercise goes from C to A: v_a = R_ac v_c.",
            "rows": "the axes of a frame are the columns of its rotation matrix, not its "
            "rows: R_bc = [x_bc y_bc z_bc].",
        },
        variants=_FRAMES_VARIANTS,
    ),
    Exercise(
        name="angle_from_trace",
        chapter=4,
        number=3,
        level="warm-up",
        title="The angle of a rotation from its trace",
        statement=r"""
Of a rotation matrix $R$ only the diagonal entries are known: $R_{11} = <<R11>>$,
$R_{22} = <<R22>>$, $R_{33} = <<R33>>$. Find its angle $\theta \in [0, \pi]$ from
$\operatorname{tr} R = 1 + 2\cos\theta$. Give a number (radians).
""",
        answer=Value(shape=(), angle=True),
        tip="tr R = 1 + 2 cos θ, so cos θ = (tr R − 1)/2; the off-diagonal entries are not needed.",
        mistakes={
            "cosine": "that is cos θ; the exercise asks for θ itself.",
            "no_minus_one": "tr R = 1 + 2 cos θ: subtract the 1 before halving.",
        },
        variants=Variants("ch04_trace", {"R11": 0.6, "R22": 0.1, "R33": -0.2}),
    ),
    Exercise(
        name="axis_of_rotation",
        chapter=4,
        number=4,
        level="core",
        title="The axis of a rotation",
        statement=r"""
Of a rotation $R = e^{\hat\omega\theta}$ with $\theta \in (0, \pi)$ we know only its trace,
$\operatorname{tr} R = <<trace_tex>>$, and its skew part
$R - R^T = <<factor_tex>><<M>>$. Find the unit axis $\omega$ from
$R - R^T = 2\sin\theta\,\hat\omega$. Give a 3-vector.
""",
        answer=Value(shape=(3,)),
        tip="The trace gives θ (so sin θ); then read ω̂ off (R − Rᵀ)/(2 sin θ): "
        "ω = (entry (3,2), entry (1,3), entry (2,1)).",
        mistakes={
            "unnormalized": "an axis is a unit vector: divide by 2 sin θ (or by its length).",
            "no_two": "R − Rᵀ is twice the skew part sin θ ω̂: mind the factor 2.",
            "sign": "that axis points the other way: in ω̂ the entry (3, 2) is +ω₁ and the "
            "entry (2, 3) is −ω₁ (likewise for ω₂ and ω₃); read each one below or above the "
            "diagonal accordingly.",
        },
        variants=Variants(
            "ch04_axis",
            {
                "trace_tex": "0",
                "factor_tex": r"\frac{1}{\sqrt3}",
                "M": [[0, -2, 1], [2, 0, -2], [-1, 2, 0]],
                "trace": 0,
                "factor": 3**-0.5,
            },
        ),  # fmt: skip
    ),
    Exercise(
        name="fixed_vs_body",
        chapter=4,
        number=5,
        level="core",
        title="Fixed axes and body axes",
        statement=r"""
A camera starts aligned with the world frame ($R = I$). It turns by <<a1>>° about the world
$<<axis1>>$ axis, then by <<a2>>° about its **own** (current) $<<axis2>>$ axis, then by <<a3>>°
about the **world** $<<axis3>>$ axis. Find its final orientation $R$ (its axes written in the
world frame). Give a 3x3 array.
""",
        answer=Value(shape=(3, 3), rotation=True),
        tip="A turn about a world (fixed) axis multiplies from the left, a turn about the "
        "body's own axis from the right.",
        mistakes={
            "all_body": "the last turn is about a world axis: it multiplies from the left.",
            "all_world": "the second turn is about the camera's own axis: it multiplies from "
            "the right.",
            "swapped": "the two rules are the other way round: a turn about a world axis "
            "multiplies from the left, one about the camera's own axis from the right.",
        },
        variants=Variants(
            "ch04_camera", {"a1": 90, "axis1": "z", "a2": 90, "axis2": "x", "a3": 60, "axis3": "x"}
        ),
    ),
    Exercise(
        name="composed_angle",
        chapter=4,
        number=6,
        level="core",
        title="The angle of a composed rotation",
        statement=r"""
Let $R = R_x(\alpha)\,R_z(\beta)$. Find $\cos\theta$, where $\theta$ is the rotation angle of
$R$, as an expression in `alpha` and `beta`; then check that $R_z(\beta)R_x(\alpha)$, a
different rotation, has the same angle. Give a scalar expression in `alpha` and `beta`.
""",
        answer=Expr(shape=(), domain=(alpha, beta)),
        tip="tr R = 1 + 2 cos θ; only the diagonal entries of the product are needed.",
        mistakes={
            "no_minus_one": "tr R = 1 + 2 cos θ: subtract the 1 before halving.",
            "sum": "angles add only for rotations about the same axis.",
            "angle": "that is the angle θ itself; the exercise asks for cos θ.",
        },
    ),
    Exercise(
        name="small_angle",
        chapter=4,
        number=7,
        level="challenge",
        title="The logarithm of a rotation near I",
        statement=r"""
For small angles $\alpha, \beta$ the rotation $R = R_z(\beta)\,R_x(\alpha)$ is close to
$I$, and its rotation vector $r = \omega\theta$ (with $e^{\hat r} = R$, as `so3.log` returns
it) is a power series in $\alpha$ and $\beta$. Find $r$ up to and including the terms of
second order: a 3-vector of polynomials of degree at most 2 in `alpha` and `beta`. (Expand
both factors to second order, multiply, and take the skew part $(R - R^T)/2 =
\sin\theta\,\hat\omega$; why does $\sin\theta \approx \theta$ not spoil the second order?)
""",
        answer=Expr(shape=(3,), domain=(alpha, beta)),
        tip="R_z(β) ≈ I + βẑ + β²ẑ²/2 and R_x(α) ≈ I + αx̂ + α²x̂²/2; the symmetric terms "
        "drop out of the skew part, and the skew part of ẑx̂ is ½(ẑx̂ − x̂ẑ).",
        mistakes={
            "first_order": "that is the first-order part; the product of the two first-order "
            "terms adds a term of second order: find its skew part.",
            "sign": "check the order of the factors: R_z(β) is on the left, so the cross term "
            "is βα ẑx̂, not αβ x̂ẑ.",
        },
    ),
    Exercise(
        name="two_half_turns",
        chapter=4,
        number=8,
        level="challenge",
        title="Two half turns",
        statement=r"""
Write $H(a) = R(a, \pi)$ for the half turn about a unit axis $a$. Take
$u = \frac{1}{<<n_u>>}<<q_u>>$ and $v = \frac{1}{<<n_v>>}<<q_v>>$, and the rotation
$R = H(u)\,H(v)$ (the half turn about $v$, then the one about $u$, both about fixed axes).
Find its rotation vector (exponential coordinates) $r = \omega\theta$ with a unit axis
$\omega$ and $\theta \in [0, \pi]$. Give a 3-vector.
Then explain the result without multiplying matrices: which line do both half turns map onto
itself, what does each half turn do in the plane through the origin perpendicular to that
line, and how are $\theta$ and the angle between $u$ and $v$ related?
""",
        answer=Value(shape=(3,)),
        tip="Build each half turn from the case θ = π of section 6. In the plane that holds "
        "u and v, a half turn about a line of that plane acts like a mirror. Keep θ in [0, π].",
        mistakes={
            "order": "the product is H(u) H(v), in this order: H(v) H(u) is its inverse, which "
            "turns the other way.",
            "long_way": "that vector is longer than π: its exponential is the right rotation, "
            "but the asked θ lies in [0, π]. Which other axis and angle give the same turn?",
            "single_angle": "the angle is not the angle between the two lines of the axes; find "
            "it from the trace of the product.",
            "unit_axis": "that is a unit vector; the rotation vector is ωθ, the axis times the "
            "angle.",
            "sum": "rotation vectors add only for turns about the same axis (section 7); u and "
            "v are different axes.",
        },
        variants=Variants(
            "ch04_half_turns", {"n_u": 3, "q_u": [1, 2, 2], "n_v": 3, "q_v": [-2, 1, -2]}
        ),
    ),
]
