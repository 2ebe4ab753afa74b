"""Tests for the helpers of course_lib._arrays that the plotting package validates through.

(The older helpers are exercised by test_adversarial.py, module by module.)
"""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

from course_lib._arrays import (
    as_angles,
    as_choice,
    as_finite_array,
    as_labels,
    as_matrix,
    as_points,
    as_positive,
    as_scalar,
    as_str,
    as_vector,
    as_vector3,
)

reals = st.floats(allow_nan=False, allow_infinity=False)
dims = st.integers(1, 4)


# --- as_vector, as_points, as_matrix: shapes in, the same numbers out --------------------------


@given(st.data(), dims)
def test_as_vector_returns_the_vector_as_float64(data, n):
    v = data.draw(hnp.arrays(np.float64, (n,), elements=reals))
    out = as_vector(v.tolist(), "v", n)
    assert out.dtype == np.float64 and out.shape == (n,)
    assert np.array_equal(out, v)


@given(hnp.arrays(np.float64, (3,), elements=reals))
def test_as_vector3_is_as_vector_of_three(v):
    assert np.array_equal(as_vector3(v, "w"), as_vector(v, "w", 3))


@given(st.data(), dims, st.integers(1, 5))
def test_as_points_gives_n_points_and_one_point_as_one_row(data, d, n):
    P = data.draw(hnp.arrays(np.float64, (n, d), elements=reals))
    assert np.array_equal(as_points(P, "p", d), P)
    assert np.array_equal(as_points(P[0], "p", d), P[:1])


@given(st.data(), dims)
def test_as_matrix_returns_the_matrix_as_float64(data, n):
    M = data.draw(hnp.arrays(np.float64, (n, n), elements=reals))
    out = as_matrix(M.tolist(), "M", n)
    assert out.shape == (n, n) and np.array_equal(out, M)


@given(hnp.arrays(np.float64, hnp.array_shapes(min_dims=0, max_dims=3), elements=reals))
def test_as_finite_array_and_as_angles_keep_any_finite_array(a):
    assert np.array_equal(as_finite_array(a, "a"), a)
    assert np.array_equal(as_angles(a, "a"), a)


@given(st.floats(min_value=5e-324, allow_infinity=False))
def test_as_positive_keeps_every_positive_float(x):
    assert as_positive(x, "r") == x


@pytest.mark.parametrize(
    ("call", "error", "match"),
    [
        (lambda: as_vector([1, 2, 3], "v", 2), ValueError, r"v must be one 2-vector .*\(3,\)"),
        (lambda: as_vector([1, np.nan], "v", 2), ValueError, r"v contains NaN"),
        (lambda: as_vector("ab", "v", 2), TypeError, "v must be an array of real numbers"),
        (lambda: as_points([[0, 0]], "p", 3), ValueError, r"shape \(3,\) or \(n, 3\)"),
        (lambda: as_points(np.zeros((2, 2, 3)), "p", 3), ValueError, r"got shape \(2, 2, 3\)"),
        (lambda: as_points([[0, 0, np.inf]], "p", 3), ValueError, "p contains NaN or infinity"),
        (lambda: as_points([0, 0], "pts", 2, min_count=2), ValueError, "at least 2 points, got 1"),
        (lambda: as_matrix(np.eye(2), "R", 3), ValueError, r"one 3x3 matrix .*\(2, 2\)"),
        (lambda: as_matrix([[1, 0], [0, np.nan]], "R", 2), ValueError, "R contains NaN"),
        (lambda: as_finite_array([1, np.inf], "x"), ValueError, "x contains NaN or infinity"),
        (lambda: as_positive(0, "r"), ValueError, "r must be > 0, got 0.0"),
        (lambda: as_positive(-1e-300, "r"), ValueError, "r must be > 0"),
        (lambda: as_positive(np.nan, "r"), ValueError, "r must be a finite real number, not NaN"),
        (lambda: as_positive(True, "r"), TypeError, "r must be a real number, got bool"),
        (lambda: as_positive([1.0], "r"), ValueError, "r must be a single number"),
        (lambda: as_str(3, "title"), TypeError, "title must be a str, got int"),
        (lambda: as_str(None, "label"), TypeError, "label must be a str, got NoneType"),
        (lambda: as_labels(["a"], 2), ValueError, "one label per item: expected 2, got 1"),
        (lambda: as_labels(["a", 1], 2, "label"), TypeError, "each of label .* got int"),
        (lambda: as_choice("4d", "kind", ("3d", "2d")), ValueError, "kind must be '3d' or '2d'"),
        (lambda: as_choice(1, "style", ("a", "b", "c")), ValueError, r"one of \['a', 'b', 'c'\]"),
        (lambda: as_choice(["a"], "style", ("a", "b")), ValueError, r"got \['a'\]"),
    ],
)
def test_new_helpers_name_the_argument_the_property_and_its_size(call, error, match):
    with pytest.raises(error, match=match):
        call()


def test_as_labels_takes_none_a_single_str_or_one_per_item():
    assert as_labels(None, 3) == [None, None, None]
    assert as_labels("$p$", 1) == ["$p$"]
    assert as_labels(("$p$", None), 2) == ["$p$", None]


def test_as_choice_returns_the_choice_itself():
    assert as_choice("dashed", "style", ("solid", "dashed", "dotted")) == "dashed"


def test_as_scalar_of_nan_says_nan_or_infinity_not_only_finite():
    # plotting's own _scalar said "NaN or infinity"; since it validates through as_scalar, the
    # message of as_scalar names NaN as well (draw_pendulum(ax, np.nan) is refused with "NaN")
    for bad in (np.nan, np.inf, -np.inf):
        with pytest.raises(ValueError, match="theta must be a finite real number, not NaN"):
            as_scalar(bad, "theta")
