"""What nbgrader shows a person as a web page: the feedback's exporter, and the student's HTML
made inert before any page is made from a submission.

nbgrader renders a submission as HTML in two places, both with nbconvert's ``HTMLExporter``:
the feedback pages (``nbgrader generate_feedback``) and the formgrader's page of a submission,
opened by the instructor, logged in. ``c.HTMLExporter.sanitize_html`` (set by the course's
config) cleans the HTML of outputs, but nbgrader's two templates render markdown cells without
it, and raw cells marked as HTML pass through as they are: a student's ``<script>`` there ran in
the instructor's browser and could set its own grades through the formgrader's API.
:class:`InertStudentHTML` makes them text in the autograded notebook, from which both pages are
made.

Links and sources are decided by a well-kept sanitizer, not by a pattern of ours: every piece
of HTML that nbconvert makes from markdown (markdown cells, anyone's, and ``text/markdown``
outputs) goes through :func:`safe_markdown2html`, which cleans nbconvert's own rendering with
``nh3`` (the Rust sanitizer ammonia): tags and attributes from an allow-list, and in every
URL attribute only the schemes of :data:`SCHEMES` or an in-page anchor, decided by nh3 after
the HTML parser has decoded entities, and again by :func:`_keep_url` on the decoded value as a
browser reads it (control characters and blanks removed, the scheme lower-cased).
The templates' other sanitizing filter, ``clean_html`` (``text/html`` outputs, raw cells), is
:func:`clean_html`, the same nh3 cleaning. ``make course`` sets both on
``HTMLExporter.filters``, which reaches the formgrader's exporter and the feedback's alike.
nbconvert's ``sanitize_html`` still runs first (bleach on outputs); it drops SVG and
JavaScript outputs.

The course's feedback template (math rendered offline) is configured on
:class:`FeedbackExporter` only: set on ``HTMLExporter`` it also replaced the formgrader's own
template, whose page of a submission then failed (``TemplateNotFound: bootstrap.min.css``).
Settings on ``HTMLExporter`` (``sanitize_html``) still reach both: a subclass reads its
parents' configuration.
"""

import re
from urllib.parse import urlsplit

import nh3
from jinja2 import pass_context
from nbconvert.exporters import HTMLExporter
from nbconvert.filters.markdown_mistune import IPythonRenderer, MarkdownWithMath
from nbgrader.preprocessors import NbGraderPreprocessor

__all__ = [
    "FeedbackExporter",
    "InertStudentHTML",
    "SCHEMES",
    "clean_html",
    "inert_output_metadata",
    "safe_markdown2html",
]

_SCHEME = re.compile(r"(?i)\b(javascript|vbscript|data)\s*:")
#: The only URL schemes a link or a source of rendered markdown may have (else an in-page anchor).
SCHEMES = frozenset({"http", "https", "mailto"})
#: Images embedded by nbconvert itself (a markdown cell's attachments) are data: URIs of these.
_IMAGE_DATA = re.compile(r"data:image/(png|jpeg|gif|webp);base64,[A-Za-z0-9+/=]*\Z")
#: Every attribute a browser reads as a URL (nh3 drops those it does not allow anyway).
_URL_ATTRIBUTES = frozenset({"href", "src", "cite", "action", "formaction", "srcset", "poster"})
_URL_ATTRIBUTES |= {"background", "longdesc", "usemap", "data", "xlink:href", "codebase"}
#: What nbconvert's markdown renderer writes, beyond nh3's default allow-list of attributes.
_ATTRIBUTES = {tag: set(names) for tag, names in nh3.ALLOWED_ATTRIBUTES.items()}
_ATTRIBUTES["*"] = {"class", "title", "lang", "dir"}
for _heading in ("h1", "h2", "h3", "h4", "h5", "h6"):
    _ATTRIBUTES[_heading] = {"id"}  # the anchors nbconvert gives headings


class FeedbackExporter(HTMLExporter):
    """``HTMLExporter`` for ``nbgrader generate_feedback`` (``GenerateFeedback.exporter_class``)."""


def inert(markdown):
    """Markdown whose HTML shows as text: every ``<`` escaped (no tag, no comment can start),
    and a script URL scheme renamed (``javascript:`` in a link becomes an unknown scheme; an
    entity would not do: the markdown renderer decodes it in a link).

    Examples
    --------
    >>> inert('<script>x</script> $a<b$ [l](javascript:go())')
    '&lt;script>x&lt;/script> $a&lt;b$ [l](unsafe-javascript:go())'
    """
    return _SCHEME.sub(r"unsafe-\1:", markdown.replace("<", "&lt;"))


