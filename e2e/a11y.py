"""Accessibility (WCAG 2.1 AA) of the course: three engines in headless Chromium (``make a11y``).

    python e2e/a11y.py [--site DIR ...] [--lab PATH ...] [--no-lab] [--no-site]
                       [--engines axe,ibm,htmlcs]

1. The engines (:mod:`a11y_engines`: axe-core, IBM's accessibility-checker-engine, pa11y's
   HTML_CodeSniffer), pinned in ``e2e/engines/package-lock.json``, are installed from npm into
   ``build/a11y-deps/`` on first use and injected into every page from those local files:
   nothing is fetched at run time.
2. Every page of each built site (default: ``build/site`` and ``build/site-instructor``, the
   student and instructor editions, served from a loopback server) is loaded, typeset by its
   own MathJax, and checked by each engine; every node counts, the theme's sidebar and footer
   included. Then the page is made 320 CSS px wide (1280 px at 400 % zoom) and must not scroll
   sideways (WCAG 1.4.10).
3. Every chapter and problem set is opened in JupyterLab (e2e's :class:`run_e2e.Lab`: its own
   server, copy and profile), run, scrolled through so that every cell is rendered, and checked
   the same way; the notebook's outputs (figures, widgets, text) and rendered markdown are the
   course's content, the rest (the cell editors, the fold buttons, menus) JupyterLab's own
   chrome, reported apart.
4. Besides the engines: the page language, one h1, headings without a skipped level and
   meaningful link text (:mod:`a11y_rules`), on the site's pages.

Prints a table per page (each engine's failures, content / chrome) and exits 1 on any failure in
the course's content (or a structure or reflow problem); 0 otherwise. Without Chromium or npm it
says which is missing and how to install it, and exits 2.
"""

import argparse
import functools
import http.server
import shutil
import sys
import threading
from pathlib import Path

import a11y_engines as engines
from a11y_rules import structure_problems
from common import ROOT, CheckFailed, KernelStalled, js, log

CHROMIUM = Path("/usr/bin/chromium")
SITES = [ROOT / "build" / "site", ROOT / "build" / "site-instructor"]
# On the site every node counts, the theme's sidebar and footer included; the structure rules
# (one h1, headings in order, link text) read the page body.
SITE_CONTENT = "html"
SITE_BODY = "div.body"
#: WCAG 1.4.10: 320 CSS px wide (1280 px at 400 % zoom) without scrolling the page sideways.
REFLOW = {"width": 320, "height": 256}
# The notebook's own content in JupyterLab: its outputs (figures, widgets, text) and its rendered
# markdown. The cell editor (CodeMirror's textbox) and the heading fold button are JupyterLab's.
LAB_CONTENT = ".jp-OutputArea-output, .jp-RenderedMarkdown"
LAB_NOT_CONTENT = ".jp-collapseHeadingButton, .cm-editor"
REFLOW_JS = """() => {
  const doc = document.documentElement;
  const inBox = el => {  // inside a box that scrolls or clips sideways: not the page's width
    for (let q = el.parentElement; q && q !== document.body; q = q.parentElement) {
      if (['auto', 'scroll', 'hidden', 'clip'].includes(getComputedStyle(q).overflowX)) {
        return true;
      }
    }
    return false;
  };
  const wide = [...document.querySelectorAll('body *')].filter(el => {
    const r = el.getBoundingClientRect();
    return r.width > 0 && r.right > doc.clientWidth + 1 && !inBox(el);
  });
  return {scroll: doc.scrollWidth, width: doc.clientWidth,
          wide: wide.slice(0, 3).map(el => el.outerHTML.slice(0, 120))};
}"""


# WCAG 2.4.3: a formula is no tab stop unless it scrolls (MathJax's menu puts each in the tab
# order; site/conf.py turns it off, course.js gives a tab stop to a formula that scrolls).
MATH_STOPS_JS = """(content) => [...document.querySelectorAll('mjx-container[tabindex]')]
  .filter(m => m.tabIndex >= 0 && m.closest(content) && m.scrollWidth <= m.clientWidth + 1)
  .length"""


