"""The student edition: a repository of its own that students clone (``make release``).

Built from the instructor's tree into ``build/release/student/``:

* ``notebooks/`` and ``problem_sets/`` (when there): every solution region replaced by its stub
  (:func:`instructor.build.student.student_notebook`); a chapter keeps the outputs of its reading
  part (strict nbval compares them), every cell from the first nbgrader cell on is cleared;
* ``course_lib/`` (all of it: the instructor's tools are in the ``instructor`` package);
* ``tests/``: the test files that need no instructor tool and name no exercise or answer
  (:func:`student_tests` says which are left out and why), with ``conftest.py`` and the nbval
  sanitizer;
* its own README, Makefile (``make lab``, ``make test``), conftest.py, .gitignore and
  ``requirements-test.txt`` (from ``instructor/release/student_template/``), the student's
  environment, ``binder/``, ``pyproject.toml`` (its pytest paths: tests, course_lib, the notebooks)
  and the licence;
* a fresh git repository, branch ``student`` (the branch the launch links open), one commit.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import nbformat

from instructor.build import course_links
from instructor.build.student import student_notebook

ROOT = Path(__file__).resolve().parents[2]
TEMPLATE = Path(__file__).resolve().with_name("student_template")

NOTEBOOK_DIRS = ("notebooks", "problem_sets")
# requirements-test.txt, the instructor's pins; pytest-xdist (and its execnet): two workers
TEST_TOOLS = ("pytest", "hypothesis", "nbval", "scipy", "pytest-xdist", "execnet")
# A test file that matches is left out, for the reason in the group's name.
INSTRUCTOR_TEST = re.compile(
    r"(?P<tool>\bnbgrader\b|\bgrader\b|playwright|\bruff\b|\btools\b|\be2e\b|\"site\""
    r"|\binstructor(?=[./]\w| import\b)|course_lib\.student|import student\b)"
    r"|(?P<answers>course_lib\.exercises|exercise_bank|import exercises\b|\banswer_[a-z]"
    r"|solutions\b|SOLUTIONS)"
)
BRANCH = course_links.STUDENT_BRANCH


def student_tests(tests_dir):
    """([files kept], {file name: why left out}) of ``tests_dir``: test files, their helper
    modules (``conftest.py``, ``plotting_helpers.py``, ...) and data files (``*.cfg``)."""
    kept, left_out = [], {}
    files = [p for p in sorted(Path(tests_dir).iterdir()) if p.is_file()]
    for path in files:
        if path.suffix != ".py":
            kept.append(path.name)
            continue
        m = INSTRUCTOR_TEST.search(path.read_text(encoding="utf-8"))
        if m is None:
            kept.append(path.name)
        elif m.group("tool"):
            left_out[path.name] = f"needs an instructor tool ({m.group('tool')})"
        else:
            left_out[path.name] = f"names exercises or their answers ({m.group('answers')!r})"
    return kept, left_out


def _notebooks(root, out):
    count = 0
    for folder in NOTEBOOK_DIRS:
        for path in sorted((root / folder).glob("*.ipynb")):
            nb = nbformat.read(path, as_version=4)
            copy = student_notebook(nb, f"{folder}/{path.name}", keep_outputs=True)
            (out / folder).mkdir(exist_ok=True)
            nbformat.write(copy, out / folder / path.name)
            count += 1
    return count


def _pins(path, names):
    lines = path.read_text(encoding="utf-8").splitlines()
    pins = [line.split("#")[0].strip() for line in lines]
    return [pin for pin in pins if pin.split("==")[0] in names]


def _pyproject(root, out):
    text = (root / "pyproject.toml").read_text(encoding="utf-8")
    folders = ("tests", "course_lib", *NOTEBOOK_DIRS)
    paths = ", ".join(f'"{p}"' for p in folders if (out / p).is_dir())
    text, n = re.subn(r"^testpaths = \[.*\]$", f"testpaths = [{paths}]", text, flags=re.M)
    if n != 1:
        raise RuntimeError("pyproject.toml: no testpaths line to rewrite")
    return text


def _readme(url, chapters):
    text = (TEMPLATE / "README.md").read_text(encoding="utf-8")
    if url is None:
        ask = "Your instructor gives you the link."
        subs = {"@HUB@": "", "@BINDER@": ask, "@COLAB@": ask, "@REPO@": "COURSE_REPOSITORY_URL"}
    else:
        colab = [course_links.colab_url(url, name, BRANCH) for name in chapters]
        subs = {
            "@HUB@": "",
            "@BINDER@": f"[Open on Binder]({course_links.binder_url(url, BRANCH)}).",
            "@COLAB@": " ".join(f"[{n[:2]}]({c})" for n, c in zip(chapters, colab) if c)
            or "Colab opens notebooks from GitHub only; use Binder.",
            "@REPO@": url,
        }
    for key, value in subs.items():
        text = text.replace(key, value)
    return text


def _git(out, *args):
    subprocess.run(["git", "-C", str(out), *args], check=True, capture_output=True)


def _commit(out, source_rev):
    _git(out, "init", "-q", "-b", BRANCH)
    _git(out, "add", "-A")
    _git(
        out,
        "-c",
        "user.name=rotations-course release",
        "-c",
        "user.email=release@rotations-course.invalid",
        "commit",
        "-q",
        "-m",
        f"Student edition of rotations-course {source_rev}",
    )


def _source_rev(root):
    run = subprocess.run(
        ["git", "-C", str(root), "rev-parse", "--short", "HEAD"], capture_output=True, text=True
    )
    return run.stdout.strip() or "(not a git checkout)"


def build_student_edition(root, out):
    """Write the student edition of the instructor tree ``root`` into ``out`` (replaced)."""
    root, out = Path(root), Path(out)
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    ignore = shutil.ignore_patterns("__pycache__", "*.pyc")
    shutil.copytree(root / "course_lib", out / "course_lib", ignore=ignore)
    shutil.copytree(root / "binder", out / "binder", ignore=ignore)
    notebooks = _notebooks(root, out)
    kept, left_out = student_tests(root / "tests")
    (out / "tests").mkdir()
    for name in kept:
        shutil.copy(root / "tests" / name, out / "tests" / name)
    for name in ("Makefile", "conftest.py"):
        shutil.copy(TEMPLATE / name, out / name)
    shutil.copy(TEMPLATE / "gitignore", out / ".gitignore")
    for name in ("LICENSE", "environment-student.txt"):
        shutil.copy(root / name, out / name)
    tools = _pins(root / "environment.txt", TEST_TOOLS)
    (out / "requirements-test.txt").write_text(
        "# `make test` installs these on top of environment-student.txt (the instructor's pins)\n"
        + "\n".join(tools)
        + "\n",
        encoding="utf-8",
    )
    (out / "pyproject.toml").write_text(_pyproject(root, out), encoding="utf-8")
    chapters = sorted(p.name for p in (out / "notebooks").glob("[0-9]*.ipynb"))
    url = course_links.repository_url(root / "pyproject.toml")
    (out / "README.md").write_text(_readme(url, chapters), encoding="utf-8")
    _commit(out, _source_rev(root))
    tests = [name for name in kept if name.startswith("test_")]
    return {"notebooks": notebooks, "tests": tests, "left_out": left_out}
