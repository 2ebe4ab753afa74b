"""The layout the architecture promises (docs/architecture.md, issue 36), checked in the sources.

- The grader uses the checker's public API only: nothing under ``instructor/grading`` imports a
  private module or name of ``course_lib`` (a leading underscore).
- No path tricks: no ``sys.path`` edit or load by file path outside the tests, except the two
  places named in :data:`PATH_EDITS`, and no ``noqa: E402``.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SOURCES = ("course_lib", "instructor", "benchmarks", "e2e", "site")

#: The sys.path edits kept on purpose, and why.
PATH_EDITS = {
    # the set-up cell of every notebook finds the repository's course_lib from where it runs
    "instructor/build/notebooks.py": 1,
    # the nbgrader_config.py that `make course` writes imports instructor.grading from there
    "instructor/grading/course.py": 1,
    # the confined kernel's start: drops '' and '.' from sys.path (removes, never adds)
    "instructor/grading/sandbox.py": 1,
}


def _python_files(*folders):
    for folder in folders:
        yield from sorted((ROOT / folder).rglob("*.py"))


def _private(module, names=()):
    parts = module.split(".")
    return any(p.startswith("_") for p in parts) or any(n.startswith("_") for n in names)


def private_imports(path):
    """``(line, text)`` of each import of a private module or name of course_lib in ``path``."""
    out = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            mod, names = node.module, [a.name for a in node.names]
            if mod.split(".")[0] == "course_lib" and _private(mod, names):
                out.append((node.lineno, f"from {mod} import {', '.join(names)}"))
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.split(".")[0] == "course_lib" and _private(alias.name):
                    out.append((node.lineno, f"import {alias.name}"))
    return out


@pytest.mark.parametrize(
    "path",
    list(_python_files("instructor/grading")),
    ids=lambda p: str(p.relative_to(ROOT)),
)
def test_the_grader_imports_only_the_checkers_public_api(path):
    assert private_imports(path) == []


def test_the_private_import_finder_finds_each_spelling(tmp_path):
    src = tmp_path / "x.py"
    src.write_text(
        "from course_lib.exercises import _engine as E\n"
        "from course_lib.exercises._reading import read_answer\n"
        "import course_lib._verdict\n"
        "from course_lib.exercises import compare, check\n"
        "from course_lib.exercises.compare import read\n"
    )
    assert [line for line, _ in private_imports(src)] == [1, 2, 3]


def test_no_path_tricks_outside_the_tests():
    found, e402 = {}, []
    for path in _python_files(*SOURCES):
        rel = str(path.relative_to(ROOT))
        text = path.read_text(encoding="utf-8")
        tree = ast.parse(text)
        for node in ast.walk(tree):
            if isinstance(node, ast.Attribute) and node.attr in (
                "spec_from_file_location",
                "SourceFileLoader",
            ):
                found.setdefault(rel, []).append(node.lineno)
        edits = [n for n in text.splitlines() if "sys.path" in n and not n.lstrip().startswith("#")]
        edits = [n for n in edits if "``" not in n]  # a docstring naming it
        if len(edits) > PATH_EDITS.get(rel, 0):
            found.setdefault(rel, []).extend(edits)
        if "noqa: E402" in text:
            e402.append(rel)
    assert found == {} and e402 == []
