r"""The grader's verdict on a recorded answer, decided in the instructor's process.

The expected answers are the instructor's reference solutions, ``instructor/answers/chNN.py``,
run here (:func:`instructor.answers.worked`) and never shipped. A recorded answer
(:mod:`course_lib.record`) is read with the whitelist of :mod:`instructor.grading.records`, then
read again by the grader's own import of ``course_lib`` (exact types, bounded sizes), and
compared by the checker's public rules, :mod:`course_lib.exercises.compare`: the set of letters
of a choice; numbers within 4 TOL; an expression as the same tree, else at *fresh* random points
drawn now from the operating system's entropy over the whole domain (fresh points defeat an
answer fitted to the package's seeded points), then the form the exercise asks for.

The verdict is the checker's own type, :class:`course_lib.exercises.CheckResult`: ``ok`` only
when its status is ``"correct"``, and a one-line message for the instructor.
"""

from __future__ import annotations

import signal
import threading
from contextlib import contextmanager
from functools import cache

import numpy as np

from course_lib.exercises import EXERCISES, CheckResult, Choice, Value, variant_of, variant_row
from course_lib.exercises import compare as C
from instructor import answers

from .records import Unreadable, parse

__all__ = ["verdict", "expected", "student_parameters", "parameters_of", "SECONDS", "deadline"]

SECONDS = 20  # one verdict at most (the reading bounds keep it far below)
SAMPLED = " (compared at fresh random points)"


def _verdict(status, note):
    """The grader's verdict: a :class:`~course_lib.exercises.CheckResult`, the type of the
    student's own check, ``ok`` only when ``status`` is ``"correct"``."""
    return CheckResult(status == "correct", note, status)


def student_parameters(name, student):
    """``(index, parameters)`` of exercise ``name``'s variant for ``student``, derived here
    from the id the grader is given (never read from the notebook); ``(0, None)`` without
    variants."""
    ex = EXERCISES[name]
    if ex.variants is None:
        return 0, None
    return variant_of(ex.variants, "" if student is None else student)


def parameters_of(name, index):
    """The parameters of variant ``index`` of exercise ``name`` (None without variants)."""
    ex = EXERCISES[name]
    return None if ex.variants is None else variant_row(ex.variants, index)


@cache
def expected(name, index=0):
    """The reference answer of exercise ``name`` (of its variant ``index``) as the checker
    reads it (:func:`course_lib.exercises.compare.read`)."""
    ex = EXERCISES[name]
    ns = answers.worked(name, parameters_of(name, index))
    return C.read(ex, ns[ex.answer_variable])


def _judge(ex, data, index):
    kind = data.get("kind")
    if kind == "none":
        return _verdict("no answer", "no answer recorded")
    if kind == "unreadable":
        return _verdict("malformed", "the answer could not be read (the check cell says why)")
    if kind not in ("choice", "explicit", "matrix"):
        return _verdict("forged", "a record of an unknown kind")
    if (kind == "choice") != isinstance(ex.answer, Choice):
        return _verdict("forged", f"a record of kind {kind!r}, not what this exercise asks for")
    answer = data.get("answer") if kind == "choice" else parse(data.get("answer"))
    got = C.read(ex, answer)
    if not C.same(ex, got, expected(ex.name, index)):
        sampled = not isinstance(ex.answer, (Choice, Value))
        return _verdict("wrong", "wrong answer" + SAMPLED * sampled)
    violation = C.form_violation(ex, got)
    if violation:
        return _verdict("form", f"right value, not in the asked form: {violation}")
    return _verdict("correct", "correct")


def _wrong_note(note, index, student, shown, data):
    """The note of a wrong answer on a variant: whose numbers were graded, and, when the
    notebook showed others, which and how to fix the id (a note only: points never use it)."""
    note = f"{note}, for this student's numbers (those of {student!r}, variant {index})"
    shown = shown if isinstance(shown, dict) else {"variant": data.get("variant")}
    used = shown.get("variant")
    if type(used) is int and used != index:
        who = shown.get("student")
        if used == 0 and not who or who == "(example)":
            whose = "the example numbers (no student id was set)"
        elif isinstance(who, str) and who:
            whose = f"the numbers of the id {who!r} (variant {used})"
        else:
            whose = f"the numbers of variant {used}"
        note += (
            f"; your notebook showed {whose}: set your student id to your course e-mail in the "
            "first cell and check this answer on your own numbers, or ask for a regrade"
        )
    return note


class _TimeUp(TimeoutError):
    """The verdict took longer than its deadline."""


@contextmanager
def deadline(seconds):
    """Raise :class:`TimeoutError` in the main thread after ``seconds`` (elsewhere: no limit)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def _raise(signum, frame):
        raise _TimeUp

    old = signal.signal(signal.SIGALRM, _raise)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def verdict(name, data, student=None, shown=None):
    """The grader's verdict on the record ``data`` (a dict) of exercise ``name``, handed in by
    ``student`` (the course's key of the submission's student; None or "": the default
    numbers): a :class:`~course_lib.exercises.CheckResult`, whose ``message`` is one line for
    the instructor and ``status`` one of the checker's or ``"forged"`` / ``"unknown"``.

    An exercise with variants is re-checked against that student's own parameters: an answer
    to another student's numbers is wrong. ``shown``: which numbers the submitted notebook
    showed (``{"variant": k, "student": id}``, from its own run; default: the record's), only
    for the note of a wrong answer, never for the points. A record of another exercise, of an
    unknown layout, or that the whitelist refuses is not correct; nothing of the record is
    ever evaluated as code.
    """
    if name not in EXERCISES:
        return _verdict("unknown", f"no exercise called {name!r}")
    if type(data) is not dict or data.get("version") != 1:
        return _verdict("forged", "a record of an unknown layout")
    if data.get("exercise") != name:
        return _verdict("forged", "the record is of another exercise")
    try:
        with deadline(SECONDS), np.errstate(all="ignore"):
            index, _ = student_parameters(name, student)
            result = _judge(EXERCISES[name], data, index)
            if index and result.status == "wrong":
                return _verdict("wrong", _wrong_note(result.message, index, student, shown, data))
            return result
    except Unreadable as err:
        return _verdict("forged", str(err))
    except C.Rejected as err:
        return _verdict("malformed", f"refused on reading: {err}")
    except TimeoutError:
        return _verdict("malformed", f"no verdict within {SECONDS} s")
    except Exception as err:  # noqa: BLE001 - never stop the class for one record
        return _verdict("malformed", f"could not be checked ({type(err).__name__})")
