"""Tests for course_lib.symbolic: the sympy layer of the course."""

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib import so3
from course_lib import symbolic as sym
from course_lib.symbolic import hat, omega, theta, unit_reduce
from course_lib.tolerance import TOL

W1, W2, W3 = omega
NORM2 = W1**2 + W2**2 + W3**2
I3 = sp.eye(3)


def _unit_axes():
    """A few fixed unit axes plus seeded random ones."""
    rng = np.random.default_rng(0)
    random = rng.normal(size=(5, 3))
    random /= np.linalg.norm(random, axis=1, keepdims=True)
    fixed = np.array([[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0], [1.0, 1.0, 1.0]])
    fixed /= np.linalg.norm(fixed, axis=1, keepdims=True)
    return np.vstack([fixed, random])


# --- symbols ----------------------------------------------------------------------------------


def test_omega_and_theta_are_real_symbols():
    assert omega.shape == (3, 1)
    assert [str(s) for s in omega] == ["omega_1", "omega_2", "omega_3"]
    assert all(s.is_real for s in omega) and theta.is_real
    assert sp.latex(omega[0]) == r"\omega_{1}"
    assert sp.latex(theta) == r"\theta"


def test_vector_and_rotation_symbols():
    x = sym.vector("x")
    assert x.shape == (3, 1) and [str(s) for s in x] == ["x_1", "x_2", "x_3"]
    assert sym.vector("omega") == omega
    R = sym.rotation_symbols()
    assert R.shape == (3, 3) and str(R[1, 2]) == "r_23"
    assert len(R.free_symbols) == 9
    with pytest.raises(ValueError, match="identifier"):
        sym.vector("not valid")
    with pytest.raises(TypeError, match="str"):
        sym.rotation_symbols(3)


# --- hat, vee, cross --------------------------------------------------------------------------


def test_hat_matches_eq_72_for_every_vector_form():
    expected = sp.Matrix([[0, -W3, W2], [W3, 0, -W1], [-W2, W1, 0]])
    assert hat(omega) == expected
    assert hat(omega.T) == expected
    assert hat(list(omega)) == expected
    assert hat(tuple(omega)) == expected


def test_hat_is_skew_and_is_the_cross_product():
    a, b = sym.w, sym.v
    assert hat(a).T == -hat(a)  # eq. 130
    assert sym.is_zero_matrix(hat(a) * b - sym.cross(a, b))  # eq. 73
    # a x b is orthogonal to a and b; the cross product is anticommutative.
    assert sp.expand((a.T * sym.cross(a, b))[0]) == 0
    assert sp.expand((b.T * sym.cross(a, b))[0]) == 0
    assert sym.is_zero_matrix(sym.cross(a, b) + sym.cross(b, a))
    assert sym.cross([1, 0, 0], [0, 1, 0]) == sp.Matrix([0, 0, 1])  # e1 x e2 = e3


@pytest.mark.parametrize(
    "bad",
    [[1, 2], [1, 2, 3, 4], sp.Matrix([1, 2]), sp.eye(3), sp.zeros(1, 4), np.zeros((3, 3))],
)
def test_hat_accepts_a_non_3_vector(bad):
    with pytest.raises(ValueError, match="3-vector"):
        hat(bad)


@pytest.mark.parametrize("bad", ["abc", 3, theta, [[1], [2], [3, 4]], [1, 2, "x"]])
def test_hat_accepts_non_expressions(bad):
    with pytest.raises(TypeError):
        hat(bad)


def test_vee_inverts_hat():
    assert sym.vee(hat(omega)) == sp.Matrix(omega)
    assert sym.vee(hat([theta, sp.sin(theta), 2])) == sp.Matrix([theta, sp.sin(theta), 2])
    W = sp.Matrix([[0, -3, 2], [3, 0, -1], [-2, 1, 0]])
    assert hat(sym.vee(W)) == W
    # skew only after trig simplification still counts as skew
    c = sp.sin(theta) ** 2 + sp.cos(theta) ** 2
    assert sym.vee(sp.Matrix([[0, -c, 0], [1, 0, 0], [0, 0, 0]])) == sp.Matrix([0, 0, 1])


