"""The class report (issue 34): a planted class of 30 on both paths, every count as planted;
the statistics (Fisher's exact test against scipy's, the discrimination index); privacy of the
shared copy; the page's accessibility basics; bad input (empty course, a set nobody submitted,
an exercise of another course version, a Gradescope export without the grader's notes).

The class is graded once per module through the grader's own preprocessors in this process
(tests/report_class.py; about 10 s); the round trips through real ``nbgrader autograde`` and
the real Gradescope autograder are in tests/test_report_roundtrip.py (slow markers)."""

from __future__ import annotations

import csv
import io
import os
import re
import sys
import time
from pathlib import Path

import pytest
import report_class as RC
import yaml

from instructor.grading import answer_log, gradescope_run
from instructor.grading.report import main, write_reports
from instructor.grading.report_data import (
    apply_roster,
    from_course,
    from_gradescope,
    known,
)
from instructor.grading.report_html import View, csv_text, page
from instructor.grading.report_stats import discrimination, fisher_less, set_stats

ROOT = Path(__file__).resolve().parents[1]


pytestmark = pytest.mark.filterwarnings("ignore::sqlalchemy.exc.SAWarning")


@pytest.fixture(scope="module")
def planted(tmp_path_factory):
    """The planted class graded into a real gradebook: (course, ids)."""
    bin_dir = str(Path(sys.executable).parent)  # nbgrader runs alembic from PATH
    os.environ["PATH"] = f"{bin_dir}{os.pathsep}{os.environ.get('PATH', '')}"
    course = tmp_path_factory.mktemp("planted")
    ids = RC.students()
    points = [RC.grade_one(course, ids, i) for i in range(RC.SIZE)]
    RC.gradebook(course, ids, points)
    return course, ids


def gradescope_export(course, ids, folder, names=True):
    """Gradescope's Export Submissions of the planted class: each submission's results.json
    as ``run_autograder`` writes it (:func:`instructor.grading.gradescope_run.results_for`)."""
    data = {}
    for k, sid in enumerate(ids):
        results = gradescope_run.results_for(course, RC.PS, sid, time.monotonic())
        if not names:
            for test in results["tests"]:
                test.pop("extra_data")
        data[f"submission_{500 + k}"] = {
            ":submitters": [{":name": f"Name {sid.upper()}", ":sid": sid, ":email": ""}],
            ":score": results["score"],
            ":status": "processed",
            ":results": results,
        }
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "submission_metadata.yml").write_text(yaml.safe_dump(data, allow_unicode=True))
    return folder


def assert_as_planted(ps):
    st = set_stats(ps, known)
    assert st.students == RC.SIZE and st.name == RC.PS
    assert [e.name for e in st.exercises] == RC.NAMES
    for e in st.exercises:
        want = RC.expected(e.name)
        got = {
            "students": e.students,
            "right": e.right,
            "mistakes": {k: c for k, c, _ in e.mistakes},
            "groups": [c for _, c, _ in e.unexplained],
            "form": e.form,
            "no_answer": e.no_answer,
            "other_numbers": len(e.other_numbers),
            "never_checked": e.never_checked,
        }
        assert got == want, e.name
        assert all(hint for _, _, hint in e.mistakes), e.name  # the bank's hint text
    hard = {(e.name, v.index) for e in st.exercises for v in e.variants if v.harder}
    six = {RC._variant(RC.HARD, sid) for sid in RC.students()[:6]}
    assert hard == {(RC.HARD, v) for v in six}  # the planted harder variant, and only it
    return st


