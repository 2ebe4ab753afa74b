"""The class report of one problem set as an HTML page and a CSV of the same numbers.

Two copies (:class:`View`): the **instructor's** names students (who gave an unexplained
answer, who answered another variant's numbers, who has no submission); the **shared** copy
has no name and no id, and every count from 1 to 4 is shown as ``<5`` (a share is hidden when
it would give such a count back). The page is one offline file (figures are ``data:`` URIs, no
script, no external request), in English (``lang``), with one ``h1``, a heading per section,
tables with a caption and ``th`` headers with ``scope``, figures with alt text, and colours
of at least 4.5:1 contrast.
"""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass
from html import escape

from . import report_plots as P
from .csv_safe import neutralise
from .report_stats import SMALL

__all__ = ["View", "page", "csv_text", "CSV_HEADER"]

CSV_HEADER = ["problem_set", "section", "exercise", "item", "students", "share", "detail"]
CSS = """
body{font-family:system-ui,sans-serif;color:#1a1a1a;background:#fff;max-width:60rem;
margin:0 auto;padding:1rem;line-height:1.5}
table{border-collapse:collapse;margin:0.5rem 0 1rem}
caption{text-align:left;font-weight:600;padding:0.25rem 0}
th,td{border:1px solid #595959;padding:0.25rem 0.5rem;text-align:left;vertical-align:top}
thead th{background:#e8eef5}
.copy{border:2px solid #8a1c1c;padding:0.5rem;color:#8a1c1c;font-weight:600}
.flag{font-weight:700;color:#8a1c1c}
figure{margin:0.5rem 0}
a{color:#0b4f8a}
"""


@dataclass(frozen=True)
class View:
    """Which copy: ``private`` (the instructor's, with names) or shared (de-identified).

    Examples
    --------
    >>> shared = View(False)
    >>> shared.count(0), shared.count(3), shared.count(12), View(True).count(3)
    ('0', '<5', '12', '3')
    >>> shared.share(12, 30), shared.share(27, 30)  # 3 not right could be worked out
    ('40%', 'hidden')
    """

    private: bool

    def count(self, c):
        return str(c) if self.private or c == 0 or c >= SMALL else f"<{SMALL}"

    def share(self, c, n):
        if not n:
            return "–"
        hidden = not self.private and (0 < c < SMALL or 0 < n - c < SMALL)
        return "hidden" if hidden else f"{100 * c / n:.0f}%"

    def who(self, names):
        return ", ".join(names) if self.private else ""


def _label(name):
    try:
        from course_lib.exercises import get

        ex = get(name)
        return f"{ex.label} {ex.title} ({name})"
    except KeyError:
        return name


def _table(caption, head, rows):
    """A table: ``head`` column names, ``rows`` lists whose first cell is the row header."""
    out = [f"<table><caption>{escape(caption)}</caption><thead><tr>"]
    out += [f'<th scope="col">{escape(h)}</th>' for h in head]
    out.append("</tr></thead><tbody>")
    for row in rows:
        cells = [f'<th scope="row">{escape(str(row[0]))}</th>']
        cells += [f"<td>{escape(str(c))}</td>" for c in row[1:]]
        out.append("<tr>" + "".join(cells) + "</tr>")
    out.append("</tbody></table>")
    return "".join(out)


def _figure(uri, alt, caption):
    return (
        f'<figure><img src="{uri}" alt="{escape(alt)}">'
        f"<figcaption>{escape(caption)}</figcaption></figure>"
    )


def _d(value):
    return "–" if value is None else f"{value:.2f}"


# ------------------------------------------------------------------------------ rows


def summary_rows(st, view):
    """Per exercise, best separating first: exercise, points, students, right, share, D,
    never ran the check."""
    rows = []
    for e in st.by_discrimination():
        known = view.count(e.checked_known)
        never = f"{view.count(e.never_checked)} of {known}" if e.checked_known else "–"
        rows.append(
            [
                _label(e.name),
                f"{e.points:g}",
                view.count(e.students),
                view.count(e.right),
                view.share(e.right, e.students),
                _d(e.discrimination),
                never,
            ]
        )
    return rows


def mistake_rows(e, view):
    return [
        [key, view.count(c), view.share(c, e.students), hint or "(no hint text)"]
        for key, c, hint in e.mistakes
    ]


def unexplained_rows(e, view):
    rows = []
    for text, c, who in e.unexplained:
        row = [text, view.count(c), view.share(c, e.students)]
        rows.append(row + [view.who(who)] if view.private else row)
    return rows


