r"""The grader's verdict on a recorded answer, decided in the instructor's process.

The expected answers are the instructor's reference solutions, ``instructor/answers/chNN.py``,
run here (after the chapter's set-up code) and never shipped. A recorded answer
(:mod:`course_lib.record`) is read with the whitelist of :mod:`instructor.grading.records`, then
read again by the grader's own import of ``course_lib`` (exact types, bounded sizes), and compared:

- **choice**: the set of letters;
- **numbers**: every entry within :math:`4\,\mathrm{TOL}\max(1, \lVert E\rVert)` of the
  reference (the student's check accepts within TOL, refuses beyond 4 TOL);
- **symbolic**: equal when both written out are the same expression tree, and otherwise
  at :data:`ROUNDS` × :data:`NPOINTS` *fresh* random points drawn now from the operating
  system's entropy over the whole domain, within the checker's 8 TOL. Fresh points defeat an
  answer fitted to the package's seeded points. The form the exercise asks for is checked with
  ``course_lib``'s own form check.

The verdict is ``"correct"`` or another status with a one-line note for the instructor.
"""

from __future__ import annotations

import signal
import threading
from contextlib import contextmanager
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import numpy as np
import sympy as sp

from course_lib import exercise_bank
from course_lib import symbolic as S
from course_lib.exercises import EXERCISES, Choice, Value
from course_lib.exercises import _engine as E
from course_lib.exercises._check import form_violation
from course_lib.exercises._reading import Rejected, read_answer, read_choice
from course_lib.exercises._variants import table, variant_of
from course_lib.tolerance import TOL
from instructor import answers

from .records import Unreadable, parse

__all__ = ["Verdict", "verdict", "expected", "fresh_points", "student_parameters", "SOLUTIONS"]

ROOT = Path(__file__).resolve().parents[2]
#: The folder of the answers (:mod:`instructor.answers`), which the confined kernel never sees.
SOLUTIONS = ROOT / "instructor" / "answers"
ROUNDS = 2
NPOINTS = 40  # fresh points per round
SECONDS = 20  # one verdict at most (the reading bounds keep it far below)


@dataclass(frozen=True)
class Verdict:
    """``status`` (``"correct"`` or why not) and a one-line ``note``."""

    status: str
    note: str

    @property
    def ok(self):
        return self.status == "correct"


def _solution_code(chapter):
    return answers.solutions(chapter)


def _readable(spec):
    return set(spec.allowed or ()) | set(spec.domain) | set(E.base_symbols(spec))


def student_parameters(name, student):
    """``(index, parameters)`` of exercise ``name``'s variant for ``student``, derived here
    from the id the grader is given (never read from the notebook); ``(0, None)`` without
    variants."""
    ex = EXERCISES[name]
    if ex.variants is None:
        return 0, None
    return variant_of(ex.variants, "" if student is None else student)


@cache
def expected(name, index=0):
    """The reference answer of exercise ``name`` (of its variant ``index``) as the checker
    reads it: the sorted letters of a choice, or ``(form, M)``."""
    ex = EXERCISES[name]
    ns = {}
    exec(exercise_bank.chapter_module(ex.chapter).SETUP, ns)  # the instructor's own code
    if ex.variants is not None:
        rows = table()["keys"].get(ex.variants.key) or [ex.variants.default]
        ns["P"] = rows[index]
    exec(_solution_code(ex.chapter)[name], ns)
    return _read(ex, ns[ex.answer_variable])


def _read(ex, obj):
    spec = ex.answer
    if isinstance(spec, Choice):
        return read_choice(obj, spec.letters)
    if isinstance(spec, Value):
        return read_answer(obj, spec.shape, set(), numeric=True)
    return read_answer(obj, spec.shape, _readable(spec))


def fresh_points(spec, rng):
    """Values of the base symbols of ``spec`` at 40 random points drawn from ``rng``, over the
    same domain as the checker's seeded points."""
    n = NPOINTS
    out = {}
    for vec in (S.omega, S.x, S.y, S.z, E.MATRIX_DEFINITIONS[S.d]):
        v = rng.normal(size=(n, 3))
        if vec == S.omega:
            v /= np.linalg.norm(v, axis=1, keepdims=True)
            if not spec.unit_omega:
                v *= rng.uniform(0.3, 2.0, size=(n, 1))
        out.update({s: v[:, i] for i, s in enumerate(vec)})
    for mat in (S.A, S.B, S.R):
        q = rng.normal(size=(n, 4))
        rots = _rotations(q / np.linalg.norm(q, axis=1, keepdims=True))
        for (i, j), s in np.ndenumerate(np.array(E.MATRIX_DEFINITIONS[mat], dtype=object)):
            out[s] = rots[:, i, j]
    turn = 4 * np.pi
    ranges = {S.theta: turn, S.alpha: turn, S.beta: turn, S.phi: turn, S.t: 4.0, S.a: 1.5}
    for s, half in ranges.items():
        out[s] = rng.uniform(-half, half, n)
    out[S.x_0] = rng.uniform(0.5, 2.0, n) * rng.choice([-1.0, 1.0], n)
    wanted = set(E.base_symbols(spec))
    return {s: v for s, v in out.items() if s in wanted}


