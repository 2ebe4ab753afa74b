"""Root pytest hooks.

- Every strict-nbval cell is a ``notebook_exec`` test: nbval collects each notebook cell as a
  test item without markers, so ``-m 'not notebook_exec'`` used to keep all of them; with the
  marker added here it deselects notebook execution whole.
- A test that needs a system tool the machine may lack carries its marker (:data:`TOOLS`:
  ``confined`` for bubblewrap, ``privdrop`` for root and python3-seccomp (Docker's seccomp
  constraint, tests/docker_seccomp.py), ``browser`` for Chromium, ``npm``). Without the tool
  the test is skipped and the run ends with one line per tool: how many were skipped, why,
  and the command that installs it. With the tool's ``*_REQUIRED=1`` variable set (``.ci/run``
  sets all three; ``privdrop`` shares ``CONFINED_REQUIRED``) a missing tool fails those tests
  instead.
- nbval starts each notebook's kernel once, its stderr thrown away: a kernel that dies while it
  starts (two pytest workers can be handed the same free port by the system: the kernel
  cannot bind it and exits) failed every cell of that notebook with "Kernel died before
  replying to kernel_info" and no reason. The plugin ``tests/nbval_kernel.py`` keeps the
  kernel's stderr and starts it a second time; a second death fails with what it printed.
- The tests run as the course's example student (``COURSE_STUDENT_ID`` is ``"(example)"``,
  the default numbers of every exercise, as in the instructor's solved copies): the exercises'
  numbers depend on the student id (``course_lib/exercises/_identity.py``), a JupyterHub sets
  ``JUPYTERHUB_USER`` in every server, and a check on an exercise with variants refuses to
  pass without an id. A test of "no id" removes the variable itself (monkeypatch).
"""

from __future__ import annotations

import os
import shutil
from dataclasses import dataclass
from functools import cache

import pytest

for _id in ("JUPYTERHUB_USER", "COURSE_GRADER_ID"):
    os.environ.pop(_id, None)
os.environ["COURSE_STUDENT_ID"] = "(example)"  # course_lib.exercises._identity.EXAMPLE_ID

pytest_plugins = ["tests.nbval_kernel"]


@dataclass(frozen=True)
class Tool:
    what: str  # the tool, as a person names it
    needed_for: str
    install: str
    required_by: str  # the environment variable that turns a skip into a failure

    def skip_reason(self, problem):
        return f"needs {self.what} ({self.needed_for}): {problem}"


TOOLS = {
    "confined": Tool(
        "bubblewrap (bwrap)",
        "the confined kernel that grades students' code",
        "sudo apt-get install bubblewrap (Debian/Ubuntu; Fedora: sudo dnf install bubblewrap; "
        "Linux only)",
        "CONFINED_REQUIRED",
    ),
    "privdrop": Tool(
        "root and libseccomp's Python bindings for /usr/bin/python3 (python3-seccomp)",
        "the privilege-drop confinement under Docker's seccomp constraint",
        "sudo apt-get install python3-seccomp (Debian/Ubuntu), and run the tests as root",
        "CONFINED_REQUIRED",
    ),
    "browser": Tool(
        "Chromium (/usr/bin/chromium)",
        "the tests in a real browser",
        "sudo apt-get install chromium",
        "BROWSER_REQUIRED",
    ),
    "npm": Tool("npm", "the website's MathJax", "sudo apt-get install npm", "NPM_REQUIRED"),
}


@cache
def missing(marker):
    """Why the tool of ``marker`` cannot be used here, or None when it can."""
    if marker == "confined":
        return _confinement_problem()
    if marker == "privdrop":
        return _privdrop_problem()
    if marker == "browser":
        return None if os.access("/usr/bin/chromium", os.X_OK) else "/usr/bin/chromium not found"
    if marker == "npm":
        return None if shutil.which("npm") else "npm not found on PATH"
    raise KeyError(marker)


def _confinement_problem():
    try:
        from instructor.grading.sandbox import bubblewrap_problem
    except ImportError:  # the student edition has no instructor/grading/
        return "the instructor package (instructor/grading/) is not here"
    return bubblewrap_problem()


def _privdrop_problem():
    import subprocess

    if os.geteuid() != 0:
        return "the tests are not run as root"
    if shutil.which("unshare") is None:
        return "unshare (util-linux) not found"
    probe = ["/usr/bin/python3", "-c", "import seccomp"]
    try:
        done = subprocess.run(probe, capture_output=True, text=True, timeout=60)
    except OSError as err:
        return f"/usr/bin/python3: {err}"
    return None if done.returncode == 0 else "python3-seccomp is not installed"


def pytest_configure(config):
    for name, tool in TOOLS.items():
        config.addinivalue_line("markers", f"{name}: {tool.skip_reason('...')}")


def pytest_collection_modifyitems(items):
    for item in items:
        if type(item).__name__ == "IPyNbCell":  # nbval's item class
            item.add_marker(pytest.mark.notebook_exec)
        if "browser" in getattr(item, "fixturenames", ()):  # the site tests' Chromium fixture
            item.add_marker(pytest.mark.browser)


def pytest_runtest_setup(item):
    for name, tool in TOOLS.items():
        if item.get_closest_marker(name) is None:
            continue
        problem = missing(name)
        if problem is None:
            continue
        if os.environ.get(tool.required_by) == "1":
            pytest.fail(f"{tool.required_by}=1, but this test {tool.skip_reason(problem)}")
        pytest.skip(tool.skip_reason(problem))


def pytest_terminal_summary(terminalreporter):
    skipped = terminalreporter.stats.get("skipped", [])
    for tool in TOOLS.values():
        prefix = f"needs {tool.what} "
        count = sum(prefix in str(getattr(r, "longrepr", "")) for r in skipped)
        if count:
            terminalreporter.write_line(
                f"{count} tests skipped: they need {tool.what} for {tool.needed_for}, which "
                f"is missing here; install it with: {tool.install} "
                f"(set {tool.required_by}=1 to make this a failure)",
                yellow=True,
                bold=True,
            )
