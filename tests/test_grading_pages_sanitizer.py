"""Student HTML on the instructor's pages: links and sources keep only http, https, mailto and
in-page anchors, whatever encoding the student writes the scheme in.

Regression (issue 32): a markdown link whose scheme runs script, written in encodings the
course's own pattern did not decode (entities with and without semicolons, a tab or a newline
inside the scheme, ``&colon;``), ran on one click in the formgrader and in the feedback page.
The payloads are those of OWASP's XSS filter evasion cheat sheet that put a script in a URL.

The page is made as nbgrader makes both of its pages: nbconvert's ``HTMLExporter`` with the
course's configuration (``sanitize_html``, the ``markdown2html`` filter of ``make course``),
after the autograde preprocessor that makes a student's markdown inert.
"""

from __future__ import annotations

import re
from html.parser import HTMLParser

import nbformat
import pytest
from nbconvert.exporters import HTMLExporter
from traitlets.config import Config

from instructor.grading.pages import InertStudentHTML, _keep_url, clean_html

SCRIPT = "alert(1)"
# OWASP XSS Filter Evasion Cheat Sheet: the spellings of a script URL.
SCHEMES = [
    "javascript:",
    "JaVaScRiPt:",
    " javascript:",
    "&#14;  javascript:",
    "&#106;&#97;&#118;&#97;&#115;&#99;&#114;&#105;&#112;&#116;&#58;",
    "&#0000106&#0000097&#0000118&#0000097&#0000115&#0000099&#0000114&#0000105&#0000112&#0000116&#0000058",
    "&#x6A&#x61&#x76&#x61&#x73&#x63&#x72&#x69&#x70&#x74&#x3A",
    "jav\tascript:",
    "jav&#x09;ascript:",
    "jav&#x0A;ascript:",
    "jav&#x0D;ascript:",
    "java\x00script:",
    "javascript&colon;",
    "java&Tab;script:",
    "vbscript:",
    "livescript:",
    "data:text/html;base64,PHNjcmlwdD5hbGVydCgxKTwvc2NyaXB0Pg==,",
    "%6A%61%76%61%73%63%72%69%70%74:",
]
# Where a URL goes in markdown and in the HTML a text/markdown or text/html output may hold.
MARKDOWN_FORMS = ["[click]({url})", "![pic]({url})", "[ref][r]\n\n[r]: {url}", "<{url}>"]
HTML_FORMS = [
    '<a href="{url}">a</a>',
    '<img src="{url}">',
    '<iframe src="{url}"></iframe>',
    '<form action="{url}"><button formaction="{url}">b</button></form>',
    '<svg><a xlink:href="{url}"><text>s</text></a></svg>',
    '<math><maction actiontype="statusline" xlink:href="{url}">m</maction></math>',
    '<object data="{url}"></object><embed src="{url}">',
    '<base href="{url}"><link rel="import" href="{url}">',
    '<meta http-equiv="refresh" content="0;url={url}">',
    '<table background="{url}"><tr><td>t</td></tr></table>',
    '<div style="background-image:url({url})">d</div>',
    '<input type="image" src="{url}">',
    '<img srcset="{url} 1x">',
]
URL_ATTRIBUTES = {"href", "src", "action", "formaction", "xlink:href", "data", "background"}
URL_ATTRIBUTES |= {"srcset", "poster", "cite", "longdesc", "codebase", "content", "style"}


def _payloads():
    out = []
    for scheme in SCHEMES:
        url = scheme + (SCRIPT if not scheme.startswith("data:") else "")
        out.append(url)
    return out


