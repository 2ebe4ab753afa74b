"""Canvas grades from Gradescope's exported scores (``make grades-canvas GRADESCOPE=...``).

Each export (*Export Submissions* zip or folder, or the *Download Grades* CSV,
:func:`instructor.grading.report_data.from_gradescope`) is one problem set; a student's score is
Gradescope's total of the submission. The CSV is :mod:`instructor.grading.canvas`'s: the same
columns, the same matching to a Canvas roster (by SIS User ID, SIS Login ID, Canvas ID or e-mail),
the same report of missing submissions and unknown students, missing work blank or 0 (``missing``).
"""

from __future__ import annotations

from types import SimpleNamespace

from .canvas import IDENTITY, POINTS_ROW, Export, _column, _match, read_roster
from .report_data import from_gradescope

__all__ = ["export"]


def _sets(exports, assignments):
    names = list(assignments or [])
    if names and len(names) != len(exports):
        raise ValueError("ASSIGNMENT: name one problem set per Gradescope export, or none")
    sets = [from_gradescope(p, names[k] if names else None) for k, p in enumerate(exports)]
    seen = [ps.name for ps in sets]
    if len(set(seen)) != len(seen):
        raise ValueError(f"GRADESCOPE: two exports of the same problem set ({seen})")
    return sets


def _people(sets):
    """``{student id: SimpleNamespace(id, email, name)}`` of every student of the exports."""
    people = {}
    for ps in sets:
        for sub in ps.submissions:
            people.setdefault(sub.student, SimpleNamespace(id=sub.student, email=sub.email))
            people[sub.student].name = sub.name or getattr(people[sub.student], "name", "")
        for sid, name in ps.missing:
            people.setdefault(sid, SimpleNamespace(id=sid, email="", name=name))
    return people


def export(exports, assignments=None, roster=None, missing="blank"):
    """An :class:`instructor.grading.canvas.Export` of the scores of Gradescope ``exports``
    (paths)."""
    sets = _sets(exports, assignments)
    fields, rows = read_roster(roster) if roster else (None, None)
    cols = [_column(ps.name, fields) for ps in sets]
    out = Export([*IDENTITY, *cols], [[POINTS_ROW, "", "", "", ""]])
    out.rows[0] += [f"{ps.max_score:g}" for ps in sets]
    scores = {(s.student, ps.name): s.score for ps in sets for s in ps.submissions}
    people = []
    for sid, who in _people(sets).items():
        row = _match(who, rows) if rows is not None else None
        if rows is not None and row is None:
            if any((sid, ps.name) in scores for ps in sets):
                out.unknown.append(sid)
            continue
        ident = [row.get(c, "") for c in IDENTITY] if row else [who.name or sid, "", sid, "", ""]
        people.append((ident, sid))
    if rows is not None:
        taken = {tuple(ident) for ident, _ in people}
        people += [
            ([r.get(c, "") for c in IDENTITY], None)
            for r in rows
            if tuple(r.get(c, "") for c in IDENTITY) not in taken
        ]
    empty = "0" if missing == "zero" else ""
    for ident, sid in people:
        cells = []
        for ps in sets:
            score = scores.get((sid, ps.name))
            if score is None:
                out.missing.append((ident[0] or sid, ps.name))
            cells.append(empty if score is None else f"{score:g}")
        out.rows.append([*ident, *cells])
    out.missing_as = missing
    return out
