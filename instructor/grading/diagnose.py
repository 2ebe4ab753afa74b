"""What the grader notes about one graded answer, for the class report (issue 34).

:func:`entry` is called by :class:`instructor.grading.preprocessor.VerifyRecords` for every
exercise check cell, in the grader's process, after its verdict: it keeps the verdict, the **known
mistake** the answer is (its key in ``MISTAKES`` of ``instructor/answers/chNN.py``, whose hint text
is the bank's ``mistakes[key]``), the variant the student was graded on and the one the notebook
showed, whether the student had run the check cell in the notebook they handed in, and, for a wrong
answer that no known mistake explains, a short text of the answer and a **group** key: equal
values (or equal expressions) get the same key.

A known mistake is matched the way the grader matches the right answer
(:mod:`instructor.grading.verify`): the instructor's mistaken expression is computed for the
student's own variant and compared with the answer (choices: the same letters; numbers: within
4·TOL; expressions: the same tree, else at fresh random points). The group key of an expression is
its values at :data:`GROUP_POINTS` fixed points rounded to :data:`DIGITS` significant digits
(``x*(1+y)`` and ``x + x*y`` share one); of numbers, the numbers so rounded; of a choice, its
letters. Nothing here decides points.
"""

from __future__ import annotations

import hashlib
from functools import cache

import numpy as np
import sympy as sp

from course_lib.exercises import EXERCISES, Choice, Value
from course_lib.exercises import compare as C
from instructor import answers

from . import verify as V
from .records import parse

__all__ = ["entry", "known_mistake", "group_of", "CHECKED", "DIGITS", "OTHER"]

#: Cell metadata key set by :class:`instructor.grading.answer_log.NoteChecksRun` on each check cell.
CHECKED = "rotations_course_checked"
DIGITS = 6  # significant digits of the group key
GROUP_POINTS = 5
SHOWN = 120  # characters of an answer's text kept for the report
#: The group of a wrong answer that is right for the numbers the notebook showed (a wrong id).
OTHER = "other-numbers"


@cache
def _mistaken(name, index):
    """``{key: answer as the checker reads it}`` of exercise ``name``'s known mistakes, for its
    variant ``index`` (the instructor's code, run here like the reference solution)."""
    ex = EXERCISES[name]
    exprs = answers.mistakes(ex.chapter).get(name, {})
    if not exprs:
        return {}
    ns = answers.worked(name, V.parameters_of(name, index))
    out = {}
    for key, expr in exprs.items():
        try:
            out[key] = C.read(ex, eval(expr, ns))
        except Exception:  # noqa: BLE001 - a mistake that cannot be read is never matched
            continue
    return out


def _answer(ex, data):
    answer = data.get("answer")
    return C.read(ex, answer if isinstance(ex.answer, Choice) else parse(answer))


def known_mistake(name, got, index=0):
    """The key of the known mistake that the read answer ``got`` of exercise ``name`` is (for
    variant ``index``), or None.

    Examples
    --------
    >>> from course_lib.exercises import xx, xy, yy
    >>> ex = EXERCISES["lagrange_identity"]
    >>> known_mistake(ex.name, C.read(ex, xx * yy + xy**2))
    'plus'
    >>> known_mistake(ex.name, C.read(ex, xx * yy)) is None
    True
    """
    ex = EXERCISES[name]
    for key, want in _mistaken(name, index).items():
        try:
            if C.same(ex, got, want):
                return key
        except Exception:  # noqa: BLE001 - a comparison that fails is no match
            continue
    return None


def _round(values):
    vals = np.asarray(values, dtype=float).ravel()
    with np.errstate(all="ignore"):
        return [float(f"{v:.{DIGITS}g}") if np.isfinite(v) else str(v) for v in vals]


def _text(M):
    """An answer on one line: an explicit matrix by its entries, else sympy's text."""
    if isinstance(M, sp.MatrixBase):
        items = [sp.sstr(e) for e in M]
        return items[0] if len(items) == 1 else "(" + ", ".join(items) + ")"
    return sp.sstr(M)


def group_of(ex, got):
    """``(key, text)`` of a read answer: equal values share the key; the text shows it."""
    if isinstance(ex.answer, Choice):
        text = "{" + ", ".join(got) + "}"
        return text, text
    form, M = got
    if isinstance(ex.answer, Value):
        nums = _round(C.numbers(M))
        text = ", ".join(f"{v:.4g}" if isinstance(v, float) else v for v in nums)
        text = text if len(nums) == 1 else f"({text})"
        return text, text
    pts = C.fresh_points(ex.answer, np.random.default_rng(34), GROUP_POINTS)
    with np.errstate(all="ignore"):
        vals = C.values(ex, got, pts)
    key = hashlib.sha256(repr(_round(vals)).encode()).hexdigest()[:16]
    text = _text(M)
    return key, text if len(text) <= SHOWN else text[: SHOWN - 1] + "…"


def _shown_right(ex, got, shown, index):
    """Is the answer right for the variant the notebook showed (another id's numbers)?"""
    if ex.variants is None or type(shown) is not int or shown == index:
        return False
    try:
        want = V.expected(ex.name, shown)
    except IndexError:  # no such row: a forged number
        return False
    return C.same(ex, got, want)


def entry(name, data, student, result, checked=None):
    """What the report keeps of one graded answer (a JSON-ready dict).

    ``data`` is the record (or None when there was none), ``result`` the grader's verdict
    (a :class:`course_lib.exercises.CheckResult`, or None when a grading note gave 0 before any
    verdict), ``checked`` whether the check cell had been run in the handed-in notebook (None:
    unknown).
    """
    out = {
        "exercise": name,
        "verdict": "zero" if result is None else result.status,
        "mistake": None,
    }
    ex = EXERCISES.get(name)
    index = V.student_parameters(name, student)[0] if ex is not None else 0
    out["variant"] = index if ex is not None and ex.variants is not None else None
    shown = data.get("variant") if isinstance(data, dict) else None
    out["shown"] = shown if type(shown) is int else None
    out["checked"] = checked
    if result is None or result.status != "wrong" or ex is None:
        return out
    try:
        with V.deadline(V.SECONDS), np.errstate(all="ignore"):
            got = _answer(ex, data)
            out["mistake"] = known_mistake(name, got, index)
            if out["mistake"] is None and _shown_right(ex, got, out["shown"], index):
                out["group"], out["answer"] = OTHER, "right for the numbers the notebook showed"
            elif out["mistake"] is None:
                out["group"], out["answer"] = group_of(ex, got)
    except Exception as err:  # noqa: BLE001 - also the time limit (a note, never a stop)
        out["group"], out["answer"] = "unreadable", f"({type(err).__name__})"
    return out
