"""Tests of course_lib.exercises and the exercise bank.

Every exercise: the reference solution passes, equivalent forms pass, every known mistake fails
with its own hint, and no message shows the expected answer. The problem set has the size and
shape the course promises. The regression tests at the end are named after the ways the old
checkers were fooled (lazy answers, tolerance, subclasses, truncated series, readable answers,
hostile input).
"""

import inspect
import itertools
import json
import re
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import course_lib
from course_lib import exercise_bank
from course_lib import exercises as EX
from course_lib import symbolic as S
from course_lib.exercises import (
    EXERCISES,
    A,
    B,
    CheckResult,
    Choice,
    Value,
    W,
    alpha,
    beta,
    check,
    exercises,
    get,
    hat,
    names,
    omega,
    t,
    theta,
    u,
    variant,
    x,
    xx,
    xy,
    y,
    yy,
)
from instructor.answers import worked
from instructor.build import exercise_fingerprints as F

ROOT = Path(__file__).resolve().parents[1]

I3 = sp.eye(3)
N2 = omega.dot(omega)
MARKERS = ("BEGIN SOLUTION", "END SOLUTION", "BEGIN HIDDEN TESTS", "END HIDDEN TESTS")


def reference(name):
    """(namespace, answer) of the instructor's reference solution."""
    ns = worked(name)
    return ns, ns[get(name).answer_variable]


def mistakes():
    for ex in EXERCISES.values():
        _, ms = F.solutions(ex.chapter)
        for mid, code in ms.get(ex.name, {}).items():
            yield ex.name, mid, code


def right(name):
    """The reference answer of ``name``, from instructor/answers (never written out in a test)."""
    return reference(name)[1]


def _sig(v, digits):
    return float(f"{float(v):.{digits}g}")


def _flat_numbers(answer):
    if isinstance(answer, sp.Expr) or np.ndim(answer) == 0:  # a sympy or numpy scalar
        return [answer]
    return list(sp.Matrix(answer))


def equivalent_forms(name):
    """The reference answer written in other forms: other containers, floats, 11 significant
    digits, expanded, with a zero matrix or an identity factor."""
    spec, answer = get(name).answer, right(name)
    if isinstance(spec, Choice):
        letters = sorted(answer)
        return ["".join(letters), ", ".join(reversed(letters)), letters, frozenset(letters)]
    if isinstance(spec, Value):
        exact = [sp.sympify(v) for v in _flat_numbers(answer)]
        floats = np.array([float(v) for v in exact])
        if spec.shape == ():
            return [exact[0], floats[0], np.float64(floats[0]), _sig(floats[0], 11)]
        rows, cols = spec.shape if len(spec.shape) == 2 else (spec.shape[0], 1)
        typed = np.array([_sig(v, 11) for v in floats]).reshape(spec.shape)
        return [
            floats.reshape(spec.shape),
            floats.reshape(spec.shape).tolist(),
            sp.Matrix(rows, cols, exact),
            tuple(typed.tolist()),
        ]
    if isinstance(answer, sp.MatrixExpr) and not isinstance(answer, sp.MatrixBase):
        n = spec.shape[0]
        return [answer + sp.ZeroMatrix(*answer.shape), sp.Identity(n) * answer]
    if isinstance(answer, sp.Expr):
        return [sp.expand(answer), answer * sp.Integer(2) / 2]
    if isinstance(answer, sp.MatrixBase):
        return [answer.applyfunc(sp.expand), list(answer)]
    return [[sp.expand(e) for e in answer], tuple(answer)]


# ----------------------------------------------------------------------------- the problem set


def test_the_problem_set_has_30_exercises_6_per_chapter_and_6_challenges():
    assert len(EXERCISES) >= 30
    for chapter in exercise_bank.CHAPTERS:
        assert len(exercises(chapter)) >= 6, chapter
    levels = [ex.level for ex in EXERCISES.values()]
    assert levels.count("challenge") >= 6
    assert {"warm-up", "core", "challenge"} <= set(levels)


def test_every_exercise_is_complete_labels_unique_and_points_by_level():
    labels = [ex.label for ex in EXERCISES.values()]
    assert len(set(labels)) == len(labels)
    assert names() == list(EXERCISES)
    for name, ex in EXERCISES.items():
        assert ex.name == name and ex.title and ex.statement.strip() and ex.tip
        assert ex.points == {"warm-up": 1, "core": 2, "challenge": 3}[ex.level]
        md = ex.markdown()
        assert md.startswith(f"### Exercise {ex.label} ({ex.level}, {ex.points} point")
        assert ex.answer_variable in md
        assert ex._repr_markdown_() == md


def test_no_statement_or_hint_mentions_the_nbgrader_marker_words():
    for ex in EXERCISES.values():
        texts = [ex.markdown(), ex.tip, *ex.mistakes.values()]
        for text in texts:
            for marker in MARKERS:
                assert marker not in text.upper(), (ex.name, marker)


def test_every_exercise_has_a_reference_solution():
    for chapter in exercise_bank.CHAPTERS:
        sols, ms = F.solutions(chapter)
        assert set(sols) == set(names(chapter))
        assert set(ms) <= set(sols)