def variant_rows(e, view):
    return [
        [
            f"variant {v.index}",
            view.count(v.students),
            view.count(v.right),
            view.share(v.right, v.students),
            f"{v.p:.3g}",
            "harder" if v.harder else "",
        ]
        for v in e.variants
    ]


def other_rows(e, view):
    rows = [
        ["right value, not in the asked form", view.count(e.form), view.share(e.form, e.students)],
        [
            "no answer, unreadable, or 0 by a grading note",
            view.count(e.no_answer),
            view.share(e.no_answer, e.students),
        ],
        [
            "graded on their own numbers, answered another variant's",
            view.count(len(e.other_numbers)),
            view.share(len(e.other_numbers), e.students),
        ],
    ]
    if e.checked_known:
        rows.append(
            [
                "never ran the check in the notebook",
                view.count(e.never_checked),
                view.share(e.never_checked, e.checked_known),
            ]
        )
    if view.private and e.other_numbers:  # a "who" column, filled on its row only
        rows = [row + [", ".join(e.other_numbers) if k == 2 else ""] for k, row in enumerate(rows)]
    return rows


# ------------------------------------------------------------------------------ page

UNEXPLAINED_HEAD = ["answer (equal values together)", "submissions", "share"]
OTHER_HEAD = ["what", "submissions", "share"]
HOW_TO_READ = (
    "<p>Each exercise shows how many submissions got each number of points, the known "
    "mistakes the grader recognised (with the hint students saw), the wrong answers no known "
    "mistake explains (equal values or expressions together), and, for exercises with "
    "per-student numbers, each variant's share right. A variant marked <strong>harder</strong> "
    "has fewer right answers than the other variants by Fisher's exact test, one-sided, "
    "p &lt; 0.05 divided by the number of variants (Bonferroni). <em>D</em> is the upper-lower "
    "discrimination index: the share right among the 27% of submissions with the most points "
    "on the other exercises minus that among the 27% with the fewest; 0.3 or more separates "
    "strong from weak students well, under 0.2 poorly, a negative D asks for a look at the "
    "exercise.</p>"
)


def _head(st, view):
    title = f"{st.name}: what the class got wrong"
    copy = (
        "Instructor's copy: it names students. Share the de-identified copy instead."
        if view.private
        else f"De-identified copy: no names, no ids; counts from 1 to {SMALL - 1} are shown "
        f"as &lt;{SMALL}."
    )
    return (
        f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        f'<meta name="viewport" content="width=device-width, initial-scale=1">'
        f"<title>{escape(title)}</title><style>{CSS}</style></head><body><main>"
        f'<h1>{escape(title)}</h1><p class="copy">{copy}</p>'
    )


def _facts(ps, st, view):
    lines = [
        f"From the {escape(ps.source)}.",
        f"{view.count(st.students)} submissions; {view.count(len(ps.missing))} students with "
        "no submission.",
    ]
    if ps.unmatched:
        lines.append(f"{view.count(len(ps.unmatched))} submissions under an id the roster lacks.")
    out = "<p>" + " ".join(lines) + "</p>"
    if view.private and (ps.missing or ps.unmatched):
        miss = ", ".join(escape(n or s) for s, n in ps.missing) or "none"
        odd = ", ".join(escape(f"{s} ({n})" if n else s) for s, n in ps.unmatched) or "none"
        out += f"<p>No submission: {miss}.</p><p>Id not in the roster: {odd}.</p>"
    return out


def _teach(st, view):
    if not st.teach_again:
        return "<h2>Teach again</h2><p>No known mistake was made.</p>"
    items = [
        f"<li><strong>{escape(_label(ex))}</strong>, mistake <code>{escape(key)}</code>: "
        f"{view.count(c)} submissions. {escape(hint)}</li>"
        for ex, key, c, hint in st.teach_again
    ]
    return (
        "<h2>Teach again</h2><p>The most common known mistakes of the set.</p><ol>"
        + "".join(items)
        + "</ol>"
    )


def _summary(st, view):
    rows = [(_label(e.name), _share(e, view)) for e in st.exercises]
    uri, alt = P.share_figure(rows)
    head = ["exercise", "points", "submissions", "right", "share right", "D", "never ran check"]
    return (
        "<h2>Exercises by how well they separate strong from weak students</h2>"
        + _figure(uri, alt, f"Share right per exercise of {st.name}.")
        + _table(
            "Exercises, best separating first (D: upper-lower discrimination index)",
            head,
            summary_rows(st, view),
        )
    )


def _share(e, view):
    text = view.share(e.right, e.students)
    return None if text in ("hidden", "–") else e.right / e.students


