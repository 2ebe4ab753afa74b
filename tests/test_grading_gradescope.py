"""The Gradescope autograder (instructor/grading/gradescope.py,
instructor/grading/gradescope_run.py), run as Gradescope
runs it: the zip extracted into ``<root>/source``, its ``prepare`` step (setup.sh's last line),
then ``run_autograder`` once per submission, with ``<root>`` a temporary folder standing in
for ``/autograder`` (``ROTATIONS_AUTOGRADER_ROOT``, for the tests only).

Each run goes through real nbgrader and the confined kernel, a few seconds each: the module is
marked ``gradescope`` (not in ``make test``); ``make test-gradescope`` runs it.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from pathlib import Path

import nbformat
import pytest

from instructor.grading import gradescope
from instructor.grading.gradescope_run import student_id
from instructor.release import leak_gate

ROOT = Path(__file__).resolve().parents[1]


pytestmark = [pytest.mark.gradescope, pytest.mark.confined, pytest.mark.notebook_exec]
PS = "ps01"
TOTAL = 14
CELL_TIMEOUT = 6  # seconds per cell in these runs (60 on Gradescope)
LIMIT = 240  # no run may take longer (Gradescope's default limit is 600 s)


@pytest.fixture(scope="module")
def autograder(tmp_path_factory):
    """``<root>/source`` from the zip's members, prepared as setup.sh prepares it."""
    top = tmp_path_factory.mktemp("autograder")
    for name, data in gradescope.members(PS).items():
        path = top / "source" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(data)
    env = {**os.environ, "ROTATIONS_AUTOGRADER_ROOT": str(top)}
    done = subprocess.run(
        [sys.executable, "-m", "instructor.grading.gradescope_run", "prepare"],
        cwd=top / "source",
        env=env,
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    return top


def notebook(top, kind):
    folder = top / "course" / ("source" if kind == "solved" else "release") / PS
    path = next(folder.glob("*.ipynb"))
    return path.name, nbformat.read(path, as_version=4)


def run_autograder(top, student, nb=None, raw=None, name=None, meta=None):
    """Hand in ``nb`` (or the bytes ``raw``) as ``student`` (or the Gradescope user ``meta``);
    run run_autograder; its results."""
    sub = top / "submission"
    for old in sub.glob("*"):
        old.unlink()
    sub.mkdir(exist_ok=True)
    filename = name or notebook(top, "blank")[0]
    if raw is not None:
        (sub / filename).write_bytes(raw)
    else:
        nbformat.write(nb, sub / filename)
    meta = meta or {"sid": student, "email": f"{student}@example.edu", "id": 1}
    (top / "submission_metadata.json").write_text(json.dumps({"users": [meta]}))
    results = top / "results" / "results.json"
    if results.exists():
        results.unlink()
    start = time.monotonic()
    done = _launch(top)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    assert time.monotonic() - start < LIMIT
    out = json.loads(results.read_text())
    _valid(out)
    return out


def _launch(top, env=None):
    """Gradescope's ``run_autograder`` of the layout at ``top`` (the tests' root, this Python,
    the short cell timeout; ``env`` added): the finished process."""
    full = {
        **os.environ,
        "ROTATIONS_AUTOGRADER_ROOT": str(top),
        "ROTATIONS_PYTHON": sys.executable,
        "ROTATIONS_CELL_TIMEOUT": str(CELL_TIMEOUT),
        **(env or {}),
    }
    return subprocess.run(
        ["/bin/bash", str(top / "source" / "run_autograder")],
        env=full,
        capture_output=True,
        text=True,
        timeout=LIMIT,
    )


def _valid(results):
    """Gradescope's results.json: a total score, tests with name, score, max_score, output."""
    assert isinstance(results["score"], float) and isinstance(results["execution_time"], float)
    assert results["tests"], results
    for test in results["tests"]:
        assert {"name", "score", "max_score", "output", "visibility"} <= set(test), test
        assert 0 <= test["score"] <= test["max_score"] or test["name"] == "grading"
        assert len(test["output"]) <= 2_000
    assert abs(results["score"] - sum(t["score"] for t in results["tests"])) < 1e-9


def scores(results):
    return {t["name"]: t["score"] for t in results["tests"]}


def no_leak(results):
    needles = leak_gate.collect_needles(ROOT)
    report = leak_gate.Report()
    leak_gate.scan_data("results.json", json.dumps(results).encode(), needles, report)
    assert report.hits == [], report.hits


def _prefix_first_answer(nb, code):
    first = next(c for c in nb.cells if c.id.endswith("-answer"))
    first.source = code + "\n" + first.source
    return nb


def test_solved_copy_gets_full_marks_and_results_hold_no_solution(autograder):
    _, nb = notebook(autograder, "solved")
    results = run_autograder(autograder, "s_solved", nb)
    assert results["score"] == TOTAL, results
    assert all(t["status"] == "passed" for t in results["tests"])
    assert len(results["tests"]) == 7
    assert results["extra_data"]["confinement"] == "bubblewrap", results  # which confinement
    no_leak(results)


def test_blank_copy_gets_zero(autograder):
    _, nb = notebook(autograder, "blank")
    results = run_autograder(autograder, "s_blank", nb)
    assert results["score"] == 0
    assert all("no answer recorded" in t["output"] for t in results["tests"]), results


def test_one_wrong_answer_loses_that_exercise_only_with_its_hint(autograder):
    _, nb = notebook(autograder, "solved")
    cell = next(c for c in nb.cells if c.id == "coords_by_projection-answer")
    cell.source += "\nanswer_coords_by_projection = [3.0, 1.0, 2.0]  # the reference coordinates\n"
    results = run_autograder(autograder, "s_one_wrong", nb)
    got = scores(results)
    assert got["coords_by_projection"] == 0 and results["score"] == TOTAL - 1, got
    (test,) = [t for t in results["tests"] if t["name"] == "coords_by_projection"]
    assert "wrong answer" in test["output"] and "The check said: ✗" in test["output"], test
    no_leak(results)


FORGED_RECORD = """\
import course_lib.record as _r
from IPython.display import display
def _forged(name, answer, result):
    display({_r.MIME: {"version": 1, "exercise": name, "kind": "explicit",
             "answer": "__import__('os').system('touch /tmp/forged-gs')"}}, raw=True)
_r.record = _forged
import sys
sys.modules["course_lib.record"] = _r
"""


def test_forged_record_gets_zero(autograder):
    _, nb = notebook(autograder, "blank")
    results = run_autograder(autograder, "s_forged", _prefix_first_answer(nb, FORGED_RECORD))
    assert results["score"] == 0, results
    assert not Path("/tmp/forged-gs").exists()


def test_a_file_that_is_not_json_gets_a_clear_message(autograder):
    results = run_autograder(autograder, "s_not_json", raw=b"\x00\xffnot a notebook {")
    assert results["score"] == 0
    assert "not a readable notebook" in results["output"], results


def test_deleted_and_reordered_cells(autograder):
    _, nb = notebook(autograder, "solved")
    checks = [i for i, c in enumerate(nb.cells) if c.id.endswith("-check")]
    del nb.cells[checks[1]]  # angle_from_lengths-check deleted
    nb.cells.reverse()  # everything else in reverse order
    results = run_autograder(autograder, "s_reordered", nb)
    got = scores(results)
    assert got["angle_from_lengths"] == 0, got
    (test,) = [t for t in results["tests"] if t["name"] == "angle_from_lengths"]
    assert "was deleted" in test["output"], test


def test_fifty_megabytes_of_output(autograder):
    _, nb = notebook(autograder, "solved")
    flood = "for _ in range(50):\n    print('x' * 2**20, flush=True)\n"
    results = run_autograder(autograder, "s_flood", _prefix_first_answer(nb, flood))
    assert results["score"] == TOTAL, results
    assert len(json.dumps(results)) < 20_000


def test_a_cell_that_never_ends(autograder):
    _, nb = notebook(autograder, "solved")
    loop = "import signal\nsignal.signal(signal.SIGINT, signal.SIG_IGN)\nwhile True:\n    pass\n"
    cell = next(c for c in nb.cells if c.id == "which_are_rigid-answer")
    cell.source = loop + cell.source
    results = run_autograder(autograder, "s_endless", nb)
    got = scores(results)
    assert got["coords_by_projection"] == got["angle_from_lengths"] == 1, got
    assert got["which_are_rigid"] == 0 and results["score"] == 2, got
    assert any("time limit" in t["output"] for t in results["tests"]), results


ATTACK = """\
import glob, json, os
seen = [p for p in glob.glob({top!r} + "/**", recursive=True) if os.path.isfile(p)]
print("SEEN", len(seen), seen[:20])
for p in seen:
    try:
        print(open(p, errors="replace").read()[:2000])
    except OSError as err:
        print("REFUSED", p, err)
try:
    os.makedirs({results!r}, exist_ok=True)
    with open({results!r} + "/results.json", "w") as f:
        json.dump({{"score": 1000.0, "output": "pwned"}}, f)
    print("WROTE results.json")
except OSError as err:
    print("REFUSED results.json", type(err).__name__)
"""


def test_student_code_sees_no_autograder_file_and_cannot_write_results(autograder):
    """A notebook that lists and prints /autograder (the solutions are in source/) and writes
    results/results.json itself: nothing of the root but course_lib is in the kernel's view."""
    _, nb = notebook(autograder, "blank")
    attack = ATTACK.format(top=str(autograder), results=str(autograder / "results"))
    results = run_autograder(autograder, "s_attack", _prefix_first_answer(nb, attack))
    assert results["score"] == 0 and "pwned" not in json.dumps(results), results
    graded = autograder / "course" / "autograded" / "s_attack@example.edu" / PS  # the e-mail
    text = next(graded.glob("*.ipynb")).read_text()
    seen = text.split("SEEN ", 1)[1].split("\\n", 1)[0]
    # in view: the installed course_lib only (what students have anyway), here the zip's copy
    # that the grader imports; never instructor/answers, the problem set, course/ or results/
    for name in ("instructor", "problem_sets", "course", "results"):
        assert f"{autograder}/{name}/" not in seen and f"source/{name}/" not in seen, seen
    assert "SOLUTIONS" not in text and "BEGIN SOLUTION" not in text
    # what it wrote landed in the sandbox's own /tmp; the real results.json is the grader's
    assert "pwned" not in (autograder / "results" / "results.json").read_text()
    no_leak(results)


def test_one_key_per_student_with_the_roster_in_the_zip(autograder, monkeypatch):
    """Issue 33, the Gradescope path of tests/test_grading_identity.py: the roster in the zip
    (source/roster.csv, read at grading time), alice7's notebook worked on her laptop id
    "Alice7@Example.EDU " and handed in under her e-mail in capitals and her sid: 14 of 14.
    bob9 worked as the bare hub user "bob9": graded on his key's numbers, results.json says so
    and carries his row for the instructor."""
    from test_grading_identity import ROSTER, WORKED_AS, differs, worked_copy

    source = next((autograder / "course" / "source" / PS).glob("*.ipynb"))
    roster = autograder / "source" / "roster.csv"
    roster.write_text(ROSTER)
    try:
        alice_nb, bob_nb = (
            worked_copy(source, WORKED_AS[s], monkeypatch) for s in ("alice7", "bob9")
        )
        alice = run_autograder(
            autograder, "", alice_nb, meta={"email": "ALICE7@example.edu", "sid": "3031042"}
        )
        bob = run_autograder(autograder, "", bob_nb, meta={"email": "Bob9@Example.edu"})
    finally:
        roster.unlink()
    assert alice["score"] == TOTAL, alice["output"]
    assert alice["extra_data"]["identity"]["graded_as"] == "alice7@example.edu"
    assert alice["extra_data"]["identity"]["how"] == "roster"
    assert "Your student id" not in alice["output"]
    lost = differs("bob9", "bob9@example.edu")
    assert bob["score"] == TOTAL - sum(ex.points for ex in lost)
    assert "graded on the numbers of 'bob9@example.edu'" in bob["output"]
    assert set(bob["extra_data"]["identity"]["lost"].split()) == {ex.name for ex in lost}
    no_leak(alice)
    no_leak(bob)


def test_student_id_from_metadata():
    assert student_id({"users": [{"sid": "", "email": "x@y.edu"}]}) == "x@y.edu"
    assert student_id({"users": [{"id": 12}]}) == "12"
    assert student_id({"users": [{"sid": "../../etc"}]}).startswith("etc-")  # never a path
    assert "/" not in student_id({"users": [{"sid": ".."}]}) != ".."
    assert student_id("not a dict") == "unknown-student"


def test_zip_holds_the_secret_members_and_nothing_else_leaks(tmp_path):
    path = gradescope.build_zip(PS, tmp_path)
    import zipfile

    with zipfile.ZipFile(path) as zf:
        names = zf.namelist()
        files = {n: zf.read(n) for n in names}
    assert "setup.sh" in names and "run_autograder" in names
    assert any(n.startswith("instructor/answers/") for n in names)
    assert gradescope.leak_check(files) == []
    # a solution line outside the SECRET members is caught
    files["instructor/grading/extra.txt"] = files[
        next(n for n in names if n.startswith("instructor/answers/ch"))
    ]
    assert gradescope.leak_check(files)


def _five(top):
    """Five submissions: solved, blank, one wrong, every other answer, a check cell deleted."""
    name, solved = notebook(top, "solved")
    _, blank = notebook(top, "blank")
    wrong = nbformat.from_dict(json.loads(json.dumps(solved)))
    cell = next(c for c in wrong.cells if c.id == "unit_tangent-answer")
    cell.source += "\nanswer_unit_tangent = None\n"
    half = nbformat.from_dict(json.loads(json.dumps(blank)))
    answers = [i for i, c in enumerate(half.cells) if c.id.endswith("-answer")]
    for i in answers[::2]:
        half.cells[i] = solved.cells[i]
    deleted = nbformat.from_dict(json.loads(json.dumps(solved)))
    deleted.cells = [c for c in deleted.cells if c.id != "bac_cab-check"]
    return name, {
        "p_solved": solved,
        "p_blank": blank,
        "p_wrong": wrong,
        "p_half": half,
        "p_deleted": deleted,
    }


def test_same_points_as_nbgrader_autograde_of_make_course(autograder, tmp_path):
    """The same 5 submissions through `make course` + `nbgrader autograde` and through
    run_autograder: the same points for every exercise."""
    from nbgrader.api import Gradebook

    from instructor.grading.course import write_course

    course = tmp_path / "course"
    write_course(course)
    env = {**os.environ, "PATH": f"{Path(sys.executable).parent}:{os.environ['PATH']}"}
    nbgrader = str(Path(sys.executable).with_name("nbgrader"))

    def run(*args):
        done = subprocess.run(
            [nbgrader, *args], cwd=course, env=env, capture_output=True, text=True
        )
        assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]

    run("generate_assignment", PS, "--create")
    name, subs = _five(autograder)
    for sid, nb in subs.items():
        dest = course / "submitted" / sid / PS
        dest.mkdir(parents=True)
        nbformat.write(nb, dest / name)
    run("autograde", PS, "--create")
    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gb:
        by_nbgrader = {
            sid: {
                g.name.removesuffix("-check"): g.score
                for nb in gb.find_submission(PS, sid).notebooks
                for g in nb.grades
            }
            for sid in subs
        }
    for sid, nb in subs.items():
        got = scores(run_autograder(autograder, sid, nb))
        assert got == by_nbgrader[sid], (sid, got, by_nbgrader[sid])
    assert sum(by_nbgrader["p_solved"].values()) == TOTAL
    assert sum(by_nbgrader["p_blank"].values()) == 0
    assert 0 < sum(by_nbgrader["p_half"].values()) < TOTAL


