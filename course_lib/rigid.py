r"""Is a map :math:`g: \mathbb{R}^3 \to \mathbb{R}^3` a rigid body transformation? (Definition 1)

Definition 1 of the notes asks two things of :math:`g`, for all :math:`p_1, p_2 \in \mathbb{R}^3`:

1. it preserves length, :math:`\|g(p_1) - g(p_2)\| = \|p_1 - p_2\|`;
2. it preserves relative orientation between vectors,
   :math:`g(p_1) \times g(p_2) = g(p_1 \times p_2)`.

:func:`check_rigid` tests both on sample pairs and reports the worst counterexample.
:func:`rotation_map`, :func:`reflection_map` and :func:`translation_map` build the maps the
notebooks compare: the 90° turn about z (rigid), the mirror that flips z (fails condition 2)
and a translation (see the note in :func:`check_rigid`). :func:`vector_map` gives the map
:math:`g_*(v) = g(v) - g(0)` that a motion induces on free vectors.
"""

from dataclasses import dataclass

import numpy as np

from . import so3
from ._arrays import (
    as_count,
    as_direction,
    as_float_array,
    as_vector3,
    as_vectors,
    fmt_vector,
    require_finite,
    vector_norm,
)
from ._verdict import Verdict
from .tolerance import TOL, check_tol, fmt_residual, tol_label

__all__ = [
    "Counterexample",
    "RigidCheck",
    "check_rigid",
    "rotation_map",
    "reflection_map",
    "translation_map",
    "vector_map",
]

_CONDITIONS = {
    "length": "condition 1 (length)",
    "cross product": "condition 2 (relative orientation between vectors)",
}


@dataclass(frozen=True, eq=False, repr=False)
class Counterexample:
    r"""A pair of points on which a condition of Definition 1 fails.

    Attributes
    ----------
    p1, p2 : ndarray, shape (3,)
        The two sample points.
    lhs, rhs : float or ndarray
        The two sides that should be equal: :math:`\|g(p_1) - g(p_2)\|` and
        :math:`\|p_1 - p_2\|` (condition 1, floats), or :math:`g(p_1) \times g(p_2)` and
        :math:`g(p_1 \times p_2)` (condition 2, 3-vectors).
    mismatch : float
        The size of the difference, :math:`|lhs - rhs|` or :math:`\|lhs - rhs\|`.
    """

    p1: np.ndarray
    p2: np.ndarray
    lhs: object
    rhs: object
    mismatch: float

    def __repr__(self):
        return (
            f"Counterexample(p1={fmt_vector(self.p1)}, p2={fmt_vector(self.p2)}, "
            f"lhs={fmt_vector(self.lhs)}, rhs={fmt_vector(self.rhs)}, mismatch={self.mismatch:.1e})"
        )


@dataclass(frozen=True, eq=False, repr=False)
class RigidCheck(Verdict):
    r"""The result of :func:`check_rigid`, a :class:`~course_lib._verdict.Verdict`.

    Attributes
    ----------
    ok : bool
        True when both conditions hold on every sample pair (within the tolerance).
    message : str
        A sentence saying what was found, with the numbers (``str`` puts ✓ or ✗ before it).
    condition : {"length", "cross product", None}
        The first condition that fails, in the notes' order; None when ``ok``.
    counterexample : Counterexample or None
        The sample pair with the largest mismatch for the failed condition.
    n_pairs : int
        How many (ordered) pairs of points were checked.
    """

    condition: object = None
    counterexample: object = None
    n_pairs: int = 0

    def __repr__(self):
        mismatch = None if self.counterexample is None else f"{self.counterexample.mismatch:.1e}"
        return (
            f"RigidCheck(ok={self.ok}, condition={self.condition!r}, n_pairs={self.n_pairs}, "
            f"mismatch={mismatch})"
        )

    def _headline_markdown(self):
        return f"**{self.mark} {'rigid.' if self.ok else 'not rigid.'}** {self.message}"

    def _details_markdown(self):
        c = self.counterexample
        if c is None:
            return ""
        # a header row that names its columns: IBM's engine fails a table whose headers are empty
        return (
            f"| counterexample | value |\n|---|---|\n"
            f"| $p_1$ | `{fmt_vector(c.p1)}` |\n| $p_2$ | `{fmt_vector(c.p2)}` |\n"
            f"| left side | `{fmt_vector(c.lhs)}` |\n| right side | `{fmt_vector(c.rhs)}` |\n"
            f"| mismatch | {c.mismatch:.1e} |"
        )


