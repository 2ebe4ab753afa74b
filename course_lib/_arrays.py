"""The one validation layer of course_lib: array-likes in, checked float64 arrays out.

Every public numeric function of course_lib starts by calling one of these, so a student who
passes a string, a ragged list, a masked array, a matrix of the wrong size, a number too large
for float64 or a NaN gets the same kind of message everywhere: the argument's name, what was
wrong and what was expected.

============================  ===================================================================
helper                        returns
============================  ===================================================================
:func:`as_float_array`        any shape, float64 (no finiteness check)
:func:`as_finite_array`       any shape, float64, finite
:func:`as_scalar`             one finite real number, as a Python float
:func:`as_positive`           one finite real number > 0, as a Python float
:func:`as_vector`             one finite n-vector, shape (n,)
:func:`as_vector3`            one finite 3-vector, shape (3,)
:func:`as_vectors`            finite 3-vectors, shape (..., 3)
:func:`as_points`             one or more finite points of dimension d, shape (k, d)
:func:`as_matrix`             one finite n x n matrix, shape (n, n)
:func:`as_direction`          one non-zero 3-vector, normalised (overflow-safe)
:func:`as_unit_axes`          unit 3-vectors within ``tol``, shape (..., 3)
:func:`as_quaternions`        finite quaternions (w, x, y, z), shape (..., 4)
:func:`as_unit_quaternions`   unit quaternions within ``tol``, shape (..., 4)
:func:`as_matrices`           finite n x n matrices, shape (..., n, n)
:func:`as_square_matrices`    finite square matrices of any size, shape (..., n, n)
:func:`as_angles`             finite angles of any shape
:func:`as_count`              a Python int >= a minimum
:func:`as_str`                a str (labels, titles)
:func:`as_labels`             one str or None per item, as a list
:func:`as_choice`             one of a few named options (a str)
:func:`broadcast_batch`       the common batch shape of several arguments, or a ValueError
                              naming each argument and its shape
============================  ===================================================================

Examples
--------
>>> as_vector3([1, 2, 3], "w")
array([1., 2., 3.])
>>> as_direction([0, 0, 1e200], "axis")
array([0., 0., 1.])
>>> as_vector3([1, 2], "w")
Traceback (most recent call last):
...
ValueError: w must be one 3-vector of shape (3,), got shape (2,)
"""

import numbers

import numpy as np

from .tolerance import TOL, check_tol, fmt_residual, tol_label

_F64 = np.dtype(np.float64)


def _overflow(name):
    return ValueError(
        f"{name} has an entry too large for a float64 (|x| > 1.8e308); expected finite real numbers"
    )


def _from_masked(x, name):
    """The data of a masked array with nothing masked; a ValueError if anything is masked."""
    hidden = int(np.ma.count_masked(x))
    if hidden:
        raise ValueError(
            f"{name} is a masked array with {hidden} masked entr{'y' if hidden == 1 else 'ies'}; "
            f"course_lib does not guess the hidden values: pass {name}.filled(value) or drop them"
        )
    return np.ma.getdata(x)


def _from_objects(arr, name):
    """float64 from an object array whose entries must all be real numbers."""
    entries = arr.ravel()
    if not all(isinstance(v, numbers.Real) for v in entries):
        kinds = sorted({type(v).__name__ for v in entries})
        raise TypeError(f"{name} must be an array of real numbers, got entries of type {kinds}")
    try:
        return arr.astype(np.float64)
    except OverflowError:  # Python ints beyond 1.8e308
        raise _overflow(name) from None


