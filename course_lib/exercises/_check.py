"""Judging one answer: form, value, and a hint that never shows the expected answer."""

from __future__ import annotations

import numpy as np
import sympy as sp
from sympy.matrices.expressions import MatrixSymbol

from .. import symbolic as S
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

_UNIT_HINT = (
    "ω is a unit vector here: use ω₁² + ω₂² + ω₃² = 1 (a term with ‖ω‖² does not "
    "vanish, it becomes 1)."
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


# ------------------------------------------------------------------------------ hints


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


def _symmetry_hint(A, Ev):
    At, Et = np.swapaxes(A, -1, -2), np.swapaxes(Ev, -1, -2)
    if E.close(A, np.zeros_like(A)):
        return None
    if E.close(Ev, -Et) and E.close(A, At):
        return (
            "your matrix is symmetric, but the right one is skew-symmetric (Mᵀ = −M): "
            "an odd power of a skew matrix is skew, an even one is symmetric."
        )
    if E.close(Ev, Et) and E.close(A, -At):
        return (
            "your matrix is skew-symmetric, but the right one is symmetric: an even power "
            "of a skew matrix is symmetric, an odd one is skew."
        )
    return None


def _uses_omega(spec):
    return bool(set(spec.domain) & set(S.omega)) or S.W in set(spec.allowed or ())


_W_BASIS = ("I", "W", "W²")


def _w_coefficients(M, H):
    """Coefficients (NPOINTS, 3) of M in the basis I, H, H² at each point, or None when M is
    not in their span."""
    basis = np.stack([np.broadcast_to(np.eye(3), H.shape), H, H @ H], -1).reshape(-1, 9, 3)
    coeffs = np.stack([np.linalg.lstsq(b, m.ravel(), rcond=None)[0] for b, m in zip(basis, M)])
    if not E.close(np.einsum("kij,kj->ki", basis, coeffs), M.reshape(-1, 9)):
        return None
    return coeffs


def _w_coefficient_hint(spec, A, Ev, pts):
    """For a polynomial in W (ω̂): which of the coefficients of I, W, W² is wrong."""
    if pts is None or spec.matrix_degree is None or S.W not in set(spec.allowed or ()):
        return None
    w = np.stack([pts[s] for s in S.omega], -1)
    H = np.zeros((len(w), 3, 3))
    H[:, 0, 1], H[:, 0, 2], H[:, 1, 2] = -w[:, 2], w[:, 1], -w[:, 0]
    H -= np.swapaxes(H, -1, -2)
    cA, cE = _w_coefficients(A, H), _w_coefficients(Ev, H)
    if cA is None or cE is None:
        return None
    same = lambda a, b: np.allclose(a, b, rtol=1e-6, atol=1e-6)  # noqa: E731 - noise of lstsq
    bad = [j for j in range(3) if not same(cA[:, j], cE[:, j])]
    if not bad:
        return None
    names = _join([_W_BASIS[j] for j in bad])
    if all(same(cA[:, j], -cE[:, j]) for j in bad):
        verb = "have" if len(bad) > 1 else "has"
        return f"the coefficient of {names} {verb} the wrong sign."
    noun = "coefficients" if len(bad) > 1 else "coefficient"
    verb = "are" if len(bad) > 1 else "is"
    rest = " (the rest is right)" if len(bad) < 3 else ""
    return f"the {noun} of {names} {verb} wrong{rest}."


def _generic_hint(spec, A, Ev, pts=None):
    shape = spec.shape
    zero = np.zeros_like(Ev)
    nonzero = not E.close(Ev, zero)
    if nonzero and E.close(A, -Ev):
        return "your answer is the negative of the right one: check the signs."
    if (
        len(shape) == 2
        and E.close(A, np.swapaxes(Ev, -1, -2))
        and not E.close(Ev, np.swapaxes(Ev, -1, -2))
    ):
        if spec.matrix_degree is not None and S.W in set(spec.allowed or ()):
            return (
                "your answer is the transpose of the right one; for a polynomial in W that "
                "means the W term (an odd power) has the wrong sign, since Wᵀ = −W."
            )
        return "your answer is the transpose of the right one (rows and columns swapped)."
    if nonzero and E.close(A, zero):
        return "your answer is zero, the right one is not."
    if nonzero:
        c = float(np.sum(A * Ev) / np.sum(Ev * Ev))
        if abs(c - 1) > 1e-6 and abs(c + 1) > 1e-6 and E.close(A, c * Ev):
            return (
                "your answer is a constant multiple of the right one: check the numerical factors."
            )
        axes = tuple(range(1, A.ndim))
        norms = np.sum(Ev * Ev, axis=axes)
        if shape != () and np.all(norms > E.TOL):  # a scalar is always a pointwise multiple
            ck = np.sum(A * Ev, axis=axes) / norms
            if E.close(A, ck.reshape((-1,) + (1,) * len(shape)) * Ev):
                example = " (for instance the powers of ‖ω‖)" if _uses_omega(spec) else ""
                return (
                    "your answer is the right one times a factor that changes with the "
                    f"symbols: check the scalar factors{example}."
                )
    if len(shape) == 2 and shape[0] == shape[1]:
        hint = _symmetry_hint(A, Ev)
        if hint:
            return hint
        D = A - Ev
        s = np.trace(D, axis1=-2, axis2=-1) / shape[0]
        if E.close(D, s[:, None, None] * np.eye(shape[0])):
            msg = (
                "your answer differs from the right one by a multiple of the identity: "
                "check its I term."
            )
            return msg + (" " + _UNIT_HINT if spec.unit_omega else "")
    per_point = [E.close(a[None], e[None]) for a, e in zip(A, Ev)]
    if any(per_point):
        return (
            "your answer agrees with the right one at some values of the symbols but not "
            "over their whole range (a truncated series, or a formula valid only for some "
            "values?)."
        )
    hint = _w_coefficient_hint(spec, A, Ev, pts)
    if hint:
        return hint
    if shape == ():
        return "your expression is not equal to the right one."
    bad = np.zeros(A.shape[1:], dtype=bool)
    for a, e in zip(A, Ev):
        bad |= np.abs(a - e) > E.TOL * max(1.0, float(np.abs(e).max()))
    return _positions(bad.reshape(shape), shape)


def _property_hint(ex, M, syms, pts):
    for residual, message in ex.properties:
        r = residual(M)
        R = sp.ImmutableMatrix(r if isinstance(r, sp.MatrixBase) else [[r]])
        vals = E.values("explicit", R, syms, pts)
        if not E.close(vals, np.zeros_like(vals)):
            return message
    return None


# ------------------------------------------------------------------------------ judges


def _stored(vals, shape):
    return np.array(vals, dtype=float).reshape((E.NPOINTS, *shape))


def judge_expr(ex, fp, answer):
    spec = ex.answer
    syms = E.base_symbols(spec)
    readable = set(spec.allowed or ()) | set(spec.domain) | set(syms)
    form, M = read_answer(answer, spec.shape, readable)
    violation = form_violation(spec, form, M)
    right = form == "explicit" and E.exact_form(ex.name, M, spec.unit_omega) == fp["exact"]
    A = None
    if not right:
        pts = E.points(ex.name, spec)
        A = E.values(form, M, syms, pts)
        Ev = _stored(fp["values"], spec.shape)
        A = A.reshape(Ev.shape)
        right = E.close(A, Ev)
    if right:
        if violation:
            return (
                "form",
                f"right value, but the exercise asks for {_describe_form(spec)}: {violation}.",
            )
        return "correct", "correct."
    for mid, vals in fp["mistakes"].items():
        if E.close(A, _stored(vals, spec.shape)):
            return "wrong", ex.mistakes[mid]
    hint = _property_hint(ex, M, syms, pts) if form == "explicit" else None
    hint = hint or _generic_hint(spec, A, Ev, pts)
    return "wrong", hint + (_ROUNDED if _typed_rounded(M) else "")


def _numbers(M):
    """The entries of a numeric answer, evaluated in double precision (never in mpmath, whose
    arbitrary precision makes sin(exp(exp(50))) take forever)."""
    f = E.numeric_function((), M)
    try:
        with np.errstate(all="ignore"):
            vals = np.array(f(), dtype=complex).ravel()
    except (TypeError, ValueError, OverflowError):
        raise Rejected("could not read your answer as numbers.") from None
    if not np.all(np.isfinite(vals)):
        raise Rejected(
            "your answer contains nan or infinity (or a number too large for double precision)."
        )
    if np.max(np.abs(vals), initial=0.0) >= MAX_MAGNITUDE:
        raise Rejected(f"your answer evaluates to {TOO_LARGE}.")
    if np.max(np.abs(vals.imag)) > E.TOL:
        raise Rejected("your answer is complex; a real answer is expected.")
    return vals.real


def _value_hint(ex, fp, v):
    spec, name = ex.answer, ex.name
    for mid, cells in fp["mistakes"].items():
        if E.match_cells(name, v, cells).all():
            return ex.mistakes[mid]
    ok = E.match_cells(name, v, fp["cells"])
    if np.any(v != 0) and E.match_cells(name, -v, fp["cells"]).all():
        return "your answer is the negative of the right one: check the signs."
    if len(spec.shape) == 1 and E.match_cells(name, v[::-1], fp["cells"]).all():
        return (
            "your components are in the reverse order: give them in the order the exercise "
            "asks for."
        )
    if len(spec.shape) == 2:
        vt = v.reshape(spec.shape).T.ravel()
        if E.match_cells(name, vt, fp["cells"]).all():
            return "your answer is the transpose of the right one (rows and columns swapped)."
    if spec.angle:
        if E.match_cells(name, v * np.pi / 180, fp["cells"]).all():
            return "your angle is in degrees; the exercise asks for radians."
        for shift in (2 * np.pi, -2 * np.pi):
            if E.match_cells(name, v + shift, fp["cells"]).all():
                return (
                    "your angle differs from the right one by a full turn (2π): give it in "
                    "the range the exercise asks for."
                )
        if E.match_cells(name, 2 * np.pi - v, fp["cells"]).all():
            return (
                "your angle is 2π minus the right one: the two have the same cosine; give the "
                "one in the range the exercise asks for."
            )
    if spec.rotation:
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
    return _positions(~ok.reshape(spec.shape), spec.shape)


_ROUNDED = (
    " Your answer holds typed decimals: the check compares about 9 digits, and a rounded "
    "decimal is off in the digits it leaves out, so give the exact value (sp.sqrt(2), "
    "sp.pi / 3, sp.acos(...)) or let Python compute it instead of typing a rounded number."
)


def _typed_rounded(M):
    """Does the answer hold a float typed with 3 to 10 significant digits (1.0472, 3.14,
    1.04719755)? A float that Python computed has 15-17; 0.5 or 2.0 are not rounded."""
    for node in sp.preorder_traversal(M):
        if isinstance(node, sp.Float):
            f = float(node)
            if f != round(f) and f == float(f"{f:.10g}") and f != float(f"{f:.2g}"):
                return True
    return False


def _single_precision(answer):
    """Does a numeric answer hold numpy floats of less than double precision (float32 ...)?"""
    items = answer if isinstance(answer, (list, tuple)) else [answer]
    for item in items:
        dtype = getattr(item, "dtype", None)
        if dtype is not None and (dtype.kind, dtype.itemsize) in {("f", 2), ("f", 4), ("c", 8)}:
            return True
        if isinstance(item, (list, tuple)) and _single_precision(item):
            return True
    return False


_MAX_REACH = 1024  # cells scanned each side: float32 rounding of entries up to about 4


def _single_precision_matches(name, v, cells):
    """Per entry: is it within float32 rounding (a few units of 2⁻²⁴, relative) of the right
    cell? Scans the neighbouring cells of the digest grid."""
    if len(np.ravel(v)) != len(cells):
        return np.zeros(len(cells), dtype=bool)
    ok = []
    for i, (x, (off, dig)) in enumerate(zip(np.ravel(v), cells)):
        reach = int(np.ceil(8 * np.finfo(np.float32).eps * max(1.0, abs(x)) / E.STEP))
        if reach > _MAX_REACH:  # a huge entry: not worth the scan
            ok.append(False)
            continue
        centre = int(np.floor((x + off * E.STEP / 2) / E.STEP))
        ok.append(any(E.digest(name, i, centre + k) == dig for k in range(-reach, reach + 1)))
    return np.array(ok)


_SINGLE = (
    "your answer is stored in single precision (float32), which keeps only about 7 "
    "digits; the check needs double precision (within TOL): compute in float64 (drop "
    "dtype=np.float32 or .astype(np.float32))."
)


def judge_value(ex, fp, answer):
    form, M = read_answer(answer, ex.answer.shape, set(), numeric=True)
    v = _numbers(M)
    if E.match_cells(ex.name, v, fp["cells"]).all():
        return "correct", "correct."
    if _single_precision(answer):
        ok = _single_precision_matches(ex.name, v, fp["cells"])
        if ok.all():
            return "wrong", "right to single precision, but " + _SINGLE
        return "wrong", _positions(
            ~ok.reshape(ex.answer.shape), ex.answer.shape
        ) + " Also, " + _SINGLE
    hint = _value_hint(ex, fp, v)
    if _typed_rounded(M) and not any(hint == text for text in ex.mistakes.values()):
        hint += _ROUNDED
    return "wrong", hint


def judge_choice(ex, fp, answer):
    letters = read_choice(answer, ex.answer.letters)
    if E.digest(ex.name, "choice", letters) == fp["digest"]:
        return "correct", "correct."
    for mid, dig in fp["mistakes"].items():
        if E.digest(ex.name, "choice", letters) == dig:
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
