"""What Gradescope's ``run_autograder`` runs: one submission graded by real ``nbgrader
autograde`` with the course's configuration, written as Gradescope's ``results.json``.

    cd /autograder/source
    python -m instructor.grading.gradescope_run prepare    # setup.sh, once per image
    python -m instructor.grading.gradescope_run grade      # run_autograder, once per submission
    python -m instructor.grading.gradescope_run selftest   # setup.sh's last step

``prepare`` makes an nbgrader course directory ``<root>/course``
(:func:`instructor.grading.course.write_course`, then ``nbgrader generate_assignment``) from the
problem set shipped in ``<root>/source``.
``grade`` takes the notebook of ``<root>/submission`` through the course's intake
(:mod:`instructor.grading.intake`: the file named as the problem set's, else the only ``*.ipynb``; a
regular file of one name inside the folder, at most 20 MB, checked before it is read, JSON
with cells), writes the grader's own copy into ``course/submitted/<student_id>/psNN/``, runs
``nbgrader autograde psNN --student=<student_id>`` (the confined kernel,
:class:`instructor.grading.preprocessor.VerifyRecords`: the same code path, so the same points as
``make course``), and writes ``<root>/results/results.json`` from the gradebook: one test per
exercise with the checker's hint or the grader's note (shown as text, never HTML).

**Whose fault.** A fault of the student's submission (no notebook, two, a link, a pipe, an
empty, oversized or non-JSON file, cells that ran past the time limits) writes a valid
``results.json`` with 0 and a note saying what was wrong and what is expected. A fault of the
grader's own (the confined kernel cannot start, nbgrader fails, a bug here) writes **no**
``results.json`` and exits 1: Gradescope then shows "The autograder failed to execute
correctly" to the instructor, who can rerun it; a broken image never records a 0.
``selftest`` (setup.sh's last step) grades the solved and a blank copy so and fails the image
build unless they get full marks and 0.

The root is ``/autograder``; the environment variable ``ROTATIONS_AUTOGRADER_ROOT`` moves it,
for the tests only. ``ROTATIONS_CELL_TIMEOUT`` and ``ROTATIONS_TIME_BUDGET`` (seconds) shorten
the per-cell and whole-run limits, for the tests too.

**Without a confined kernel** (bubblewrap, or the privilege drop of a root grader:
:func:`confinement`, the one place that decides it) the
submission is not run and run_autograder exits 1, unless the zip was built with
``--unconfined`` (file ``source/UNCONFINED``): then students' code runs as root in the
grading container, which holds the solutions (docs/grading.md).

The student: ``users[0]`` of ``<root>/submission_metadata.json``: its ``email``, ``sid`` or
``id``, whichever the course's roster (``source/roster.csv``, in the zip when built with
``ROSTER=``) knows, resolved to the course's key (:func:`identity`,
:mod:`instructor.grading.identity`);
without a roster, the e-mail, normalised. The nbgrader student id of the graded copy is that
key made a folder name, and ``course/submission-id.csv`` maps it back to the key, so every
preprocessor grades the key's numbers. ``results.json`` says whose numbers were graded when
the notebook showed others or the roster does not know the student, and carries it in
``extra_data["identity"]`` for the instructor.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from dataclasses import replace
from pathlib import Path

ROOT_ENV = "ROTATIONS_AUTOGRADER_ROOT"
DEFAULT_ROOT = "/autograder"
#: The whole run: below Gradescope's default limit of 10 minutes, room for results.json.
TIME_BUDGET = 480
CELL_TIMEOUT = 60
MAX_OUTPUT = 2_000  # characters of one test's output in results.json
VISIBILITY = "visible"
UNCONFINED_FLAG = "UNCONFINED"
SOURCE = Path(__file__).resolve().parents[2]
# instructor.grading.preprocessor.HINT (not imported: nbgrader is slow to load)
HINT = "The check said: "
ROSTER = "roster.csv"  # the instructor's roster in the zip (source/), when there is one
SUBMISSION_ID = "submission-id.csv"  # this run's folder name -> the course's key
NOTE = "**GradingNote**: "  # the first cell of an autograded notebook with an identity note

__all__ = [
    "identity",
    "student_id",
    "results_for",
    "failure",
    "grade",
    "prepare",
    "selftest",
    "main",
]


def root():
    """The autograder root: ``/autograder``, or ``$ROTATIONS_AUTOGRADER_ROOT`` (tests)."""
    return Path(os.environ.get(ROOT_ENV) or DEFAULT_ROOT)


def _safe(value):
    """A folder name of nbgrader's for an id: letters, digits and ``_.@+-``, at most 80; an id
    that had to be changed gets 8 hex digits of its hash (two such ids stay two folders)."""
    value = str(value)
    text = re.sub(r"[^A-Za-z0-9_.@+-]", "_", value)[:80].strip("._")
    if text != value:
        text = f"{text}-{hashlib.sha256(value.encode()).hexdigest()[:8]}".lstrip("-")
    return text


def _aliases(metadata):
    """The ids Gradescope gives of the submission's student, ``(field, id)``: ``users[0]``'s
    ``email``, then ``sid``, then ``id`` (the non-empty ones)."""
    users = metadata.get("users") if isinstance(metadata, dict) else None
    user = users[0] if isinstance(users, list) and users and isinstance(users[0], dict) else {}
    return [(k, str(user[k])) for k in ("email", "sid", "id") if user.get(k) not in (None, "")]


def identity(metadata, roster):
    """The :class:`instructor.grading.identity.Resolved` key of the submission's student: the first
    of its e-mail, ``sid`` and ``id`` that the roster knows, else the e-mail (or the first id
    there is) as given, normalised, with a note when there is a roster. A student found by
    ``sid`` or ``id`` when the e-mail is not in the roster gets a note saying so.

    Examples
    --------
    >>> from instructor.grading.identity import Roster
    >>> r = Roster({"3031042": "alice@b.edu", "alice@b.edu": "alice@b.edu"}, ["roster.csv"])
    >>> who = identity({"users": [{"sid": "3031042", "email": "Alice@old.edu"}]}, r)
    >>> who.key, who.note[:43]
    ('alice@b.edu', "the id 'alice@old.edu' is not in the course")
    >>> identity({"users": [{"email": " Bob@B.edu"}]}, Roster()).key
    'bob@b.edu'
    """
    resolved = [(field, roster.resolve(name)) for field, name in _aliases(metadata)]
    first = resolved[0][1] if resolved else roster.resolve("unknown-student")
    for field, got in resolved:
        if got.how == "roster" and got is first:
            return got
        if got.how == "roster":  # found by its sid or id, not by its e-mail: said in the note
            return replace(got, given=first.given, via=f"{field} {got.given}")
    return first


def student_id(metadata):
    """The nbgrader student id (a folder name) of a submission from Gradescope's
    ``submission_metadata.json`` (a dict): its e-mail, else ``sid``, else ``id``, made safe.

    Examples
    --------
    >>> student_id({"users": [{"sid": "3031 42", "email": "a@b.edu", "id": 7}]})
    'a@b.edu'
    >>> student_id({"users": [{"sid": "3031 42", "id": 7}]})
    '3031_42-0a048622'
    >>> student_id({})
    'unknown-student'
    """
    names = _aliases(metadata)
    return _safe(names[0][1]) if names else "unknown-student"


def assignment(source=SOURCE):
    """The problem set of this autograder (``psNN``) and its notebook's file name."""
    made = sorted((source / "problem_sets").glob("ps[0-9][0-9]_*.ipynb"))
    if len(made) != 1:
        raise ValueError(f"the autograder must hold one problem set, found {len(made)}")
    return made[0].name[:4], made[0].name


