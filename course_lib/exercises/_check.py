"""Judging one answer: form, value, and a hint that never shows the expected answer.

Every comparison goes through the key-stretched digests of :mod:`._digests`: the student's
answer, or a transformation of it (its negative, its transpose, a known mistake undone ...), is
rounded, digested and compared with the stored digests of the right answer.
"""

from __future__ import annotations

import numpy as np
import sympy as sp
from sympy.matrices.expressions import MatrixSymbol

from .. import symbolic as S
from . import _digests as D
from . import _engine as E
from ._model import Choice, Expr, Value
from ._reading import (
    MAX_MAGNITUDE,
    TOO_LARGE,
    Rejected,
    describe_shape,
    matrix_degree,
    read_answer,
    read_choice,
)
from ._transforms import EXPR_TRANSFORMS, NUMBER_OPS, PERMUTATIONS, apply_letters

_UNIT_HINT = (
    "ω is a unit vector here: use ω₁² + ω₂² + ω₃² = 1 (a term with ‖ω‖² does not "
    "vanish, it becomes 1)."
)


_COMPLEX_ANSWER = (
    "your answer is complex; a real answer is expected. If it came from sp.solve, pick the "
    "real solution (sympy lists every root; a symbol made with real=True keeps only real "
    "ones); if it came from acos or asin, their argument must lie in [−1, 1]: recheck it."
)
_NOT_FINITE = (
    "your answer contains nan or infinity (or a number too large for double precision): "
    "look for a division by zero, or acos/asin/sqrt of a number outside their domain "
    "(a cosine lies in [−1, 1])."
)


def _join(items):
    items = list(items)
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


# ------------------------------------------------------------------------------ form


def _describe_form(spec):
    allowed = spec.allowed or spec.domain
    mats = [str(s) for s in allowed if isinstance(s, MatrixSymbol)]
    scal = [str(s) for s in allowed if isinstance(s, sp.Symbol)]
    if spec.matrix_degree is not None:
        what = f"a matrix expression in {_join(mats)} of degree at most {spec.matrix_degree}"
        return what + (f", with coefficients in {_join(scal)}" if scal else "")
    if spec.no_roots:
        return "the simplified form, without a square root of an expression in the symbols"
    return f"an expression in {_join(scal)} only"


def _explicit_constants_ok(e):
    """Explicit matrices inside a matrix expression: only multiples of the identity."""
    for node in sp.preorder_traversal(e):
        if isinstance(node, sp.MatrixBase):
            n = node.shape[0]
            if (
                node.shape[0] != node.shape[1]
                or node.free_symbols
                or node != node[0, 0] * sp.eye(n)
            ):
                return False
    return True


def form_violation(spec, form, M):
    """Why the answer is not in the asked form (a phrase), or None."""
    allowed = set(spec.allowed or spec.domain)
    if spec.matrix_degree is not None:
        if form != "matrix":
            return "you gave explicit entries"
        if matrix_degree(M) > spec.matrix_degree:
            return "reduce the higher powers first"
        if not _explicit_constants_ok(M):
            return "you wrote out explicit entries inside it"
    used = {s for s in sp.preorder_traversal(M) if isinstance(s, (sp.Symbol, MatrixSymbol))}
    outside = sorted(str(s) for s in used - allowed)
    if outside:
        return f"your answer uses {_join(outside)}"
    if spec.no_roots:
        for node in sp.preorder_traversal(M):
            if node.is_Pow and not node.exp.is_Integer and node.base.free_symbols:
                return "your answer still has a root of an expression in the symbols"
    return None


# ------------------------------------------------------------------------------ words


def _positions(bad, shape):
    idx = np.argwhere(bad)
    if len(shape) == 0:
        return "the value is not right."
    if len(shape) == 1:
        names = [str(i[0] + 1) for i in idx]
        noun = "components" if len(names) > 1 else "component"
    else:
        names = [f"({i + 1}, {j + 1})" for i, j in idx]
        noun = "entries" if len(names) > 1 else "entry"
        if len(names) == bad.size > 1:
            return f"all {bad.size} entries are wrong."
    verb = "are" if len(names) > 1 else "is"
    return f"{noun} {_join(names)} {verb} wrong."


def _free_symbols(M):
    """The free symbols of a read answer (a sympy object, or a list of them)."""
    items = M if isinstance(M, (list, tuple)) else [M]
    return set().union(*(getattr(m, "free_symbols", set()) for m in items))