def test_planted_class_from_the_nbgrader_course_every_count_as_planted(planted):
    course, ids = planted
    (ps,) = from_course(course)
    st = assert_as_planted(ps)
    assert sorted(s for s, _ in ps.missing) == sorted(RC.ABSENT)
    # the three most common known mistakes: 4 x the 4th mistake of angle_from_lengths and of
    # which_are_rigid, then 3 x the 3rd of coords_by_projection (problem-set order breaks ties)
    assert [(ex, key, c) for ex, key, c, _ in st.teach_again] == [
        ("angle_from_lengths", "reversed", 4),
        ("which_are_rigid", "point_reflection", 4),
        ("coords_by_projection", "unnormalized", 3),
    ]
    unexplained = {e.name: e.unexplained for e in st.exercises}
    assert unexplained["coords_by_projection"][0][:2] == ("(0.5, 0.5, 0.5)", 3)
    assert unexplained["which_are_rigid"][0][:2] == ("{a}", 3)


def test_planted_class_from_a_gradescope_export_every_count_as_planted(planted, tmp_path):
    course, ids = planted
    ps = from_gradescope(gradescope_export(course, ids, tmp_path / "export"))
    assert ps.name == RC.PS and ps.notes == []
    assert_as_planted(ps)
    assert {s.name for s in ps.submissions} == {f"Name {sid.upper()}" for sid in ids}


def test_a_roster_lists_missing_work_and_a_wrong_id(planted, tmp_path):
    course, ids = planted
    (ps,) = from_course(course)
    wrong = ps.submissions[3]
    real, wrong.student = wrong.student, "not-a-student"  # handed in under an id Canvas lacks
    rows = [{"Student": f"S {sid}", "ID": str(k), "SIS User ID": sid} for k, sid in enumerate(ids)]
    rows.append({"Student": "Never Came", "ID": "99", "SIS User ID": "late"})
    apply_roster(ps, rows)
    assert ps.unmatched == [("not-a-student", "Name " + real.upper())]
    assert sorted(s for s, _ in ps.missing) == sorted([real, "late"])


def _cells(text):
    return list(csv.reader(io.StringIO(text)))


def test_shared_copy_names_nobody_and_hides_counts_under_five(planted):
    course, ids = planted
    (ps,) = from_course(course)
    st = set_stats(ps, known)
    shared_html, shared_csv = page(ps, st, View(False)), csv_text(ps, st, View(False))
    mine = page(ps, st, View(True))
    for text in (shared_html, shared_csv):
        for sid in [*ids, *RC.ABSENT]:
            assert sid not in text and sid.upper() not in text
    assert f"Name {ids[RC.WRONG_ID].upper()} ({ids[RC.WRONG_ID]})" in mine  # names who did what
    counts = [r[4] for r in _cells(shared_csv)[1:] if r[4]]
    assert all(c == "<5" or c == "0" or int(c) >= 5 for c in counts)
    assert "<5" in counts
    for row in _cells(shared_csv)[1:]:
        assert row[5] in ("", "hidden", "–") or row[4] not in ("<5",)


def test_page_is_offline_and_has_the_accessible_structure(planted):
    course, _ = planted
    (ps,) = from_course(course)
    html = page(ps, set_stats(ps, known), View(True))
    assert html.startswith("<!DOCTYPE html>") and '<html lang="en">' in html
    assert html.count("<h1>") == 1 and "<h2>Teach again</h2>" in html
    assert not re.search(r"(src|href)=\"(https?:)?//", html) and "<script" not in html
    imgs = re.findall(r"<img [^>]*>", html)
    assert len(imgs) == 1 + len(RC.NAMES)
    assert all(re.search(r'alt="[^"]{20,}"', img) and 'src="data:image/png' in img for img in imgs)
    assert html.count("<table>") == html.count("<caption>")
    assert '<th scope="col">' in html and '<th scope="row">' in html


