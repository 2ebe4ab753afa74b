"""A class graded by real nbgrader 0.9.6 in a `make course` directory, attacked as students do.

Each student of the class hands in problem set 2 (the release copy, or the instructor's
solved copy) with one attack in it. The attacks are those of issue 17: they all got full marks
when the points were decided in the student's kernel. Now every attack scores 0, nothing of the
instructor's (source/, solutions, gradebook) is read or written, the instructor's copy gets
full marks, a blank copy 0, and a malformed submission is graded around (0 for the broken grade
cells, with a note) without stopping the class.

One attack of each kind runs in `make test` (:func:`test_fast_class`, about a minute); the rest
are marked ``slow_grading`` (``pytest -m slow_grading tests/test_grading_nbgrader.py``, about
two minutes more).
"""

from __future__ import annotations

import hashlib
import json
import os
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest

from course_lib.exercises import exercises
from instructor.grading.course import write_course

ROOT = Path(__file__).resolve().parents[1]

pytestmark = [pytest.mark.notebook_exec, pytest.mark.confined]
NBGRADER = Path(sys.executable).with_name("nbgrader")
PS = "ps02"
CHAPTER = 2
TOTAL = sum(ex.points for ex in exercises(CHAPTER))

REDEFINE_CHECK = """\
class _Pass:
    ok, status, message = True, "correct", "correct."
def check(name, answer):
    return _Pass()
"""
SET_JUDGE = """\
import course_lib.exercises as _ce
_ce.judge = lambda ex, fp, answer: ("correct", "correct.")
"""
INPUT_TRANSFORMER = """\
def _strip(lines):
    return [l for l in lines if not l.lstrip().startswith(("assert", "record("))]
get_ipython().input_transformers_post.append(_strip)
"""
AST_TRANSFORMER = """\
import ast
class _Drop(ast.NodeTransformer):
    def visit_Assert(self, node):
        return None
    def visit_Expr(self, node):
        return None
get_ipython().ast_transformers.append(_Drop())
"""
FORGED_RECORD = """\
import course_lib.record as _r
from IPython.display import display
def _forged(name, answer, result):
    display({_r.MIME: {"version": 1, "exercise": name, "kind": "explicit",
             "answer": "__import__('os').system('touch /tmp/forged')"}}, raw=True)
_r.record = _forged
import sys
sys.modules["course_lib.record"] = _r
"""
FOLDER = {
    "course_lib/__init__.py": "",
    "course_lib/exercises.py": (
        "import sympy\n"
        "class _Pass:\n    ok, status, message = True, 'correct', 'correct.'\n"
        "def check(name, answer):\n    return _Pass()\n"
        "def __getattr__(name):\n    return sympy.Symbol(name)\n"
    ),
    "course_lib/record.py": "def record(name, answer, result):\n    pass\n",
}


# 60 MB of stdout, 600 times the 100 kB kept per cell (200 MB took past the 60 s cell timeout
# on a machine at load 8: a 0 for a slow machine, not for the flood)
FLOOD = "for _ in range(60):\n    print('x' * 10**6)\n"


def _snoop(course):
    return f"""\
import glob, os
seen = glob.glob({str(course)!r} + "/**", recursive=True)
for p in seen + glob.glob({str(ROOT)!r} + "/instructor/**"):
    if os.path.isfile(p):
        print("SEEN", p)
        print(open(p, errors="replace").read()[:20000])
for target in ({str(course / "gradebook.db")!r}, {str(course / "source" / PS / "x.txt")!r}):
    try:
        with open(target, "a") as f:
            f.write("pwned")
        print("WROTE", target)
    except OSError as err:
        print("REFUSED", type(err).__name__)
"""


def run(args, cwd):
    env = {**os.environ, "PATH": f"{NBGRADER.parent}{os.pathsep}{os.environ.get('PATH', '')}"}
    proc = subprocess.run(
        [str(NBGRADER), *args], cwd=cwd, capture_output=True, text=True, timeout=900, env=env
    )
    return proc.returncode, proc.stdout + proc.stderr


def _digest(folder):
    h = hashlib.sha256()
    for p in sorted(Path(folder).rglob("*")):
        if p.is_file():
            h.update(str(p).encode() + p.read_bytes())
    return h.hexdigest()