def _call(g, x):
    """(shape of g(x), g(x)) or (None, the exception g raised)."""
    try:
        out = g(x.copy())
    except Exception as err:  # noqa: BLE001 - any failure only means "not this calling style"
        return None, err
    return np.shape(out), out


def _evaluate(g, X, tol):
    """g on the rows of X (M, 3), calling it on the whole batch or point by point.

    ``g`` is probed on two rows (a shape that a per-point ``R @ p`` cannot silently mistake for
    a 3x3 matrix) and on single points. It is used batched only if the batched probe gives back
    two 3-vectors that agree with the single-point calls (or if single points are refused);
    otherwise it is applied row by row, which is what g: R³ → R³ means.
    """
    M = X.shape[0]
    batch_shape, batch_out = _call(g, X[:2])
    single_shape, single_out = _call(g, X[0])
    batched = batch_shape == (2, 3)
    per_point = single_shape == (3,)
    if batched and per_point:
        rows = [single_out, _call(g, X[1])[1]]
        try:
            agree = np.allclose(
                np.asarray(batch_out, dtype=np.float64),
                np.asarray(rows, dtype=np.float64),
                rtol=0,
                atol=tol,
            )
        except (TypeError, ValueError):
            agree = False
        batched = bool(agree)
    if not (batched or per_point):

        def outcome(shape, out):
            return (
                f"raised {type(out).__name__}: {out}"
                if shape is None
                else f"returned shape {shape}"
            )

        got_batched, got_single = outcome(batch_shape, batch_out), outcome(single_shape, single_out)
        cause = single_out if single_shape is None else (batch_out if batch_shape is None else None)
        raise TypeError(
            f"g must map an (N, 3) array of points to an (N, 3) array, or one point of shape (3,) "
            f"to shape (3,); on points of shape (2, 3) g {got_batched}, and on one point of "
            f"shape (3,) g {got_single}"
        ) from cause
    if batched:
        out, how = g(X.copy()), "batched"
    else:
        out, how = [g(x.copy()) for x in X], "point by point"
    try:
        out = as_float_array(out, "g(p)")
    except ValueError as err:  # ragged: some calls returned other shapes
        raise ValueError(f"g must return one 3-vector per point (called {how}): {err}") from None
    if out.shape != (M, 3):
        raise ValueError(
            f"g must return one 3-vector per point: called {how} on {M} points it returned shape "
            f"{out.shape}, expected {(M, 3)}"
        )
    return require_finite(out, "g(p)")


def _pairs(points, n, seed):
    """(p1, p2) arrays of shape (K, 3) from the points argument of check_rigid."""
    if points is None:
        rng = np.random.default_rng(seed)
        sample = rng.standard_normal((as_count(n, "n", minimum=1), 2, 3))
        return sample[:, 0], sample[:, 1]
    pts = as_vectors(points, "points")
    if pts.ndim == 2:
        if pts.shape[0] < 2:
            raise ValueError(
                f"points must hold at least 2 points to form a pair, got shape {pts.shape}"
            )
        i, j = np.nonzero(~np.eye(pts.shape[0], dtype=bool))
        return pts[i], pts[j]
    if pts.ndim == 3 and pts.shape[1] == 2 and pts.shape[0] >= 1:
        return pts[:, 0], pts[:, 1]
    raise ValueError(
        f"points must have shape (N, 3) (every ordered pair of distinct points is checked) or "
        f"(K, 2, 3) (K explicit pairs), got shape {pts.shape}"
    )