def as_float_array(x, name):
    """Convert an array-like of real numbers to a float64 array, refusing anything else.

    Never writes into ``x``; the result may share memory with it (read-only arrays are fine).

    Raises
    ------
    TypeError
        For non-numeric input (strings, None, objects, complex numbers).
    ValueError
        For ragged nesting, masked entries, or numbers too large for float64.
    """
    if type(x) is np.ndarray and x.dtype is _F64:
        return x
    if isinstance(x, (str, bytes)) or x is None:
        raise TypeError(f"{name} must be an array of real numbers, got {type(x).__name__} {x!r}")
    if isinstance(x, np.ma.MaskedArray):
        x = _from_masked(x, name)
    try:
        arr = np.asarray(x)
    except ValueError as err:  # ragged nested lists
        raise ValueError(f"{name} must be a rectangular array of real numbers: {err}") from None
    except OverflowError:
        raise _overflow(name) from None
    if arr.dtype == object:
        return _from_objects(arr, name)
    if arr.dtype.kind == "c":
        raise TypeError(f"{name} must be real, got complex dtype {arr.dtype}")
    if arr.dtype.kind not in "biuf":
        raise TypeError(f"{name} must be an array of real numbers, got dtype {arr.dtype}")
    if arr.dtype.kind == "f" and arr.dtype.itemsize > 8:  # long double: may exceed float64
        with np.errstate(over="ignore"):
            out = arr.astype(np.float64)
        if np.any(np.isinf(out) & np.isfinite(arr)):
            raise _overflow(name)
        return out
    return np.asarray(arr, dtype=np.float64)


_NUMBER = (float, int)


def small_floats(x, n):
    """One finite vector of ``n`` entries as a tuple of Python floats, else None.

    The single-call path of the public functions: ``x`` is a float64 array of shape (n,) or a
    list or tuple of n ints and floats, all finite. Anything else (a batch, another dtype, NaN,
    an int too large for a float) gives None, and the caller takes its validating batch path,
    which accepts or explains it.

    >>> small_floats([1, 2.5, 3], 3)
    (1.0, 2.5, 3.0)
    >>> small_floats([1, float("nan"), 3], 3) is None, small_floats([[1, 2, 3]], 3) is None
    (True, True)
    """
    if type(x) is np.ndarray:
        if x.dtype is not _F64 or x.shape != (n,):
            return None
        out = tuple(x.tolist())
    elif type(x) in (list, tuple) and len(x) == n and all(type(v) in _NUMBER for v in x):
        try:
            out = tuple(float(v) for v in x)
        except OverflowError:  # an int beyond 1.8e308: the batch path says so
            return None
    else:
        return None
    for v in out:
        if v - v != 0.0:  # NaN or infinity: the batch path explains
            return None
    return out


def small_tol(tol):
    """``tol`` when it is a float in [0, 1) (the single-call paths take it as it is), else None."""
    return tol if type(tol) is float and 0.0 <= tol < 1.0 else None


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


def as_scalar(x, name):
    """One finite real number, as a Python float (bools, strings and arrays of size > 1 refused).

    >>> as_scalar(np.float32(0.5), "theta")
    0.5
    """
    if isinstance(x, (bool, np.bool_)):
        raise TypeError(f"{name} must be a real number, got bool {x!r}")
    arr = as_float_array(x, name)
    if arr.ndim != 0:
        raise ValueError(f"{name} must be a single number, got an array of shape {arr.shape}")
    value = float(arr)
    if not np.isfinite(value):
        raise ValueError(f"{name} must be a finite real number, not NaN or infinity; got {value!r}")
    return value


def as_positive(x, name):
    """One finite real number > 0, as a Python float (a length, a size, a scale).

    >>> as_positive(2, "r")
    2.0
    >>> as_positive(0, "r")
    Traceback (most recent call last):
    ...
    ValueError: r must be > 0, got 0.0
    """
    value = as_scalar(x, name)
    if not value > 0:
        raise ValueError(f"{name} must be > 0, got {value!r}")
    return value


def as_vectors(x, name="w"):
    """A finite float64 array of shape (..., 3)."""
    arr = as_float_array(x, name)
    if arr.ndim == 0 or arr.shape[-1] != 3:
        raise ValueError(f"{name} must have shape (..., 3) (3-vectors), got shape {arr.shape}")
    return require_finite(arr, name)


