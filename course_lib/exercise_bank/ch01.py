r"""Exercises of chapter 1 (§0.1.1 rigid bodies and rigid body motions)."""

import sympy as sp

from course_lib.exercises._model import Choice, Exercise, Expr, Value, Variants
from course_lib.symbolic import t, x, xx, xy, y, yy, z

CHAPTER = 1
SETUP = (
    "import numpy as np\nimport sympy as sp\n\n"
    "from course_lib.exercises import check, parameters, t, x, xx, xy, y, yy, z"
)

_HELIX = sp.Matrix([sp.cos(2 * t), sp.sin(2 * t), 3 * t])  # p(t), as in the statement
_TANGENT_PROPERTIES = (
    (lambda M: M.dot(M) - 1, "your vector is not a unit vector: divide ṗ by its length ‖ṗ‖."),
    (
        lambda M: M.cross(_HELIX.diff(t)),
        "your vector has length 1 but does not point along ṗ(t): differentiate each component "
        "again, minding the signs and the chain rule (d/dt cos 2t = −2 sin 2t, "
        "d/dt sin 2t = 2 cos 2t).",
    ),
)

EXERCISES = [
    Exercise(
        name="coords_by_projection",
        chapter=1,
        number=1,
        level="warm-up",
        title="Coordinates by projection",
        statement=r"""
A right-handed orthonormal frame has its origin at $o = <<o>>$, and its three axes point
along the directions $<<d1>>$, $<<d2>>$ and $<<d3>>$ (in reference
coordinates; these are directions, not yet unit vectors). The point $p$ has reference
coordinates $<<p>>$. Find its coordinates in this frame, measured from the frame's own
origin (equations (3)–(5) and the note on them). Give a 3-vector (list, numpy array or sympy
Matrix).
""",
        answer=Value(shape=(3,)),
        tip="First make the basis vectors unit vectors eᵢ; each coordinate is then the "
        "projection (p − o) · eᵢ.",
        mistakes={
            "weights": "you combined the basis vectors with the entries of p − o as weights; a "
            "coordinate is a projection, the dot product of p − o with one basis "
            "vector.",
            "no_origin": "you projected p itself; the frame's origin is o, so project the "
            "vector p − o from the origin to the point.",
            "unnormalized": "the given directions are not unit vectors: divide each by its "
            "length before projecting (equation (1)).",
        },
        variants=Variants(
            "ch01_frame",
            {"o": [1, 1, 0], "d1": [1, 1, 0], "d2": [-1, 1, 0], "d3": [0, 0, 2], "p": [3, 1, 2]},
        ),
    ),
    Exercise(
        name="angle_from_lengths",
        chapter=1,
        number=2,
        level="warm-up",
        title="An angle from three lengths",
        statement=r"""
Two vectors have the lengths $\lVert x\rVert = <<a>>$ and $\lVert y\rVert = <<b>>$, and
$\lVert x - y\rVert = \sqrt{<<m>>}$. Find the angle between the two diagonals $x - y$ and
$x + y$ of the parallelogram spanned by $x$ and $y$ (lengths and inner products only: no
coordinates are needed). Give the angle in radians, in $[0, \pi]$.
""",
        answer=Value(shape=(), angle=True),
        tip="Expand ‖x − y‖² = (x − y)ᵀ(x − y) to get xᵀy first; then expand (x − y)ᵀ(x + y) "
        "and ‖x + y‖² the same way.",
        mistakes={
            "cosine": "that is the cosine of the angle; the exercise asks for the angle itself.",
            "sign": "sign: ‖x − y‖² = ‖x‖² + ‖y‖² − 2xᵀy, so a short x − y means a positive "
            "inner product xᵀy.",
            "x_and_y": "that is the angle between x and y; the exercise asks for the angle "
            "between the diagonals x − y and x + y.",
            "reversed": "that is the angle between y − x and x + y (π minus the right one): "
            "mind the order in x − y.",
        },
        variants=Variants("ch01_lengths", {"a": 3, "b": 4, "m": 13}),
    ),
    Exercise(
        name="which_are_rigid",
        chapter=1,
        number=3,
        level="core",
        title="Which maps are rigid body transformations?",
        statement=r"""
Which of these maps $g:\mathbb{R}^3\to\mathbb{R}^3$ are rigid body transformations in the sense
of Definition 1 (they keep every distance **and** the cross product,
$g_*(v) \times g_*(w) = g_*(v \times w)$)? Write each as $g(p) = Mp + d$ first.

(a) the reflection in the plane $x = y$ &nbsp;
(b) the half turn about the line through the origin along $(1, 1, 0)$ &nbsp;
(c) the point reflection $p \mapsto -p$, followed by the half turn about the $z$ axis &nbsp;
(d) the reflection in the plane $x = 0$, followed by the reflection in the plane $y = 0$ &nbsp;
(e) the translation by $(1, 2, 3)$, followed by the quarter turn about the $x$ axis &nbsp;
(f) the point reflection $p \mapsto -p$, followed by the translation by $(0, 0, 1)$

Give the set of letters, e.g. `{"a", "c"}` or the string `"ac"`.
""",
        answer=Choice(letters="abcdef"),
        tip="Every map here keeps distances; test the cross product on e₁, e₂: is "
        "g_*(e₁) × g_*(e₂) = g_*(e₃)? (For g(p) = Mp + d that is det M = +1.)",
        mistakes={
            "mirrors": "recheck the handedness: for each map compare g_*(e₁) × g_*(e₂) with "
            "g_*(e₃).",
            "translation": "recheck what Definition 1 allows: what does a translation do to "
            "the difference of two points?",
            "two_mirrors": "recheck the maps made of two reflections: what does each one do "
            "to the handedness?",
            "point_reflection": "recheck the maps built from p ↦ −p: what is det(−I) in three "
            "dimensions, and what does a turn after it change?",
        },
    ),
    Exercise(
        name="unit_tangent",
        chapter=1,
        number=4,
        level="core",
        title="The unit tangent of a helix",
        statement=r"""
A particle follows the helix $p(t) = (\cos 2t,\ \sin 2t,\ 3t)$ (a trajectory as in equation
(6)). Find the unit tangent $T(t) = \dot p(t) / \lVert \dot p(t)\rVert$ in the time symbol `t`,
**simplified**: no square root of an expression in $t$ may be left. Give a 3-vector.
""",
        answer=Expr(shape=(3,), domain=(t,), no_roots=True),
        tip="Differentiate each component (mind the chain rule), then simplify ‖ṗ‖ with "
        "sin² + cos² = 1.",
        mistakes={
            "velocity": "that is the velocity ṗ; divide it by its length ‖ṗ‖ (a unit "
            "vector has length 1)."
        },
        properties=_TANGENT_PROPERTIES,
    ),
    Exercise(
        name="lagrange_identity",
        chapter=1,
        number=5,
        level="core",
        title="The length of a cross product",
        statement=r"""
For the generic vectors `x`, `y`, write $\lVert x \times y\rVert^2$ in terms of the three
numbers $x^Tx$, $y^Ty$ and $x^Ty$ only: use the symbols `xx`, `yy`, `xy` (standing for
$x^Tx$, $y^Ty$, $x^Ty$). Expand both sides in components with sympy to find and confirm the
formula. Give a scalar expression in `xx`, `yy`, `xy`.
""",
        answer=Expr(shape=(), domain=tuple(x) + tuple(y), allowed=(xx, yy, xy)),
        tip="Try x = y (the cross product vanishes) and x ⊥ y (it has length ‖x‖‖y‖).",
        mistakes={
            "plus": "sign: for x = y the cross product is 0, so your two terms must cancel there."
        },
    ),
    Exercise(
        name="bac_cab",
        chapter=1,
        number=6,
        level="challenge",
        title="A double cross product",
        statement=r"""
For the generic vectors `x`, `y`, `z`, the vector $x \times (y \times z)$ lies in the plane of
$y$ and $z$: $x \times (y \times z) = \alpha\, y + \beta\, z$. Find the scalars $\alpha$ and
$\beta$ as expressions in the components of $x, y, z$ (derive it from the components; check it
with sympy). Give the pair $(\alpha, \beta)$ as a list of two expressions.
""",
        answer=Expr(shape=(2,), domain=tuple(x) + tuple(y) + tuple(z)),
        tip="Compare the first component of both sides; α and β are inner products.",
        mistakes={"swapped": "you swapped α and β: α is the coefficient of y."},
    ),
    Exercise(
        name="motion_from_points",
        chapter=1,
        number=7,
        level="challenge",
        title="A motion from three points",
        statement=r"""
A rigid body transformation $g(p) = Rp + d$ maps the three points $a = <<a>>$,
$b = <<b>>$ and $c = <<c>>$ to $g(a) = <<ga>>$, $g(b) = <<gb>>$ and
$g(c) = <<gc>>$. Find $R$. None of the points is the origin or a basis vector, and
$b - a$, $c - a$ are not perpendicular, so no column of $R$ can be read off directly: use what
Definition 1 says about differences of points and about cross products.
Give a 3x3 array or matrix.
""",
        answer=Value(shape=(3, 3), rotation=True),
        tip="A difference of two points loses d; three known vectors and their known images "
        "give one matrix equation for R.",
        mistakes={
            "mirror": "your matrix turns the frame inside out: the image of a cross product "
            "is the cross product of the images, in the same order (condition 2).",
            "points": "you used the points themselves, so d is mixed into your R: work with "
            "differences of points, which d does not change.",
            "columns": "b − a is not a basis vector, so R(b − a) is not a column of R: relate "
            "R to the vectors you know and solve for it.",
        },
        variants=Variants(
            "ch01_motion",
            {
                "a": [3, 3, 0],
                "b": [0, 3, 3],
                "c": [3, 0, 3],
                "ga": [2, 6, 4],
                "gb": [2, 3, 7],
                "gc": [5, 3, 4],
            },
        ),  # fmt: skip
    ),
]