def _require_checkable(p1, p2):
    """Refuse sample points so large that the check's own p1 − p2 or p1 × p2 overflows."""
    with np.errstate(over="ignore", invalid="ignore"):
        bad = ~(np.isfinite(p1 - p2).all(axis=-1) & np.isfinite(np.cross(p1, p2)).all(axis=-1))
    if bad.any():
        w = int(np.argmax(bad))
        raise ValueError(
            f"points are too large for this check: p1 − p2 or p1 × p2 overflows float64 for "
            f"p1 = {p1[w]}, p2 = {p2[w]} (‖p1‖ = {float(vector_norm(p1[w])):.3g}, ‖p2‖ = "
            f"{float(vector_norm(p2[w])):.3g}); use points with norms below 1e150"
        )


def _measure(p1, p2, image):
    """Both conditions on the pairs: {condition: (mismatch, lhs, rhs, allowed / tol)}.

    A mismatch that overflows is infinite (it fails); the allowed mismatch grows with the
    sizes involved beyond 1, so that rounding of large points is not taken for a failure.
    """
    k = p1.shape[0]
    g1, g2, gc = image[:k], image[k : 2 * k], image[2 * k :]
    with np.errstate(over="ignore", invalid="ignore"):
        len_lhs = vector_norm(g1 - g2)
        len_rhs = vector_norm(p1 - p2)
        cross_lhs = np.cross(g1, g2)
        measured = {
            "length": (np.abs(len_lhs - len_rhs), len_lhs, len_rhs, np.maximum(1.0, len_rhs)),
            "cross product": (
                vector_norm(cross_lhs - gc),
                cross_lhs,
                gc,
                np.maximum(1.0, vector_norm(p1) * vector_norm(p2)),
            ),
        }
    for mismatch, *_ in measured.values():
        mismatch[~np.isfinite(mismatch)] = np.inf
    return measured


def _allowed(scale, label):
    return label if scale == 1.0 else f"{label} × {scale:.3g}"


def _failure_message(condition, c, scale, tol):
    label = tol_label(tol)
    if condition == "length":
        return (
            f"‖g(p1) − g(p2)‖ = {c.lhs:.6g} but ‖p1 − p2‖ = {c.rhs:.6g} "
            f"(mismatch {fmt_residual(c.mismatch, scale * tol)} > {_allowed(scale, label)})"
        )
    if not np.isfinite(c.lhs).all():
        return "g(p1)×g(p2) overflows float64: g maps these points too far from the origin"
    return (
        f"g(p1)×g(p2) = {fmt_vector(c.lhs)}, g(p1×p2) = {fmt_vector(c.rhs)} "
        f"(‖difference‖ = {fmt_residual(c.mismatch, scale * tol)} > {_allowed(scale, label)})"
    )


def _rigid_verdict(p1, p2, measured, tol):
    """The RigidCheck of the measured mismatches: ✓, or the worst pair of the first failure."""
    k = p1.shape[0]
    label = tol_label(tol)
    plural = "pair" if k == 1 else "pairs"
    failed = [c for c, (mis, _, _, scale) in measured.items() if np.any(mis > tol * scale)]
    if not failed:
        return RigidCheck(
            ok=True,
            message=(
                f"g is a rigid body transformation on these {k} sample {plural}: both conditions "
                f"of Definition 1 hold within {label} (a sample can refute rigidity, never prove "
                f"it)."
            ),
            n_pairs=k,
        )
    condition = failed[0]
    mis, lhs, rhs, scale = measured[condition]
    w = int(np.argmax(np.where(mis > tol * scale, mis, -1.0)))  # the worst failing pair
    lhs, rhs = (float(lhs[w]), float(rhs[w])) if condition == "length" else (lhs[w], rhs[w])
    c = Counterexample(p1[w], p2[w], lhs, rhs, float(mis[w]))
    detail = _failure_message(condition, c, float(scale[w]), tol)
    also = f"; {_CONDITIONS['cross product']} fails too" if len(failed) == 2 else ""
    message = (
        f"g fails {_CONDITIONS[condition]}: {detail} for p1 = {fmt_vector(c.p1)}, "
        f"p2 = {fmt_vector(c.p2)}{also}; checked {k} sample {plural}."
    )
    return RigidCheck(ok=False, message=message, condition=condition, counterexample=c, n_pairs=k)


