"""One key per student, on the grader's side: the instructor's roster (it never ships).

    python -m instructor.grading.identity --check ROSTER.csv [ID ...]   # read a roster: its size,
    or errors;
                                                            # with IDs, the key of each
    python -m instructor.grading.identity --domain berkeley.edu         # the course's e-mail domain

The course's key of a student (:func:`course_lib.exercises.course_key`) is their normalised
institutional e-mail, or login, from which their exercises' numbers are drawn. Every platform
names the student its own way: nbgrader's student id (a folder name, often the JupyterHub
user), Gradescope's ``submission_metadata.json`` (e-mail, ``sid``), a laptop's
``set_student_id``. The **roster** maps each alias to the key; it is a CSV, either

- a Canvas gradebook export (columns ``Student``, ``ID``, ``SIS User ID``, ``SIS Login ID``,
  ``Section`` ...): the key is the row's e-mail column when the export has one (``Email``),
  otherwise its ``SIS Login ID`` (with the course's e-mail domain, when set); the aliases are
  ``ID``, ``SIS User ID``, ``SIS Login ID`` (and ``Integration ID``). Canvas's "Points
  Possible" row and its "Student, Test" row are skipped;
- or a plain CSV, one student a row: ``key,alias,alias,...`` (a first row whose first cell is
  ``key`` is a header).

Every alias and key is normalised. A roster that maps one alias to two students, has an empty
row, or a row without a key is refused with the line named: nothing is graded on a guess. An
id the roster does not know is graded on the id as given (normalised), with a note.
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import os
import sys
from dataclasses import dataclass
from pathlib import Path

from course_lib.exercises import SETTINGS_FILE, check_domain, course_key, normalise_id

ROOT = Path(__file__).resolve().parents[2]

__all__ = ["Resolved", "Roster", "RosterError", "read_roster", "load", "write_report", "REPORT"]

CANVAS = ("Student", "ID")
CANVAS_ALIASES = ("ID", "SIS User ID", "SIS Login ID", "Integration ID")
EMAIL_COLUMNS = ("email", "e-mail", "email address")
SKIPPED_STUDENTS = {"points possible", "student, test", "test student"}
#: The instructor's list of the students whose id needs a look, beside ``gradebook.db``.
REPORT = "identity-report.csv"
REPORT_COLUMNS = ("assignment", "student", "graded_as", "how", "shown_as", "other_numbers", "lost")


class RosterError(ValueError):
    """A roster that cannot be trusted: the message names the file and the line."""


@dataclass(frozen=True)
class Resolved:
    """The key an id resolves to, and how: ``"roster"``, ``"not in the roster"`` or
    ``"no roster"``."""

    given: str
    key: str
    how: str
    #: Another id of the same submission that the roster knew when ``given`` was not in it
    #: (Gradescope: ``"sid 3031042"`` when the e-mail is unknown); "" otherwise.
    via: str = ""

    @property
    def note(self):
        """One line for the feedback and the report ('' when the roster knew the id)."""
        if self.how == "roster" and self.via:
            return (
                f"the id {self.given!r} is not in the course's roster: graded as {self.key!r}, "
                f"the roster's student of the {self.via}; if that is not you, tell your "
                "instructor."
            )
        if self.how == "not in the roster":
            return (
                f"the id {self.given!r} is not in the course's roster: graded on the numbers of "
                f"{self.key!r}, the id as given; if that is not you, tell your instructor."
            )
        return ""


class Roster:
    """Aliases to keys; :meth:`resolve` an id. An empty roster resolves by normalisation."""

    def __init__(self, aliases=None, sources=()):
        self.aliases = dict(aliases or {})
        self.sources = list(sources)

    def __len__(self):
        return len(set(self.aliases.values()))

    def resolve(self, raw):
        """The :class:`Resolved` key of the id ``raw`` (any string).

        Examples
        --------
        >>> r = Roster({"alice": "alice@b.edu", "3031042": "alice@b.edu"}, ["roster.csv"])
        >>> r.resolve(" ALICE ").key, r.resolve("3031042").how
        ('alice@b.edu', 'roster')
        >>> r.resolve("zed").how
        'not in the roster'
        >>> Roster().resolve("Alice@B.edu ").key
        'alice@b.edu'
        """
        given = normalise_id("" if raw is None else str(raw))
        for candidate in (given, course_key(given)):
            if candidate in self.aliases:
                return Resolved(given, self.aliases[candidate], "roster")
        how = "not in the roster" if self.sources else "no roster"
        return Resolved(given, course_key(given), how)


def _rows(path):
    try:
        text = Path(path).read_text(encoding="utf-8-sig")
    except UnicodeDecodeError as err:
        raise RosterError(f"roster {path}: not UTF-8 text ({err.reason})") from None
    reader = csv.reader(io.StringIO(text, newline=""))
    for row in reader:
        yield reader.line_num, [cell.strip() for cell in row]


def _canvas_header(row):
    return all(c in row for c in CANVAS) and any(c.startswith("SIS ") for c in row)


def read_roster(path):
    """``{alias: (key, line)}`` of the roster at ``path`` (Canvas export or plain CSV).

    Raises
    ------
    RosterError
        An empty file, an empty row, a row without a key, or one alias of two students; the
        message names the file and the line.
    """
    rows = list(_rows(path))
    if not rows:
        raise RosterError(f"roster {path}: the file is empty")
    out = {}
    header = rows[0][1]
    canvas = _canvas_header(header)
    if canvas or normalise_id(header[0] if header else "") == "key":
        rows = rows[1:]
    for line, row in rows:
        if not any(row):
            raise RosterError(
                f"roster {path}, line {line}: an empty row; remove it (every row is one student)"
            )
        if canvas:
            cells = dict(zip(header, row))
            if normalise_id(cells.get("Student", "")) in SKIPPED_STUDENTS:
                continue
            key, names = _canvas_key(cells, path, line), [cells.get(c, "") for c in CANVAS_ALIASES]
        else:
            if not row[0]:
                raise RosterError(f"roster {path}, line {line}: no key (the first cell is empty)")
            key, names = course_key(row[0]), row[1:]
        for alias in {normalise_id(a) for a in [key, *names] if a.strip()}:
            seen = out.get(alias)
            if seen and seen[0] != key:
                raise RosterError(
                    f"roster {path}, line {line}: the alias {alias!r} is also on line {seen[1]}, "
                    f"for another student ({seen[0]!r} and {key!r}): one alias, one student"
                )
            out.setdefault(alias, (key, line))
    return out


def _canvas_key(cells, path, line):
    email = next((v for k, v in cells.items() if normalise_id(k) in EMAIL_COLUMNS and v), "")
    key = course_key(email or cells.get("SIS Login ID", ""))
    if not key:
        who = cells.get("Student") or cells.get("ID") or "?"
        raise RosterError(
            f"roster {path}, line {line}: no key for {who!r} (its SIS Login ID is empty, and "
            "the export has no e-mail column)"
        )
    return key


def load(paths):
    """The :class:`Roster` of one or more roster files (an alias of two students across the
    files is refused too); an empty list gives the empty roster."""
    aliases, where = {}, {}
    for path in paths:
        for alias, (key, line) in read_roster(path).items():
            if alias in aliases and aliases[alias] != key:
                raise RosterError(
                    f"roster {path}, line {line}: the alias {alias!r} is also in {where[alias]}, "
                    f"for another student ({aliases[alias]!r} and {key!r})"
                )
            aliases[alias], where[alias] = key, f"{path}, line {line}"
    return Roster(aliases, [str(p) for p in paths])


def write_report(path, assignment, student, row):
    """Replace the rows of (``assignment``, ``student``) in the report CSV at ``path`` by
    ``row`` (a dict of :data:`REPORT_COLUMNS`), or remove them when ``row`` is None. Several
    grading processes at once (docs/grading.md) take turns on a lock file beside it."""
    import fcntl

    path = Path(path)
    with open(path.with_name(path.name + ".lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        _rewrite(path, assignment, student, row)


def _rewrite(path, assignment, student, row):
    """The report's rows, every cell formula-safe (:mod:`instructor.grading.csv_safe`: ``shown_as``
    comes from the student's own record), as they are stored and matched."""
    from instructor.grading.csv_safe import neutralise

    rows = []
    this = (neutralise(assignment), neutralise(student))
    if path.is_file():
        with open(path, newline="", encoding="utf-8") as f:
            rows = [r for r in csv.DictReader(f) if (r["assignment"], r["student"]) != this]
    if row is not None:
        new = {c: row.get(c, "") for c in REPORT_COLUMNS}
        new.update(zip(REPORT_COLUMNS, (assignment, student)))
        rows.append({c: neutralise(v) for c, v in new.items()})
    if not rows and not path.is_file():
        return
    tmp = path.with_name(path.name + ".tmp")
    with open(tmp, "w", newline="", encoding="utf-8") as f:
        writer = csv.DictWriter(f, REPORT_COLUMNS)
        writer.writeheader()
        writer.writerows(sorted(rows, key=lambda r: (r["assignment"], r["student"])))
    os.replace(tmp, path)


