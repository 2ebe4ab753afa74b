r"""The group axioms (Definitions 3-4) checked on a sample of elements.

A group :math:`(G, \circ)` is a set with a binary operation such that

1. :math:`G` is closed under :math:`\circ`: :math:`g_1 \circ g_2 \in G`;
2. there is an identity :math:`e \in G` with :math:`e \circ g = g \circ e = g`;
3. every :math:`g` has an inverse :math:`g^{-1} \in G` with
   :math:`g \circ g^{-1} = g^{-1} \circ g = e`;
4. :math:`\circ` is associative: :math:`g_1 \circ (g_2 \circ g_3) = (g_1 \circ g_2) \circ g_3`.

:func:`check_group` tests the four axioms, in this order, on a finite sample and lists every
failure. The ready-made samples used by notebook 02 are :func:`real_addition` (a group),
:func:`so3_multiplication` (a group, Proposition 5), and the non-examples
:func:`so3_addition` and :func:`so3_scalar_multiplication`. Each returns a :class:`GroupSample`
that unpacks into :func:`check_group`::

    check_group(**so3_addition())
"""

import math
import numbers
from dataclasses import dataclass, field, fields
from typing import NamedTuple

import numpy as np

from . import so3
from ._arrays import as_count, fmt_vector
from ._verdict import Verdict
from .tolerance import TOL, check_tol, tol_label

__all__ = [
    "Failure",
    "GroupCheck",
    "GroupSample",
    "check_group",
    "real_addition",
    "so3_multiplication",
    "so3_addition",
    "so3_scalar_multiplication",
]

AXIOMS = ("closure", "identity", "inverse", "associativity")


class Failure(NamedTuple):
    """One failed axiom instance: ``(axiom, elements, message)``.

    ``axiom`` is one of ``"closure"``, ``"identity"``, ``"inverse"``, ``"associativity"``;
    ``elements`` is the tuple of offending elements; ``message`` says what went wrong.
    """

    axiom: str
    elements: tuple
    message: str


@dataclass(frozen=True, eq=False, repr=False)
class GroupCheck(Verdict):
    """The result of :func:`check_group`, a :class:`~course_lib._verdict.Verdict`.

    Attributes
    ----------
    ok : bool
        True when no axiom failed on the sample.
    message : str
        The summary (``str`` puts ✓ or ✗ before it), then one line per failed axiom with its
        first failure.
    failures : list of Failure
        Every failed instance, axioms in the notes' order.
    name : str
        The name of the structure, e.g. ``"(SO(3), +)"``.
    counts : dict
        How many instances of each axiom were checked.
    """

    failures: list = field(default_factory=list)
    name: str = "(G, ∘)"
    counts: dict = field(default_factory=dict)

    # The failed axioms are a list right under the verdict line.
    _details_separator = "\n"

    def __repr__(self):
        failed = sorted({f.axiom for f in self.failures}, key=AXIOMS.index)
        return (
            f"GroupCheck(name={self.name!r}, ok={self.ok}, failed_axioms={failed}, "
            f"n_failures={len(self.failures)})"
        )

    def _headline_markdown(self):
        return f"**{self.mark} {self.message.partition(chr(10))[0]}**"

    def _details_markdown(self):
        rest = self.message.partition("\n")[2]
        return "\n".join(f"- {line.lstrip('- ')}" for line in rest.splitlines() if line.strip())


def _default_equal(tol):
    """‖a − b‖ ≤ tol, scaled by the largest entry beyond 1 (rounding grows with the size)."""

    def equal(a, b):
        try:
            a = np.asarray(a, dtype=np.float64)
            b = np.asarray(b, dtype=np.float64)
        except (TypeError, ValueError, OverflowError):
            return bool(np.array_equal(np.asarray(a, dtype=object), np.asarray(b, dtype=object)))
        if a.shape != b.shape:
            return False
        with np.errstate(over="ignore", invalid="ignore"):
            scale = max(
                1.0, float(np.max(np.abs(a), initial=0.0)), float(np.max(np.abs(b), initial=0.0))
            )
            return bool(np.linalg.norm((a - b) / scale) <= tol)

    return equal


def _fmt(x):
    """Short text for an element: rounded numbers, or repr for anything else."""
    if x is None or isinstance(x, (str, bytes)):
        return repr(x)
    try:
        arr = np.asarray(x, dtype=np.float64)
    except (TypeError, ValueError, OverflowError):
        return repr(x)
    text = fmt_vector(arr)
    return text.replace("\n", "") if arr.ndim >= 2 else text


