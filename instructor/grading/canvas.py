"""``make grades-canvas COURSE=DIR [ASSIGNMENT=psNN] [ROSTER=export.csv]``: nbgrader's grades
as a CSV that Canvas's gradebook import takes.

    python -m instructor.grading.canvas DIR [--assignment psNN ...] [--roster canvas-export.csv]
    [--out F]

Canvas imports a CSV laid out like its own gradebook export: the columns ``Student``, ``ID``,
``SIS User ID``, ``SIS Login ID``, ``Section`` (a student is matched by ``ID``, the Canvas user
id, or by an SIS id), then one column per assignment (``Name (canvas id)`` updates that
assignment, a new name makes a new one), and a second row ``Points Possible``. A blank score
changes nothing in Canvas.

The scores come from ``DIR/gradebook.db`` through nbgrader's :class:`nbgrader.api.Gradebook`.
With ``--roster`` (the instructor's Canvas gradebook export, the recommended way), each nbgrader
student id is matched to a roster row by ``SIS User ID``, ``SIS Login ID``, ``ID`` or the
student's e-mail, and the roster's own identity columns and assignment column names
(``ps01 (12345)``) are used. Without it, ``ID`` is nbgrader's ``lms_user_id`` and ``SIS User
ID`` the nbgrader id.

Names, ids and sections come from students and the roster: a cell that a spreadsheet would read
as a formula (``=``, ``+``, ``-``, ``@`` ...) is written with a leading ``'``
(:mod:`instructor.grading.csv_safe`); Canvas matches students by ``ID``, which is a number.
The students of ``DIR/identity-report.csv`` (written by the grader: a notebook that showed
other numbers than the student's own, or an id the course's roster does not know) are listed
in the report too ("check the id"), with the exercises whose points a regrade may change.

Nothing is silently zero: a student of the roster or the gradebook with no submission of an
assignment gets a **blank** cell and is listed as missing; a graded nbgrader student that no
roster row matches is left out of the CSV and listed as unknown. The list goes to stderr and
to the report file beside the CSV. ``--missing zero`` (``make grades-canvas MISSING=zero``)
writes 0 instead of a blank for missing work, still listed.

``--gradescope EXPORT`` (once per problem set) takes the scores from Gradescope's exports
instead of a course directory (:mod:`instructor.grading.canvas_gradescope`), with the same columns,
roster matching and report.
"""

from __future__ import annotations

import argparse
import csv
import io
import os
import sys
from dataclasses import dataclass, field
from pathlib import Path

from instructor.grading.csv_safe import write_rows

__all__ = ["Export", "export", "read_roster", "write_csv", "IDENTITY"]

IDENTITY = ("Student", "ID", "SIS User ID", "SIS Login ID", "Section")
POINTS_ROW = "Points Possible"


@dataclass
class Export:
    """The CSV's rows, and what could not be exported as a score."""

    header: list
    rows: list
    missing: list = field(default_factory=list)  # (student, assignment)
    unknown: list = field(default_factory=list)  # nbgrader ids no roster row matches
    identity: list = field(default_factory=list)  # rows of the course's identity report
    missing_as: str = "blank"  # issue 34: a missing submission's cell, "blank" or "zero"
    twice: list = field(default_factory=list)  # (roster row's name, [nbgrader ids]) left out

    def report(self):
        """The lines of the report: every missing submission and unknown student."""
        lines = [f"{len(self.rows) - 1} students, {len(self.header) - len(IDENTITY)} assignments"]
        as_what = "0, not blank: --missing zero" if self.missing_as == "zero" else "blank, not 0"
        lines += [f"missing submission: {who} has no {ps} ({as_what})" for who, ps in self.missing]
        lines += [
            f"unknown student: {sid} is graded in nbgrader but not in the roster"
            for sid in self.unknown
        ]
        lines += [
            f"check the id: {r['student']} on {r['assignment']} was graded on the numbers of "
            f"{r['graded_as']} ({r['how']})"
            + (f"; the notebook showed others in {r['other_numbers']}" * bool(r["other_numbers"]))
            + (f"; points lost there: {r['lost']} (regrade?)" * bool(r["lost"]))
            for r in self.identity
        ]
        lines += [
            f"matched twice: the roster row of {who} matches the nbgrader students "
            f"{', '.join(sids)}; left out (no score written): grade one id per student, or fix "
            "the roster"
            for who, sids in self.twice
        ]
        return lines


def read_roster(path):
    """The rows of a Canvas gradebook export (dicts), without its ``Points Possible`` row."""
    text = Path(path).read_text(encoding="utf-8-sig")
    reader = csv.DictReader(io.StringIO(text))
    missing = [c for c in IDENTITY[:2] if c not in (reader.fieldnames or [])]
    if missing:
        raise ValueError(f"roster: {path} is not a Canvas gradebook export (no {missing} column)")
    rows = [r for r in reader if POINTS_ROW not in (r.get("Student") or "")]
    return reader.fieldnames, rows


def _column(ps, fieldnames):
    """The roster's column of assignment ``ps`` (``ps01 (12345)``), else ``ps`` itself."""
    for name in fieldnames or ():
        if name == ps or name.startswith(f"{ps} ("):
            return name
    return ps


def _match(student, rows):
    keys = {student.id, student.email or ""} - {""}
    for row in rows:
        if keys & {row.get("SIS User ID"), row.get("SIS Login ID"), row.get("ID")}:
            return row
    return None


