r"""Exercises of chapter 2 (§0.1.2 rotations, SO(3), coordinate changes, the hat map)."""

from course_lib.exercises._model import Choice, Exercise, Expr, Value
from course_lib.symbolic import A, B, R, X, Y, d

CHAPTER = 2
SETUP = ("import numpy as np\nimport sympy as sp\n"
         "from course_lib.exercises import check, hat, A, B, R, X, Y, d, x, y")

EXERCISES = [
    Exercise(
        name="which_in_so3", chapter=2, number=1, level="warm-up",
        title="Which matrices are rotations?",
        statement=r"""
Which of these matrices are in SO(3) (Definition 2)?

(a) $\begin{pmatrix}0&-1&0\\1&0&0\\0&0&1\end{pmatrix}$ &nbsp;
(b) $\begin{pmatrix}1&0&0\\0&1&0\\0&0&-1\end{pmatrix}$ &nbsp;
(c) $\begin{pmatrix}0.6&0.8&0\\-0.8&0.6&0\\0&0&1\end{pmatrix}$ &nbsp;
(d) $\begin{pmatrix}1&1&0\\0&1&0\\0&0&1\end{pmatrix}$ &nbsp;
(e) $\begin{pmatrix}0&0&1\\1&0&0\\0&1&0\end{pmatrix}$ &nbsp;
(f) $-I$

Give the set of letters, e.g. `{"a", "c"}` or the string `"ac"`.
""",
        answer=Choice(letters="abcdef"),
        tip="Check RᵀR = I (Proposition 3) and det R = +1 (Proposition 4) for each.",
        mistakes={"orthogonal": "RᵀR = I is not enough: a rotation also has det R = +1 "
                                "(Proposition 4); a reflection has det R = −1."},
    ),
    Exercise(
        name="vb_from_va", chapter=2, number=2, level="warm-up",
        title="From a-coordinates to b-coordinates",
        statement=r"""
Frame $B$'s axes, written in frame $A$, are $x_{ab} = (1, 0, 0)$, $y_{ab} = (0, 0, 1)$ and
$z_{ab} = (0, -1, 0)$. A vector has the coordinates $v_a = (1, 2, 3)$ in $A$. Find its
coordinates $v_b$ in $B$ (equation (64) read backwards). Give a 3-vector.
""",
        answer=Value(shape=(3,)),
        tip="v_a = R_ab v_b, and R_ab⁻¹ = R_abᵀ (Proposition 5).",
        mistakes={"direction": "R_ab turns b-coordinates into a-coordinates (v_a = R_ab v_b); "
                               "you need the other direction, R_ba = R_abᵀ."},
    ),
    Exercise(
        name="complete_rotation", chapter=2, number=3, level="core",
        title="Complete a rotation matrix",
        statement=r"""
Find the last column $(a, b, c)$ that makes
$R = \begin{pmatrix} 2/3 & -2/3 & a \\ 1/3 & 2/3 & b \\ 2/3 & 1/3 & c \end{pmatrix}$
a rotation matrix (check first that the two given columns are orthonormal). Give the 3-vector
$(a, b, c)$.
""",
        answer=Value(shape=(3,)),
        tip="The columns of a rotation are a right-handed orthonormal frame: r₃ = r₁ × r₂.",
        mistakes={"det": "with this column det R = −1 (a reflection): the third column is "
                         "r₁ × r₂, in that order."},
    ),
    Exercise(
        name="inverse_of_product", chapter=2, number=4, level="core",
        title="Undoing two rotations",
        statement=r"""
Let `A` stand for $R_{ab}$ and `B` for $R_{bc}$ (two rotation matrices, `MatrixSymbol`s), so
$R_{ac} = AB$. Write $R_{ca} = R_{ac}^{-1}$ in terms of `A` and `B`, **without an inverse**
(use Proposition 5). Give a matrix expression in `A`, `B` (products and `.T`).
""",
        answer=Expr(shape=(3, 3), allowed=(A, B), matrix_degree=2),
        tip="For a rotation R⁻¹ = Rᵀ; and the inverse of a product is the product of the "
            "inverses in reverse order.",
        mistakes={
            "order": "order: (AB)ᵀ = BᵀAᵀ; the factor applied last is undone first.",
            "forward": "that is R_ac itself; the exercise asks for the opposite direction, "
                       "R_ca = R_ac⁻¹.",
        },
    ),
    Exercise(
        name="rigid_inverse", chapter=2, number=5, level="core",
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
        name="hat_product", chapter=2, number=6, level="challenge",
        title="A product of two hat matrices",
        statement=r"""
For vectors $x, y$, show that $\hat x \hat y + (x^T y)\, I$ is an outer product of two vectors:
apply it to a vector $v$ and use $\hat x v = x \times v$ (Definition 5). Write it in terms of
`X` and `Y`, the 3x1 `MatrixSymbol`s standing for $x$ and $y$ (products and `.T`; no hat).
Give a 3x3 matrix expression.
""",
        answer=Expr(shape=(3, 3), allowed=(X, Y), matrix_degree=2),
        tip="x̂ŷv = x × (y × v); expand the double cross product (exercise 1.6 of chapter 1).",
    ),
    Exercise(
        name="two_mirrors", chapter=2, number=7, level="challenge",
        title="Two mirrors make a rotation",
        statement=r"""
The mirrors $M_i = I - 2 n_i n_i^T$ have the unit normals $n_1 = (1, 0, 0)$ and
$n_2 = (\cos 30°, \sin 30°, 0)$. Show that $R = M_2 M_1$ is in SO(3) (each $M_i$ is orthogonal
with $\det M_i = -1$) and that it is a rotation about $z$. By what angle $\theta$ does it turn,
with $R = R_z(\theta)$ and $\theta \in (-\pi, \pi]$? Give a number (radians).
""",
        answer=Value(shape=(), angle=True),
        tip="Compute R = M₂M₁ and compare it with R_z(θ) (its first column is (cos θ, sin θ, 0)).",
        mistakes={
            "half": "that is the angle between the two mirrors; two reflections turn by twice "
                    "that angle.",
            "order": "R = M₂M₁ applies M₁ first; your angle is the one of M₁M₂.",
        },
    ),
]