def _fmt_member(x):
    """Like _fmt, adding the determinant of a square matrix (what SO(3) membership hinges on)."""
    text = _fmt(x)
    try:
        arr = np.asarray(x, dtype=np.float64)
    except (TypeError, ValueError, OverflowError):
        return text
    if arr.ndim == 2 and arr.shape[0] == arr.shape[1] and np.all(np.isfinite(arr)):
        with np.errstate(all="ignore"):
            det = float(np.linalg.det(arr))
        text += f" (det = {det:.6g})" if math.isfinite(det) else ""
    return text


def _member_of_sample(elements, equal):
    def member(x):
        return any(equal(x, y) for y in elements)

    return member


def _truth(value, what):
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise TypeError(f"{what} must return a bool, got {type(value).__name__} {value!r}")


class _Structure(NamedTuple):
    """The candidate group, with every user callable wrapped to give clear errors."""

    elements: list
    op: object
    identity: object
    inverse: object
    equal: object
    member: object


def _returning(fn, fn_name):
    """fn, refusing None as a result (a missing ``return`` would otherwise read as "nan")."""

    def call(*args):
        out = fn(*args)
        if out is None:
            shown = ", ".join(_fmt(a) for a in args)
            raise TypeError(
                f"{fn_name}({shown}) returned None; {fn_name} must return an element of the set "
                f"(is a return statement missing?)"
            )
        return out

    return call


def _checked(fn, fn_name):
    """fn as a bool-valued test: a TypeError if it returns anything but a bool."""

    def call(*args):
        return _truth(fn(*args), fn_name)

    return call


def _structure(elements, op, identity, inverse, equal, member, tol):
    """Validate check_group's arguments and wrap its callables."""
    for fn, fn_name in ((op, "op"), (inverse, "inverse")):
        if not callable(fn):
            raise TypeError(f"{fn_name} must be callable, got {type(fn).__name__} {fn!r}")
    for fn, fn_name in ((equal, "equal"), (member, "member")):
        if fn is not None and not callable(fn):
            raise TypeError(f"{fn_name} must be callable or None, got {type(fn).__name__} {fn!r}")
    elements = list(elements)
    if not elements:
        raise ValueError("elements must hold at least one element of the set")
    if identity is None:
        raise TypeError("identity must be an element of the set, got None")
    equal = _default_equal(tol) if equal is None else _checked(equal, "equal")
    member = _member_of_sample(elements, equal) if member is None else _checked(member, "member")
    for i, x in enumerate(elements):
        if not member(x):
            raise ValueError(
                f"elements[{i}] = {_fmt_member(x)} is not a member of the set (member(x) is "
                f"False); the sample must be drawn from the set being checked"
            )
    op, inverse = _returning(op, "op"), _returning(inverse, "inverse")
    return _Structure(elements, op, identity, inverse, equal, member)


def _sample_tuples(n, k, max_samples, rng):
    """All k-tuples of indices of n elements, or a seeded sample of max_samples of them."""
    total = n**k
    if total <= max_samples:
        return [tuple(int(i) for i in np.unravel_index(t, (n,) * k)) for t in range(total)]
    return [tuple(int(i) for i in row) for row in rng.integers(0, n, size=(max_samples, k))]


