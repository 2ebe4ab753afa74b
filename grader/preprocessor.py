"""The nbgrader preprocessors of the course (named in its ``nbgrader_config.py``).

- :class:`ConfinedExecute` runs a submission in the confined kernel of :mod:`grader.sandbox`
  (nbgrader's own ``Execute``, with that kernel manager whatever the notebook names).
- :class:`VerifyRecords` runs after it, in nbgrader's process, which no student code has
  touched: every exercise check cell keeps its points only when the grader's verdict on the
  answer it recorded (:mod:`grader.verify`) is "correct"; otherwise its outputs become one
  error whose one line says why. A missing, duplicated, forged or unreadable record gives 0.
- :class:`GuardCells` runs first on a submission (sanitize stage): a grade cell of the release
  that was deleted, duplicated or retyped is put back as released, with an error output that
  gives it 0 and says what happened, so that nbgrader grades the rest of the notebook and the
  rest of the class instead of stopping. Grade or solution metadata that is not in the release
  (a cell the student added, an answer cell turned into a graded one) is removed: the cell is
  a plain cell (0 points), followed by a note.
- :class:`CapOutput` cuts the outputs of each cell to :attr:`CapOutput.max_bytes` (100 kB) of
  text with a note, keeping every error (which decides a grade cell's 0).
- When the kernel dies (``os._exit`` in an answer cell, a crash, the memory limit),
  :class:`ConfinedExecute` keeps what ran and gives every grade cell that did not run 0 with a
  note, instead of leaving the student without a grade.
"""

from __future__ import annotations

import json

import nbformat
from nbclient.exceptions import DeadKernelError
from nbgrader import utils
from nbgrader.api import Gradebook, MissingEntry
from nbgrader.preprocessors import Execute, NbGraderPreprocessor
from traitlets import Integer

from course_lib.record import MIME
from course_lib.student import nbgrader_metadata

from .sandbox import ConfinedKernelManager
from .verify import verdict

__all__ = ["ConfinedExecute", "VerifyRecords", "GuardCells", "CapOutput", "note_output"]

SUFFIX = "-check"
ZERO = "rotations_course_zero"  # cell metadata: the note of a grade cell put back with 0


def note_output(note):
    """An error output holding one line: nbgrader gives its cell 0 points."""
    return nbformat.v4.new_output(
        "error", ename="GradingNote", evalue=note, traceback=[f"GradingNote: {note}"]
    )


class ConfinedExecute(Execute):
    """nbgrader's Execute with the confined kernel (:mod:`grader.sandbox`)."""

    def __init__(self, *args, **kwargs):
        kwargs["kernel_manager_class"] = ConfinedKernelManager
        super().__init__(*args, **kwargs)

    def preprocess(self, nb, resources=None, km=None):
        try:
            return super().preprocess(nb, resources, km=km)
        except DeadKernelError:
            self.log.warning("the kernel died: grade cells that did not run get 0")
        for cell in nb.cells:
            if cell.cell_type == "code" and utils.is_grade(cell) and cell.execution_count is None:
                gid = cell.metadata.nbgrader.get("grade_id", "")
                note = (
                    f"{gid}: 0 points: the kernel died (os._exit, a crash or the memory limit) "
                    "before this cell ran."
                )
                cell.outputs = [note_output(note)]
                cell.metadata[ZERO] = note  # VerifyRecords keeps this note
        return nb, resources


def _records(cell):
    return [o for o in cell.get("outputs", []) if MIME in o.get("data", {})]


class VerifyRecords(NbGraderPreprocessor):
    """Each exercise check cell keeps its points only on the grader's "correct"."""

    def preprocess_cell(self, cell, resources, cell_index):
        if cell.cell_type != "code" or not utils.is_grade(cell):
            return cell, resources
        grade_id = cell.metadata.nbgrader.get("grade_id", "")
        if not grade_id.endswith(SUFFIX):
            return cell, resources
        name = grade_id[: -len(SUFFIX)]
        zero = cell.metadata.pop(ZERO, None)
        if zero:
            cell.outputs = [note_output(zero)]
            return cell, resources
        failed = any(o.output_type == "error" for o in cell.outputs)
        records = _records(cell)
        if len(records) != 1:
            note = "no answer record" if not records else f"{len(records)} answer records"
            cell.outputs = [note_output(f"{name}: 0 points: {note} in the check cell's output.")]
            return cell, resources
        result = verdict(name, json.loads(json.dumps(records[0]["data"][MIME])))
        if not result.ok:
            cell.outputs = [note_output(f"{name}: 0 points from the grader: {result.note}.")]
        elif not failed:  # nothing in the outputs may read as a score: no execute_result
            cell.outputs = [
                o
                for o in cell.outputs
                if o.output_type != "execute_result"
                and not (o.output_type == "stream" and o.name == "stderr")
            ]
        self.log.info("%s: grader's verdict %s", name, result.status)
        return cell, resources


