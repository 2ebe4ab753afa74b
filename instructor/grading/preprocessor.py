"""The nbgrader preprocessors of the course (named in its ``nbgrader_config.py``).

- :class:`ConfinedExecute` runs a submission in the confined kernel of
  :mod:`instructor.grading.sandbox`
  (nbgrader's own ``Execute``, with that kernel manager whatever the notebook names).
- :class:`VerifyRecords` runs after it, in nbgrader's process, which no student code has
  touched: every exercise check cell keeps its points only when the grader's verdict on the
  answer it recorded (:mod:`instructor.grading.verify`) is "correct"; otherwise its outputs become
  one error whose one line says why. A missing, duplicated, forged or unreadable record gives 0.
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
- :class:`ConfinedExporter` (``c.Autograde.exporter_class``) refuses the whole autograde run,
  before any submission is touched, when the kernel cannot be confined here (no bubblewrap)
  and the instructor has not opted in to unconfined grading.
"""

from __future__ import annotations

import json
import math
import shutil
import time

import nbformat
import zmq
from jupyter_core.utils import run_sync
from nbclient.exceptions import CellTimeoutError, DeadKernelError
from nbconvert.exporters import NotebookExporter
from nbgrader import utils
from nbgrader.api import Gradebook, MissingEntry
from nbgrader.converters.base import NbGraderException
from nbgrader.nbgraderformat.v3 import MetadataValidatorV3
from nbgrader.preprocessors import Execute, NbGraderPreprocessor
from traitlets import Enum, Integer

from course_lib.record import MIME
from instructor.build.student import nbgrader_metadata

from . import (
    answer_log,  # issue 34
    intake,
)
from .diagnose import CHECKED, entry  # issue 34
from .id_preprocessors import SHOWN, CourseIdentity, ShownNumbers, shown_phrase
from .identity import RosterError, write_report
from .sandbox import (
    INSTALL,
    ConfinedKernelManager,
    confinement,
    confinement_problem,
    hidden_problem,
)
from .verify import student_parameters, verdict

__all__ = [
    "CourseIdentity",
    "ShownNumbers",
    "ConfinedExecute",
    "ConfinedExporter",
    "VerifyRecords",
    "GuardCells",
    "CapOutput",
    "note_output",
    "refusal",
]

SUFFIX = "-check"
ZERO = "rotations_course_zero"  # cell metadata: the note of a grade cell put back with 0


def note_output(note):
    """An error output holding one line: nbgrader gives its cell 0 points."""
    return nbformat.v4.new_output(
        "error", ename="GradingNote", evalue=note, traceback=[f"GradingNote: {note}"]
    )


def refusal(problem):
    """What ``nbgrader autograde`` says when it will not run students' code unconfined."""
    return (
        f"refusing to run students' code: the confined grading kernel needs bubblewrap, or a "
        f"grader run as root for the privilege drop, and here {problem}. Unconfined, a "
        f"submission runs as you: it can read the solutions "
        f"(instructor/answers), other submissions and the gradebook, and change them. Install "
        f"bubblewrap ({INSTALL}; Linux only) and run the command again. Or, only for work you "
        f"trust, grade without confinement: add --ConfinedKernelManager.unconfined=True to "
        f"the command, or set c.ConfinedKernelManager.unconfined = True in nbgrader_config.py "
        f"(docs/grading.md, 'Grading without bubblewrap'). Nothing was graded: submitted/, "
        f"autograded/ and gradebook.db are as they were."
    )


