"""The grader's side, without nbgrader: records read with a whitelist, verdicts against the
instructor's solutions at fresh random points (instructor/grading/records.py,
instructor/grading/verify.py), the
record a check cell leaves (course_lib/record.py) and the confined kernel's command."""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from course_lib.exercises import EXERCISES, CheckResult, alpha, check, compare
from course_lib.exercises import _engine as E
from course_lib.record import MIME, CheckFailed, answer_record
from instructor import answers
from instructor.grading import records, sandbox, verify
from instructor.grading.records import Unreadable, parse

ROOT = Path(__file__).resolve().parents[1]

NAMES = list(EXERCISES)


@pytest.mark.parametrize("name", NAMES)
def test_the_reference_solution_is_correct_and_every_known_mistake_is_not(name):
    ns = answers.worked(name)
    ex = EXERCISES[name]
    assert verify.verdict(name, answer_record(name, ns[ex.answer_variable])).ok
    for mid, expr in answers.mistakes(ex.chapter).get(name, {}).items():
        got = verify.verdict(name, answer_record(name, eval(expr, ns)))
        assert not got.ok, (mid, got)


def test_an_answer_fitted_to_the_checkers_seeded_points_is_wrong_at_fresh_points():
    """composed_angle = cos of a composed angle in α and β, replaced by a trigonometric
    polynomial in α alone through its values at the checker's 40 seeded points."""
    name = "composed_angle"
    spec = EXERCISES[name].answer
    pts, _ = E.points(name, spec)
    ref = answers.worked(name)["answer_" + name]
    f = sp.lambdify(sorted(ref.free_symbols, key=str), ref)
    target = f(pts[alpha], pts[E.base_symbols(spec)[1]])
    a = pts[alpha]
    k = (len(a) - 1) // 2  # harmonics: as many terms as seeded points
    cols = [np.ones_like(a)] + [g(n * a) for n in range(1, k + 1) for g in (np.cos, np.sin)]
    harmonics = [(n, g) for n in range(1, k + 1) for g in (sp.cos, sp.sin)]
    if len(cols) < len(a):
        cols.append(np.cos((k + 1) * a))
        harmonics.append((k + 1, sp.cos))
    # least squares: the seeded points repeat α where only β is redrawn
    coef = np.linalg.lstsq(np.stack(cols, -1), target, rcond=None)[0]
    terms = [sp.Float(coef[0])] + [
        sp.Float(c) * g(n * alpha) for c, (n, g) in zip(coef[1:], harmonics)
    ]
    fitted = sp.Add(*terms)
    got = verify.verdict(name, answer_record(name, fitted))
    assert got.status == "wrong" and "fresh random points" in got.message


def test_fresh_points_are_new_on_every_draw_and_not_the_checkers():
    spec = EXERCISES["hat_fifth"].answer
    rng = np.random.default_rng()
    one, two = compare.fresh_points(spec, rng), compare.fresh_points(spec, rng)
    seeded, _ = E.points("hat_fifth", spec)
    assert set(one) == set(seeded)
    for s in one:
        assert not np.isin(one[s], two[s]).any() and not np.isin(one[s], seeded[s]).any()


def test_fresh_points_come_from_the_domain_of_the_checkers_seeded_points():
    """One sample domain for the checker and the grader (the grader kept a copy of its own)."""
    spec = EXERCISES["composed_angle"].answer
    fresh = compare.fresh_points(spec, np.random.default_rng(1), 400)
    seeded, near = E.points("composed_angle", spec)
    for s in fresh:
        far = seeded[s][~near]
        assert far.min() - 1 < fresh[s].min() and fresh[s].max() < far.max() + 1, s
        assert np.abs(fresh[s]).max() <= 4 * np.pi
    spec = EXERCISES["half_turn"].answer  # ω a unit vector
    fresh = compare.fresh_points(spec, np.random.default_rng(2), 50)
    w = np.stack([fresh[s] for s in E.base_symbols(spec) if s.name.startswith("omega")], -1)
    assert np.allclose(np.linalg.norm(w, axis=-1), 1)


def test_the_graders_verdict_is_the_checkers_result_type():
    ex = EXERCISES["hat_fifth"]
    right = verify.verdict(
        ex.name, answer_record(ex.name, answers.worked(ex.name)["answer_hat_fifth"])
    )
    forged = verify.verdict(ex.name, {"version": 1, "exercise": "other"})
    assert type(right) is type(forged) is CheckResult
    assert right.ok and right.status == "correct" and str(right).startswith("✓")
    assert not forged.ok and forged.status == "forged" and "another exercise" in forged.message


