"""What the chapters' variant draws share (``DRAWS`` of instructor/answers/chNN.py): the pair
check, and the exact constructions that give each key thousands of parameter sets (issue 33)."""

import itertools
from fractions import Fraction
from functools import cache

import numpy as np

__all__ = [
    "apart",
    "signed_permutation",
    "quadruples",
    "unit_axis",
    "quaternion_matrix",
    "integer_quaternion",
    "rational_unit_quaternions",
    "fraction_text",
]


def apart(exercise, values, gap=0.01):
    """Why the answer and the known mistakes of ``exercise`` are unfit: every pair of
    ``values`` (name -> value) that is not at least ``gap`` apart in some entry."""
    names = list(values)
    return [
        f"{exercise}: {a} and {b} are too close"
        for i, a in enumerate(names)
        for b in names[i + 1 :]
        if np.shape(values[a]) == np.shape(values[b])
        and np.abs(np.ravel(values[a]) - np.ravel(values[b])).max() < gap
    ]


def signed_permutation(rng):
    """A rotation whose columns are signed coordinate axes (one of the 24), not the identity."""
    while True:
        R = np.zeros((3, 3), dtype=int)
        R[rng.permutation(3), np.arange(3)] = rng.choice([-1, 1], size=3)
        if round(np.linalg.det(R)) == 1 and not np.array_equal(R, np.eye(3)):
            return R


@cache
def quadruples(largest=21):
    """Pythagorean quadruples ``((a, b, c), n)``: 0 < a <= b <= c, a² + b² + c² = n², n <=
    ``largest``, gcd 1. Each gives a unit vector (a, b, c)/n that a first-year writes exactly,
    along no coordinate axis or plane (48 signed orders each)."""
    out = []
    for a, b, c in itertools.combinations_with_replacement(range(1, largest), 3):
        n2 = a * a + b * b + c * c
        n = round(n2**0.5)
        if n * n == n2 and n <= largest and np.gcd.reduce([a, b, c]) == 1:
            out.append(((a, b, c), n))
    return out


def unit_axis(rng, largest=21):
    """A signed, permuted Pythagorean quadruple: ``(q, n)`` with ``q / n`` a unit vector."""
    table = quadruples(largest)
    q, n = table[rng.integers(len(table))]
    q = np.array(q)[rng.permutation(3)] * rng.choice([-1, 1], size=3)
    return [int(v) for v in q], n


def quaternion_matrix(q):
    """The rotation of the integer quaternion ``q = (w, x, y, z)`` (not unit) as ``(M, n)``:
    the integer matrix M with R = M / n, n = |q|² (Euler-Rodrigues; the Cayley transform of
    the vector (x, y, z)/w when w != 0)."""
    w, x, y, z = (int(v) for v in q)
    M = [
        [w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z],
    ]
    return np.array(M), w * w + x * x + y * y + z * z


def integer_quaternion(rng, largest=3):
    """A random integer quaternion with entries in [-largest, largest], three of them non-zero
    at least (a rotation about an axis along no coordinate axis)."""
    while True:
        q = rng.integers(-largest, largest + 1, size=4)
        if np.count_nonzero(q) >= 3 and np.gcd.reduce(q) == 1:
            return q


@cache
def rational_unit_quaternions(n):
    """Integer quadruples ``q`` with |q|² = n² (so q / n is a unit quaternion with rational
    entries), every sign and order."""
    out = []
    r = range(-n, n + 1)
    for w, x, y in itertools.product(r, r, r):
        rest = n * n - w * w - x * x - y * y
        if rest < 0:
            continue
        z = round(rest**0.5)
        if z * z == rest:
            out.extend({(w, x, y, z), (w, x, y, -z)})
    return sorted(out)


def fraction_text(value):
    """An exact rational as the statement writes it: ``-2/9``, ``0``, ``1``."""
    return str(Fraction(value))
