"""What Gradescope's ``run_autograder`` runs: one submission graded by real ``nbgrader
autograde`` with the course's configuration, written as Gradescope's ``results.json``.

    python grader/gradescope_run.py prepare      # setup.sh, once per image
    python grader/gradescope_run.py grade        # run_autograder, once per submission

``prepare`` makes an nbgrader course directory ``<root>/course``
(:func:`grader.course.write_course`, then ``nbgrader generate_assignment``) from the problem
set shipped in ``<root>/source``.
``grade`` copies ``<root>/submission/*.ipynb`` into ``course/submitted/<student_id>/psNN/``,
runs ``nbgrader autograde psNN --student=<student_id>`` (the confined kernel,
:class:`grader.preprocessor.VerifyRecords`: the same code path, so the same points as
``make course``), and writes ``<root>/results/results.json`` from the gradebook: one test per
exercise with the checker's hint or the grader's note. Whatever happens (a notebook that is not
JSON, a kernel that never ends, a crash of nbgrader), a valid ``results.json`` is written with
a message saying what happened; the run never ends without one.

The root is ``/autograder``; the environment variable ``ROTATIONS_AUTOGRADER_ROOT`` moves it,
for the tests only. ``ROTATIONS_CELL_TIMEOUT`` and ``ROTATIONS_TIME_BUDGET`` (seconds) shorten
the per-cell and whole-run limits, for the tests too.

**Without bubblewrap** (a Gradescope image whose Docker forbids user namespaces) the
submission is not run: ``results.json`` says so, with 0 points and ``"status": "failed"``,
unless the zip was built with ``--unconfined`` (file ``source/UNCONFINED``): then students'
code runs as root in the grading container, which holds the solutions (docs/grading.md).

The student: ``users[0]`` of ``<root>/submission_metadata.json``, its ``sid``, else its
``email``, else its ``id`` (:func:`student_id`); it is the nbgrader student id of the graded
submission, so every preprocessor sees it as ``resources["nbgrader"]["student"]``.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

ROOT_ENV = "ROTATIONS_AUTOGRADER_ROOT"
DEFAULT_ROOT = "/autograder"
#: The whole run: below Gradescope's default limit of 10 minutes, room for results.json.
TIME_BUDGET = 480
CELL_TIMEOUT = 60
MAX_OUTPUT = 2_000  # characters of one test's output in results.json
VISIBILITY = "visible"
UNCONFINED_FLAG = "UNCONFINED"
SOURCE = Path(__file__).resolve().parents[1]
HINT = "The check said: "  # grader.preprocessor.HINT (not imported: nbgrader is slow to load)

__all__ = ["student_id", "results_for", "failure", "grade", "prepare", "main"]


def root():
    """The autograder root: ``/autograder``, or ``$ROTATIONS_AUTOGRADER_ROOT`` (tests)."""
    return Path(os.environ.get(ROOT_ENV) or DEFAULT_ROOT)


def student_id(metadata):
    """The student of a submission from Gradescope's ``submission_metadata.json`` (a dict):
    ``users[0]``'s ``sid``, else ``email``, else ``id``, as an nbgrader student id.

    Examples
    --------
    >>> student_id({"users": [{"sid": "3031 42", "email": "a@b.edu", "id": 7}]})
    '3031_42'
    >>> student_id({"users": [{"email": "a@b.edu", "id": 7}]})
    'a@b.edu'
    >>> student_id({})
    'unknown-student'
    """
    users = metadata.get("users") if isinstance(metadata, dict) else None
    user = users[0] if isinstance(users, list) and users and isinstance(users[0], dict) else {}
    for key in ("sid", "email", "id"):
        value = user.get(key)
        if value not in (None, ""):
            text = re.sub(r"[^A-Za-z0-9_.@+-]", "_", str(value))[:80].strip("._")
            if text:
                return text
    return "unknown-student"


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
    sys.path.insert(0, str(SOURCE))
    from grader.course import write_course

    top = Path(top or root())
    course = top / "course"
    if course.exists():
        shutil.rmtree(course)
    ps, _ = assignment()
    write_course(course, root=SOURCE)
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
            }
        )
    total = sum(t["score"] for t in tests)
    most = sum(t["max_score"] for t in tests)
    return {
        "score": total,
        "execution_time": round(time.monotonic() - started, 1),
        "output": f"{ps}: {total:g} of {most:g} points, graded by the course's grader.",
        "visibility": VISIBILITY,
        "stdout_visibility": "hidden",
        "tests": tests,
    }


def _submission(top, expected):
    files = sorted((top / "submission").glob("*.ipynb"))
    if not files:
        return None, f"no notebook (.ipynb) in the submission: upload {expected}."
    named = [f for f in files if f.name == expected]
    return (named or files)[0], None


def _readable(path):
    import nbformat

    try:
        nb = nbformat.read(path, as_version=4)
    except Exception as err:  # noqa: BLE001 - any unreadable file: say so, 0 points
        return f"{path.name} is not a readable notebook ({type(err).__name__}): 0 points."
    if not isinstance(nb.get("cells"), list):
        return f"{path.name} has no cells: 0 points."
    return None


def _autograde(course, ps, student, budget):
    """``nbgrader autograde`` in a process group of its own, stopped at ``budget`` seconds."""
    cmd = [_nbgrader(), "autograde", ps, f"--student={student}", "--create", "--force"]
    cmd.append(f"--Execute.timeout={int(os.environ.get('ROTATIONS_CELL_TIMEOUT', CELL_TIMEOUT))}")
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


def grade(top=None):
    """run_autograder's step: grade the submission, write results.json; returns it."""
    started = time.monotonic()
    top = Path(top or root())
    budget = float(os.environ.get("ROTATIONS_TIME_BUDGET", TIME_BUDGET))
    try:
        results = _grade(top, started, budget)
    except Exception as err:  # noqa: BLE001 - never end without a results.json
        results = failure(f"the autograder failed ({type(err).__name__}: {err})", started)
    _write(results, top)
    return results


