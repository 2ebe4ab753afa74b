"""Write the problem sets from the exercise bank, and the pointer that ends each chapter.

    python -m instructor.build.sync_exercises          # every chapter of the bank
    python -m instructor.build.sync_exercises 1 3      # chapters 1 and 3 only

``make exercises`` runs it after ``instructor/build/exercise_fingerprints.py`` and before executing
the problem sets. For chapter N (reading notebook ``notebooks/NN_<slug>.ipynb``) it writes:

- ``problem_sets/psNN_<slug>.ipynb``, the nbgrader source notebook of the chapter's graded
  exercises: a title, how the exercises work, the set-up cell (the imports of ``SETUP`` in the
  chapter's bank module), then per exercise its statement (from the bank), its answer cell
  (nbgrader solution cell: ``answer_<name> = None`` and the worked solution of
  ``instructor/answers/chNN.py`` between nbgrader's markers) and its check cell (autograder test
  cell, locked, with the points of the exercise's level);
- the last cell of the chapter: a pointer to its problem set. A chapter holds no exercise.

What an instructor added by hand is kept: the hidden tests of a check cell (between
``### BEGIN HIDDEN TESTS`` and ``### END HIDDEN TESTS``) and every cell whose id this tool does
not write (it stays after the cell it followed). The worked solutions have one home,
``instructor/answers/chNN.py``: a problem set whose solution region differs from it is not
overwritten (the tool says where, and exits 2), so an edit made in the notebook is never lost.

Idempotent: a cell whose source and metadata are already right keeps its outputs. Cell ids are
derived from the exercise names. Re-execute the problem sets afterwards (``make exercises``).
"""

from __future__ import annotations

import argparse
import hashlib
import re
import sys
from pathlib import Path

import nbformat

from course_lib import exercise_bank
from course_lib.exercises import exercises
from instructor.build.exercise_fingerprints import solutions
from instructor.build.student import nbgrader_metadata

ROOT = Path(__file__).resolve().parents[2]

CHAPTERS_DIR = ROOT / "notebooks"
PROBLEM_SETS_DIR = ROOT / "problem_sets"
MARK = "### "
HIDDEN = re.compile(r"^### BEGIN HIDDEN TESTS$.*?^### END HIDDEN TESTS$", re.M | re.S)
SOLUTION = re.compile(r"^### BEGIN SOLUTION\n(.*?)\n### END SOLUTION$", re.M | re.S)
INTRO = """## How the exercises work

Each exercise shows its level (warm-up, core or challenge) and its points in the heading. Write
your answer in the code cell under the statement and assign it to the variable named there;
the cell after it checks the answer: it shows ✓ when the answer is right, and otherwise stops
with an error whose message is a hint (it never shows the answer). Where an exercise asks for a
form (for example a matrix expression in `W`, which stands for $\\hat\\omega$), a right value in
another form is marked wrong, with a hint that says which form is asked for. Numbers are
compared to about nine digits: give exact values (`sp.sqrt(2)`, `sp.pi / 3`) or let Python
compute them, rather than typing rounded decimals.
The symbols come from `course_lib.exercises`. Run the setup cell at the top first."""


class SyncError(Exception):
    """A problem set that the tool must not overwrite; the message says where and why."""


def chapter_notebook(chapter):
    """The reading notebook ``notebooks/NN_<slug>.ipynb`` of ``chapter``."""
    found = sorted(CHAPTERS_DIR.glob(f"{chapter:02d}_*.ipynb"))
    if len(found) != 1:
        raise SyncError(f"chapter {chapter}: expected one notebook notebooks/{chapter:02d}_*.ipynb")
    return found[0]


def problem_set_path(chapter):
    """``problem_sets/psNN_<slug>.ipynb``: the chapter's slug with ``ps`` in front."""
    return PROBLEM_SETS_DIR / f"ps{chapter_notebook(chapter).name}"


