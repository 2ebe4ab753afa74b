"""``make release`` (release/): the student edition, the wheel and the leak gate.

One release is built for the module (without the website, which ``make release`` and ``make
site-test`` build and check; its folder is scanned empty here) into a temporary folder. The
gate must pass on it, and fail, naming the file and the line, on a worked-solution line planted
in a copy: in a file of the edition, only in its git history, in the wheel, in a page of the
site (inside the HTML of highlighted code), as an answer's expression in a sentence (the
issue's docstring leak), and on nbgrader's markers and a solutions folder.
"""

import shutil
import subprocess
import zipfile
from pathlib import Path

import nbformat
import pytest

from instructor.release import leak_gate, make_release, student_edition

ROOT = Path(__file__).resolve().parents[1]


CELL_WITH_REGION = (
    "answer_x = None\n### BEGIN SOLUTION\nhelper_value = sp.Rational(42, 17) * omega_hat\n"
    ")\n\nR = Rz\nanswer_x = helper_value.T @ np.eye(3)  # the transpose\n### END SOLUTION"
)


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    out = tmp_path_factory.mktemp("release")
    lines, hits = make_release.release(out, with_site=False)
    return out, lines, hits


@pytest.fixture(scope="module")
def needles():
    return leak_gate.collect_needles(ROOT)


def _gate(student, dist, site, needles):
    report = leak_gate.Report()
    leak_gate.scan_tree(student, needles, report, "student")
    leak_gate.scan_history(student, needles, report, "student")
    for wheel in sorted(Path(dist).glob("*.whl")):
        leak_gate.scan_wheel(wheel, needles, report)
    leak_gate.scan_tree(site, needles, report, "site")
    return report.hits


@pytest.fixture
def copy(built, tmp_path):
    """A copy of the built release (the edition with its .git) to plant leaks in."""
    out, _, _ = built
    shutil.copytree(out, tmp_path / "release", symlinks=True)
    return tmp_path / "release"


def _git(repo, *args):
    ident = ["-c", "user.name=test", "-c", "user.email=test@example.invalid"]
    subprocess.run(["git", "-C", str(repo), *ident, *args], check=True, capture_output=True)


def a_solution_line(needles):
    return max(needles.lines, key=len)


# ------------------------------------------------------------------------------ the release


def test_the_release_passes_its_gate(built):
    out, lines, hits = built
    assert hits == [], lines
    assert any(line.startswith("leak gate: ") for line in lines)


def test_the_needles_hold_every_worked_solution(needles):
    assert needles.regions >= 30 and len(needles.lines) >= 150
    from_files = [
        line.strip()
        for path in sorted((ROOT / "instructor" / "answers").glob("*.py"))
        for line, _ in leak_gate._solutions_file_lines(path)
    ]
    assert len(from_files) >= 100
    missing = [
        line
        for line in from_files
        if line not in needles.lines
        and len("".join(line.split())) >= leak_gate.MIN_CHARS
        and not leak_gate.PUNCTUATION.match(line)
    ]
    assert missing == []


def test_the_edition_is_a_repository_of_its_own_with_one_commit(built):
    student = built[0] / "student"
    log = subprocess.run(
        ["git", "-C", str(student), "log", "--all", "--format=%s"], capture_output=True, text=True
    )
    assert len(log.stdout.splitlines()) == 1 and "Student edition" in log.stdout
    branch = subprocess.run(
        ["git", "-C", str(student), "branch", "--show-current"], capture_output=True, text=True
    )
    assert branch.stdout.strip() == "student"  # the branch the launch links open
    status = subprocess.run(
        ["git", "-C", str(student), "status", "--porcelain"], capture_output=True, text=True
    )
    assert status.stdout == ""