# --- intake and the grader's own faults (issue 32) -----------------------------------------


def run_raw(top, student, fill, env=None):
    """run_autograder on a submission folder that ``fill(folder)`` makes (any kind of file):
    ``(exit code, results or None, stderr)``; results, when written, are valid."""
    import shutil

    sub = top / "submission"
    if sub.is_symlink() or sub.is_file():
        sub.unlink()
    elif sub.exists():
        shutil.rmtree(sub)
    sub.mkdir()
    fill(sub)
    meta = {"users": [{"sid": student, "id": 1}]}
    (top / "submission_metadata.json").write_text(json.dumps(meta))
    results = top / "results" / "results.json"
    done = _launch(top, env)
    out = json.loads(results.read_text()) if results.is_file() else None
    if out is not None:
        _valid(out)
        assert out["output_format"] == out["test_output_format"] == "text"
    return done.returncode, out, done.stderr


def _sparse(path, size=2 * 2**30):
    with open(path, "wb") as f:
        f.truncate(size)


def _zip_bomb(path):
    """A .zip whose one member unpacks to 256 MB of zeros (about 250 kB packed)."""
    import zipfile

    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as zf:
        with zf.open("ps01_rigid_body_motion.ipynb", "w", force_zip64=True) as member:
            block = b"\0" * 2**20
            for _ in range(256):
                member.write(block)


