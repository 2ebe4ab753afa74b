"""The built course website (``make site-test`` builds it first), opened in headless Chromium.

Checks the chapter pages the way a student sees them offline: the math is typeset by the
site's own MathJax (no request leaves the site), the tables printed with ``Markdown(...)`` are
tables, every figure loads and has alt text, and no worked solution is published.
"""

import functools
import http.server
import re
import threading
from pathlib import Path

import nbformat
import pytest
from playwright.sync_api import sync_playwright

ROOT = Path(__file__).resolve().parents[1]
SITE = ROOT / "build" / "site"
CHROMIUM = "/usr/bin/chromium"
CHAPTERS = sorted(p.stem for p in (ROOT / "notebooks").glob("[0-9]*.ipynb"))
BEGIN = re.compile(r"^\s*#+\s*BEGIN SOLUTION\s*$")   # the markers, as course_lib.student reads them
END = re.compile(r"^\s*#+\s*END SOLUTION\s*$")


def solution_lines():
    """Distinctive lines of every worked solution (between the nbgrader markers, nowhere else)."""
    lines, elsewhere = set(), set()
    for path in (ROOT / "notebooks").glob("[0-9]*.ipynb"):
        for cell in nbformat.read(path, as_version=4).cells:
            inside = False
            for line in cell.source.splitlines():
                if BEGIN.search(line):
                    inside = True
                elif END.search(line):
                    inside = False
                elif inside and len(line.strip()) >= 25 and not line.strip().startswith("#"):
                    lines.add(line.strip())
                else:
                    elsewhere.add(line.strip())
    return lines - elsewhere


@pytest.fixture(scope="module")
def server():
    if not (SITE / "index.html").is_file():
        pytest.fail("no site in build/site: run `make site-test` (it builds the site first)")
    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass

    handler = functools.partial(Quiet, directory=str(SITE))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{httpd.server_port}"
    httpd.shutdown()
    httpd.server_close()


@pytest.fixture(scope="module")
def browser():
    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox"])
        yield b
        b.close()


def open_page(browser, url):
    """Load ``url``; every request that leaves the site is refused and recorded."""
    page = browser.new_page(viewport={"width": 1200, "height": 900})
    outside = []

    def route(r):
        if r.request.url.startswith(url.split("/", 3)[0] + "//" + url.split("/")[2]):
            r.continue_()
        else:
            outside.append(r.request.url)
            r.abort()

    page.route("**/*", route)
    page.goto(url, wait_until="networkidle")
    if page.query_selector("script[src*='mathjax']"):
        page.wait_for_function("window.MathJax && MathJax.startup && MathJax.startup.promise")
        page.evaluate("MathJax.startup.promise")
    return page, outside


def test_index_lists_every_chapter(server, browser):
    page, outside = open_page(browser, f"{server}/index.html")
    links = page.eval_on_selector_all("a.reference.internal", "els => els.map(e => e.href)")
    assert all(any(link.endswith(f"{c}.html") for link in links) for c in CHAPTERS), links
    assert "Student edition" in page.inner_text("body")
    assert outside == []


@pytest.mark.parametrize("chapter", CHAPTERS)
def test_chapter_page_offline(server, browser, chapter):
    page, outside = open_page(browser, f"{server}/{chapter}.html")
    assert outside == [], f"requests left the site: {outside[:3]}"
    typeset = page.eval_on_selector_all("mjx-container", "els => els.length")
    assert typeset >= 20, f"{chapter}: only {typeset} formulas typeset"
    body = page.inner_text("div.body")
    prose = page.evaluate("""() => { const c = document.querySelector('div.body').cloneNode(true);
        c.querySelectorAll('div.highlight, pre, mjx-container').forEach(e => e.remove());
        return c.innerText; }""")
    assert not re.search(r"\$\$?\\[a-zA-Z]+", prose), "raw TeX left in the text (outside code)"
    images = page.eval_on_selector_all(
        "div.body img[src*='_images/']",
        "els => els.map(e => [e.complete && e.naturalWidth > 0, e.alt])")
    assert images and all(ok for ok, _ in images), f"{chapter}: a figure did not load"
    assert all(alt and alt != "Figure" for _, alt in images[:3]) and all(alt for _, alt in images)
    leaked = [line for line in solution_lines() if line in body]
    assert leaked == [], f"{chapter}: solution text on the page: {leaked[:2]}"
    assert "Traceback" not in body and "NotImplementedError" not in prose
    page.close()


def test_markdown_tables_are_tables(server, browser):
    """Chapter 3 prints tables with ``Markdown(...)``: they are rendered, math typeset inside."""
    page, _ = open_page(browser, f"{server}/{CHAPTERS[2]}.html")
    cells_with_math = page.eval_on_selector_all("div.body table td mjx-container, div.body table th mjx-container",
                                                "els => els.length")
    assert cells_with_math > 0
    assert "| ---" not in page.inner_text("div.body")