def _uses_omega(spec):
    return bool(set(spec.domain) & set(S.omega)) or S.W in set(spec.allowed or ())


_W_BASIS = ("I", "W", "W²")
_NEGATIVE = "your answer is the negative of the right one: check the signs."
_TRANSPOSE = "your answer is the transpose of the right one (rows and columns swapped)."
_TRANSPOSE_W = (
    "your answer is the transpose of the right one; for a polynomial in W that "
    "means the W term (an odd power) has the wrong sign, since Wᵀ = −W."
)


# ------------------------------------------------------------------------------ symbolic


class _Symbolic:
    """A symbolic answer's values and the comparisons of its features with the digests."""

    writes_omega = True  # False for an answer written in W alone (set by judge_expr)

    def __init__(self, ex, fp, A, pts, near):
        self.ex, self.fp, self.A, self.pts, self.near = ex, fp, A, pts, near
        self.name, self.spec = ex.name, ex.answer

    def right(self, A):
        z = D.projections(self.name, "value", A, 2)
        return D.matches(self.name, "value", z, E.STEP_VALUE, self.fp["value"])

    def feature(self, label, stored_label=None):
        stored_label = stored_label or label.lstrip("-")
        base = label.lstrip("-").rstrip("0123456789")
        which = {"coef": "coefficients", "entry": "entries"}.get(base, base)
        z = E.features(self.name, self.spec, self.A, self.pts, self.near, (which,)).get(label)
        if z is None:
            return False
        return D.matches(self.name, stored_label, z, E.step_of(label), self.fp.get(stored_label))

    def mistake(self, mid, rec):
        if "value" in rec:
            z = D.projections(self.name, "value", self.A, 2)
            return D.matches(self.name, f"mistake {mid}", z, E.STEP_VALUE, rec["value"])
        moved = EXPR_TRANSFORMS[rec["transform"]](self.A, self.pts)
        return moved is not None and self.right(moved)


def _symmetry_hint(A, structure):
    At = np.swapaxes(A, -1, -2)
    scale = max(1.0, float(np.max(np.abs(A))))
    if structure == "skew" and np.max(np.abs(A - At)) <= E.TOL * scale:
        return (
            "your matrix is symmetric, but the right one is skew-symmetric (Mᵀ = −M): "
            "an odd power of a skew matrix is skew, an even one is symmetric."
        )
    if structure == "symmetric" and np.max(np.abs(A + At)) <= E.TOL * scale:
        return (
            "your matrix is skew-symmetric, but the right one is symmetric: an even power "
            "of a skew matrix is symmetric, an odd one is skew."
        )
    return None


def _w_coefficient_hint(s):
    """For a polynomial in W (ω̂): which of the coefficients of I, W, W² is wrong."""
    if "coef0" not in s.fp or E.w_coefficients(s.A, s.pts) is None:
        return None
    bad = [j for j in range(3) if not s.feature(f"coef{j}")]
    if not bad:
        return None
    names = _join([_W_BASIS[j] for j in bad])
    if all(s.feature(f"-coef{j}") for j in bad):
        verb = "have" if len(bad) > 1 else "has"
        return f"the coefficient of {names} {verb} the wrong sign."
    noun = "coefficients" if len(bad) > 1 else "coefficient"
    verb = "are" if len(bad) > 1 else "is"
    rest = " (the rest is right)" if len(bad) < 3 else ""
    return f"the {noun} of {names} {verb} wrong{rest}."


def _shape_hints(s):
    """Hints from the negative, the transpose and the zero answer."""
    A, shape = s.A, s.spec.shape
    zero = bool(np.all(np.abs(A) <= E.TOL))
    if not zero and s.right(-A):
        return _NEGATIVE
    if len(shape) == 2:
        At = np.swapaxes(A, -1, -2)
        if not np.allclose(A, At, rtol=0, atol=E.TOL) and s.right(At):
            return _TRANSPOSE_W if E._uses_w(s.spec) else _TRANSPOSE
    if zero:
        return "your answer is zero, the right one is not."
    return None