def test_vee_accepts_non_skew_matrix():
    with pytest.raises(ValueError, match=r"not skew-symmetric.*entry \(0, 0\).*is 2"):
        sym.vee(sp.eye(3))
    with pytest.raises(ValueError, match=r"not skew-symmetric.*entry \(0, 1\)"):
        sym.vee(sp.Matrix([[0, W1, 0], [W1, 0, 0], [0, 0, 0]]))
    with pytest.raises(ValueError, match="shape"):
        sym.vee(sp.zeros(2, 2))
    with pytest.raises(TypeError):
        sym.vee("W")


# --- unit_reduce and is_zero_matrix ------------------------------------------------------------


def test_unit_reduce_basic_forms():
    assert unit_reduce(NORM2) == 1
    assert unit_reduce(NORM2 - 1) == 0
    assert unit_reduce(W1) == W1  # nonzero on the sphere stays nonzero
    assert unit_reduce(sp.sqrt(NORM2) * W2) == W2
    assert unit_reduce(NORM2 / (1 + W1)) == 1 / (1 + W1)
    assert unit_reduce(sp.Integer(5)) == 5
    M = sp.Matrix([[NORM2, W1], [theta * (NORM2 - 1), 0]])
    assert unit_reduce(M) == sp.Matrix([[1, W1], [0, 0]])
    # a different vector of symbols
    x = sym.vector("x")
    assert unit_reduce(x[0] ** 2 + x[1] ** 2 + x[2] ** 2, x) == 1


def test_unit_reduce_misses_zero_hidden_in_high_powers_of_omega_3():
    expr = W3**6 - (1 - W1**2 - W2**2) ** 3 + W3**5 - W3 * (1 - W1**2 - W2**2) ** 2
    assert unit_reduce(expr) == 0
    assert unit_reduce((W1 * W2 + W3**3) * (NORM2**2 - 1)) == 0


def test_unit_reduce_with_trig_coefficients():
    expr = sp.sin(theta) * NORM2 + sp.cos(theta) ** 2 * W3**2 + sp.sin(theta) ** 2 * W3**2
    assert unit_reduce(expr - sp.sin(theta) - W3**2) == 0
    assert unit_reduce(theta * W1 * (NORM2 - 1)) == 0
    assert sym.is_zero_matrix(sp.Matrix([sp.cos(theta) * (NORM2 - 1), 0]), unit=True)


def test_unit_reduce_refuses_non_polynomials():
    with pytest.raises(ValueError, match="polynomial"):
        unit_reduce(sp.sin(W1) * NORM2)
    with pytest.raises(ValueError, match="distinct symbols"):
        unit_reduce(W1, [W1, W1, W2])


_monomial = st.tuples(st.integers(-3, 3), st.integers(0, 3), st.integers(0, 3), st.integers(0, 4))
_coefficient = st.sampled_from([1, theta, sp.sin(theta), sp.cos(theta), sp.Rational(1, 2)])


def _poly(terms, coeffs):
    return sum(
        (n * c * W1**i * W2**j * W3**k for (n, i, j, k), c in zip(terms, coeffs)),
        sp.Integer(0),
    )


@settings(max_examples=25, deadline=None)
@given(
    st.lists(_monomial, min_size=1, max_size=5),
    st.lists(_coefficient, min_size=5, max_size=5),
    st.lists(_monomial, min_size=1, max_size=3),
)
def test_unit_reduce_kills_every_multiple_of_the_constraint(terms, coeffs, qterms):
    p = _poly(terms, coeffs)
    q = _poly(qterms, [1] * len(qterms))
    reduced = unit_reduce(p + q * (NORM2 - 1))
    assert sp.expand(reduced - unit_reduce(p)) == 0
    # the normal form has omega_3 at most to the first power ...
    assert reduced == 0 or sp.degree(sp.expand(reduced), W3) <= 1
    # ... and agrees with p on the unit sphere
    f_p = sp.lambdify((W1, W2, W3, theta), p, "numpy")
    f_r = sp.lambdify((W1, W2, W3, theta), reduced, "numpy")
    for x, y, z in _unit_axes():
        assert abs(f_p(x, y, z, 0.7) - f_r(x, y, z, 0.7)) <= 1e3 * TOL


