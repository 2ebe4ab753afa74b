"""Optional system tools (issue 24): without npm or Chromium the commands that need them say
which tool is missing and how to install it, and exit non-zero (never a traceback); CI turns
every skip for a missing tool into a failure.
"""

from __future__ import annotations

import importlib.util
import os
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BIN = Path(sys.executable).parent


def venv_only_env():
    """The environment with a PATH of the venv's programs only: no npm, no bwrap."""
    env = {k: v for k, v in os.environ.items() if not k.endswith("_REQUIRED")}
    return {**env, "PATH": str(BIN)}


def test_regression_site_build_without_npm_names_npm_instead_of_a_traceback(tmp_path):
    code = (
        "from instructor.build import website as build; "
        f"build.DEPS = __import__('pathlib').Path({str(tmp_path)!r}); build.install_scripts()"
    )
    done = subprocess.run(
        [sys.executable, "-c", code],
        cwd=ROOT,
        env=venv_only_env(),
        capture_output=True,
        text=True,
    )
    assert done.returncode != 0
    assert "Traceback" not in done.stderr, done.stderr
    assert "npm not found on PATH" in done.stderr and "apt-get install npm" in done.stderr
    assert list(tmp_path.iterdir()) == []  # nothing half-installed


def test_ci_makes_every_missing_tool_a_failure():
    """.ci/run sets the *_REQUIRED variable of every tool the root conftest.py can skip for."""
    spec = importlib.util.spec_from_file_location("root_conftest", ROOT / "conftest.py")
    root_conftest = sys.modules[spec.name] = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(root_conftest)
    ci = (ROOT / ".ci" / "run").read_text()
    for tool in root_conftest.TOOLS.values():
        assert re.search(rf"^export .*\b{tool.required_by}=1\b", ci, re.MULTILINE), tool.what


def test_a_test_using_the_browser_fixture_is_marked_browser():
    """site/test_site.py's tests that open Chromium (through its ``browser`` fixture) carry the
    ``browser`` marker, so without Chromium they are skipped with the one summary line."""
    done = subprocess.run(
        [sys.executable, "-m", "pytest", "--collect-only", "-q", "-m", "browser",
         "site/test_site.py", "-p", "no:cacheprovider"],
        cwd=ROOT, capture_output=True, text=True,
    )  # fmt: skip
    collected = [line for line in done.stdout.splitlines() if "::" in line]
    assert any("test_markdown_tables_are_tables" in line for line in collected), done.stdout
    assert not any("test_instructor_banner" in line for line in collected), done.stdout