def _rotations(q):
    w, x, y, z = q.T
    rows = [
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ]
    return np.stack([np.stack(r, -1) for r in rows], -2)


def _explicit(form, M):
    """An explicit matrix of the answer (matrix symbols written out), or None when too big."""
    if form == "explicit":
        return M
    try:
        out = sp.ImmutableMatrix(M.xreplace(E.MATRIX_DEFINITIONS).doit())
    except Exception:  # noqa: BLE001 - too big or not explicit: the numeric check decides
        return None
    return out if out.shape == M.shape else None


def _same_symbolic(ex, got, want):
    spec = ex.answer
    a, b = _explicit(*got), _explicit(*want)
    if a is not None and a == b:  # the same expression tree: equal without sampling
        return True
    rng = np.random.default_rng()  # fresh entropy from the operating system
    syms = E.base_symbols(spec)
    for _ in range(ROUNDS):
        pts = fresh_points(spec, rng)
        va = E.values(got[0], got[1], syms, pts).reshape(NPOINTS, -1)
        vb = E.values(want[0], want[1], syms, pts).reshape(NPOINTS, -1)
        if not _close(va, vb):
            return False
    return True


def _close(va, vb):
    """Equal values: within the checker's value grid (8 TOL) relative to max(1, |value|)."""
    return bool(np.all(np.abs(va - vb) <= E.STEP_VALUE * np.maximum(1.0, np.abs(vb))))


def _numbers(M):
    with np.errstate(all="ignore"):
        vals = np.array(E.numeric_function((), M)(), dtype=complex).ravel()
    if not np.all(np.isfinite(vals)) or np.max(np.abs(vals.imag), initial=0.0) > TOL:
        raise Rejected("not a finite real number")
    return vals.real


def _same_numbers(got, want):
    a, b = _numbers(got[1]), _numbers(want[1])
    return a.shape == b.shape and np.linalg.norm(a - b) <= 4 * TOL * max(1.0, np.linalg.norm(b))


def _judge(ex, data, index):
    kind = data.get("kind")
    if kind == "none":
        return Verdict("no answer", "no answer recorded")
    if kind == "unreadable":
        return Verdict("malformed", "the answer could not be read (the check cell says why)")
    if kind not in ("choice", "explicit", "matrix"):
        return Verdict("forged", "a record of an unknown kind")
    if kind == "choice":
        got = read_choice(data.get("answer"), ex.answer.letters)
        same = got == expected(ex.name, index)
        return Verdict("correct", "correct") if same else Verdict("wrong", "wrong answer")
    got = _read(ex, parse(data.get("answer")))
    want = expected(ex.name, index)
    if isinstance(ex.answer, Value):
        same = _same_numbers(got, want)
        return Verdict("correct", "correct") if same else Verdict("wrong", "wrong answer")
    if not _same_symbolic(ex, got, want):
        return Verdict("wrong", "wrong answer (compared at fresh random points)")
    violation = form_violation(ex.answer, *got)
    if violation:
        return Verdict("form", f"right value, not in the asked form: {violation}")
    return Verdict("correct", "correct")


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


class _TimeUp(Exception):
    pass


@contextmanager
def _deadline(seconds):
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
    """The grader's :class:`Verdict` on the record ``data`` (a dict) of exercise ``name``,
    handed in by ``student`` (the course's key of the submission's student; None or "": the
    default numbers).

    An exercise with variants is re-checked against that student's own parameters: an answer
    to another student's numbers is wrong. ``shown``: which numbers the submitted notebook
    showed (``{"variant": k, "student": id}``, from its own run; default: the record's), only
    for the note of a wrong answer, never for the points. A record of another exercise, of an
    unknown layout, or that the whitelist refuses is not correct; nothing of the record is
    ever evaluated as code.
    """
    if name not in EXERCISES:
        return Verdict("unknown", f"no exercise called {name!r}")
    if type(data) is not dict or data.get("version") != 1:
        return Verdict("forged", "a record of an unknown layout")
    if data.get("exercise") != name:
        return Verdict("forged", "the record is of another exercise")
    try:
        with _deadline(SECONDS), np.errstate(all="ignore"):
            index, _ = student_parameters(name, student)
            result = _judge(EXERCISES[name], data, index)
            if index and result.status == "wrong":
                return Verdict("wrong", _wrong_note(result.note, index, student, shown, data))
            return result
    except Unreadable as err:
        return Verdict("forged", str(err))
    except Rejected as err:
        return Verdict("malformed", f"refused on reading: {err}")
    except _TimeUp:
        return Verdict("malformed", f"no verdict within {SECONDS} s")
    except Exception as err:  # noqa: BLE001 - never stop the class for one record
        return Verdict("malformed", f"could not be checked ({type(err).__name__})")
