r"""The record of an answer that a check cell leaves for the grader.

A check cell of a problem set runs the student's own :func:`course_lib.exercises.check` for
the feedback (✓, or the hint) and calls :func:`record`, which writes the answer into the cell's
output as a *declarative record*: a small JSON object with the exercise's name and the answer
as sympy's ``srepr`` text (a tree of numbers, the exercise's symbols and elementary
functions), or the letters of a choice. Nothing is pickled, and the record holds only the
student's own answer.

At grading time the points are not decided here, in the student's kernel, but by the
instructor's grader, which reads the record with a whitelist (never ``eval``) and re-checks the
answer against the reference solutions at fresh random points. The record is a
``display_data`` output with the MIME type :data:`MIME` (front ends show its ``text/plain``
part, the verdict line); a check cell never produces an ``execute_result``, which nbgrader
would read as a partial score.

Examples
--------
>>> from course_lib.exercises import W
>>> data = answer_record("hat_fifth", -W)
>>> data["exercise"], data["kind"], data["answer"]
('hat_fifth', 'matrix', "MatMul(Integer(-1), MatrixSymbol(Str('W'), Integer(3), Integer(3)))")
>>> answer_record("hat_fifth", None)["kind"]
'none'
"""

from __future__ import annotations

import sympy as sp

from .exercises import Choice, Value, get, student_id, variant
from .exercises._engine import base_symbols
from .exercises._reading import read_answer, read_choice

__all__ = ["MIME", "VERSION", "CheckFailed", "answer_record", "record"]

#: MIME type of the record in a check cell's outputs.
MIME = "application/vnd.rotations-course.answer+json"
#: Version of the record's layout.
VERSION = 1


class CheckFailed(AssertionError):
    """A failed check: shown (and listed by ``nbgrader validate``) as one line with the hint."""

    def _render_traceback_(self):  # IPython shows this instead of a traceback
        return [f"{type(self).__name__}: {self}"]


def answer_record(name, answer):
    """The record of ``answer`` to exercise ``name``: a JSON-ready dict.

    ``kind`` is ``"none"`` (no answer yet), ``"unreadable"`` (the checker cannot read it; the
    student's check says why), ``"choice"`` (``answer`` holds the sorted letters),
    ``"explicit"`` or ``"matrix"`` (``answer`` holds the ``srepr`` of the answer as the checker
    reads it: an explicit matrix, or a matrix expression).
    """
    ex = get(name)
    out = {"version": VERSION, "exercise": name, "kind": "none", "answer": None}
    if ex.variants is not None:  # whose numbers the kernel used: a note for the grader, no points
        out["variant"] = variant(name)[1]
        out["student"] = student_id()[0]
    if answer is None:
        return out
    spec = ex.answer
    try:
        if isinstance(spec, Choice):
            out["kind"], out["answer"] = "choice", read_choice(answer, spec.letters)
            return out
        if isinstance(spec, Value):
            form, M = read_answer(answer, spec.shape, set(), numeric=True)
        else:
            readable = set(spec.allowed or ()) | set(spec.domain) | set(base_symbols(spec))
            form, M = read_answer(answer, spec.shape, readable)
        out["kind"], out["answer"] = form, sp.srepr(M)
    except Exception:  # noqa: BLE001 - the student's own check reports what is wrong
        out["kind"] = "unreadable"
    return out


def record(name, answer, result):
    """Show the verdict of the student's check and leave the answer's record for the grader.

    Displays one ``display_data`` output holding the record (:data:`MIME`) and, as its
    ``text/plain``, the line ``✓ name: correct.`` when the check passed (else nothing); when
    it did not pass, raises :class:`CheckFailed`
    with the whole hint on one line. Never returns a value (a check cell has no
    ``execute_result``).
    """
    from IPython.display import display  # only in a kernel

    # text/plain always: JupyterLab prints "No renderer could be found" for a bundle without
    # one; a failed check shows nothing here, its hint is the error line below.
    data = {MIME: answer_record(name, answer), "text/plain": str(result) if result.ok else ""}
    display(data, raw=True)
    if not result.ok:
        raise CheckFailed(f"✗ {result.message}")
