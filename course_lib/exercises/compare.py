r"""Compare an answer with a reference answer by the checker's own rules (public API).

:func:`course_lib.exercises.check` compares a student's answer with stored digests of the
right one. The instructor's grader compares a *recorded* answer with the reference answer it
computes itself from the answers it never ships. Both must read, evaluate and judge the form
alike; this module is that common ground, and the only part of the checker the grader uses
besides the names of :mod:`course_lib.exercises`. It holds no answer.

- :func:`read`: an answer read as the checker reads it (exact types, bounded sizes), or
  :class:`Rejected` with the reason;
- :func:`fresh_points`: points drawn from any generator over the domain of the checker's own
  seeded points;
- :func:`same`: equality under the one tolerance policy (:mod:`course_lib.tolerance`):

  - a choice: the same set of letters;
  - numbers: :math:`\lVert a - b\rVert \le 4\,\mathrm{TOL}\max(1, \lVert b\rVert)` (the check
    accepts within TOL and refuses beyond 4 TOL, so the grader never disagrees with it);
  - an expression: the same expression tree, else, at :data:`ROUNDS` × :data:`NPOINTS` fresh
    points, every value within :math:`8\,\mathrm{TOL}\max(1, |b|)` (the checker's value grid);
- :func:`form_violation`: why a right value is not in the form the exercise asks for.

Examples
--------
>>> from course_lib.exercises import EXERCISES, W, hat, omega
>>> ex = EXERCISES["hat_fifth"]
>>> got = read(ex, W**5)
>>> same(ex, got, read(ex, hat(omega) ** 5)), same(ex, got, read(ex, W**3))
(True, False)
>>> form_violation(ex, got)
'reduce the higher powers first'
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from ..tolerance import TOL
from . import _engine as E
from ._check import form_violation as _form_violation
from ._check import numbers
from ._model import Choice, Value
from ._reading import _FUNCTIONS, Rejected, read_answer, read_choice

__all__ = [
    "ALLOWED_FUNCTIONS",
    "NPOINTS",
    "ROUNDS",
    "Rejected",
    "form_violation",
    "fresh_points",
    "numbers",
    "read",
    "same",
    "values",
]

#: The elementary functions an answer may use (sympy's classes).
ALLOWED_FUNCTIONS = _FUNCTIONS
#: Rounds of fresh points in :func:`same`, and points per round.
ROUNDS, NPOINTS = 2, 40


def read(ex, answer):
    """Answer ``answer`` to exercise ``ex`` as the checker reads it: the sorted letters of a
    choice, else ``(form, M)`` with ``form`` ``"explicit"`` (an ImmutableMatrix) or
    ``"matrix"`` (a matrix expression in ``W``, ``A`` ...).

    Raises
    ------
    Rejected
        If the checker would refuse the answer (its message says why).
    """
    spec = ex.answer
    if isinstance(spec, Choice):
        return read_choice(answer, spec.letters)
    if isinstance(spec, Value):
        return read_answer(answer, spec.shape, set(), numeric=True)
    return read_answer(answer, spec.shape, E.readable_symbols(spec))


def form_violation(ex, got):
    """Why the read answer ``got`` is not in the form exercise ``ex`` asks for (None: it is,
    or the exercise asks for no form)."""
    if isinstance(ex.answer, (Choice, Value)):
        return None
    return _form_violation(ex.answer, *got)


def fresh_points(spec, rng, n=NPOINTS):
    """``{symbol: array of n values}`` of the base symbols of the answer ``spec``, drawn from
    the numpy Generator ``rng`` over the domain of the checker's seeded points."""
    return E.fresh_points(spec, rng, n)


def values(ex, got, pts):
    """Real values of the read expression ``got`` of exercise ``ex`` at the points ``pts``:
    an array (points, rows, cols). Raises :class:`Rejected` where it is undefined or complex."""
    return E.values(got[0], got[1], E.base_symbols(ex.answer), pts)


def _explicit(form, M):
    """An explicit matrix of the answer (matrix symbols written out), or None when too big."""
    if form == "explicit":
        return M
    try:
        out = sp.ImmutableMatrix(M.xreplace(E.MATRIX_DEFINITIONS).doit())
    except Exception:  # noqa: BLE001 - too big or not explicit: the values decide
        return None
    return out if out.shape == M.shape else None


def _same_expression(ex, got, want, rng):
    a, b = _explicit(*got), _explicit(*want)
    if a is not None and a == b:  # the same expression tree: equal without sampling
        return True
    for _ in range(ROUNDS):
        pts = fresh_points(ex.answer, rng)
        va = values(ex, got, pts).reshape(NPOINTS, -1)
        vb = values(ex, want, pts).reshape(NPOINTS, -1)
        if not np.all(np.abs(va - vb) <= E.STEP_VALUE * np.maximum(1.0, np.abs(vb))):
            return False
    return True


def same(ex, got, want, rng=None):
    """Whether the read answers ``got`` and ``want`` of exercise ``ex`` are equal (module
    docstring). ``rng``: the generator of the fresh points (default: new entropy from the
    operating system, so that an answer fitted to any fixed points fails)."""
    spec = ex.answer
    if isinstance(spec, Choice):
        return got == want
    if isinstance(spec, Value):
        a, b = numbers(got[1]), numbers(want[1])
        return a.shape == b.shape and bool(
            np.linalg.norm(a - b) <= 4 * TOL * max(1.0, np.linalg.norm(b))
        )
    with np.errstate(all="ignore"):
        return _same_expression(ex, got, want, np.random.default_rng() if rng is None else rng)
