"""Tests of course_lib.exercises: the registry and the answer checkers.

For every exercise: the reference answer and several equivalent forms pass; typical mistakes
fail with the right hint, and no hint shows the expected answer; malformed answers give a clear
message instead of an exception.
"""


import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib import exercises as ex_mod
from course_lib.exercises import (
    EXERCISES, CheckResult, R_generic, a, check, exercises, get, names, t, x, x_0, y,
)
from course_lib.symbolic import hat, omega, polarization_identity, theta, unit_reduce, vee
from course_lib.tolerance import TOL

W = sp.Matrix(omega)
I3 = sp.eye(3)
S2 = np.sqrt(2.0)
RAC = np.array([[1 / S2, -1 / S2, 0], [1 / S2, 1 / S2, 0], [0, 0, 1]])
RX60 = np.array([[1, 0, 0], [0, 0.5, -np.sqrt(3) / 2], [0, np.sqrt(3) / 2, 0.5]])
RZ = sp.Matrix([[sp.cos(theta), -sp.sin(theta), 0], [sp.sin(theta), sp.cos(theta), 0],
                [0, 0, 1]])
MIRROR = sp.diag(1, 1, -1)
P_HELIX = sp.Matrix([sp.cos(2 * t), sp.sin(2 * t), 3 * t])
N2 = (W.T * W)[0, 0]                       # ‖ω‖², left unsimplified on purpose
R1, R2, R3 = R_generic[:, 0], R_generic[:, 1], R_generic[:, 2]


def _rodrigues(s, c):
    return I3 + s * hat(omega) + c * hat(omega) ** 2


# Equivalent forms of the right answer, for every exercise (not the registry's own object).
EQUIVALENT = {
    "coords_by_projection": [
        [2 * sp.sqrt(2), sp.sqrt(2), 2],
        np.array([[1, 3, 2]]) @ RAC,                          # row vector 1x3
        (2.8284271247, 1.4142135624, 2.0),                    # typed to 10 digits
        sp.Matrix([4 / sp.sqrt(2), 2 / sp.sqrt(2), 2]),
    ],
    "polarization": [
        x.dot(y),
        sp.Rational(1, 4) * ((x + y).dot(x + y) - (x - y).dot(x - y)),
        x.T * y,                                              # a 1x1 Matrix
        polarization_identity(x, y)[1],
    ],
    "reflection_cross": [
        -1, -1.0, sp.Integer(-1), np.float64(-1.0),
        sp.cancel((MIRROR * x).cross(MIRROR * y)[2] / (MIRROR * x.cross(y))[2]),
    ],
    "trajectory_velocity": [
        P_HELIX.diff(t),
        [-4 * sp.sin(t) * sp.cos(t), 2 * (sp.cos(t) ** 2 - sp.sin(t) ** 2), 3],
        sp.Matrix([[-2 * sp.sin(2 * t), 2 * sp.cos(2 * t), 3]]),  # 1x3 row
        (sp.diff(P_HELIX[0], t), sp.diff(P_HELIX[1], t), sp.Integer(3)),
    ],
    "rab_example": [
        [[-1, 0, 0], [0, 1, 0], [0, 0, -1]],
        np.diag([-1.0, 1.0, -1.0]) + 1e-12,
        sp.diag(-1, 1, -1),
        np.column_stack([[-1, 0, 0], [0, 1, 0], [0, 0, -1]]),
    ],
    "rac_example": [
        RAC,
        sp.Matrix([[1, -1, 0], [1, 1, 0], [0, 0, sp.sqrt(2)]]) / sp.sqrt(2),
        np.round(RAC, 10),
        RZ.subs(theta, sp.pi / 4),
    ],
    "va_example": [
        [0, 2 / sp.sqrt(2), 3],
        (0, 1.4142135624, 3),
        sp.Matrix([0, sp.sqrt(2), 3]),
        RAC @ np.array([1, 1, 3]),
    ],
    "rotation_inverse": [
        RX60.T,
        np.linalg.inv(RX60),
        sp.Matrix([[1, 0, 0], [0, sp.Rational(1, 2), sp.sqrt(3) / 2],
                   [0, -sp.sqrt(3) / 2, sp.Rational(1, 2)]]),
        RX60.T.tolist(),
    ],
    "det_triple_product": [
        R1.dot(R2.cross(R3)),
        R_generic.det(),
        R_generic[0, :].dot(R_generic[1, :].cross(R_generic[2, :])),   # rows: det Rᵀ = det R
        R2.dot(R3.cross(R1)),                                          # cyclic
    ],
    "rotated_hat": [
        RZ * W,
        vee(sp.trigsimp(RZ * hat(omega) * RZ.T)),
        [omega[0] * sp.cos(theta) - omega[1] * sp.sin(theta),
         omega[0] * sp.sin(theta) + omega[1] * sp.cos(theta), omega[2]],
        RZ.T.T * W * (sp.sin(theta) ** 2 + sp.cos(theta) ** 2),
    ],
    "ode_solution": [
        x_0 * sp.exp(a * t),
        sp.exp(a * t) * x_0,
        x_0 * sp.exp(a * t / 2) ** 2,
        sp.dsolve(sp.Function("f")(t).diff(t) - a * sp.Function("f")(t),
                  ics={sp.Function("f")(0): x_0}).rhs,
    ],
    "pendulum_speed": [
        sp.pi, np.pi, 3.14159265359, abs(2 * sp.diff(sp.pi / 6 * sp.cos(3 * t), t)
                                          .subs(t, sp.pi / 6)),
    ],
    "hat_squared": [
        W * W.T - I3,
        hat(omega) ** 2,
        W * W.T - N2 * I3,                                    # correct on the unit sphere
        W * W.T - W.norm() ** 2 * I3,
        unit_reduce(hat(omega) ** 2),
    ],
    "hat_cubed": [
        -hat(omega),
        hat(omega) ** 3,
        -N2 * hat(omega),
        (W * W.T - I3) * hat(omega),
    ],
    "hat_fourth": [
        I3 - W * W.T,
        hat(omega) ** 4,
        -hat(omega) ** 2,
        N2 * (N2 * I3 - W * W.T),
    ],
    "rodrigues": [
        _rodrigues(sp.sin(theta), 1 - sp.cos(theta)),
        _rodrigues(sp.sin(theta), 2 * sp.sin(theta / 2) ** 2),          # half-angle form
        (I3 + sp.sin(theta) * hat(omega) + (1 - sp.cos(theta)) * (W * W.T - I3)),
        sp.cos(theta) * I3 + sp.sin(theta) * hat(omega) + (1 - sp.cos(theta)) * W * W.T,
        (I3 + sp.sin(theta) * hat(omega) / W.norm()
         + (1 - sp.cos(theta)) * hat(omega) ** 2 / N2),
        _rodrigues(2 * sp.sin(theta / 2) * sp.cos(theta / 2), 1 - sp.cos(theta)).applyfunc(
            sp.expand),
    ],
}