def test_is_zero_matrix():
    assert sym.is_zero_matrix(sp.zeros(3))
    assert sym.is_zero_matrix([[0, sp.sin(theta) ** 2 + sp.cos(theta) ** 2 - 1]])
    assert not sym.is_zero_matrix(sp.Matrix([0, W1]))
    assert not sym.is_zero_matrix(NORM2 - 1)
    assert sym.is_zero_matrix(NORM2 - 1, unit=True)


# --- hat-map identities -----------------------------------------------------------------------


def test_hat_squared_identity_eq_137_and_140():
    lhs, rhs = sym.hat_squared_identity()
    assert lhs == (hat(omega) ** 2).applyfunc(sp.expand)
    assert lhs[0, 0] == -(W2**2) - W3**2 and lhs[0, 1] == W1 * W2  # eq. 137
    assert rhs == omega * omega.T - NORM2 * I3
    assert sym.is_zero_matrix(lhs - rhs)


def test_hat_squared_identity_unit_eq_141():
    lhs, rhs = sym.hat_squared_identity(unit=True)
    assert rhs == omega * omega.T - I3
    assert sym.is_zero_matrix(lhs - rhs, unit=True)
    assert not sym.is_zero_matrix(lhs - rhs)  # only true on the unit sphere


def test_hat_cubed_identity_eq_148():
    lhs, rhs = sym.hat_cubed_identity()
    assert lhs == (hat(omega) ** 3).applyfunc(sp.expand)
    assert sym.is_zero_matrix(lhs + NORM2 * hat(omega))
    lhs, rhs = sym.hat_cubed_identity(unit=True)
    assert rhs == -hat(omega)
    assert sym.is_zero_matrix(lhs - rhs, unit=True)
    assert not sym.is_zero_matrix(lhs - rhs)
    lhs, rhs = sym.hat_squared_identity(sym.w)  # any vector of symbols
    assert sym.is_zero_matrix(lhs - rhs)


def test_higher_hat_powers_cycle_eqs_152_156():
    W = hat(omega)
    assert sym.is_zero_matrix(W**4 + W**2, unit=True)  # eq. 153
    assert sym.is_zero_matrix(W**5 - W, unit=True)  # eq. 156


def test_induction_step_any_left_factor_times_cube_plus_hat_vanishes_for_unit_omega():
    # Chapter 3's induction step w^(n+2) = w^(n-1) w^3 = -w^n replaces w^3 by -w under an
    # arbitrary left factor M = w^(n-1): M (w^3 + w) must reduce to zero with free m_ij.
    M = sym.rotation_symbols("m")
    W = hat(omega)
    product = (M * (W**3 + W)).applyfunc(sp.expand)
    assert not sym.is_zero_matrix(product)
    assert unit_reduce(product) == sp.zeros(3, 3)


def test_matrix_symbol_exponent_rule_used_by_the_induction_step():
    # The notebook shows the step with a MatrixSymbol; it relies on sympy merging powers.
    n = sp.Symbol("n", integer=True, positive=True)
    Om = sp.MatrixSymbol("W", 3, 3)
    assert sp.MatMul(Om ** (n - 1), Om**3, evaluate=False).doit() == Om ** (n + 2)
    assert sp.MatMul(Om ** (n - 1), -Om, evaluate=False).doit() == -(Om**n)


def test_cached_identity_mutated_by_caller():
    lhs, _ = sym.hat_squared_identity()
    lhs[0, 0] = 42
    again, _ = sym.hat_squared_identity()
    assert again[0, 0] == -(W2**2) - W3**2


def test_hat_conjugation_and_rotation_preserves_cross_eqs_74_75():
    R = sym.rodrigues([0, 0, 1])  # a rotation with a symbolic angle
    a, b = sym.w, sym.v
    assert sym.is_zero_matrix(R * hat(a) * R.T - hat(R * a))  # eq. 74
    assert sym.is_zero_matrix(R * sym.cross(a, b) - sym.cross(R * a, R * b))  # eq. 75