def check_group(
    elements,
    op,
    identity,
    inverse,
    equal=None,
    tol=TOL,
    member=None,
    name="(G, ∘)",
    max_samples=1000,
    seed=0,
):
    r"""Check the four group axioms of Definition 4 on a sample of elements.

    With :math:`S \subset G` the sample and :math:`\mathrm{member}` the test of :math:`x \in G`:

    1. closure: :math:`\mathrm{member}(g_1 \circ g_2)` for pairs :math:`g_1, g_2 \in S`;
    2. identity: :math:`\mathrm{member}(e)` and :math:`e \circ g = g \circ e = g`
       for :math:`g \in S`;
    3. inverse: :math:`\mathrm{member}(g^{-1})` and :math:`g \circ g^{-1} = g^{-1} \circ g = e`;
    4. associativity: :math:`g_1 \circ (g_2 \circ g_3) = (g_1 \circ g_2) \circ g_3` on triples.

    All pairs and triples are used when there are at most ``max_samples`` of them, otherwise a
    seeded random sample of that many. Equality defaults to the tolerance policy,
    :math:`\|a - b\| \le \mathrm{tol} \cdot \max(1, |a|_\infty, |b|_\infty)` (Frobenius for
    matrices, Euclidean for vectors; the scale only matters for entries beyond 1, where
    rounding grows with the size).
    Uniqueness of the inverse (in the notes' axiom 3) is not tested separately: it follows
    from axioms 2-4. A sample can refute the axioms, never prove them (the proofs are the
    notes' example for :math:`(\mathbb{R}, +)` and Proposition 5 for SO(3)).

    Parameters
    ----------
    elements : sequence or ndarray
        The sample of the set; an array is split along its first axis. Each must be a member.
    op : callable
        The binary operation, ``op(a, b)`` = :math:`a \circ b`.
    identity : object
        The candidate identity element :math:`e`.
    inverse : callable
        ``inverse(g)`` = the candidate :math:`g^{-1}`.
    equal : callable, optional
        ``equal(a, b) -> bool``; default: ``‖a − b‖ ≤ tol`` (times the largest entry if > 1).
    tol : float, optional
        Tolerance of the default ``equal``, default :data:`~course_lib.tolerance.TOL`.
    member : callable, optional
        ``member(x) -> bool``, is x in G (e.g. :func:`course_lib.so3.is_rotation`). Default:
        "equal to one of ``elements``", right for a finite set given in full.
    name : str, optional
        How the structure is called in the messages.
    max_samples : int, optional
        Most pairs (closure) and triples (associativity) checked (default 1000).
    seed : int, optional
        Seed for sampling pairs and triples when there are too many.

    Returns
    -------
    GroupCheck
        ``.ok``, ``.failures`` (list of ``(axiom, elements, message)``), ``.message``,
        ``.counts``; displays as a ✓/✗ summary in a notebook.

    Raises
    ------
    TypeError
        If ``op``, ``inverse``, ``equal`` or ``member`` is not callable, or ``member``/``equal``
        does not return a bool.
    ValueError
        If ``elements`` is empty or holds a non-member, or ``tol`` < 0, or ``max_samples`` < 1.

    Examples
    --------
    >>> check_group([1, -1], op=lambda a, b: a * b, identity=1, inverse=lambda a: a).ok
    True
    >>> result = check_group(**so3_addition(n=2))
    >>> [axiom for axiom, _, _ in result.failures][:1]
    ['closure']
    >>> print(result.failures[0].message)    # the notes' I + I = 2I
    g1 ∘ g2 = [[2., 0., 0.], [0., 2., 0.], [0., 0., 2.]] (det = 8) is not in the set
    """
    tol = check_tol(tol)
    max_samples = as_count(max_samples, "max_samples", minimum=1)
    G = _structure(elements, op, identity, inverse, equal, member, tol)
    rng = np.random.default_rng(seed)
    pairs = _sample_tuples(len(G.elements), 2, max_samples, rng)
    triples = _sample_tuples(len(G.elements), 3, max_samples, rng)
    failures = _closure(G, pairs) + _identity(G) + _inverse(G) + _associativity(G, triples)
    counts = {
        "closure": len(pairs),
        "identity": 1 + len(G.elements),
        "inverse": len(G.elements),
        "associativity": len(triples),
    }
    return _group_verdict(name, len(G.elements), failures, counts, tol)


def _closure(G, pairs):
    """Axiom 1: g1 ∘ g2 is a member, for the sampled pairs."""
    failures = []
    for i, j in pairs:
        a, b = G.elements[i], G.elements[j]
        c = G.op(a, b)
        if not G.member(c):
            failures.append(
                Failure("closure", (a, b), f"g1 ∘ g2 = {_fmt_member(c)} is not in the set")
            )
    return failures


def _identity(G):
    """Axiom 2: e is a member and e ∘ g = g ∘ e = g."""
    e = G.identity
    failures = []
    if not G.member(e):
        failures.append(
            Failure("identity", (e,), f"the identity e = {_fmt_member(e)} is not in the set")
        )
    for g in G.elements:
        sides = (("e ∘ g", G.op(e, g)), ("g ∘ e", G.op(g, e)))
        bad = [(side, v) for side, v in sides if not G.equal(v, g)]
        if bad:
            shown = ", ".join(f"{side} = {_fmt(v)}" for side, v in bad)
            which = " and ".join(side for side, _ in bad)
            failures.append(Failure("identity", (g,), f"{which} ≠ g for g = {_fmt(g)}: {shown}"))
    return failures


