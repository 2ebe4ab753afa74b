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
    if isinstance(tol, bool) or not isinstance(tol, numbers.Real):
        raise TypeError(
            f"tol must be a real number (default TOL = {TOL:g}), got {type(tol).__name__} {tol!r}"
        )
    tol = float(tol)
    if not math.isfinite(tol) or tol < 0:
        raise ValueError(f"tol must be a finite number >= 0 (default TOL = {TOL:g}), got {tol!r}")
    return tol


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
    >>> tol_label(TOL), tol_label(1e-6)
    ('TOL = 1e-09', 'tol = 1e-06')
    """
    return f"TOL = {tol:g}" if tol == TOL else f"tol = {tol:g}"