def _generic_hint(s):
    shape = s.spec.shape
    hint = _shape_hints(s)
    if hint:
        return hint
    if s.feature("scaled"):
        return "your answer is a constant multiple of the right one: check the numerical factors."
    if shape != () and s.feature("direction"):
        example = " (for instance the powers of ‖ω‖)" if _uses_omega(s.spec) else ""
        return (
            "your answer is the right one times a factor that changes with the "
            f"symbols: check the scalar factors{example}."
        )
    hint = _symmetry_hint(s.A, s.fp.get("structure", "")) if len(shape) == 2 else None
    if hint:
        return hint
    if len(shape) == 2 and s.feature("traceless"):
        msg = (
            "your answer differs from the right one by a multiple of the identity: "
            "check its I term."
        )
        # the ‖ω‖² advice is for answers in ω₁, ω₂, ω₃ or u; in W alone no ‖ω‖² can appear
        return msg + (" " + _UNIT_HINT if s.spec.unit_omega and s.writes_omega else "")
    if s.feature("near"):
        return (
            "your answer agrees with the right one at some values of the symbols but not "
            "over their whole range (a truncated series, or a formula valid only for some "
            "values?)."
        )
    hint = _w_coefficient_hint(s)
    if hint:
        return hint
    if shape == ():
        return "your expression is not equal to the right one."
    size = int(np.prod(shape))
    bad = np.array([not s.feature(f"entry{j}") for j in range(size)])
    return _positions(bad.reshape(shape), shape)


def _property_hint(ex, M, syms, pts):
    for residual, message in ex.properties:
        r = residual(M)
        R = sp.ImmutableMatrix(r if isinstance(r, sp.MatrixBase) else [[r]])
        vals = E.values("explicit", R, syms, pts)
        if np.max(np.abs(vals), initial=0.0) > E.TOL:
            return message
    return None


def judge_expr(ex, fp, answer):
    spec = ex.answer
    syms = E.base_symbols(spec)
    form, M = read_answer(answer, spec.shape, E.readable_symbols(spec))
    violation = form_violation(spec, form, M)
    pts, near = E.points(ex.name, spec)
    A = E.values(form, M, syms, pts)
    s = _Symbolic(ex, fp, A.reshape((len(A), *spec.shape)), pts, near)
    free = _free_symbols(M)
    s.writes_omega = bool(set(S.omega) & free) or S.W not in free
    if s.right(s.A):
        if violation:
            return (
                "form",
                f"right value, but the exercise asks for {_describe_form(spec)}: {violation}.",
            )
        return "correct", "correct."
    for mid, rec in fp["mistakes"].items():
        if s.mistake(mid, rec):
            return "wrong", ex.mistakes[mid]
    hint = _property_hint(ex, M, syms, pts) if form == "explicit" else None
    hint = hint or _generic_hint(s)
    return "wrong", hint + (_ROUNDED if _typed_rounded(M) else "")


# ------------------------------------------------------------------------------ numbers


def numbers(M):
    """The entries of a numeric answer, evaluated in double precision (never in mpmath, whose
    arbitrary precision makes sin(exp(exp(50))) take forever)."""
    f = E.numeric_function((), M)
    try:
        with np.errstate(all="ignore"):
            vals = np.array(f(), dtype=complex).ravel()
    except (TypeError, ValueError, OverflowError):
        raise Rejected("could not read your answer as numbers.") from None
    if not np.all(np.isfinite(vals)):
        raise Rejected(_NOT_FINITE)
    if np.max(np.abs(vals), initial=0.0) >= MAX_MAGNITUDE:
        raise Rejected(f"your answer evaluates to {TOO_LARGE}.")
    if np.max(np.abs(vals.imag)) > E.TOL:
        raise Rejected(_COMPLEX_ANSWER)
    return vals.real


def _groups_ok(name, label, digests, shape, vec, stop=True):
    """Per group of entries (a vector whole, a matrix by columns): does it match its digest?
    With ``stop``, the groups after the first that does not match count as not matching."""
    ok = [False] * len(digests)
    for g, stored in enumerate(digests):
        ok[g] = E.number_group_ok(name, label, vec, shape, g, stored)
        if stop and not ok[g]:
            break
    return ok


def _all_right(name, fp, vec, shape):
    """Are all entries right (within TOL each)?"""
    vec = np.ravel(vec)
    if len(vec) != fp["size"] or not np.all(np.isfinite(vec)):
        return False
    return all(_groups_ok(name, "value", fp["value"], shape, vec))