@pytest.mark.parametrize(
    "text",
    [
        "__import__('os').system('true')",
        "Symbol('x').__class__",
        "(lambda: 1)()",
        "Integer(10**40)",
        "Integer(" + "9" * 40 + ")",
        "Pow(Integer(2), Integer(100000000000000000000000000000))",
        "Float('nan')",
        "Float('1e400')",
        "Symbol('x', evil=True)",
        "Symbol('x', **{'real': True})",
        "eval('1')",
        "Add(" * 300 + "Integer(1)" + ")" * 300,
        "[" * 300 + "]" * 300,
        "Integer(1) + Integer(2)",
        "x" * 300_000,
        "Rational(1, 0)",
    ],
)
def test_forged_record_text_is_refused_within_a_second_without_evaluating_it(text):
    start = time.perf_counter()
    with pytest.raises(Unreadable, match="^record: "):
        parse(text)
    assert time.perf_counter() - start < 1.0


BIG = f"Integer({10**30})"
NESTED_POW = f"Pow(Pow(Pow({BIG}, Integer(64)), Integer(64)), Integer(64))"


@pytest.mark.parametrize(
    "text",
    [
        f"ImmutableDenseMatrix([[{NESTED_POW}]])",
        NESTED_POW.replace(BIG, f"Mul({BIG}, Symbol('x'))"),
        "Mul(" + ", ".join([f"Pow(Integer({10**30}), Integer(64))"] * 8) + ")",
        "Add(" + ", ".join([f"Pow(Rational(1, {10**30}), Integer(64))"] * 8) + ")",
    ],
)
def test_nested_pow_record_is_refused_within_a_second_regression_issue17(text):
    """A nested Pow of a large base took 20 s of the grader's CPU per record."""
    start = time.perf_counter()
    with pytest.raises(Unreadable, match="bits"):
        parse(text)
    assert time.perf_counter() - start < 1.0


def test_parse_reads_back_what_srepr_writes():
    from course_lib.exercises import W, omega, theta

    for obj in (
        sp.sin(theta) * W + (1 - sp.cos(theta)) * W**2,
        sp.ImmutableMatrix([[sp.pi / 3, sp.Rational(-1, 2)], [sp.Float(0.25), sp.E]]),
        omega.dot(omega) ** 2 * sp.Identity(3) - W.T,
    ):
        assert sp.srepr(parse(sp.srepr(obj))) == sp.srepr(obj)
    assert set(records.CONSTRUCTORS) >= {"Add", "Mul", "Pow", "MatMul", "ImmutableDenseMatrix"}


@pytest.mark.parametrize(
    ("data", "status"),
    [
        ({"version": 1, "exercise": "hat_fifth", "kind": "none", "answer": None}, "no answer"),
        ({"version": 1, "exercise": "hat_cubed", "kind": "matrix", "answer": "W"}, "forged"),
        ({"exercise": "hat_fifth", "kind": "matrix", "answer": "Integer(1)"}, "forged"),
        ({"version": 1, "exercise": "hat_fifth", "kind": "pickle", "answer": "x"}, "forged"),
        ({"version": 1, "exercise": "hat_fifth", "kind": "unreadable"}, "malformed"),
        (
            {"version": 1, "exercise": "hat_fifth", "kind": "explicit", "answer": "Symbol('q')"},
            "malformed",
        ),
        ([1, 2], "forged"),
    ],
)
def test_a_record_that_is_missing_forged_or_of_another_exercise_is_not_correct(data, status):
    got = verify.verdict("hat_fifth", data)
    assert got.status == status and not got.ok and "\n" not in got.message


def test_the_asked_form_is_checked_by_the_grader_too():
    from course_lib.exercises import W

    right_value_wrong_form = W**5  # hat_fifth asks for degree at most 2 in W
    got = verify.verdict("hat_fifth", answer_record("hat_fifth", right_value_wrong_form))
    assert got.status == "form" and "reduce the higher powers" in got.message
    assert check("hat_fifth", right_value_wrong_form).status == "form"


def test_the_record_holds_only_the_students_answer_and_a_failed_check_is_one_line():
    rec = answer_record("angle_from_lengths", 1.0)
    assert rec["kind"] == "explicit"
    assert rec["answer"] == "ImmutableDenseMatrix([[Float('1.0', precision=53)]])"
    assert answer_record("which_in_so3", None)["kind"] == "none"
    assert answer_record("which_in_so3", {"b", "a"})["answer"] == "ab"
    assert answer_record("hat_fifth", object())["kind"] == "unreadable"
    assert MIME.startswith("application/vnd.") and MIME.endswith("+json")
    err = CheckFailed("✗ hat_fifth: a hint that is long " + "and whole " * 30)
    lines = err._render_traceback_()
    assert len(lines) == 1 and lines[0].endswith("and whole ") and isinstance(err, AssertionError)