class GuardCells(NbGraderPreprocessor):
    """Put back deleted, duplicated or retyped grade cells, each with 0 points and a note."""

    def preprocess(self, nb, resources):
        notebook_id = resources["unique_key"]
        assignment_id = resources["nbgrader"]["assignment"]
        with Gradebook(resources["nbgrader"]["db_url"]) as gb:
            try:
                source = gb.find_notebook(notebook_id, assignment_id)
            except MissingEntry:
                return nb, resources
            released = {c.name: (c.cell_type, c.source) for c in source.source_cells}
            grades = {g.name: g.max_score for g in source.grade_cells}
            solutions = {c.name for c in source.solution_cells}
        seen, cells = set(), []
        for cell in nb.cells:
            gid = cell.get("metadata", {}).get("nbgrader", {}).get("grade_id")
            note = _unreleased(cell, grades, solutions, released)
            if note:
                self.log.warning("%s: %s", notebook_id, note)
                cells += [cell, nbformat.v4.new_markdown_cell(f"**GradingNote**: {note}")]
                continue
            if gid not in grades or gid not in released:
                cells.append(cell)
                continue
            if gid in seen:
                self.log.warning("%s: grade cell %s duplicated", notebook_id, gid)
                cells[_index(cells, gid)] = _zero(released[gid], gid, grades[gid], "was duplicated")
                continue
            seen.add(gid)
            if cell.cell_type != released[gid][0]:
                self.log.warning("%s: grade cell %s retyped", notebook_id, gid)
                cell = _zero(released[gid], gid, grades[gid], "was changed to another type")
            cells.append(cell)
        for gid in sorted(set(grades) - seen):
            if gid in released:
                self.log.warning("%s: grade cell %s deleted: put back with 0", notebook_id, gid)
                cells.append(_zero(released[gid], gid, grades[gid], "was deleted"))
        nb.cells = cells
        return nb, resources


def _unreleased(cell, grades, solutions, released):
    """Remove grade or solution metadata that the release does not have; the note, or None."""
    meta = cell.get("metadata", {}).get("nbgrader")
    if not isinstance(meta, dict):
        return None
    gid = str(meta.get("grade_id", ""))[:80]
    added = []
    if meta.get("grade") and gid not in grades:
        added.append("a grade cell")
    if meta.get("solution") and gid not in solutions:
        added.append("an answer cell")
    if not added and (gid in released or gid in grades or gid in solutions or not meta):
        return None
    if gid in grades or gid in solutions or gid in released:
        meta["grade"] = bool(meta.get("grade")) and gid in grades
        meta["solution"] = bool(meta.get("solution")) and gid in solutions
        if not meta["grade"]:
            meta.pop("points", None)
    else:
        del cell.metadata["nbgrader"]
    what = " and ".join(added) or "grading metadata"
    return (
        f"the cell `{gid}` was made {what} in the submission, which the released problem "
        "set does not have: graded as a plain cell (0 points)."
    )


class CapOutput(NbGraderPreprocessor):
    """At most :attr:`max_bytes` of output text per cell; errors are always kept (shortened)."""

    max_bytes = Integer(100_000, help="Output bytes kept per cell.").tag(config=True)

    def preprocess_cell(self, cell, resources, cell_index):
        if cell.cell_type != "code":
            return cell, resources
        budget, kept, cut = self.max_bytes, [], 0
        for out in cell.get("outputs", []):
            size = _size(out)
            if out.output_type == "error":
                kept.append(_short_error(out))
            elif size <= budget:
                kept.append(out)
                budget -= size
            else:
                cut += size
                if out.output_type == "stream" and budget > 0:
                    kept.append(
                        nbformat.v4.new_output("stream", name=out.name, text=out.text[:budget])
                    )
                    cut -= budget
                budget = 0
        if cut:
            note = f"\n[GradingNote: {cut} bytes of output cut, over {self.max_bytes} per cell]\n"
            kept.append(nbformat.v4.new_output("stream", name="stdout", text=note))
            cell.outputs = kept
        return cell, resources


def _size(out):
    """Bytes of an output's text (at least 100: a flood of empty outputs counts too)."""
    parts = [out.get("text", ""), out.get("evalue", ""), *out.get("traceback", [])]
    for value in out.get("data", {}).values():
        parts.append(value if isinstance(value, str) else json.dumps(value))
    return max(100, sum(len(p) for p in parts if isinstance(p, str)))


def _short_error(out, limit=2_000):
    return nbformat.v4.new_output(
        "error",
        ename=str(out.get("ename", ""))[:200],
        evalue=str(out.get("evalue", ""))[:limit],
        traceback=[line[:limit] for line in out.get("traceback", [])[-5:]],
    )


def _index(cells, gid):
    return next(
        i
        for i, c in enumerate(cells)
        if c.get("metadata", {}).get("nbgrader", {}).get("grade_id") == gid
    )


def _zero(released, gid, points, what):
    """The released grade cell, marked so that it keeps 0 points with a note."""
    kind, source = released
    new = (nbformat.v4.new_code_cell if kind == "code" else nbformat.v4.new_markdown_cell)(source)
    new.metadata = nbgrader_metadata(gid, grade=True, locked=True, points=points)
    new.id = gid
    new.metadata[ZERO] = f"{gid}: 0 points: the grade cell {what} in the submission."
    return new
