r"""The checking engine: sample points, evaluation, and the features that are digested.

Nothing here knows an expected answer. The checker compares a student's answer with
*fingerprints* that the repository tool ``python -m instructor.build.exercise_fingerprints``
makes from the instructor's reference solutions: key-stretched digests of rounded values
(:mod:`course_lib.exercises._digests`), never the values themselves.

**Sample points** (:func:`points`). A symbolic answer is evaluated at seeded points over the
whole domain (ω on the whole unit sphere or anywhere, angles over two full turns each way, t
over [−4, 4], ...), and a quarter of them near zero (small angles, small t), where truncated
series agree. The points come in *pairs*: every base point is repeated with one *unit* drawn
afresh (one scalar symbol, one coordinate of a free vector, a whole unit vector or rotation),
everything else kept. An answer that ignores a unit (a function of α alone where β matters,
coefficients in θ alone where ‖ω‖ matters) takes the same value on both points of such a pair
where the right answer does not, so it cannot match by interpolating the points.

**Features** (:func:`features`). From the values :math:`A` of an answer at the points come the
numbers that are rounded and digested: the value itself (two projections, grid
:data:`STEP_VALUE`), and for the hints, one projection each (grid :data:`STEP_HINT`) of: the
values near zero, each entry, :math:`A/\lVert A\rVert` (a constant multiple), :math:`A_k /
\lVert A_k\rVert` at every point (a factor that changes with the symbols), the traceless part
(the I term), and the coefficients of I, W, W² of a polynomial in W. A numeric answer has one
digest of all its entries together (grid :data:`STEP_NUMBER`, :func:`number_digest`).
"""

from __future__ import annotations

import zlib
from functools import lru_cache

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
from . import _digests as D
from ._reading import Rejected

#: Grid of the entries of a numeric answer: an entry within TOL of the right one always
#: passes, one more than 4 TOL away never does. Half-shifted (NUMBER_OFFSET): integers and short
#: decimals sit in the middle of their cells, so no neighbour cell has to be tried for them.
STEP_NUMBER = 3 * TOL
NUMBER_OFFSET = 0.5
#: Grid of the projections of a symbolic answer (its verdict) and of the hints' features.
STEP_VALUE = 8 * TOL
STEP_HINT = 32 * TOL


def number_groups(shape):
    """The index groups of a numeric answer's entries that are digested together: a matrix by
    columns, a vector or a number whole. (A digest per entry let a search recover a vector one
    entry at a time; the whole of a 3x3 matrix at once would need up to 1.7^9 candidate cells
    tried per comparison, since an entry is within TOL of a cell edge 2 times in 3.)"""
    if len(shape) == 2:
        return [list(range(j, shape[0] * shape[1], shape[1])) for j in range(shape[1])]
    return [list(range(int(np.prod(shape, dtype=int))))]


def number_digests(name, label, values, shape):
    """The digests of the groups of the entries ``values`` (flat) of a numeric answer."""
    v = np.ravel(values)
    return [
        D.cell_digest(name, f"{label}{g}", v[idx], STEP_NUMBER, NUMBER_OFFSET)
        for g, idx in enumerate(number_groups(shape))
    ]


def number_group_ok(name, label, values, shape, g, stored):
    """Do the entries of group ``g`` of ``values`` (within TOL each) have the stored digest?"""
    idx = number_groups(shape)[g]
    v = np.ravel(values)[idx]
    return D.matches(name, f"{label}{g}", v, STEP_NUMBER, stored, TOL, NUMBER_OFFSET)


#: Points: at least this many, in pairs over the units of the exercise.
MIN_POINTS = 48
_TURN = 4 * np.pi
_NEAR = 0.3  # half-width of the scalar ranges of the points near zero

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


def readable_symbols(spec):
    """The symbols an answer to ``spec`` may be written in: its allowed stand-ins (``W``,
    ``xx`` ...), its domain and the base symbols they stand for."""
    return set(spec.allowed or ()) | set(spec.domain) | set(base_symbols(spec))


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