@pytest.fixture(scope="module")
def course(tmp_path_factory):
    root = tmp_path_factory.mktemp("course")
    write_course(root)
    code, out = run(["generate_assignment", PS, "--create"], root)
    assert code == 0, out
    return root


def _notebook(course, kind):
    folder = course / ("source" if kind == "solved" else "release") / PS
    path = next(folder.glob("*.ipynb"))
    return path.name, nbformat.read(path, as_version=4)


def submit(course, student, kind="blank", prefix="", files=None, edit=None):
    """Hand in the blank (release) or solved (source) copy with an attack in it."""
    name, nb = _notebook(course, kind)
    if prefix:
        first = next(c for c in nb.cells if c.id.endswith("-answer"))
        first.source = prefix + "\n" + first.source
    if edit:
        edit(nb)
    dest = course / "submitted" / student / PS
    dest.mkdir(parents=True)
    nbformat.write(nb, dest / name)
    (dest / "timestamp.txt").write_text("2026-01-01 00:00:00.000000 UTC")
    for rel, text in (files or {}).items():
        (dest / rel).parent.mkdir(parents=True, exist_ok=True)
        (dest / rel).write_text(text)


def scores(course):
    from nbgrader.api import Gradebook

    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gb:
        return {s.student.id: (s.score, s.max_score) for s in gb.find_assignment(PS).submissions}


def autograded(course, student):
    path = next((course / "autograded" / student / PS).glob("*.ipynb"))
    return nbformat.read(path, as_version=4)


def _malform(nb):
    checks = [i for i, c in enumerate(nb.cells) if c.id.endswith("-check")]
    dup = nbformat.from_dict(json.loads(json.dumps(nb.cells[checks[0]])))
    dup.id = "a-copy"
    nb.cells[checks[2]].cell_type = "markdown"  # retyped
    nb.cells[checks[2]].pop("outputs", None)
    nb.cells[checks[2]].pop("execution_count", None)
    del nb.cells[checks[1]]  # deleted
    nb.cells.insert(checks[0] + 1, dup)  # duplicated


def _add_grade_cells(nb):
    """A new graded cell worth 100 points, and the first answer cell made a graded one."""
    extra = nbformat.v4.new_code_cell("print('free points')")
    extra.metadata = {
        "nbgrader": {
            "grade": True,
            "grade_id": "free",
            "locked": False,
            "points": 100,
            "solution": False,
            "schema_version": 3,
        }
    }
    extra.id = "free"
    nb.cells.append(extra)
    answer = next(c for c in nb.cells if c.id.endswith("-answer"))
    answer.metadata["nbgrader"].update(grade=True, points=50)


def _exit_in_third_answer(nb):
    answers = [c for c in nb.cells if c.id.endswith("-answer")]
    answers[2].source = "import os\nos._exit(0)\n" + answers[2].source


def _malformed_metadata(nb):
    """Check cells 1-3: ``metadata.nbgrader`` null, a string, and string grade and points."""
    checks = [c for c in nb.cells if c.id.endswith("-check")]
    checks[0].metadata["nbgrader"] = None
    checks[1].metadata["nbgrader"] = "grade"
    checks[2].metadata["nbgrader"].update(grade="yes", points="1e9")


def _points_of_cells(nb, ids):
    return sum(c.metadata["nbgrader"]["points"] for c in nb.cells if c.id in ids)


