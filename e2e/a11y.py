"""Accessibility (WCAG 2.1 AA) of the course: axe-core in headless Chromium (``make a11y``).

    python e2e/a11y.py [--site DIR ...] [--lab PATH ...] [--no-lab] [--no-site]

1. axe-core, pinned (:data:`AXE`), is installed from npm into ``build/a11y-deps/`` on first use
   and injected into every page from that local file: nothing is fetched at run time.
2. Every page of each built site (default: ``build/site`` and ``build/site-instructor``, the
   student and instructor editions, served from a loopback server) is loaded, typeset by its
   own MathJax, and checked with axe's ``wcag2a, wcag2aa, wcag21a, wcag21aa`` rules; the page
   body (``div.body``) is the course's content, the rest (sidebar, footer) the theme's chrome.
3. Every chapter and problem set is opened in JupyterLab (e2e's :class:`run_e2e.Lab`: its own
   server, copy and profile), run, scrolled through so that every cell is rendered, and checked
   the same way; the notebook's outputs (figures, widgets, text) and rendered markdown are the
   course's content, the rest (the cell editors, the fold buttons, menus) JupyterLab's own
   chrome, reported apart.
4. Besides axe: the page language, one h1, headings without a skipped level and meaningful link
   text (:mod:`a11y_rules`), on the site's pages.

Prints a table per page (violations and incomplete checks, content / chrome) and exits 1 on any
violation in the course's content (or a structure problem); 0 otherwise. Without Chromium or
npm it says which is missing and how to install it, and exits 2.
"""

import argparse
import functools
import http.server
import shutil
import subprocess
import sys
import threading
from pathlib import Path

from a11y_rules import WCAG_TAGS, structure_problems
from common import ROOT, CheckFailed, KernelStalled, js, log

AXE = "axe-core@4.10.3"
DEPS = ROOT / "build" / "a11y-deps"
AXE_JS = DEPS / "node_modules" / "axe-core" / "axe.min.js"
CHROMIUM = Path("/usr/bin/chromium")
SITES = [ROOT / "build" / "site", ROOT / "build" / "site-instructor"]
SITE_CONTENT = "div.body"
# The notebook's own content in JupyterLab: its outputs (figures, widgets, text) and its rendered
# markdown. The cell editor (CodeMirror's textbox) and the heading fold button are JupyterLab's.
LAB_CONTENT = ".jp-OutputArea-output, .jp-RenderedMarkdown"
LAB_NOT_CONTENT = ".jp-collapseHeadingButton, .cm-editor"


def missing_tools(need_npm):
    """What is missing to run the checks, each with how to install it."""
    out = []
    if not CHROMIUM.exists():
        out.append(f"{CHROMIUM} is missing: install it with `sudo apt-get install chromium`")
    if need_npm and shutil.which("npm") is None:
        out.append("npm is missing (it installs axe-core): `sudo apt-get install npm`")
    return out


def install_axe():
    if not AXE_JS.is_file():
        cmd = ["npm", "install", "--no-save", "--no-audit", "--no-fund", "--prefix", str(DEPS)]
        subprocess.run([*cmd, AXE], check=True)
    return AXE_JS


def run_axe(page, content, not_content=None):
    """axe's WCAG A/AA results on ``page``, its nodes sorted into content / chrome."""
    if not page.evaluate("typeof window.axe !== 'undefined'"):
        page.add_script_tag(path=str(AXE_JS))
    return page.evaluate(js("axe_run"), [content, WCAG_TAGS, not_content])


def count(rules, where):
    return sum(1 for r in rules for n in r["nodes"] if n["where"] == where)


def row(name, result, extra=()):
    v, i = result["violations"], result["incomplete"]
    return [
        name,
        count(v, "content"),
        count(v, "chrome"),
        count(i, "content"),
        count(i, "chrome"),
        list(extra),
    ]


def print_table(title, rows):
    log(f"{title}")
    log(f"  {'page':<46} {'violations':>10} {'(chrome)':>9} {'incomplete':>11} {'(chrome)':>9}")
    for name, vc, vx, ic, ix, _ in rows:
        log(f"  {name:<46} {vc:>10} {vx:>9} {ic:>11} {ix:>9}")


def details(name, result, structure):
    """The lines that explain a page's failures: each rule, where, and the first nodes."""
    lines = [f"{name}: {p}" for p in structure]
    for rule in result["violations"]:
        nodes = [n for n in rule["nodes"] if n["where"] == "content"]
        if nodes:
            lines.append(
                f"{name}: {rule['id']} ({rule['impact']}): {rule['help']}; "
                f"{len(nodes)} node(s), e.g. {nodes[0]['html']!r} {nodes[0]['why']!r}"
            )
    return lines