def _inverse(G):
    """Axiom 3: g⁻¹ is a member and g ∘ g⁻¹ = g⁻¹ ∘ g = e."""
    failures = []
    for g in G.elements:
        gi = G.inverse(g)
        problems = [] if G.member(gi) else [f"g⁻¹ = {_fmt_member(gi)} is not in the set"]
        left, right = G.op(g, gi), G.op(gi, g)
        if not G.equal(left, G.identity):
            problems.append(f"g ∘ g⁻¹ = {_fmt(left)} ≠ e")
        if not G.equal(right, G.identity):
            problems.append(f"g⁻¹ ∘ g = {_fmt(right)} ≠ e")
        if problems:
            failures.append(
                Failure("inverse", (g, gi), f"for g = {_fmt(g)}: " + "; ".join(problems))
            )
    return failures


def _associativity(G, triples):
    """Axiom 4: g1 ∘ (g2 ∘ g3) = (g1 ∘ g2) ∘ g3, for the sampled triples."""
    failures = []
    for i, j, k in triples:
        a, b, c = G.elements[i], G.elements[j], G.elements[k]
        left, right = G.op(a, G.op(b, c)), G.op(G.op(a, b), c)
        if not G.equal(left, right):
            message = f"g1 ∘ (g2 ∘ g3) = {_fmt(left)} ≠ (g1 ∘ g2) ∘ g3 = {_fmt(right)}"
            failures.append(Failure("associativity", (a, b, c), message))
    return failures


def _group_verdict(name, n, failures, counts, tol):
    """The GroupCheck: ✓ with what was checked, or ✗ with the first failure of each axiom."""
    checked = (
        f"{n} sample element{'s' if n != 1 else ''}, {counts['closure']} pairs, "
        f"{counts['associativity']} triples"
    )
    if not failures:
        message = (
            f"{name} passes all four group axioms on {checked} (equality within "
            f"{tol_label(tol)}); a sample can refute the axioms, never prove them."
        )
        return GroupCheck(ok=True, message=message, failures=[], name=name, counts=counts)
    failed = [a for a in AXIOMS if any(f.axiom == a for f in failures)]
    which = ", ".join(f"{AXIOMS.index(a) + 1} ({a})" for a in failed)
    lines = [f"{name} is not a group: fails {which} on {checked}."]
    for axiom in failed:
        mine = [f for f in failures if f.axiom == axiom]
        lines.append(
            f"- axiom {AXIOMS.index(axiom) + 1} ({axiom}), {len(mine)} "
            f"failure{'s' if len(mine) != 1 else ''}, e.g. {mine[0].message}"
        )
    return GroupCheck(
        ok=False, message="\n".join(lines), failures=failures, name=name, counts=counts
    )


# --------------------------------------------------------------------------------------------
# ready-made samples for notebook 02
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class GroupSample:
    """The arguments of :func:`check_group` for one example; unpack it with ``**``.

    ``check_group(**sample)`` works because the sample behaves as a mapping of its fields.
    """

    name: str
    elements: list = field(repr=False)
    op: object = field(repr=False)
    identity: object = field(repr=False)
    inverse: object = field(repr=False)
    member: object = field(repr=False)
    note: str = ""

    def keys(self):
        return [f.name for f in fields(self) if f.name != "note"]

    def __getitem__(self, key):
        if key not in self.keys():
            raise KeyError(key)
        return getattr(self, key)


def _is_real_number(x):
    return isinstance(x, numbers.Real) and not isinstance(x, (bool, np.bool_)) and math.isfinite(x)


def real_addition(n=6, seed=0):
    r"""(ℝ, +): a group (the notes' worked example).

    .. math:: a \circ b = a + b, \qquad e = 0, \qquad a^{-1} = -a

    Parameters
    ----------
    n : int, optional
        Number of sample reals (seeded; 0 is always included).
    seed : int, optional

    Returns
    -------
    GroupSample

    Examples
    --------
    >>> check_group(**real_addition()).ok
    True
    """
    n = as_count(n, "n", minimum=1)
    rng = np.random.default_rng(seed)
    elements = [0.0] + [float(x) for x in np.round(rng.uniform(-10, 10, size=n - 1), 3)]
    return GroupSample(
        name="(ℝ, +)",
        elements=elements,
        op=lambda a, b: a + b,
        identity=0.0,
        inverse=lambda a: -a,
        member=_is_real_number,
        note="member: is a finite real number",
    )


def so3_multiplication(n=6, seed=0):
    r"""(SO(3), ·): a group under matrix multiplication (Proposition 5).

    .. math:: R_1 \circ R_2 = R_1 R_2, \qquad e = I, \qquad R^{-1} = R^\mathsf{T}

    Parameters
    ----------
    n : int, optional
        Number of sample rotations (the identity plus ``n − 1`` Haar-random ones).
    seed : int, optional

    Returns
    -------
    GroupSample

    Examples
    --------
    >>> check_group(**so3_multiplication()).ok
    True
    """
    n = as_count(n, "n", minimum=1)
    elements = [np.eye(3)] + list(so3.random_rotations(n - 1, seed=seed))
    return GroupSample(
        name="(SO(3), ·)",
        elements=elements,
        op=np.matmul,
        identity=np.eye(3),
        inverse=np.transpose,
        member=so3.is_rotation,
        note="member: so3.is_rotation",
    )


