r"""Reading an answer record with a whitelist: never ``eval``, never an attribute or import.

A record's answer is sympy's ``srepr`` text, e.g.
``Add(Symbol('theta', real=True), Integer(1))``. It is parsed by :func:`ast.parse` into a
syntax tree, and the tree is walked: only calls of the constructors in :data:`CONSTRUCTORS`,
integer, float-string and name literals, lists and keyword assumptions of a symbol are allowed;
sizes are bounded (:data:`MAX_TEXT`, :data:`MAX_NODES`, :data:`MAX_DEPTH`, integers up to
:data:`MAX_INTEGER`, exponents up to :data:`MAX_EXPONENT`, and the exact numbers a power, sum or
product would build up to :data:`MAX_BITS` bits) *before* any sympy object is built.
Anything else is :class:`Unreadable` with one line that says what.

Examples
--------
>>> parse("Add(Symbol('theta', real=True), Integer(1))")
theta + 1
>>> parse("__import__('os').system('true')")
Traceback (most recent call last):
    ...
instructor.grading.records.Unreadable: record: a call of something other than a sympy constructor
"""

from __future__ import annotations

import ast

import sympy as sp
from sympy.core.numbers import Float, Integer, Rational
from sympy.matrices.expressions import (
    Identity,
    MatAdd,
    MatMul,
    MatPow,
    MatrixSymbol,
    Transpose,
    ZeroMatrix,
)

from course_lib.exercises.compare import ALLOWED_FUNCTIONS

__all__ = ["Unreadable", "parse", "CONSTRUCTORS"]

MAX_TEXT = 200_000
MAX_NODES = 4_000
MAX_DEPTH = 60
MAX_INTEGER = 10**30
MAX_EXPONENT = 64
MAX_NAME = 40
MAX_BITS = 20_000  # of any exact number built, about 6,000 digits

# The elementary functions of the answer language: the checker's own list, read in once.
_FUNCTIONS = {f.__name__: f for f in ALLOWED_FUNCTIONS}
#: The names a record may call, and what they build.
CONSTRUCTORS = {
    "Add": sp.Add,
    "Mul": sp.Mul,
    "Pow": sp.Pow,
    "Symbol": sp.Symbol,
    "Integer": Integer,
    "Rational": Rational,
    "Float": Float,
    "ImmutableDenseMatrix": sp.ImmutableMatrix,
    "MatrixSymbol": MatrixSymbol,
    "Str": sp.core.symbol.Str,
    "Identity": Identity,
    "ZeroMatrix": ZeroMatrix,
    "MatAdd": MatAdd,
    "MatMul": MatMul,
    "MatPow": MatPow,
    "Transpose": Transpose,
    **_FUNCTIONS,
}
_NAMES = {"pi": sp.pi, "E": sp.E, "I": sp.I}
_ASSUMPTIONS = {"real", "positive", "nonnegative", "commutative", "integer"}


class Unreadable(ValueError):
    """A record the grader refuses; the message is one line for the instructor's note."""


def _fail(what):
    raise Unreadable(f"record: {what}")


def _integer(node):
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        return -_integer(node.operand)
    if not (isinstance(node, ast.Constant) and type(node.value) is int):
        _fail("an integer was expected")
    if abs(node.value) > MAX_INTEGER:
        _fail(f"an integer larger than {MAX_INTEGER:.0e}")
    return node.value


def _string(node):
    if not (isinstance(node, ast.Constant) and type(node.value) is str):
        _fail("a string was expected")
    if len(node.value) > MAX_NAME:
        _fail(f"a name or number text longer than {MAX_NAME} characters")
    return node.value


def _float(args, kwargs):
    if len(args) != 1 or set(kwargs) - {"precision"} or kwargs.get("precision", 53) != 53:
        _fail("Float takes one string of a double-precision number")
    text = _string(args[0])
    value = float(text)  # ValueError for anything but a number: caught by the caller
    if not abs(value) < 1e300:
        _fail("a number of 1e300 or more, nan or infinity")
    return Float(text, precision=53)