def _bad_inputs(top):
    name = notebook(top, "blank")[0]
    solved = top / "course" / "source" / PS / name
    return {
        "no notebook": (lambda s: (s / "README.txt").write_text("hi"), "no notebook"),
        "two notebooks": (
            lambda s: [(s / n).write_bytes(solved.read_bytes()) for n in ("a.ipynb", "b c.ipynb")],
            "2 notebooks",
        ),
        "empty": (lambda s: (s / name).write_bytes(b""), "empty"),
        "not JSON": (lambda s: (s / name).write_bytes(b"\x00\xffnot {"), "not a readable"),
        "2 GB": (lambda s: _sparse(s / name), "over the limit of 20 MB"),
        "zip bomb": (lambda s: _zip_bomb(s / "ps01.zip"), "A .zip is not unpacked"),
        "link to the solved copy": (lambda s: (s / name).symlink_to(solved), "symbolic link"),
        "link to /etc/shadow": (lambda s: (s / name).symlink_to("/etc/shadow"), "symbolic link"),
        "linked folder": (lambda s: (s / "x").symlink_to(solved.parent), "no notebook"),
        "hard link": (lambda s: os.link(solved, s / name), "hard link"),
        "FIFO": (lambda s: os.mkfifo(s / name), "named pipe"),
        "folder named .ipynb": (lambda s: (s / name).mkdir(), "a folder"),
    }


