"""The engines of ``make a11y`` (e2e/a11y_engines.py, e2e/a11y.py), judged without a browser:
pinned exactly by the project, each with its runner; what is missing said with how to install it."""

import json
from pathlib import Path

import a11y
import a11y_engines as engines
import pytest

ROOT = Path(__file__).resolve().parents[1]


def test_every_engine_is_pinned_to_one_version_in_the_projects_package_json_and_lock():
    package = json.loads((engines.PACKAGE / "package.json").read_text())
    pinned = engines.versions()
    assert set(pinned) == {"axe", "ibm", "htmlcs"}
    for name, (npm, *_rest) in engines.ENGINES.items():
        assert package["dependencies"][npm] == pinned[name]  # exact: no ^ or ~ range
        assert pinned[name][0].isdigit()


def test_every_engine_has_its_page_script():
    for name, (_, _, runner, glob) in engines.ENGINES.items():
        text = (ROOT / "e2e" / "js" / f"{runner}.js").read_text()
        assert glob in text, name
    assert "'WCAG_2_1'" in (ROOT / "e2e" / "js" / "ace_run.js").read_text()
    assert "'WCAG2AA'" in (ROOT / "e2e" / "js" / "htmlcs_run.js").read_text()


def test_missing_npm_is_named_with_the_command_that_installs_it(monkeypatch):
    monkeypatch.setattr(a11y.shutil, "which", lambda name: None)
    monkeypatch.setattr(a11y, "CHROMIUM", Path("/nonexistent/chromium"))
    problems = a11y.missing_tools(need_npm=True)
    assert any("chromium" in p and "apt-get install chromium" in p for p in problems)
    assert any("npm is missing" in p and "apt-get install npm" in p for p in problems)
    assert a11y.main(["--no-lab", "--no-site"]) == 2


class _Page:
    def __init__(self, nodes):
        self.nodes = nodes

    def evaluate(self, script, *args):
        return self.nodes


@pytest.mark.parametrize("nodes, runs_ibm", [(900, True), (40_000, False)])
def test_ibm_is_left_out_only_on_pages_bigger_than_asked(nodes, runs_ibm):
    names, why = a11y._engines_for(_Page(nodes), ["axe", "ibm", "htmlcs"], 15_000)
    assert ("ibm" in names) is runs_ibm and ("ibm skipped" in why) is not runs_ibm
    assert a11y._engines_for(_Page(nodes), ["axe", "ibm"], None)[0] == ["axe", "ibm"]
