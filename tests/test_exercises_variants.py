"""Tests of course_lib.exercises._variants: the student's id and the variant it selects.

Bad ids (empty, unicode, 1,000 characters, white space) give a valid, stable variant; the
same student gets the same variant whatever the spelling of white space and case; the
variants of a class spread over the table; the id's sources have a fixed precedence.
"""

import subprocess
import sys

import pytest

from course_lib.exercises import _variants as V
from course_lib.exercises import identity_line, set_student_id, student_id, variant_index

K = 64


@pytest.fixture(autouse=True)
def _no_ambient_id(monkeypatch):
    monkeypatch.delenv(V.ENV_ID, raising=False)
    monkeypatch.delenv(V.HUB_ID, raising=False)
    monkeypatch.delenv(V.GRADER_ID, raising=False)
    set_student_id(None)
    yield
    set_student_id(None)


BAD_IDS = ["", " ", "\t\n ", "é" * 3, "學生 七", "x" * 1000, "a b", "0", "🙂", "Ａｄａ"]


@pytest.mark.parametrize("raw", BAD_IDS)
def test_bad_ids_give_a_valid_variant_that_is_stable(raw):
    first = variant_index("coords_by_projection", K, raw)
    assert 0 <= first < K and isinstance(first, int)
    again = subprocess.run(
        [
            sys.executable,
            "-c",
            "import sys; from course_lib.exercises._variants import variant_index as v; "
            "print(v('coords_by_projection', 64, sys.argv[1]))",
            raw,
        ],
        capture_output=True,
        text=True,
        check=True,
    )
    assert int(again.stdout) == first  # the same in another process (no hash randomisation)


def test_no_id_or_only_white_space_is_the_default_variant():
    for raw in ("", "   ", "\u3000", None):
        assert variant_index("angle_from_trace", K, raw if raw is not None else "") == 0
    assert variant_index("angle_from_trace", K) == 0  # this kernel: no id set
    assert "No student id is set" in identity_line()
    assert "set_student_id" in identity_line() and "JupyterHub" in identity_line()


def test_spelling_of_case_white_space_and_unicode_width_does_not_change_the_variant():
    base = variant_index("two_half_turns", K, "ada lovelace")
    for raw in ("Ada Lovelace", "  ADA\tLOVELACE ", "ａｄａ lovelace"):
        assert variant_index("two_half_turns", K, raw) == base


def test_a_class_spreads_over_the_table_and_exercises_vary_independently():
    ids = [f"student{i:04d}" for i in range(1000)]
    counts = [0] * K
    for sid in ids:
        counts[variant_index("angle_from_trace", K, sid)] += 1
    assert min(counts) > 0 and max(counts) < 3 * 1000 / K  # every variant used, none crowded
    same = sum(
        variant_index("angle_from_trace", K, s) == variant_index("two_mirrors", K, s) for s in ids
    )
    assert same < 3 * 1000 / K  # the two exercises' variants are not the same index


def test_precedence_grader_then_setter_then_course_variable_then_hub_user(monkeypatch):
    monkeypatch.setenv(V.HUB_ID, "hub-user")
    assert student_id() == ("hub-user", V.HUB_ID)
    monkeypatch.setenv(V.ENV_ID, "Code-17")
    assert student_id() == ("code-17", V.ENV_ID)
    set_student_id("  Given ")
    assert student_id() == ("given", "set_student_id")
    assert variant_index("x", K) == variant_index("x", K, "given")
    assert "given" in identity_line()
    monkeypatch.setenv(V.GRADER_ID, "Graded")  # the grading kernel: the notebook cannot change it
    assert student_id() == ("graded", V.GRADER_ID)


def test_bad_arguments_say_what_was_wrong():
    with pytest.raises(TypeError, match="student id must be a string"):
        set_student_id(17)
    with pytest.raises(TypeError, match="student id must be a string"):
        variant_index("x", K, b"ada")
    for count in (0, -1, 2.0, True):
        with pytest.raises(ValueError, match="count must be a positive integer"):
            variant_index("x", count, "ada")
    assert variant_index("x", 1, "ada") == 0


# ---------------------------------------------------------------- placeholders of a variant

LATEX = r"$R = \begin{pmatrix} <<a>> & 0 \\ 0 & 1 \end{pmatrix}$, $\theta = <<angle>>$"


def _template():
    from course_lib.exercises import Exercise, Value

    return Exercise(
        name="template_demo",
        chapter=4,
        number=9,
        level="core",
        title="A template",
        statement=LATEX,
        answer=Value(shape=()),
        tip="cos <<angle>> first",
        mistakes={"cosine": "that is cos <<angle>>, not the angle"},
    )


def test_a_variant_fills_statement_tip_and_hints_and_keeps_latex_backslashes():
    ex = _template()
    assert ex.placeholders() == ["a", "angle"]
    got = ex.filled({"a": r"\tfrac{1}{2}", "angle": r"\pi/3"})
    assert got.statement == LATEX.replace("<<a>>", r"\tfrac{1}{2}").replace("<<angle>>", r"\pi/3")
    assert got.tip == r"cos \pi/3 first" and got.mistakes["cosine"].startswith(r"that is cos \pi/3")
    assert got.name == ex.name and got.answer == ex.answer and ex.statement == LATEX  # a copy


def test_a_missing_or_unknown_placeholder_value_is_a_clear_error():
    from course_lib.exercises._model import fill_placeholders

    ex = _template()
    with pytest.raises(ValueError, match=r"placeholders \['angle'\]"):
        ex.filled({"a": "1"})
    with pytest.raises(ValueError, match=r"template_demo: .*\['b'\]"):
        ex.filled({"a": "1", "angle": "2", "b": "3"})
    assert fill_placeholders("no placeholder, {braces} and << spaced >>", {}) == (
        "no placeholder, {braces} and << spaced >>"
    )


def test_every_placeholder_of_the_bank_is_a_parameter_of_its_exercise():
    """A <<name>> in a statement, tip or hint that is not a parameter of the exercise's
    variants would reach the students unfilled (regression: placeholders were allowed only once
    the tables existed)."""
    from course_lib.exercises import EXERCISES

    for name, ex in EXERCISES.items():
        defaults = {} if ex.variants is None else ex.variants.default
        assert set(ex.placeholders()) <= set(defaults), name