def _number_mistake(ex, fp, mid, rec, v):
    """Did the student make the known mistake ``mid``? Its transformation (a permutation of the
    entries, then an operation per entry) turns the student's answer into the right one; or,
    stored as the digests of its value, the answer matches them."""
    shape = ex.answer.shape
    if "value" in rec:
        return all(_groups_ok(ex.name, f"mistake {mid} ", rec["value"], shape, v))
    t = rec["transform"]
    moved = v[PERMUTATIONS[t["perm"]](shape)]
    with np.errstate(all="ignore"):
        fixed = np.array([NUMBER_OPS[op](float(x)) for op, x in zip(t["ops"], moved)])
    return _all_right(ex.name, fp, fixed, shape)


def _angle_hint(name, fp, v, shape):
    if _all_right(name, fp, v * np.pi / 180, shape):
        return "your angle is in degrees; the exercise asks for radians."
    if any(_all_right(name, fp, v + shift, shape) for shift in (2 * np.pi, -2 * np.pi)):
        return (
            "your angle differs from the right one by a full turn (2π): give it in "
            "the range the exercise asks for."
        )
    if _all_right(name, fp, 2 * np.pi - v, shape):
        return (
            "your angle is 2π minus the right one: the two have the same cosine; give the "
            "one in the range the exercise asks for."
        )
    return None


def _rotation_hint(v):
    R = v.reshape(3, 3)
    if np.linalg.norm(R.T @ R - np.eye(3)) > 1e-6:
        return (
            "your matrix is not a rotation: its columns are not orthonormal "
            f"(‖RᵀR − I‖ = {np.linalg.norm(R.T @ R - np.eye(3)):.3g})."
        )
    if np.linalg.det(R) < 0:
        return (
            "your matrix has det R = −1: a reflection, not a rotation (check the order "
            "of a cross product or the sign of one column)."
        )
    return None


def _pi_text(x):
    """A range's end as the statement writes it: 0, π, −π/2, 2π/3 ... (else the number)."""
    from fractions import Fraction

    f = Fraction(x / np.pi).limit_denominator(12)
    if abs(float(f) * np.pi - x) > 1e-12:
        return f"{x:.4g}".replace("-", "−")
    if f == 0:
        return "0"
    num = {1: "", -1: "−"}.get(f.numerator, f"{f.numerator}".replace("-", "−"))
    return f"{num}π" + (f"/{f.denominator}" if f.denominator != 1 else "")


def _range_hint(ranges, v):
    """Which entry lies outside the range the statement asks for (the student's own entry)."""
    for (name, low, high), x in zip(ranges, np.ravel(v)):
        if not low - E.TOL <= x <= high + E.TOL:
            return (
                f"your {name} = {x:.4g} lies outside [{_pi_text(low)}, {_pi_text(high)}], the "
                "range the exercise asks for: bring it into that range (adding or subtracting "
                "2π gives the same turn), or pick the other solution the exercise describes."
            )
    return None


def _unit_hint(v):
    """A vector whose length is not 1 where a unit vector is asked for."""
    length = float(np.linalg.norm(v))
    if abs(length - 1.0) <= 1e-6:
        return None
    return f"your answer has length {length:.4g}: it must be a unit vector (length 1)."


def _value_hint(ex, fp, v):
    spec, name = ex.answer, ex.name
    for mid, rec in fp["mistakes"].items():
        if _number_mistake(ex, fp, mid, rec, v):
            return ex.mistakes[mid]
    if np.any(v != 0) and _all_right(name, fp, -v, spec.shape):
        return _NEGATIVE
    if len(spec.shape) == 1 and _all_right(name, fp, v[::-1], spec.shape):
        return (
            "your components are in the reverse order: give them in the order the exercise "
            "asks for."
        )
    if len(spec.shape) == 2 and _all_right(name, fp, v.reshape(spec.shape).T.ravel(), spec.shape):
        return _TRANSPOSE
    hint = _angle_hint(name, fp, v, spec.shape) if spec.angle else None
    hint = hint or _range_hint(spec.ranges, v) or (_unit_hint(v) if spec.unit else None)
    hint = hint or (_rotation_hint(v) if spec.rotation else None)
    if hint:
        return hint
    return _not_right(spec.shape, _groups_ok(name, "value", fp["value"], spec.shape, v, False))


def _not_right(shape, ok):
    """What is wrong, to the group: a digest covers a vector whole or a matrix's column (a
    verdict per entry would let a search find the answer one entry at a time)."""
    if len(shape) == 0:
        return "the value is not right."
    if len(shape) == 1:
        return "your answer is not right: at least one component is wrong."
    bad = [str(g + 1) for g, good in enumerate(ok) if not good]
    return (
        f"column {bad[0]} is not right."
        if len(bad) == 1
        else f"columns {_join(bad)} are not right."
    )


