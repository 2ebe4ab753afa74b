"""Tests of course_lib.groups: the four group axioms of Definition 4 on samples."""

import operator

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib import so3
from course_lib.groups import (
    Failure,
    GroupCheck,
    GroupSample,
    check_group,
    real_addition,
    so3_addition,
    so3_multiplication,
    so3_scalar_multiplication,
)
from course_lib.tolerance import TOL

Z4 = dict(
    elements=[0, 1, 2, 3], op=lambda a, b: (a + b) % 4, identity=0, inverse=lambda a: (-a) % 4
)


def axioms_failed(result):
    return sorted({f.axiom for f in result.failures})


# ------------------------------------------------------------------ the notes' examples


def test_reals_under_addition_are_a_group():
    result = check_group(**real_addition())
    assert result.ok and result.failures == []
    assert result.counts == {"closure": 36, "identity": 7, "inverse": 6, "associativity": 216}


def test_so3_under_multiplication_is_a_group_proposition_5():
    sample = so3_multiplication(n=5, seed=1)
    assert all(so3.is_rotation(R) for R in sample.elements)
    assert np.array_equal(sample.elements[0], np.eye(3))
    result = check_group(**sample)
    assert result.ok, result.message


def test_so3_addition_fails_closure_with_I_plus_I_det_8():
    result = check_group(**so3_addition())
    assert not result.ok
    first = result.failures[0]
    assert first.axiom == "closure"
    a, b = first.elements
    assert np.array_equal(a, np.eye(3)) and np.array_equal(b, np.eye(3))
    assert np.linalg.det(a + b) == pytest.approx(2.0**3)  # det(2I) = 8, not 2 as the notes say
    assert "(det = 8)" in first.message
    # every pair fails closure: det(R1 + R2) = 1 is impossible for rotations here
    assert sum(f.axiom == "closure" for f in result.failures) == result.counts["closure"]
    assert axioms_failed(result) == ["closure", "identity", "inverse"]
    doc = " ".join(so3_addition.__doc__.split())
    assert "2^3 = 8" in doc and "slip" in doc


def test_so3_addition_fails_identity_and_inverse_only_by_membership():
    result = check_group(**so3_addition())
    identity = [f for f in result.failures if f.axiom == "identity"]
    assert (
        len(identity) == 1
        and "the identity e = " in identity[0].message
        and "(det = 0)" in identity[0].message
    )
    inverse = [f for f in result.failures if f.axiom == "inverse"]
    assert all("g⁻¹ = " in f.message and "(det = -1)" in f.message for f in inverse)
    assert all("≠ e" not in f.message for f in inverse)  # R + (−R) = 0 = e does hold


def test_so3_scalar_multiplication_fails_closure_det_c_cubed():
    result = check_group(**so3_scalar_multiplication(c=2.0))
    first = result.failures[0]
    assert first.axiom == "closure" and "(det = 8)" in first.message
    for f in result.failures:  # every failure is a membership failure: scaling leaves SO(3)
        assert "is not in the set" in f.message
    c3 = check_group(**so3_scalar_multiplication(c=3.0)).failures[0]
    assert "(det = 27)" in c3.message
    assert check_group(**so3_scalar_multiplication(c=1)).ok  # c = 1 is (SO(3), ·)


# ------------------------------------------------------------------ other structures


def test_finite_group_with_default_membership_and_equality():
    assert check_group(**Z4).ok
    assert check_group([1, -1], op=operator.mul, identity=1, inverse=lambda a: a).ok


def test_finite_set_not_closed():
    result = check_group([0, 1, 2, 3], op=operator.add, identity=0, inverse=operator.neg)
    assert "closure" in axioms_failed(result)
    closure = [f for f in result.failures if f.axiom == "closure"]
    assert all(a + b > 3 for a, b in (f.elements for f in closure))
    assert len(closure) == sum(a + b > 3 for a in range(4) for b in range(4))


def test_wrong_inverse_is_named_with_its_element():
    result = check_group(**{**Z4, "inverse": lambda a: a})
    assert axioms_failed(result) == ["inverse"]
    bad = sorted(f.elements[0] for f in result.failures)
    assert bad == [1, 3]  # a + a ≡ 0 (mod 4) only for 0 and 2
    assert "for g = 1: g ∘ g⁻¹ = 2 ≠ e" in result.failures[0].message


