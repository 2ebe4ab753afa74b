"""The three accessibility engines ``make a11y`` runs on every page, pinned and served locally.

* **axe-core** (Deque), rules tagged ``wcag2a, wcag2aa, wcag21a, wcag21aa``;
* **IBM Equal Access** (``accessibility-checker-engine``'s ``ace.js``), policy ``WCAG_2_1``;
* **HTML_CodeSniffer** (``html_codesniffer``'s ``HTMLCS.js``), standard ``WCAG2AA``: pa11y's
  engine, run directly (pa11y's CLI drives a Chromium that puppeteer downloads itself, which a
  machine without access to Google's download server cannot get; pa11y does no more than inject
  HTMLCS.js, run ``HTMLCS.process`` and report its errors, which is what this does).

Their versions are pinned in ``e2e/engines/package.json`` and its lock file, installed with
``npm ci`` into ``build/a11y-deps/`` on first use (again when the lock file changes) and injected
into each page from those files (Playwright ``add_script_tag(path=)``): nothing is fetched at run
time. Each runner (``e2e/js/*_run.js``) returns ``{"violations": [...], "incomplete": [...]}``,
each rule with its nodes sorted into the course's ``content`` and the page's ``chrome``.
"""

import filecmp
import json
import shutil
import subprocess
import time

from a11y_rules import WCAG_TAGS
from common import HERE, ROOT, js

PACKAGE = HERE / "engines"
DEPS = ROOT / "build" / "a11y-deps"
MODULES = DEPS / "node_modules"
#: name -> (npm package, the script injected into the page, its runner in e2e/js, the global)
ENGINES = {
    "axe": ("axe-core", "axe.min.js", "axe_run", "axe"),
    "ibm": ("accessibility-checker-engine", "ace.js", "ace_run", "ace"),
    "htmlcs": ("html_codesniffer", "build/HTMLCS.js", "htmlcs_run", "HTMLCS"),
}
#: what each engine checks, for the tables
POLICY = {"axe": ",".join(WCAG_TAGS), "ibm": "WCAG_2_1", "htmlcs": "WCAG2AA"}


def versions():
    """name -> the pinned version, read from the lock file."""
    lock = json.loads((PACKAGE / "package-lock.json").read_text())
    return {k: lock["packages"][f"node_modules/{p}"]["version"] for k, (p, *_) in ENGINES.items()}


def script(name):
    package, path, _, _ = ENGINES[name]
    return MODULES / package / path


def installed():
    """Whether every engine is in build/a11y-deps/ at the versions of the lock file."""
    lock = DEPS / "package-lock.json"
    return (
        lock.is_file()
        and filecmp.cmp(lock, PACKAGE / "package-lock.json", shallow=False)
        and all(script(n).is_file() for n in ENGINES)
    )


def install():
    """``npm ci`` of e2e/engines/ into build/a11y-deps/ unless already there."""
    if installed():
        return
    DEPS.mkdir(parents=True, exist_ok=True)
    for name in ("package.json", "package-lock.json"):
        shutil.copy(PACKAGE / name, DEPS / name)
    subprocess.run(["npm", "ci", "--no-audit", "--no-fund"], cwd=DEPS, check=True)


def run(page, name, content, not_content=None):
    """Engine ``name``'s result on ``page``, its nodes sorted into content / chrome."""
    _, _, runner, glob = ENGINES[name]
    if not page.evaluate(f"typeof window.{glob} !== 'undefined'"):
        page.add_script_tag(path=str(script(name)))
    if name == "axe":
        return page.evaluate(js(runner), [content, WCAG_TAGS, not_content])
    return page.evaluate(js(runner), [content, not_content])


def run_all(page, content, not_content=None, names=tuple(ENGINES)):
    """name -> result, for every engine of ``names``; each result has its ``seconds``."""
    out = {}
    for n in names:
        start = time.monotonic()
        out[n] = run(page, n, content, not_content)
        out[n]["seconds"] = time.monotonic() - start
    return out


def timing(results):
    """ "axe 1.2 s, ibm 3.4 s, ..." for the log."""
    return ", ".join(f"{n} {r['seconds']:.1f} s" for n, r in results.items())