_ROUNDED = (
    " Your answer holds typed decimals: the check compares about 9 digits, and a rounded "
    "decimal is off in the digits it leaves out, so give the exact value (sp.sqrt(2), "
    "sp.pi / 3, sp.acos(...)) or let Python compute it instead of typing a rounded number."
)


def _typed_rounded(M):
    """Does the answer hold a float typed with 3 to 10 significant digits (1.0472, 3.14,
    1.04719755)? A float that Python computed has 15-17; 0.5 or 2.0 are not rounded."""
    for node in sp.preorder_traversal(M):
        if type(node) is sp.Float:
            f = float(node)
            if f != round(f) and f == float(f"{f:.10g}") and f != float(f"{f:.2g}"):
                return True
    return False


def _single_precision(answer):
    """Does a numeric answer hold numpy floats of less than double precision (float32 ...)?"""
    items = answer if type(answer) in (list, tuple) else [answer]
    for item in items:
        kind = type(item)
        if kind is np.ndarray or kind in (np.float16, np.float32, np.complex64):
            if (item.dtype.kind, item.dtype.itemsize) in {("f", 2), ("f", 4), ("c", 8)}:
                return True
        if kind in (list, tuple) and _single_precision(item):
            return True
    return False


_SIMPLE_BASES = (1.0, np.pi, np.sqrt(2), np.sqrt(3))


def _simple_near(x):
    """The simple value (a fraction, times 1, π, √2 or √3) within 2 float32 ulps of ``x``, or
    ``x``."""
    from fractions import Fraction

    ulp = float(np.spacing(np.float32(abs(x)))) if abs(x) < 1e6 else 0.0
    for base in _SIMPLE_BASES:
        guess = float(Fraction(x / base).limit_denominator(360)) * base
        if abs(guess - x) <= 2 * ulp:
            return guess
    return x


def _single_precision_right(name, fp, v, shape):
    """Is the answer the single-precision rounding of the right one? The digest cannot be
    scanned over a float32 rounding interval (tens of cells per entry), so each entry is
    replaced by the simple value near it, when there is one, and they are checked together."""
    return _all_right(name, fp, np.array([_simple_near(x) for x in v]), shape)


_SINGLE = (
    "your answer is stored in single precision (float32), which keeps only about 7 "
    "digits; the check needs double precision (within TOL): compute in float64 (drop "
    "dtype=np.float32 or .astype(np.float32))."
)


def judge_value(ex, fp, answer):
    form, M = read_answer(answer, ex.answer.shape, set(), numeric=True)
    v = numbers(M)
    shape = ex.answer.shape
    if _all_right(ex.name, fp, v, shape):
        return "correct", "correct."
    if _single_precision(answer):
        if _single_precision_right(ex.name, fp, v, shape):
            return "wrong", "right to single precision, but " + _SINGLE
        ok = _groups_ok(ex.name, "value", fp["value"], shape, v, stop=False)
        return "wrong", _not_right(shape, ok) + " Also, " + _SINGLE
    hint = _value_hint(ex, fp, v)
    if _typed_rounded(M) and not any(hint == text for text in ex.mistakes.values()):
        hint += _ROUNDED
    return "wrong", hint


# ------------------------------------------------------------------------------ choices


def judge_choice(ex, fp, answer):
    letters = read_choice(answer, ex.answer.letters)
    if D.stretched(ex.name, "letters", letters) == fp["letters"]:
        return "correct", "correct."
    for mid, rec in fp["mistakes"].items():
        if D.stretched(ex.name, "letters", apply_letters(rec["mask"], letters)) == fp["letters"]:
            return "wrong", ex.mistakes[mid]
    return "wrong", "that is not the right set of letters."


JUDGES = {Expr: judge_expr, Value: judge_value, Choice: judge_choice}


def judge(ex, fp, answer):
    """(status, text) for one answer; raises Rejected for an answer that cannot be read."""
    return JUDGES[type(ex.answer)](ex, fp, answer)


def expected_shape_phrase(ex):
    spec = ex.answer
    if isinstance(spec, Choice):
        return "a set of letters"
    if isinstance(spec, Expr) and spec.matrix_degree is not None:
        return "a matrix expression"
    return describe_shape(spec.shape)


__all__ = ["judge", "expected_shape_phrase", "form_violation"]