def test_wrong_identity_is_reported():
    result = check_group(**{**Z4, "identity": 1})
    assert "identity" in axioms_failed(result)
    msg = next(f.message for f in result.failures if f.axiom == "identity")
    assert "e ∘ g and g ∘ e ≠ g" in msg


def test_subtraction_is_not_associative():
    result = check_group(
        [0.0, 1.0, 2.5, -4.0],
        op=operator.sub,
        identity=0.0,
        inverse=lambda a: a,
        member=lambda x: True,
    )
    assert "associativity" in axioms_failed(result)
    f = next(f for f in result.failures if f.axiom == "associativity")
    a, b, c = f.elements
    assert abs((a - (b - c)) - ((a - b) - c)) > TOL
    assert "g1 ∘ (g2 ∘ g3) = " in f.message and "≠ (g1 ∘ g2) ∘ g3 = " in f.message


def test_failures_are_tuples_in_the_notes_order():
    result = check_group(**so3_addition(n=3))
    for f in result.failures:
        assert isinstance(f, Failure) and isinstance(f, tuple) and len(f) == 3
        axiom, elements, message = f
        assert isinstance(elements, tuple) and isinstance(message, str)
    order = ["closure", "identity", "inverse", "associativity"]
    positions = [order.index(f.axiom) for f in result.failures]
    assert positions == sorted(positions)


# ------------------------------------------------------------------ tolerance and sampling


def test_default_equality_is_absolute_TOL():
    near = [0.0, 1.0]
    exact = check_group(
        near,
        op=lambda a, b: a + b + 1e-12,
        identity=0.0,
        inverse=operator.neg,
        member=lambda x: True,
    )
    assert exact.ok
    off = check_group(
        near,
        op=lambda a, b: a + b + 1e-6,
        identity=0.0,
        inverse=operator.neg,
        member=lambda x: True,
    )
    assert not off.ok
    assert check_group(
        near,
        op=lambda a, b: a + b + 1e-6,
        identity=0.0,
        inverse=operator.neg,
        member=lambda x: True,
        tol=1e-5,
    ).ok


def test_many_elements_are_sampled_with_a_seed():
    elements = list(range(12))
    kwargs = dict(
        op=lambda a, b: (a + b) % 12, identity=0, inverse=lambda a: (-a) % 12, max_samples=100
    )
    a = check_group(elements, seed=3, **kwargs)
    b = check_group(elements, seed=3, **kwargs)
    assert a.ok and a.counts["associativity"] == 100 and a.counts["closure"] == 100
    assert a.counts == b.counts
    few = check_group(elements[:4], **kwargs)
    assert few.counts["closure"] == 16 and few.counts["associativity"] == 64


def test_custom_equal_is_used():
    # integers mod 3 compared by residue: 5 and 2 are the same element
    result = check_group(
        [0, 1, 2],
        op=operator.add,
        identity=0,
        inverse=operator.neg,
        equal=lambda a, b: (a - b) % 3 == 0,
        member=lambda x: isinstance(x, int),
    )
    assert result.ok


# ------------------------------------------------------------------ properties


@settings(deadline=None, max_examples=25)
@given(st.integers(0, 2**32 - 1))
def test_any_sample_of_rotations_passes_all_axioms(seed):
    assert check_group(**so3_multiplication(n=4, seed=seed)).ok


@settings(deadline=None)
@given(
    st.lists(st.floats(-1e3, 1e3, allow_nan=False, allow_infinity=False), min_size=1, max_size=5)
)
def test_any_sample_of_reals_passes_all_axioms_under_addition(xs):
    sample = real_addition()
    result = check_group(
        xs, op=sample.op, identity=sample.identity, inverse=sample.inverse, member=sample.member
    )
    assert result.ok, result.message


@settings(deadline=None, max_examples=25)
@given(st.integers(0, 2**32 - 1), st.floats(1.1, 5.0))
def test_scaled_rotations_are_never_closed(seed, c):
    result = check_group(**so3_scalar_multiplication(c=c, n=3, seed=seed))
    closure = [f for f in result.failures if f.axiom == "closure"]
    assert len(closure) == result.counts["closure"]
    for f in closure:
        a, b = f.elements
        assert np.linalg.det(c * a @ b) == pytest.approx(c**3)