# Typical mistakes and a piece of the hint each must produce.
MISTAKES = {
    "coords_by_projection": [
        (RAC @ [1, 3, 2], "projection"),
        (-(RAC.T @ [1, 3, 2]), "negative"),
        ([sp.sqrt(2), 2 * sp.sqrt(2), 2], "components 1 and 2 are wrong"),
    ],
    "polarization": [
        (4 * x.dot(y), "constant multiple"),
        (-x.dot(y), "negative"),
        (x.dot(x), "not equal"),
    ],
    "reflection_cross": [
        (1, "orientation"),
        (0, "zero"),
        (2, "not right"),
    ],
    "trajectory_velocity": [
        (sp.Matrix([-sp.sin(2 * t), sp.cos(2 * t), 3]), "chain rule"),
        (-P_HELIX.diff(t), "negative"),
        (P_HELIX, "position p(t) itself"),
        ([-2 * sp.sin(2 * t), 2 * sp.cos(2 * t), 0], "component 3 is wrong"),
    ],
    "rab_example": [
        (np.eye(3), "entries (1, 1) and (3, 3) are wrong"),
        (-np.diag([-1, 1, -1]), "negative"),
    ],
    "rac_example": [
        (RAC.T, "as rows"),
        (3 * RAC, "constant multiple"),
        (np.array([[1, 0, 0], [0, 1 / S2, -1 / S2], [0, 1 / S2, 1 / S2]]), "wrong"),
    ],
    "va_example": [
        (RAC.T @ [1, 1, 3], "R_abᵀ"),
        ([1, 1, 3], "components 1 and 2 are wrong"),
    ],
    "rotation_inverse": [
        (RX60, "R itself"),
        (-RX60.T, "negative"),
        (2 * RX60.T, "constant multiple"),
    ],
    "det_triple_product": [
        (R1.dot(R3.cross(R2)), "order of the cross product"),
        (2 * R_generic.det(), "constant multiple"),
        (0, "zero"),
    ],
    "rotated_hat": [
        (RZ.T * W, "other way round"),
        (W, "ω itself"),
        (-RZ * W, "negative"),
    ],
    "ode_solution": [
        (x_0 * sp.exp(-a * t), "sign in the exponent"),
        (sp.exp(a * t), "initial condition"),
        (x_0 + a * t, "does not satisfy"),
    ],
    "pendulum_speed": [
        (-np.pi, "never negative"),
        (0, "angular velocity"),
        (np.pi / 2, "length r"),
        (7, "not right"),
    ],
    "hat_squared": [
        (W * W.T, "unit vector"),
        (W * W.T + I3, "unit vector"),
        (I3 - W * W.T, "negative"),
        (W * W.T - 2 * I3, "multiple of the identity"),
        (3 * (W * W.T - I3), "constant multiple"),
        ((W * W.T - I3).T + hat(omega), "wrong"),
    ],
    "hat_cubed": [
        (hat(omega), "negative"),
        (W * W.T * hat(omega), "vanishes"),
        (-2 * hat(omega), "constant multiple"),
    ],
    "hat_fourth": [
        (-W * W.T, "unit vector"),
        (W * W.T - I3, "negative"),
        (hat(omega), "wrong"),
    ],
    "rodrigues": [
        (_rodrigues(sp.cos(theta), 1 - sp.sin(theta)), "swapped"),
        (_rodrigues(-sp.sin(theta), 1 - sp.cos(theta)), "transpose"),
        (_rodrigues(sp.sin(theta), sp.cos(theta)), "even series"),
        (_rodrigues(sp.sin(theta), sp.cos(theta) - 1), "sign of the ω̂² term"),
        (_rodrigues(theta, theta ** 2 / 2), "cut after three terms"),
        (_rodrigues(sp.sin(theta), 1 - sp.cos(theta)) - I3, "identity"),
    ],
}