def test_the_edition_holds_no_instructor_tool_and_no_answer_test(built):
    student = built[0] / "student"
    assert (
        not (student / "instructor").exists()
        and not (student / "course_lib" / "student.py").exists()
    )
    tests = {p.name for p in (student / "tests").glob("test_*.py")}
    assert "test_exercises.py" not in tests and "test_student.py" not in tests
    assert {"test_so3.py", "test_interactive.py"} <= tests
    # what the kept tests import from their folder comes along (regression: plotting_helpers)
    assert {"conftest.py", "nbval_sanitize.cfg", "plotting_helpers.py"} <= {
        p.name for p in (student / "tests").iterdir()
    }
    for name in ("README.md", "Makefile", "conftest.py", "requirements-test.txt", ".gitignore"):
        assert (student / name).is_file(), name
    pins = (student / "requirements-test.txt").read_text()
    assert "nbgrader" not in pins and "pytest==" in pins and "nbval==" in pins
    assert "pytest-xdist==" in pins and "execnet==" in pins  # the Makefile's two workers
    assert "nbgrader==" not in (student / "environment-student.txt").read_text()


def test_the_chapters_keep_their_reading_part_and_lose_every_solution(built):
    for path in sorted((built[0] / "student" / "notebooks").glob("*.ipynb")):
        text = path.read_text(encoding="utf-8")
        assert "BEGIN SOLUTION" not in text
        nb = nbformat.reads(text, as_version=4)
        assert any(c.get("outputs") for c in nb.cells), f"{path.name}: reading outputs dropped"
        graded = [i for i, c in enumerate(nb.cells) if c.metadata.get("nbgrader")]
        assert all(not c.get("outputs") for c in nb.cells[graded[0] if graded else len(nb.cells) :])


def test_the_student_readme_covers_every_way_in_and_the_round_trip(built):
    readme = (built[0] / "student" / "README.md").read_text()
    for words in (
        "laptop",
        "JupyterHub",
        "Binder",
        "Colab",
        "Run a chapter",
        "problem set",
        "Hand it in",
        "make test",
        "Your student id",
        'set_student_id("',
    ):
        assert words in readme, words
    assert "@" not in readme.replace("user.email", ""), "a placeholder left in the README"
    assert "instructor edition" not in readme.lower() and "instructor/answers" not in readme


def test_the_wheel_pulls_in_what_the_notebooks_import_and_no_tool(built):
    (wheel,) = (built[0] / "dist").glob("*.whl")
    with zipfile.ZipFile(wheel) as zf:
        names = zf.namelist()
        meta = zf.read(next(n for n in names if n.endswith("METADATA"))).decode()
    requires = [
        line.split(":", 1)[1].strip() for line in meta.splitlines() if "Requires-Dist" in line
    ]
    for package in ("numpy", "sympy", "matplotlib", "ipywidgets", "ipympl"):
        assert any(r.startswith(package) for r in requires), (package, requires)
    assert not any("nbgrader" in r or "pytest" in r for r in requires)
    assert all(n.startswith("course_lib") for n in names)
    assert "instructor/build/student.py" not in names


def test_student_tests_leave_out_what_names_answers_and_say_why(tmp_path):
    (tmp_path / "test_a.py").write_text("from course_lib import so3\n")
    (tmp_path / "test_b.py").write_text("answer_hat = omega * omega.T\n")
    (tmp_path / "test_c.py").write_text("import nbgrader\n")
    # regression: a test of the e2e/ or site/ helpers, which the edition does not hold, was
    # kept and failed the edition's make test at collection (ModuleNotFoundError: a11y_rules)
    (tmp_path / "test_d.py").write_text('sys.path.insert(0, str(ROOT / "e2e"))\n')
    (tmp_path / "test_e.py").write_text('build = ROOT / "site" / "build.py"\n')
    (tmp_path / "helpers.py").write_text("def f():\n    return 1\n")
    (tmp_path / "sanitize.cfg").write_text("[x]\n")
    kept, left_out = student_edition.student_tests(tmp_path)
    assert kept == ["helpers.py", "sanitize.cfg", "test_a.py"]
    assert "answers" in left_out["test_b.py"] and "tool" in left_out["test_c.py"]
    assert "tool" in left_out["test_d.py"] and "tool" in left_out["test_e.py"]