def _keep_url(tag, attribute, value):
    """nh3's attribute filter: a URL attribute is kept only with a scheme of :data:`SCHEMES`,
    as an in-page anchor, or as an image nbconvert embedded; ``value`` is already decoded by
    the HTML parser, and a browser also drops blanks and control characters in a URL."""
    if attribute not in _URL_ATTRIBUTES:
        return value
    url = re.sub(r"[\x00-\x20\x7f]", "", value)
    if url.startswith("#"):
        return value
    if tag == "img" and attribute == "src" and _IMAGE_DATA.match(url):
        return value
    try:
        scheme = urlsplit(url).scheme.lower()
    except ValueError:
        return None
    return value if scheme in SCHEMES else None


def clean_html(html):
    """HTML that runs nothing and links nowhere but :data:`SCHEMES` and the page itself: the
    course's ``HTMLExporter.filters["clean_html"]``, in place of nbconvert's (bleach with a
    short list of tags, which showed a paragraph's ``<p>`` as text on the pages).

    Examples
    --------
    >>> clean_html('<a href="jav&#x09;ascript:go()">x</a><a href="#top">top</a>')
    '<a rel="noopener noreferrer">x</a><a href="#top" rel="noopener noreferrer">top</a>'
    >>> clean_html(b'<img src=x onerror=go()><script>go()</script>ok')
    '<img>ok'
    """
    html = html.decode() if isinstance(html, bytes) else str(html)
    return nh3.clean(
        html,
        attributes=_ATTRIBUTES,
        attribute_filter=_keep_url,
        url_schemes={*SCHEMES, "data"},  # data: only for images, decided by _keep_url
        clean_content_tags={"script", "style"},
    )


@pass_context
def safe_markdown2html(context, source):
    """nbconvert's ``markdown2html`` (the same renderer, attachments and anchors), cleaned by
    :func:`clean_html`: the course's ``HTMLExporter.filters["markdown2html"]``."""
    cell = context.get("cell", {})
    path = context.get("resources", {}).get("metadata", {}).get("path", "")
    renderer = IPythonRenderer(
        escape=False, attachments=cell.get("attachments", {}), embed_images=False, path=path
    )
    return clean_html(MarkdownWithMath(renderer=renderer).render(source))


#: Output metadata the templates write into a tag's attributes, unquoted: only a plain number.
_SIZE = re.compile(r"\d{1,5}(\.\d{1,3})?\Z")


def inert_output_metadata(output):
    """An output's metadata as the page may use it: ``width`` and ``height`` of an image only
    when they are plain numbers (nbconvert's templates write them into the ``<img>`` tag without
    quotes, so ``"1 onerror=..."`` became a handler), and no ``filenames`` (which nbconvert
    takes as the image's ``src``: any URL).

    Examples
    --------
    >>> out = {"metadata": {"image/png": {"width": "1 onerror=go()", "height": 40},
    ...        "filenames": {"image/png": "https://x.example/a.png"}}}
    >>> inert_output_metadata(out)["metadata"]
    {'image/png': {'height': 40}}
    """
    meta = output.get("metadata")
    if not isinstance(meta, dict):
        return output
    meta.pop("filenames", None)
    for value in meta.values():
        if isinstance(value, dict):
            for key in ("width", "height"):
                if key in value and not _SIZE.match(str(value[key])):
                    del value[key]
    return output


class InertStudentHTML(NbGraderPreprocessor):
    """Autograde: in every cell the student could write (not locked by the release), markdown
    HTML becomes text and a raw cell loses the format that would pass it to the page as HTML;
    in every code cell, locked or not (its outputs are the student's kernel's), the output
    metadata the templates put into tags is made inert (:func:`inert_output_metadata`).
    Locked cells were put back from the release by ``OverwriteCells`` before this runs."""

    def preprocess_cell(self, cell, resources, index):
        for output in cell.get("outputs", []) if cell.cell_type == "code" else []:
            inert_output_metadata(output)
        nbgrader = cell.get("metadata", {}).get("nbgrader")
        if isinstance(nbgrader, dict) and nbgrader.get("locked") is True:
            return cell, resources
        if cell.cell_type == "markdown":
            cell.source = inert(cell.source)
        elif cell.cell_type == "raw":
            for key in ("format", "raw_mimetype"):
                cell.metadata.pop(key, None)
        return cell, resources