def _solution_texts(name):
    """Ways the expected answer could be printed; none may appear in a hint."""
    ex = get(name)
    value = ex._expected()
    if ex.kind == "numeric":
        arr = np.asarray(value, dtype=float)
        texts = {str(arr), repr(arr), str(np.round(arr, 4)), str(arr.tolist())}
        return {s for s in texts if len(s) > 3}
    expr = sp.sympify(value) if ex.shape == () else sp.Matrix(value)
    texts = {str(expr), sp.pretty(expr), sp.latex(expr), sp.pretty(expr, use_unicode=False)}
    if ex.shape != ():
        texts |= {str(e) for e in expr if len(str(e)) > 8}
    return {s for s in texts if len(s) >= 3}


# --------------------------------------------------------------------------------- registry

def test_registry_has_at_least_four_exercises_per_chapter_and_half_symbolic():
    assert len(EXERCISES) >= 12
    for chapter in (1, 2, 3):
        assert len(exercises(chapter)) >= 4
    kinds = [ex.kind for ex in EXERCISES.values()]
    assert set(kinds) <= {"symbolic", "numeric"}
    assert kinds.count("symbolic") * 2 >= len(kinds)


def test_required_exercises_exist_with_their_chapters():
    required = {"hat_squared": 3, "hat_cubed": 3, "rodrigues": 3, "rab_example": 2,
                "va_example": 2}
    for name, chapter in required.items():
        assert get(name).chapter == chapter
    assert get("hat_squared").kind == get("hat_cubed").kind == get("rodrigues").kind == "symbolic"


def test_every_exercise_is_complete_and_labels_are_unique():
    labels = [ex.label for ex in EXERCISES.values()]
    assert len(set(labels)) == len(labels)
    assert names() == list(EXERCISES)
    for name, ex in EXERCISES.items():
        assert ex.name == name and ex.title and ex.statement.strip()
        assert ex.shape in ((), (3,), (3, 3))
        assert name in ex.markdown() and f"answer_{name}" in ex.markdown()
        assert ex._repr_markdown_() == ex.markdown()
        namespace = {}
        exec(ex.setup, namespace)               # the setup code imports what the cell needs
        assert callable(namespace["check"])


