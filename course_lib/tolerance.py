"""The one tolerance policy of course_lib.

Every numerical check in the package (is this a rotation? is this matrix skew? is this axis a
unit vector? does a student's numeric answer match?) compares a *residual* against the same
absolute tolerance::

    TOL = 1e-9

Residuals are measured in the Frobenius norm for matrices and the Euclidean norm for vectors,
for example ``‖RᵀR − I‖_F ≤ TOL`` and ``|det R − 1| ≤ TOL``.

Why 1e-9: rotations built in double precision from a few products carry errors of order
1e-16 to 1e-15, and entries typed in by hand to 10 significant digits (``0.7071067812``)
carry errors of order 1e-10. Both pass; a matrix that is wrong in the third digit, or a
reflection, fails by many orders of magnitude. Functions that accept a ``tol`` argument use
``TOL`` as its default, so a lab that needs a looser check passes ``tol=`` explicitly rather
than changing the policy.

Two checks compare sizes that can be far from 1 and scale the tolerance with them beyond unit
size, because rounding does: :func:`course_lib.rigid.check_rigid` (tol × ‖p₁ − p₂‖ and
tol × ‖p₁‖‖p₂‖) and the default equality of :func:`course_lib.groups.check_group` (tol × the
largest entry). For inputs of unit size both are the plain ``TOL``.

Messages name the tolerance with :func:`tol_label` and print residuals with
:func:`fmt_residual`, which never shows a failing residual as equal to the tolerance.
"""

import math
import numbers

TOL = 1e-9


def check_tol(tol):
    """Return ``tol`` as a float after checking it is a finite real number >= 0.

    Parameters
    ----------
    tol : real number
        A tolerance passed by a caller in place of the default ``TOL``.

    Returns
    -------
    float

    Raises
    ------
    TypeError
        If ``tol`` is not a real number (a bool, a string, None...).
    ValueError
        If ``tol`` is negative, NaN or infinite.

    Examples
    --------
    >>> check_tol(1e-6)
    1e-06
    >>> check_tol(-1)
    Traceback (most recent call last):
    ...
    ValueError: tol must be a finite number >= 0 (default TOL = 1e-09), got -1.0
    """
    if type(tol) is float and 0.0 <= tol < math.inf:  # the common case, fast
        return tol
    if isinstance(tol, bool) or not isinstance(tol, numbers.Real):
        raise TypeError(
            f"tol must be a real number (default {tol_label(TOL)}), got {type(tol).__name__} "
            f"{tol!r}"
        )
    try:
        value = float(tol)
    except OverflowError:  # a Python int beyond 1.8e308
        value, tol = math.inf, "an integer beyond 1.8e308"
    if not math.isfinite(value) or value < 0:
        shown = tol if isinstance(tol, str) else repr(value)
        raise ValueError(
            f"tol must be a finite number >= 0 (default {tol_label(TOL)}), got {shown}"
        )
    return value


def tol_label(tol):
    """How error messages name a tolerance: ``TOL = 1e-09`` for the policy's, else ``tol = ...``.

    Parameters
    ----------
    tol : float

    Returns
    -------
    str

    Examples
    --------
    >>> tol_label(TOL), tol_label(1e-6), tol_label(1.5e-9)
    ('TOL = 1e-09', 'tol = 1e-06', 'tol = 1.5e-09')
    """
    return f"TOL = {TOL!r}" if tol == TOL else f"tol = {float(tol)!r}"


def fmt_residual(value, tol):
    """A residual in ``.1e`` form, with more digits only when needed to tell it from ``tol``.

    A message never reads ``1.0e-09 > TOL = 1e-09``: the value gets as many digits as it takes
    to show on which side of the tolerance it lies.

    Parameters
    ----------
    value, tol : float

    Returns
    -------
    str

    Examples
    --------
    >>> fmt_residual(3.2e-2, TOL), fmt_residual(1.04e-9, TOL), fmt_residual(1e-9 + 1e-24, TOL)
    ('3.2e-02', '1.04e-09', '1.000000000000001e-09')
    """
    value = float(value)
    if not math.isfinite(value):
        return repr(value)
    for digits in range(1, 17):
        text = f"{value:.{digits}e}"
        shown = float(text)
        if (shown > tol) == (value > tol) and (shown < tol) == (value < tol):
            return text
    return repr(value)
