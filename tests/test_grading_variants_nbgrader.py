"""Per-student variants graded by real nbgrader (issue 27): two students swap their answers.

Problem set 4 in a `make course` directory. Each student's solved copy computes its answers from
``P = parameters(name)``, so in the confined kernel (which gets nbgrader's student id) it answers
that student's own numbers. Two students whose answer cells read the *other* student's numbers
(``parameters(name, student=other)``: an answer copied from a neighbour) get 0 on every exercise
with variants, with the grader's note, and full marks on the rest; a third student who did their
own work gets full marks.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from test_grading_nbgrader import run

from course_lib.exercises import exercises, variants_enabled
from course_lib.exercises._variants import table, variant_index
from instructor.grading.course import write_course

ROOT = Path(__file__).resolve().parents[1]


pytestmark = [pytest.mark.notebook_exec, pytest.mark.confined, pytest.mark.slow_grading]
PS, CHAPTER = "ps04", 4
VARIED = [ex for ex in exercises(CHAPTER) if ex.variants is not None]
TOTAL = sum(ex.points for ex in exercises(CHAPTER))


def _students():
    """Three student ids whose variants of every key of the problem set differ, none 0."""
    keys = {ex.variants.key for ex in VARIED}
    picked, seen = [], {k: set() for k in keys}
    for i in range(10_000):
        sid = f"student{i}"
        idx = {k: variant_index(k, len(table()["keys"][k]), sid) for k in keys}
        if all(v and v not in seen[k] for k, v in idx.items()):
            picked.append(sid)
            for k, v in idx.items():
                seen[k].add(v)
        if len(picked) == 3:
            return picked
    raise AssertionError("no three students with different variants")


def _submit(course, student, numbers_of):
    """The solved copy, its answer cells reading the numbers of ``numbers_of``."""
    import nbformat

    path = next((course / "source" / PS).glob("*.ipynb"))
    nb = nbformat.read(path, as_version=4)
    for cell in nb.cells:
        for ex in VARIED:
            if cell.get("id") == f"{ex.name}-answer" and numbers_of != student:
                own = f'P = parameters("{ex.name}")'
                assert own in cell.source
                cell.source = cell.source.replace(
                    own, f'P = parameters("{ex.name}", student="{numbers_of}")'
                )
    dest = course / "submitted" / student / PS
    dest.mkdir(parents=True)
    nbformat.write(nb, dest / path.name)
    (dest / "timestamp.txt").write_text("2026-01-01 00:00:00.000000 UTC")


def _points(course, student):
    from nbgrader.api import Gradebook

    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gb:
        sub = gb.find_submission(PS, student)
        return {g.cell.name: g.score for g in sub.notebooks[0].grades}


def test_swapped_answers_get_0_for_both_students_and_own_work_full_marks(tmp_path):
    assert variants_enabled() and VARIED, "the course ships its variants on"
    ada, bob, cyd = _students()
    write_course(tmp_path)
    code, out = run(["generate_assignment", PS, "--create"], tmp_path)
    assert code == 0, out
    _submit(tmp_path, ada, bob)
    _submit(tmp_path, bob, ada)
    _submit(tmp_path, cyd, cyd)
    code, out = run(["autograde", PS, "--create"], tmp_path)
    assert code == 0, out
    swapped = {f"{ex.name}-check" for ex in VARIED}
    for student in (ada, bob):
        points = _points(tmp_path, student)
        assert all(points[c] == 0 for c in swapped), (student, points)
        assert sum(points.values()) == TOTAL - sum(ex.points for ex in VARIED), points
        path = next((tmp_path / "autograded" / student / PS).glob("*.ipynb"))
        notes = path.read_text()
        assert "this student's numbers" in notes
    assert sum(_points(tmp_path, cyd).values()) == TOTAL