def math_stop_problems(page, content):
    n = page.evaluate(MATH_STOPS_JS, content)
    return [f"{n} formula(s) that do not scroll are tab stops"] if n else []


def missing_tools(need_npm):
    """What is missing to run the checks, each with how to install it."""
    out = []
    if not CHROMIUM.exists():
        out.append(f"{CHROMIUM} is missing: install it with `sudo apt-get install chromium`")
    if need_npm and shutil.which("npm") is None:
        out.append(
            "npm is missing (it installs the engines axe-core, IBM's accessibility-checker-engine"
            " and HTML_CodeSniffer): `sudo apt-get install npm`"
        )
    return out


def count(rules, where):
    return sum(1 for r in rules for n in r["nodes"] if n["where"] == where)


def row(name, results, extra=()):
    """[name, {engine: (content, chrome) violations}, extra problems]."""
    counts = {
        e: (count(r["violations"], "content"), count(r["violations"], "chrome"))
        for e, r in results.items()
    }
    return [name, counts, list(extra)]


def print_table(title, rows, names):
    log(f"{title}")
    log(f"  {'page':<46} " + " ".join(f"{n:>12}" for n in names) + "  (failures: content/chrome)")
    for name, counts, extra in rows:
        cells = " ".join(
            f"{f'{counts[n][0]}/{counts[n][1]}' if n in counts else 'not run':>12}" for n in names
        )
        log(f"  {name:<46} {cells}" + (f"  +{len(extra)} other" if extra else ""))


def details(name, results, structure):
    """The lines that explain a page's failures: each engine and rule, where, the first nodes."""
    lines = [f"{name}: {p}" for p in structure]
    for engine, result in results.items():
        for rule in result["violations"]:
            nodes = [n for n in rule["nodes"] if n["where"] == "content"]
            if nodes:
                lines.append(
                    f"{name}: [{engine}] {rule['id']} ({rule['impact']}): {rule['help'][:160]}; "
                    f"{len(nodes)} node(s), e.g. {nodes[0]['html']!r} {nodes[0]['why'][:160]!r}"
                )
    return lines


def chrome_summary(results):
    """engine:rule id -> nodes, of the violations outside the course's content (reported)."""
    out = {}
    for by_engine in results:
        for engine, result in by_engine.items():
            for rule in result["violations"]:
                n = count([rule], "chrome")
                if n:
                    key = f"{engine}:{rule['id']}"
                    out[key] = out.get(key, 0) + n
    return out


def reflow_problems(page):
    """WCAG 1.4.10: the page at 320 CSS px scrolls sideways? (what sticks out, if so)"""
    page.set_viewport_size(REFLOW)
    page.wait_for_timeout(300)
    info = page.evaluate(REFLOW_JS)
    if info["scroll"] <= info["width"]:
        return []
    return [
        f"at {REFLOW['width']} CSS px the page scrolls sideways ({info['scroll']} px wide): "
        + "; ".join(info["wide"])
    ]


def _serve(directory):
    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass

    handler = functools.partial(Quiet, directory=str(directory))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    return httpd


def _engines_for(page, names, ibm_max_nodes):
    """The engines to run on ``page``: IBM's only up to ``ibm_max_nodes`` elements, if given.

    IBM's engine takes about 2.5 ms an element (a chapter typeset by MathJax has 20 000 to
    60 000: 50-140 s a page on a shared machine); CI runs it on the smaller pages only."""
    nodes = page.evaluate("document.getElementsByTagName('*').length")
    if ibm_max_nodes is None or "ibm" not in names or nodes <= ibm_max_nodes:
        return names, f"{nodes} elements"
    return [n for n in names if n != "ibm"], f"{nodes} elements: ibm skipped"


