"""A planted class of 30 for the class report's tests (issue 34), on problem set 1.

Every student has a **role** per exercise: right; one of the exercise's known mistakes (the
j-th mistake of the bank planted j + 1 times, so every count differs); an unexplained answer
(group A three times, written two ways with the same value; group B once); right value in
another form than asked (where the exercise asks for a form); no answer. Student 29 set a wrong
id in the kernel (another student's numbers); every fifth student handed in without running the
checks; two students of the gradebook submitted nothing. The first six students share one
variant of ``coords_by_projection`` and all of them make a known mistake there: a harder
variant.

:func:`grade` runs the planted check cells through the grader's own preprocessors
(:class:`instructor.grading.answer_log.NoteChecksRun`,
:class:`instructor.grading.preprocessor.VerifyRecords`) in this
process, without a kernel (the kernel's part, the record, is made by
:func:`course_lib.record.answer_record` as the check cell does), then stores each grade cell's
points in a real nbgrader gradebook as ``SaveAutoGrades`` would: full points unless the cell
ends with an error. :func:`expected` gives the counts the plan implies.
"""

from __future__ import annotations

import itertools
import shutil
import tempfile
from collections import Counter
from pathlib import Path

import nbformat
import numpy as np
import sympy as sp

from course_lib.exercises import EXERCISES, Choice, Value, set_student_id, variant_of
from course_lib.record import MIME, answer_record
from instructor import answers
from instructor.grading.answer_log import NoteChecksRun
from instructor.grading.preprocessor import VerifyRecords

PS = "ps01"
NOTEBOOK = "ps01_rigid_body_motion"
NAMES = [
    "coords_by_projection",
    "angle_from_lengths",
    "which_are_rigid",
    "unit_tangent",
    "lagrange_identity",
    "bac_cab",
    "motion_from_points",
]
FORM = {  # right value, not in the asked form (evaluated after the solution)
    "unit_tangent": "velocity / sp.sqrt(velocity.dot(velocity))",
    "lagrange_identity": "sp.expand(x.cross(y).dot(x.cross(y)))",
}
SIZE = 30
WRONG_ID = SIZE - 1
ABSENT = ("absent-1", "absent-2")
HARD = "coords_by_projection"


def _variant(name, sid):
    return variant_of(EXERCISES[name].variants, sid)[0]


def students():
    """30 ids: the first six share a variant of ``coords_by_projection``."""
    by_variant, pool = {}, []
    for i in range(100_000):  # 1,024 rows a key: six on one row turn up after a few thousand
        sid = f"stu{i:05d}"
        pool.append(sid)
        same = by_variant.setdefault(_variant(HARD, sid), [])
        same.append(sid)
        if len(same) == 6:
            break
    six = same
    rest = [sid for sid in pool if sid not in six]
    return six + rest[: SIZE - 6]


def kernel_id(ids, i):
    """The id the student's kernel had: another student's for the wrong-id student."""
    if i != WRONG_ID:
        return ids[i]
    mine = ids[i]
    return next(
        f"typo{k}"
        for k in itertools.count()
        if all(
            _variant(n, f"typo{k}") != _variant(n, mine)
            for n in NAMES
            if EXERCISES[n].variants is not None
        )
    )


def roles(name):
    """The role of each of the 30 students on exercise ``name``."""
    keys = list(EXERCISES[name].mistakes)
    plan = [f"mistake:{k}" for j, k in enumerate(keys) for _ in range(j + 1)]
    plan += ["A1", "A2", "A1", "B"]
    plan += ["form", "form"] if name in FORM else []
    plan += ["none"]
    plan += ["right"] * (SIZE - len(plan))
    plan[WRONG_ID] = "right"  # right for the numbers the kernel showed (another id's)
    return plan


def checked(i):
    return i % 5 != 4


def _namespace(name, kid):
    ex = EXERCISES[name]
    return answers.worked(name, variant_of(ex.variants, kid)[1] if ex.variants else None)


def _other_letters(ex, right, mistakes):
    taken = {frozenset(right)} | {frozenset(m) for m in mistakes}
    subsets = (set(c) for r in range(1, 4) for c in itertools.combinations(ex.answer.letters, r))
    return [s for s in subsets if frozenset(s) not in taken]


def _unexplained(ex, right, mistakes, which):
    if isinstance(ex.answer, Choice):
        return _other_letters(ex, right, mistakes)[0 if which.startswith("A") else 1]
    if isinstance(ex.answer, Value):  # the same numbers whatever the student's variant
        moved = np.full(ex.answer.shape, 0.5 if which.startswith("A") else 7.0)
        return moved.tolist() if ex.answer.shape else float(moved)
    items = list(sp.Matrix(right)) if ex.answer.shape else [sp.sympify(right)]
    if which == "A1":
        moved = [e + 1 for e in items]
    elif which == "A2":  # the same value written otherwise
        moved = [sp.expand(2 * (e + 1)) / 2 for e in items]
    else:
        moved = [2 * e + 3 for e in items]
    return moved if ex.answer.shape else moved[0]


