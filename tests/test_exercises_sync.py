"""Tests of tools/sync_exercises.py: the notebooks' exercise sections come from the bank.

The real notebooks' sections are exactly what the tool writes (each statement is written once,
in the bank), the tool is idempotent, and the cells carry the nbgrader metadata autograde
needs. Chapter 4's section is built on a stub notebook and its cells are run in order.
"""

import copy
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
from course_lib.exercises import exercises  # noqa: E402
from tools import sync_exercises as sync  # noqa: E402

NOTEBOOKS = sorted((ROOT / "notebooks").glob("0[1-9]_*.ipynb"))
MARKER_WORDS = ("BEGIN SOLUTION", "END SOLUTION", "HIDDEN TESTS")


def section(nb):
    start = next(
        i
        for i, c in enumerate(nb.cells)
        if c.cell_type == "markdown" and c.source.lstrip().startswith("## Exercises")
    )
    return nb.cells[start:]


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_real_notebook_section_is_what_the_bank_writes(path):
    nb = nbformat.read(path, as_version=4)
    again = sync.sync(copy.deepcopy(nb), sync.chapter_of(path))
    assert nbformat.writes(again) == nbformat.writes(nb)  # idempotent, up to date
    for ex in exercises(sync.chapter_of(path)):
        sources = [c.source for c in section(nb)]
        assert ex.markdown() in sources


def test_stub_notebook_gets_the_section_appended_and_a_second_run_changes_nothing():
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_markdown_cell("# Chapter 4")])
    once = sync.sync(copy.deepcopy(nb), 4)
    twice = sync.sync(copy.deepcopy(once), 4)
    assert nbformat.writes(once) == nbformat.writes(twice)
    assert once.cells[0].source == "# Chapter 4"
    assert len(once.cells) == 1 + 2 + 3 * len(exercises(4))
    nbformat.validate(once)


@pytest.mark.parametrize("chapter", [1, 2, 3, 4])
def test_cells_carry_nbgrader_metadata_points_by_level_and_unique_grade_ids(chapter):
    nb = sync.sync(nbformat.v4.new_notebook(), chapter)
    metas = [c.metadata["nbgrader"] for c in nb.cells]
    ids = [m["grade_id"] for m in metas]
    assert len(set(ids)) == len(ids)
    for ex in exercises(chapter):
        by_id = {m["grade_id"]: (m, c) for m, c in zip(metas, nb.cells)}
        check, cell = by_id[f"{ex.name}-check"]
        assert check["grade"] and check["locked"] and not check["solution"]
        assert check["points"] == ex.points
        assert "assert result.ok, result.message" in cell.source
        answer, cell = by_id[f"{ex.name}-answer"]
        assert answer["solution"] and not answer["grade"] and not answer["locked"]
        lines = cell.source.split("\n")
        assert lines[0] == f"{ex.answer_variable} = None"
        assert lines[1] == "### BEGIN SOLUTION" and lines[-1] == "### END SOLUTION"
    for cell in nb.cells:
        if cell.metadata["nbgrader"]["solution"]:
            continue
        for word in MARKER_WORDS:  # nbgrader matches them anywhere in a line
            assert word not in cell.source.upper()


@pytest.mark.parametrize("chapter", [1, 2, 3, 4])
def test_section_cells_run_in_order_and_every_check_passes(chapter):
    nb = sync.sync(nbformat.v4.new_notebook(), chapter)
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


def test_command_line_skips_a_missing_notebook_and_refuses_an_unnumbered_one(tmp_path, capsys):
    bad = tmp_path / "notes.ipynb"
    nbformat.write(nbformat.v4.new_notebook(), bad)
    assert sync.main([str(tmp_path / "04_missing.ipynb"), str(bad)]) == 2
    out = capsys.readouterr().out
    assert "no such notebook, skipped" in out and "must start with a chapter number" in out
    good = tmp_path / "04_working_with_rotations.ipynb"
    nbformat.write(nbformat.v4.new_notebook(), good)
    assert sync.main([str(good)]) == 0
    text = good.read_text()
    assert sync.main([str(good)]) == 0 and good.read_text() == text
    assert "(unchanged)" in capsys.readouterr().out


@pytest.mark.parametrize("chapter", [1, 2, 3, 4])
@pytest.mark.parametrize(
    "command",
    [["check", "--output-format", "concise"], ["format", "--check"]],
    ids=["ruff check", "ruff format --check"],
)
def test_generated_cells_pass_ruff(chapter, command, tmp_path):
    """What the tools write (setup cell, exercise section) is ruff-clean and in ruff's format.

    `make lint` covers the notebooks too; this finds a template or a worked solution that would
    not pass, before any notebook is regenerated. Formatting must also leave the nbgrader
    markers where they are (the answer cells are unchanged by `ruff format`). F401 is not asked
    of a section alone: chapter 3's answers are symbolic, yet its set-up cell imports numpy
    for the student's own work.
    """
    from tools import notebooks as nbtool

    nb = sync.sync(nbformat.v4.new_notebook(), chapter)
    nbtool.put_setup_cell(nb, "https://github.com/example/rotations-course")
    path = tmp_path / f"ch{chapter:02d}.ipynb"
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