def _nbgrader():
    return str(Path(sys.executable).with_name("nbgrader"))


def _env():
    """The environment of nbgrader: its own bin folder first (it runs ``alembic`` from PATH)."""
    bin_dir = str(Path(sys.executable).parent)
    return {**os.environ, "PATH": f"{bin_dir}{os.pathsep}{os.environ.get('PATH', '')}"}


def prepare(top=None):
    """setup.sh's step: the nbgrader course directory ``<root>/course`` for this set."""
    from instructor.grading.course import write_course

    top = Path(top or root())
    course = top / "course"
    if course.exists():
        shutil.rmtree(course)
    ps, _ = assignment()
    write_course(course, root=SOURCE)
    with open(course / "nbgrader_config.py", "a", encoding="utf-8") as f:  # one student a run
        f.write(f"c.CourseIdentity.rosters = [{str(course / SUBMISSION_ID)!r}]\n")
    done = subprocess.run(
        [_nbgrader(), "generate_assignment", ps, "--create"],
        cwd=course,
        env=_env(),
        capture_output=True,
        text=True,
    )
    if done.returncode != 0:
        raise RuntimeError(f"nbgrader generate_assignment failed:\n{done.stdout}{done.stderr}")
    os.chmod(course, 0o700)
    return course


def failure(message, started, max_score=0.0):
    """A results.json dict that gives 0 and says why (the run itself went wrong)."""
    return {
        "score": 0.0,
        "execution_time": round(time.monotonic() - started, 1),
        "output": message,
        "output_format": "text",
        "test_output_format": "text",
        "visibility": VISIBILITY,
        "stdout_visibility": "hidden",
        "tests": [
            {
                "name": "grading",
                "score": 0.0,
                "max_score": float(max_score),
                "status": "failed",
                "output": message,
                "visibility": VISIBILITY,
            }
        ],
    }


