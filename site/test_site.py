"""The built course website (``make site-test`` builds it first), opened in headless Chromium.

Checks the pages the way a student sees them offline, in a 1200 px wide window: the math is
typeset by the site's own MathJax, the tables printed with ``Markdown(...)`` are tables, every
figure of a chapter is on its page (each image output of the executed notebook, the explorers'
still pictures included, each with alt text), no page is wider than the window, no request
leaves the site (from the page or from a notebook output in it, loaded or only referenced), no
worked solution is published, and the instructor's site (when built) has its banner on every
page. ``COURSE_SITE_DIR`` chooses the site (default ``build/site``; ``make release`` checks
``build/release/site``); the executed notebooks are read from the build's ``site-src-*``.
"""

import functools
import http.server
import json
import os
import re
import shutil
import subprocess
import sys
import threading
from pathlib import Path

import pytest
from playwright.sync_api import sync_playwright

ROOT = Path(__file__).resolve().parents[1]
SITE = Path(os.environ.get("COURSE_SITE_DIR", ROOT / "build" / "site"))
EXECUTED = ROOT / "build" / "site-src-student"  # the notebooks the pages were rendered from
INSTRUCTOR = ROOT / "build" / "site-instructor"
CHROMIUM = "/usr/bin/chromium"
WIDTH = 1200
PAGES = sorted(p.stem for p in SITE.glob("*.html") if p.stem not in ("genindex", "search"))
NOTEBOOK_PAGES = sorted(p.stem for p in EXECUTED.glob("*.ipynb"))
BEGIN = re.compile(
    r"^\s*#+\s*BEGIN SOLUTION\s*$"
)  # the markers, as instructor.build.student reads them
END = re.compile(r"^\s*#+\s*END SOLUTION\s*$")
# a request, not a link: what a page loads by itself (an <a href> to Binder is only a link)
LOADS_OUTSIDE = re.compile(
    r"<(script|img|link|iframe|source|video|audio|embed)\b[^>]*\b(src|href)=[\"']?(https?:)?//",
    re.I,
)
CSS_OUTSIDE = re.compile(r"url\(\s*[\"']?(https?:)?//|@import\s+[\"']?(https?:)?//", re.I)


def solution_lines():
    """Distinctive lines of every worked solution (between the nbgrader markers, nowhere else)."""
    lines, elsewhere = set(), set()
    for folder in ("notebooks", "problem_sets"):
        for path in (ROOT / folder).glob("*.ipynb"):
            for cell in json.loads(path.read_text(encoding="utf-8"))["cells"]:
                inside = False
                for line in "".join(cell["source"]).splitlines():
                    if BEGIN.search(line):
                        inside = True
                    elif END.search(line):
                        inside = False
                    elif inside and len(line.strip()) >= 25 and not line.strip().startswith("#"):
                        lines.add(line.strip())
                    else:
                        elsewhere.add(line.strip())
    return lines - elsewhere


EXPLORER_STILLS = {  # chapter: its explorers
    "02_rotations": 1,
    "03_exponential_coordinates": 1,
    "05_orientation_in_practice": 1,
}


def image_outputs(chapter):
    """(image outputs, explorer stills) of the executed notebook the page was made from."""
    nb = json.loads((EXECUTED / f"{chapter}.ipynb").read_text(encoding="utf-8"))
    images = stills = 0
    for cell in nb["cells"]:
        if "remove-output" in cell.get("metadata", {}).get("tags", []):
            continue
        for output in cell.get("outputs", []):
            data = output.get("data", {})
            images += "image/png" in data
            stills += "A still picture of the explorer" in "".join(data.get("text/markdown", ""))
    return images, stills


def _serve(directory):
    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass

    handler = functools.partial(Quiet, directory=str(directory))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    return httpd


@pytest.fixture(scope="module")
def server():
    if not (SITE / "index.html").is_file():
        pytest.fail(f"no site in {SITE}: run `make site-test` (it builds the site first)")
    httpd = _serve(SITE)
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
    """Load ``url`` in a 1200 px window; every request that leaves the site is refused, kept."""
    page = browser.new_page(viewport={"width": WIDTH, "height": 900})
    outside = []
    origin = "/".join(url.split("/", 3)[:3])

    def route(r):
        if r.request.url.startswith(origin) or r.request.url.startswith("data:"):
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


@pytest.fixture(scope="module")
def visit(server, browser):
    """visit(name) -> (page, requests refused): each page is loaded once for all the tests."""
    pages = {}

    def load(name):
        if name not in pages:
            pages[name] = open_page(browser, f"{server}/{name}.html")
        return pages[name]

    yield load
    for page, _ in pages.values():
        page.close()


def test_index_lists_every_page(server, browser):
    page, outside = open_page(browser, f"{server}/index.html")
    links = page.eval_on_selector_all("a.reference.internal", "els => els.map(e => e.href)")
    assert all(any(link.endswith(f"{c}.html") for link in links) for c in NOTEBOOK_PAGES), links
    assert "Student edition" in page.inner_text("body")
    assert outside == []


@pytest.mark.parametrize("name", PAGES)
def test_no_page_loads_anything_from_outside_the_site(name):
    """Static check of every page and stylesheet: catches what a lazy page might load later."""
    text = (SITE / f"{name}.html").read_text(encoding="utf-8")
    assert not LOADS_OUTSIDE.search(text), LOADS_OUTSIDE.search(text).group(0)
    assert not CSS_OUTSIDE.search(text)
    for css in SITE.glob("_static/**/*.css"):
        found = CSS_OUTSIDE.search(css.read_text(encoding="utf-8", errors="replace"))
        assert not found, f"{css.name}: {found.group(0)}"