def _keywords(call):
    out = {}
    for kw in call.keywords:
        if kw.arg is None:
            _fail("** in a call")
        if kw.arg == "precision":
            out[kw.arg] = _integer(kw.value)
            continue
        if kw.arg not in _ASSUMPTIONS:
            _fail(f"the keyword {kw.arg!r}")
        if not (isinstance(kw.value, ast.Constant) and type(kw.value.value) is bool):
            _fail("an assumption that is not True or False")
        out[kw.arg] = kw.value.value
    return out


def _build(node, depth, count):
    count[0] += 1
    if count[0] > MAX_NODES or depth > MAX_DEPTH:
        _fail(f"too large (more than {MAX_NODES} nodes or {MAX_DEPTH} levels)")
    if isinstance(node, ast.Name):
        if node.id not in _NAMES:
            _fail(f"the name {node.id[:MAX_NAME]!r}")
        return _NAMES[node.id]
    if isinstance(node, ast.List):
        return [_build(n, depth + 1, count) for n in node.elts]
    if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Name)):
        _fail("a call of something other than a sympy constructor")
    name = node.func.id
    if name not in CONSTRUCTORS:
        _fail("a call of something other than a sympy constructor")
    kwargs = _keywords(node)
    if name in ("Integer", "Rational"):
        nums = [_integer(a) for a in node.args]
        arity = 1 if name == "Integer" else 2
        if len(nums) != arity or kwargs or (arity == 2 and nums[1] == 0):
            _fail(f"a malformed {name}")
        return CONSTRUCTORS[name](*nums)
    if name == "Float":
        return _float(node.args, kwargs)
    if name in ("Symbol", "Str"):
        if len(node.args) != 1 or (name == "Str" and kwargs):
            _fail(f"a malformed {name}")
        return CONSTRUCTORS[name](_string(node.args[0]), **kwargs)
    if kwargs:
        _fail(f"keywords in a call of {name}")
    args = [_build(a, depth + 1, count) for a in node.args]
    if name in ("Pow", "MatPow"):
        exp = args[1] if len(args) == 2 else None
        if not isinstance(exp, (Integer, Rational)) or abs(exp.p) > MAX_EXPONENT or exp.q > 64:
            _fail(f"{name} needs a rational exponent of at most {MAX_EXPONENT}")
        if name == "Pow" and _bits(args[0]) * abs(exp.p) > MAX_BITS:
            _fail(f"a power of a number of more than {MAX_BITS} bits")
    if name in ("Add", "Mul") and sum(_bits(a) for a in args) > MAX_BITS:
        _fail(f"a sum or product of numbers of more than {MAX_BITS} bits")
    return CONSTRUCTORS[name](*args)


def _bits(obj):
    """The bits of the largest exact number in ``obj`` (before a power or product of it is
    built: sympy evaluates those on numbers, and nested powers grow without bound)."""
    if not isinstance(obj, sp.Basic):
        return 0
    numbers = [obj] if isinstance(obj, Rational) else obj.atoms(Rational)
    return max((max(n.p.bit_length(), n.q.bit_length()) for n in numbers), default=0)


def parse(text):
    """The sympy object of a record's ``srepr`` text, read with the whitelist.

    Raises
    ------
    Unreadable
        For anything but a bounded tree of the whitelisted constructors.
    """
    if type(text) is not str:
        _fail(f"the answer is a {type(text).__name__}, not text")
    if len(text) > MAX_TEXT:
        _fail(f"longer than {MAX_TEXT} characters")
    try:
        tree = ast.parse(text, mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        _fail("not a sympy srepr")
    try:
        return _build(tree.body, 0, [0])
    except Unreadable:
        raise
    except Exception as err:  # noqa: BLE001 - a constructor refused its arguments
        _fail(f"sympy refused it ({type(err).__name__})")
