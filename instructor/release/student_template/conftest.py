"""pytest hooks of the student edition.

Every notebook cell that nbval runs is a ``notebook_exec`` test (``-m "not notebook_exec"``
skips them all). A cell you have not solved yet stops with ``NotImplementedError`` (its stub):
that is expected, and the test checks that it stops for that reason and no other. A check cell
may fail with its verdict (no answer yet, or a hint), never because the notebook is broken (a
name or an import that is missing). Every other cell must run without an error and, where the
notebook stores outputs, give the same outputs. A kernel that dies as it starts is started
a second time (``tests/nbval_kernel.py``), and a second death says what the kernel printed.
"""

import pytest

pytest_plugins = ["tests.nbval_kernel"]

STUB = "raise NotImplementedError("
BROKEN = {"NameError", "SyntaxError", "ImportError", "ModuleNotFoundError", "AttributeError"}


def _expected_stop(cell):
    """Why ``cell`` may stop: 'stub', 'check' or None (it must run through)."""
    if STUB in cell.source:
        return "stub"
    if cell.get("metadata", {}).get("nbgrader", {}).get("grade"):
        return "check"
    return None


def _expect_stop(item, kind):
    run = item.runtest

    def runtest():
        run()
        errors = [o for o in item.test_outputs if o.get("output_type") == "error"]
        names = [e["ename"] for e in errors]
        if kind == "stub" and names != ["NotImplementedError"]:
            raise AssertionError(f"an unsolved exercise should stop at its stub, got {names}")
        if kind == "check" and set(names) & BROKEN:
            raise AssertionError(f"a check cell should fail only with its verdict, got {names}")

    item.options["check_exception"] = True
    item.runtest = runtest


def pytest_collection_modifyitems(items):
    for item in items:
        if type(item).__name__ == "IPyNbCell":  # nbval's item class
            item.add_marker(pytest.mark.notebook_exec)
            kind = _expected_stop(item.cell)
            if kind:
                _expect_stop(item, kind)