# --- matrix exponential and Rodrigues ----------------------------------------------------------


def test_exp_series_definition_6():
    N = sp.Matrix([[0, 1, 0], [0, 0, 1], [0, 0, 0]])
    expected = sp.Matrix([[1, 1, sp.Rational(1, 2)], [0, 1, 1], [0, 0, 1]])
    assert sym.exp_series(N, 8) == expected
    a = sp.Symbol("a")
    for order in range(6):
        expected = sp.series(sp.exp(a), a, 0, order + 1).removeO()
        assert sp.expand(sym.exp_series(sp.Matrix([[a]]), order + 1)[0] - expected) == 0
    assert sym.exp_series(hat(omega), 1) == I3


def test_exp_series_agrees_with_numeric_exp_series():
    A = sp.Matrix([[0.1, -0.4, 0.2], [0.3, 0.0, -0.5], [0.0, 0.6, -0.2]])
    for order in (0, 1, 4, 9):
        ours = np.array(sym.exp_series(A, order + 1), dtype=np.float64)
        theirs = so3.exp_series(np.array(A, dtype=np.float64), order + 1)
        assert np.linalg.norm(ours - theirs) <= TOL


@pytest.mark.parametrize("bad, err", [(0, ValueError), (2.0, TypeError), (True, TypeError)])
def test_exp_series_bad_terms(bad, err):
    with pytest.raises(err, match="terms"):
        sym.exp_series(sp.eye(2), bad)


def test_exp_series_accepts_non_square():
    with pytest.raises(ValueError, match="square"):
        sym.exp_series(sp.zeros(2, 3), 2)


@pytest.mark.parametrize("order", range(13))
def test_rodrigues_coefficients_match_sin_and_one_minus_cos_series(order):
    a, b = sym.rodrigues_coefficients(order)
    sin_series = sp.series(sp.sin(theta), theta, 0, order + 1).removeO()
    vers_series = sp.series(1 - sp.cos(theta), theta, 0, order + 1).removeO()
    assert sp.expand(a - sin_series) == 0
    assert sp.expand(b - vers_series) == 0
    assert sp.Poly(a, theta).degree() <= order if a != 0 else order == 0


def test_rodrigues_coefficients_off_by_one_order():
    # order N keeps theta**N and nothing beyond it
    a, b = sym.rodrigues_coefficients(3)
    assert a.coeff(theta, 3) == sp.Rational(-1, 6) and b.coeff(theta, 4) == 0
    a, b = sym.rodrigues_coefficients(4)
    assert b.coeff(theta, 4) == sp.Rational(-1, 24) and a.coeff(theta, 5) == 0


def test_rodrigues_coefficients_reproduce_the_matrix_series_for_unit_omega():
    A = hat(omega) * theta
    for order in range(6):
        a, b = sym.rodrigues_coefficients(order)
        collapsed = I3 + a * hat(omega) + b * hat(omega) ** 2
        assert sym.is_zero_matrix(sym.exp_series(A, order + 1) - collapsed, unit=True)


def test_rodrigues_is_eq_159():
    R = sym.rodrigues()
    W = hat(omega)
    assert sym.is_zero_matrix(R - (I3 + sp.sin(theta) * W + (1 - sp.cos(theta)) * W**2))
    assert sym.rodrigues([0, 0, 1]) == sp.Matrix(
        [[sp.cos(theta), -sp.sin(theta), 0], [sp.sin(theta), sp.cos(theta), 0], [0, 0, 1]]
    )
    # rotating by theta about omega leaves omega fixed, and R solves q' = hat(omega) q (eq. 122)
    assert sym.is_zero_matrix(R * omega - omega, unit=True)
    assert sym.is_zero_matrix(R.diff(theta) - W * R, unit=True)
    assert R.subs(theta, 0) == I3


def test_rodrigues_is_orthogonal_for_unit_omega():
    R = sym.rodrigues()
    assert sym.is_zero_matrix(R.T * R - I3, unit=True)


