"""`make test` lints too: ruff check and ruff format --check over the paths of `make lint`.

Those are the Python sources and the notebooks: ruff reads the code cells of .ipynb files
itself (magics such as ``%config`` are understood), so the notebooks follow the same rules.
Their generated cells are ruff-clean at the source (instructor/build/notebooks.py,
instructor/build/sync_exercises.py;
tests/test_exercises_sync.py checks them on their own).

The paths come from the Makefile's ``LINT_PATHS`` line, so `make lint` and this test always
look at the same files; the rules are pyproject.toml's ``[tool.ruff]``. Both commands take
well under a second. A failure shows ruff's own report: run `make lint` to see it again, and
`.venv/bin/ruff check --fix` / `.venv/bin/ruff format` on the files it names to fix them.
"""

import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def lint_paths():
    """The existing paths of the Makefile's ``LINT_PATHS := ...`` line."""
    makefile = (ROOT / "Makefile").read_text()
    found = re.search(r"^LINT_PATHS\s*:=\s*(.+)$", makefile, flags=re.MULTILINE)
    assert found, "the Makefile has no `LINT_PATHS := ...` line for `make lint`"
    paths = [p for p in found.group(1).split() if (ROOT / p).exists()]
    assert paths, f"none of LINT_PATHS exists: {found.group(1)}"
    return paths


@pytest.mark.parametrize(
    "command",
    [
        ["check", "--no-cache", "--output-format", "concise"],
        ["format", "--check", "--no-cache", "--output-format", "concise"],
    ],
    ids=["ruff check", "ruff format --check"],
)
def test_the_sources_pass_ruff(command):
    run = subprocess.run(
        [sys.executable, "-m", "ruff", *command, *lint_paths()],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=120,
    )
    if run.returncode != 0:
        report = (run.stdout + run.stderr).strip()
        pytest.fail(f"`ruff {' '.join(command)}` found problems:\n{report}", pytrace=False)