def as_vector(x, name, n=3):
    """One finite n-vector: a float64 array of shape (n,) (a 2-vector for a planar figure).

    >>> as_vector([1, 2], "v", 2)
    array([1., 2.])
    >>> as_vector([1, 2, 3], "v", 2)
    Traceback (most recent call last):
    ...
    ValueError: v must be one 2-vector of shape (2,), got shape (3,)
    """
    arr = as_float_array(x, name)
    if arr.shape != (n,):
        raise ValueError(f"{name} must be one {n}-vector of shape ({n},), got shape {arr.shape}")
    return require_finite(arr, name)


def as_vector3(x, name="w"):
    """One finite 3-vector: a float64 array of shape (3,)."""
    return as_vector(x, name, 3)


def as_points(x, name="p", d=3, min_count=1):
    """One point of shape (d,) or n points of shape (n, d), finite, returned as (n, d).

    >>> as_points([1, 2], "p", 2)
    array([[1., 2.]])
    >>> as_points([[0, 0, 0]], "points", 3, min_count=2)
    Traceback (most recent call last):
    ...
    ValueError: points must hold at least 2 points, got 1
    """
    arr = as_float_array(x, name)
    shape = arr.shape
    if arr.ndim == 1:
        arr = arr[None, :]
    if arr.ndim != 2 or arr.shape[1] != d:
        raise ValueError(
            f"{name} must have shape ({d},) or (n, {d}) (one point or n points in {d}D), "
            f"got shape {shape}"
        )
    require_finite(arr, name)
    if arr.shape[0] < min_count:
        raise ValueError(f"{name} must hold at least {min_count} points, got {arr.shape[0]}")
    return arr


def vector_norm(v):
    """‖v‖ along the last axis without overflow or underflow (scaled by the largest entry).

    Infinite where an entry is infinite, or where the norm itself exceeds 1.8e308.
    """
    v = np.asarray(v)
    if v.shape[-1] == 0:
        return np.zeros(v.shape[:-1])
    big = np.max(np.abs(v), axis=-1, keepdims=True)
    safe = np.where((big > 0) & (big < np.inf), big, 1.0)
    with np.errstate(over="ignore", invalid="ignore"):
        norm = big[..., 0] * np.sqrt(np.sum((v / safe) ** 2, axis=-1))
    return np.where(big[..., 0] == np.inf, np.inf, norm)


def frobenius_norm(M):
    """‖M‖_F over the last two axes, without overflow or underflow."""
    M = np.asarray(M)
    return vector_norm(M.reshape(M.shape[:-2] + (M.shape[-2] * M.shape[-1],)))


def as_direction(x, name="axis", tol=TOL):
    r"""One non-zero 3-vector, returned normalised, :math:`x / \|x\|`.

    The norm is taken without overflow (``[1e160, 1e160, 0]`` is a direction, not infinity).

    Raises
    ------
    ValueError
        If ``x`` is not one finite 3-vector, or :math:`\|x\| \le` tol (no direction).
    """
    v = as_vector3(x, name)
    tol = check_tol(tol)
    length = float(vector_norm(v))
    if not length > tol:
        raise ValueError(
            f"{name} must be non-zero to define a direction: ‖{name}‖ = "
            f"{fmt_residual(length, tol)} ≤ {tol_label(tol)}"
        )
    big = float(np.max(np.abs(v)))
    unit = v / big
    return unit / np.linalg.norm(unit)


def as_unit_axes(x, name="w", tol=TOL, hint="divide it by its norm"):
    r"""Unit 3-vectors, :math:`|\|x\| - 1| \le` tol, as a float64 array of shape (..., 3).

    The message names the worst norm and its batch index, and ends with ``hint``.
    """
    return _require_unit(as_vectors(x, name), name, check_tol(tol), "a unit vector", hint)


