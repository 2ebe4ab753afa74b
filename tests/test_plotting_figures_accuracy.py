"""Tests for course_lib.plotting.figures_accuracy: convergence and error curves on log axes."""

import matplotlib

matplotlib.use("Agg")


import matplotlib.pyplot as plt
import numpy as np
import pytest
from hypothesis import settings
from plotting_helpers import (
    _render,
)

from course_lib import so3
from course_lib.plotting import (
    plot_convergence,
    plot_error_curves,
)
from course_lib.tolerance import TOL

FAST = settings(max_examples=25, deadline=None)


# --- plot_convergence -------------------------------------------------------------------------


def test_plot_convergence_of_the_exponential_series():
    w = np.array([0.3, -0.4, 1.2])
    terms = np.arange(1, 21)

    def error(th, n):
        return np.linalg.norm(so3.exp_series(so3.hat(w * th), int(n)) - so3.exp(w * th))

    errors = {f"θ = {th}": [error(th, n) for n in terms] for th in (0.5, 2.0)}
    fig, ax = plot_convergence(terms, errors, title="Series (124)")
    assert ax.get_title() == "Series (124)" and ax.get_yscale() == "log"
    assert ax.get_xlabel() and ax.get_ylabel()
    lines = ax.get_lines()
    assert [ln.get_label() for ln in lines] == ["θ = 0.5", "θ = 2.0", "TOL = 1e-09"]
    assert np.allclose(lines[2].get_ydata(), TOL)
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert legend == ["θ = 0.5", "θ = 2.0", "TOL = 1e-09"]
    # the errors shrink: the series converges
    y = np.asarray(lines[0].get_ydata(), dtype=float)
    assert y[-1] < y[0]
    _render(fig)


def test_plot_convergence_zero_error_does_not_break_the_log_axis():
    # an exact 0 (series reproduced to the last bit) cannot sit on a log axis: it is left out
    fig, ax = plot_convergence([1, 2, 3], [1e-2, 1e-8, 0.0], label="error")
    y = np.asarray(ax.get_lines()[0].get_ydata(), dtype=float)
    assert np.isnan(y[2]) and np.allclose(y[:2], [1e-2, 1e-8])
    _render(fig)


@pytest.mark.parametrize(
    ("terms", "errors", "match"),
    [
        ([1, 2], [0.1, -0.1], "errors must be >= 0"),
        ([1, 2], [0.1], "shape of terms"),
        ([1, 2], [0.0, 0.0], "no error is positive"),
        ([1, 2], [0.1, np.nan], "NaN"),
        ([], [], "non-empty"),
    ],
)
def test_plot_convergence_refuses_bad_errors(terms, errors, match):
    with pytest.raises(ValueError, match=match):
        plot_convergence(terms, errors)


def test_plot_convergence_draws_dashed_references_on_log_log_axes():
    fig, ax = plot_convergence(
        [4, 8, 16],
        [1e-3, 6e-5, 4e-6],
        show_tol=False,
        logx=True,
        references={"slope $N^{-4}$": [1e-3, 6.25e-5, 3.9e-6]},
    )
    reference = ax.get_lines()[-1]
    assert (ax.get_xscale(), ax.get_yscale()) == ("log", "log")
    assert reference.get_label() == "slope $N^{-4}$" and reference.get_linestyle() == "--"
    assert [t.get_text() for t in ax.get_legend().get_texts()][-1] == "slope $N^{-4}$"
    plt.close(fig)


@pytest.mark.parametrize("reference", [[1.0, 2.0], [1.0, 0.0, 1.0], [1.0, -1.0, 1.0]])
def test_plot_convergence_refuses_bad_references(reference):
    with pytest.raises(ValueError, match="references.*positive with the shape of terms"):
        plot_convergence([1, 2, 3], [0.1, 0.01, 0.001], references={"bound": reference})


# plot_error_curves ----------------------------------------------------------------------------


def test_error_curves_are_log_log_and_floor_exact_zeros():
    x = np.logspace(-1, -6, 6)
    fig, ax = plot_error_curves(x, {"a": 1e-16 / x, "zero": np.zeros(6)}, "t", "gap", floor=1e-18)
    assert ax.get_xscale() == ax.get_yscale() == "log"
    assert ax.xaxis_inverted()
    lines = {line.get_label(): line for line in ax.get_lines()}
    assert np.allclose(lines["a"].get_ydata(), 1e-16 / x)
    assert np.all(lines["zero"].get_ydata() == 1e-18)


@pytest.mark.parametrize(
    "x, curves, error",
    [
        ([1.0, 0.0], {"a": [1.0, 1.0]}, ValueError),  # x not positive
        ([1.0, 0.1], [1.0, 1.0], TypeError),  # curves not a dict
        ([1.0, 0.1], {"a": [1.0, -1.0]}, ValueError),  # negative error
        ([1.0, 0.1], {"a": [1.0, np.nan]}, ValueError),
        ([1.0, 0.1], {"a": [1.0, 1.0, 1.0]}, ValueError),  # shapes differ
    ],
)
def test_error_curves_reject_bad_input(x, curves, error):
    with pytest.raises(error):
        plot_error_curves(x, curves, "t", "x")
