"""``make report COURSE=DIR`` or ``make report GRADESCOPE=EXPORT``: what the class got wrong.

    python -m instructor.grading.report --course DIR [--assignment psNN ...]
        [--roster canvas.csv] [--out D]
    python -m instructor.grading.report --gradescope EXPORT [--assignment psNN]
        [--roster canvas.csv] [--out D]

For each problem set, four files in ``--out`` (default ``DIR/report/``, or ``report/`` beside the
export): ``psNN.html`` and ``psNN.csv``, the instructor's copy (it names students), and
``psNN-shared.html`` and ``psNN-shared.csv``, the de-identified copy (no names, no ids, counts
from 1 to 4 shown as ``<5``). Data: :mod:`instructor.grading.report_data`; numbers:
:mod:`instructor.grading.report_stats`; page: :mod:`instructor.grading.report_html`.
docs/grading.md, "What the class
got wrong", says how to read it.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from . import report_data as D
from .report_html import View, csv_text, page
from .report_stats import set_stats

__all__ = ["write_reports", "main"]


def write_reports(sets, out, roster=None):
    """Write the four files of each :class:`~instructor.grading.report_data.ProblemSet` of ``sets``
    into
    the folder ``out``; returns the paths written."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for ps in sets:
        if roster is not None:
            D.apply_roster(ps, roster)
        st = set_stats(ps, D.known)
        stem = "".join(c if c.isalnum() or c in "-_." else "_" for c in ps.name) or "set"
        for suffix, view in (("", View(True)), ("-shared", View(False))):
            html = out / f"{stem}{suffix}.html"
            html.write_text(page(ps, st, view), encoding="utf-8")
            table = out / f"{stem}{suffix}.csv"
            table.write_text(csv_text(ps, st, view), encoding="utf-8", newline="")
            written += [html, table]
    return written


def _load(args):
    if bool(args.course) == bool(args.gradescope):
        raise ValueError("give one of COURSE=DIR (nbgrader) or GRADESCOPE=EXPORT")
    if args.course:
        sets = D.from_course(args.course, args.assignment)
        return sets, Path(args.out or Path(args.course) / "report")
    if args.assignment and len(args.assignment) > 1:
        raise ValueError("ASSIGNMENT: a Gradescope export holds one assignment; name one")
    ps = D.from_gradescope(args.gradescope, (args.assignment or [None])[0])
    return [ps], Path(args.out or Path(args.gradescope).resolve().parent / "report")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--course", help="an nbgrader course directory")
    parser.add_argument("--gradescope", help="a Gradescope export (zip, folder or grades CSV)")
    parser.add_argument("--assignment", action="append", help="psNN (default: every one)")
    parser.add_argument("--roster", help="the course's Canvas gradebook export (CSV)")
    parser.add_argument("--out", help="the folder of the reports")
    args = parser.parse_args(argv)
    try:
        sets, out = _load(args)
        roster = None
        if args.roster:
            from .canvas import read_roster

            roster = read_roster(args.roster)[1]
        paths = write_reports(sets, out, roster)
    except (OSError, ValueError) as err:
        print(f"make report: {err}", file=sys.stderr)
        return 2
    for ps in sets:
        odd = f", {len(ps.unmatched)} under an id the roster lacks" if ps.unmatched else ""
        print(f"{ps.name}: {len(ps.submissions)} submissions, {len(ps.missing)} missing{odd}")
        for note in ps.notes:
            print(f"report: {note}", file=sys.stderr)
    print(f"wrote {len(paths)} files in {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