def chapter_title(chapter):
    """The title of the chapter's notebook, without its "Chapter N ·" prefix."""
    nb = nbformat.read(chapter_notebook(chapter), as_version=4)
    for cell in nb.cells:
        m = re.match(r"#\s+Chapter\s+\d+\s*·\s*(.+)", cell.source.strip())
        if cell.cell_type == "markdown" and m:
            return m.group(1).strip()
    raise SyncError(f"{chapter_notebook(chapter).name}: no '# Chapter {chapter} · Title' heading")


def _tally(chapter):
    exs = exercises(chapter)
    levels = ", ".join(
        f"{sum(ex.level == level for ex in exs)} {level}"
        for level in ("warm-up", "core", "challenge")
        if any(ex.level == level for ex in exs)
    )
    return f"{len(exs)} exercises, {sum(ex.points for ex in exs)} points ({levels})"


def _title(chapter):
    chap = chapter_notebook(chapter).name
    return (
        f"# Problem set {chapter} · {chapter_title(chapter)}\n\n"
        f"The graded exercises of chapter {chapter} ([{chap}](../notebooks/{chap})): "
        f"{_tally(chapter)}. {_reads(chapter)}"
        + (
            " Start with your student id (next section): some exercises give every student "
            "numbers of their own."
            if _varied(chapter)
            else ""
        )
    )


def _varied(chapter):
    return [ex for ex in exercises(chapter) if ex.variants is not None]


#: The section on the student id at the top of a problem set with variants (issue 33).
ID_INTRO = """## Your student id

Some exercises give every student numbers of their own, drawn from your **student id: your
institutional e-mail address** (unless your instructor names another id). Set it in the cell
below, once per session, before the exercises:

- **laptop, Binder or Colab**: type your e-mail between the quotes of `set_student_id("")`,
  then run the cell;
- **the course's JupyterHub**: nothing to type (leave the quotes empty): your hub user is used;
- **graded by Gradescope or nbgrader**: the grader uses the id of your submission, whatever
  this cell says.

The cell then says whose numbers these are and lists every statement with your numbers, so
that you can read them all before you start. Without an id, no check says ✓. If the numbers
you worked on were not those of your id, the grader's feedback says so and your instructor
sees it (a regrade, not a silent 0)."""


def _id_source(chapter):
    """The student-id cell: set the id (students edit the quotes), then the statements."""
    return (
        "from course_lib.exercises import set_student_id, your_numbers\n\n"
        'set_student_id("")  # laptop, Binder, Colab: your e-mail between the quotes; hub: leave\n'
        f"your_numbers({chapter})"
    )


def _reads(chapter):
    """What the problem set needs: the bank's ``READS`` (a chapter that also uses earlier ones
    says which), or the chapter alone."""
    default = "Read the chapter first; every exercise uses only what it shows."
    return getattr(exercise_bank.chapter_module(chapter), "READS", default)


def pointer_source(chapter):
    """The chapter's last cell: where its exercises are."""
    ps = problem_set_path(chapter).name
    return (
        "## Problem set\n\n"
        f"The exercises of this chapter are graded, in a notebook of their own: "
        f"[problem set {chapter}](../problem_sets/{ps}) (`problem_sets/{ps}`), "
        f"{_tally(chapter)}."
    )


#: The statement cell of an exercise with variants: its numbers are each student's own.
OWN_NUMBERS = (
    "In this exercise every student has their own numbers: the cell below shows the statement "
    "with yours (run it; the student-id cell at the top lists them too). In the answer cell, "
    "`P` holds them, by the names the statement uses."
)


def _statement(ex):
    """The markdown of the statement cell (an exercise with variants: the heading, and where
    the student's own statement is)."""
    if ex.variants is None:
        return ex.markdown()
    heading, *_, assign = ex.markdown().split("\n\n")
    return "\n\n".join([heading, OWN_NUMBERS, assign])


