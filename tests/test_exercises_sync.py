"""Tests of instructor/build/sync_exercises.py: problem sets come from the bank; chapters point to
them.

The committed problem sets are exactly what the tool writes (each statement is written once, in
the bank), the tool is idempotent, the cells carry the nbgrader metadata autograde needs, the
chapters hold no exercise, and what an instructor adds by hand (hidden tests, cells of their
own, a solution edited in the notebook) is never lost.
"""

import copy
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest

from course_lib.exercises import exercises
from instructor.build import sync_exercises as sync

ROOT = Path(__file__).resolve().parents[1]

CHAPTERS = [1, 2, 3, 4, 5]
MARKER_WORDS = ("BEGIN SOLUTION", "END SOLUTION", "HIDDEN TESTS")
HIDDEN = (
    "### BEGIN HIDDEN TESTS\nassert answer_coords_by_projection is not None\n### END HIDDEN TESTS"
)


def _fresh(chapter):
    return sync.sync_problem_set(None, chapter)


def _writes(nb):
    return nbformat.writes(nb)


@pytest.mark.parametrize("chapter", CHAPTERS)
def test_committed_problem_set_is_what_the_bank_writes(chapter):
    path = sync.problem_set_path(chapter)
    nb = nbformat.read(path, as_version=4)
    again = sync.sync_problem_set(copy.deepcopy(nb), chapter, path)
    assert _writes(again) == _writes(nb)  # idempotent, up to date
    sources = [c.source for c in nb.cells]
    for ex in exercises(chapter):  # an exercise with variants: its statement shown by a cell
        assert sync._statement(ex) in sources
        if ex.variants is not None:
            assert f'show("{ex.name}")' in sources[sources.index(sync._statement(ex)) + 1]


@pytest.mark.parametrize("chapter", CHAPTERS)
def test_chapter_holds_no_exercise_and_ends_with_a_pointer_that_resolves(chapter):
    path = sync.chapter_notebook(chapter)
    nb = nbformat.read(path, as_version=4)
    assert _writes(sync.sync_chapter(copy.deepcopy(nb), chapter)) == _writes(nb)
    assert not any("nbgrader" in c.metadata for c in nb.cells)
    assert not any("answer_" in c.source for c in nb.cells if c.cell_type == "code")
    last = nb.cells[-1]
    assert last.source.startswith("## Problem set")
    target = path.parent / f"../problem_sets/{sync.problem_set_path(chapter).name}"
    assert f"]({target.relative_to(path.parent)})" in last.source and target.resolve().is_file()


def test_a_new_problem_set_is_stable_and_valid():
    once = _fresh(4)
    twice = sync.sync_problem_set(copy.deepcopy(once), 4)
    assert _writes(once) == _writes(twice)
    # each exercise: statement, answer, check; one with variants also the cell showing its numbers;
    # the head: title, the student id (its text and its cell), how the exercises work, set-up
    assert len(once.cells) == 5 + sum(3 + (ex.variants is not None) for ex in exercises(4))
    assert once.cells[0].source.startswith("# Problem set 4 · Working with Rotations")
    nbformat.validate(once)


@pytest.mark.parametrize("chapter", CHAPTERS)
def test_cells_carry_nbgrader_metadata_points_by_level_and_unique_grade_ids(chapter):
    nb = _fresh(chapter)
    nb.cells = [c for c in nb.cells if sync.ID_META not in c.metadata]  # the student's own cell
    metas = [c.metadata["nbgrader"] for c in nb.cells]
    ids = [m["grade_id"] for m in metas]
    assert len(set(ids)) == len(ids)
    by_id = {m["grade_id"]: (m, c) for m, c in zip(metas, nb.cells)}
    for ex in exercises(chapter):
        check, cell = by_id[f"{ex.name}-check"]
        assert check["grade"] and check["locked"] and not check["solution"]
        assert check["points"] == ex.points
        assert "assert result.ok, result.message" in cell.source
        answer, cell = by_id[f"{ex.name}-answer"]
        assert answer["solution"] and not answer["grade"] and not answer["locked"]
        lines = cell.source.split("\n")
        if ex.variants is not None:  # the student's numbers first, read by the solution
            assert lines.pop(0).startswith(f'P = parameters("{ex.name}")  # your numbers: ')
        assert lines[0] == f"{ex.answer_variable} = None"
        assert lines[1] == "### BEGIN SOLUTION" and lines[-1] == "### END SOLUTION"
    for cell in nb.cells:
        if cell.metadata["nbgrader"]["solution"]:
            continue
        for word in MARKER_WORDS:  # nbgrader matches them anywhere in a line
            assert word not in cell.source.upper()


@pytest.mark.parametrize("chapter", CHAPTERS)
def test_the_student_id_comes_first_editable_and_lists_the_statements(chapter):
    """Issue 33/37: the problem set's first cells say how to set the id, set or ask for it, and
    show every statement with the student's numbers before any answer cell can stop Run All."""
    nb = _fresh(chapter)
    ids = [c.get("id") for c in nb.cells]
    title, text, cell = nb.cells[:3]
    assert ids[:3] == [
        f"ps{chapter}-title",
        f"ps{chapter}-student-id",
        f"ps{chapter}-student-id-cell",
    ]
    assert "student id" in title.source and text.source == sync.ID_INTRO
    for platform in ("laptop, Binder or Colab", "JupyterHub", "Gradescope or nbgrader"):
        assert platform in text.source
    assert cell.cell_type == "code" and "nbgrader" not in cell.metadata  # students edit it
    assert 'set_student_id("")' in cell.source and f"your_numbers({chapter})" in cell.source
    first_answer = next(i for i, c in enumerate(nb.cells) if c.get("id", "").endswith("-answer"))
    assert ids.index(f"ps{chapter}-student-id-cell") < first_answer