def check_rigid(g, points=None, n=50, seed=0, tol=TOL):
    r"""Test the two conditions of Definition 1 on sample pairs of points.

    For every sample pair :math:`(p_1, p_2)` it measures

    .. math::

        \big|\, \|g(p_1) - g(p_2)\| - \|p_1 - p_2\| \,\big| \le \mathrm{tol}
        \quad\text{(condition 1, length)}

        \| g(p_1) \times g(p_2) - g(p_1 \times p_2) \| \le \mathrm{tol}
        \quad\text{(condition 2, relative orientation between vectors)}

    Beyond unit sizes the allowed mismatch grows with the sizes compared, tol ×
    :math:`\|p_1 - p_2\|` and tol × :math:`\|p_1\|\|p_2\|`, because rounding does: a rotation
    of points a million units away is still rigid. Points so large that :math:`p_1 \times p_2`
    overflows float64 are refused (ValueError), not blamed on ``g``.

    A sample check can *refute* rigidity (one counterexample suffices) but never *prove* it:
    ``ok=True`` only means no sample pair failed. The proof for rotations is Proposition 7.

    Note on the notes' Definition 1: condition 2 is stated for points and applies the cross
    product to :math:`g(p_1), g(p_2)` themselves. Taken literally, a translation
    :math:`p \mapsto p + d` (:math:`d \ne 0`) preserves lengths but fails condition 2, although
    it is a rigid motion. The usual statement applies condition 2 to vectors
    :math:`v = p - q`, mapped by :math:`g_*(v) = g(p) - g(q)` (:func:`vector_map`); on points
    it singles out the linear rigid maps, the rotations. This function checks the definition as
    written; ``check_rigid(vector_map(g))`` checks the usual statement.

    Parameters
    ----------
    g : callable
        The map. Either vectorised, taking an (N, 3) array of points to an (N, 3) array, or
        taking one point (3,) to (3,); which one is detected and a per-point ``g`` is applied
        row by row.
    points : array_like, optional
        Shape (N, 3): every ordered pair of distinct points is checked (N(N−1) pairs).
        Shape (K, 2, 3): the K given pairs. Default: ``n`` random pairs.
    n : int, optional
        Number of random pairs when ``points`` is not given (default 50).
    seed : int or numpy.random.Generator, optional
        Seed of the random pairs (default 0, so results are reproducible).
    tol : float, optional
        Absolute tolerance on both mismatches, default :data:`~course_lib.tolerance.TOL`.

    Returns
    -------
    RigidCheck
        ``.ok``, ``.condition`` (``"length"``, ``"cross product"`` or None), ``.message``,
        ``.counterexample`` (the worst pair of the first failing condition) and ``.n_pairs``.
        It displays as a ✓/✗ sentence in a notebook.

    Raises
    ------
    TypeError
        If ``g`` is not callable, or maps neither (N, 3) → (N, 3) nor (3,) → (3,); if points
        are not numeric.
    ValueError
        If ``g`` returns the wrong number of points or NaN/inf, if ``points`` has a wrong shape
        or holds NaN/inf, or ``n`` < 1, or ``tol`` < 0.

    Examples
    --------
    >>> check_rigid(rotation_map(so3.rot_z(np.pi / 2))).ok
    True
    >>> result = check_rigid(reflection_map([0, 0, 1]), points=np.eye(3))
    >>> result.ok, result.condition
    (False, 'cross product')
    >>> print(result)
    ✗ g fails condition 2 (relative orientation between vectors): g(p1)×g(p2) = [0., 0., 1.],
    g(p1×p2) = [ 0.,  0., -1.] (‖difference‖ = 2.0e+00 > TOL = 1e-09) for p1 = [1., 0., 0.],
    p2 = [0., 1., 0.]; checked 6 sample pairs.
    """
    if not callable(g):
        raise TypeError(
            f"g must be a callable mapping points of R³ to R³, got {type(g).__name__} {g!r}"
        )
    tol = check_tol(tol)
    p1, p2 = _pairs(points, n, seed)
    _require_checkable(p1, p2)
    image = _evaluate(g, np.concatenate([p1, p2, np.cross(p1, p2)]), tol)
    return _rigid_verdict(p1, p2, _measure(p1, p2, image), tol)


