r"""Key-stretched digests of rounded values: what the checker compares an answer with.

The package stores no value of an expected answer, only digests that are slow to compute on
purpose (``hashlib.scrypt``, :data:`SCRYPT` parameters, about 1 MiB of memory and a few
milliseconds per digest), so that trying candidate answers offline costs thousands of times
more per guess than a plain hash, and a fit has no values to fit.

**Rounding.** A real value :math:`v` is rounded to a grid of step :math:`h`:
:math:`c = \lfloor v / h \rfloor`. The stored digest is that of the reference value's cell. When
a student's value lies within :math:`\varepsilon` (the noise allowed, TOL-sized) of a cell
edge, the neighbouring cell is tried too, so a value within :math:`\varepsilon` of the
reference value always matches, and one more than :math:`h + \varepsilon` away never does.
Nothing about where the reference value lies in its cell is stored (an offset per value would
be a fast, unstretched test of a guess).

**Several values at once.** A symbolic answer has hundreds of values (every entry at every
sample point). They are combined into :math:`K` random projections
:math:`z = \sum_i w_i\,\operatorname{asinh}(v_i)` with :math:`\sum_i |w_i| = 1`, so that every
value within :math:`\varepsilon` moves :math:`z` by at most :math:`\varepsilon`; only the
:math:`K` projections are rounded and digested together (at most :math:`2^K` digests per
comparison). ``asinh`` makes the tolerance absolute for small values and relative for large
ones.

**A numeric answer** is digested by groups of entries (a vector whole, a matrix by columns),
never one entry alone: a digest per entry let a search recover a vector one entry at a time,
each from a few thousand simple closed forms, in seconds.
"""

from __future__ import annotations

import hashlib
import itertools
import zlib
from functools import lru_cache

import numpy as np

from ..tolerance import TOL

__all__ = ["SCRYPT", "stretched", "cell_digest", "matches", "projections", "weights"]

#: scrypt cost parameters: n (CPU/memory cost), r (block size), p (parallelism).
SCRYPT = {"n": 2**10, "r": 8, "p": 1}

_SALT = "rotations-course/exercises/v2"
#: Noise allowed in a rounded value (a value within it of the reference always matches).
EPS = 1.5 * TOL


@lru_cache(maxsize=4096)
def stretched(name, label, payload):
    """Salted scrypt digest (16 hex digits) of ``payload`` for exercise ``name``, ``label``.

    Examples
    --------
    >>> len(stretched("example", "entry0", (3,)))
    16
    """
    salt = f"{_SALT}|{name}|{label}".encode()
    out = hashlib.scrypt(str(payload).encode(), salt=salt, dklen=8, maxmem=2**25, **SCRYPT)
    return out.hex()


def _cells(z, step, offset=0.0):
    return tuple(int(c) for c in np.floor(np.asarray(z, dtype=float) / step + offset))


def cell_digest(name, label, z, step, offset=0.0):
    """Digest of the cells of the values ``z`` (a number or a short sequence)."""
    return stretched(name, label, _cells(np.atleast_1d(z), step, offset))


def candidate_cells(z, step, eps=EPS, offset=0.0):
    r"""Every tuple of cells the values ``z`` may have been rounded to, allowing ``eps``.

    A value :math:`v` is in cell :math:`c = \lfloor v/h + o \rfloor` (``offset`` :math:`o`:
    0.5 puts the multiples of :math:`h` in the middle of their cells); within ``eps`` of the
    edge of its cell it may also be in the neighbouring one.

    Examples
    --------
    >>> list(candidate_cells([0.5, 0.99], 1.0, eps=0.05))
    [(0, 0), (0, 1)]
    """
    z = np.atleast_1d(np.asarray(z, dtype=float))
    options = []
    for v in z:
        c = int(np.floor(v / step + offset))
        opts = [c]
        if v - (c - offset) * step < eps:
            opts.append(c - 1)
        if (c + 1 - offset) * step - v < eps:
            opts.append(c + 1)
        options.append(opts)
    return itertools.product(*options)


def matches(name, label, z, step, stored, eps=EPS, offset=0.0):
    """Does one of the cells of ``z`` (within ``eps``) have the stored digest?"""
    if stored is None:
        return False
    z = np.atleast_1d(np.asarray(z, dtype=float))
    if not np.all(np.isfinite(z)) or np.max(np.abs(z), initial=0.0) > 1e12:
        return False
    return any(
        stretched(name, label, cells) == stored for cells in candidate_cells(z, step, eps, offset)
    )


@lru_cache(maxsize=256)
def weights(name, label, size, k):
    """``k`` seeded random weight rows of length ``size``, each with absolute sum 1."""
    rng = np.random.default_rng(zlib.crc32(f"{name}|{label}|{size}".encode()))
    w = rng.normal(size=(k, size))
    w /= np.sum(np.abs(w), axis=1, keepdims=True)
    w.flags.writeable = False
    return w


def projections(name, label, values, k):
    """The ``k`` projections of asinh of ``values`` (any shape), as an array of k numbers."""
    flat = np.arcsinh(np.ravel(np.asarray(values, dtype=float)))
    return weights(name, label, flat.size, k) @ flat
