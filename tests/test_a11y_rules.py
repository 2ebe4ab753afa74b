"""Alt text and page structure (e2e/a11y_rules.py), judged without a browser: every figure of
every chapter gets alt text that says what it shows (the site takes it from the markdown cell
under the figure), and the rules themselves reject what they must."""

import importlib.util
import json
import re
import sys
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "e2e"))
from a11y_rules import alt_text_problem, structure_problems  # noqa: E402


def _site_build():
    spec = importlib.util.spec_from_file_location("site_build", ROOT / "site" / "build.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


CHAPTERS = sorted((ROOT / "notebooks").glob("[0-9]*.ipynb"))


@pytest.mark.parametrize("bad", ["", "  ", "Figure", "figure 3", "Fig. 12", "image", "plot 2"])
def test_generic_or_missing_alt_text_fails(bad):
    assert alt_text_problem(bad) is not None


@pytest.mark.parametrize(
    "code",
    ["plotting.draw_frame(ax, R)", "fig, ax = plotting.axes3d('A')", "plt.show()",
     "import numpy as np"],
)  # fmt: skip
def test_code_as_alt_text_fails(code):
    assert "code" in alt_text_problem(code)


def test_alt_text_must_be_a_string():
    with pytest.raises(TypeError, match="alt must be a str"):
        alt_text_problem(None)


def test_a_figure_without_a_caption_gets_no_acceptable_alt_text():
    """A figure with no markdown cell after it: the site would write "Figure"; that fails."""
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell("fig"), nbformat.v4.new_code_cell("x = 1")]
    assert alt_text_problem(_site_build()._alt_text(nb.cells, 0)) is not None


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.stem)
def test_every_figure_of_the_chapter_has_alt_text_that_describes_it(path):
    nb = nbformat.read(path, as_version=4)
    alt_text = _site_build()._alt_text
    figures = 0
    for i, cell in enumerate(nb.cells):
        outputs = cell.get("outputs", [])
        if any("image/png" in o.get("data", {}) for o in outputs):
            figures += 1
            problem = alt_text_problem(alt_text(nb.cells, i))
            assert problem is None, f"cell {i} ({cell.source[:60]!r}): {problem}"
        for o in outputs:  # the animation player's frames carry their own alt text
            html = "".join(o.get("data", {}).get("text/html", ""))
            for alt in re.findall(r'<img id="_anim_img[^>]*\balt="([^"]*)"', html):
                assert alt_text_problem(alt) is None
            assert '<img id="_anim_img' not in html or "aria-label=" in html
    assert figures > 0


def test_the_animation_has_alt_text_and_a_labelled_slider():
    from course_lib.interactive import spin_animation

    html = spin_animation(frames=2).data
    alt = re.search(r'<img id="_anim_img[^>]*\balt="([^"]*)"', html).group(1)
    assert alt_text_problem(alt) is None and "spinning" in alt
    assert re.search(r'<input id="_anim_slider\w+" type="range" aria-label="[^"]+"', html)


def test_the_animation_never_plays_by_itself_and_can_be_paused():
    """WCAG 2.2.2: matplotlib's player starts only on Play; it has a Pause button."""
    from course_lib.interactive import spin_animation

    html = spin_animation(frames=2).data
    assert 'aria-label="Pause"' in html and 'aria-label="Play"' in html
    constructor = html[html.index("function Animation(") :]
    constructor = constructor[: constructor.index("Animation.prototype")]
    start = html[html.index("new Animation(") :]
    start = start[: start.index("</script>")]
    assert "play" not in constructor and "play" not in start  # it shows frame 0 and waits
    assert "this.set_frame(this.current_frame)" in constructor


def _page(**kw):
    info = {"lang": "en", "h1": 1, "headings": [{"level": 1, "text": "T"}], "links": []}
    return {**info, **kw}


def test_structure_of_a_good_page_passes():
    heads = [{"level": 1, "text": "T"}, {"level": 2, "text": "A"}, {"level": 3, "text": "B"},
             {"level": 2, "text": "C"}]  # fmt: skip
    links = [{"text": "Problem set 2: rotations", "href": "ps02.html"}]
    assert structure_problems(_page(headings=heads, links=links)) == []


@pytest.mark.parametrize(
    "page, expected",
    [
        (_page(lang=""), "no language"),
        (_page(h1=2), "2 h1"),
        (_page(headings=[{"level": 1, "text": "T"}, {"level": 3, "text": "x"}]), "skipped"),
        (_page(links=[{"text": "click here", "href": "a.html"}]), "says nothing"),
        (_page(links=[{"text": " ", "href": "a.html"}]), "no text"),
    ],
)
def test_structure_problems_are_named(page, expected):
    assert any(expected in p for p in structure_problems(page)), structure_problems(page)


def test_chapter_links_have_meaningful_text():
    """The links written in the chapters' markdown (WCAG 2.4.4)."""
    for path in CHAPTERS:
        for cell in json.loads(path.read_text())["cells"]:
            if cell["cell_type"] != "markdown":
                continue
            for text in re.findall(r"\[([^\]]*)\]\([^)]*\)", "".join(cell["source"])):
                links = [{"text": text, "href": "?"}]
                assert structure_problems(_page(links=links)) == [], (path.name, text)