def _image(p, f, what):
    """f(p) for the maps built here: a ValueError, not inf, if the image overflows float64."""
    p = as_vectors(p, "p")
    with np.errstate(over="ignore", invalid="ignore"):
        out = f(p)
    if not np.isfinite(out).all():
        raise ValueError(
            f"{what} overflows float64: p is too far from the origin (a coordinate of the image "
            f"would exceed 1.8e308)"
        )
    return out


def rotation_map(R):
    r"""The map :math:`p \mapsto R p` of a rotation matrix, for use with :func:`check_rigid`.

    .. math:: g(p) = R\,p, \qquad R \in SO(3)

    Parameters
    ----------
    R : array_like, shape (3, 3)
        A rotation (checked with :func:`course_lib.so3.check_rotation`).

    Returns
    -------
    callable
        ``g(p)`` for ``p`` of shape (..., 3), returning shape (..., 3).

    Raises
    ------
    ValueError
        If ``R`` is not a single 3x3 rotation matrix.

    Examples
    --------
    The notes' 90° turn about z takes x to y:

    >>> g = rotation_map(so3.rot_z(np.pi / 2))
    >>> np.round(g([1, 0, 0]), 12) + 0.0
    array([0., 1., 0.])
    """
    R = so3.check_rotation(R)
    if R.shape != (3, 3):
        raise ValueError(f"rotation_map needs one 3x3 rotation, got shape {R.shape}")
    R = R.copy()

    def g(p):
        return _image(p, lambda q: q @ R.T, "R p")

    g.__name__ = "rotation_map"
    g.__doc__ = "p ↦ R p for R =\n" + np.array2string(R, precision=4)
    return g


def reflection_map(normal):
    r"""The mirror across the plane through the origin with the given normal.

    .. math::
        g(p) = (I - 2\, n n^\mathsf{T})\, p, \qquad n = \frac{\text{normal}}{\|\text{normal}\|}

    It preserves lengths (condition 1) but reverses the relative orientation between vectors,
    so it fails condition 2 of Definition 1: with ``normal = (0, 0, 1)`` it is the notes'
    counterexample, :math:`g(x) \times g(y) = -g(x \times y)`.

    Parameters
    ----------
    normal : array_like, shape (3,)
        A nonzero normal vector of the mirror plane (it is normalised).

    Returns
    -------
    callable
        ``g(p)`` for ``p`` of shape (..., 3).

    Raises
    ------
    ValueError
        If ``normal`` is not one finite 3-vector, or ‖normal‖ ≤ TOL (no direction).

    Examples
    --------
    >>> g = reflection_map([0, 0, 1])
    >>> g([1.0, 2.0, 3.0])
    array([ 1.,  2., -3.])
    """
    n = as_direction(normal, "normal")
    M = np.eye(3) - 2.0 * np.outer(n, n)

    def g(p):
        return _image(p, lambda q: q @ M.T, "the mirror image of p")

    g.__name__ = "reflection_map"
    g.__doc__ = f"p ↦ (I − 2nnᵀ) p for n = {fmt_vector(n)}"
    return g