def test_command_line_writes_both_copies(planted, tmp_path, capsys):
    course, ids = planted
    assert main(["--course", str(course), "--out", str(tmp_path / "r")]) == 0
    names = sorted(p.name for p in (tmp_path / "r").iterdir())
    assert names == ["ps01-shared.csv", "ps01-shared.html", "ps01.csv", "ps01.html"]
    assert "30 submissions, 2 missing" in capsys.readouterr().out
    roster = tmp_path / "canvas.csv"
    lines = [f"S {sid},{k},{sid},,A" for k, sid in enumerate(ids[1:])] + ["Late,99,late,,A"]
    roster.write_text("Student,ID,SIS User ID,SIS Login ID,Section\n" + "\n".join(lines))
    args = ["--course", str(course), "--roster", str(roster), "--out", str(tmp_path / "r2")]
    assert main(args) == 0
    out = capsys.readouterr().out
    assert "30 submissions, 1 missing, 1 under an id the roster lacks" in out
    assert f"Id not in the roster: {ids[0]}" in (tmp_path / "r2" / "ps01.html").read_text()


def test_fisher_exact_test_equals_scipys_one_sided():
    stats = pytest.importorskip("scipy.stats")
    for table in [(0, 6, 24, 0), (0, 6, 20, 4), (1, 2, 3, 4), (5, 0, 0, 5), (0, 0, 3, 1)]:
        a, b, c, d = table
        want = stats.fisher_exact([[a, b], [c, d]], alternative="less")[1]
        assert fisher_less(*table) == pytest.approx(want, rel=1e-12), table
    with pytest.raises(ValueError, match="non-negative integers"):
        fisher_less(-1, 0, 0, 0)


def test_discrimination_index_upper_minus_lower():
    assert discrimination([(i, True, str(i)) for i in range(20)]) == 0.0
    assert discrimination([(i, i < 5, str(i)) for i in range(20)]) == -1.0
    assert discrimination([(i, True, str(i)) for i in range(5)]) is None  # too few


def test_empty_course_and_a_set_nobody_submitted(tmp_path, capsys):
    assert main(["--course", str(tmp_path)]) == 2
    assert "no gradebook.db" in capsys.readouterr().err
    with RC.new_gradebook(tmp_path / "gradebook.db"):
        pass
    assert main(["--course", str(tmp_path)]) == 2
    assert "no assignment yet" in capsys.readouterr().err
    with RC.new_gradebook(tmp_path / "gradebook.db") as gb:
        gb.add_assignment("ps02")
        gb.update_or_create_notebook("nb", "ps02")
        gb.update_or_create_grade_cell(
            "hat_product-check", "nb", "ps02", max_score=3, cell_type="code"
        )
        gb.add_student("ada")
    (ps,) = from_course(tmp_path)
    paths = write_reports([ps], tmp_path / "r")
    assert "Nobody submitted ps02" in paths[0].read_text()
    assert ps.missing == [("ada", "")]


def test_a_gradebook_of_another_course_version_notes_each_unknown_exercise(tmp_path):
    with RC.new_gradebook(tmp_path / "gradebook.db") as gb:
        gb.add_assignment("ps01")
        gb.update_or_create_notebook("nb", "ps01")
        for gid in ("bac_cab-check", "old_exercise-check"):
            gb.update_or_create_grade_cell(gid, "nb", "ps01", max_score=2, cell_type="code")
        gb.add_student("ada")
        gb.add_submission("ps01", "ada")
    (ps,) = from_course(tmp_path)
    assert any("'old_exercise' is not an exercise of this course version" in n for n in ps.notes)
    assert not any("'bac_cab'" in n for n in ps.notes)
    html = page(ps, set_stats(ps, known), View(True))
    assert "Not an exercise of this course version" in html


def test_gradescope_export_without_extra_data_or_scores_only_says_so(planted, tmp_path):
    course, ids = planted
    ps = from_gradescope(gradescope_export(course, ids, tmp_path / "bare", names=False), "ps01")
    assert any("30 of 30 submissions have no notes" in n for n in ps.notes)
    grades = tmp_path / "grades.csv"
    grades.write_text(
        "First Name,Last Name,SID,Email,Total Score,Max Points,Status\n"
        "Ada,L,s1,a@x,12,14,Graded\nBob,R,s2,b@x,,14,Missing\n"
    )
    ps = from_gradescope(grades, "ps01")
    assert ps.scores_only and any("scores only" in n for n in ps.notes)
    assert ps.missing == [("s2", "Bob R")] and ps.submissions[0].score == 12
    with pytest.raises(ValueError, match="not a Gradescope grades CSV"):
        from_gradescope(_write(tmp_path / "other.csv", "a,b\n1,2\n"))
    with pytest.raises(ValueError, match="neither a zip, a folder nor a CSV"):
        from_gradescope(_write(tmp_path / "x.json", "{}"))