class ConfinedExporter(NotebookExporter):
    """Autograde's exporter: it is made once, before the first submission is read, so a
    refusal here stops the run with nothing half-graded (a refusal per notebook would have
    let nbgrader remove each student's earlier autograded copy, under ``--force``)."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        try:  # a roster that cannot be trusted stops the run before anything is graded
            CourseIdentity(config=self.config).roster()
        except (OSError, RosterError) as err:
            self.log.error("%s: nothing was graded", err)
            raise NbGraderException(f"{err}: nothing was graded") from None
        problem = confinement_problem()
        if ConfinedKernelManager.unconfined_in(self.config):
            self.log.warning(
                "grading UNCONFINED (ConfinedKernelManager.unconfined = True): students' code "
                "runs as you, with your files (%s)",
                problem or "bubblewrap is here, but not used",
            )
        elif problem:
            self.log.error(refusal(problem))
            raise NbGraderException(refusal(problem))
        elif confinement() == "privdrop":
            km = ConfinedKernelManager(config=self.config)
            shutil.rmtree(km.scratch, ignore_errors=True)
            hidden, _ = hidden_problem(km.hide)
            if hidden:
                why = f"refusing to run students' code: {hidden}. {NOTHING}"
                self.log.error(why)
                raise NbGraderException(why)
        if not problem and not ConfinedKernelManager.unconfined_in(self.config):
            self.log.info("students' kernels run confined by %s", confinement())
        coursedir = getattr(self.parent, "coursedir", None)
        if coursedir is not None:  # autograde copies no other file of submitted/ (intake.py)
            coursedir.ignore = [*coursedir.ignore, "*", ".*"]

    def from_filename(self, filename, resources=None, **kw):
        """The notebook through the course's intake
        (:func:`instructor.grading.intake.nbgrader_read`): a
        refused file is graded as an empty notebook that carries the note (every grade cell 0)."""
        nb, resources = intake.nbgrader_read(
            filename, getattr(self.parent, "coursedir", None), resources, self.log
        )
        return self.from_notebook_node(nb, resources=resources, **kw)


NOTHING = "Nothing was graded: submitted/, autograded/ and gradebook.db are as they were."


class ConfinedExecute(Execute):
    """nbgrader's Execute with the confined kernel (:mod:`instructor.grading.sandbox`).

    Output is capped **while it arrives** (:meth:`process_message`): at most
    :attr:`max_output_bytes` of a cell's output messages reach the notebook held in the
    grader's memory, then one note line; the first errors are always kept, shortened, so a cut
    never turns a failed grade cell into a passed one. (Capping after execution, as
    :class:`CapOutput` does, let 20 s of flushed 1 MB writes hold 1.5 GB in the grader.)

    A kernel that dies, or that does not stop at the interrupt after a cell's timeout (SIGINT
    ignored), ends the run: the cells that ran keep their outputs, the cell that hung gets an
    error note, every grade cell that did not run gets 0 with a note; the student is graded.
    After the last cell the kernel is killed at once (:attr:`shutdown_kernel`): every output
    has arrived by then, and its graceful teardown only cost time.
    """

    max_output_bytes = Integer(
        100_000, help="Output bytes (JSON text of the messages) kept per cell while it runs."
    ).tag(config=True)
    notebook_budget = Integer(
        300, help="Seconds for a notebook's whole run: a cell not started by then is not run."
    ).tag(config=True)
    shutdown_kernel = Enum(
        ["graceful", "immediate"],
        default_value="immediate",
        help="How the kernel stops after the last cell: 'immediate' (SIGKILL to its process "
        "group; bwrap's PID namespace or privdrop's kill_all ends the rest) once every output "
        "has arrived, or 'graceful' (nbclient's default: a shutdown request, then the kernel's "
        "own teardown, about 0.35 s of CPU and 0.6 s of waiting per submission, for nothing "
        "the grade uses).",
    ).tag(config=True)

    def __init__(self, *args, **kwargs):
        kwargs["kernel_manager_class"] = ConfinedKernelManager
        super().__init__(*args, **kwargs)
        self._start_cell(None)

    def create_kernel_manager(self):
        km = super().create_kernel_manager()
        # Messages wait in ZMQ's receive queue until the loop reads them: at its default of 1000
        # messages, a flood of 1 MB writes held up to 1 GB in the grader (483 MB for a 6 s flood
        # on a loaded machine). Past IOPUB_QUEUE waiting messages the socket drops them.
        km.context.setsockopt(zmq.RCVHWM, IOPUB_QUEUE)
        # the student of the submission, from nbgrader (never from the notebook), as the course's
        # key (the roster): the kernel's checks judge that student's variants, as VerifyRecords
        given = (self.resources or {}).get("nbgrader", {}).get("student") or ""
        km.student = CourseIdentity(config=self.config).roster().resolve(given).key
        return km

    def _start_cell(self, index):
        self._running, self._budget, self._cut = index, self.max_output_bytes - NOTE_ROOM, 0
        self._errors = self._stderr = 0

    def preprocess(self, nb, resources=None, km=None):
        self._start_cell(None)
        if nb.metadata.get(intake.NOTE):  # refused at intake: GuardCells gave every grade cell 0
            return nb, resources
        self._deadline, self._over = None, False  # the budget starts at the first cell
        student = (resources or {}).get("nbgrader", {}).get("student") or "?"
        if ConfinedKernelManager.unconfined_in(self.config):
            self.log.info("%s: the submission's kernel runs UNCONFINED (opted in)", student)
        else:
            self.log.info("%s: the submission's kernel runs confined by %s", student, confinement())
        try:
            nb, resources = super().preprocess(nb, resources, km=km)
            if not self._over:
                return nb, resources
            why = OVER_BUDGET.format(self.notebook_budget)
        except DeadKernelError:
            self.log.warning("the kernel died: grade cells that did not run get 0")
            why = "the kernel died (os._exit, a crash or the memory limit) before this cell ran."
        except CellTimeoutError:
            self.log.warning("a cell timed out and the kernel did not stop: it was killed")
            why = HUNG
            if self._running is not None:
                cell = nb.cells[self._running]
                gid = _grade_id(cell) or f"cell {self._running}"
                note = f"{gid}: {HUNG_HERE}"
                cell.outputs = [*cell.get("outputs", []), note_output(note)]
                if utils.is_grade(cell):
                    cell.metadata[ZERO] = f"{gid}: 0 points: {HUNG_HERE}"
        for cell in nb.cells:
            if cell.cell_type == "code" and utils.is_grade(cell) and cell.execution_count is None:
                note = f"{_grade_id(cell)}: 0 points: {why}"
                cell.outputs = [note_output(note)]
                cell.metadata[ZERO] = note  # VerifyRecords keeps this note
        return nb, resources

    async def async_execute_cell(self, cell, cell_index, execution_count=None, store_history=True):
        now = time.monotonic()
        if getattr(self, "_deadline", None) is None:
            self._deadline = now + self.notebook_budget
        elif now > self._deadline:
            self._over = True  # past the notebook's budget: not run (preprocess gives it 0)
            return cell
        self._start_cell(cell_index)
        try:
            return await super().async_execute_cell(
                cell, cell_index, execution_count=execution_count, store_history=store_history
            )
        finally:
            if self._cut:
                note = (
                    f"\n[GradingNote: {self._cut} bytes of output cut while the cell ran, "
                    f"over {self.max_output_bytes} per cell]\n"
                )
                cell.outputs.append(nbformat.v4.new_output("stream", name="stdout", text=note))

    execute_cell = run_sync(async_execute_cell)

    async def async_start_new_kernel_client(self):
        kc = await super().async_start_new_kernel_client()  # the kernel answered: sockets bound
        self.km.seal_scratch()
        return kc

    start_new_kernel_client = run_sync(async_start_new_kernel_client)

    def process_message(self, msg, cell, cell_index):
        kind = msg.get("msg_type", "")
        if kind in OUTPUT_MESSAGES or kind.startswith("comm"):
            content = msg.get("content", {})
            size = max(100, len(json.dumps(content, default=str)))
            size += sum(len(b) for b in msg.get("buffers") or ())
            if kind == "error":
                self._errors += 1
                if self._errors > 3 and size > self._budget:
                    self._cut += size
                    return None
                msg = {**msg, "content": _short_error(content)}
                size = min(size, 12_000)
            elif size > self._budget:
                self._cut += size
                stderr = kind == "stream" and content.get("name") == "stderr"
                if kind == "stream" and (self._budget > 0 or (stderr and not self._stderr)):
                    keep = max(self._budget, 200)
                    text = str(content.get("text", ""))[:keep]
                    msg = {**msg, "content": {**content, "text": text}}
                    self._cut -= len(text)
                    self._stderr += stderr
                    self._budget = 0
                    return super().process_message(msg, cell, cell_index)
                self._budget = 0
                return None
            self._budget = max(0, self._budget - size)
        return super().process_message(msg, cell, cell_index)


#: At most this many messages wait unread in the grader's receive queues (ZMQ's RCVHWM).
IOPUB_QUEUE = 32
#: Messages that become outputs (or update them) in the grader's copy of the notebook.
OUTPUT_MESSAGES = {"stream", "display_data", "execute_result", "update_display_data", "error"}
NOTE_ROOM = 200  # so CapOutput, after, never cuts again what ConfinedExecute kept
HUNG = (
    "an earlier cell ran past the time limit and ignored the interrupt (SIGINT), so the "
    "kernel was stopped before this cell ran."
)
OVER_BUDGET = (
    "the notebook's cells ran past its time budget of {} s in all, so this cell was not run "
    "(the cells before it kept their points)."
)
HUNG_HERE = (
    "this cell ran past the time limit and ignored the interrupt (SIGINT): the kernel was "
    "stopped, and the cells after it did not run."
)


def _grade_id(cell):
    meta = cell.get("metadata", {}).get("nbgrader", {})
    return meta.get("grade_id", "") if isinstance(meta, dict) else ""


HINT = "The check said: "


def _hint(cell):
    """The hint of the kernel-side check (its ``CheckFailed`` line), shortened, or ''."""
    for out in cell.get("outputs", []):
        if out.get("output_type") == "error" and out.get("ename") == "CheckFailed":
            return str(out.get("evalue", ""))[:500]
    return ""


def _records(cell):
    return [o for o in cell.get("outputs", []) if MIME in o.get("data", {})]


class VerifyRecords(NbGraderPreprocessor):
    """Each exercise check cell keeps its points only on the grader's "correct".

    The student is nbgrader's student id resolved to the course's key by the roster
    (:class:`~instructor.grading.id_preprocessors.CourseIdentity`). Where the submitted notebook
    showed other numbers than the key's
    (:class:`~instructor.grading.id_preprocessors.ShownNumbers`), the
    feedback says so at the top and in each exercise concerned, and the student is listed in the
    instructor's identity report (a regrade, not a silent 0); an id the roster does not know is
    graded as given, with a note, and listed too."""

    def preprocess(self, nb, resources):
        ident = CourseIdentity(config=self.config)
        info = resources.get("nbgrader", {})
        self._who = ident.roster().resolve(info.get("student") or "")
        shown = nb.metadata.get(SHOWN)
        self._shown = shown if isinstance(shown, dict) else {}
        self._other, self._lost = [], []
        self._answers = []  # issue 34: the class report's note of each answer
        nb, resources = super().preprocess(nb, resources)
        answer_log.save(resources, self._answers, self.log)
        lines = [self._who.note] if self._who.note else []
        if self._other:
            lines.append(self.mismatch_note())
        if lines:
            nb.cells.insert(0, nbformat.v4.new_markdown_cell("**GradingNote**: " + " ".join(lines)))
        if "assignment" in info and "student" in info:
            row = None
            if lines:
                row = {
                    "assignment": info["assignment"],
                    "student": info["student"],
                    "graded_as": self._who.key,
                    "how": self._who.how,
                    "shown_as": "; ".join(
                        sorted({str(self._shown[n].get("student")) for n in self._other})
                    ),
                    "other_numbers": " ".join(self._other),
                    "lost": " ".join(self._lost),
                }
            write_report(ident.report_path(resources), info["assignment"], info["student"], row)
        return nb, resources

    def mismatch_note(self):
        """The feedback's line on the exercises whose numbers were not the graded ones."""
        first = self._shown[self._other[0]]
        lost = f" Points lost on them: {', '.join(self._lost)}." if self._lost else ""
        return (
            f"your answers were graded on the numbers of {self._who.key!r}, your course id, but "
            f"your notebook showed the {shown_phrase(first)} in {', '.join(self._other)}.{lost} "
            "Set your student id (your course e-mail) in the first cell of the problem set, "
            "check those answers on your own numbers and hand in again, or ask your "
            "instructor for a regrade: you are on their list."
        )

    # --- issue 34: what the class report keeps of each answer (instructor/grading/answer_log.py)
    # ---
    def _note(self, name, cell, resources, data=None, result=None):
        who = getattr(self, "_who", None)  # the key whose numbers were graded
        student = who.key if who is not None else resources.get("nbgrader", {}).get("student")
        checked = cell.metadata.get(CHECKED)
        if not hasattr(self, "_answers"):  # preprocess_cell called on its own
            self._answers = []
        try:  # a note for the report: it never changes or stops the grading
            self._answers.append(entry(name, data, student, result, checked))
        except Exception as err:  # noqa: BLE001
            self.log.warning("%s: no note for the class report (%r)", name, err)

    # --- end issue 34 ---

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
            self._note(name, cell, resources)  # issue 34
            return cell, resources
        failed = any(o.output_type == "error" for o in cell.outputs)
        records = _records(cell)
        if len(records) != 1:
            note = "no answer record" if not records else f"{len(records)} answer records"
            cell.outputs = [note_output(f"{name}: 0 points: {note} in the check cell's output.")]
            self._note(name, cell, resources)  # issue 34
            return cell, resources
        key = self._who.key  # nbgrader's student through the roster, never the notebook's
        shown = self._shown.get(name)
        result = verdict(name, json.loads(json.dumps(records[0]["data"][MIME])), key, shown)
        if isinstance(shown, dict) and shown.get("variant") != student_parameters(name, key)[0]:
            self._other.append(name)
            if not result.ok:
                self._lost.append(name)
        if not result.ok:
            note = note_output(f"{name}: 0 points from the grader: {result.message}.")
            hint = _hint(cell)
            if hint:  # the student's own check's hint, shown after the note (feedback, Gradescope)
                note.traceback.append(f"{HINT}{hint}")
            cell.outputs = [note]
        elif not failed:  # nothing in the outputs may read as a score: no execute_result
            cell.outputs = [
                o
                for o in cell.outputs
                if o.output_type != "execute_result"
                and not (o.output_type == "stream" and o.name == "stderr")
            ]
        self.log.info("%s: grader's verdict %s", name, result.status)
        self._note(name, cell, resources, records[0]["data"][MIME], result)  # issue 34
        return cell, resources


