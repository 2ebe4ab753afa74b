r"""The checking engine: sample points, fingerprints, the comparison and the hints.

Nothing here knows an expected answer. What the engine compares with is a *fingerprint* made by
the repository tool ``tools/exercise_fingerprints.py`` from the instructor's reference solutions:

- a symbolic answer (:class:`~course_lib.exercises._model.Expr`): its values at
  :data:`NPOINTS` seeded points spread over the whole domain (ω on the whole unit sphere, angles
  over two full turns each way, t over [−4, 4], ...) and a salted digest of its exact normal form
  (expanded, reduced modulo :math:`\lVert\omega\rVert = 1` where ω is a unit vector);
- a numeric answer (:class:`~course_lib.exercises._model.Value`): a salted digest of every entry
  rounded to a grid of step :math:`4\,\mathrm{TOL}`, on whichever of two offset grids keeps the
  value at least TOL from a cell edge, so an entry within TOL of the right one always lands in
  the right cell (and one more than :math:`4\,\mathrm{TOL}` away never does);
- a choice (:class:`~course_lib.exercises._model.Choice`): a salted digest of the letters.

A symbolic answer is right when its normal form has the stored digest (exact), or else when at
every point :math:`\lVert A(p_k) - E(p_k)\rVert \le \mathrm{TOL}\,\max(1, \lVert E(p_k)\rVert)`.
Known mistakes have fingerprints too; hints come from those and from transformations of the
student's own answer (its negative, its transpose, degrees for radians ...), never from the
expected answer.
"""

from __future__ import annotations

import hashlib
import zlib
from functools import lru_cache
from math import comb

import numpy as np
import sympy as sp
from sympy.matrices.expressions import (
    Identity,
    MatAdd,
    MatMul,
    MatPow,
    MatrixExpr,
    MatrixSymbol,
    Transpose,
    ZeroMatrix,
)

from .. import symbolic as S
from ..tolerance import TOL
from ._reading import Rejected, degree_bound

NPOINTS = 40
STEP = 4 * TOL
_SALT = "rotations-course/exercises/v1"
_TURN = 4 * np.pi
_MAX_EXACT_TERMS = 300
_MAX_EXACT_DEGREE = 8

#: What each stand-in symbol of a form means in the base symbols.
SCALAR_DEFINITIONS = {S.xx: S.x.dot(S.x), S.yy: S.y.dot(S.y), S.xy: S.x.dot(S.y)}
MATRIX_DEFINITIONS = {
    S.W: S.hat(S.omega),
    S.u: S.omega,
    S.X: S.x,
    S.Y: S.y,
    S.d: S.vector("d"),
    S.A: S.rotation_symbols("a"),
    S.B: S.rotation_symbols("b"),
    S.R: S.rotation_symbols("r"),
}
_ROTATIONS = (S.A, S.B, S.R)
_VECTORS = (S.omega, S.x, S.y, S.z, MATRIX_DEFINITIONS[S.d])
_SCALAR_RANGES = {
    S.theta: (-_TURN, _TURN),
    S.alpha: (-_TURN, _TURN),
    S.beta: (-_TURN, _TURN),
    S.phi: (-_TURN, _TURN),
    S.t: (-4.0, 4.0),
    S.a: (-1.5, 1.5),
}


def digest(*parts):
    """Salted SHA-256 digest (16 hex digits) of the parts, joined by ``|``."""
    text = "|".join([_SALT, *map(str, parts)])
    return hashlib.sha256(text.encode()).hexdigest()[:16]


# ------------------------------------------------------------------------------ sample points


def base_symbols(spec):
    """The scalar symbols an Expr answer is finally a function of, in a fixed order."""
    syms = set(spec.domain)
    for s in spec.allowed or ():
        if s in SCALAR_DEFINITIONS:
            syms |= SCALAR_DEFINITIONS[s].free_symbols
        elif s in MATRIX_DEFINITIONS:
            syms |= MATRIX_DEFINITIONS[s].free_symbols
        elif isinstance(s, sp.Symbol):
            syms.add(s)
    return tuple(sorted(syms, key=lambda s: s.name))