def test_exercises_rejects_an_unknown_chapter_and_check_an_unknown_name():
    with pytest.raises(ValueError, match="chapter must be one of"):
        exercises(99)
    with pytest.raises(KeyError, match="known exercises"):
        check("hat_fith", None)


def test_stored_fingerprints_are_those_of_the_reference_solutions():
    """instructor/build/exercise_fingerprints.py --check on a sample: every exercise's default and
    8 rows of every variant table, recomputed from the solutions, are what the package holds (the
    whole of 22 tables of 1,024 rows takes minutes; ``--check`` does it)."""
    stored = EX._fingerprints()
    built = F.build(sample=lambda n: range(1, n, n // 8), jobs=1)
    assert len(built) > len(EXERCISES)
    for name, record in built.items():
        assert stored[name] == json.loads(json.dumps(record, sort_keys=True)), name


# ----------------------------------------------------------------------------- right answers


@pytest.mark.parametrize("name", list(EXERCISES))
def test_reference_solution_passes(name):
    result = check(name, reference(name)[1])
    assert result.ok and result.status == "correct", str(result)
    assert str(result) == f"✓ {name}: correct."


@pytest.mark.parametrize("name", list(EXERCISES))
def test_equivalent_forms_pass(name):
    forms = equivalent_forms(name)
    assert len(forms) >= 2
    for answer in forms:
        result = check(name, answer)
        assert result.ok, (answer, str(result))


# ----------------------------------------------------------------------------- mistakes


def _solution_texts(name):
    """Printable forms of the expected answer that must never appear in a message."""
    _, answer = reference(name)
    spec = get(name).answer
    if isinstance(spec, Choice):
        return set()
    if isinstance(spec, Value):
        vals = np.ravel(
            np.asarray(
                sp.Matrix(answer)
                if not np.isscalar(answer) and not isinstance(answer, sp.Expr)
                else [answer],
                dtype=float,
            )
        )
        return {f"{v:.6g}" for v in vals if abs(v) not in (0.0, 1.0)}
    texts = {str(answer), sp.latex(answer)}
    if isinstance(answer, sp.MatrixBase):
        texts |= {str(e) for e in answer if len(str(e)) > 6}
    return {s for s in texts if len(s) >= 4}


@pytest.mark.parametrize("name, mid, code", list(mistakes()))
def test_known_mistake_fails_with_its_own_hint(name, mid, code):
    ns, _ = reference(name)
    result = check(name, eval(code, ns))
    assert not result.ok and result.status == "wrong", str(result)
    assert variant(name)[0].mistakes[mid] in result.message  # with this variant's numbers
    assert result.message.count("Hint:") == 1
    for text in _solution_texts(name):
        assert text not in result.message


def _other(v, k):
    """v with its entry k changed."""
    out = np.array([float(e) for e in _flat_numbers(v)])
    out[k] += 1
    return out


def _floats(v):
    """A numeric reference answer as a float array."""
    return np.array([float(e) for e in _flat_numbers(v)])


def _times_rows(v, signs):
    return np.array(v, dtype=float) * np.array(signs)[:, None]


# Wrong answers made from the reference answer r (a function of r), with the hint they get.
WRONG = [
    ("hat_fifth", lambda r: -r * W, "symmetric, but the right one is skew"),
    ("hat_fifth", lambda r: -W, "a factor that changes with the symbols"),
    ("hat_fifth", lambda r: -r, "negative of the right one"),
    ("half_turn", lambda r: r + sp.Identity(3), "multiple of the identity"),
    ("half_turn", lambda r: r + sp.Identity(3), "ω₁² + ω₂² + ω₃² = 1"),
    ("inverse_of_product", lambda r: 2 * r, "constant multiple"),
    ("motion_from_points", lambda r: 2 * np.array(r), "not orthonormal"),
    ("motion_from_points", lambda r: _times_rows(r, [1, 1, -1]), "det R = −1"),
    # the images written as rows: R was symmetric before, so this went unnoticed
    ("motion_from_points", lambda r: np.array(r).T, "transpose"),
    ("compose_frames", lambda r: np.array(r).T, "transpose"),
    ("angle_from_lengths", lambda r: float(r) * 180 / np.pi, "degrees"),
    ("angle_from_lengths", lambda r: float(r) + 2 * np.pi, "full turn"),
    ("angle_from_trace", lambda r: 2 * sp.pi - r, "2π minus the right one"),
    ("vb_from_va", lambda r: _other(r, 2), "at least one component is wrong"),
    ("unit_tangent", lambda r: 2 * r, "not a unit vector"),
    ("unit_tangent", lambda r: [-sp.sin(t), sp.cos(t), 0], "does not point along ṗ(t)"),
    ("ode_shifted", lambda r: [r[0], 2 * r[1]], "put t = 1 into (106) and solve for x(0)"),
    # issue 37: (1, 0, 0) is the line of the yaw and roll columns, not their normal
    ("unreachable_omega", lambda r: [1, 0, 0], "yaw and roll columns of E both lie along it"),
    ("unreachable_omega", lambda r: 1.5 * _floats(r), "length 1.5: it must be a unit vector"),
    ("quaternion_of_turn", lambda r: _floats(r) + [0.2, 0, 0, 0], "must be a unit vector"),
    ("compose_quaternions", lambda r: 0.5 * _floats(r), "must be a unit vector"),
    # issue 37: an angle outside the statement's range is told so, per entry
    ("proper_euler_angles", lambda r: _floats(r) + [0, 2 * np.pi, 0], "β = "),
    ("proper_euler_angles", lambda r: _floats(r) + [0, 2 * np.pi, 0], "outside [−π, 0]"),
    ("angle_from_ros", lambda r: 4.0, "θ = 4 lies outside [0, π]"),
    ("angle_between_quaternions", lambda r: -0.5, "outside [0, π]"),
    (
        "spatial_angular_velocity",
        lambda r: [r[0], r[1], sp.Pow(r[2] ** 2, sp.S.Half, evaluate=False)],
        "not over their whole range",
    ),
    ("planar_ode", lambda r: _other(r, 1), "at least one component is wrong"),
    ("which_are_rigid", lambda r: "b", "not the right set"),
]


@pytest.mark.parametrize("name, make, fragment", WRONG, ids=[f"{n}-{f[:20]}" for n, _, f in WRONG])
def test_wrong_answer_gets_the_hint_derived_from_its_fingerprint(name, make, fragment):
    result = check(name, make(right(name)))
    assert not result.ok and result.status == "wrong", str(result)
    assert fragment in result.message, str(result)


# ----------------------------------------------------------------------------- the asked form


def explicit(r):
    """A matrix expression in W or u written out as an explicit matrix."""
    return sp.ImmutableMatrix(r.xreplace({W: sp.ImmutableMatrix(hat(omega)), u: omega}).doit())


@pytest.mark.parametrize(
    "name, answer, fragment",
    [
        ("hat_fifth", W**5, "reduce the higher powers first"),
        ("hat_fifth", hat(omega) ** 5, "you gave explicit entries"),
        ("half_turn", S.rodrigues().subs(theta, sp.pi), "you gave explicit entries"),
        ("half_turn", lambda: explicit(right("half_turn")), "you gave explicit entries"),
        (
            "rodrigues_derivative",
            W * (I3 + sp.sin(theta) * W + (1 - sp.cos(theta)) * W**2),
            "reduce the higher powers first",
        ),
        ("rodrigues_derivative", sp.diff(S.rodrigues(), theta), "you gave explicit entries"),
        ("lagrange_identity", sp.expand(x.cross(y).dot(x.cross(y))), "your answer uses x_1"),
        (
            "unit_tangent",
            sp.diff(sp.Matrix([sp.cos(2 * t), sp.sin(2 * t), 3 * t]), t)
            / sp.Matrix([sp.cos(2 * t), sp.sin(2 * t), 3 * t]).diff(t).norm(),
            "root",
        ),
        (
            "exp_general_axis",
            lambda: explicit(right("exp_general_axis")),
            "you gave explicit entries",
        ),
    ],
)
def test_right_value_in_the_wrong_form_is_not_accepted(name, answer, fragment):
    result = check(name, answer() if callable(answer) else answer)
    assert not result.ok and result.status == "form", str(result)
    assert "right value, but the exercise asks for" in result.message
    assert fragment in result.message, str(result)


# ----------------------------------------------------------------------------- malformed input


@pytest.mark.parametrize(
    "name, answer, status, fragment",
    [
        ("hat_fifth", None, "no answer", "answer_hat_fifth"),
        ("lagrange_identity", "xx*yy - xy**2", "malformed", "string"),
        ("vb_from_va", [1, 2], "malformed", "expected a 3-vector, got a 2-vector"),
        ("motion_from_points", np.zeros((3, 3, 3)), "malformed", "shape (3, 3, 3)"),
        ("vb_from_va", [0, sp.nan, 3], "malformed", "nan or infinity"),
        ("vb_from_va", [0, float("inf"), 3], "malformed", "nan or infinity"),
        ("vb_from_va", [0, sp.sqrt(2) * sp.I, 3], "malformed", "complex"),
        ("vb_from_va", [0, sp.Symbol("s"), 3], "malformed", "a number is expected"),
        ("vb_from_va", np.array([True, False, True]), "malformed", "truth values"),
        ("vb_from_va", [[1, 2], [3]], "malformed", "different lengths"),
        ("composed_angle", sp.Eq(sp.Symbol("x"), 1), "malformed", ".rhs"),
        ("composed_angle", sp.Function("f")(alpha), "not allowed", "not allowed here"),
        ("composed_angle", sp.cos(sp.Symbol("alpha")), "malformed", "not the one of the course"),
        ("composed_angle", sp.cos(theta), "malformed", "does not belong"),
        ("composed_angle", alpha / (beta - beta), "malformed", "nan or infinity"),
        ("composed_angle", sp.sqrt(-1 - alpha**2), "malformed", "complex"),
        ("which_are_rigid", {"b", "z"}, "malformed", "not one of the letters"),
        ("which_are_rigid", 3, "malformed", "set of letters"),
        ("two_mirrors", lambda: 0, "malformed", "function"),
    ],
)
def test_malformed_answer_gets_a_clear_message(name, answer, status, fragment):
    result = check(name, answer)
    assert not result.ok and result.status == status, str(result)
    assert fragment in result.message, str(result)


def test_a_string_answer_is_never_evaluated():
    import builtins

    check("lagrange_identity", "__import__('builtins').setattr(__import__('builtins'), 'PW', 1)")
    assert not hasattr(builtins, "PW")


def test_check_result_is_a_verdict_with_a_status():
    from course_lib._verdict import Verdict

    r = check("vb_from_va", right("vb_from_va"))
    assert isinstance(r, Verdict) and isinstance(r, CheckResult)
    assert bool(r) and r._repr_markdown_() == "**✓** vb_from_va: correct."


# ----------------------------------------------------------------------------- properties


@settings(max_examples=20, deadline=None)
@given(st.integers(-3, 3), st.lists(st.integers(-2, 2), min_size=9, max_size=9))
def test_adding_what_vanishes_on_the_unit_sphere_keeps_an_answer_right(k, entries):
    extra = k * (N2 - 1) * sp.Matrix(3, 3, entries)
    assert check("half_turn", right("half_turn") + extra).status in ("correct", "form")


@settings(max_examples=25, deadline=None)
@given(st.floats(0.0, 0.9), st.integers(0, 2))
def test_numbers_within_tol_pass_and_numbers_4_tol_away_fail(size, which):
    answer = np.array([float(v) for v in right("vb_from_va")])
    near, far = answer.copy(), answer.copy()
    near[which] += size * EX._engine.TOL
    far[which] += (4.0 + size) * EX._engine.TOL
    assert check("vb_from_va", near).ok
    assert not check("vb_from_va", far).ok


@settings(max_examples=20, deadline=None)
@given(st.floats(0.1, 5.0).filter(lambda c: abs(c - 1) > 1e-3))
def test_a_scaled_symbolic_answer_is_a_constant_multiple(c):
    result = check("rodrigues_derivative", sp.Float(c) * right("rodrigues_derivative"))
    assert not result.ok and "constant multiple" in result.message


# ----------------------------------------------------------------------------- regressions


def test_regression_tolerance_cannot_be_set_by_the_student():
    with pytest.raises(TypeError):
        check("vb_from_va", 0, tol=1e6)  # the old check(name, 0, tol=1e6) passed
    assert "tol" not in inspect.signature(check).parameters


def test_regression_sympy_subclass_with_its_own_add_is_not_allowed():
    class Zero(sp.Symbol):
        def __add__(self, other):
            return sp.Integer(0)

        __radd__ = __sub__ = __rsub__ = __add__

    class ZeroMatrix(sp.ImmutableMatrix):
        def __sub__(self, other):
            return sp.zeros(3, 3)

    for name in ("ode_shifted", "composed_angle", "lagrange_identity"):
        result = check(name, Zero("q"))
        assert result.status == "not allowed" and "class of your own" in result.message
    result = check("rodrigues_derivative", ZeroMatrix(sp.eye(3)))
    assert result.status == "not allowed"


def test_regression_list_and_float_subclasses_are_not_allowed():
    class L(list):
        pass

    class Fl(float):
        def __eq__(self, other):
            return True

    assert check("vb_from_va", L(right("vb_from_va"))).status == "not allowed"
    assert check("two_mirrors", Fl(0.0)).status == "not allowed"


RIGHT_COS = right("composed_angle")


def _cos_angle(c_alpha):
    """The answer to composed_angle with cos α replaced by c_alpha."""
    return RIGHT_COS.subs(sp.cos(alpha), c_alpha)


@pytest.mark.parametrize(
    "fake",
    [
        _cos_angle(sum((-1) ** k * alpha ** (2 * k) / sp.factorial(2 * k) for k in range(9))),
        _cos_angle(sum((-1) ** k * alpha ** (2 * k) / sp.factorial(2 * k) for k in range(14))),
        RIGHT_COS + sp.floor(alpha**2 / 1000),
        RIGHT_COS * (1 + sp.Heaviside(alpha - 10)),
        RIGHT_COS + sp.Mod(alpha, 100) - alpha,
        sp.Piecewise((RIGHT_COS, alpha < 3), (0, True)),
        sp.Integral(sp.diff(RIGHT_COS, alpha), alpha),
        sp.Abs(RIGHT_COS),
    ],
)
def test_regression_truncated_series_and_piecewise_fakes_fail(fake):
    assert check("composed_angle", RIGHT_COS).ok
    result = check("composed_angle", fake)
    assert not result.ok and result.status in ("wrong", "not allowed", "too complex"), str(result)


def test_regression_truncated_rodrigues_series_fails():
    s = sum((-1) ** k * theta ** (2 * k + 1) / sp.factorial(2 * k + 1) for k in range(5))
    c = sum((-1) ** k * theta ** (2 * k) / sp.factorial(2 * k) for k in range(5))
    r = right("rodrigues_derivative")
    result = check("rodrigues_derivative", r.subs({sp.sin(theta): s, sp.cos(theta): c}))
    assert not result.ok and "whole range" in result.message
    result = check("rodrigues_derivative", r + sp.floor(theta**2 / 10) * sp.Identity(3))
    assert result.status == "not allowed"


def test_regression_lazy_library_answers_are_not_accepted():
    lazy = {
        "hat_fifth": hat(omega) ** 5,
        "half_turn": S.rodrigues().subs(theta, sp.pi),
        "rodrigues_derivative": sp.diff(S.rodrigues(), theta),
        "inverse_of_product": (A * B).I,
        "lagrange_identity": x.cross(y).dot(x.cross(y)),
    }
    for name, answer in lazy.items():
        result = check(name, answer)
        assert not result.ok and result.status in ("form", "not allowed"), str(result)


def test_regression_no_expected_answer_is_readable_from_the_package():
    for ex in EXERCISES.values():
        assert not any(hasattr(ex, attr) for attr in ("_expected", "expected", "solution"))
        assert "answer_" + ex.name + " =" not in repr(ex)
    assert not hasattr(EX, "_cache")
    package = Path(course_lib.__file__).parent
    text = "\n".join(p.read_text() for p in package.rglob("*") if p.suffix in (".py", ".json"))
    for chapter in exercise_bank.CHAPTERS:
        sols, _ = F.solutions(chapter)
        for name, code in sols.items():
            for line in code.splitlines():
                if line.startswith(f"answer_{name} ="):
                    assert line not in text, (name, line)
    for name in ("hat_fifth", "half_turn", "exp_general_axis", "bac_cab", "composed_angle"):
        for sol in _solution_texts(name):
            assert sol not in text, (name, sol)
    for chapter in exercise_bank.CHAPTERS:  # no line of any worked solution either
        for code in F.solutions(chapter)[0].values():
            for line in code.splitlines():
                given = any(line.strip() in ex.statement for ex in EXERCISES.values())
                if len(line.strip()) > 30 and not line.lstrip().startswith("#") and not given:
                    assert line.strip() not in text, line


@pytest.mark.parametrize(
    "name, hostile",
    [
        ("bac_cab", [(sum(x) + sum(y)) ** 16, 0]),
        ("lagrange_identity", (xx + yy + xy + 1) ** 30),
        ("composed_angle", (alpha + beta + 1) ** 200),
        (
            "composed_angle",
            sp.Integral(sp.exp(-(alpha**2)) * sp.sin(beta * alpha) ** 9, (alpha, 0, beta)),
        ),
        ("hat_fifth", W**40),
        ("hat_fifth", sp.MatMul(*([W] * 30))),
        ("composed_angle", sp.Add(*[sp.cos(k * alpha) for k in range(3000)])),
        ("exp_general_axis", sp.exp(sp.exp(sp.exp(theta) ** 30)) * W),
    ],
)
def test_regression_hostile_answers_get_a_message_not_a_hang_or_internal_error(name, hostile):
    result = check(name, hostile)
    assert not result.ok
    assert result.status in ("too complex", "not allowed", "wrong", "malformed"), str(result)
    assert "could not check" not in result.message
    assert not re.search(r"\d\.\d{5,}", result.message)  # no sample point leaks


def test_readme_states_the_exercise_count_and_points_of_the_bank():
    text = (ROOT / "README.md").read_text()
    total = sum(ex.points for ex in EXERCISES.values())
    assert f"{len(EXERCISES)} in all ({total} points)" in text
    for chapter in exercise_bank.CHAPTERS:
        exs = exercises(chapter)
        levels = [sum(ex.level == lv for ex in exs) for lv in ("warm-up", "core", "challenge")]
        row = (
            " | ".join(map(str, levels)) + f" | {len(exs)} exercises, "
            f"{sum(ex.points for ex in exs)} points |"
        )
        assert row in text, row


@pytest.mark.parametrize(
    "hostile",
    [
        sp.sin(sp.Integer(10) ** (10**4)),  # mpmath would need 10⁴ digits
        sp.sin(sp.exp(sp.exp(50))),  # ... or e^(e^50) digits: a hang
        sp.Float("1e100000"),
    ],
)
def test_regression_numeric_answers_are_evaluated_in_double_precision_not_mpmath(hostile):
    result = check("two_mirrors", hostile)
    assert not result.ok and result.status in ("too complex", "malformed"), str(result)


def test_regression_no_method_of_a_foreign_class_is_called():
    calls = []

    class Spy(sp.Symbol):
        def __eq__(self, other):
            calls.append("eq")
            return True

        def __hash__(self):
            calls.append("hash")
            return 0

    spy = Spy("s")
    for name, answer in (
        ("ode_shifted", spy),
        ("unit_tangent", [spy, 0, 0]),
        ("two_mirrors", spy),
        ("lagrange_identity", (spy,)),
    ):
        calls.clear()
        result = check(name, answer)
        assert result.status == "not allowed", str(result)
        assert calls == [], (name, calls)


# ----------------------------------------------------------------------------- regressions


@pytest.mark.parametrize("dtype", [np.float32, np.complex64])
def test_a_correct_float32_answer_is_not_reported_as_wrong_entries(dtype):
    # issue 11: the right answer as float32 was told "components 1, 2 and 3 are wrong"
    right = np.array([float(v) for v in reference("axis_of_rotation")[1]])
    result = check("axis_of_rotation", right.astype(dtype))
    assert not result.ok and result.status == "wrong", str(result)
    assert "single precision" in result.message and "float64" in result.message
    assert "wrong." not in result.message.split("Hint:")[0]
    listed = check("axis_of_rotation", [np.float32(v) for v in right])
    assert "single precision" in listed.message
    assert check("axis_of_rotation", right.astype(np.float64)).ok
    wrong = check("axis_of_rotation", (right + [0, 0, 1e-3]).astype(dtype))
    assert wrong.message.startswith(
        "axis_of_rotation: your answer is not right: at least one component is wrong. Also, "
        "your answer is stored in single precision"
    ), str(wrong)


def test_regression_a_huge_float32_answer_is_checked_quickly():
    import time

    start = time.perf_counter()
    result = check("chain_vector", np.array([1e30, 3, -2], dtype=np.float32))
    assert time.perf_counter() - start < 1.0 and "at least one component" in result.message


def test_regression_inner_products_written_as_1x1_matrices_were_refused():
    # x.T * z is how the chapter writes xᵀz: a list of such 1x1 matrices is a right answer
    result = check("bac_cab", [sp.Matrix([[e]]) for e in right("bac_cab")])
    assert result.ok, result.message


def test_regression_every_wrong_scalar_was_told_to_check_its_scalar_factors():
    # A nonzero scalar is at every point a multiple of the right one, so "the right one times
    # a factor that changes with the symbols" fired for any wrong scalar: a missing square,
    # an extra term. A vector or matrix still gets it, with ‖ω‖ where ω is about.
    r = right("lagrange_identity")
    for wrong in (r.subs(xy**2, xy), r + 1, xx + yy - 2 * xy):
        message = check("lagrange_identity", wrong).message
        assert "changes with the symbols" not in message and "not equal" in message, message
        assert "ω" not in message.split("Hint:")[0]
    assert "‖ω‖" in check("hat_fifth", omega.dot(omega) * W).message


def test_regression_a_huge_number_was_called_too_large_for_double_precision_or_crashed():
    # 1e300 was "too large for double precision" (it is not); exp(700) gave "could not check
    # your answer (OverflowError)" from the digest of a number that large.
    for huge in (1e300, sp.exp(700)):
        message = check("angle_from_lengths", huge).message
        assert "1e300 or more, larger than any answer here" in message, message
        assert "OverflowError" not in message and "double precision" not in message


def test_regression_np_eye_in_a_matrix_expression_was_blamed_on_indexing():
    # u @ u.T - np.eye(3) is a numpy array of entries u[i, 0]·u[j, 0] − δ: the message spoke of
    # indexing and sp.Matrix(...), not of the np.eye that did it.
    result = check("half_turn", u @ u.T - np.eye(3))
    assert result.status == "not allowed" and "np.eye" in result.message, str(result)
    assert "indexing" not in result.message


def test_regression_fractions_decimals_mpmath_and_numpy_scalars_were_refused():
    # Fraction was called "a class of your own", np.uint64 and np.longdouble "could not read".
    from decimal import Decimal
    from fractions import Fraction

    import mpmath

    thirds = [sp.Rational(v) for v in right("complete_rotation")]
    assert check("complete_rotation", [Fraction(int(v.p), int(v.q)) for v in thirds]).ok
    assert check("complete_rotation", [Decimal(int(v.p)) / int(v.q) for v in thirds]).ok
    assert check("complete_rotation", [mpmath.mpf(int(v.p)) / int(v.q) for v in thirds]).ok
    angle = right("angle_from_lengths")
    assert check("angle_from_lengths", mpmath.mpf(str(sp.N(angle, 30)))).ok
    assert check("angle_from_lengths", mpmath.pi * float(angle / sp.pi)).ok
    assert check("angle_from_lengths", np.longdouble(float(angle))).ok
    assert check("vb_from_va", [np.uint64(int(v)) for v in right("vb_from_va")]).ok
    assert "nan or infinity" in check("angle_from_lengths", Decimal("NaN")).message
    assert "complex" in check("angle_from_lengths", mpmath.mpc(1, 1)).message


def test_regression_a_sign_error_in_a_polynomial_in_w_was_called_a_transpose_only():
    wrong = right("rodrigues_derivative").subs(W, -W)  # the W term's sign flipped
    result = check("rodrigues_derivative", wrong)
    assert not result.ok
    assert "the W term" in result.message and "Wᵀ = −W" in result.message


def _typed(answer, digits):
    """The answer with its numbers typed to ``digits`` significant digits: each irrational
    number of an expression, every entry of a list of numbers."""
    if isinstance(answer, sp.MatrixBase) and answer.free_symbols:
        parts = [e.as_independent(*e.free_symbols, as_Add=False) for e in answer]
        return sp.Matrix(answer.shape[0], 1, [sp.Float(_sig(c, digits)) * f for c, f in parts])
    if isinstance(answer, sp.Expr):
        return _sig(answer, digits)
    return [_sig(v, digits) for v in _flat_numbers(answer)]


@pytest.mark.parametrize(
    ("name", "digits"),
    [
        ("angle_from_lengths", 5),
        ("pendulum_speed", 3),
        # 8-9 digits were not recognised as typed, and an expression never heard of rounding
        # (a rounded value between TOL and 4 TOL away may pass: the digests' grid, as before)
        ("angle_from_lengths", 8),
        ("two_mirrors", 8),
        ("complete_rotation", 8),
        ("unit_tangent", 5),
    ],
)
def test_regression_a_rounded_decimal_got_only_the_value_is_not_right(name, digits):
    typed = _typed(right(name), digits)
    result = check(name, typed)
    assert not result.ok and "typed decimals" in result.message, result.message
    assert "typed decimals" not in check(name, 0.5).message  # a short exact decimal


def test_regression_theta_instead_of_cos_theta_got_a_factor_hint():
    cos_theta = right("composed_angle")
    assert check("composed_angle", cos_theta).ok
    assert "asks for cos θ" in check("composed_angle", sp.acos(cos_theta)).message


def test_regression_a_wrong_coefficient_of_a_polynomial_in_w_got_all_9_entries_are_wrong():
    wrong_sign = check("rodrigues_derivative", -right("rodrigues_derivative").subs(W, -W))
    assert "the coefficient of W² has the wrong sign" in wrong_sign.message
    no_division = right("exp_general_axis").replace(
        lambda e: e.is_Pow and e.base == N2 and e.exp.is_negative, lambda e: sp.Integer(1)
    )
    message = check("exp_general_axis", no_division).message
    assert "the coefficients of W and W² are wrong (the rest is right)" in message
    assert "entries" not in message


def test_regression_an_entry_of_a_matrix_symbol_got_an_unexplained_not_allowed():
    result = check("half_turn", sp.Matrix(right("half_turn")))
    assert result.status == "not allowed"
    assert "matrix expression itself" in result.message


def test_regression_a_series_with_its_order_term_got_an_unexplained_not_allowed():
    r = list(right("small_angle"))
    series = r[0] + sp.O(alpha**3)  # a series that keeps its order term
    result = check("small_angle", [series, *r[1:]])
    assert result.status == "not allowed" and ".removeO()" in result.message
    assert check("small_angle", [series.removeO(), *r[1:]]).ok


@pytest.mark.parametrize(
    "container",
    [sp.Tuple, sp.Array, lambda v: [sp.Tuple(*v)]],
    ids=["Tuple (nonlinsolve)", "Array", "list of one Tuple"],
)
def test_regression_a_right_answer_in_a_sympy_tuple_or_array_was_called_an_equation(container):
    result = check("ode_shifted", container(list(right("ode_shifted"))))
    assert result.ok, result.message


@pytest.mark.filterwarnings("ignore::PendingDeprecationWarning")  # numpy's view of np.matrix
def test_regression_numpy_matrix_was_called_a_class_of_your_own():
    result = check("motion_from_points", np.matrix(right("motion_from_points")))
    assert result.ok, result.message


def test_regression_a_dict_from_solve_got_could_not_read_an_entry():
    r = right("ode_shifted")
    result = check("ode_shifted", [{sp.Symbol("a"): r[0]}, r[1]])
    assert not result.ok and "dict" in result.message and "sol[" in result.message


def test_regression_a_pair_in_the_wrong_order_got_components_1_and_2_are_wrong():
    r = right("ode_shifted")
    result = check("ode_shifted", [r[1], r[0]])
    assert not result.ok and "reverse order" in result.message


@pytest.mark.parametrize("answer", [[[[1.0]]], [[1, 2, [3]]], [[0, 1, np.array([2.0])]]])
def test_regression_a_list_nested_three_deep_got_could_not_read_an_entry_of_type_list(answer):
    result = check("rigid_inverse", answer)
    assert result.status == "malformed"
    assert "nested three levels deep" in result.message and "[[a, b, c]" in result.message


@pytest.mark.parametrize(
    "answer",
    [lambda r: [r], lambda r: (r,), lambda r: [sp.Matrix([1, 2, 3])]],
    ids=["list of a MatMul", "tuple of a MatMul", "list of a Matrix"],
)
def test_regression_a_matrix_inside_a_list_got_could_not_read_an_entry_of_type_matmul(answer):
    result = check("rigid_inverse", answer(right("rigid_inverse")))
    assert result.status == "malformed"
    assert "itself a 3x1 matrix" in result.message and "not a list that holds it" in result.message
    assert check("rigid_inverse", right("rigid_inverse")).ok  # the matrix itself is read and right


# ----------------------------------------------------------------------------- fingerprints


def _leaves(obj):
    if isinstance(obj, dict):
        for v in obj.values():
            yield from _leaves(v)
    elif isinstance(obj, list):
        for v in obj:
            yield from _leaves(v)
    else:
        yield obj


def test_the_fingerprints_hold_no_value_only_digests_and_names():
    raw = json.loads(F.TARGET.read_text())
    for packed in raw.get(EX._store.FIELD, {}).values():  # a variant row: a template, digests
        for line in packed["rows"]:
            template, *digests = line.split(" ")
            assert int(template) < len(packed["templates"])
            assert all(re.fullmatch(r"[0-9a-f]{16}", d) for d in digests), line
    names_ok = {"", "skew", "symmetric"} | set(EX._transforms.EXPR_TRANSFORMS)
    names_ok |= set(EX._transforms.NUMBER_OPS) | set(EX._transforms.PERMUTATIONS)
    stored = EX._store.Fingerprints(raw)
    for name in stored:  # every record, the packed rows unpacked
        fp = json.loads(json.dumps(stored[name]))
        if "size" in fp:  # a numeric answer's number of entries: its shape says as much
            shape = get(name.split("@")[0]).answer.shape  # name@k: a variant of the exercise
            assert fp.pop("size") == int(np.prod(shape, dtype=int))
        for leaf in _leaves(fp):
            assert leaf is None or isinstance(leaf, str), (name, leaf)
            hexdigest = re.fullmatch(r"[0-9a-f]{16}", leaf or "")
            letters = re.fullmatch(r"[a-f]{1,6}", leaf or "")
            assert leaf is None or hexdigest or leaf in names_ok or letters, (name, leaf)


def test_a_stored_digest_is_a_salted_scrypt_of_a_whole_vector_rounded():
    import hashlib

    ex = get("vb_from_va")
    fp = EX._fingerprints()[ex.name]
    step, offset = EX._engine.STEP_NUMBER, EX._engine.NUMBER_OFFSET
    v = [float(x) for x in right(ex.name)]
    cell = [int(np.floor(x / step + offset)) for x in v]
    salt = f"{EX._digests._SALT}|{ex.name}|value0".encode()
    options = [
        hashlib.scrypt(str(tuple(c)).encode(), salt=salt, dklen=8, **EX._digests.SCRYPT).hex()
        for c in itertools.product(*[(k - 1, k, k + 1) for k in cell])
    ]
    assert set(fp) == {"size", "value", "mistakes"} and fp["size"] == 3 and len(fp["value"]) == 1
    assert fp["value"][0] in options


def test_regression_a_vector_was_recoverable_one_entry_at_a_time():
    # attack 8: a digest per entry let a search of ~7,300 simple closed forms per entry
    # recover 10 exercises in 10 minutes. Now a vector matches only whole (a matrix by
    # columns): a right first entry alone matches nothing, and no entry has a digest of its own.
    ex = get("vb_from_va")
    fp = EX._fingerprints()[ex.name]
    r = np.array([float(v) for v in right(ex.name)])
    assert check(ex.name, r).ok
    shape = ex.answer.shape
    assert not EX._engine.number_group_ok(ex.name, "value", r[:1], (1,), 0, fp["value"][0])
    assert "entr" not in json.dumps(fp)
    matrix = get("compose_frames")
    assert len(EX._fingerprints()[matrix.name]["value"]) == 3  # one digest per column
    assert shape == (3,)


@pytest.mark.parametrize("name", [n for n, ex in EXERCISES.items() if hasattr(ex.answer, "domain")])
def test_the_points_come_in_pairs_that_redraw_one_unit_each(name):
    spec = get(name).answer
    pts, near = EX._engine.points(name, spec)
    table = np.stack([pts[s] for s in EX._engine.base_symbols(spec)], -1)
    syms = list(EX._engine.base_symbols(spec))
    assert len(table) >= EX._engine.MIN_POINTS and 0 < near.sum() < len(table)
    for unit in EX._engine._units(spec):
        inside = np.array([s in unit for s in syms])
        same_outside = np.all(table[:, None, ~inside] == table[None, :, ~inside], axis=-1)
        differ_inside = np.any(table[:, None, inside] != table[None, :, inside], axis=-1)
        assert np.any(same_outside & differ_inside), (name, unit)


def _bump_interpolant(symbol, nodes, values):
    """A smooth function of ``symbol`` alone taking ``values`` at ``nodes`` (narrow bumps)."""
    gaps = np.diff(np.sort(nodes))
    width = float(np.min(gaps[gaps > 0])) / 10
    return sp.Add(
        *[
            sp.Float(v) * sp.exp(-(((symbol - sp.Float(n)) / sp.Float(width)) ** 2))
            for n, v in zip(nodes, values)
        ]
    )


def test_regression_a_function_of_alpha_alone_interpolating_the_points_passed():
    # issue 17: composed_angle took a function of α alone that matched the stored values at
    # the 40 points; every point now has a partner with the same α and another β.
    name = "composed_angle"
    spec = get(name).answer
    pts, _ = EX._engine.points(name, spec)
    values = F.expr_values(get(name), right(name)).ravel()
    nodes, first = np.unique(pts[alpha], return_index=True)
    fake = _bump_interpolant(alpha, nodes, values[first])
    result = check(name, fake)
    assert not result.ok and result.status == "wrong", str(result)


def test_regression_coefficients_in_theta_alone_interpolating_the_points_passed():
    # issue 17: exp_general_axis took I + α(θ)W + β(θ)W² with α, β interpolating the points
    # in θ alone (no ‖ω‖); points with the same θ and another ω now tell them apart.
    name = "exp_general_axis"
    ex = get(name)
    pts, _ = EX._engine.points(name, ex.answer)
    coeffs = EX._engine.w_coefficients(F.expr_values(ex, right(name)), pts)
    nodes, first = np.unique(pts[theta], return_index=True)
    c1 = _bump_interpolant(theta, nodes, coeffs[first, 1])
    c2 = _bump_interpolant(theta, nodes, coeffs[first, 2])
    result = check(name, sp.Identity(3) + c1 * W + c2 * W**2)
    assert not result.ok and result.status == "wrong", str(result)


def test_regression_angle_hints_of_a_vector_of_angles_were_checked_against_one_entry():
    # digested whole, the three angles of 5.4 must be compared whole: in degrees they get the
    # degrees hint (compared as a scalar, the hint could never fire)
    r = np.array([float(v) for v in right("proper_euler_angles")])
    assert "in degrees" in check("proper_euler_angles", np.degrees(r)).message
