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

The course's feedback template (math rendered offline) is configured on
:class:`FeedbackExporter` only: set on ``HTMLExporter`` it also replaced the formgrader's own
template, whose page of a submission then failed (``TemplateNotFound: bootstrap.min.css``).
Settings on ``HTMLExporter`` (``sanitize_html``) still reach both: a subclass reads its
parents' configuration.
"""

import re

from nbconvert.exporters import HTMLExporter
from nbgrader.preprocessors import NbGraderPreprocessor

__all__ = ["FeedbackExporter", "InertStudentHTML"]

_SCHEME = re.compile(r"(?i)\b(javascript|vbscript|data)\s*:")


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


class InertStudentHTML(NbGraderPreprocessor):
    """Autograde: in every cell the student could write (not locked by the release), markdown
    HTML becomes text and a raw cell loses the format that would pass it to the page as HTML.
    Locked cells were put back from the release by ``OverwriteCells`` before this runs."""

    def preprocess_cell(self, cell, resources, index):
        nbgrader = cell.get("metadata", {}).get("nbgrader")
        if isinstance(nbgrader, dict) and nbgrader.get("locked") is True:
            return cell, resources
        if cell.cell_type == "markdown":
            cell.source = inert(cell.source)
        elif cell.cell_type == "raw":
            for key in ("format", "raw_mimetype"):
                cell.metadata.pop(key, None)
        return cell, resources