def set_domain(domain, root=ROOT):
    """Write the course's e-mail domain (None: none) into ``course_lib``'s settings."""
    path = root / "course_lib" / "exercises" / SETTINGS_FILE
    data = json.loads(path.read_text(encoding="utf-8"))
    data["email_domain"] = check_domain(domain)
    path.write_text(json.dumps(data, indent=2, ensure_ascii=False) + "\n", encoding="utf-8")
    return data["email_domain"]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", metavar="ROSTER", help="read a roster and report")
    parser.add_argument("--domain", help="the course's e-mail domain ('none' to remove it)")
    parser.add_argument("ids", nargs="*", help="ids to resolve with the roster")
    args = parser.parse_args(argv)
    try:
        if args.domain:
            value = set_domain(None if args.domain.lower() == "none" else args.domain)
            print(f"e-mail domain of the course: {value}; now `make exercises` and commit")
        roster = load([args.check] if args.check else [])
    except (OSError, ValueError) as err:
        print(f"instructor.grading.identity: {err}", file=sys.stderr)
        return 2
    if args.check:
        print(f"{args.check}: {len(roster)} students, {len(roster.aliases)} aliases")
    for raw in args.ids:
        got = roster.resolve(raw)
        print(f"{raw!r} -> {got.key!r} ({got.how})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