# ------------------------------------------------------------------------------ the needles


def test_trivial_lines_are_skipped_with_their_reason(tmp_path):
    cell = nbformat.v4.new_code_cell(CELL_WITH_REGION)
    public = nbformat.v4.new_code_cell("R = Rz\nanswer_x = None")
    nbformat.write(nbformat.v4.new_notebook(cells=[public, cell]), _mkdir(tmp_path) / "01.ipynb")
    found = leak_gate.collect_needles(tmp_path)
    assert set(found.lines) == {
        "helper_value = sp.Rational(42, 17) * omega_hat",
        "answer_x = helper_value.T @ np.eye(3)  # the transpose",
        "answer_x = helper_value.T @ np.eye(3)",
        "helper_value.T @ np.eye(3)",
    }
    assert found.skipped == {"punctuation": 1, "blank": 1, "short": 1}
    assert found.regions == 1


def test_worked_solutions_of_tools_solutions_are_read_without_running_them(tmp_path):
    (tmp_path / "instructor" / "answers").mkdir(parents=True)
    (tmp_path / "instructor" / "answers" / "ch09.py").write_text(
        'raise SystemExit("never run")\nSOLUTIONS = {"e": """\\nanswer_e = sp.sqrt(17) / 4"""}\n'
    )
    found = leak_gate.collect_needles(tmp_path)
    assert found.lines["answer_e = sp.sqrt(17) / 4"] == "instructor/answers/ch09.py exercise e"


def _mkdir(root):
    (root / "notebooks").mkdir(exist_ok=True)
    return root / "notebooks"


# ------------------------------------------------------------------------------ planted leaks


def test_planted_leak_in_a_file_of_the_edition_names_file_and_line(copy, needles):
    line = a_solution_line(needles)
    target = copy / "student" / "course_lib" / "so3.py"
    text = target.read_text().splitlines()
    text.insert(9, f"# {line}")
    target.write_text("\n".join(text) + "\n")
    hits = _gate(copy / "student", copy / "dist", copy / "site", needles)
    assert any(h.startswith("student/course_lib/so3.py:10: solution line of ") for h in hits), hits


def test_regression_an_executed_problem_set_with_right_answer_records_is_found(copy, needles):
    """An executed instructor problem set holds, in each check cell's output, the record of the
    worked answer (sympy srepr): shipping one gives the answers away without a solution line."""
    executed = ROOT / "problem_sets" / "ps03_exponential_coordinates.ipynb"
    target = copy / "student" / "problem_sets" / executed.name
    target.write_bytes(executed.read_bytes())
    hits = _gate(copy / "student", copy / "dist", copy / "site", needles)
    assert any(f"{executed.name}:" in h and "record of a right answer" in h for h in hits), hits


def test_planted_leak_only_in_the_history_is_found(copy, needles):
    student = copy / "student"
    (student / "scratch.py").write_text(a_solution_line(needles) + "\n")
    _git(student, "add", "scratch.py")
    _git(student, "commit", "-q", "-m", "scratch")
    _git(student, "rm", "-q", "scratch.py")
    _git(student, "commit", "-q", "-m", "remove scratch")
    assert not (student / "scratch.py").exists()
    hits = _gate(student, copy / "dist", copy / "site", needles)
    assert any("history" in h and "scratch.py:1:" in h for h in hits), hits


def test_planted_leak_in_the_wheel_is_found(copy, needles):
    (wheel,) = (copy / "dist").glob("*.whl")
    with zipfile.ZipFile(wheel, "a") as zf:
        zf.writestr("course_lib/extra.py", '"""Help."""\n\nX = 1\n' + a_solution_line(needles))
    hits = _gate(copy / "student", copy / "dist", copy / "site", needles)
    assert any(f"{wheel.name}!course_lib/extra.py:4:" in h for h in hits), hits