def so3_addition(n=6, seed=0):
    r"""(SO(3), +): NOT a group, it is not closed under addition.

    .. math:: R_1 \circ R_2 = R_1 + R_2, \qquad e = 0, \qquad R^{-1} = -R

    The notes' counterexample is :math:`I + I = 2I`. Its determinant is
    :math:`\det(2I) = 2^3 = 8` for a 3x3 matrix; the notes write :math:`\det(R_1 + R_2) = 2`,
    a slip (the conclusion, :math:`2I \notin SO(3)`, stands). The zero matrix and :math:`-R`
    (det −1) are not rotations either, so axioms 2 and 3 fail too.

    Parameters
    ----------
    n : int, optional
        Number of sample rotations (the identity first, so the notes' example shows up).
    seed : int, optional

    Returns
    -------
    GroupSample

    Examples
    --------
    >>> sorted({f.axiom for f in check_group(**so3_addition()).failures})
    ['closure', 'identity', 'inverse']
    >>> round(float(np.linalg.det(np.eye(3) + np.eye(3))), 9)
    8.0
    """
    n = as_count(n, "n", minimum=1)
    elements = [np.eye(3)] + list(so3.random_rotations(n - 1, seed=seed))
    return GroupSample(
        name="(SO(3), +)",
        elements=elements,
        op=np.add,
        identity=np.zeros((3, 3)),
        inverse=np.negative,
        member=so3.is_rotation,
        note="I + I = 2I has det(2I) = 8 (the notes say 2: a slip), so 2I is not in SO(3)",
    )


def so3_scalar_multiplication(c=2.0, n=6, seed=0):
    r"""SO(3) with a scalar multiplication by ``c``: NOT closed (the notes' second non-example).

    .. math:: R_1 \circ R_2 = c\,R_1 R_2, \qquad e = \tfrac{1}{c} I, \qquad
              R^{-1} = \tfrac{1}{c^2} R^\mathsf{T}

    Scalar multiplication takes a number and a matrix, so on its own it is not a binary
    operation on SO(3); here it follows the matrix product, which gives back (SO(3), ·) for
    :math:`c = 1`. The equations of axioms 2-4 all hold (with the :math:`e` and inverse above),
    so every failure :func:`check_group` reports is a failure of *membership*: scaling leaves
    SO(3), because :math:`\det(cR) = c^3 \det R`. With the notes' :math:`c = 2` and
    :math:`R_1 = R_2 = I`: :math:`\det(2I) = 2^3 = 8 \ne 1` (the notes write
    :math:`\det(2I) = 2`, a slip; the conclusion stands).

    Parameters
    ----------
    c : float, optional
        The nonzero scalar (default 2, as in the notes).
    n : int, optional
        Number of sample rotations (the identity first).
    seed : int, optional

    Returns
    -------
    GroupSample

    Raises
    ------
    TypeError
        If ``c`` is not a real number.
    ValueError
        If ``c`` is zero or not finite.

    Examples
    --------
    >>> result = check_group(**so3_scalar_multiplication())
    >>> result.failures[0].axiom, sorted({f.axiom for f in result.failures})
    ('closure', ['closure', 'identity', 'inverse'])
    >>> check_group(**so3_scalar_multiplication(c=1)).ok
    True
    """
    if isinstance(c, (bool, np.bool_)) or not isinstance(c, numbers.Real):
        raise TypeError(f"c must be a real number, got {type(c).__name__} {c!r}")
    c = float(c)
    if not math.isfinite(c) or c == 0.0:
        raise ValueError(f"c must be a finite nonzero number, got {c!r}")
    n = as_count(n, "n", minimum=1)
    elements = [np.eye(3)] + list(so3.random_rotations(n - 1, seed=seed))
    return GroupSample(
        name=f"(SO(3), R1 ∘ R2 = c R1 R2 with c = {c:g})",
        elements=elements,
        op=lambda a, b: c * np.matmul(a, b),
        identity=np.eye(3) / c,
        inverse=lambda a: np.transpose(a) / c**2,
        member=so3.is_rotation,
        note=f"det(cR) = c³ det R = {c**3:g} for c = {c:g}",
    )