def as_quaternions(x, name="q"):
    """A finite float64 array of shape (..., 4): quaternions, scalar first (w, x, y, z)."""
    arr = as_float_array(x, name)
    if arr.ndim == 0 or arr.shape[-1] != 4:
        raise ValueError(
            f"{name} must have shape (..., 4) (quaternions (w, x, y, z), scalar first), "
            f"got shape {arr.shape}"
        )
    return require_finite(arr, name)


def as_unit_quaternions(x, name="q", tol=TOL):
    r"""Unit quaternions, :math:`|\|q\| - 1| \le` tol, as a float64 array of shape (..., 4).

    >>> as_unit_quaternions([1, 0, 0, 0], "q")
    array([1., 0., 0., 0.])
    >>> as_unit_quaternions([1, 1, 0, 0], "q")
    Traceback (most recent call last):
    ...
    ValueError: q must be a unit quaternion: ‖q‖ = 1.41421, |‖q‖ − 1| = 4.1e-01 > TOL = 1e-09;
    divide it by its norm (a rotation is a quaternion of norm 1)
    """
    hint = "divide it by its norm (a rotation is a quaternion of norm 1)"
    return _require_unit(as_quaternions(x, name), name, check_tol(tol), "a unit quaternion", hint)


def _require_unit(w, name, tol, what, hint):
    """w itself if every row along the last axis has norm 1 within tol, else a ValueError that
    names the worst norm and its batch index, and ends with ``hint``."""
    norm = vector_norm(w)
    off = np.abs(norm - 1.0)
    if not np.all(off <= tol):
        worst = np.unravel_index(np.argmax(off), off.shape) if off.ndim else ()
        where = f" at batch index {tuple(int(i) for i in worst)}" if worst else ""
        raise ValueError(
            f"{name} must be {what}: ‖{name}‖ = {float(norm[worst]):.6g}, |‖{name}‖ − 1| = "
            f"{fmt_residual(float(off[worst]), tol)} > {tol_label(tol)}{where}; {hint}"
        )
    return w


def as_matrices(x, name="R", n=3, finite=True):
    """A float64 array of shape (..., n, n), finite unless the caller checks that itself."""
    arr = as_float_array(x, name)
    if arr.ndim < 2 or arr.shape[-2:] != (n, n):
        raise ValueError(
            f"{name} must have shape (..., {n}, {n}) ({n}x{n} matrices), got shape {arr.shape}"
        )
    return require_finite(arr, name) if finite else arr


def as_matrix(x, name="R", n=3):
    """One finite n x n matrix: a float64 array of shape (n, n).

    >>> as_matrix(np.eye(2), "R", 3)
    Traceback (most recent call last):
    ...
    ValueError: R must be one 3x3 matrix of shape (3, 3), got shape (2, 2)
    """
    arr = as_float_array(x, name)
    if arr.shape != (n, n):
        raise ValueError(
            f"{name} must be one {n}x{n} matrix of shape ({n}, {n}), got shape {arr.shape}"
        )
    return require_finite(arr, name)


def as_square_matrices(x, name="A"):
    """A finite float64 array of shape (..., n, n) for any n >= 1."""
    arr = as_float_array(x, name)
    if arr.ndim < 2 or arr.shape[-1] != arr.shape[-2] or arr.shape[-1] == 0:
        raise ValueError(f"{name} must have shape (..., n, n) (square matrices), got {arr.shape}")
    return require_finite(arr, name)


def as_finite_array(x, name):
    """A finite float64 array of any shape."""
    return require_finite(as_float_array(x, name), name)


def as_angles(x, name="theta"):
    """A finite float64 array of any shape (angles in radians)."""
    return as_finite_array(x, name)


