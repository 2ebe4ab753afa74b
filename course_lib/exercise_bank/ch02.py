r"""Exercises of chapter 2 (§0.1.2 rotations, SO(3), coordinate changes, the hat map)."""

from course_lib.exercises._model import Choice, Exercise, Expr, Value, Variants
from course_lib.symbolic import A, B, R, X, Y, d

CHAPTER = 2
SETUP = (
    "import numpy as np\nimport sympy as sp\n\n"
    "from course_lib.exercises import A, B, R, X, Y, check, d, hat, parameters, x, y"
)

EXERCISES = [
    Exercise(
        name="which_in_so3",
        chapter=2,
        number=1,
        level="warm-up",
        title="Which products are rotations?",
        statement=r"""
Let $R, S \in$ SO(3) be any two rotations and $M$ any reflection ($M^TM = I$, $\det M = -1$).
Which of these matrices are **always** in SO(3) (Definition 2)?

(a) $RSR^T$ &nbsp; (b) $-R$ &nbsp; (c) $R^T S$ &nbsp; (d) $M R M$ &nbsp; (e) $R + S - I$ &nbsp;
(f) $M R$

Give the set of letters, e.g. `{"a", "c"}` or the string `"ac"`.
""",
        answer=Choice(letters="abcdef"),
        tip="For each, check XᵀX = I (Proposition 3) and det X = +1 (Proposition 4): use "
        "(XY)ᵀ = YᵀXᵀ, det(XY) = det X det Y and det(−X) = (−1)³ det X.",
        mistakes={
            "orthogonal": "XᵀX = I is not enough: a rotation also has det = +1 "
            "(Proposition 4). Recheck the determinants.",
            "two_reflections": "recheck the products with reflections in them: what does each "
            "factor do to the determinant, and is a product of orthogonal matrices orthogonal?",
            "sum": "recheck the sums: is a sum of rotations orthogonal? Try a simple example "
            "and compute XᵀX.",
            "minus": "recheck the negated matrices: what is det(−X) for a 3x3 matrix X?",
        },
    ),
    Exercise(
        name="vb_from_va",
        chapter=2,
        number=2,
        level="warm-up",
        title="From a-coordinates to b-coordinates",
        statement=r"""
Two of frame $B$'s axes, written in frame $A$, are $x_{ab} = <<x_ab>>$ and
$y_{ab} = <<y_ab>>$; $B$ is right-handed. A vector has the coordinates $v_a = <<v_a>>$ in
$A$. Find its coordinates $v_b$ in $B$ (equation (64) read backwards). Give a 3-vector.
""",
        answer=Value(shape=(3,)),
        tip="The third axis is z_ab = x_ab × y_ab; then v_a = R_ab v_b, and R_ab⁻¹ = R_abᵀ "
        "(Proposition 5).",
        mistakes={
            "direction": "R_ab turns b-coordinates into a-coordinates (v_a = R_ab v_b); "
            "you need the other direction, R_ba = R_abᵀ.",
            "left_handed": "your z_ab points the wrong way: a right-handed frame has "
            "z_ab = x_ab × y_ab, in that order.",
        },
        variants=Variants("ch02_frame", {"x_ab": [0, 0, 1], "y_ab": [1, 0, 0], "v_a": [1, 2, 3]}),
    ),
    Exercise(
        name="complete_rotation",
        chapter=2,
        number=3,
        level="core",
        title="Complete a rotation matrix",
        statement=r"""
Find the three missing entries $(a, b, c)$ that make
$R = <<R>>$
a rotation matrix (Proposition 3: its columns are orthonormal). Give the 3-vector
$(a, b, c)$, and check $\det R = +1$.
""",
        answer=Value(shape=(3,)),
        tip="Unit columns fix |a|, |b| and |c|; perpendicular columns (r₁ · r₃ = 0, "
        "r₁ · r₂ = 0) then fix their signs.",
        mistakes={
            "abs": "the unit lengths fix only |a|, |b|, |c|: the signs come from the "
            "orthogonality of the columns, r₁ · r₃ = 0 and r₁ · r₂ = 0."
        },
        variants=Variants(
            "ch02_missing",
            {"R": [["2/3", "-2/3", "a"], ["1/3", "b", "-2/3"], ["c", "1/3", "2/3"]]},
        ),
    ),
    Exercise(
        name="inverse_of_product",
        chapter=2,
        number=4,
        level="core",
        title="Undoing two rotations",
        statement=r"""
Let `A` stand for $R_{ab}$ and `B` for $R_{cb}$ (two rotation matrices, `MatrixSymbol`s; mind
the order of the subscripts of `B`). Write $R_{ca}$ in terms of `A` and `B`, **without an
inverse**, using (64) for each pair of frames and Proposition 5. Give a matrix expression in
`A`, `B` (products and `.T`).
""",
        answer=Expr(shape=(3, 3), allowed=(A, B), matrix_degree=2),
        tip="Write how v_c follows from v_a one frame at a time (eq. 64), then use "
        "Proposition 5 for the step that goes against a subscript.",
        mistakes={
            "order": "order: in a product of frame changes the inner subscripts must meet; "
            "check which factor comes first.",
            "forward": "that is R_ac; the exercise asks for the opposite direction, R_ca = R_acᵀ.",
            "bc": "B stands for R_cb, not R_bc: mind the order of its subscripts.",
        },
    ),
    Exercise(
        name="rigid_inverse",
        chapter=2,
        number=5,
        level="core",
        title="The inverse of a rigid motion",
        statement=r"""
A rigid body transformation is $g(p) = Rp + d$ with a rotation $R$ (`R`) and a translation
$d$ (`d`, a 3x1 `MatrixSymbol`). Its inverse has the same shape,
$g^{-1}(q) = R^T q + e$. Find $e$ in terms of `R` and `d`, without an inverse.
Give a 3x1 matrix expression.
""",
        answer=Expr(shape=(3,), allowed=(R, d), matrix_degree=2),
        tip="g⁻¹(g(p)) = p for every p; try p = 0 first.",
        mistakes={
            "minus_d": "check g⁻¹(g(0)) = 0: g(0) = d, and g⁻¹ first rotates d by Rᵀ.",
            "no_transpose": "undo the rotation with R⁻¹ = Rᵀ: check g⁻¹(g(0)) = 0.",
        },
    ),
    Exercise(
        name="hat_product",
        chapter=2,
        number=6,
        level="challenge",
        title="A product of two hat matrices",
        statement=r"""
For vectors $x, y$, show that $\hat x \hat y + (x^T y)\, I$ is an outer product of two vectors:
apply it to a vector $v$, use $\hat x v = x \times v$ (Definition 5) and the expansion of a
double cross product (problem set 1, exercise 1.6). Write it in terms of
`X` and `Y`, the 3x1 `MatrixSymbol`s standing for $x$ and $y$ (products and `.T`; no hat).
Give a 3x3 matrix expression.
""",
        answer=Expr(shape=(3, 3), allowed=(X, Y), matrix_degree=2),
        tip="x̂ŷv = x × (y × v); expand the double cross product (exercise 1.6 of chapter 1).",
    ),
    Exercise(
        name="two_mirrors",
        chapter=2,
        number=7,
        level="challenge",
        title="Two mirrors make a rotation",
        statement=r"""
The mirrors $M_i = I - 2 n_i n_i^T$ have the unit normals $n_1 = (1, 0, 0)$ and
$n_2 = (\cos\psi, \sin\psi, 0)$. Show that $R = M_2 M_1$ is in SO(3) (each $M_i$ is
orthogonal with $\det M_i = -1$) and that it is a rotation about $z$, $R = R_z(\theta)$; find
$\theta$ as a function of $\psi$. Then find the $\psi \in (0, \pi)$ for which
$M_2 M_1 = R_z(<<turn>>°)$. Give $\psi$ (radians).
""",
        answer=Value(shape=(), angle=True),
        tip="Compute R = M₂M₁ with sympy for a symbolic ψ and compare its first column with "
        "(cos θ, sin θ, 0).",
        mistakes={
            "double": "that ψ makes M₂M₁ turn by twice that angle: two reflections turn by "
            "twice the angle between their mirrors.",
            "order": "with that ψ it is M₁M₂ that equals R_z(<<turn>>°): R = M₂M₁ applies M₁ "
            "first.",
        },
        variants=Variants("ch02_mirrors", {"turn": 100}),
    ),
]