class GuardCells(NbGraderPreprocessor):
    """Put back deleted, duplicated or retyped grade cells, each with 0 points and a note."""

    def preprocess(self, nb, resources):
        notebook_id = resources["unique_key"]
        assignment_id = resources["nbgrader"]["assignment"]
        refused = nb.metadata.get(intake.NOTE)  # the intake's note: every grade cell 0 with it
        with Gradebook(resources["nbgrader"]["db_url"]) as gb:
            try:
                source = gb.find_notebook(notebook_id, assignment_id)
            except MissingEntry:
                return nb, resources
            released = {c.name: (c.cell_type, c.source) for c in source.source_cells}
            locked = {c.name for c in source.source_cells if c.locked}
            grades = {g.name: g.max_score for g in source.grade_cells}
            solutions = {c.name for c in source.solution_cells}
        seen, cells = set(), []
        for cell in nb.cells:
            gid, note = _repair(cell, released, locked, grades, solutions)
            if note:  # malformed metadata: that of the released cell, or none
                self.log.warning("%s: %s", notebook_id, note)
                if gid in grades:
                    if gid in seen:
                        cells[_index(cells, gid)] = _zero(
                            released[gid], gid, grades[gid], "was duplicated"
                        )
                    else:
                        seen.add(gid)
                        cells.append(_zero(released[gid], gid, grades[gid], MALFORMED))
                    continue
                cells += [cell, nbformat.v4.new_markdown_cell(f"**GradingNote**: {note}")]
                continue
            note = _unreleased(cell, grades, solutions, released)
            if note:
                self.log.warning("%s: %s", notebook_id, note)
                cells += [cell, nbformat.v4.new_markdown_cell(f"**GradingNote**: {note}")]
                continue
            gid = cell.get("metadata", {}).get("nbgrader", {}).get("grade_id")
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
                cells.append(_zero(released[gid], gid, grades[gid], "was deleted", refused))
        nb.cells = cells
        return nb, resources