def test_rodrigues_agrees_with_so3_exp():
    f = sp.lambdify((*omega, theta), sym.rodrigues(), "numpy")
    for axis in _unit_axes():
        for angle in (0.0, 0.3, -1.2, np.pi / 2, np.pi, 2.9):
            ours = np.array(f(*axis, angle), dtype=np.float64)
            assert np.linalg.norm(ours - so3.exp(axis, angle)) <= TOL


# --- general-case identities -------------------------------------------------------------------


def test_det_triple_product_identity_eq_52():
    lhs, rhs = sym.det_triple_product_identity()
    R = sym.rotation_symbols()
    assert sp.expand(lhs - R.det()) == 0
    assert sp.expand(lhs - rhs) == 0
    lhs, rhs = sym.det_triple_product_identity(sp.Matrix([[1, 2, 3], [0, 1, 4], [5, 6, 0]]))
    assert lhs == rhs == 1
    with pytest.raises(ValueError, match="shape"):
        sym.det_triple_product_identity(sp.eye(2))


def test_polarization_identity_eq_17():
    lhs, rhs = sym.polarization_identity()
    assert lhs == sum(a * b for a, b in zip(sym.w, sym.v))
    assert sp.expand(lhs - rhs) == 0
    lhs, rhs = sym.polarization_identity([1, 2, 3], [4, -5, 6])
    assert lhs == rhs == 12


def test_so3_constraints_eqs_111_116():
    R = sym.rotation_symbols()
    r = {(i, j): R[i - 1, j - 1] for i in range(1, 4) for j in range(1, 4)}
    expected = [
        r[1, 1] * r[1, 2] + r[2, 1] * r[2, 2] + r[3, 1] * r[3, 2],
        r[1, 1] * r[1, 3] + r[2, 1] * r[2, 3] + r[3, 1] * r[3, 3],
        r[1, 2] * r[1, 3] + r[2, 2] * r[2, 3] + r[3, 2] * r[3, 3],
        r[1, 1] ** 2 + r[2, 1] ** 2 + r[3, 1] ** 2 - 1,
        r[1, 2] ** 2 + r[2, 2] ** 2 + r[3, 2] ** 2 - 1,
        r[1, 3] ** 2 + r[2, 3] ** 2 + r[3, 3] ** 2 - 1,
    ]
    got = sym.so3_constraints()
    assert len(got) == 6
    assert all(sp.expand(g - e) == 0 for g, e in zip(got, expected))
    # they vanish on a rotation with a symbolic angle, and not on 2I
    assert all(sym.is_zero_matrix(c) for c in sym.so3_constraints(sym.rodrigues([1, 0, 0])))
    assert any(c != 0 for c in sym.so3_constraints(2 * I3))


def test_constraint_jacobian_rank_is_six_so_dim_so3_is_three():
    J = sym.constraint_jacobian()
    assert J.shape == (6, 9)
    assert sym.constraint_jacobian_rank() == 6
    assert 9 - sym.constraint_jacobian_rank(sym.rodrigues([0, 0, 1], sp.pi / 3)) == 3
    for R in so3.random_rotations(5, seed=1):
        assert sym.constraint_jacobian_rank(R) == 6


def test_constraint_jacobian_rank_at_non_rotation():
    with pytest.raises(ValueError, match=r"not orthogonal: ‖RᵀR − I‖ = 5\.2e\+00"):
        sym.constraint_jacobian_rank(2 * np.eye(3))
    with pytest.raises(ValueError, match="shape"):
        sym.constraint_jacobian_rank(np.eye(2))
    with pytest.raises(TypeError, match="numbers"):
        sym.constraint_jacobian_rank(sym.rotation_symbols())


def test_solve_scalar_ode_eq_106():
    sol = sym.solve_scalar_ode()
    t, a, x0 = sp.symbols("t a x_0", real=True)
    x = sp.Function("x")
    assert sol == sp.Eq(x(t), x0 * sp.exp(a * t))
    assert sol.rhs.subs(t, 0) == x0
    ode = sp.Eq(x(t).diff(t), a * x(t))
    assert sp.checkodesol(ode, sol) == (True, 0)