def test_bad_submissions_get_0_a_clear_note_and_valid_results_regression_issue32(autograder):
    """A link to the solved copy got full marks; a 2 GB upload was read whole into memory."""
    for case, (fill, said) in _bad_inputs(autograder).items():
        start = time.monotonic()
        code, results, err = run_raw(autograder, "s_bad", fill)
        assert code == 0, (case, err[-2000:])
        assert results["score"] == 0 and said in results["output"], (case, results)
        assert time.monotonic() - start < 30, case  # refused before nbgrader ran
        no_leak(results)
    assert not (autograder / "course" / "submitted" / "s_bad").exists()


def test_another_name_unicode_and_spaces_and_a_student_id_with_dots_are_graded(autograder):
    _, nb = notebook(autograder, "solved")

    def fill(sub):
        nbformat.write(nb, sub / "mon devoir é (final).ipynb")
        _zip_bomb(sub / "backup.zip")

    code, results, err = run_raw(autograder, "../../evil/..", fill)
    assert code == 0, err[-2000:]
    assert results["score"] == TOTAL, results
    assert "mon devoir é (final).ipynb" in results["output"], results["output"]
    student = results["extra_data"]["student"]  # never a path: the safe letters, then a hash
    assert student.startswith("evil") and "/" not in student and ".." not in student
    assert results["extra_data"]["confinement"] == "bubblewrap"
    assert (autograder / "course" / "submitted" / student / PS).is_dir()