def test_tests_cover_every_exercise():
    assert set(EQUIVALENT) == set(EXERCISES) == set(MISTAKES)


def test_exercises_rejects_unknown_chapter():
    with pytest.raises(ValueError, match="chapter must be 1, 2 or 3"):
        exercises(4)


def test_unknown_name_lists_the_known_names():
    with pytest.raises(KeyError) as info:
        check("hat_sqared", None)
    for name in EXERCISES:
        assert name in str(info.value)
    with pytest.raises(KeyError, match="known exercises"):
        get(3)


def test_statements_do_not_print_the_expected_symbolic_answers():
    for name in ("hat_squared", "hat_cubed", "hat_fourth", "rodrigues", "ode_solution"):
        statement = get(name).statement
        for text in _solution_texts(name):
            assert text not in statement


# --------------------------------------------------------------------------------- correct

@pytest.mark.parametrize("name", list(EXERCISES))
def test_reference_answer_passes(name):
    result = check(name, get(name)._expected())
    assert result.ok and result.status == "correct", str(result)
    assert str(result) == f"✓ {name}: correct."


@pytest.mark.parametrize("name, answer",
                         [(n, f) for n, forms in EQUIVALENT.items() for f in forms])
def test_equivalent_forms_pass(name, answer):
    result = check(name, answer)
    assert result.ok, str(result)


# --------------------------------------------------------------------------------- mistakes

@pytest.mark.parametrize("name, answer, hint",
                         [(n, w, h) for n, ms in MISTAKES.items() for w, h in ms])
def test_typical_mistake_fails_with_the_right_hint(name, answer, hint):
    result = check(name, answer)
    assert not result.ok and result.status == "wrong", str(result)
    assert hint in result.message, str(result)
    assert str(result).startswith(f"✗ {name}: ")
    for text in _solution_texts(name):
        assert text not in result.message
        assert text not in result._repr_html_()
    if name == "reflection_cross":              # the answer is a short number
        assert "-1" not in result.message and "−1" not in result.message


def test_hint_adds_the_exercise_tip_once():
    result = check("rodrigues", _rodrigues(sp.cos(theta), 1 - sp.sin(theta)))
    assert result.message.count("Hint:") == 1
    assert get("rodrigues").tip in result.message


def test_forgetting_the_unit_constraint_is_named_for_hat_squared():
    # ωωᵀ − ‖ω‖²I is right for unit ω; ωωᵀ alone (the ‖ω‖² term dropped) is not.
    assert check("hat_squared", W * W.T - N2 * I3).ok
    wrong = check("hat_squared", W * W.T)
    assert "ω₁² + ω₂² + ω₃² = 1" in wrong.message


# --------------------------------------------------------------------------------- malformed

@pytest.mark.parametrize("name, answer, fragment", [
    ("hat_squared", "omega*omega.T - eye(3)", "not a string"),
    ("va_example", "0, 1.41, 3", "not a string"),
    ("rab_example", [["-1", 0, 0], [0, 1, 0], [0, 0, -1]], "not a string"),
    ("hat_squared", W, "expected a 3x3 matrix, got a 3x1 matrix"),
    ("rodrigues", hat(omega)[0, 0], "expected a 3x3 matrix, got a scalar"),
    ("va_example", [0, 1, 2, 3], "expected a 3-vector, got a 4x1 matrix"),
    ("pendulum_speed", [1.0, 2.0], "expected a scalar"),
    ("hat_squared", W * W.T - sp.Symbol("x") * I3, "symbol(s) x, which do not belong"),
    ("rodrigues", _rodrigues(sp.sin(sp.Symbol("theta")), 1 - sp.cos(theta)),
     "not the real symbols"),
    ("hat_squared", hat(sp.symbols("omega_1:4")) ** 2, "not the real symbols"),
    ("ode_solution", sp.Eq(sp.Function("x")(t), x_0 * sp.exp(a * t)), ".rhs"),
    ("ode_solution", sp.Function("x")(t), "undefined function"),
    ("rab_example", {"R": 1}, "got an object of type dict"),
    ("rab_example", np.zeros((3, 3, 3)), "shape (3, 3, 3)"),
    ("va_example", [0, sp.nan, 3], "nan or infinity"),
    ("va_example", [0, sp.sqrt(2) * sp.I, 3], "complex"),
    ("va_example", [0, sp.Symbol("s"), 3], "a number is expected"),
    ("polarization", x.dot(y) == 0, "truth value"),
    ("reflection_cross", sp.sqrt(x[0] - 10), "complex"),
    ("ode_solution", x_0 / (a - a), "nan or infinity"),
    ("rab_example", lambda: 0, "got an object of type function"),
    ("rab_example", [[-1, 0, 0], [0, 1], [0, 0, -1]], "rows have different lengths"),
    ("rab_example", [True, 0, 0], "truth value"),
    ("va_example", np.array([True, False, True]), "truth value"),
    ("va_example", [sp.Matrix([1]), 0, 0], "could not read"),
    ("pendulum_speed", complex(np.pi, 1), "complex"),
    ("pendulum_speed", float("nan"), "nan or infinity"),
])
def test_malformed_answer_gives_a_clear_message(name, answer, fragment):
    result = check(name, answer)
    assert not result.ok and result.status == "malformed", str(result)
    assert fragment in result.message, str(result)