class _Attributes(HTMLParser):
    """Every (tag, attribute, value) of a page, values decoded as a browser decodes them."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.found = []

    def handle_starttag(self, tag, attrs):
        self.found += [(tag, name, value or "") for name, value in attrs]

    handle_startendtag = handle_starttag


def _script_urls(page):
    """The URL attributes of ``page`` that a browser would run as script."""
    parser = _Attributes()
    parser.feed(page)
    bad = []
    for tag, name, value in parser.found:
        if name.startswith("on") and name not in BASELINE_HANDLERS:
            bad.append((tag, name, value))
        if name not in URL_ATTRIBUTES:
            continue
        # as a browser reads a URL: blanks and C0 controls at the ends, tabs and newlines
        # anywhere, dropped; then the scheme is the letters before the first colon
        url = re.sub(r"[\t\n\r]", "", value).strip("\x00\x20\x7f" + "".join(map(chr, range(32))))
        urls = [url] if name != "content" else re.findall(r"url=(.*)", url, re.I)
        if name == "style":
            urls = re.findall(r"url\((.*?)\)", url, re.I)
        for one in urls:
            scheme = re.match(r"\s*([a-z][a-z0-9+.-]*):", one, re.I)
            if scheme and scheme.group(1).lower() not in {"http", "https", "mailto"}:
                if not (tag == "img" and one.startswith("data:image/png")):
                    bad.append((tag, name, value))
    return bad


def _exporter():
    c = Config()
    c.HTMLExporter.sanitize_html = True
    c.HTMLExporter.filters = {
        "markdown2html": "instructor.grading.pages.safe_markdown2html",
        "clean_html": "instructor.grading.pages.clean_html",
    }
    return HTMLExporter(config=c)


def _page(markdown_cells, outputs):
    nb = nbformat.v4.new_notebook()
    for text in markdown_cells:
        nb.cells.append(nbformat.v4.new_markdown_cell(text))
    code = nbformat.v4.new_code_cell("x = 1")
    code.outputs = outputs
    nb.cells.append(code)
    inert = InertStudentHTML()
    for index, cell in enumerate(nb.cells):
        inert.preprocess_cell(cell, {}, index)
    page, _ = _exporter().from_notebook_node(nb)
    return page


BASELINE_HANDLERS = {
    name
    for _, name, _ in (
        lambda p: (p.feed(_exporter().from_notebook_node(nbformat.v4.new_notebook())[0]), p.found)[
            1
        ]
    )(_Attributes())
    if name.startswith("on")
}


@pytest.mark.parametrize("url", _payloads())
def test_regression_a_script_url_in_a_markdown_cell_never_reaches_the_page(url):
    page = _page([form.format(url=url) for form in MARKDOWN_FORMS], [])
    assert _script_urls(page) == []


@pytest.mark.parametrize("url", _payloads())
def test_a_script_url_in_markdown_or_html_outputs_never_reaches_the_page(url):
    markdown = "\n\n".join(form.format(url=url) for form in MARKDOWN_FORMS + HTML_FORMS)
    html = "".join(form.format(url=url) for form in HTML_FORMS)
    outputs = [
        nbformat.v4.new_output("display_data", data={"text/markdown": markdown}),
        nbformat.v4.new_output("display_data", data={"text/html": html}),
        nbformat.v4.new_output("execute_result", data={"text/markdown": markdown}),
    ]
    page = _page([], outputs)
    assert _script_urls(page) == []


def test_the_allowed_links_and_the_course_markdown_survive():
    page = _page(
        [
            "# Heading\n\n[site](https://example.edu/a?b=1) [mail](mailto:ta@example.edu) "
            "[up](#heading) $\\hat{\\omega}$ and `code` and **bold**\n\n| a | b |\n|---|---|\n"
            "| 1 | 2 |"
        ],
        [nbformat.v4.new_output("display_data", data={"text/markdown": "[doc](http://x.org)"})],
    )
    assert 'href="https://example.edu/a?b=1"' in page
    assert 'href="mailto:ta@example.edu"' in page
    assert 'href="#heading"' in page
    assert 'href="http://x.org"' in page
    assert "\\hat{\\omega}" in page and "<table>" in page and "<strong>bold</strong>" in page


@pytest.mark.parametrize(
    ("tag", "attribute", "value", "kept"),
    [
        ("a", "href", "https://a.b", True),
        ("a", "href", "#x", True),
        ("a", "href", "relative/page.html", False),
        ("a", "href", "//evil.example/x", False),
        ("a", "href", "java\tscript:x", False),
        ("img", "src", "data:image/png;base64,iVBORw0KGgo=", True),
        ("img", "src", "data:image/svg+xml;base64,PHN2Zz4=", False),
        ("a", "href", "data:image/png;base64,iVBORw0KGgo=", False),
        ("a", "title", "javascript:not-a-url", True),
    ],
)
def test_keep_url_decides_on_the_decoded_value(tag, attribute, value, kept):
    assert (_keep_url(tag, attribute, value) is not None) is kept


def test_clean_html_removes_handlers_and_scripts():
    assert clean_html('<p onclick="go()">x</p><script>go()</script>') == "<p>x</p>"


def test_the_check_finds_a_script_url_where_nothing_cleans_the_page():
    """Not vacuous: nbconvert's own markdown2html renders an entity-encoded scheme as a live
    ``javascript:`` link, and the check above says so."""
    nb = nbformat.v4.new_notebook()
    for url in ("&#106;avascript:alert(1)", "javascript&colon;alert(1)"):
        nb.cells.append(nbformat.v4.new_markdown_cell(f"[click]({url})"))
    page, _ = HTMLExporter().from_notebook_node(nb)
    assert len(_script_urls(page)) == 2


def test_regression_paragraphs_headings_and_images_render_and_are_not_shown_as_tags():
    """nbconvert's bleach-based clean_html escaped <p>, <h1>, <img>: the pages showed them as
    text once sanitize_html was on."""
    png = "https://example.edu/dot.png"
    page = _page([f"# Title\n\nA paragraph.\n\n![a dot]({png})"], [])
    assert "&lt;p&gt;" not in page and "&lt;h1" not in page and "&lt;img" not in page
    assert "<p>A paragraph.</p>" in page and f'src="{png}"' in page


def test_regression_image_size_metadata_puts_no_handler_on_the_page():
    """Red team, issue 32: nbconvert's templates write an image's width and height into the
    <img> tag without quotes; a student's output with width "1 onerror=alert(124)" gave the
    feedback page (and the formgrader's, classic template) a live handler. Its filenames set
    the image's src to any URL."""
    png = "iVBORw0KGgo="
    output = nbformat.v4.new_output(
        "display_data",
        data={"image/png": png},
        metadata={
            "image/png": {"width": "1 onerror=alert(124)", "height": "1 onload=alert(125)"},
            "filenames": {"image/png": "https://evil.example/x.png"},
        },
    )
    nb = nbformat.v4.new_notebook()
    code = nbformat.v4.new_code_cell("x = 1", metadata={"nbgrader": {"locked": True}})
    code.outputs = [output]
    nb.cells.append(code)
    InertStudentHTML().preprocess_cell(code, {}, 0)
    page, _ = _exporter().from_notebook_node(nb)
    assert _script_urls(page) == [] and "evil.example" not in page
    assert "onerror" not in page and "onload=alert" not in page
    kept = nbformat.v4.new_output(
        "display_data", data={"image/png": png}, metadata={"image/png": {"width": 320}}
    )
    InertStudentHTML().preprocess_cell(nbformat.v4.new_code_cell(outputs=[kept]), {}, 0)
    assert kept.metadata["image/png"] == {"width": 320}