def check_site(browser, site, names, ibm_max_nodes=None):
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
                run, skipped = _engines_for(page, names, ibm_max_nodes)
                result = engines.run_all(page, SITE_CONTENT, names=run)
                structure = structure_problems(page.evaluate(js("page_structure"), SITE_BODY))
                structure += math_stop_problems(page, SITE_BODY)
                structure += reflow_problems(page)
            finally:
                page.close()
            rows.append(row(f"{site.name}/{name}", result, structure))
            log(
                f"  {site.name}/{name}: {engines.timing(result)}"
                + (f" ({skipped})" if skipped else "")
            )
            failures += details(f"{site.name}/{name}", result, structure)
            results.append(result)
    finally:
        httpd.shutdown()
        httpd.server_close()
    return rows, failures, results


def _engines_on_notebook(page, names):
    """The engines' results on the notebook open and run in ``page``, every cell rendered
    first, and its formulas that are tab stops."""
    page.evaluate(js("sweep"))
    page.wait_for_timeout(500)
    result = engines.run_all(page, LAB_CONTENT, LAB_NOT_CONTENT, names)
    return result, math_stop_problems(page, LAB_CONTENT)


def axe_problems(page, nb):
    """axe-core's failures in the course's content of notebook ``nb`` open in ``page`` (e2e's
    ``run_e2e --axe``: the notebook already opened and run there, not a second time)."""
    result, stops = _engines_on_notebook(page, ["axe"])
    log(f"  axe-core on its content: {engines.timing(result)}")
    return [f"accessibility: {line}" for line in details(nb, result, stops)]


def _check_notebook(lab, nb, timeout, names):
    """The engines' results on notebook ``nb`` run in ``lab``; CheckFailed if it cannot run."""
    from notebook_checks import open_and_run

    page = lab.context.new_page()
    try:
        open_and_run(page, lab.server, nb, [], timeout)
        return _engines_on_notebook(page, names)
    finally:
        try:
            page.evaluate(js("shutdown_kernel"))
        except Exception:
            pass
        page.close()


def check_lab(pw, paths, names, timeout=240):
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
                    result, stops = _check_notebook(lab, nb, timeout, names)
                except KernelStalled as exc:
                    log(f"  {nb}: kernel stalled ({exc}); retrying once on a new JupyterLab")
                    lab.close()
                    lab = Lab(pw, paths, fixtures=False)
                    result, stops = _check_notebook(lab, nb, timeout, names)
            except CheckFailed as exc:
                failures.append(f"{nb}: could not be checked: {exc}")
                continue
            rows.append(row(nb, result, stops))
            log(f"  {nb}: {engines.timing(result)}")
            failures += details(nb, result, stops)
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
    parser.add_argument(
        "--ibm-max-nodes",
        type=int,
        help="on the site, run IBM's engine only on pages of at most this many elements",
    )
    parser.add_argument(
        "--engines",
        default=",".join(engines.ENGINES),
        help=f"which engines, comma-separated (default: all: {', '.join(engines.ENGINES)})",
    )
    args = parser.parse_args(argv)
    names = [n.strip() for n in args.engines.split(",") if n.strip()]
    unknown = [n for n in names if n not in engines.ENGINES]
    if unknown or not names:
        parser.error(f"--engines: unknown {unknown}; expected some of {list(engines.ENGINES)}")
    problems = missing_tools(need_npm=not engines.installed())
    if problems:
        for p in problems:
            log(p)
        return 2
    engines.install()
    pinned = engines.versions()
    title = ", ".join(f"{n} {pinned[n]} ({engines.POLICY[n]})" for n in names)
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
                rows, fails, results = check_site(browser, site, names, args.ibm_max_nodes)
                print_table(f"site {site.name}: {title}", rows, names)
                failures += fails
                all_results += results
        finally:
            browser.close()
        if labs:
            rows, fails, results = check_lab(pw, [p.resolve() for p in labs], names)
            print_table(
                "JupyterLab: the notebooks' content (cells) and JupyterLab's chrome", rows, names
            )
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
        else f"0 failures of WCAG 2.0/2.1 A and AA in the course's content ({title})"
    )
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