def _units(spec):
    """The units that are drawn afresh one at a time: tuples of base symbols."""
    wanted = set(base_symbols(spec))
    units = []
    for vec in _VECTORS:
        if vec == S.omega and spec.unit_omega:
            units.append(tuple(vec))
        else:
            units.extend((s,) for s in vec)
    units.extend(tuple(MATRIX_DEFINITIONS[m]) for m in _ROTATIONS)
    units.extend((s,) for s in (*_SCALAR_RANGES, S.x_0))
    return [u for u in units if set(u) & wanted]


def _draw(rng, unit, spec, near):
    """Fresh values of one unit: {symbol: float}."""
    first = unit[0]
    if len(unit) == 9:  # a rotation
        return dict(zip(unit, _random_rotations(rng, 1)[0].ravel()))
    if len(unit) == 3:  # the unit vector ω
        v = rng.normal(size=3)
        return dict(zip(unit, v / np.linalg.norm(v)))
    if first in S.omega:  # a coordinate of a free ω: |ω| from about 0.3 to 2
        return {first: rng.uniform(0.2, 1.2) * rng.choice([-1.0, 1.0])}
    if first in _SCALAR_RANGES:
        lo, hi = _SCALAR_RANGES[first]
        return {first: rng.uniform(-_NEAR, _NEAR) if near and first != S.a else rng.uniform(lo, hi)}
    if first == S.x_0:
        return {first: rng.uniform(0.5, 2.0) * rng.choice([-1.0, 1.0])}
    return {first: rng.normal()}  # a coordinate of x, y, z or d


def fresh_points(spec, rng, n):
    """``n`` points drawn from ``rng`` over the same domain as :func:`points` (no pairs, no
    points near zero): ``{symbol: array}`` of the base symbols of ``spec``."""
    units, rows = _units(spec), []
    for _ in range(n):
        row = {}
        for unit in units:
            row.update(_draw(rng, unit, spec, False))
        rows.append(row)
    return {s: np.array([r[s] for r in rows]) for s in base_symbols(spec)}