def test_fast_class(course):
    """The instructor's copy, a blank one, one attack of each kind and a malformed copy."""
    before = {p: _digest(course / p) for p in ("source", "release")}
    db = (course / "gradebook.db").read_bytes()
    submit(course, "a_instructor", "solved")
    submit(course, "b_blank")
    submit(course, "c_redefine_check", prefix=REDEFINE_CHECK)
    submit(course, "d_course_lib_folder", files=FOLDER)
    submit(course, "e_snoop", prefix=_snoop(course))
    submit(course, "f_malformed", "solved", edit=_malform)
    submit(course, "g_instructor_after", "solved")
    submit(course, "h_added_grade_cells", "solved", edit=_add_grade_cells)
    submit(course, "i_os_exit", "solved", edit=_exit_in_third_answer)
    submit(course, "j_malformed_metadata", "solved", edit=_malformed_metadata)
    code, out = run(["autograde", PS, "--create"], course)
    assert code == 0, out
    got = scores(course)
    assert got["a_instructor"] == got["g_instructor_after"] == (TOTAL, TOTAL)
    # grading metadata the student added is dropped: graded, and only for the released cells
    assert got["h_added_grade_cells"] == (TOTAL, TOTAL), got
    added = autograded(course, "h_added_grade_cells").cells
    assert any("GradingNote" in c.source and "free" in c.source for c in added)
    # os._exit in the third answer: the checks before it keep their points, the rest 0 + note
    _, solved = _notebook(course, "solved")
    checks = [c.id for c in solved.cells if c.id.endswith("-check")]
    assert got["i_os_exit"] == (_points_of_cells(solved, checks[:2]), TOTAL), got
    died = json.dumps([c.get("outputs", []) for c in autograded(course, "i_os_exit").cells])
    assert "kernel died" in died
    for student in ("b_blank", "c_redefine_check", "d_course_lib_folder", "e_snoop"):
        assert got[student] == (0, TOTAL), (student, got)
    # the malformed copy: 0 for the three broken grade cells, full marks for the rest
    assert got["f_malformed"] == (TOTAL - _points_of_cells(solved, checks[:3]), TOTAL)
    notes = [
        o.evalue
        for c in autograded(course, "f_malformed").cells
        for o in c.get("outputs", [])
        if o.output_type == "error"
    ]
    assert any("duplicated" in n for n in notes) and any("deleted" in n for n in notes), notes
    assert any("another type" in n for n in notes), notes
    # metadata.nbgrader null, a string, "points": "1e9": the student was dropped (regression)
    assert got["j_malformed_metadata"] == (TOTAL - _points_of_cells(solved, checks[:3]), TOTAL)
    notes = [
        o.evalue
        for c in autograded(course, "j_malformed_metadata").cells
        for o in c.get("outputs", [])
        if o.output_type == "error"
    ]
    assert sum("malformed grading metadata" in n for n in notes) == 3, notes
    # nothing of the instructor's was read or written
    snoop = json.dumps([c.get("outputs", []) for c in autograded(course, "e_snoop").cells])
    assert "BEGIN SOLUTION" not in snoop and "SOLUTIONS" not in snoop
    assert "SEEN" not in snoop and "WROTE" not in snoop and "REFUSED" in snoop
    assert {p: _digest(course / p) for p in ("source", "release")} == before
    assert (course / "gradebook.db").read_bytes() != db  # graded, but by nbgrader only
    assert not (course / "source" / PS / "x.txt").exists()
    # no check cell output reads as a score
    for cell in autograded(course, "a_instructor").cells:
        if cell.id.endswith("-check"):
            kinds = {o.output_type for o in cell.outputs}
            assert kinds == {"display_data"}, cell.outputs


@pytest.mark.slow_grading
def test_slow_attacks(course):
    """The other in-kernel attacks of issue 17: every one scores 0."""
    attacks = {
        "s_set_judge": SET_JUDGE,
        "s_input_transformer": INPUT_TRANSFORMER,
        "s_ast_transformer": AST_TRANSFORMER,
        "s_forged_record": FORGED_RECORD,
    }
    for student, prefix in attacks.items():
        submit(course, student, prefix=prefix)
    submit(course, "s_folder_solved_names", files=FOLDER, prefix=REDEFINE_CHECK)
    submit(course, "s_output_flood", "solved", prefix=FLOOD)
    code, out = run(["autograde", PS, "--create"], course)
    assert code == 0, out
    got = scores(course)
    for student in (*attacks, "s_folder_solved_names"):
        assert got[student] == (0, TOTAL), (student, got)
    assert not Path("/tmp/forged").exists()
    # 60 x 1 MB of stdout: graded as usual, and the autograded notebook stays small
    (path,) = (course / "autograded" / "s_output_flood" / PS).glob("*.ipynb")
    assert got["s_output_flood"] == (TOTAL, TOTAL), (got, path.read_text()[-3000:])
    assert path.stat().st_size < 2_000_000, path.stat().st_size
    assert "bytes of output cut" in path.read_text()