def _numbers_source(ex):
    """The locked cell that shows the statement with the student's numbers."""
    return f'from course_lib.exercises import show\n\nshow("{ex.name}")'


def _numbers_line(ex):
    """The answer cell's first line for an exercise with variants: the student's numbers."""
    line = f'P = parameters("{ex.name}")  # your numbers: '
    names = ", ".join(f'P["{p}"]' for p in ex.variants.default)
    if len(line + names) > 100:
        names = f'P["{next(iter(ex.variants.default))}"] ... (named as in the statement)'
    return line + names


def _solution_source(ex, code):
    numbers = [] if ex.variants is None else [_numbers_line(ex)]
    return "\n".join(
        [
            *numbers,
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


def problem_set_cells(chapter):
    """The generated cells of a problem set, as (kind, id, source, metadata) tuples."""
    bank = exercise_bank.chapter_module(chapter)
    sols, _ = solutions(chapter)
    head = [
        ("markdown", f"ps{chapter}-title", _title(chapter)),
        ("markdown", f"ch{chapter}-exercises", INTRO),
        ("code", f"ch{chapter}-exercises-setup", bank.SETUP),
    ]
    cells = [(kind, cid, src, nbgrader_metadata(cid, locked=True)) for kind, cid, src in head]
    if _varied(chapter):  # after the title: the id, and every statement with its numbers
        md, code = f"ps{chapter}-student-id", f"ps{chapter}-student-id-cell"
        cells[1:1] = [
            ("markdown", md, ID_INTRO, nbgrader_metadata(md, locked=True)),
            ("code", code, _id_source(chapter), {ID_META: True}),  # the student's to edit
        ]
    for ex in exercises(chapter):
        cells.append(
            (
                "markdown",
                f"{ex.name}-statement",
                _statement(ex),
                nbgrader_metadata(f"{ex.name}-statement", locked=True),
            )
        )
        if ex.variants is not None:
            cid = f"{ex.name}-numbers"
            cells.append(("code", cid, _numbers_source(ex), nbgrader_metadata(cid, locked=True)))
        cells += [
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


# ---------------------------------------------------------------------------------------------
# Merging with what is on disk
# ---------------------------------------------------------------------------------------------

_OWNED_ID = re.compile(
    r"^(ps\d+-title|ps\d+-student-id(-cell)?|ch\d+-exercises(-setup)?"
    r"|[a-z][a-z0-9_]*-(statement|numbers|answer|check))$"
)
#: The metadata key of the student-id cell (no nbgrader metadata: students edit it).
ID_META = "course_student_id"


def _owned(cell):
    """Whether the tool wrote ``cell``: an exercise-style id and nbgrader metadata.

    A chapter's own cells (ids such as ``angles-check``) and an instructor's cells (random ids)
    are never the tool's, whatever their ids look like.
    """
    meta = cell.get("metadata", {})
    return bool(_OWNED_ID.match(cell.get("id") or "")) and ("nbgrader" in meta or ID_META in meta)


def _digest(code):
    return hashlib.sha256(code.strip().encode()).hexdigest()[:16]


def _guard_solution(path, cid, old, code):
    """SyncError if the solution region of ``old`` was edited by hand and differs from ``code``."""
    m = SOLUTION.search(old.source)
    written = old.get("metadata", {}).get("course", {}).get("solution")
    if m is None or m.group(1).strip() == code.strip() or _digest(m.group(1)) == written:
        return
    raise SyncError(
        f"{path.name}, cell {cid}: its worked solution was edited in the notebook and differs "
        f"from instructor/answers; copy your edit into instructor/answers (the one home of the "
        f"solutions) or undo it, then run again. Nothing was written."
    )


def _make_cell(kind, cid, source, meta, old):
    if old is not None and old.cell_type == kind and cid.endswith("-check"):
        source = "\n".join([source, *HIDDEN.findall(old.source)])  # keep the hidden tests
    if old is not None and old.cell_type == kind and old.source == source:
        new = old  # unchanged: keep its outputs
    elif kind == "markdown":
        new = nbformat.v4.new_markdown_cell(source)
    else:
        new = nbformat.v4.new_code_cell(source)
    new.id = cid
    new.metadata = {**{k: v for k, v in new.get("metadata", {}).items() if k != "nbgrader"}, **meta}
    return new


def sync_problem_set(nb, chapter, path=None):
    """The problem set ``nb`` (or a new one) rewritten from the bank; hand-made cells kept."""
    path = path or problem_set_path(chapter)
    nb = nb or nbformat.v4.new_notebook()
    sols, _ = solutions(chapter)
    old = {c.get("id"): c for c in nb.cells}
    generated = problem_set_cells(chapter)
    ids = {cid for _, cid, _, _ in generated}
    for cid, cell in old.items():
        if cid in ids and cid.endswith("-answer"):
            _guard_solution(path, cid, cell, sols[cid.removesuffix("-answer")])
    follows, prev = {}, None  # hand-made cells, by the generated cell they follow
    for cell in nb.cells:
        cid = cell.get("id")
        if cid in ids:
            prev = cid
        elif not _owned(cell):
            follows.setdefault(prev, []).append(cell)
    cells = follows.get(None, [])
    for kind, cid, src, meta in generated:
        cell = _make_cell(kind, cid, src, meta, old.get(cid))
        if cid.endswith("-answer"):
            cell.metadata["course"] = {"solution": _digest(sols[cid.removesuffix("-answer")])}
        cells += [cell, *follows.get(cid, [])]
    nb.cells = cells
    nb.metadata.setdefault(
        "kernelspec", {"name": "python3", "display_name": "Python 3", "language": "python"}
    )
    return nb


def sync_chapter(nb, chapter):
    """The chapter ``nb`` without exercise cells, ending with the pointer to its problem set."""
    pid = f"ch{chapter}-problem-set"
    cells = [c for c in nb.cells if not _owned(c) and c.get("id") != pid]
    old = next((c for c in nb.cells if c.get("id") == pid), None)
    source = pointer_source(chapter)
    pointer = (
        old if old is not None and old.source == source else nbformat.v4.new_markdown_cell(source)
    )
    pointer.id = pid
    nb.cells = [*cells, pointer]
    return nb


def _write(path, nb, old_text):
    text = nbformat.writes(nb) + "\n"
    if text != old_text:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
    return text != old_text


def sync(chapter):
    """Rewrite the chapter's problem set and pointer; one line saying what changed."""
    ps_path, ch_path = problem_set_path(chapter), chapter_notebook(chapter)
    ps_text = ps_path.read_text(encoding="utf-8") if ps_path.exists() else ""
    ps = nbformat.reads(ps_text, as_version=4) if ps_text else None
    ps = sync_problem_set(ps, chapter, ps_path)
    ch_text = ch_path.read_text(encoding="utf-8")
    ch = sync_chapter(nbformat.reads(ch_text, as_version=4), chapter)
    changed = [
        p.name for p, nb, t in ((ps_path, ps, ps_text), (ch_path, ch, ch_text)) if _write(p, nb, t)
    ]
    return f"chapter {chapter}: {_tally(chapter)}; " + (
        f"rewrote {', '.join(changed)}" if changed else "unchanged"
    )


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("chapters", nargs="*", type=int, metavar="CHAPTER")
    args = parser.parse_args(argv)
    chapters = args.chapters or sorted(exercise_bank.CHAPTERS)
    unknown = sorted(set(chapters) - set(exercise_bank.CHAPTERS))
    if unknown:
        print(f"no such chapter in the bank: {unknown}; known: {sorted(exercise_bank.CHAPTERS)}")
        return 2
    try:
        for chapter in chapters:
            print(sync(chapter))
    except SyncError as err:
        print(err)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