def test_the_confined_kernel_command_is_an_allow_list_without_network_or_privileges():
    cmd = sandbox.bwrap_command(["/venv", "/repo/course_lib"], "/tmp/k1", ["-f", "/tmp/k1/c.json"])
    text = " ".join(cmd)
    assert "--ro-bind / /" not in text and "--remount-ro /" in text
    assert "--ro-bind /repo/course_lib /repo/course_lib" in text and "/repo " not in text
    assert "--bind /tmp/k1 /tmp/k1" in text and "--size" in text
    for flag in ("--unshare-all", "--die-with-parent", "--new-session", "--clearenv"):
        assert flag in text
    assert "--cap-drop ALL" in text and "--share-net" not in text
    python = cmd.index("--") + 1
    assert cmd[python + 1] == "-P" and "import course_lib" in cmd[python + 3]
    assert cmd[-2:] == ["-f", "/tmp/k1/c.json"]


def test_make_course_writes_the_config_and_every_problem_set_and_refuses_stale_check_cells(
    tmp_path,
):
    from instructor.grading import course

    names = course.write_course(tmp_path / "c")
    assert names == [p.name[:4] for p in sorted((ROOT / "problem_sets").glob("ps*.ipynb"))]
    config = (tmp_path / "c" / "nbgrader_config.py").read_text()
    for word in ("ConfinedExecute", "VerifyRecords", "GuardCells", "ConfinedKernelManager.hide"):
        assert word in config
    compile(config, "nbgrader_config.py", "exec")
    assert str((tmp_path / "c").resolve()) in config and str(ROOT) in config
    fake = tmp_path / "repo"
    (fake / "problem_sets").mkdir(parents=True)
    import nbformat

    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("assert check('x', 1)")])
    nb.cells[0].id = "x-check"
    nbformat.write(nb, fake / "problem_sets" / "ps01_x.ipynb")
    with pytest.raises(ValueError, match="regenerate the problem sets"):
        course.write_course(tmp_path / "d", root=fake)
    with pytest.raises(ValueError, match="outside the repository"):
        course.write_course(ROOT / "build" / "course")


def test_record_shows_the_verdict_leaves_one_record_and_a_wrong_answer_stops_with_the_hint(
    monkeypatch,
):
    import IPython.display

    from course_lib.exercises import W
    from course_lib.record import record

    shown = []
    monkeypatch.setattr(IPython.display, "display", lambda data, raw: shown.append((data, raw)))
    right = answers.worked("hat_fifth")["answer_hat_fifth"]
    assert record("hat_fifth", right, check("hat_fifth", right)) is None
    ((data, raw),) = shown
    assert raw and data["text/plain"] == "✓ hat_fifth: correct."
    assert verify.verdict("hat_fifth", data[MIME]).ok
    shown.clear()
    with pytest.raises(CheckFailed, match="^✗ hat_fifth: your answer is the negative"):
        record("hat_fifth", -right, check("hat_fifth", -right))
    ((data, raw),) = shown
    assert data["text/plain"] == "" and data[MIME]["kind"] == "matrix"
    assert verify.verdict("hat_fifth", data[MIME]).status == "wrong"
    assert W in parse(data[MIME]["answer"]).free_symbols


def test_a_record_of_the_wrong_kind_is_forged_regression_unwhitelisted_choice_kind():
    """A "choice" record skips the whitelist of records.parse (its answer is letters): on an
    exercise that asks for numbers it once reached the reader raw, and the right numbers as a
    JSON list were graded correct. A kind that does not fit the exercise is now forged."""
    ex = EXERCISES["coords_by_projection"]
    right = [float(v) for v in np.ravel(np.asarray(answers.worked(ex.name)[ex.answer_variable]))]
    data = {"version": 1, "exercise": ex.name, "kind": "choice", "answer": right}
    got = verify.verdict(ex.name, data)
    assert got.status == "forged" and "kind 'choice'" in got.message
    letters = next(e for e in EXERCISES.values() if e.answer.__class__.__name__ == "Choice")
    data = {"version": 1, "exercise": letters.name, "kind": "explicit", "answer": "1"}
    assert verify.verdict(letters.name, data).status == "forged"