SIGINT_LOOP = "import signal\nsignal.signal(signal.SIGINT, signal.SIG_IGN)\nwhile True:\n    pass\n"
FLUSHED_FLOOD = """\
import sys, time
_t0 = time.time()
while time.time() - _t0 < 4:
    sys.stdout.write("y" * 2**20 + "\\n"); sys.stdout.flush(); time.sleep(0.005)
"""
PEAK = (
    "import resource, subprocess, sys\n"
    "subprocess.run(sys.argv[1:])\n"
    "print('PEAK_KB', resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)\n"
)


def _in_answers(numbers, code):
    def edit(nb):
        answers = [c for c in nb.cells if c.id.endswith("-answer")]
        for i in numbers:
            answers[i].source = code + "\n" + answers[i].source

    return edit


@pytest.mark.slow_grading
def test_sigint_ignoring_loop_and_flushed_floods_no_longer_drop_the_student(tmp_path):
    """A loop that ignores SIGINT (the interrupt at the timeout) and flushed 1 MB writes in three
    cells: both students were dropped (autograde exit 1; the floods held 3.2 GB in the grader).
    Now the loop's kernel is killed after the timeout and the checks before it keep their
    points; the floods are cut as they arrive and score full marks."""
    root = tmp_path / "course"
    write_course(root)
    code, out = run(["generate_assignment", PS, "--create"], root)
    assert code == 0, out
    submit(root, "a_sigint_loop", "solved", edit=_in_answers([2], SIGINT_LOOP))
    submit(root, "b_flushed_floods", "solved", edit=_in_answers([0, 1, 2], FLUSHED_FLOOD))
    submit(root, "c_instructor_after", "solved")
    env = {**os.environ, "PATH": f"{NBGRADER.parent}{os.pathsep}{os.environ.get('PATH', '')}"}
    argv = [sys.executable, "-c", PEAK, str(NBGRADER), "autograde", PS, "--create"]
    proc = subprocess.run(  # a short timeout: the loop costs it, and 4 s of iopub, once
        [*argv, "--Execute.timeout=20"], cwd=root, capture_output=True, text=True, env=env
    )
    assert proc.returncode == 0 and "PEAK_KB" in proc.stdout, proc.stdout + proc.stderr
    peak_mb = int(proc.stdout.split("PEAK_KB")[1].split()[0]) // 1024
    got = scores(root)
    _, solved = _notebook(root, "solved")
    checks = [c.id for c in solved.cells if c.id.endswith("-check")]
    assert got["a_sigint_loop"] == (_points_of_cells(solved, checks[:2]), TOTAL), got
    hung = json.dumps([c.get("outputs", []) for c in autograded(root, "a_sigint_loop").cells])
    assert "ignored the interrupt" in hung and "kernel was stopped" in hung
    assert got["b_flushed_floods"] == got["c_instructor_after"] == (TOTAL, TOTAL), got
    (path,) = (root / "autograded" / "b_flushed_floods" / PS).glob("*.ipynb")
    assert path.stat().st_size < 1_000_000 and "cut while the cell ran" in path.read_text()
    assert peak_mb < 1000, peak_mb  # nbgrader or its kernel; before: 3.2 GB and exit 1


FAKE_MATHJAX = "window.ROTATIONS_FAKE_MATHJAX = {a: {b: 1}}; // {{ not a template {% x %} {# #}\n"


@pytest.mark.slow_grading
def test_feedback_inlines_mathjax_instead_of_the_cdn(tmp_path):
    """nbgrader's feedback template loaded MathJax 2.7.7 from a CDN: raw TeX offline."""
    js = tmp_path / "tex-svg.js"
    js.write_text(FAKE_MATHJAX)
    root = tmp_path / "course"
    write_course(root, mathjax=js)
    code, out = run(["generate_assignment", PS, "--create"], root)
    assert code == 0, out
    submit(root, "a_instructor", "solved")
    code, out = run(["autograde", PS, "--create"], root)
    assert code == 0, out
    code, out = run(["generate_feedback", PS], root)
    assert code == 0, out
    (page,) = (root / "feedback" / "a_instructor" / PS).glob("*.html")
    html = page.read_text()
    assert FAKE_MATHJAX.strip() in html and "window.MathJax = {tex:" in html
    assert "cdnjs" not in html and "mathjax/2.7" not in html.lower()