@lru_cache(maxsize=64)
def points(name, spec):
    """Seeded values of the base symbols, ``{symbol: array}``, and the mask of the points near
    zero (cached). Base points, each followed by its variants with one unit drawn afresh."""
    rng = np.random.default_rng(zlib.crc32(name.encode()))
    units = _units(spec)
    per_base = 1 + len(units)
    bases = max(8, -(-MIN_POINTS // per_base))
    rows, near = [], []
    for k in range(bases):
        is_near = k % 4 == 0
        base = {}
        for unit in units:
            base.update(_draw(rng, unit, spec, is_near))
        rows.append(base)
        for unit in units:
            rows.append({**base, **_draw(rng, unit, spec, is_near)})
        near.extend([is_near] * per_base)
    syms = base_symbols(spec)
    pts = {s: np.array([r[s] for r in rows]) for s in syms}
    mask = np.array(near)
    mask.flags.writeable = False
    for v in pts.values():
        v.flags.writeable = False
    return pts, mask


def npoints(pts):
    """Number of points of a points dict."""
    return len(next(iter(pts.values()))) if pts else 1


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
    """Values of an explicit matrix at the points: complex array (points, rows, cols)."""
    n = npoints(pts)
    f = numeric_function(syms, M)
    args = [pts[s].astype(complex) for s in syms]
    with np.errstate(all="ignore"):
        rows = f(*args)
    return np.stack(
        [
            np.stack([np.broadcast_to(np.asarray(v, dtype=complex), (n,)) for v in row], -1)
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
        return np.broadcast_to(np.eye(e.shape[0], dtype=complex), (npoints(pts), *e.shape))
    if kind is ZeroMatrix:
        return np.zeros((npoints(pts), *e.shape), dtype=complex)
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
    """Real values (points, rows, cols) of an answer read by ``read_answer``."""
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


# ------------------------------------------------------------------------------ features


def _sign(A):
    """+1 or -1: the sign that makes the answer's projection on a fixed direction positive."""
    r = np.cos(np.arange(1, A.size + 1) * 1.618).reshape(A.shape)
    return 1.0 if np.sum(r * A) >= 0 else -1.0


def w_coefficients(A, pts):
    """Coefficients (points, 3) of A (points, 3, 3) in the basis I, Ŵ, Ŵ² at each point, or
    None when A is not in their span."""
    w = np.stack([pts[s] for s in S.omega], -1)
    H = np.zeros((len(w), 3, 3))
    H[:, 0, 1], H[:, 0, 2], H[:, 1, 2] = -w[:, 2], w[:, 1], -w[:, 0]
    H -= np.swapaxes(H, -1, -2)
    basis = np.stack([np.broadcast_to(np.eye(3), H.shape), H, H @ H], -1).reshape(-1, 9, 3)
    coeffs = np.stack([np.linalg.lstsq(b, m.ravel(), rcond=None)[0] for b, m in zip(basis, A)])
    fitted = np.einsum("kij,kj->ki", basis, coeffs)
    if not np.allclose(fitted, A.reshape(-1, 9), rtol=1e-9, atol=1e-9):
        return None
    return coeffs


def _uses_w(spec):
    return spec.matrix_degree is not None and S.W in set(spec.allowed or ())


def features(name, spec, A, pts, near, which):
    """The projections (label -> array) of the values A (points, *shape) named in ``which``:
    "value", "near", "entries", "scaled", "direction", "traceless", "coefficients"."""
    out = {}
    shape = spec.shape
    if "value" in which:
        out["value"] = D.projections(name, "value", A, 2)
    if "near" in which:
        out["near"] = D.projections(name, "near", A[near], 1)
    if "entries" in which and shape != ():
        flat = A.reshape(len(A), -1)
        for j in range(flat.shape[1]):
            out[f"entry{j}"] = D.projections(name, f"entry{j}", flat[:, j], 1)
    norm = np.sqrt(np.sum(A * A))
    if "scaled" in which and norm > 1e-6:
        out["scaled"] = D.projections(name, "scaled", _sign(A) * A / norm, 1)
    if "direction" in which and shape != ():
        axes = tuple(range(1, A.ndim))
        norms = np.sqrt(np.sum(A * A, axis=axes, keepdims=True))
        if np.all(norms > 1e-6):
            unit = A / norms
            signs = np.array([_sign(a) for a in unit]).reshape((-1,) + (1,) * len(shape))
            out["direction"] = D.projections(name, "direction", signs * unit, 1)
    if "traceless" in which and len(shape) == 2 and shape[0] == shape[1]:
        tr = np.trace(A, axis1=-2, axis2=-1) / shape[0]
        out["traceless"] = D.projections(name, "traceless", A - tr[:, None, None] * np.eye(3), 1)
    if "coefficients" in which and _uses_w(spec):
        coeffs = w_coefficients(A, pts)
        if coeffs is not None:
            for j in range(3):
                out[f"coef{j}"] = D.projections(name, f"coef{j}", coeffs[:, j], 1)
                out[f"-coef{j}"] = D.projections(name, f"coef{j}", -coeffs[:, j], 1)
    return out


def step_of(label):
    """The grid step of a feature."""
    return STEP_VALUE if label == "value" else STEP_HINT


def structure(A):
    """ "skew", "symmetric" or "" for the values A (points, n, n) of a square matrix answer."""
    if A.ndim != 3 or A.shape[1] != A.shape[2]:
        return ""
    At = np.swapaxes(A, -1, -2)
    scale = max(1.0, float(np.max(np.abs(A))))
    if np.max(np.abs(A + At)) <= TOL * scale:
        return "skew"
    if np.max(np.abs(A - At)) <= TOL * scale:
        return "symmetric"
    return ""
