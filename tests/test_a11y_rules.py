"""Alt text and page structure (e2e/a11y_rules.py), judged without a browser: every figure of
every chapter gets alt text that says what it shows (the site takes it from the markdown cell
under the figure), and the rules themselves reject what they must."""

import base64
import io
import json
import re
from pathlib import Path

import nbformat
import pytest
from a11y_rules import alt_text_problem, structure_problems
from PIL import Image

from course_lib.plotting.display import figure_alt_and_png
from instructor.build.alt_text import figure_alt

ROOT = Path(__file__).resolve().parents[1]


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
    assert alt_text_problem(figure_alt(nb.cells, 0)) is not None


def _html(output):
    html = output.get("data", {}).get("text/html", "")
    return "".join(html) if isinstance(html, list) else html


def _is_figure(output):
    return "image/png" in output.get("data", {}) or figure_alt_and_png(_html(output)) is not None


def lab_alt_problems(nb):
    """What JupyterLab would show without alt text, in the stored outputs of ``nb``.

    JupyterLab writes no alt for an ``image/png`` output; a figure is shown with its alt text
    only as ``plotting.show``'s ``<img alt>``, an explorer's still too (JupyterLab opens a stored
    notebook without the widget state and shows it). Each figure's alt text must be the site's
    (the caption), and describe it; an explorer's says what it shows in its state.
    """
    problems, alt_text = [], figure_alt
    for i, cell in enumerate(nb.cells):
        for o in cell.get("outputs", []):
            where = f"cell {i} ({cell.source[:50]!r})"
            if "image/png" in o.get("data", {}):
                problems.append(f"{where}: an image/png output (no alt text in JupyterLab)")
            found = figure_alt_and_png(_html(o))
            if found:
                alt, png = found
                problem = alt_text_problem(alt)
                still = o.get("metadata", {}).get("explorer_still")
                if problem or (alt != alt_text(nb.cells, i) and not still):
                    problems.append(f"{where}: alt {alt!r}: {problem or 'not the caption'}")
                if Image.open(io.BytesIO(base64.b64decode(png))).mode != "P":
                    problems.append(f"{where}: not a palette PNG (run `make notebooks`)")
            for img in re.findall(r"<img\b[^>]*>", _html(o)):
                if not re.search(r'\balt="[^"]+"', img):
                    problems.append(f"{where}: an <img> without alt text")
    return problems


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.stem)
def test_every_figure_of_the_chapter_has_alt_text_that_describes_it(path):
    nb = nbformat.read(path, as_version=4)
    alt_text = figure_alt
    figures = 0
    for i, cell in enumerate(nb.cells):
        outputs = cell.get("outputs", [])
        if any(_is_figure(o) for o in outputs):
            figures += 1
            problem = alt_text_problem(alt_text(nb.cells, i))
            assert problem is None, f"cell {i} ({cell.source[:60]!r}): {problem}"
        for o in outputs:  # the animation player's frames carry their own alt text
            html = _html(o)
            for alt in re.findall(r'<img id="_anim_img[^>]*\balt="([^"]*)"', html):
                assert alt_text_problem(alt) is None
            assert '<img id="_anim_img' not in html or "aria-label=" in html
    assert figures > 0


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.stem)
def test_every_figure_shown_in_jupyterlab_has_the_sites_alt_text(path):
    """Regression (axe image-alt in JupyterLab): the figures were image/png outputs, which
    JupyterLab 4 shows as an <img> without alt; plotting.show gives them the site's alt text."""
    assert lab_alt_problems(nbformat.read(path, as_version=4)) == []


@pytest.mark.parametrize(
    "alt",
    [r"Figure: the scalar part w = cosfractheta2 of the quaternion", r"a turn by 45^circ about z.",
     r"Figure: w = \cos\theta of the turn.", "Figure: the dashed segment from p1 to p2 has the"],
)  # fmt: skip
def test_alt_text_with_raw_latex_or_cut_off_fails(alt):
    """Regression: the chapters' alt texts were the captions with $ and \\ stripped, cut at 200
    characters ("w = cosfractheta2 ...", "... has the same ")."""
    assert alt_text_problem(alt) is not None


def test_the_caption_becomes_plain_text_a_screen_reader_reads():
    source = (
        r"*Figure: $w = \cos\frac\theta2$, $R_z(60^\circ)$, $\dots$, $\dot q = \omega \times q$.*"
    )
    cells = [nbformat.v4.new_code_cell("fig"), nbformat.v4.new_markdown_cell(source)]
    assert figure_alt(cells, 0) == "Figure: w = cos θ/2, Rz(60°), …, q̇ = ω × q."


def test_a_figure_output_without_alt_text_fails():
    nb = nbformat.read(CHAPTERS[0], as_version=4)
    i, output = next(
        (i, o) for i, c in enumerate(nb.cells) for o in c.get("outputs", []) if _is_figure(o)
    )
    _, png = figure_alt_and_png(_html(output))
    output["data"] = {"image/png": png, "text/plain": "<Figure size 432x432 with 1 Axes>"}
    assert any("image/png output" in p for p in lab_alt_problems(nb))
    output["data"] = {"text/html": f'<img src="data:image/png;base64,{png}">'}
    assert any("without alt" in p for p in lab_alt_problems(nb))
    output["data"] = {
        "text/html": f'<img class="course-figure" alt="Figure 3" src="data:image/png;base64,{png}">'
    }
    assert any("Figure 3" in p for p in lab_alt_problems(nb))


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


def test_alt_text_tool_gives_a_stale_show_call_its_caption_and_keeps_the_rest():
    """instructor/build/alt_text.py --apply: the call's text becomes the caption; code around it
    (with non-ASCII before the call, where ast counts bytes) is kept; a second run changes
    nothing."""
    from instructor.build.alt_text import rewrite

    code = 'label = "θ = 30°"\nplot.show(\n    "Figure: old text, cut off at"\n)\nprint(label)'
    caption = r"*Figure: a turn by $\theta = 30^\circ$ about $z$.*"
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(code), nbformat.v4.new_markdown_cell(caption)]
    assert rewrite(nb) == [0]
    assert nb.cells[0].source == (
        'label = "θ = 30°"\nplot.show(\n    "Figure: a turn by θ = 30° about z."\n)\nprint(label)'
    )
    assert rewrite(nb) == []


def test_regression_the_sites_explorer_still_says_the_state_not_the_sliders():
    """The site's alt text of an explorer's still was the text around the cell ("Move the
    sliders to choose an axis..."); it is what the explorer shows in that state."""
    from course_lib.interactive import rotation_explorer
    from instructor.build import website as build

    explorer = rotation_explorer()
    output = nbformat.v4.new_output("display_data", data=explorer._repr_mimebundle_())
    cells = [
        nbformat.v4.new_markdown_cell("Move the sliders to choose an axis and an angle."),
        nbformat.v4.new_code_cell("rotation_explorer()", outputs=[output]),
    ]
    nb = build.finish(nbformat.v4.new_notebook(cells=cells))
    outputs = nb.cells[1].outputs
    assert "image/png" in outputs[0]["data"] and "text/html" not in outputs[0]["data"]
    assert outputs[1]["data"]["text/markdown"] == build.STILL_NOTE
    alt = nb.cells[1].metadata["mystnb"]["image"]["alt"]
    assert alt == explorer.alt_text() and "θ = 2.09 rad (120°)" in alt
    assert alt_text_problem(alt) is None
