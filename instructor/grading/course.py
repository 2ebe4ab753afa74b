"""``make course COURSE=DIR``: an nbgrader course directory for the problem sets.

    python -m instructor.grading.course DIR

writes

- ``DIR/roster.csv`` with ``--roster FILE`` (``make course ROSTER=FILE``): the instructor's
  roster, checked, which maps every id of a student to the course's key
  (instructor/grading/identity.py);
- ``DIR/nbgrader_config.py``: the course's preprocessors (:mod:`instructor.grading.preprocessor`:
  the confined kernel, the grader's verdict, the guard against malformed submissions), the folders
  the kernel must not see, timeouts;
- ``DIR/source/psNN/psNN_<slug>.ipynb`` for every problem set: the notebooks of
  ``problem_sets/`` when the repository has them, otherwise the exercise section of each
  chapter notebook (everything from its ``## Exercises`` heading, check cells as
  ``instructor/build/sync_exercises.py`` writes them today).

Then the plain nbgrader commands are the instructor's whole workflow::

    cd DIR
    nbgrader generate_assignment ps01 --create
    nbgrader autograde ps01                      # after collecting into submitted/<student>/
    nbgrader generate_feedback ps01
"""

from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import sys
from pathlib import Path

import nbformat

from instructor.build import sync_exercises
from instructor.grading.sandbox import INSTALL, confinement_problem

ROOT = Path(__file__).resolve().parents[2]

__all__ = ["problem_sets", "config_text", "write_course", "hidden_folders", "write_feedback_math"]

KERNELSPEC = {"name": "python3", "display_name": "Python 3 (ipykernel)", "language": "python"}
TIMEOUT = 60
BUDGET = 300  # seconds for a notebook's whole run (instructor.grading.preprocessor.ConfinedExecute)
RECORD = "record("  # what every check cell calls (course_lib.record)
#: MathJax 3 as the site build installs it from npm (``make site``).
MATHJAX = Path("build") / "site-deps" / "node_modules" / "mathjax" / "es5" / "tex-svg.js"
FEEDBACK = "rotations_feedback"  # nbconvert template: nbgrader's feedback, math offline
MATHJAX_MACRO = """\
{%- macro mathjax(url=None) -%}
<script>
window.MathJax = {tex: {inlineMath: [["$", "$"], ["\\\\(", "\\\\)"]],
  displayMath: [["$$", "$$"], ["\\\\[", "\\\\]"]], processEscapes: true},
  svg: {fontCache: "global"}};
</script>
<script>{% raw %}"""
FEEDBACK_CONFIG = """
# Feedback renders its math offline: MathJax 3 (SVG output, no web fonts) inlined into each
# feedback page by the template in templates/{name}/ (written by `make course`).
import os as _os

import nbgrader as _nbgrader

from instructor.grading.pages import FeedbackExporter

_formgrader = _os.path.join(_os.path.dirname(_nbgrader.__file__), "server_extensions", "formgrader")
# On the feedback's exporter only: the formgrader's HTMLExporter keeps nbgrader's own template.
c.GenerateFeedback.exporter_class = FeedbackExporter
c.FeedbackExporter.template_name = {name!r}
c.FeedbackExporter.extra_template_basedirs = [
    {templates!r},
    _os.path.join(_formgrader, "templates"),
]
"""