def as_count(n, name="n", minimum=0, maximum=None):
    """A plain int in [minimum, maximum] (bools and floats are refused)."""
    if isinstance(n, bool) or not isinstance(n, numbers.Integral):
        raise TypeError(f"{name} must be an integer, got {type(n).__name__} {n!r}")
    if n < minimum:
        raise ValueError(f"{name} must be >= {minimum}, got {n}")
    if maximum is not None and n > maximum:
        raise ValueError(f"{name} must be <= {maximum}, got {n}")
    return int(n)


def as_str(x, name):
    """``x`` itself if it is a str (a title, a label), else a TypeError naming ``name``.

    >>> as_str(3, "title")
    Traceback (most recent call last):
    ...
    TypeError: title must be a str, got int
    """
    if not isinstance(x, str):
        raise TypeError(f"{name} must be a str, got {type(x).__name__}")
    return x


def as_labels(labels, n, name="labels"):
    """One label (str or None) per item, as a list of length ``n``; ``None`` gives no labels.

    A single str is one label.

    >>> as_labels("$p$", 1), as_labels(None, 2)
    (['$p$'], [None, None])
    >>> as_labels(["$p$"], 2)
    Traceback (most recent call last):
    ...
    ValueError: labels must hold one label per item: expected 2, got 1
    """
    if labels is None:
        return [None] * n
    if isinstance(labels, str):
        labels = [labels]
    labels = list(labels)
    if len(labels) != n:
        raise ValueError(f"{name} must hold one label per item: expected {n}, got {len(labels)}")
    for lab in labels:
        if lab is not None and not isinstance(lab, str):
            raise TypeError(f"each of {name} must be a str or None, got {type(lab).__name__}")
    return labels


def as_choice(x, name, choices):
    """``x`` if it is one of the str ``choices``, else a ValueError listing them.

    >>> as_choice("2d", "kind", ("3d", "2d"))
    '2d'
    >>> as_choice("wavy", "style", ("solid", "dashed", "dotted"))
    Traceback (most recent call last):
    ...
    ValueError: style must be one of ['dashed', 'dotted', 'solid'], got 'wavy'
    """
    if not isinstance(x, str) or x not in choices:
        if len(choices) == 2:
            allowed = " or ".join(repr(c) for c in choices)
        else:
            allowed = f"one of {sorted(choices)}"
        raise ValueError(f"{name} must be {allowed}, got {x!r}")
    return x


def broadcast_batch(*named):
    """The broadcast batch shape of ``(name, array, core_ndim)`` triples, or a ValueError.

    ``core_ndim`` is 1 for vectors (..., 3) and 2 for matrices (..., 3, 3); the rest of each
    shape is its batch shape.

    >>> broadcast_batch(("p", np.zeros((4, 3)), 1), ("frame", np.zeros((3, 3)), 2))
    (4,)
    >>> broadcast_batch(("p", np.zeros((2, 3)), 1), ("frame", np.zeros((5, 3, 3)), 2))
    Traceback (most recent call last):
    ...
    ValueError: the batches do not broadcast: p has shape (2, 3) (batch (2,)),
    frame has shape (5, 3, 3) (batch (5,))
    """
    batches = [np.shape(a)[: np.ndim(a) - core] for _, a, core in named]
    try:
        return np.broadcast_shapes(*batches)
    except ValueError:
        shapes = ", ".join(
            f"{name} has shape {np.shape(a)} (batch {b})" for (name, a, _), b in zip(named, batches)
        )
        raise ValueError(f"the batches do not broadcast: {shapes}") from None


def fmt_vector(v, digits=4):
    """A short, platform-stable text form of a vector or scalar (rounded, no negative zeros)."""
    arr = np.asarray(v, dtype=np.float64)
    with np.errstate(over="ignore", invalid="ignore"):  # rounding 1e305 to 4 digits overflows
        arr = np.where(np.abs(arr) < 1e290, np.round(arr, digits), arr) + 0.0
    if arr.ndim == 0:
        return f"{float(arr):.{digits}g}"
    return np.array2string(arr, separator=", ", precision=digits, suppress_small=True)