def _grade(top, started, budget):
    from grader.sandbox import confinement, confinement_problem

    ps, expected = assignment()
    course = top / "course"
    metadata = {}
    meta_path = top / "submission_metadata.json"
    if meta_path.is_file():
        try:
            metadata = json.loads(meta_path.read_text())
        except ValueError:
            metadata = {}
    student = student_id(metadata)
    path, problem = _submission(top, expected)
    problem = problem or _readable(path)
    if problem:
        return failure(problem, started)
    confined = confinement_problem()
    if confined and not (SOURCE / UNCONFINED_FLAG).is_file():
        return failure(
            "the autograder cannot run your notebook here: its confined kernel needs "
            f"bubblewrap or a root grader ({confined}). Nothing was graded; tell your instructor.",
            started,
        )
    kind = confinement() if not (SOURCE / UNCONFINED_FLAG).is_file() else "unconfined"
    (top / "results").mkdir(parents=True, exist_ok=True)
    os.chmod(top / "results", 0o700)  # closed to the privdrop kernel's uid (docs/grading.md)
    dest = course / "submitted" / student / ps
    if dest.exists():
        shutil.rmtree(dest)
    dest.mkdir(parents=True)
    shutil.copyfile(path, dest / expected)
    code, log = _autograde(course, ps, student, budget - (time.monotonic() - started))
    if code is None:
        return failure(f"0 points: {log}; the cells of your notebook ran too long.", started)
    if code != 0:
        return failure(
            "the autograder could not grade this notebook; tell your instructor.", started
        )
    results = results_for(course, ps, student, started)
    results["output"] += f" Confinement of the student's code: {kind}."
    results["extra_data"] = {"confinement": kind}
    return results


def main(argv=None):
    args = sys.argv[1:] if argv is None else argv
    if args == ["prepare"]:
        print(f"prepared {prepare()}")
        return 0
    if args == ["grade"]:
        results = grade()
        print(f"score {results['score']:g}: {results.get('output', '')}")
        return 0
    print("usage: gradescope_run.py prepare|grade", file=sys.stderr)
    return 2


if __name__ == "__main__":
    if str(SOURCE) not in sys.path:
        sys.path.insert(0, str(SOURCE))
    sys.exit(main())