def _write(results, top):
    folder = top / "results"
    folder.mkdir(parents=True, exist_ok=True)
    tmp = folder / ".results.json.tmp"
    tmp.write_text(json.dumps(results, indent=1, ensure_ascii=False))
    os.replace(tmp, folder / "results.json")


def _short(text):
    text = str(text)
    return text if len(text) <= MAX_OUTPUT else text[: MAX_OUTPUT - 20] + " [... cut]"


def _messages(cell):
    """What a graded check cell says: its error lines (the hint, or the grader's note)."""
    lines = []
    for out in cell.get("outputs", []):
        if out.get("output_type") == "error":
            lines.append(f"{out.get('ename', '')}: {out.get('evalue', '')}".strip(": "))
            tb = out.get("traceback") or []
            lines += [str(t) for t in tb[1:] if str(t).startswith(HINT)][:1]
    return lines


def results_for(course, ps, student, started):
    """results.json from the gradebook and the autograded notebook of ``student``."""
    import nbformat
    from nbgrader.api import Gradebook

    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gb:
        sub = gb.find_submission(ps, student)
        grades = [(g.name, g.score, g.max_score) for nb in sub.notebooks for g in nb.grades]
        cells = [c.name for nb in gb.find_assignment(ps).notebooks for c in nb.grade_cells]
        order = {name: i for i, name in enumerate(cells)}
    grades.sort(key=lambda g: order.get(g[0], len(order)))
    autograded = next((course / "autograded" / student / ps).glob("*.ipynb"), None)
    cells = {}
    if autograded is not None:
        nb = nbformat.read(autograded, as_version=4)
        cells = {c.metadata.get("nbgrader", {}).get("grade_id"): c for c in nb.cells}
    from instructor.grading.answer_log import (
        read_student,  # issue 34: the grader's notes per answer
    )

    notes = read_student(course, ps, student)
    tests = []
    for number, (gid, score, max_score) in enumerate(grades, 1):
        name = gid[: -len("-check")] if gid.endswith("-check") else gid
        full = score is not None and score >= max_score
        said = _messages(cells.get(gid, {}))
        output = "✓ correct" if full else ("\n".join(said) or "0 points: no answer.")
        tests.append(
            {
                "name": name,
                "number": str(number),
                "score": float(score or 0.0),
                "max_score": float(max_score),
                "status": "passed" if full else "failed",
                "output": _short(output),
                "visibility": VISIBILITY,
                "extra_data": notes.get(name, {}),  # issue 34: for the class report
            }
        )
    total = sum(t["score"] for t in tests)
    most = sum(t["max_score"] for t in tests)
    output = f"{ps}: {total:g} of {most:g} points, graded by the course's grader."
    note = _identity_note(autograded)
    if note:
        output += f"\n\nYour student id: {note}"
    return {
        "score": total,
        "execution_time": round(time.monotonic() - started, 1),
        "output": _short(output),
        "output_format": "text",
        "test_output_format": "text",
        "visibility": VISIBILITY,
        "stdout_visibility": "hidden",
        "tests": tests,
        # the set's name (the class report, issue 34) and whose numbers were graded (issue 33)
        "extra_data": {"assignment": ps, "identity": _identity_data(course, ps, student)},
    }


