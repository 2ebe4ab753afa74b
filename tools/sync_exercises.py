"""Write the "## Exercises" section of chapter notebooks from the exercise bank.

    python tools/sync_exercises.py notebooks/*.ipynb

The chapter is read from the file name (``01_...`` is chapter 1). Everything from the markdown
cell that starts with ``## Exercises`` to the end of the notebook is replaced by:

- an introduction and the set-up cell (the imports of ``SETUP`` in the chapter's bank module);
- per exercise: the statement (markdown, from the bank), the answer cell (nbgrader solution
  cell: ``answer_<name> = None`` and the worked solution of ``tools/solutions/chNN.py`` between
  nbgrader's markers) and the check cell (nbgrader autograder test cell, locked, with the points
  of the exercise's level: it shows ✓, or fails with the hint).

A notebook without such a heading gets the section appended. Idempotent: a cell whose source
and metadata are already right keeps its outputs, so running it twice changes nothing. Cell ids
are derived from the exercise names. Re-execute the notebooks afterwards.
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

import nbformat

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from course_lib import exercise_bank  # noqa: E402
from course_lib.exercises import exercises  # noqa: E402
from course_lib.student import nbgrader_metadata  # noqa: E402
from tools.exercise_fingerprints import solutions  # noqa: E402

MARK = "### "
HEADING = "## Exercises"
INTRO = """## Exercises

Each exercise shows its level (warm-up, core or challenge) and its points in the heading. Write
your answer in the code cell under the statement and assign it to the variable named there;
the cell after it checks the answer: it shows ✓ when the answer is right, and otherwise stops
with an error whose message is a hint (it never shows the answer). Where an exercise asks for a
form (for example a matrix expression in `W`, which stands for $\\hat\\omega$), a right value in
another form is marked wrong, with a hint that says which form is asked for. Numbers are
compared to about nine digits: give exact values (`sp.sqrt(2)`, `sp.pi / 3`) or let Python
compute them, rather than typing rounded decimals.
The symbols come from `course_lib.exercises`."""


def _solution_source(ex, code):
    return "\n".join(
        [
            f"{ex.answer_variable} = None",
            MARK.strip() + " BEGIN SOLUTION",
            code.rstrip(),
            MARK.strip() + " END SOLUTION",
        ]
    )


def _check_source(ex):
    """The check cell: the student's check for feedback, and the answer's record for the
    grader (course_lib.record), which decides the points outside the student's kernel. No
    last-line value: nbgrader would read an execute_result as a partial score."""
    return (
        "from course_lib.record import record\n\n"
        f'result = check("{ex.name}", {ex.answer_variable})\n'
        f'record("{ex.name}", {ex.answer_variable}, result)\n'
        "assert result.ok, result.message"
    )


def section_cells(chapter):
    """The cells of a chapter's exercise section, as (kind, id, source, metadata) tuples."""
    bank = exercise_bank.chapter_module(chapter)
    sols, _ = solutions(chapter)
    cells = [
        (
            "markdown",
            f"ch{chapter}-exercises",
            INTRO,
            nbgrader_metadata(f"ch{chapter}-exercises", locked=True),
        ),
        (
            "code",
            f"ch{chapter}-exercises-setup",
            bank.SETUP,
            nbgrader_metadata(f"ch{chapter}-exercises-setup", locked=True),
        ),
    ]
    for ex in exercises(chapter):
        cells += [
            (
                "markdown",
                f"{ex.name}-statement",
                ex.markdown(),
                nbgrader_metadata(f"{ex.name}-statement", locked=True),
            ),
            (
                "code",
                f"{ex.name}-answer",
                _solution_source(ex, sols[ex.name]),
                nbgrader_metadata(f"{ex.name}-answer", solution=True),
            ),
            (
                "code",
                f"{ex.name}-check",
                _check_source(ex),
                nbgrader_metadata(f"{ex.name}-check", grade=True, locked=True, points=ex.points),
            ),
        ]
    return cells


def _make_cell(kind, cid, source, meta, old):
    if (
        old is not None
        and old.cell_type == kind
        and old.source == source
        and old.get("metadata", {}).get("nbgrader") == meta["nbgrader"]
    ):
        new = old  # unchanged: keep its outputs
    elif kind == "markdown":
        new = nbformat.v4.new_markdown_cell(source)
    else:
        new = nbformat.v4.new_code_cell(source)
    new.id = cid
    new.metadata = {**{k: v for k, v in new.get("metadata", {}).items() if k != "nbgrader"}, **meta}
    return new


def chapter_of(path):
    m = re.match(r"(\d\d)_", Path(path).name)
    if not m or int(m.group(1)) not in exercise_bank.CHAPTERS:
        raise ValueError(f"{path}: the file name must start with a chapter number, e.g. 01_")
    return int(m.group(1))


def sync(nb, chapter):
    """The notebook with its exercise section rewritten (a new cell list; nb is updated)."""
    start = next(
        (
            i
            for i, c in enumerate(nb.cells)
            if c.cell_type == "markdown" and c.source.lstrip().startswith(HEADING)
        ),
        len(nb.cells),
    )
    old = {c.get("id"): c for c in nb.cells[start:]}
    new = [
        _make_cell(kind, cid, src, meta, old.get(cid))
        for kind, cid, src, meta in section_cells(chapter)
    ]
    nb.cells = nb.cells[:start] + new
    return nb


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("notebooks", nargs="+", metavar="NOTEBOOK")
    args = parser.parse_args(argv)
    status = 0
    for name in args.notebooks:
        path = Path(name)
        if not path.is_file():
            print(f"{path}: no such notebook, skipped")
            continue
        try:
            chapter = chapter_of(path)
        except ValueError as err:
            print(err)
            status = 2
            continue
        text = path.read_text()
        nb = sync(nbformat.reads(text, as_version=4), chapter)
        out = nbformat.writes(nb) + ("\n" if text.endswith("\n") else "")
        if out != text:
            path.write_text(out)
        print(
            f"{path}: chapter {chapter}, {len(exercises(chapter))} exercises"
            + ("" if out != text else " (unchanged)")
        )
    return status


if __name__ == "__main__":
    sys.exit(main())