CONFIG = """\
# The course's nbgrader configuration, written by `make course` (instructor/grading/course.py).
# Points are decided outside the student's kernel: see docs/grading.md.
import sys

sys.path.insert(0, {repo!r})  # the repository: the instructor package (its grading, its answers)

from nbconvert.preprocessors import ClearMetadataPreprocessor
from nbgrader.preprocessors import (
    AssignLatePenalties,
    CheckCellMetadata,
    ClearOutput,
    DeduplicateIds,
    IgnorePattern,
    LimitOutput,
    OverwriteCells,
    OverwriteKernelspec,
    SaveAutoGrades,
)

from instructor.grading.preprocessor import (
    CapOutput,
    ConfinedExecute,
    ConfinedExporter,
    GuardCells,
    ShownNumbers,
    VerifyRecords,
)
from instructor.grading.pages import InertStudentHTML
# issue 34: was each check run by the student?
from instructor.grading.answer_log import NoteChecksRun

c = get_config()  # noqa: F821
c.CourseDirectory.root = {root!r}
c.CourseDirectory.course_id = "rotations"

# A deleted, duplicated or retyped grade cell: put back with 0 points and a note.
# ShownNumbers first: which numbers the student's own run showed (a note, never points).
c.Autograde.sanitize_preprocessors = [
    NoteChecksRun,  # issue 34: before ClearOutput empties them (instructor/grading/answer_log.py)
    ShownNumbers,
    ClearOutput,
    GuardCells,
    DeduplicateIds,
    OverwriteKernelspec,
    OverwriteCells,
    CheckCellMetadata,
]
# The submission runs in the confined kernel; the grader then re-checks every recorded answer.
c.Autograde.autograde_preprocessors = [
    ConfinedExecute,
    VerifyRecords,
    CapOutput,
    InertStudentHTML,  # the student's markdown and raw HTML as text (instructor/grading/pages.py)
    IgnorePattern,
    ClearMetadataPreprocessor,
    LimitOutput,
    SaveAutoGrades,
    AssignLatePenalties,
    CheckCellMetadata,
]
c.Execute.timeout = {timeout}  # seconds per cell
# A notebook's whole run: a cell not started after this many seconds is not run (0, a note).
c.ConfinedExecute.notebook_budget = {budget}
# Intake (instructor/grading/intake.py): only regular files inside a submission are read, at
# most 20 MB; autograde reads submitted/ through ConfinedExporter, collect copies from the
# exchange so.
c.ExchangeFactory.collect = "instructor.grading.collect.SafeCollect"
c.ConfinedKernelManager.hide = {hide!r}
# Without bubblewrap, autograde refuses to run students' code (it would run as you, with the
# solutions and the gradebook in reach). Only for work you trust (docs/grading.md):
# c.ConfinedKernelManager.unconfined = True
c.Autograde.exporter_class = ConfinedExporter  # makes that refusal before anything is graded
c.CapOutput.max_bytes = 100_000  # output text kept per cell (autograded notebook, feedback)
c.Validator.width = 100000  # `nbgrader validate`: each failed check's hint on one whole line
# Wherever nbgrader renders a submission as HTML (the formgrader page the instructor opens, the
# feedback pages), the HTML of its outputs is sanitized (and InertStudentHTML above makes the
# student's markdown and raw HTML text): a student's <script> would run in the instructor's
# logged-in browser and could set its own grades through the formgrader's API.
c.HTMLExporter.sanitize_html = True
# Every link and source of rendered markdown and output HTML through nh3: only http, https,
# mailto and in-page anchors, decided after decoding (instructor/grading/pages.py).
c.HTMLExporter.filters = {{
    "markdown2html": "instructor.grading.pages.safe_markdown2html",
    "clean_html": "instructor.grading.pages.clean_html",
}}
# The roster (docs/variants.md, "One id per student"): every alias of a student (this nbgrader
# student id, a hub user, an SIS id) to the course's key, from which their numbers are drawn.
# Students whose notebook showed other numbers, or whom the roster does not know, are listed in
# identity-report.csv beside gradebook.db.
c.CourseIdentity.rosters = {rosters!r}
"""


def problem_sets(root=ROOT):
    """``{(assignment, file name): notebook}`` of every problem set, in order."""
    out = {}
    folder = root / "problem_sets"
    made = sorted(folder.glob("ps[0-9][0-9]_*.ipynb")) if folder.is_dir() else []
    for path in made:
        nb = nbformat.read(path, as_version=4)
        out[(path.name[:4], path.name)] = nb
    if out:
        return {k: _clean(nb) for k, nb in out.items()}
    for path in sorted((root / "notebooks").glob("[0-9][0-9]_*.ipynb")):
        chapter = sync_exercises.chapter_of(path)
        nb = sync_exercises.sync(nbformat.read(path, as_version=4), chapter)
        start = next(
            i
            for i, c in enumerate(nb.cells)
            if c.cell_type == "markdown" and c.source.lstrip().startswith(sync_exercises.HEADING)
        )
        ps = nbformat.v4.new_notebook(cells=nb.cells[start:])
        out[(f"ps{chapter:02d}", f"ps{path.name}")] = _clean(ps)
    return out


def _clean(nb):
    nb.metadata = {"kernelspec": dict(KERNELSPEC), "language_info": {"name": "python"}}
    for cell in nb.cells:
        if cell.cell_type == "code":
            cell.outputs, cell.execution_count = [], None
    return nb


def hidden_folders(course, root=ROOT):
    """What the confined kernel must not see: the course directory, this repository, and the
    project folder of the Python environment or of ``course_lib`` when it holds solutions."""
    import course_lib

    out = [Path(course).resolve(), root.resolve()]
    for candidate in (Path(sys.prefix).parent, Path(course_lib.__file__).resolve().parents[1]):
        if (candidate / "instructor" / "answers").is_dir():
            out.append(candidate.resolve())
    return sorted({str(p) for p in out})