def translation_map(d):
    r"""The translation :math:`p \mapsto p + d`.

    .. math:: g(p) = p + d

    It preserves lengths, but for :math:`d \ne 0` it fails condition 2 of Definition 1 as the
    notes state it (on points): see the note in :func:`check_rigid`. On free vectors it acts as
    the identity, ``vector_map(translation_map(d))(v) == v``.

    Parameters
    ----------
    d : array_like, shape (3,)
        The displacement.

    Returns
    -------
    callable
        ``g(p)`` for ``p`` of shape (..., 3).

    Raises
    ------
    ValueError
        If ``d`` is not one finite 3-vector.

    Examples
    --------
    >>> result = check_rigid(translation_map([1, 0, 0]))
    >>> result.ok, result.condition
    (False, 'cross product')
    """
    d = as_vector3(d, "d").copy()

    def g(p):
        return _image(p, lambda q: q + d, "p + d")

    g.__name__ = "translation_map"
    g.__doc__ = f"p ↦ p + d for d = {fmt_vector(d)}"
    return g


def vector_map(g):
    r"""The map that the motion ``g`` induces on free vectors, :math:`g_*(v) = g(v) - g(0)`.

    A free vector is a difference of points, :math:`v = p - q` (eq. 7). A motion moves the two
    points, and with them the vector, to :math:`g(p) - g(q)`. For a motion
    :math:`g(p) = Rp + d` that is

    .. math:: g_*(v) = g(v) - g(0) = R\,v, \qquad g(p) - g(q) = R\,(p - q) = g_*(p - q),

    so :math:`g_*` depends on the vector only, not on the points that represent it (eq. 8), and
    the translation part drops out: a translation's :math:`g_*` is the identity, a rotation's
    is the rotation itself. This is how the usual statement of Definition 1 applies condition 2
    to vectors (see the note in :func:`check_rigid`): ``check_rigid(vector_map(g))``.

    Parameters
    ----------
    g : callable
        A map of points of R³, vectorised ((N, 3) to (N, 3)) or point by point ((3,) to (3,)),
        as accepted by :func:`check_rigid`.

    Returns
    -------
    callable
        ``g_star(v)`` for ``v`` of shape (..., 3), returning shape (..., 3). It calls ``g`` on
        the vectors and on the origin each time (``g`` may change between calls).

    Raises
    ------
    TypeError
        If ``g`` is not callable; when ``g_star`` is called, if ``g`` maps neither (N, 3) to
        (N, 3) nor (3,) to (3,), or ``v`` is not numeric.
    ValueError
        When ``g_star`` is called, if ``v`` does not have shape (..., 3) or holds NaN/inf, or
        ``g`` returns the wrong number of points or NaN/inf.

    Examples
    --------
    A translation does not change free vectors, so its vector map passes both conditions of
    Definition 1, while the translation itself fails condition 2:

    >>> shift = translation_map([1, 0, 0])
    >>> g_star = vector_map(shift)
    >>> g_star([0.0, 2.0, 3.0])
    array([0., 2., 3.])
    >>> check_rigid(shift).ok, check_rigid(g_star).ok
    (False, True)
    """
    if not callable(g):
        raise TypeError(
            f"g must be a callable mapping points of R³ to R³, got {type(g).__name__} {g!r}"
        )

    def g_star(v):
        v = as_vectors(v, "v")
        flat = v.reshape(-1, 3)
        # g(0) goes first, so g is always probed on at least two points (see _evaluate)
        image = _evaluate(g, np.concatenate([np.zeros((1, 3)), flat]), TOL)
        return (image[1:] - image[0]).reshape(v.shape)

    name = getattr(g, "__name__", type(g).__name__)
    g_star.__name__ = "vector_map"
    g_star.__doc__ = f"v ↦ g(v) − g(0), the map on free vectors of {name}"
    return g_star
