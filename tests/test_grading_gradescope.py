"""The Gradescope autograder (grader/gradescope.py, grader/gradescope_run.py), run as Gradescope
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

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "release"))
import leak_gate  # noqa: E402

from grader import gradescope  # noqa: E402
from grader.gradescope_run import student_id  # noqa: E402

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
        [sys.executable, str(top / "source/grader/gradescope_run.py"), "prepare"],
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


def run_autograder(top, student, nb=None, raw=None, name=None):
    """Hand in ``nb`` (or the bytes ``raw``) as ``student``; run run_autograder; its results."""
    sub = top / "submission"
    for old in sub.glob("*"):
        old.unlink()
    sub.mkdir(exist_ok=True)
    filename = name or notebook(top, "blank")[0]
    if raw is not None:
        (sub / filename).write_bytes(raw)
    else:
        nbformat.write(nb, sub / filename)
    meta = {"users": [{"sid": student, "email": f"{student}@example.edu", "id": 1}]}
    (top / "submission_metadata.json").write_text(json.dumps(meta))
    results = top / "results" / "results.json"
    if results.exists():
        results.unlink()
    env = {
        **os.environ,
        "ROTATIONS_AUTOGRADER_ROOT": str(top),
        "ROTATIONS_PYTHON": sys.executable,
        "ROTATIONS_CELL_TIMEOUT": str(CELL_TIMEOUT),
    }
    start = time.monotonic()
    done = subprocess.run(
        ["bash", str(top / "source" / "run_autograder")],
        env=env,
        capture_output=True,
        text=True,
        timeout=LIMIT,
    )
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    assert time.monotonic() - start < LIMIT
    out = json.loads(results.read_text())
    _valid(out)
    return out


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
    assert results["extra_data"] == {"confinement": "bubblewrap"}, results  # which confinement
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
    graded = autograder / "course" / "autograded" / "s_attack" / PS
    text = next(graded.glob("*.ipynb")).read_text()
    seen = text.split("SEEN ", 1)[1].split("\\n", 1)[0]
    # in view: the installed course_lib only (what students have anyway), here the zip's copy
    # that the grader imports; never tools/solutions, the problem set, course/ or results/
    for name in ("tools", "problem_sets", "course", "results", "grader"):
        assert f"{autograder}/{name}/" not in seen and f"source/{name}/" not in seen, seen
    assert "SOLUTIONS" not in text and "BEGIN SOLUTION" not in text
    # what it wrote landed in the sandbox's own /tmp; the real results.json is the grader's
    assert "pwned" not in (autograder / "results" / "results.json").read_text()
    no_leak(results)


def test_student_id_from_metadata():
    assert student_id({"users": [{"sid": "", "email": "x@y.edu"}]}) == "x@y.edu"
    assert student_id({"users": [{"id": 12}]}) == "12"
    assert student_id({"users": [{"sid": "../../etc"}]}) == "etc"  # never a path
    assert student_id({"users": [{"sid": ".."}]}) == "unknown-student"
    assert student_id("not a dict") == "unknown-student"


def test_zip_holds_the_secret_members_and_nothing_else_leaks(tmp_path):
    path = gradescope.build_zip(PS, tmp_path)
    import zipfile

    with zipfile.ZipFile(path) as zf:
        names = zf.namelist()
        files = {n: zf.read(n) for n in names}
    assert "setup.sh" in names and "run_autograder" in names
    assert any(n.startswith("tools/solutions/") for n in names)
    assert gradescope.leak_check(files) == []
    # a solution line outside the SECRET members is caught
    files["grader/extra.txt"] = files[next(n for n in names if n.startswith("tools/solutions/"))]
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

    from grader.course import write_course

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