def config_text(course, root=ROOT, timeout=TIMEOUT, rosters=()):
    """The text of ``nbgrader_config.py`` for the course directory ``course``."""
    course = Path(course).resolve()
    return CONFIG.format(
        repo=str(root.resolve()),
        root=str(course),
        timeout=int(timeout),
        budget=BUDGET,
        hide=hidden_folders(course, root),
        rosters=[str(p) for p in rosters],
    )


ROSTER = "roster.csv"  # the copy of the instructor's roster in the course directory


def copy_roster(roster, course):
    """Check the roster (:mod:`instructor.grading.identity`: RosterError naming the line) and copy
    it into the course directory, which the confined kernel never sees; returns the copy."""
    from instructor.grading.identity import load

    load([roster])
    dest = Path(course) / ROSTER
    if Path(roster).resolve() != dest.resolve():
        shutil.copyfile(roster, dest)
    os.chmod(dest, 0o600)
    return dest


def write_feedback_math(course, mathjax):
    """The feedback template whose ``mathjax()`` macro inlines MathJax's ``tex-svg.js``
    (nbgrader's feedback template calls nbconvert's macro without a URL: always the CDN);
    returns the config lines that select it."""
    js = Path(mathjax).read_text(encoding="utf-8")
    if "{% endraw" in js or "</script" in js.lower():
        raise ValueError(f"{mathjax}: cannot be inlined into a page")
    folder = Path(course) / "templates" / FEEDBACK
    folder.mkdir(parents=True, exist_ok=True)
    conf = {"base_template": "feedback", "mimetypes": {"text/html": True}}
    (folder / "conf.json").write_text(json.dumps(conf, indent=2) + "\n")
    macro = MATHJAX_MACRO + js + "{% endraw %}</script>\n{%- endmacro %}\n"
    (folder / "mathjax.html.j2").write_text(macro, encoding="utf-8")
    return FEEDBACK_CONFIG.format(name=FEEDBACK, templates=str(folder.parent))


def write_course(course, root=ROOT, mathjax=None, roster=None):
    """Write the course directory; returns the assignment names. ``mathjax``: the
    ``tex-svg.js`` of MathJax 3 for offline feedback (default: the site build's, when there);
    ``roster``: the instructor's roster CSV, copied in (default: a ``roster.csv`` already in
    the course directory, else none)."""
    course = Path(course).resolve()
    if course == root.resolve() or root.resolve() in course.parents:
        raise ValueError(f"COURSE must be outside the repository, got {course}")
    course.mkdir(parents=True, exist_ok=True)
    mathjax = Path(mathjax) if mathjax else root / MATHJAX
    if roster or (course / ROSTER).is_file():
        rosters = [copy_roster(roster or course / ROSTER, course)]
    else:
        rosters = []
    config = config_text(course, root, rosters=rosters)
    if mathjax.is_file():
        config += write_feedback_math(course, mathjax)
    (course / "nbgrader_config.py").write_text(config)
    names, sets = [], problem_sets(root)
    for (_, filename), nb in sets.items():
        stale = [
            c.id for c in nb.cells if c.get("id", "").endswith("-check") and RECORD not in c.source
        ]
        if stale:
            raise ValueError(
                f"{filename}: the check cells {', '.join(stale[:3])}... record no answer for the "
                "grader (an older check cell): regenerate the problem sets (make exercises)"
            )
    for (assignment, filename), nb in sets.items():
        folder = course / "source" / assignment
        folder.mkdir(parents=True, exist_ok=True)
        nbformat.write(nb, folder / filename)
        names.append(assignment)
    return names


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("course", metavar="DIR", help="the course directory to write")
    parser.add_argument("--mathjax", help="MathJax 3's es5/tex-svg.js (default: make site's)")
    parser.add_argument("--roster", help="roster CSV: Canvas export, or key,alias...")
    args = parser.parse_args(argv)
    if not re.fullmatch(r"[^\0]+", args.course):
        parser.error("DIR must be a folder name")
    try:
        names = write_course(Path(args.course), mathjax=args.mathjax, roster=args.roster)
    except (OSError, ValueError) as err:
        print(f"make course: {err}", file=sys.stderr)
        return 2
    print(f"{args.course}: nbgrader_config.py and source/ for {', '.join(names)}")
    problem = confinement_problem()
    if problem:
        print(
            f"make course: no confined kernel on this machine ({problem}): `nbgrader autograde` "
            f"will refuse to run students' code until bubblewrap is installed ({INSTALL}) or "
            "it runs as root (the privilege drop), unless you opt in to unconfined grading "
            "(docs/grading.md)",
            file=sys.stderr,
        )
    if not (Path(args.course) / "templates" / FEEDBACK).is_dir():
        print(
            "make course: feedback loads MathJax from a CDN (run `make site` first, or pass "
            "--mathjax .../mathjax/es5/tex-svg.js, for math offline)",
            file=sys.stderr,
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