def _random_rotations(rng, n):
    """Uniform rotations from unit quaternions. Kept here rather than calling
    ``so3.random_rotations``: the stored fingerprints depend on these exact draws, so a change
    of the library's sampler must not change what the checker compares with."""
    q = rng.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    w, x, y, z = q.T
    return np.stack(
        [
            np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
            np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
            np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
        ],
        -2,
    )


@lru_cache(maxsize=64)
def points(name, spec):
    """Seeded values of the base symbols: {symbol: array of NPOINTS floats} (cached)."""
    rng = np.random.default_rng(zlib.crc32(name.encode()))
    wanted = set(base_symbols(spec))
    out = {}
    for vec in _VECTORS:
        v = rng.normal(size=(NPOINTS, 3))
        if vec == S.omega:
            v /= np.linalg.norm(v, axis=1, keepdims=True)
            if not spec.unit_omega:
                v *= rng.uniform(0.3, 2.0, size=(NPOINTS, 1))
        out.update({s: v[:, i] for i, s in enumerate(vec)})
    for mat in _ROTATIONS:
        rots = _random_rotations(rng, NPOINTS)
        for (i, j), s in np.ndenumerate(np.array(MATRIX_DEFINITIONS[mat], dtype=object)):
            out[s] = rots[:, i, j]
    for s, (lo, hi) in _SCALAR_RANGES.items():
        out[s] = rng.uniform(lo, hi, NPOINTS)
    out[S.x_0] = rng.uniform(0.5, 2.0, NPOINTS) * rng.choice([-1.0, 1.0], NPOINTS)
    return {s: v for s, v in out.items() if s in wanted}


# ------------------------------------------------------------------------------ evaluation

#: The numpy functions of the allowed elementary functions. lambdify with this namespace
#: instead of modules="numpy" avoids importing all of numpy's namespace (seconds, once).
_NAMESPACE = {
    "sin": np.sin,
    "cos": np.cos,
    "tan": np.tan,
    "exp": np.exp,
    "log": np.log,
    "asin": np.arcsin,
    "acos": np.arccos,
    "atan": np.arctan,
    "atan2": np.arctan2,
    "sinh": np.sinh,
    "cosh": np.cosh,
    "tanh": np.tanh,
    "sqrt": np.sqrt,
    "Abs": np.abs,
    "pi": np.pi,
    "E": np.e,
    "I": 1j,
}


def numeric_function(syms, M):
    """A numpy function of ``syms`` returning the entries of the matrix M as nested lists."""
    return sp.lambdify(syms, sp.Matrix(M).tolist(), modules=[_NAMESPACE], docstring_limit=0)


def _lambdified(M, syms, pts):
    """Values of an explicit matrix at the points: complex array (NPOINTS, rows, cols)."""
    f = numeric_function(syms, M)
    args = [pts[s].astype(complex) for s in syms]
    with np.errstate(all="ignore"):
        rows = f(*args)
    return np.stack(
        [
            np.stack([np.broadcast_to(np.asarray(v, dtype=complex), (NPOINTS,)) for v in row], -1)
            for row in rows
        ],
        -2,
    )


def _eval_matrix_expr(e, syms, pts, cache):
    kind = type(e)
    if kind is MatrixSymbol:
        key = (e, syms)
        if key not in cache:
            cache[key] = _lambdified(MATRIX_DEFINITIONS[e], syms, pts)
        return cache[key]
    if kind is Identity:
        return np.broadcast_to(np.eye(e.shape[0], dtype=complex), (NPOINTS, *e.shape))
    if kind is ZeroMatrix:
        return np.zeros((NPOINTS, *e.shape), dtype=complex)
    if not isinstance(e, MatrixExpr) or isinstance(e, sp.MatrixBase):
        return _lambdified(
            sp.ImmutableMatrix(e) if isinstance(e, sp.MatrixBase) else sp.ImmutableMatrix([[e]]),
            syms,
            pts,
        )
    parts = [_eval_matrix_expr(a, syms, pts, cache) for a in e.args] if kind is not MatPow else None
    if kind is MatAdd:
        return sum(parts[1:], parts[0])
    if kind is MatMul:
        out = None
        for p in parts:
            if p.shape[1:] == (1, 1) and out is not None and out.shape[1:] != (1, 1):
                out = out * p
            elif out is None:
                out = p
            elif out.shape[1:] == (1, 1):
                out = out * p
            else:
                out = out @ p
        return out
    if kind is MatPow:
        base = _eval_matrix_expr(e.args[0], syms, pts, cache)
        return np.linalg.matrix_power(base, int(e.args[1]))
    if kind is Transpose:
        return np.swapaxes(_eval_matrix_expr(e.args[0], syms, pts, cache), -1, -2)
    raise Rejected(f"could not evaluate the {kind.__name__} in your answer.")