def chrome_summary(results):
    """Rule id -> nodes, of the violations outside the course's content (reported only)."""
    out = {}
    for result in results:
        for rule in result["violations"]:
            n = count([rule], "chrome")
            if n:
                out[rule["id"]] = out.get(rule["id"], 0) + n
    return out


def _serve(directory):
    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass

    handler = functools.partial(Quiet, directory=str(directory))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    return httpd


def check_site(browser, site):
    """(rows, failure lines, results) for every page of the site in ``site``."""
    pages = sorted(p.name for p in site.glob("*.html"))
    httpd = _serve(site)
    rows, failures, results = [], [], []
    try:
        for name in pages:
            page = browser.new_page(viewport={"width": 1200, "height": 900})
            try:
                page.goto(f"http://127.0.0.1:{httpd.server_port}/{name}", wait_until="networkidle")
                if page.query_selector("script[src*='mathjax']"):
                    page.wait_for_function("window.MathJax && MathJax.startup")
                    page.evaluate("MathJax.startup.promise")
                result = run_axe(page, SITE_CONTENT)
                structure = structure_problems(page.evaluate(js("page_structure"), SITE_CONTENT))
            finally:
                page.close()
            rows.append(row(f"{site.name}/{name}", result, structure))
            failures += details(f"{site.name}/{name}", result, structure)
            results.append(result)
    finally:
        httpd.shutdown()
        httpd.server_close()
    return rows, failures, results


def _axe_notebook(lab, nb, timeout):
    """axe's result on notebook ``nb`` opened and run in ``lab``; CheckFailed if it cannot run."""
    from notebook_checks import open_and_run

    page = lab.context.new_page()
    try:
        open_and_run(page, lab.server, nb, [], timeout)
        page.evaluate(js("sweep"))
        page.wait_for_timeout(500)
        return run_axe(page, LAB_CONTENT, LAB_NOT_CONTENT)
    finally:
        try:
            page.evaluate(js("shutdown_kernel"))
        except Exception:
            pass
        page.close()


def check_lab(pw, paths, timeout=240):
    """(rows, failure lines, results) for every notebook of ``paths`` opened in JupyterLab.

    A stalled kernel (cells left queued while it says idle, :class:`common.KernelStalled`) is
    retried once on a new server with a new browser profile, as ``run_e2e`` does; a real defect
    fails twice."""
    from run_e2e import Lab

    rows, failures, results = [], [], []
    lab = Lab(pw, paths, fixtures=False)
    try:
        for nb in lab.notebooks:
            try:
                try:
                    result = _axe_notebook(lab, nb, timeout)
                except KernelStalled as exc:
                    log(f"  {nb}: kernel stalled ({exc}); retrying once on a new JupyterLab")
                    lab.close()
                    lab = Lab(pw, paths, fixtures=False)
                    result = _axe_notebook(lab, nb, timeout)
            except CheckFailed as exc:
                failures.append(f"{nb}: could not be checked: {exc}")
                continue
            rows.append(row(nb, result))
            failures += details(nb, result, [])
            results.append(result)
    finally:
        lab.close()
    return rows, failures, results


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--site", action="append", type=Path, help="a built site (repeatable)")
    parser.add_argument("--lab", action="append", type=Path, help="notebooks for JupyterLab")
    parser.add_argument("--no-site", action="store_true")
    parser.add_argument("--no-lab", action="store_true")
    args = parser.parse_args(argv)
    problems = missing_tools(need_npm=not AXE_JS.is_file())
    if problems:
        for p in problems:
            log(p)
        return 2
    install_axe()
    sites = [] if args.no_site else (args.site or SITES)
    for site in sites:
        if not (site / "index.html").is_file():
            log(f"no site in {site}: build it first (`make site`, `make site SOLUTIONS=1`)")
            return 2
    labs = [] if args.no_lab else (args.lab or [ROOT / "notebooks", ROOT / "problem_sets"])
    from playwright.sync_api import sync_playwright

    failures, all_results = [], []
    with sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=str(CHROMIUM), args=["--no-sandbox"])
        try:
            for site in sites:
                rows, fails, results = check_site(browser, site)
                print_table(f"site {site.name} (axe-core {AXE.split('@')[1]}, {WCAG_TAGS})", rows)
                failures += fails
                all_results += results
        finally:
            browser.close()
        if labs:
            rows, fails, results = check_lab(pw, [p.resolve() for p in labs])
            print_table("JupyterLab: the notebooks' content (cells) and JupyterLab's chrome", rows)
            failures += fails
            all_results += results
    chrome = chrome_summary(all_results)
    if chrome:
        log(
            "outside the course's content (theme / JupyterLab chrome, not failed): "
            + ", ".join(f"{k} x{v}" for k, v in sorted(chrome.items()))
        )
    for line in failures:
        log(f"FAIL {line}")
    log(
        f"{len(failures)} problem(s) in the course's content"
        if failures
        else "0 violations of WCAG 2.0/2.1 A and AA rules in the course's content"
    )
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
