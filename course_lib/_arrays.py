"""Input conversion shared by the numeric modules: array-likes in, float64 arrays out.

Every public numeric function of course_lib starts by calling one of these, so a student who
passes a string, a ragged list, a matrix of the wrong size or a NaN gets the same kind of
message everywhere: what was wrong, and what was expected.
"""

import numbers

import numpy as np


def as_float_array(x, name):
    """Convert an array-like of real numbers to a float64 array, refusing anything else.

    Raises TypeError for non-numeric input (strings, None, objects, complex numbers) and
    ValueError for ragged nesting.
    """
    if isinstance(x, (str, bytes)) or x is None:
        raise TypeError(f"{name} must be an array of real numbers, got {type(x).__name__} {x!r}")
    try:
        arr = np.asarray(x)
    except ValueError as err:  # ragged nested lists
        raise ValueError(f"{name} must be a rectangular array of real numbers: {err}") from None
    if arr.dtype == object:
        try:
            if not all(isinstance(v, numbers.Real) for v in arr.ravel()):
                raise TypeError
            arr = arr.astype(np.float64)
        except (TypeError, ValueError):
            raise TypeError(
                f"{name} must be an array of real numbers, got entries of type "
                f"{sorted({type(v).__name__ for v in arr.ravel()})}"
            ) from None
    if arr.dtype.kind == "c":
        raise TypeError(f"{name} must be real, got complex dtype {arr.dtype}")
    if arr.dtype.kind not in "biuf":
        raise TypeError(f"{name} must be an array of real numbers, got dtype {arr.dtype}")
    return np.asarray(arr, dtype=np.float64)


def require_finite(arr, name):
    """Raise ValueError if ``arr`` holds NaN or infinity, saying how many and where."""
    finite = np.isfinite(arr)
    if not finite.all():
        bad = np.argwhere(~finite)
        first = tuple(int(i) for i in bad[0])
        raise ValueError(
            f"{name} contains NaN or infinity ({len(bad)} non-finite "
            f"entr{'y' if len(bad) == 1 else 'ies'}, first at index {first}); "
            f"expected finite real numbers"
        )
    return arr


def as_vectors(x, name="w"):
    """A finite float64 array of shape (..., 3)."""
    arr = as_float_array(x, name)
    if arr.ndim == 0 or arr.shape[-1] != 3:
        raise ValueError(f"{name} must have shape (..., 3) (3-vectors), got shape {arr.shape}")
    return require_finite(arr, name)


def as_matrices(x, name="R", n=3, finite=True):
    """A float64 array of shape (..., n, n), finite unless the caller checks that itself."""
    arr = as_float_array(x, name)
    if arr.ndim < 2 or arr.shape[-2:] != (n, n):
        raise ValueError(
            f"{name} must have shape (..., {n}, {n}) ({n}x{n} matrices), got shape {arr.shape}"
        )
    return require_finite(arr, name) if finite else arr


def as_square_matrices(x, name="A"):
    """A finite float64 array of shape (..., n, n) for any n >= 1."""
    arr = as_float_array(x, name)
    if arr.ndim < 2 or arr.shape[-1] != arr.shape[-2] or arr.shape[-1] == 0:
        raise ValueError(f"{name} must have shape (..., n, n) (square matrices), got {arr.shape}")
    return require_finite(arr, name)


def as_angles(x, name="theta"):
    """A finite float64 array of any shape (angles in radians)."""
    return require_finite(as_float_array(x, name), name)


def as_count(n, name="n", minimum=0):
    """A plain int >= minimum (bools and floats are refused)."""
    if isinstance(n, bool) or not isinstance(n, numbers.Integral):
        raise TypeError(f"{name} must be an integer, got {type(n).__name__} {n!r}")
    if n < minimum:
        raise ValueError(f"{name} must be >= {minimum}, got {n}")
    return int(n)


def fmt_vector(v, digits=4):
    """A short, platform-stable text form of a vector or scalar (rounded, no negative zeros)."""
    arr = np.round(np.asarray(v, dtype=np.float64), digits) + 0.0
    if arr.ndim == 0:
        return f"{float(arr):.{digits}g}"
    return np.array2string(arr, separator=", ", precision=digits, suppress_small=True)
