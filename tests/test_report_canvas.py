"""Canvas grades from Gradescope's exported scores (instructor/grading/canvas_gradescope.py) and
missing work as 0 or blank on both paths (issue 34): the Canvas layout, a roster's ids, an unknown
id, bad input."""

from __future__ import annotations

import csv
import os
import sys
from pathlib import Path

import pytest
import yaml

from instructor.grading.canvas import IDENTITY, export, main, write_csv
from instructor.grading.canvas_gradescope import export as from_gradescope

ROOT = Path(__file__).resolve().parents[1]

pytestmark = pytest.mark.filterwarnings("ignore::sqlalchemy.exc.SAWarning")

ROSTER = (
    "Student,ID,SIS User ID,SIS Login ID,Section,ps01 (555),ps02\n"
    "    Points Possible,,,,,14,14\n"
    '"Lovelace, Ada",9001,s1,ada@example.edu,A,,\n'
    '"Ross, Bob",9002,s2,bob@example.edu,A,,\n'
    '"Curie, Marie",9003,s3,marie@example.edu,B,,\n'
)


def _export(folder, ps, people):
    data = {}
    for k, (sid, name, score) in enumerate(people):
        tests = [{"name": "bac_cab", "score": score, "max_score": 14.0, "extra_data": {}}]
        data[f"submission_{k}"] = {
            ":submitters": [{":name": name, ":sid": sid, ":email": f"{sid}@example.edu"}],
            ":score": score,
            ":results": {"tests": tests, "extra_data": {"assignment": ps}},
        }
    folder.mkdir(parents=True)
    (folder / "submission_metadata.yml").write_text(yaml.safe_dump(data))
    return folder


def _rows(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.reader(f))


@pytest.fixture
def exports(tmp_path):
    one = _export(tmp_path / "e1", "ps01", [("s1", "Ada L", 14.0), ("s2", "Bob R", 3.5)])
    two = _export(tmp_path / "e2", "ps02", [("s1", "Ada L", 7.0), ("zz", "Who", 1.0)])
    roster = tmp_path / "roster.csv"
    roster.write_text(ROSTER)
    return one, two, roster


def test_gradescope_scores_with_a_roster_missing_blank_and_unknown_listed(exports, tmp_path):
    one, two, roster = exports
    result = from_gradescope([one, two], roster=roster)
    rows = _rows(write_csv(result, tmp_path / "out.csv"))
    assert rows[0] == [*IDENTITY, "ps01 (555)", "ps02"]
    assert rows[1][5:] == ["14", "14"]
    table = {r[2]: r[5:] for r in rows[2:]}
    assert table == {"s1": ["14", "7"], "s2": ["3.5", ""], "s3": ["", ""]}
    assert result.unknown == ["zz"]  # graded on Gradescope, in no roster row
    assert ("Curie, Marie", "ps01") in result.missing
    assert "missing submission: Ross, Bob has no ps02 (blank, not 0)" in result.report()


def test_missing_as_zero_on_both_paths(exports, tmp_path, monkeypatch):
    one, two, roster = exports
    result = from_gradescope([one, two], roster=roster, missing="zero")
    table = {r[2]: r[5:] for r in result.rows[1:]}
    assert table["s3"] == ["0", "0"] and table["s2"] == ["3.5", "0"]
    assert "has no ps02 (0, not blank: --missing zero)" in "\n".join(result.report())
    from report_class import new_gradebook

    monkeypatch.setenv("PATH", f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}")
    course = tmp_path / "course"
    with new_gradebook(course / "gradebook.db") as gb:
        gb.add_assignment("ps01")
        gb.update_or_create_notebook("nb", "ps01")
        gb.update_or_create_grade_cell("a-check", "nb", "ps01", max_score=2, cell_type="code")
        gb.add_student("ada")
    assert export(course, missing="zero").rows[1][5:] == ["0"]
    assert export(course).rows[1][5:] == [""]


def test_command_line_and_bad_input(exports, tmp_path, capsys):
    one, two, roster = exports
    out = tmp_path / "c.csv"
    args = ["--gradescope", str(one), "--gradescope", str(two), "--out", str(out)]
    assert main([*args, "--missing", "zero"]) == 0
    assert _rows(out)[0][5:] == ["ps01", "ps02"]
    assert main(["--gradescope", str(one), "--gradescope", str(one)]) == 2
    assert "two exports of the same problem set" in capsys.readouterr().err
    assert main([]) == 2
    assert "give one of COURSE=DIR" in capsys.readouterr().err
    assert main(["--gradescope", str(tmp_path / "nothing.zip")]) == 2
    assert "does not exist" in capsys.readouterr().err
