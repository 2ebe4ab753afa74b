r"""Error plots on a log scale: the convergence of a series and errors near a limit.

:func:`plot_convergence` shows the error of the truncated exponential series, eq. (124)/(126);
:func:`plot_error_curves` errors against a small parameter such as :math:`\pi - \theta`
(chapter 04: reading the angle and axis of a rotation near 180°).
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from .._arrays import as_finite_array, as_positive, as_str
from ..tolerance import TOL, tol_label
from .axes import _LAYOUT_2D, DPI, FONT_SIZE, TITLE_SIZE, _dim

__all__ = ["plot_convergence", "plot_error_curves"]


def _error_series(series, shape):
    """The error curves by name, each of ``shape``, >= 0; zeros become gaps (NaN) on a log scale."""
    ys = {}
    for name, err in series.items():
        y = as_finite_array(err, "errors" if name is None else f"errors[{name!r}]")
        if y.shape != shape:
            raise ValueError(f"errors must have the shape of terms {shape}, got {y.shape}")
        if (y < 0).any():
            raise ValueError(f"errors must be >= 0 (they are norms), got min {y.min():.3g}")
        if not (y > 0).any():
            raise ValueError("no error is positive: nothing to show on a log scale")
        ys[name] = np.where(y > 0, y, np.nan)
    return ys


def _reference_curves(references, shape):
    """The reference curves by name, each positive and of ``shape``."""
    refs = {}
    for name, ref in references.items():
        y = as_finite_array(ref, f"references[{name!r}]")
        if y.shape != shape or not (y > 0).all():
            raise ValueError(
                f"references[{name!r}] must be positive with the shape of terms "
                f"{shape}, got shape {y.shape}"
            )
        refs[name] = y
    return refs


def plot_convergence(
    terms,
    errors,
    title="Convergence of the series",
    ax=None,
    label=None,
    show_tol=True,
    xlabel="number of terms $N$",
    ylabel=r"error $\|\cdot\|_F$ (log scale)",
    references=None,
    logx=False,
):
    r"""Semilog plot of an approximation error against the number of series terms.

    Made for the truncated series of the matrix exponential (eq. 124, 126),

    .. math:: \Big\| \sum_{n=0}^{N-1} \frac{A^n}{n!} - e^{A} \Big\|_F,

    but any non-negative errors can be plotted. Exact zeros cannot be shown on a log axis and
    are left out of the line; a dotted line marks the tolerance ``TOL``. A new figure uses
    constrained layout (see :func:`axes2d`): long tick labels such as :math:`10^{-16}` and a
    tall y label fit on the canvas without ``fig.tight_layout()``.

    Parameters
    ----------
    terms : array_like, shape (k,)
        Numbers of terms (the x values).
    errors : array_like, shape (k,), or dict of str -> array_like
        Errors for each entry of ``terms``; a dict plots one labelled line per entry.
    title : str
        Title of the axes.
    ax : matplotlib.axes.Axes, optional
        A 2D axes to draw into; a new figure by default.
    label : str, optional
        Legend label of a single error array.
    show_tol : bool, default True
        Draw the horizontal line ``y = TOL``.
    xlabel, ylabel : str
        Axis labels.
    references : dict of str -> array_like, optional
        Reference curves (a bound, a slope :math:`N^{-p}`), each of the shape of ``terms``,
        drawn as thin dashed black lines with their label.
    logx : bool, default False
        Log scale on the x axis too (for convergence orders: a power law is a straight line).

    Returns
    -------
    fig : matplotlib.figure.Figure
    ax : matplotlib.axes.Axes

    Raises
    ------
    ValueError
        If shapes differ, an error is negative or non-finite, or no error is positive; or a
        reference curve does not have the shape of ``terms`` or is not positive.
    TypeError
        If ``ax`` is a 3D axes.

    Examples
    --------
    >>> import math, matplotlib.pyplot as plt
    >>> n = [1, 2, 3, 4, 5]
    >>> errors = [abs(math.e - sum(1 / math.factorial(j) for j in range(k))) for k in n]
    >>> fig, ax = plot_convergence(n, errors)
    >>> ax.get_yscale(), len(ax.get_lines())
    ('log', 2)
    >>> plt.close(fig)
    >>> fig, ax = plot_convergence(n, errors, show_tol=False, logx=True,
    ...                            references={"bound": [2 * e for e in errors]})
    >>> ax.get_xscale(), ax.get_lines()[-1].get_label(), ax.get_lines()[-1].get_linestyle()
    ('log', 'bound', '--')
    >>> plt.close(fig)
    """
    x = as_finite_array(terms, "terms")
    if x.ndim != 1 or x.size == 0:
        raise ValueError(f"terms must be a non-empty 1-D array, got shape {x.shape}")
    ys = _error_series(errors if isinstance(errors, dict) else {label: errors}, x.shape)
    refs = _reference_curves(references or {}, x.shape)
    if ax is None:
        as_str(title, "title")
        fig, ax = plt.subplots(figsize=(5.6, 4.0), dpi=DPI, layout=_LAYOUT_2D)
    else:
        if _dim(ax) != 2:
            raise TypeError("plot_convergence needs a 2D axes; got a 3D axes")
        fig = ax.figure
    for name, y in ys.items():
        ax.plot(x, y, marker="o", markersize=4, linewidth=1.8, label=name)
    for name, y in refs.items():
        ax.plot(x, y, color="black", linestyle="--", linewidth=1.0, label=name)
    ax.set_yscale("log")
    if logx:
        ax.set_xscale("log")
    if show_tol:
        ax.axhline(TOL, color="0.4", linestyle=":", linewidth=1.2, label=tol_label(TOL))
    ax.set_xlabel(as_str(xlabel, "xlabel"), fontsize=FONT_SIZE)
    ax.set_ylabel(as_str(ylabel, "ylabel"), fontsize=FONT_SIZE)
    ax.set_title(as_str(title, "title"), fontsize=TITLE_SIZE)
    ax.tick_params(axis="both", labelsize=FONT_SIZE - 2)
    ax.grid(True, which="major", color="0.9")
    if any(name is not None for name in ys) or show_tol or refs:
        ax.legend(fontsize=FONT_SIZE - 1)
    return fig, ax


# --------------------------------------------------------------------------------------------
# Chapter 04: errors near a limit (the angle of a rotation near 180°)
# --------------------------------------------------------------------------------------------


def plot_error_curves(
    x, curves, title, xlabel, ylabel="error (log scale)", floor=1e-17, show_tol=True, reverse_x=True
):
    r"""Log-log plot of errors against a small parameter, e.g. :math:`\pi - \theta`.

    Drawn with :func:`plot_convergence` on a logarithmic x axis. Errors below ``floor``
    (exact zeros included, which a log axis cannot show) are drawn at ``floor``, so a method
    that is exact still shows as a line at the bottom of the plot.

    Parameters
    ----------
    x : array_like, shape (k,)
        Positive values of the parameter (the x values).
    curves : dict of str -> array_like, shape (k,)
        One labelled error curve per entry (errors >= 0).
    title, xlabel, ylabel : str
        Title and axis labels.
    floor : float, default 1e-17
        Smallest error drawn (> 0).
    show_tol : bool, default True
        Draw the horizontal line ``y = TOL``.
    reverse_x : bool, default True
        Let x decrease to the right, so that "approaching the limit" reads left to right.

    Returns
    -------
    fig : matplotlib.figure.Figure
    ax : matplotlib.axes.Axes

    Raises
    ------
    ValueError
        If an x value is not positive, shapes differ, an error is negative or non-finite, or
        ``floor`` is not positive.
    TypeError
        If ``curves`` is not a dict.

    Examples
    --------
    >>> import numpy as np, matplotlib.pyplot as plt
    >>> gaps = np.logspace(-1, -8, 8)
    >>> fig, ax = plot_error_curves(gaps, {"1e-16/gap": 1e-16 / gaps, "exact": 0 * gaps},
    ...                             "Errors", "gap")
    >>> ax.get_xscale(), bool(ax.xaxis_inverted()), float(ax.get_lines()[1].get_ydata().min())
    ('log', True, 1e-17)
    >>> plt.close(fig)
    """
    xs = as_finite_array(x, "x")
    if xs.ndim != 1 or not (xs > 0).all():
        raise ValueError(f"x must be a 1-D array of positive values (log axis), got {x!r}")
    if not isinstance(curves, dict):
        raise TypeError(f"curves must be a dict of label -> errors, got {type(curves).__name__}")
    low = as_positive(floor, "floor")
    clipped = {}
    for name, err in curves.items():
        y = as_finite_array(err, f"curves[{name!r}]")
        if (y < 0).any():
            raise ValueError(f"curves[{name!r}] must be >= 0 (errors), got min {y.min():.3g}")
        clipped[name] = np.maximum(y, low)
    fig, ax = plot_convergence(
        xs, clipped, title=title, show_tol=show_tol, xlabel=xlabel, ylabel=ylabel
    )
    ax.set_xscale("log")
    if reverse_x:
        ax.invert_xaxis()
    return fig, ax