def answer(name, role, kid):
    """The planted answer of a student whose kernel had id ``kid``."""
    ex = EXERCISES[name]
    ns = _namespace(name, kid)
    right = ns[ex.answer_variable]
    mistakes = answers.mistakes(ex.chapter)
    wrong = [eval(e, ns) for e in mistakes.get(name, {}).values()]
    if role == "right":
        return right
    if role == "none":
        return None
    if role.startswith("mistake:"):
        return eval(mistakes[name][role.split(":", 1)[1]], ns)
    if role == "form":
        return eval(FORM[name], ns)
    return _unexplained(ex, right, wrong, role)


def _cell(name, i, record):
    cell = nbformat.v4.new_code_cell(f'record("{name}", answer_{name}, check(...))')
    cell.metadata["nbgrader"] = {
        "grade": True,
        "grade_id": f"{name}-check",
        "locked": True,
        "points": EXERCISES[name].points,
        "solution": False,
        "schema_version": 3,
    }
    executed = [nbformat.v4.new_output("display_data", data={MIME: record, "text/plain": ""})]
    cell.outputs = executed if checked(i) else []
    cell.execution_count = 1 if checked(i) else None
    return cell, executed


def notebook(ids, i):
    """The handed-in notebook of student ``i`` and, per check cell, its outputs once run."""
    kid = kernel_id(ids, i)
    set_student_id(kid)
    try:
        made = [_cell(n, i, answer_record(n, answer(n, roles(n)[i], kid))) for n in NAMES]
    finally:
        set_student_id(None)
    return nbformat.v4.new_notebook(cells=[c for c, _ in made]), [o for _, o in made]


def grade_one(course, ids, i):
    """Grade student ``i`` with the grader's preprocessors; ``{exercise: points}``."""
    nb, executed = notebook(ids, i)
    resources = {
        "nbgrader": {
            "student": ids[i],
            "assignment": PS,
            "notebook": NOTEBOOK,
            "db_url": f"sqlite:///{course / 'gradebook.db'}",
        }
    }
    for k, cell in enumerate(nb.cells):
        NoteChecksRun().preprocess_cell(cell, resources, k)
        cell.outputs = executed[k]  # what the confined kernel's run leaves
        cell.execution_count = 1
    nb, _ = VerifyRecords().preprocess(nb, resources)
    return {
        n: 0.0
        if any(o.output_type == "error" for o in c.outputs)
        else float(c.metadata.nbgrader["points"])
        for n, c in zip(NAMES, nb.cells)
    }


_TEMPLATE = {}


def new_gradebook(path):
    """An empty nbgrader gradebook at ``path``, copied from one made once (nbgrader makes a new
    one by running ``alembic`` in a subprocess: seconds each on a loaded machine)."""
    from nbgrader.api import Gradebook

    if "db" not in _TEMPLATE:
        folder = Path(tempfile.mkdtemp(prefix="report-gradebook-"))
        with Gradebook(f"sqlite:///{folder / 'gradebook.db'}"):
            pass
        _TEMPLATE["db"] = folder / "gradebook.db"
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    shutil.copyfile(_TEMPLATE["db"], path)
    return Gradebook(f"sqlite:///{path}")


def gradebook(course, ids, points):
    """A real nbgrader gradebook of the planted class (``points[i]``: student i's points)."""
    with new_gradebook(course / "gradebook.db") as gb:
        gb.add_assignment(PS)
        gb.update_or_create_notebook(NOTEBOOK, PS)
        for name in NAMES:
            gb.update_or_create_grade_cell(
                f"{name}-check", NOTEBOOK, PS, max_score=EXERCISES[name].points, cell_type="code"
            )
        for sid in [*ids, *ABSENT]:
            gb.add_student(sid, first_name="Name", last_name=sid.upper())
        for sid, got in zip(ids, points):
            sub = gb.add_submission(PS, sid)
            for g in sub.notebooks[0].grades:
                g.auto_score = got[g.name[: -len("-check")]]
            gb.db.commit()


def expected(name):
    """What the report must count for exercise ``name``, from the plan."""
    plan = roles(name)
    ex = EXERCISES[name]
    variants = ex.variants is not None
    right = sum(r == "right" for r in plan) - (1 if variants else 0)
    mistakes = Counter(r.split(":", 1)[1] for r in plan if r.startswith("mistake:"))
    groups = [3, 1]
    return {
        "students": SIZE,
        "right": right,
        "mistakes": dict(mistakes),
        "groups": groups,
        "form": plan.count("form"),
        "no_answer": plan.count("none"),
        "other_numbers": 1 if variants else 0,
        "never_checked": sum(not checked(i) for i in range(SIZE)),
    }