#: Values of the matrix symbols at the (cached) points of an exercise, by id of the points.
_SYMBOL_VALUES = {}


def values(form, M, syms, pts):
    """Real values (NPOINTS, rows, cols) of an answer read by ``read_answer``."""
    if form == "matrix":
        entry = _SYMBOL_VALUES.get(id(pts))
        if entry is None or entry[0] is not pts:  # keeps pts alive: ids never reused
            entry = _SYMBOL_VALUES[id(pts)] = (pts, {})
        vals = _eval_matrix_expr(M.xreplace(SCALAR_DEFINITIONS), syms, pts, entry[1])
    else:
        vals = _lambdified(M.xreplace(SCALAR_DEFINITIONS), syms, pts)
    if not np.all(np.isfinite(vals)):
        raise Rejected(
            "your answer is undefined (a division by zero, or a huge value) at some "
            "values of the symbols."
        )
    scale = np.maximum(1.0, np.abs(vals.real))
    if np.max(np.abs(vals.imag) / scale, initial=0.0) > TOL:
        raise Rejected(
            "your answer is complex-valued; a real answer is expected (check "
            "square roots of negative quantities and stray factors of I)."
        )
    return vals.real


def exact_form(name, M, unit_omega):
    """Salted digest of the exact normal form of an explicit answer, or None if too big."""
    entries = []
    for e in M.xreplace(SCALAR_DEFINITIONS):
        n, deg = len(e.free_symbols), degree_bound(e)
        if deg > _MAX_EXACT_DEGREE or comb(n + deg, n) > _MAX_EXACT_TERMS or sp.count_ops(e) > 200:
            return None
        e = sp.expand(e)
        if unit_omega and e.free_symbols & set(S.omega):
            try:
                e = sp.expand(S.unit_reduce(e))
            except (ValueError, sp.PolynomialError):
                pass
        entries.append(sp.srepr(e))
    return digest(name, "exact", *entries)


def close(A, E):
    """At every point ‖A − E‖ ≤ TOL·max(1, ‖E‖) (Frobenius / Euclidean norm)."""
    A, E = np.asarray(A, dtype=float), np.asarray(E, dtype=float)
    if A.shape != E.shape:
        return False
    axes = tuple(range(1, A.ndim))
    err = np.sqrt(np.sum((A - E) ** 2, axis=axes))
    scale = np.maximum(1.0, np.sqrt(np.sum(E**2, axis=axes)))
    return bool(np.all(err <= TOL * scale))


# ------------------------------------------------------------------------------ numeric digests


def value_cells(name, vec):
    """Fingerprint of a numeric answer: [offset index, digest] for each entry."""
    out = []
    for i, v in enumerate(np.ravel(vec)):
        off = 0 if abs((v / STEP) % 1 - 0.5) <= 0.25 else 1
        cell = int(np.floor((v + off * STEP / 2) / STEP))
        out.append([off, digest(name, i, cell)])
    return out


def match_cells(name, vec, cells):
    """Per entry: does the entry fall in the stored cell?"""
    flat = np.ravel(vec)
    if len(flat) != len(cells):
        return np.zeros(len(cells), dtype=bool)
    ok = []
    for i, (v, (off, dig)) in enumerate(zip(flat, cells)):
        cell = int(np.floor((v + off * STEP / 2) / STEP)) if np.isfinite(v) else None
        ok.append(cell is not None and digest(name, i, cell) == dig)
    return np.array(ok)