@pytest.mark.parametrize("chapter", NOTEBOOK_PAGES)
def test_chapter_page_offline(visit, chapter):
    page, outside = visit(chapter)
    assert outside == [], f"requests left the site: {outside[:3]}"
    body = page.inner_text("div.body")
    prose = page.evaluate("""() => { const c = document.querySelector('div.body').cloneNode(true);
        c.querySelectorAll('div.highlight, pre, mjx-container').forEach(e => e.remove());
        return c.innerText; }""")
    assert not re.search(r"\$\$?\\[a-zA-Z]+", prose), "raw TeX left in the text (outside code)"
    if chapter[:1].isdigit():
        typeset = page.eval_on_selector_all("mjx-container", "els => els.length")
        assert typeset >= 20, f"{chapter}: only {typeset} formulas typeset"
    leaked = [line for line in solution_lines() if line in body]
    assert leaked == [], f"{chapter}: solution text on the page: {leaked[:2]}"
    assert "Traceback" not in body and "NotImplementedError" not in prose


@pytest.mark.parametrize("chapter", NOTEBOOK_PAGES)
def test_every_figure_of_the_chapter_is_on_its_page(visit, chapter):
    """Regression (issue 16): the Explore sections of 02 and 03 showed no picture."""
    images, stills = image_outputs(chapter)
    page, _ = visit(chapter)
    shown = page.eval_on_selector_all(
        "div.body img[src*='_images/']",
        "els => els.map(e => [e.complete && e.naturalWidth > 0, e.alt])",
    )
    assert len(shown) == images, f"{chapter}: {len(shown)} figures on the page, {images} made"
    assert all(ok for ok, _ in shown), f"{chapter}: a figure did not load"
    assert all(alt for _, alt in shown) and all(alt != "Figure" for _, alt in shown[:3])
    # text_content, not inner_text: an explorer in a closed "Going deeper" fold is not rendered
    notes = page.text_content("div.body").count("A still picture of the explorer")
    assert notes == stills
    explorers = EXPLORER_STILLS.get(chapter, 0)
    assert stills >= explorers, f"{chapter}: the explorer's still picture is missing"


@pytest.mark.parametrize("chapter", NOTEBOOK_PAGES)
def test_going_deeper_parts_are_folded_as_in_jupyterlab(visit, chapter):
    """Issue 18: every heading the notebook folds ("jp-MarkdownHeadingCollapsed") is a closed
    <details> on the page, its heading the summary, the rest of its part inside."""
    cells = json.loads((EXECUTED / f"{chapter}.ipynb").read_text())["cells"]
    folds = [c for c in cells if c.get("metadata", {}).get("jp-MarkdownHeadingCollapsed")]
    page, _ = visit(chapter)
    found = page.eval_on_selector_all(
        "details.going-deeper",
        "els => els.map(e => [e.open, e.querySelector('summary').innerText,"
        " e.children.length, e.querySelector('div.cell, p') !== null])",
    )
    assert len(found) == len(folds), f"{chapter}: {len(found)} folded parts, {len(folds)} folds"
    for is_open, summary, children, content in found:
        assert not is_open and summary.startswith(("Going deeper", "Errata"))
        assert children > 1 and content


@pytest.mark.parametrize("name", PAGES)
def test_no_horizontal_overflow_at_1200_px(visit, name):
    """Regression (issue 16): the chapter pages were 1357 px wide in a 1200 px window."""
    page, outside = visit(name)
    assert outside == [], f"{name}: requests left the site: {outside[:3]}"
    width = page.evaluate("document.documentElement.scrollWidth")
    assert width <= WIDTH, f"{name}: the page is {width} px wide in a {WIDTH} px window"


def test_markdown_tables_are_tables(visit):
    """Chapter 3 prints tables with ``Markdown(...)``: they are rendered, math typeset inside."""
    page, _ = visit("03_exponential_coordinates")
    cells_with_math = page.eval_on_selector_all(
        "div.body table td mjx-container, div.body table th mjx-container", "els => els.length"
    )
    assert cells_with_math > 0
    assert "| ---" not in page.inner_text("div.body")


@pytest.mark.parametrize("edition", ["instructor", "student"])
def test_instructor_banner_on_every_page_and_only_there(tmp_path, edition):
    """site/conf.py and site/templates on a two-page site (a whole build takes minutes)."""
    src, out = tmp_path / "src", tmp_path / "out"
    src.mkdir()
    shutil.copy(ROOT / "site" / "conf.py", src / "conf.py")
    shutil.copytree(ROOT / "site" / "templates", src / "_templates")
    (src / "index.md").write_text("# Course\n\n```{toctree}\npage\n```\n", encoding="utf-8")
    (src / "page.md").write_text("# A page\n\nText.\n", encoding="utf-8")
    static = tmp_path / "static"
    static.mkdir()
    (static / "course.css").write_text("", encoding="utf-8")
    env = {**os.environ, "COURSE_SITE_STATIC": str(static), "COURSE_SITE_EDITION": edition}
    subprocess.run(
        [sys.executable, "-m", "sphinx", "-b", "html", "-q", str(src), str(out)],
        check=True,
        env=env,
    )
    pages = sorted(out.glob("*.html"))
    assert len(pages) >= 4  # index, page, genindex, search
    banners = {p.name: "instructor-banner" in p.read_text(encoding="utf-8") for p in pages}
    assert set(banners.values()) == {edition == "instructor"}, banners