# ------------------------------------------------------------------ display


def test_display_of_a_pass():
    result = check_group(**real_addition(n=3))
    assert isinstance(result, GroupCheck) and bool(result) is True
    assert str(result) == "✓ " + result.message
    assert result.message.startswith(
        "(ℝ, +) passes all four group axioms on 3 sample elements, 9 pairs, 27 triples"
    )
    assert "never prove" in result.message
    assert result._repr_markdown_().startswith("**✓")
    assert repr(result) == "GroupCheck(name='(ℝ, +)', ok=True, failed_axioms=[], n_failures=0)"


def test_display_of_a_failure():
    result = check_group(**so3_addition(n=2))
    assert bool(result) is False
    head = str(result).splitlines()[0]
    assert head == (
        "✗ (SO(3), +) is not a group: fails 1 (closure), 2 (identity), 3 (inverse) "
        "on 2 sample elements, 4 pairs, 8 triples."
    )
    assert (
        "- axiom 1 (closure), 4 failures, e.g. g1 ∘ g2 = [[2., 0., 0.], [0., 2., 0.], "
        "[0., 0., 2.]] (det = 8)" in result.message
    )
    md = result._repr_markdown_()
    assert md.startswith("**✗") and md.count("\n- axiom") == 3
    assert repr(result) == (
        "GroupCheck(name='(SO(3), +)', ok=False, "
        "failed_axioms=['closure', 'identity', 'inverse'], n_failures=7)"
    )


def test_group_sample_unpacks_into_check_group_and_is_frozen():
    sample = so3_addition()
    assert isinstance(sample, GroupSample)
    assert set(sample.keys()) == {"name", "elements", "op", "identity", "inverse", "member"}
    assert sample["name"] == "(SO(3), +)" and "det(2I) = 8" in sample.note
    with pytest.raises(KeyError):
        sample["note"]
    with pytest.raises(AttributeError):
        sample.name = "x"


# ------------------------------------------------------------------ bad input


def test_elements_must_be_members():
    with pytest.raises(ValueError, match=r"elements\[1\] = .*\(det = 8\) is not a member"):
        check_group(
            [np.eye(3), 2 * np.eye(3)],
            op=np.matmul,
            identity=np.eye(3),
            inverse=np.transpose,
            member=so3.is_rotation,
        )


def test_empty_elements_are_refused():
    with pytest.raises(ValueError, match="at least one element"):
        check_group([], op=operator.add, identity=0, inverse=operator.neg)


@pytest.mark.parametrize("field", ["op", "inverse", "equal", "member"])
def test_non_callables_are_refused(field):
    kwargs = {**Z4, field: 3}
    with pytest.raises(TypeError, match=f"{field} must be callable"):
        check_group(**kwargs)


def test_member_and_equal_must_return_bools():
    with pytest.raises(TypeError, match="member must return a bool, got ndarray"):
        check_group(
            [np.eye(3)],
            op=np.matmul,
            identity=np.eye(3),
            inverse=np.transpose,
            member=lambda x: np.isfinite(x),
        )
    with pytest.raises(TypeError, match="equal must return a bool, got str"):
        check_group(**Z4, equal=lambda a, b: "yes")


def test_bad_tol_max_samples_and_sample_arguments_are_refused():
    with pytest.raises(ValueError, match="tol must be"):
        check_group(**Z4, tol=-1)
    with pytest.raises(ValueError, match="max_samples must be >= 1"):
        check_group(**Z4, max_samples=0)
    with pytest.raises(ValueError, match="c must be a finite nonzero number"):
        so3_scalar_multiplication(c=0)
    with pytest.raises(TypeError, match="c must be a real number"):
        so3_scalar_multiplication(c="2")
    with pytest.raises(TypeError, match="n must be an integer"):
        so3_multiplication(n=2.0)
    with pytest.raises(ValueError, match="n must be >= 1"):
        real_addition(n=0)


def test_real_membership_refuses_non_reals():
    member = real_addition().member
    assert member(1.5) and member(np.float64(2.0)) and member(3)
    assert not member(float("nan")) and not member(1j) and not member("1") and not member(True)