def _write(path, text):
    path.write_text(text)
    return path


def test_equal_expressions_written_otherwise_are_one_group_of_unexplained_answers():
    from course_lib.exercises import EXERCISES, xx, xy, yy
    from course_lib.exercises.compare import read as _read
    from instructor.grading.diagnose import group_of

    ex = EXERCISES["lagrange_identity"]
    one = group_of(ex, _read(ex, xx * (yy + 1)))
    two = group_of(ex, _read(ex, xx * yy + xx))
    other = group_of(ex, _read(ex, xx * yy + xy))
    assert one[0] == two[0] != other[0]
    assert one[1] == "x·x*(y·y + 1)"


@pytest.mark.parametrize(
    "module",
    [
        "instructor.grading.diagnose",
        "instructor.grading.report_stats",
        "instructor.grading.report_html",
        "instructor.grading.answer_log",
    ],
)
def test_the_examples_in_the_docstrings_run(module):
    import doctest
    import importlib

    failed, tried = doctest.testmod(importlib.import_module(module))
    assert failed == 0 and tried > 0


def test_a_submission_the_autograder_could_not_grade_is_said_not_an_exercise(tmp_path):
    failed = gradescope_run.failure("the autograder failed (RuntimeError: x)", time.monotonic())
    graded = {"tests": [{"name": "bac_cab", "score": 3.0, "max_score": 3.0, "extra_data": {}}]}
    data = {
        "submission_1": {":submitters": [{":sid": "a"}], ":results": failed},
        "submission_2": {":submitters": [{":sid": "b"}], ":results": graded},
    }
    (tmp_path / "submission_metadata.yml").write_text(yaml.safe_dump(data))
    ps = from_gradescope(tmp_path, "ps01")
    assert ps.exercises == ["bac_cab"] and len(ps.submissions) == 2
    assert any("1 submissions were not graded by the autograder" in n for n in ps.notes)
    assert not any("'grading'" in n for n in ps.notes)


def test_a_failing_note_never_changes_the_grade(planted, monkeypatch, tmp_path):
    """Regression guard: the report's notes are taken after the verdict and may fail alone."""
    import instructor.grading.preprocessor as pre

    def broken(*args):
        raise RuntimeError("broken diagnosis")

    course, ids = planted
    right = [i for i in range(RC.SIZE) if all(RC.roles(n)[i] == "right" for n in RC.NAMES)]
    before = RC.grade_one(tmp_path, ids, right[0])
    monkeypatch.setattr(pre, "entry", broken)
    after = RC.grade_one(tmp_path, ids, right[0])
    assert after == before == {n: float(RC.EXERCISES[n].points) for n in RC.NAMES}
    log = answer_log.read(tmp_path, RC.PS)[ids[right[0]]]
    assert log == {}  # the notes are missing, said by the report; the grade is whole


def test_a_wrong_verdict_is_logged_as_wrong_regression_falsy_verdict():
    """The grader's verdict is a CheckResult, false when not correct: the log once read a
    wrong answer's verdict as no verdict at all ("zero")."""
    from course_lib.exercises import EXERCISES, xx, yy
    from course_lib.record import answer_record
    from instructor.grading.diagnose import entry
    from instructor.grading.verify import verdict

    ex = EXERCISES["lagrange_identity"]
    data = answer_record(ex.name, xx * yy + 7)
    logged = entry(ex.name, data, None, verdict(ex.name, data), checked=True)
    assert logged["verdict"] == "wrong" and logged["group"]