@pytest.mark.parametrize("chapter", CHAPTERS)
def test_problem_set_cells_run_in_order_and_every_check_passes(chapter):
    nb = _fresh(chapter)
    ns = {}
    results = []
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        ns.pop("result", None)
        exec(cell.source, ns)  # a check cell records the answer and shows the verdict
        if "result" in ns:
            results.append(ns["result"])
    assert len(results) == len(exercises(chapter))
    assert all(str(r).startswith("✓ ") for r in results), [str(r) for r in results]


def test_hidden_tests_and_hand_made_cells_survive_a_resync():
    nb = _fresh(1)
    check = next(c for c in nb.cells if c.id == "coords_by_projection-check")
    check.source += "\n" + HIDDEN
    mine = nbformat.v4.new_markdown_cell("A note of the instructor's, after exercise 1.1.")
    at = nb.cells.index(check) + 1
    nb.cells.insert(at, mine)
    first = nbformat.v4.new_code_cell("RNG_SEED = 7  # the instructor's own first cell")
    nb.cells.insert(0, first)
    again = sync.sync_problem_set(copy.deepcopy(nb), 1)
    assert _writes(again) == _writes(nb)
    ids = [c.id for c in again.cells]
    assert ids[0] == first.id and ids[ids.index("coords_by_projection-check") + 1] == mine.id
    kept = next(c for c in again.cells if c.id == "coords_by_projection-check")
    assert kept.source.endswith(HIDDEN) and kept.source.count("BEGIN HIDDEN TESTS") == 1


def test_a_changed_solution_in_tools_solutions_is_written(monkeypatch):
    nb = _fresh(1)
    sols, mistakes = sync.solutions(1)
    changed = {**sols, "coords_by_projection": sols["coords_by_projection"] + "  # edited"}
    monkeypatch.setattr(sync, "solutions", lambda chapter: (changed, mistakes))
    again = sync.sync_problem_set(nb, 1)
    cell = next(c for c in again.cells if c.id == "coords_by_projection-answer")
    assert "# edited" in cell.source


def test_a_solution_edited_in_the_notebook_is_never_overwritten(tmp_path):
    nb = _fresh(1)
    cell = next(c for c in nb.cells if c.id == "coords_by_projection-answer")
    cell.source = cell.source.replace("### END SOLUTION", "x_extra = 1\n### END SOLUTION")
    with pytest.raises(sync.SyncError, match="coords_by_projection-answer.*edited in the notebook"):
        sync.sync_problem_set(nb, 1, tmp_path / "ps01_x.ipynb")


def test_cells_of_an_exercise_removed_from_the_bank_are_dropped():
    nb = _fresh(1)
    stale = [
        nbformat.v4.new_markdown_cell("### Exercise 1.9: gone"),
        nbformat.v4.new_code_cell("answer_gone = None"),
    ]
    stale[0].id, stale[1].id = "gone-statement", "gone-answer"
    for cell in stale:
        cell.metadata["nbgrader"] = {"grade_id": cell.id, "locked": True}
    nb.cells += stale
    again = sync.sync_problem_set(nb, 1)
    assert not {"gone-statement", "gone-answer"} & {c.id for c in again.cells}


def test_chapter_cells_whose_ids_look_like_exercise_cells_are_kept():
    """Regression: a chapter cell id such as ``angles-check`` matched the exercise-id pattern and
    sync dropped it (found on chapter 05); only cells with nbgrader metadata are the tool's."""
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_markdown_cell("# Chapter 1 · Frames")])
    mine = nbformat.v4.new_code_cell("print(1)")
    mine.id = "angles-check"
    nb.cells.append(mine)
    again = sync.sync_chapter(nb, 1)
    assert [c.id for c in again.cells][-2:] == ["angles-check", "ch1-problem-set"]


def test_command_line_refuses_an_unknown_chapter(capsys):
    assert sync.main(["9"]) == 2
    assert "no such chapter in the bank: [9]" in capsys.readouterr().out


@pytest.mark.parametrize("chapter", CHAPTERS)
@pytest.mark.parametrize(
    "command",
    [["check", "--output-format", "concise"], ["format", "--check"]],
    ids=["ruff check", "ruff format --check"],
)
def test_generated_cells_pass_ruff(chapter, command, tmp_path):
    """What the tools write (setup cell, problem set) is ruff-clean and in ruff's format.

    `make lint` covers the notebooks too; this finds a template or a worked solution that would
    not pass, before any notebook is regenerated. Formatting must also leave the nbgrader
    markers where they are (the answer cells are unchanged by `ruff format`). F401 is not asked
    of a problem set: chapter 3's answers are symbolic, yet its set-up cell imports numpy for
    the student's own work.
    """
    from instructor.build import notebooks as nbtool

    nb = _fresh(chapter)
    nbtool.put_setup_cell(nb, "https://github.com/example/rotations-course")
    path = tmp_path / f"ps{chapter:02d}.ipynb"
    nbformat.write(nb, path)
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "ruff",
            *command,
            "--no-cache",
            "--config",
            str(ROOT / "pyproject.toml"),
        ]
        + (["--ignore", "F401"] if command[0] == "check" else [])
        + [str(path)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert run.returncode == 0, run.stdout + run.stderr