def _identity_note(autograded):
    """The identity note VerifyRecords put first in the autograded notebook, or ''."""
    if autograded is None:
        return ""
    import nbformat

    cells = nbformat.read(autograded, as_version=4).cells
    first = cells[0] if cells else None
    if first is not None and first.cell_type == "markdown" and first.source.startswith(NOTE):
        return first.source[len(NOTE) :]
    return ""


def _identity_data(course, ps, student):
    """The row of the course's identity report for this submission, or the plain key."""
    import csv

    from instructor.grading.csv_safe import neutralise

    report = course / "identity-report.csv"
    if report.is_file():
        with open(report, newline="", encoding="utf-8") as f:
            for row in csv.DictReader(f):
                if (row["assignment"], row["student"]) == (neutralise(ps), neutralise(student)):
                    return row
    return {"assignment": ps, "student": student}


class GraderFault(RuntimeError):
    """The run failed for the grader's own reasons: run_autograder exits 1, no results.json
    (Gradescope shows an autograder error the instructor can rerun), never a recorded 0."""


def _intake(top, expected):
    """``(bytes of the notebook to grade, note)``; :class:`instructor.grading.intake.Refused` with
    the student's note when there is none to grade (instructor/grading/intake.py)."""
    from instructor.grading import intake

    folder = top / "submission"
    if not folder.is_dir() or folder.is_symlink():
        raise intake.Refused("no submission folder: nothing was handed in.")
    name, note = intake.pick(folder, expected)
    data = intake.read_inside(folder / name, folder)
    intake.parse(data, name)
    return data, note


def confinement():
    """``(name, problem)`` of the confinement this autograder uses: bubblewrap, else the
    privilege drop (a root grader: Gradescope's Docker container), the first that can start
    (:func:`instructor.grading.sandbox.confinement`); ``problem`` is None when one can start."""
    from instructor.grading import sandbox

    if (SOURCE / UNCONFINED_FLAG).is_file():
        return "unconfined (opted in: UNCONFINED)", None
    return sandbox.confinement() or "none", sandbox.confinement_problem()


def _autograde(course, ps, student, budget):
    """``nbgrader autograde`` in a process group of its own, stopped at ``budget`` seconds."""
    cmd = [_nbgrader(), "autograde", ps, f"--student={student}", "--create", "--force"]
    cmd.append(f"--Execute.timeout={int(os.environ.get('ROTATIONS_CELL_TIMEOUT', CELL_TIMEOUT))}")
    if os.environ.get("ROTATIONS_NOTEBOOK_BUDGET"):
        cmd.append(
            f"--ConfinedExecute.notebook_budget={int(os.environ['ROTATIONS_NOTEBOOK_BUDGET'])}"
        )
    if (SOURCE / UNCONFINED_FLAG).is_file():
        cmd.append("--ConfinedKernelManager.unconfined=True")
    proc = subprocess.Popen(
        cmd,
        cwd=course,
        env=_env(),
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        start_new_session=True,
    )
    try:
        out, _ = proc.communicate(timeout=budget)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return None, f"the grading ran past its time limit ({budget:.0f} s) and was stopped"
    log = out.decode(errors="replace")
    sys.stdout.write(log[-20_000:])  # the instructor's log (stdout is hidden from students)
    return proc.returncode, log


def grade(top=None, course=None):
    """run_autograder's step: grade the submission, write results.json; returns it. A fault of
    the grader's own (:class:`GraderFault`, any exception) removes a stale results.json and
    raises: run_autograder then exits 1."""
    started = time.monotonic()
    top = Path(top or root())
    stale = top / "results" / "results.json"
    if stale.is_file():
        stale.unlink()
    budget = float(os.environ.get("ROTATIONS_TIME_BUDGET", TIME_BUDGET))
    results = _grade(top, started, budget, Path(course or top / "course"))
    _write(results, top)
    return results


