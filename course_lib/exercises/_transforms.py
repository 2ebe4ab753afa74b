r"""Known mistakes as transformations of the student's answer.

The package stores no digest of a known mistake's value where it can avoid it. Instead, the
fingerprint of a mistake names a transformation from the small, generic library below (a sign,
a transpose, rows for columns, a factor 2 or 1/2, degrees for radians, a cosine, a full turn,
...) that turns the mistaken answer into the right one. The checker applies it to the
*student's* answer and compares the result with the digests of the right answer: a match means
the student made that mistake. The tool ``python -m instructor.build.exercise_fingerprints``
finds, for every mistake of the bank, the transformation that does this (it holds both answers).

A transformation names only what the hint already says in words; none of them holds a value of
an answer.

Examples
--------
>>> NUMBER_OPS["rad"](180.0) == np.pi
True
>>> [int(i) for i in PERMUTATIONS["transpose"]((3, 3))]
[0, 3, 6, 1, 4, 7, 2, 5, 8]
"""

from __future__ import annotations

import numpy as np

from .. import symbolic as S

__all__ = ["NUMBER_OPS", "PERMUTATIONS", "EXPR_TRANSFORMS", "apply_letters"]


def _acos(v):
    return float(np.arccos(v)) if -1.0 <= v <= 1.0 else float("nan")


#: Operations on one entry of a numeric answer: each maps a mistaken entry to the right one.
NUMBER_OPS = {
    "same": lambda v: v,
    "neg": lambda v: -v,
    "half": lambda v: v / 2,
    "double": lambda v: 2 * v,
    "third": lambda v: v / 3,
    "triple": lambda v: 3 * v,
    "fifth": lambda v: v / 5,
    "two_thirds": lambda v: 2 * v / 3,
    "three_halves": lambda v: 3 * v / 2,
    "over_sqrt2": lambda v: v / np.sqrt(2),
    "over_sqrt3": lambda v: v / np.sqrt(3),
    "rad": lambda v: v * np.pi / 180,
    "acos": _acos,
    "cos": lambda v: float(np.cos(v)),
    "pi_minus": lambda v: np.pi - v,
    "two_pi_minus": lambda v: 2 * np.pi - v,
    "minus_two_pi": lambda v: v - 2 * np.pi,
    "plus_two_pi": lambda v: v + 2 * np.pi,
}


def _transpose(shape):
    return np.arange(int(np.prod(shape))).reshape(shape).T.ravel()


#: Rearrangements of the entries (index arrays into the flat answer), by name.
PERMUTATIONS = {
    "identity": lambda shape: np.arange(int(np.prod(shape))),
    "transpose": lambda shape: _transpose(shape) if len(shape) == 2 else None,
    "reverse": lambda shape: np.arange(shape[0])[::-1] if len(shape) == 1 else None,
    "cycle1": lambda shape: np.roll(np.arange(shape[0]), -1) if len(shape) == 1 else None,
    "cycle2": lambda shape: np.roll(np.arange(shape[0]), 1) if len(shape) == 1 else None,
}


def _norm_power(k):
    def apply(A, pts):
        if not all(s in pts for s in S.omega):
            return None
        n2 = sum(pts[s] ** 2 for s in S.omega)
        return A * (n2 ** (k / 2)).reshape((-1,) + (1,) * (A.ndim - 1))

    return apply


def _negate_component(i):
    def apply(A, pts):
        if A.ndim != 2 or i >= A.shape[1]:
            return None
        out = A.copy()
        out[:, i] = -out[:, i]
        return out

    return apply


def _scalar(f):
    return lambda A, pts: f(A) if A.ndim == 1 else None


#: Transformations of the values (points, *shape) of a symbolic answer, by name (None where
#: one does not apply to the answer's shape or symbols).
EXPR_TRANSFORMS = {
    "neg": lambda A, pts: -A,
    "transpose": lambda A, pts: np.swapaxes(A, -1, -2) if A.ndim == 3 else None,
    "reverse": lambda A, pts: A[:, ::-1] if A.ndim == 2 else None,
    **{f"neg{i}": _negate_component(i) for i in range(3)},
    "minus_half": _scalar(lambda a: a - 0.5),
    "plus_half": _scalar(lambda a: a + 0.5),
    "cos": _scalar(np.cos),
    "half": lambda A, pts: A / 2,
    "double": lambda A, pts: 2 * A,
    **{f"norm^{k}": _norm_power(k) for k in (2, 4, -2, -4)},
}


def apply_letters(mask, letters):
    """The letters that differ from ``letters`` in the letters of ``mask`` (a symmetric
    difference): what a mistake's mask turns the mistaken set into."""
    return "".join(sorted(set(letters) ^ set(mask)))