def test_an_answer_that_breaks_while_being_read_gives_a_message_not_a_traceback():
    class Hostile:
        def __array__(self, *args, **kwargs):
            raise RuntimeError("no array for you")

        def __iter__(self):
            raise RuntimeError("no iteration either")

    result = check("rab_example", [Hostile(), 0, 0])
    assert not result.ok and result.status == "malformed"
    assert "could not" in result.message


def test_zero_dimensional_array_is_read_as_a_number():
    assert check("pendulum_speed", np.array(np.pi)).ok
    assert check("reflection_cross", np.array(-1)).ok


def test_none_means_no_answer_yet():
    result = check("rodrigues", None)
    assert not result.ok and result.status == "no answer"
    assert "no answer yet" in str(result) and "answer_rodrigues" in str(result)


def test_string_answer_is_never_evaluated():
    marker = "__import__('builtins').setattr(__import__('builtins'), 'PWNED_BY_CHECK', 1)"
    result = check("polarization", marker)
    assert result.status == "malformed"
    import builtins
    assert not hasattr(builtins, "PWNED_BY_CHECK")


# --------------------------------------------------------------------------------- display

def test_display_is_deterministic_and_readable():
    results = [check("hat_cubed", hat(omega)), check("hat_cubed", -hat(omega)),
               check("hat_cubed", None), check("hat_cubed", "x")]
    again = [check("hat_cubed", hat(omega)), check("hat_cubed", -hat(omega)),
             check("hat_cubed", None), check("hat_cubed", "x")]
    for r, s in zip(results, again):
        assert str(r) == repr(r) == str(s)
        assert r._repr_html_() == s._repr_html_()
        assert "0x" not in r._repr_html_() and " at " not in repr(r)
        assert ("✓" if r.ok else "✗") in r._repr_html_()
        assert bool(r) is r.ok
    assert "<code>answer_hat_cubed</code>" in results[2]._repr_html_()


def test_check_result_escapes_html():
    r = CheckResult("n", False, "a < b & `c`", "wrong")
    assert "a &lt; b &amp; <code>c</code>" in r._repr_html_()


# --------------------------------------------------------------------------------- properties

@settings(max_examples=25, deadline=None)
@given(st.integers(-3, 3), st.sampled_from(["hat_squared", "hat_cubed", "hat_fourth",
                                            "rodrigues"]),
       st.lists(st.integers(-2, 2), min_size=9, max_size=9))
def test_adding_multiples_of_the_unit_constraint_keeps_an_answer_correct(k, name, entries):
    # Anything that vanishes on the unit sphere may be added: the answer stays equivalent.
    extra = k * (N2 - 1) * sp.Matrix(3, 3, entries)
    assert check(name, sp.Matrix(get(name)._expected()) + extra).ok


@settings(max_examples=25, deadline=None)
@given(st.floats(0.1, 5.0).filter(lambda c: abs(c - 1) > 1e-3),
       st.sampled_from(["hat_squared", "rodrigues", "rotated_hat", "rac_example",
                        "trajectory_velocity"]))
def test_a_scaled_answer_is_rejected_as_a_constant_multiple(c, name):
    value = get(name)._expected()
    scaled = c * np.asarray(value) if get(name).kind == "numeric" else sp.Float(c) * value
    result = check(name, scaled)
    assert not result.ok and "constant multiple" in result.message


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(-1.0, 1.0), min_size=3, max_size=3),
       st.floats(0.0, 0.9))