def _exercise(e, view):
    anchor = escape(e.name)
    out = [f'<section id="ex-{anchor}"><h2>{escape(_label(e.name))}</h2>']
    if not e.known:
        out.append("<p>Not an exercise of this course version: points only.</p>")
    out.append(
        f"<p>{view.count(e.students)} submissions, {view.count(e.right)} right "
        f"({view.share(e.right, e.students)}).</p>"
    )
    uri, alt = P.score_figure(_label(e.name), e.distribution, view.count)
    out.append(_figure(uri, alt, f"Points of {e.name} ({e.points:g} at most)."))
    out.append(_section_tables(e, view))
    return "".join(out) + "</section>"


def _section_tables(e, view):
    out = ["<h3>Known mistakes</h3>"]
    rows = mistake_rows(e, view)
    head = ["mistake", "submissions", "share", "the hint students saw"]
    out.append(_table(f"Known mistakes of {e.name}", head, rows) if rows else "<p>None.</p>")
    out.append("<h3>Wrong answers no known mistake explains</h3>")
    rows = unexplained_rows(e, view)
    head = UNEXPLAINED_HEAD + (["who"] if view.private else [])
    out.append(
        _table(f"Unexplained wrong answers to {e.name}", head, rows) if rows else "<p>None.</p>"
    )
    out.append("<h3>Other answers and the check</h3>")
    head = OTHER_HEAD + (["who"] if view.private and e.other_numbers else [])
    out.append(_table(f"Other outcomes of {e.name}", head, other_rows(e, view)))
    if e.variants:
        out.append("<h3>Variants</h3>")
        head = ["variant", "submissions", "right", "share right", "p (Fisher, one-sided)", "flag"]
        out.append(_table(f"Variants of {e.name}", head, variant_rows(e, view)))
    return "".join(out)


def page(ps, st, view):
    """The whole HTML page of one problem set (a string)."""
    parts = [_head(st, view), _facts(ps, st, view)]
    if not st.students:
        parts.append(f"<h2>No submission</h2><p>Nobody submitted {escape(st.name)}.</p>")
    else:
        parts += [_teach(st, view), _summary(st, view)]
        parts += [_exercise(e, view) for e in st.exercises]
    if ps.notes:
        parts.append("<h2>Notes</h2><ul>")
        parts += [f"<li>{escape(n)}</li>" for n in ps.notes]
        parts.append("</ul>")
    parts.append("<h2>How to read this report</h2>" + HOW_TO_READ)
    return "".join(parts) + "</main></body></html>\n"


# ------------------------------------------------------------------------------ CSV


def _csv_rows(ps, st, view):
    rows = [["set", "", "submissions", view.count(st.students), "", ps.source]]
    rows.append(["set", "", "no submission", view.count(len(ps.missing)), "", ""])
    rows.append(["set", "", "id not in the roster", view.count(len(ps.unmatched)), "", ""])
    for rank, (ex, key, c, hint) in enumerate(st.teach_again, 1):
        rows.append(["teach again", ex, f"{rank}. {key}", view.count(c), "", hint])
    for e in st.by_discrimination():
        rows += _exercise_csv(e, view)
    rows += [["note", "", "", "", "", n] for n in ps.notes]
    return [[ps.name, *r] for r in rows]


def _exercise_csv(e, view):
    n = e.students
    rows = [["exercise", e.name, "submissions", view.count(n), "", f"D={_d(e.discrimination)}"]]
    rows.append(["right", e.name, "right", view.count(e.right), view.share(e.right, n), ""])
    for v, c in sorted(e.distribution.items()):
        rows.append(["points", e.name, f"{v:g} points", view.count(c), view.share(c, n), ""])
    for key, c, share, hint in mistake_rows(e, view):
        rows.append(["known mistake", e.name, key, c, share, hint])
    for text, c, share, *who in unexplained_rows(e, view):
        rows.append(["unexplained", e.name, text, c, share, ", ".join(who)])
    for what, c, share, *who in other_rows(e, view):
        rows.append(["other", e.name, what, c, share, ", ".join(who)])
    for name, students, right, share, p, flag in variant_rows(e, view):
        rows.append(["variant", e.name, name, students, share, f"right {right}; p={p} {flag}"])
    return rows


def csv_text(ps, st, view):
    """The CSV of the same numbers as :func:`page` (one row per number)."""
    buf = io.StringIO()
    writer = csv.writer(buf)
    writer.writerow(CSV_HEADER)
    for row in _csv_rows(ps, st, view):
        writer.writerow([neutralise(c) for c in row])
    return buf.getvalue()
