"""Tests of course_lib.rigid: Definition 1 checked on sample pairs."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib import so3
from course_lib.rigid import (
    Counterexample,
    RigidCheck,
    check_rigid,
    reflection_map,
    rotation_map,
    translation_map,
    vector_map,
)
from course_lib.tolerance import TOL

AXES = np.eye(3)  # the notes' x, y, z
R_Z90 = so3.rot_z(np.pi / 2)

components = st.floats(-3.0, 3.0, allow_nan=False, allow_infinity=False)
rotation_vectors = st.tuples(components, components, components)


# ------------------------------------------------------------------ the notes' examples


def test_quarter_turn_about_z_is_rigid_and_moves_axes_as_in_the_figure():
    g = rotation_map(R_Z90)
    assert np.linalg.norm(g(AXES[0]) - AXES[1]) <= TOL  # x -> y
    assert np.linalg.norm(g(AXES[1]) + AXES[0]) <= TOL  # y -> -x
    # eqs. (11)-(14): g(x × y) = g(z) = g(x) × g(y)
    assert np.linalg.norm(np.cross(g(AXES[0]), g(AXES[1])) - g(np.cross(AXES[0], AXES[1]))) <= TOL
    result = check_rigid(g, points=AXES)
    assert result.ok and result.condition is None and result.counterexample is None
    assert result.n_pairs == 6
    assert check_rigid(g).ok


def test_reflection_flips_z_and_fails_condition_2_with_the_notes_counterexample():
    g = reflection_map([0, 0, 1])
    result = check_rigid(g, points=AXES)
    assert not result.ok and result.condition == "cross product"
    c = result.counterexample
    # the notes: g(x) × g(y) = −g(x × y)
    assert np.linalg.norm(c.lhs + c.rhs) <= TOL
    assert np.linalg.norm(c.lhs - c.rhs) == pytest.approx(c.mismatch)
    assert c.mismatch == pytest.approx(2.0)
    assert np.array_equal(c.p1, AXES[0]) and np.array_equal(c.p2, AXES[1])
    # named as in the notes: "g preserves relative orientation between vectors"
    assert "condition 2 (relative orientation between vectors)" in result.message
    assert "g(p1)×g(p2) = [0., 0., 1.]" in result.message
    assert "g(p1×p2) = [ 0.,  0., -1.]" in result.message
    assert "2.0e+00 > TOL = 1e-09" in result.message


def test_reflection_preserves_length():
    g = reflection_map([1, 2, -2])
    p = np.random.default_rng(0).standard_normal((20, 3))
    d_in = np.linalg.norm(p[:, None] - p[None], axis=-1)
    d_out = np.linalg.norm(g(p)[:, None] - g(p)[None], axis=-1)
    assert np.abs(d_in - d_out).max() <= TOL
    assert check_rigid(g).condition == "cross product"  # condition 1 passed, 2 failed


def test_translation_preserves_length_but_fails_condition_2_as_stated_on_points():
    d = np.array([1.0, -2.0, 0.5])
    g = translation_map(d)
    p = np.random.default_rng(1).standard_normal((2, 3))
    assert abs(np.linalg.norm(g(p[0]) - g(p[1])) - np.linalg.norm(p[0] - p[1])) <= TOL
    result = check_rigid(g)
    assert not result.ok and result.condition == "cross product"
    c = result.counterexample
    expected_lhs = np.cross(c.p1 + d, c.p2 + d)
    expected_rhs = np.cross(c.p1, c.p2) + d
    assert (
        np.linalg.norm(c.lhs - expected_lhs) <= TOL and np.linalg.norm(c.rhs - expected_rhs) <= TOL
    )
    doc = " ".join(check_rigid.__doc__.split())  # the notes' slip is documented
    assert "applies the cross product to" in doc and "translation" in doc


def test_scaling_fails_condition_1_with_both_lengths_in_the_message():
    result = check_rigid(lambda p: 2 * np.asarray(p), points=[[0, 0, 0], [3, 4, 0]])
    assert not result.ok and result.condition == "length"
    c = result.counterexample
    assert (
        c.lhs == pytest.approx(10.0)
        and c.rhs == pytest.approx(5.0)
        and c.mismatch == pytest.approx(5.0)
    )
    assert "condition 1 (length)" in result.message
    assert "‖g(p1) − g(p2)‖ = 10 but ‖p1 − p2‖ = 5" in result.message
    assert "mismatch 5.0e+00 > TOL = 1e-09" in result.message
    # these two points are collinear with 0, so p1 × p2 = 0 and condition 2 holds for them
    assert "fails too" not in result.message
    both = check_rigid(lambda p: 2 * np.asarray(p), points=[[1, 0, 0], [0, 1, 0]])
    assert both.condition == "length"
    assert "condition 2 (relative orientation between vectors) fails too" in both.message


def test_counterexample_is_the_worst_pair():
    g = lambda p: np.asarray(p) * np.array([1.0, 1.0, 1.5])  # noqa: E731 - stretches z only
    pts = np.array([[0, 0, 0], [1, 0, 0], [0, 0, 1], [0, 0, 4]], dtype=float)
    c = check_rigid(g, points=pts).counterexample
    assert c.mismatch == pytest.approx(2.0)  # |6 - 4| for (0,0,0)-(0,0,4)
    assert {tuple(c.p1), tuple(c.p2)} == {(0, 0, 0), (0, 0, 4)}


# ------------------------------------------------------------------ properties


@settings(deadline=None)
@given(rotation_vectors)
def test_rotations_from_hypothesis_floats_are_always_rigid(r):
    result = check_rigid(rotation_map(so3.exp(r)), n=20)
    assert result.ok, result.message


@settings(deadline=None)
@given(st.integers(0, 2**32 - 1))
def test_haar_random_rotations_are_always_rigid(seed):
    R = so3.random_rotations(1, seed=seed)[0]
    assert check_rigid(rotation_map(R), n=20, seed=seed).ok


@settings(deadline=None)
@given(rotation_vectors.filter(lambda v: np.linalg.norm(v) > 0.1), st.integers(0, 1000))
def test_reflections_always_fail_condition_2_by_twice_the_cross_product(normal, seed):
    result = check_rigid(reflection_map(normal), n=10, seed=seed)
    assert result.condition == "cross product"
    c = result.counterexample
    assert c.mismatch == pytest.approx(2 * np.linalg.norm(np.cross(c.p1, c.p2)))


# ------------------------------------------------------------------ calling conventions


def test_per_point_callable_is_detected_and_agrees_with_batched():
    R = so3.rot_x(0.7)
    per_point = check_rigid(lambda p: R @ p, n=30)
    batched = check_rigid(rotation_map(R), n=30)
    assert per_point.ok and batched.ok and per_point.n_pairs == batched.n_pairs == 30
    stretch = np.diag([1.0, 2.0, 1.0])
    a = check_rigid(lambda p: stretch @ p, n=30)
    b = check_rigid(lambda P: P @ stretch.T, n=30)
    assert a.condition == b.condition == "length"
    assert a.counterexample.mismatch == pytest.approx(b.counterexample.mismatch)


def test_per_point_callable_misread_as_batched():
    # p ↦ p‖p‖ accepts a (2, 3) array too, but with np.linalg.norm of the whole array: the
    # result must come from calling it point by point.
    def g(p):
        return np.asarray(p) * np.linalg.norm(p)

    pts = np.array([[1.0, 0, 0], [0, 2.0, 0], [0, 0, 3.0]])
    c = check_rigid(g, points=pts).counterexample
    expected = {
        (i, j): abs(np.linalg.norm(g(p) - g(q)) - np.linalg.norm(p - q))
        for i, p in enumerate(pts)
        for j, q in enumerate(pts)
        if i != j
    }
    assert c.mismatch == pytest.approx(max(expected.values()))


def test_per_point_rotation_with_three_points_is_not_mistaken_for_a_matrix_product():
    # R @ P for a (3, 3) array P of points is a valid product with the wrong meaning.
    R = so3.rot_y(0.3)
    assert check_rigid(lambda p: R @ p, points=[[1.0, 2, 3], [0, 1, 0], [4, 0, 1]]).ok


def test_explicit_pairs_and_all_ordered_pairs():
    pts = np.random.default_rng(3).standard_normal((5, 3))
    assert check_rigid(rotation_map(R_Z90), points=pts).n_pairs == 20
    pairs = pts[:4].reshape(2, 2, 3)
    assert check_rigid(rotation_map(R_Z90), points=pairs).n_pairs == 2
    assert check_rigid(rotation_map(R_Z90), n=7).n_pairs == 7


def test_same_seed_same_pairs_different_seed_different_pairs():
    g = translation_map([0, 0, 1])
    a, b, c = check_rigid(g, seed=4), check_rigid(g, seed=4), check_rigid(g, seed=5)
    assert np.array_equal(a.counterexample.p1, b.counterexample.p1)
    assert not np.array_equal(a.counterexample.p1, c.counterexample.p1)


def test_tolerance_is_absolute_TOL_by_default_and_can_be_passed():
    R = so3.rot_z(0.4)
    nudge = np.array([1e-7, 0.0, 0.0])
    g = lambda p: np.asarray(p) @ R.T + nudge * (np.asarray(p)[..., :1] ** 2)  # noqa: E731
    assert not check_rigid(g).ok
    loose = check_rigid(g, tol=1e-4)
    assert loose.ok and "tol = 0.0001" in loose.message
    assert check_rigid(lambda p: np.asarray(p) @ R.T * (1 + 1e-14)).ok


# ------------------------------------------------------------------ display


def test_display_of_a_pass():
    result = check_rigid(rotation_map(R_Z90), n=12)
    assert str(result) == "✓ " + result.message
    assert result.message.startswith("g is a rigid body transformation on these 12 sample pairs")
    assert "never prove" in result.message
    assert result._repr_markdown_().startswith("**✓")
    assert repr(result) == "RigidCheck(ok=True, condition=None, n_pairs=12, mismatch=None)"
    assert bool(result) is True


def test_display_of_a_failure():
    result = check_rigid(reflection_map([0, 0, 1]), points=AXES)
    assert str(result).startswith("✗ g fails condition 2 (relative orientation between vectors)")
    md = result._repr_markdown_()
    assert md.startswith("**✗") and "| mismatch | 2.0e+00 |" in md and "$p_1$" in md
    # regression (IBM table_headers_exists in JupyterLab): the header row names its columns
    assert "| counterexample | value |\n|---|---|" in md and "| | |" not in md
    assert (
        repr(result)
        == "RigidCheck(ok=False, condition='cross product', n_pairs=6, mismatch=2.0e+00)"
    )
    assert "\n" not in repr(result.counterexample) and "mismatch=2.0e+00" in repr(
        result.counterexample
    )
    assert bool(result) is False
    assert isinstance(result, RigidCheck) and isinstance(result.counterexample, Counterexample)


def test_result_is_frozen():
    result = check_rigid(rotation_map(R_Z90), n=3)
    with pytest.raises(AttributeError):
        result.ok = False


# ------------------------------------------------------------------ bad input


def test_g_must_be_callable():
    with pytest.raises(TypeError, match="g must be a callable"):
        check_rigid(np.eye(3))


@pytest.mark.parametrize(
    "g",
    [
        lambda p: 1.0,  # scalar
        lambda p: np.zeros(2),  # wrong length
        lambda p: np.zeros((4, 4)),  # matrix
    ],
)
def test_callables_returning_the_wrong_shape_are_refused(g):
    with pytest.raises(TypeError, match=r"g must map an \(N, 3\) array.*returned shape"):
        check_rigid(g, n=3)


def test_batched_callable_dropping_points_is_refused():
    calls = []

    def g(P):
        calls.append(1)
        P = np.asarray(P)
        return P if len(calls) == 1 else P[:-1]  # right on the probe, wrong afterwards

    with pytest.raises(
        ValueError, match=r"one 3-vector per point.*shape \(8, 3\), expected \(9, 3\)"
    ):
        check_rigid(g, n=3)


def test_callable_that_raises_is_reported_with_its_error():
    def g(p):
        raise RuntimeError("boom")

    with pytest.raises(TypeError, match="raised RuntimeError: boom") as info:
        check_rigid(g, n=3)
    assert isinstance(info.value.__cause__, RuntimeError)


def test_callable_returning_nan_or_text_is_refused():
    with pytest.raises(ValueError, match=r"g\(p\) contains NaN"):
        check_rigid(lambda p: np.full(np.shape(p), np.nan), n=3)
    with pytest.raises(TypeError, match=r"g\(p\) must be an array of real numbers"):
        check_rigid(lambda p: np.full(np.shape(p), "x"), n=3)


@pytest.mark.parametrize(
    "points, exc, pattern",
    [
        ([[1, 2, 3]], ValueError, "at least 2 points"),
        ([1, 2], ValueError, r"points must have shape \(\.\.\., 3\)"),
        (np.zeros((2, 3, 3)), ValueError, r"\(K, 2, 3\)"),
        ([[1, 2, np.nan], [0, 0, 1]], ValueError, "points contains NaN"),
        ("points", TypeError, "points must be"),
    ],
)
def test_bad_points_are_refused(points, exc, pattern):
    with pytest.raises(exc, match=pattern):
        check_rigid(rotation_map(R_Z90), points=points)


def test_bad_n_and_tol_are_refused():
    g = rotation_map(R_Z90)
    with pytest.raises(ValueError, match="n must be >= 1"):
        check_rigid(g, n=0)
    with pytest.raises(TypeError, match="n must be an integer"):
        check_rigid(g, n=2.5)
    with pytest.raises(ValueError, match="tol must be"):
        check_rigid(g, tol=-1.0)


def test_map_builders_refuse_bad_input():
    with pytest.raises(ValueError, match="reflection"):
        rotation_map(np.diag([1.0, 1.0, -1.0]))
    with pytest.raises(ValueError, match="one 3x3 rotation"):
        rotation_map(so3.random_rotations(2, seed=0))
    with pytest.raises(
        ValueError,
        match=r"normal must be non-zero to define a direction: ‖normal‖ = 0\.0e\+00 ≤ TOL",
    ):
        reflection_map([0, 0, 0])
    with pytest.raises(ValueError, match="normal must be one 3-vector"):
        reflection_map(np.eye(3))
    with pytest.raises(ValueError, match="d contains NaN"):
        translation_map([0, np.nan, 0])
    with pytest.raises(TypeError, match="p must be"):
        rotation_map(R_Z90)("not a point")


def test_reflection_normal_is_normalised():
    g = reflection_map([0, 0, 5])
    assert np.array_equal(g([1.0, 2.0, 3.0]), [1.0, 2.0, -3.0])


def test_docstrings_name_condition_2_as_the_notes_do():
    # the notes: "2. g preserves relative orientation between vectors"
    import course_lib.rigid as rigid

    for doc in (rigid.__doc__, reflection_map.__doc__):
        text = " ".join(doc.split())
        assert "relative orientation between vectors" in text
        assert "preserves orientation" not in text and "reverses orientation" not in text


# ------------------------------------------------------------- vector_map: g_*(v) = g(v) − g(0)


@settings(max_examples=30, deadline=None)
@given(d=rotation_vectors, seed=st.integers(0, 2**32 - 1))
def test_vector_map_of_a_translation_is_the_identity_and_is_rigid(d, seed):
    shift = translation_map(d)
    g_star = vector_map(shift)
    v = np.random.default_rng(seed).standard_normal((7, 3))
    assert np.linalg.norm(g_star(v) - v) <= TOL
    assert np.linalg.norm(g_star(v[0]) - v[0]) <= TOL and g_star(v[0]).shape == (3,)
    result = check_rigid(g_star)
    assert result.ok, result.message


@settings(max_examples=30, deadline=None)
@given(r=rotation_vectors, seed=st.integers(0, 2**32 - 1))
def test_vector_map_of_a_rotation_is_the_rotation_itself(r, seed):
    g = rotation_map(so3.exp(r))
    v = np.random.default_rng(seed).standard_normal((5, 3))
    assert np.linalg.norm(vector_map(g)(v) - g(v)) <= TOL
    assert check_rigid(vector_map(g)).ok


def test_vector_map_of_a_rigid_motion_is_its_rotation_on_any_representative():
    # g(p) = R p + d: g_*(v) = R v, and g(p) − g(q) = g_*(p − q) for every pair (eq. 8)
    R, d = so3.exp([0.5, 0.4, 1.2]), np.array([0.1, -0.7, 0.3])
    motion = lambda P: np.asarray(P) @ R.T + d  # noqa: E731
    g_star = vector_map(motion)
    assert np.linalg.norm(g_star(np.eye(3)) - R.T) <= TOL  # rows g_*(e_i) = columns of R
    p, q = np.random.default_rng(3).standard_normal((2, 10, 3))
    assert np.linalg.norm(motion(p) - motion(q) - g_star(p - q)) <= TOL
    assert not check_rigid(motion).ok and check_rigid(g_star).ok


def test_vector_map_accepts_per_point_callables_and_batches_of_any_shape():
    M = so3.rot_x(0.3)
    per_point = lambda p: M @ np.asarray(p, dtype=float) + 1.0  # noqa: E731 - (3,) -> (3,) only
    g_star = vector_map(per_point)
    v = np.random.default_rng(4).standard_normal((2, 4, 3))
    out = g_star(v)
    assert out.shape == (2, 4, 3)
    assert np.linalg.norm(out - v @ M.T) <= TOL
    assert g_star(np.zeros((0, 3))).shape == (0, 3)
    assert g_star.__name__ == "vector_map" and "g(v) − g(0)" in g_star.__doc__


def test_vector_map_refuses_bad_input():
    with pytest.raises(TypeError, match="g must be a callable"):
        vector_map(np.eye(3))
    g_star = vector_map(translation_map([1, 0, 0]))
    with pytest.raises(ValueError, match=r"v must have shape \(\.\.\., 3\)"):
        g_star([1.0, 2.0])
    with pytest.raises(ValueError, match="v contains NaN"):
        g_star([1.0, np.nan, 0.0])
    with pytest.raises(TypeError, match="v must be"):
        g_star("not a vector")
    with pytest.raises(TypeError, match="g must map"):
        vector_map(lambda p: 1.0)([1.0, 0.0, 0.0])