def _missing_bwrap():
    return {"PATH": "/nonexistent"}  # run_autograder and nbgrader are run by absolute path


def test_the_graders_own_faults_exit_1_and_write_no_results(autograder):
    """A run that failed for the grader's reasons gave the student a recorded 0."""
    import shutil

    _, blank = notebook(autograder, "blank")
    name = notebook(autograder, "blank")[0]

    def fill(sub):
        nbformat.write(blank, sub / name)

    # the confined kernel cannot start (here: no bwrap on PATH)
    code, results, err = run_raw(autograder, "s_fault", fill, env=_missing_bwrap())
    assert code == 1 and results is None and "bwrap" in err, err[-2000:]
    # nbgrader itself fails (its gradebook is not a database)
    db = autograder / "course" / "gradebook.db"
    shutil.copyfile(db, db.with_suffix(".keep"))
    try:
        db.write_bytes(b"not a database")
        code, results, err = run_raw(autograder, "s_fault", fill)
    finally:
        os.replace(db.with_suffix(".keep"), db)
    assert code == 1 and results is None and "nbgrader autograde exited" in err, err[-2000:]
    # a bug of the grader's own (a setting it cannot read)
    code, results, err = run_raw(autograder, "s_fault", fill, env={"ROTATIONS_CELL_TIMEOUT": "x"})
    assert code == 1 and results is None and "ValueError" in err, err[-2000:]


def _selftest(top, env=None):
    full = {**os.environ, "ROTATIONS_AUTOGRADER_ROOT": str(top), **(env or {})}
    return subprocess.run(
        [sys.executable, "-m", "instructor.grading.gradescope_run", "selftest"],
        cwd=top / "source",
        env=full,
        capture_output=True,
        text=True,
        timeout=LIMIT,
    )


def test_setup_self_test_passes_on_a_good_image_and_fails_a_broken_one(autograder):
    done = _selftest(autograder)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    assert f"the solved copy got {TOTAL} of {TOTAL} points" in done.stdout
    assert f"the blank copy got 0 of {TOTAL} points" in done.stdout
    # no confinement: the build fails, with the reason
    done = _selftest(autograder, _missing_bwrap())
    assert done.returncode == 1 and "bwrap" in done.stderr, done.stderr[-2000:]
    # a grader that does not give the solved copy full marks: tests/test_grading_intake.py