def test_planted_leak_in_highlighted_code_of_a_site_page_is_found(copy, needles):
    line = "answer_hat_fifth = n2**2 * W"
    assert line in needles.lines
    spans = '<span class="n">answer_hat_fifth</span> <span class="o">=</span> ' + (
        '<span class="n">n2</span><span class="o">**</span><span class="mi">2</span> '
        '<span class="o">*</span> <span class="n">W</span>'
    )
    (copy / "site" / "03.html").write_text(f"<html><body>\n<pre>{spans}</pre>\n</body></html>")
    hits = _gate(copy / "student", copy / "dist", copy / "site", needles)
    assert any(h.startswith("site/03.html:2: solution line of ") for h in hits), hits


def test_regression_an_answer_expression_in_a_docstring_is_found(copy, needles):
    """Issue 16: help(course_lib.exercises) showed the answer to 3.3 in a sentence."""
    lines = [line for line in needles.lines if line.startswith("answer_") and "  #" not in line]
    expression = max((line.split("=", 1)[1].strip() for line in lines), key=len)
    assert expression in needles.lines
    target = copy / "student" / "course_lib" / "exercises" / "__init__.py"
    target.write_text(target.read_text() + f'\n"""For example `{expression}` is accepted."""\n')
    hits = _gate(copy / "student", copy / "dist", copy / "site", needles)
    assert any("course_lib/exercises/__init__.py" in h and expression in h for h in hits), hits


def test_planted_markers_and_a_solutions_folder_are_found(copy, needles):
    nb = copy / "student" / "notebooks" / "x.ipynb"
    cell = nbformat.v4.new_code_cell("x = None\n### BEGIN SOLUTION\nx = 1\n### END SOLUTION")
    nbformat.write(nbformat.v4.new_notebook(cells=[cell]), nb)
    (copy / "site" / "solutions").mkdir()
    (copy / "site" / "solutions" / "ch01.html").write_text("<p>nothing</p>")
    hits = _gate(copy / "student", copy / "dist", copy / "site", needles)
    assert any("notebooks/x.ipynb" in h and "'BEGIN SOLUTION'" in h for h in hits), hits
    assert any(h == "site/solutions: a solutions folder" for h in hits), hits


def test_a_class_roster_in_the_edition_is_found(copy, needles):
    """Issue 33: the roster maps every student's ids; it stays with the instructor."""
    export = 'Student,ID,SIS User ID,SIS Login ID,Section\n"Seven, Alice",1,3031042,alice7,A\n'
    (copy / "student" / "problem_sets" / "class.csv").write_text(export)
    (copy / "site" / "roster.csv").write_text("alice7@example.edu,alice7\n")
    hits = _gate(copy / "student", copy / "dist", copy / "site", needles)
    assert any(h.startswith("student/problem_sets/class.csv: a class roster") for h in hits), hits
    assert any(h.startswith("site/roster.csv: a class roster") for h in hits), hits


def test_the_command_line_fails_and_lists_the_hits(copy, needles, capsys):
    (copy / "site" / "leak.txt").write_text(a_solution_line(needles))
    status = leak_gate.main([str(ROOT), *(str(copy / p) for p in ("student", "dist", "site"))])
    out = capsys.readouterr().out
    assert status == 1 and "  LEAK site/leak.txt:1: solution line of " in out
    assert out.startswith("leak gate: ") and out.splitlines()[0].endswith(": 1 hits")


def test_regression_every_package_of_course_lib_is_in_the_wheel():
    # course_lib.interactive became a package and the wheel's explicit package list missed it:
    # in the Colab run the chapter's explorer cells failed (ModuleNotFoundError)
    import tomllib

    listed = set(
        tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["packages"]
    )
    found = {
        ".".join(p.parent.relative_to(ROOT).parts)
        for p in (ROOT / "course_lib").rglob("__init__.py")
        if "__pycache__" not in p.parts
    }
    assert found == listed