def _grade(top, started, budget, course):
    from instructor.grading.identity import load
    from instructor.grading.intake import Refused

    ps, expected = assignment()
    metadata = {}
    meta_path = top / "submission_metadata.json"
    if meta_path.is_file():
        try:
            metadata = json.loads(meta_path.read_text())
        except ValueError:
            metadata = {}
    try:
        data, note = _intake(top, expected)
    except Refused as err:
        return failure(f"0 points: {err}", started)
    name, problem = confinement()
    if problem:
        raise GraderFault(f"the confined kernel cannot start here ({problem})")
    (top / "results").mkdir(parents=True, exist_ok=True)
    os.chmod(top / "results", 0o700)  # closed to the privdrop kernel's uid (docs/grading.md)
    roster_file = SOURCE / ROSTER
    try:
        who = identity(metadata, load([roster_file] if roster_file.is_file() else []))
    except ValueError as err:  # the instructor's roster cannot be trusted: nothing on a guess
        raise GraderFault(f"the course's roster is refused ({err})") from err
    student = _safe(who.key)
    rows = _csv_row(["key", "alias"]) + _csv_row([who.key, student])
    (course / SUBMISSION_ID).write_text(rows, encoding="utf-8")
    submitted = course / "submitted"
    dest = submitted / student / ps
    if submitted.resolve() not in dest.resolve().parents:
        raise GraderFault(f"student id {student!r} would leave submitted/")
    if dest.exists():
        shutil.rmtree(dest)
    dest.mkdir(parents=True)
    (dest / expected).write_bytes(data)  # the grader's own copy: one name, a regular file
    code, log = _autograde(course, ps, student, budget - (time.monotonic() - started))
    if code is None:
        return failure(f"0 points: {log}; the cells of your notebook ran too long.", started)
    if code != 0:
        raise GraderFault(f"nbgrader autograde exited {code}")
    results = results_for(course, ps, student, started)
    if note:
        results["output"] += " " + note
    results["output"] += f" Confinement of the student's code: {name}."
    results["extra_data"]["confinement"] = name
    results["extra_data"]["student"] = student  # the folder name nbgrader graded
    ident = {"given": who.given, "graded_as": who.key, "how": who.how}
    results["extra_data"]["identity"].update(ident, **({"via": who.via} if who.via else {}))
    if who.note:
        results["output"] = _short(f"{results['output']}\n\nYour student id: {who.note}")
    return results


def selftest(top=None):
    """setup.sh's last step: the solved copy must get full marks and a blank copy 0, graded
    as students will be (the same course, confinement and run_autograder code); otherwise
    :class:`GraderFault` (the image build fails)."""
    import tempfile

    top = Path(top or root())
    course = top / "course"
    ps, expected = assignment()
    for kind, folder in (("solved", "source"), ("blank", "release")):
        work = Path(tempfile.mkdtemp(prefix=f"selftest-{kind}-"))
        try:
            (work / "submission").mkdir()
            shutil.copyfile(course / folder / ps / expected, work / "submission" / expected)
            meta = {"users": [{"sid": f"selftest-{kind}"}]}
            (work / "submission_metadata.json").write_text(json.dumps(meta))
            results = grade(work, course)
        finally:
            shutil.rmtree(work, ignore_errors=True)
        most = sum(t.get("max_score", 0.0) for t in results["tests"])
        want = most if kind == "solved" else 0.0
        if not results["tests"] or most <= 0 or results["score"] != want:
            raise GraderFault(
                f"self-test: the {kind} copy got {results['score']:g} of {most:g} points, "
                f"expected {want:g} ({results.get('output', '')[:300]})"
            )
        print(f"self-test: the {kind} copy got {results['score']:g} of {most:g} points")
    return True


def _csv_row(cells):
    import csv
    import io

    buf = io.StringIO()
    csv.writer(buf).writerow(cells)
    return buf.getvalue()


def main(argv=None):
    args = sys.argv[1:] if argv is None else argv
    if args == ["prepare"]:
        print(f"prepared {prepare()}")
        return 0
    try:
        if args == ["grade"]:
            results = grade()
            print(f"score {results['score']:g}: {results.get('output', '')}")
            return 0
        if args == ["selftest"]:
            selftest()
            print("self-test passed: full marks for the solved copy, 0 for a blank one")
            return 0
    except Exception as err:  # noqa: BLE001 - the grader's own fault: exit 1, no results.json
        print(
            f"gradescope_run: the autograder itself failed ({type(err).__name__}: {err}); "
            "no results.json was written (Gradescope shows an autograder error; rerun it)",
            file=sys.stderr,
        )
        return 1
    print(
        "usage: python -m instructor.grading.gradescope_run prepare|grade|selftest", file=sys.stderr
    )
    return 2


if __name__ == "__main__":
    sys.exit(main())