def export(course, assignments=None, roster=None, missing="blank"):
    """An :class:`Export` of the gradebook of the course directory ``course``; a missing
    submission's cell is blank, or 0 with ``missing="zero"``."""
    from nbgrader.api import Gradebook, MissingEntry

    bin_dir = str(Path(sys.executable).parent)  # nbgrader runs alembic from PATH
    if bin_dir not in os.environ.get("PATH", "").split(os.pathsep):
        os.environ["PATH"] = f"{bin_dir}{os.pathsep}{os.environ.get('PATH', '')}"
    db = Path(course) / "gradebook.db"
    if not db.is_file():
        raise ValueError(f"COURSE: no gradebook.db in {course} (run nbgrader autograde first)")
    fields, rows = read_roster(roster) if roster else (None, None)
    report = (
        Path(course) / "identity-report.csv"
    )  # instructor.grading.identity.REPORT, by VerifyRecords
    flagged = []
    if report.is_file():
        with open(report, newline="", encoding="utf-8") as f:
            flagged = list(csv.DictReader(f))
    with Gradebook(f"sqlite:///{db}") as gb:
        known = {a.name: a for a in gb.assignments}
        names = list(assignments or sorted(known))
        for ps in names:
            if ps not in known:
                raise ValueError(f"ASSIGNMENT: {ps!r} is not in the gradebook ({sorted(known)})")
        cols = [_column(ps, fields) for ps in names]
        out = Export([*IDENTITY, *cols], [[POINTS_ROW, "", "", "", ""]])
        out.rows[0] += [f"{known[ps].max_score:g}" for ps in names]
        scores = {}
        for student in gb.students:
            for ps in names:
                try:
                    scores[student.id, ps] = gb.find_submission(ps, student.id).score
                except MissingEntry:
                    pass
        people = []
        for student in gb.students:
            row = _match(student, rows) if rows is not None else None
            if rows is not None and row is None:
                if any((student.id, ps) in scores for ps in names):
                    out.unknown.append(student.id)
                continue
            name = f"{student.last_name or ''}, {student.first_name or ''}".strip(", ")
            ident = (
                [row.get(c, "") for c in IDENTITY]
                if row
                else [name or student.id, student.lms_user_id or "", student.id, "", ""]
            )
            people.append((ident, student.id))
        if rows is not None:
            people = _once(people, out)
            taken = {tuple(ident) for ident, _ in people}
            people += [
                ([r.get(c, "") for c in IDENTITY], None)
                for r in rows
                if tuple(r.get(c, "") for c in IDENTITY) not in taken
            ]
        for ident, sid in people:
            cells = []
            for ps in names:
                score = scores.get((sid, ps))
                if score is None:
                    out.missing.append((ident[0] or sid, ps))
                cells.append(("0" if missing == "zero" else "") if score is None else f"{score:g}")
            out.rows.append([*ident, *cells])
    out.identity = [r for r in flagged if r.get("assignment") in names]
    out.missing_as = missing
    return out


def _once(people, out):
    """``people`` without the roster rows that two or more nbgrader students matched (two
    rows of one Canvas student: which score Canvas keeps would depend on its import order);
    those are listed in ``out.twice``."""
    by_row = {}
    for ident, sid in people:
        by_row.setdefault(tuple(ident), []).append(sid)
    out.twice += [(ident[0], sids) for ident, sids in by_row.items() if len(sids) > 1]
    return [(ident, sid) for ident, sid in people if len(by_row[tuple(ident)]) == 1]


def write_csv(result, path):
    """Write the CSV (UTF-8, header then ``Points Possible`` then one row per student); a cell
    that a spreadsheet would read as a formula is neutralised
    (:mod:`instructor.grading.csv_safe`)."""
    return write_rows(path, [result.header, *result.rows])


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("course", metavar="DIR", nargs="?", help="an nbgrader course directory")
    parser.add_argument("--assignment", action="append", help="psNN (default: every one)")
    parser.add_argument("--roster", help="the course's Canvas gradebook export (CSV)")
    parser.add_argument("--out", help="the CSV to write (default: DIR/canvas-grades.csv)")
    # issue 34: Gradescope's exported scores instead of a course
    # (instructor/grading/canvas_gradescope.py)
    parser.add_argument("--gradescope", action="append", help="a Gradescope export, per set")
    parser.add_argument("--missing", choices=("blank", "zero"), default="blank")
    args = parser.parse_args(argv)
    try:
        if bool(args.course) == bool(args.gradescope):
            raise ValueError("give one of COURSE=DIR (nbgrader) or GRADESCOPE=EXPORT")
        if args.gradescope:
            from .canvas_gradescope import export as gradescope_export

            result = gradescope_export(args.gradescope, args.assignment, args.roster, args.missing)
        else:
            result = export(args.course, args.assignment, args.roster, args.missing)
    except (OSError, ValueError) as err:
        print(f"make grades-canvas: {err}", file=sys.stderr)
        return 2
    home = Path(args.course) if args.course else Path(args.gradescope[0]).resolve().parent
    out = Path(args.out or home / "canvas-grades.csv")
    write_csv(result, out)
    lines = result.report()
    report = out.with_name(out.stem + "-report.txt")
    report.write_text("\n".join(lines) + "\n")
    print(f"{out}: {lines[0]}; report in {report}")
    for line in lines[1:]:
        print(f"grades-canvas: {line}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