MALFORMED = "had malformed grading metadata"


def _malformed(meta):
    """Whether a cell's ``metadata.nbgrader`` is not what nbgrader's schema 3 allows (a dict
    of booleans, a grade id string, finite points for a grade cell ...): nbgrader's own
    validator decides, plus finite points."""
    if not isinstance(meta, dict):
        return True
    cell = nbformat.from_dict({"cell_type": "code", "source": "", "metadata": {"nbgrader": {}}})
    cell.metadata.nbgrader = nbformat.from_dict(json.loads(json.dumps(meta)))
    try:
        MetadataValidatorV3().validate_cell(cell)
    except Exception:  # nbgrader's and jsonschema's ValidationError, KeyError, TypeError
        return True
    points = meta.get("points", 0)
    return not math.isfinite(points)


def _repair(cell, released, locked, grades, solutions):
    """Malformed nbgrader metadata (null, a string, ``"grade": "yes"``, ``"points": "1e9"``
    ...) made nbgrader (or this preprocessor) fail and the student was dropped. Such a cell is
    taken for the released cell of its grade id (or, failing that, of its cell id): a grade
    cell is put back as released with 0 points (the caller), an answer or locked cell gets
    its released metadata back; a cell of no released id loses the metadata. Returns
    ``(grade id or None, note)``; ``(None, None)`` when the metadata is well formed."""
    if not isinstance(cell.get("metadata"), dict):
        cell["metadata"] = nbformat.NotebookNode()
    if "nbgrader" not in cell.metadata or not _malformed(cell.metadata["nbgrader"]):
        return None, None
    meta = cell.metadata.pop("nbgrader")
    gid = meta.get("grade_id") if isinstance(meta, dict) else None
    if not isinstance(gid, str) or gid not in released:
        gid = cell.get("id") if isinstance(cell.get("id"), str) else None
    if gid not in released:
        return None, (
            "a cell had malformed grading metadata in the submission: graded as a plain cell "
            "(0 points)."
        )
    if gid not in grades:
        cell.metadata.update(
            nbgrader_metadata(gid, solution=gid in solutions, locked=gid in locked)
        )
    return gid, (
        f"the cell `{gid}` had malformed grading metadata in the submission: "
        + (
            "put back as released, 0 points."
            if gid in grades
            else "its released metadata put back."
        )
    )


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
    tb = out.get("traceback", [])
    tb = tb[-5:] if isinstance(tb, list) else [tb]
    return nbformat.v4.new_output(
        "error",
        ename=str(out.get("ename", ""))[:200],
        evalue=str(out.get("evalue", ""))[:limit],
        traceback=[str(line)[:limit] for line in tb],
    )


def _index(cells, gid):
    return next(
        i
        for i, c in enumerate(cells)
        if c.get("metadata", {}).get("nbgrader", {}).get("grade_id") == gid
    )


def _zero(released, gid, points, what, note=None):
    """The released grade cell, marked so that it keeps 0 points with a note."""
    kind, source = released
    new = (nbformat.v4.new_code_cell if kind == "code" else nbformat.v4.new_markdown_cell)(source)
    new.metadata = nbgrader_metadata(gid, grade=True, locked=True, points=points)
    new.id = gid
    new.metadata[ZERO] = (
        f"{gid}: {note}" if note else (f"{gid}: 0 points: the grade cell {what} in the submission.")
    )
    return new