def test_numeric_answers_are_judged_by_the_residual_norm_against_tol(direction, size):
    d = np.asarray(direction)
    if np.linalg.norm(d) < 1e-3:
        d = np.array([1.0, 0.0, 0.0])
    d = d / np.linalg.norm(d)
    expected = RAC @ np.array([1.0, 1.0, 3.0])
    assert check("va_example", expected + size * TOL * d).ok
    wrong = check("va_example", expected + (1.5 + size) * TOL * d)
    assert not wrong.ok


@settings(max_examples=25, deadline=None)
@given(st.sets(st.integers(0, 2), min_size=1, max_size=3), st.floats(0.01, 3.0))
def test_wrong_components_are_named_exactly(which, delta):
    answer = RAC @ np.array([1.0, 1.0, 3.0])
    answer[list(which)] += delta
    result = check("va_example", answer)
    assert not result.ok
    listed = result.message.split(" wrong")[0]
    assert listed.startswith("component")
    for i in range(3):
        assert (str(i + 1) in listed) == (i in which)


@settings(max_examples=20, deadline=None)
@given(st.floats(-3.0, 3.0))
def test_rodrigues_is_right_at_any_fixed_angle_rewrite(phi):
    # cos θ written through a shifted angle: cos θ = cos(θ − φ)cos φ − sin(θ − φ)sin φ.
    c = sp.cos(theta - phi) * sp.cos(phi) - sp.sin(theta - phi) * sp.sin(phi)
    assert check("rodrigues", _rodrigues(sp.sin(theta), 1 - c)).ok


# --------------------------------------------------------------------------------- regressions

def test_scalar_reference_answers_do_not_crash():
    # A scalar expected answer (sympy number) used to fail when stored as a 1x1 matrix.
    for name in ("reflection_cross", "polarization", "ode_solution", "det_triple_product"):
        assert check(name, get(name)._expected()).ok


def test_lookalike_symbol_without_real_assumption_is_not_silently_accepted():
    w1, w2, w3 = sp.symbols("omega_1:4")        # complex by default
    result = check("hat_cubed", -hat([w1, w2, w3]))
    assert not result.ok and "real=True" in result.message


def test_expected_answer_is_not_exposed_in_the_exercise_repr():
    for name, ex in EXERCISES.items():
        text = repr(ex)
        assert "_expected" not in text and "_mistakes" not in text
        for sol in _solution_texts(name):
            assert sol not in text


def test_module_exports_the_exercise_symbols():
    assert all(s.is_real for s in (*x, *y, t, a, x_0, *R_generic))
    assert set(ex_mod.__all__) >= {"check", "get", "EXERCISES", "x", "y", "t", "a", "x_0"}


def test_answer_that_cannot_be_evaluated_falls_back_to_exact_simplification(monkeypatch):
    # When the sample-point evaluation fails, unit_reduce + trigsimp still decide exactly.
    def unevaluable(ex, M):
        raise ex_mod._Malformed("cannot evaluate")

    for name in ("rodrigues", "hat_squared"):    # reference values are computed beforehand
        check(name, get(name)._expected())
    monkeypatch.setattr(ex_mod, "_evaluate", unevaluable)
    half_angle = _rodrigues(sp.sin(theta), 2 * sp.sin(theta / 2) ** 2)
    assert check("rodrigues", half_angle).ok
    assert check("hat_squared", W * W.T - I3 * W.norm() ** 2).ok
    wrong = check("rodrigues", _rodrigues(sp.cos(theta), 1 - sp.sin(theta)))
    assert not wrong.ok and wrong.message == "cannot evaluate"


def test_tol_argument_loosens_the_check_and_is_validated():
    near = RAC @ np.array([1.0, 1.0, 3.0]) + 1e-6
    assert not check("va_example", near).ok
    assert check("va_example", near, tol=1e-5).ok
    assert check("hat_squared", W * W.T - I3 + 1e-7 * I3, tol=1e-6).ok
    with pytest.raises(ValueError, match="tol must be a finite number"):
        check("va_example", near, tol=-1.0)
    with pytest.raises(TypeError, match="tol must be a real number"):
        check("va_example", near, tol="1e-3")
