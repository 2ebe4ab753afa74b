r"""Reading a student's answer: plain sympy, numpy and Python objects only, bounded in size.

An answer is walked node by node before anything is computed with it. Every node must be of an
allowed type *exactly* (a subclass, e.g. a sympy class with its own ``__add__``, is refused, and
none of its methods is ever called); functions that hide a piecewise definition or an
unevaluated operation (``floor``, ``Heaviside``, ``Mod``, ``Piecewise``, ``Integral``, ``Sum``,
``Derivative``, ``Abs`` ...) are "not allowed here"; an answer with more than
:data:`MAX_NODES` nodes, a degree above :data:`MAX_DEGREE` or a matrix power above
:data:`MAX_MATRIX_DEGREE` is "too complex to check". These bounds are what keeps every check
well under a second: nothing is expanded or simplified before they hold.
"""

from __future__ import annotations

import sys
from decimal import Decimal
from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp
from sympy.core.function import UndefinedFunction
from sympy.matrices.expressions import (
    Identity,
    MatAdd,
    MatMul,
    MatPow,
    MatrixExpr,
    MatrixSymbol,
    Transpose,
    ZeroMatrix,
)
from sympy.matrices.expressions.matexpr import MatrixElement

__all__ = ["Rejected", "read_choice", "read_answer", "degree_bound"]

MAX_NODES = 800
MAX_DEGREE = 24
MAX_MATRIX_DEGREE = 6
MAX_INTEGER = 10**30
MAX_POWER = 400
MAX_DEPTH = 40
MAX_ENTRIES = 81
# Numbers at least this large are refused: no answer is near it, and digests of them overflow.
MAX_MAGNITUDE = 1e300
TOO_LARGE = "a number of 1e300 or more, larger than any answer here"

_FUNCTIONS = (
    sp.sin,
    sp.cos,
    sp.tan,
    sp.exp,
    sp.log,
    sp.asin,
    sp.acos,
    sp.atan,
    sp.atan2,
    sp.sinh,
    sp.cosh,
    sp.tanh,
)
_SCALAR_TYPES = {sp.Add, sp.Mul, sp.Pow, sp.Symbol, sp.Integer, sp.Rational, sp.Float, *_FUNCTIONS}
_NUMBER_SINGLETONS = {
    type(n)
    for n in (
        sp.S.Zero,
        sp.S.One,
        sp.S.NegativeOne,
        sp.S.Half,
        sp.S.Pi,
        sp.S.Exp1,
        sp.S.ImaginaryUnit,
    )
}
_BAD_NUMBERS = {
    type(n) for n in (sp.S.NaN, sp.S.Infinity, sp.S.NegativeInfinity, sp.S.ComplexInfinity)
}
_MATRIX_TYPES = {MatAdd, MatMul, MatPow, Transpose, Identity, ZeroMatrix, MatrixSymbol}
_EXPLICIT = (sp.ImmutableDenseMatrix, sp.MutableDenseMatrix)


# Numbers of the standard library and of mpmath (sympy's own arithmetic), read as numbers.
_FLOATS = (float, Decimal, mpmath.mpf, type(mpmath.pi))  # mpmath.pi: a class of its own
_COMPLEX = (complex, mpmath.mpc)


class Rejected(Exception):
    """An answer the checker refuses; ``str`` is the message, ``status`` its kind."""

    def __init__(self, message, status="malformed"):
        super().__init__(message)
        self.status = status


def _too_complex(what):
    return Rejected(f"too complex to check: simplify it first ({what}).", "too complex")


_HEAPTYPE = 1 << 9  # Py_TPFLAGS_HEAPTYPE: set on every class made by a class statement
_LIBRARIES = {"sympy", "numpy", "builtins", "mpmath", "fractions", "decimal"}


def _is(kind, classes):
    """Is ``kind`` (a type) one of ``classes`` or a subclass? Uses the MRO of the type only."""
    return issubclass(kind, classes)


def _type_name(kind):
    return type.__getattribute__(kind, "__name__")


def _genuine(kind):
    """Is ``kind`` a class of sympy, numpy or Python itself (not a student's subclass, whatever
    its ``__module__`` says)? Looked up in the module it names, compared by identity."""
    if not type.__getattribute__(kind, "__flags__") & _HEAPTYPE:
        return True  # a static type, written in C: no class statement makes one
    name = str(type.__getattribute__(kind, "__module__"))
    if name.split(".")[0] not in _LIBRARIES:
        return False
    module = sys.modules.get(name)
    return module is not None and getattr(module, _type_name(kind), None) is kind


def _not_allowed(node):
    kind = type(node)
    name = _type_name(kind)
    if type(kind) is UndefinedFunction:
        return Rejected(
            f"not allowed here: the undefined function {name} (give an explicit expression).",
            "not allowed",
        )
    if not _genuine(kind) or not _is(kind, sp.Basic):
        return Rejected(
            f"not allowed here: your answer contains an object of type {name} "
            "(a class of your own); build it from plain sympy objects.",
            "not allowed",
        )
    if _is(kind, sp.Inverse):
        why = "the exercise asks for the answer without an inverse"
    elif _is(kind, (sp.Integral, sp.Sum, sp.Product, sp.Derivative)):
        why = "evaluate it first (.doit()) and simplify the result"
    elif _is(kind, sp.Order):
        why = "a series keeps its O(...) term: drop it with .removeO()"
    elif _is(kind, MatrixElement):
        return Rejected(
            f"not allowed here: {node}, an entry of a matrix symbol or matrix expression "
            "(from indexing it, or from sp.Matrix(...) of a matrix expression). Give the "
            "matrix expression itself, with numbers or the exercise's scalar symbols as "
            "coefficients; an inner product such as uᵀu is a number you can work out "
            "(for a unit vector, uᵀu = 1).",
            "not allowed",
        )
    else:
        why = "give an expression built from +, −, ·, powers and elementary functions"
    return Rejected(f"not allowed here: {name} ({why}).", "not allowed")


def _check_node(node, symbols, numeric):
    """Types are looked at first and exactly: no method of a foreign class is ever called."""
    kind = type(node)
    if kind in _BAD_NUMBERS:
        raise Rejected("your answer contains nan or infinity.")
    if kind in _NUMBER_SINGLETONS:
        return
    if kind in _SCALAR_TYPES or kind in _MATRIX_TYPES or kind in _EXPLICIT:
        if kind is sp.Symbol or kind is MatrixSymbol:
            if symbols is not None:
                _check_symbol(node, symbols, numeric)
        elif kind is sp.Integer or kind is sp.Rational:
            if max(abs(node.p), node.q) > MAX_INTEGER:
                raise _too_complex(f"a number with more than {len(str(MAX_INTEGER))} digits")
        elif kind is sp.Float and not abs(float(node)) < MAX_MAGNITUDE:
            raise _too_complex(TOO_LARGE)
        elif kind is sp.Pow or kind is MatPow:
            _check_power(node.args[1])
        return
    if (numeric or numeric is None) and kind is sp.Abs:
        return
    raise _not_allowed(node)


def _check_symbol(s, symbols, numeric):
    if numeric:
        raise Rejected(f"a number is expected here, but your answer contains the symbol {s}.")
    if s in symbols:
        return
    same_name = [k for k in symbols if getattr(k, "name", None) == s.name]
    if same_name:
        raise Rejected(
            f"the symbol {s} in your answer is not the one of the course (made with "
            "other assumptions, e.g. without real=True); import it from "
            "course_lib.exercises."
        )
    names = ", ".join(sorted(str(k) for k in symbols)) or "none"
    raise Rejected(
        f"your answer contains the symbol {s}, which does not belong to this "
        f"exercise (its symbols: {names})."
    )


def _check_power(exponent):
    """A power is bounded before anything evaluates it (2**10**29 would never finish)."""
    kind = type(exponent)
    if kind is sp.Integer or kind is sp.Rational:
        if abs(exponent.p) > MAX_POWER * exponent.q:
            raise _too_complex(f"a power above {MAX_POWER}")


def _walk(expr, symbols, numeric):
    """Check every node of a sympy object, its type first and by identity, its depth and the
    number of nodes; return the number of nodes. No method of a node is called before its type
    is known to be one of sympy's own allowed classes."""
    count = 0
    stack = [(expr, 0)]
    while stack:
        node, depth = stack.pop()
        count += 1
        if count > MAX_NODES:
            raise _too_complex(f"more than {MAX_NODES} terms and factors")
        if depth > MAX_DEPTH:
            raise _too_complex(f"nested more than {MAX_DEPTH} levels deep")
        _check_node(node, symbols, numeric)
        if type(node) in _EXPLICIT:
            if node.rows * node.cols > MAX_ENTRIES:
                raise Rejected(f"wrong shape: your matrix is {node.rows}x{node.cols}.")
            stack.extend((e, depth + 1) for e in node)
        elif type(node) is not MatrixSymbol:
            stack.extend((a, depth + 1) for a in node.args)
    return count


def degree_bound(e, memo=None):
    """An upper bound of the polynomial degree of ``e`` (arguments of functions count apart).

    Examples
    --------
    >>> from course_lib.symbolic import x
    >>> degree_bound((x[0] + x[1]) ** 3 * x[2])
    4
    """
    memo = {} if memo is None else memo
    if e in memo:
        return memo[e]
    if e.is_Symbol:
        out = 1
    elif e.is_Number or not e.args:
        out = 0
    elif e.is_Add:
        out = max(degree_bound(a, memo) for a in e.args)
    elif e.is_Mul:
        out = sum(degree_bound(a, memo) for a in e.args)
    elif e.is_Pow:
        base, ex = e.args
        if ex.is_Number:
            out = int(np.ceil(abs(float(ex)) * degree_bound(base, memo)))
        else:
            out = degree_bound(base, memo) + degree_bound(ex, memo) + 1
    else:  # an elementary function: a new atom
        inner = max(degree_bound(a, memo) for a in e.args)
        if inner > MAX_DEGREE:
            raise _too_complex(f"degree above {MAX_DEGREE} inside {type(e).__name__}")
        out = 1 if inner else 0
    if out > MAX_DEGREE:
        raise _too_complex(f"degree above {MAX_DEGREE}")
    memo[e] = out
    return out


def matrix_degree(e):
    """Degree of a matrix expression in its matrix symbols (scalar factors count 0)."""
    kind = type(e)
    if kind is MatrixSymbol:
        out = 1
    elif kind in (Identity, ZeroMatrix) or kind in _EXPLICIT or not isinstance(e, MatrixExpr):
        out = 0
    elif kind is MatAdd:
        out = max(matrix_degree(a) for a in e.args)
    elif kind is MatMul:
        out = sum(matrix_degree(a) for a in e.args)
    elif kind is MatPow:
        base, ex = e.args
        if not (ex.is_Integer and ex >= 0):
            raise Rejected("a matrix power must have a whole exponent ≥ 0 here.", "not allowed")
        out = int(ex) * matrix_degree(base)
    else:  # Transpose
        out = matrix_degree(e.args[0])
    if out > MAX_MATRIX_DEGREE:
        raise _too_complex(f"matrix power above {MAX_MATRIX_DEGREE}")
    return out


#: numpy's own scalar types, compared by identity: a subclass (even one claiming
#: ``__module__ = "numpy"``) is a class of the student's own and none of its methods is called.
_NUMPY_INTS = {
    np.int8,
    np.int16,
    np.int32,
    np.int64,
    np.uint8,
    np.uint16,
    np.uint32,
    np.uint64,
}
_NUMPY_FLOATS = {np.float16, np.float32, np.float64, np.longdouble}
_NUMPY_COMPLEX = {np.complex64, np.complex128, np.clongdouble}


def _decimal(v):
    """A Decimal as an exact sympy number, its size checked before anything is computed."""
    if not v.is_finite():
        raise Rejected("your answer contains nan or infinity.")
    if v.is_zero():
        return sp.Integer(0)
    if v.adjusted() >= 300:  # the exponent of the leading digit: no digit string is built
        raise _too_complex(TOO_LARGE)
    if v.adjusted() < -300 or len(v.as_tuple().digits) > 40:
        return sp.Float(float(v))
    return sp.Rational(*v.as_integer_ratio())


def _scalar(v):
    kind = type(v)
    if kind in _EXPLICIT and v.shape == (1, 1):  # x.T * y: a 1x1 Matrix stands for the number
        return _scalar(v[0, 0])
    if kind is bool or kind is np.bool_:
        raise Rejected("an entry of your answer is a truth value (True/False), not a number.")
    if kind is int or kind in _NUMPY_INTS:
        if kind is int and v.bit_length() > 1000:  # before int(), str() or any arithmetic
            raise _too_complex(TOO_LARGE)
        return sp.Integer(int(v))
    if kind is Fraction:
        if max(v.numerator.bit_length(), v.denominator.bit_length()) > 1000:
            raise _too_complex(TOO_LARGE)
        return sp.Rational(v.numerator, v.denominator)
    if kind is Decimal:
        return _decimal(v)
    if kind in _FLOATS or kind in _NUMPY_FLOATS:
        if not np.isfinite(float(v)):
            raise Rejected("your answer contains nan or infinity.")
        if not abs(float(v)) < MAX_MAGNITUDE:
            raise _too_complex(TOO_LARGE)
        return sp.Float(float(v))
    if kind in _COMPLEX or kind in _NUMPY_COMPLEX:
        if v.imag != 0:
            raise Rejected("your answer is complex; a real answer is expected.")
        return _scalar(float(v.real))
    if kind is dict:
        raise Rejected(
            "your answer holds a dict (from sp.solve(..., dict=True)?): give the values "
            "themselves, e.g. [sol[a], sol[b]], in the order the exercise asks for."
        )
    if kind is str:
        raise Rejected(
            "your answer is a string (text), not a string of numbers or "
            "expressions: give sympy expressions or numbers, not a string."
        )
    if _is(kind, (sp.Basic, sp.MatrixBase)) or not _genuine(kind):
        return _sympy_entry(v, kind)
    raise Rejected(
        f"could not read an entry of type {_type_name(kind)} as a number or an expression."
    )


def _sympy_entry(v, kind):
    """An entry that is a sympy object: screened by type before anything else."""
    if not _genuine(kind):
        raise Rejected(
            f"not allowed here: an entry of type {_type_name(kind)} (a class of your "
            "own); give plain numbers or sympy expressions.",
            "not allowed",
        )
    if _is(kind, (sp.MatrixBase, MatrixExpr)):
        raise Rejected(
            f"an entry of your answer is itself a {v.shape[0]}x{v.shape[1]} matrix "
            f"({_type_name(kind)}): give the matrix itself, not a list that holds it."
        )
    if not _is(kind, sp.Expr):
        raise Rejected(
            f"your answer is a {_type_name(kind)} (an equation or a truth "
            "value?), not an expression; for an Eq from dsolve take its .rhs."
        )
    _walk(v, None, None)  # types, depth and size only; symbols are checked later
    return v


_ARRAYS = (
    sp.ImmutableDenseNDimArray,
    sp.MutableDenseNDimArray,
    sp.ImmutableSparseNDimArray,
    sp.MutableSparseNDimArray,
)


def _plain(answer):
    """sympy's own containers (a Tuple from nonlinsolve, an N-dim Array, numpy's matrix) as
    the plain list, tuple or array they stand for; anything else unchanged."""
    kind = type(answer)
    if kind is sp.Tuple:
        return tuple(answer)
    if kind in _ARRAYS:
        return answer.tolist()
    if kind is np.matrix:
        return np.asarray(answer)
    return answer


def _rows(answer):
    """Nested lists / tuples / arrays as a list of rows of sympy scalars."""
    answer = _plain(answer)
    kind = type(answer)
    if kind is np.ndarray:
        if answer.dtype.kind == "b":
            raise Rejected("your array holds truth values (True/False), not numbers.")
        if answer.dtype.kind not in "iufcO":
            raise Rejected(f"could not read an array of dtype {answer.dtype} as numbers.")
        if answer.ndim > 2 or answer.size > MAX_ENTRIES:
            raise Rejected(f"wrong shape: your array has shape {answer.shape}.")
        answer = answer.tolist()
        kind = type(answer)
    if kind not in (list, tuple):
        return [[_scalar(answer)]], "a scalar"
    if len(answer) > MAX_ENTRIES:
        raise Rejected(f"wrong shape: your answer is a {kind.__name__} of {len(answer)} items.")
    rows = []
    for r in answer:
        r = _plain(r)
        if type(r) is np.ndarray:
            if r.size > MAX_ENTRIES:
                raise Rejected(f"wrong shape: a row of your answer has shape {r.shape}.")
            r = r.tolist()
        if type(r) in (list, tuple):
            if len(r) > MAX_ENTRIES:
                raise Rejected(
                    f"wrong shape: a row of your answer is a {type(r).__name__} of {len(r)} items."
                )
            if any(type(_plain(v)) in (list, tuple, np.ndarray) for v in r):
                raise Rejected(
                    "wrong shape: your answer is nested three levels deep (a list inside a "
                    "row); give a vector as [a, b, c] or a matrix as a list of rows "
                    "[[a, b, c], [d, e, f], [g, h, i]]."
                )
            rows.append([_scalar(v) for v in r])
        else:
            rows.append([_scalar(r)])
    lengths = {len(r) for r in rows}
    if len(lengths) > 1:
        raise Rejected("could not read your answer: its rows have different lengths.")
    if rows and len(rows[0]) == 1 and len(rows) > 1:
        return rows, f"a {len(rows)}-vector"
    return rows, f"a {len(rows)}x{len(rows[0]) if rows else 0} array"


def _target(shape):
    return {0: (1, 1), 1: (shape[0], 1) if shape else (1, 1), 2: shape}[len(shape)]


def describe_shape(shape):
    """``a scalar``, ``a 3-vector`` or ``a 3x3 matrix``."""
    if shape == ():
        return "a scalar"
    if len(shape) == 1:
        return f"a {shape[0]}-vector"
    return f"a {shape[0]}x{shape[1]} matrix"


def _fit_shape(M, shape, got):
    rows, cols = _target(shape)
    if M.shape == (rows, cols):
        return M
    if len(shape) == 1 and M.shape == (1, rows):
        return M.T
    raise Rejected(f"wrong shape: expected {describe_shape(shape)}, got {got}.")


def _refuse_numpy_of_matrix_expressions(array):
    """A matrix expression mixed with a numpy array (``u @ u.T - np.eye(3)``) becomes a numpy
    array of its entries: say so, instead of blaming the entries."""
    for entry in array.flat:
        kind = type(entry)
        if _is(kind, sp.Basic) and _genuine(kind) and entry.has(MatrixElement):
            raise Rejected(
                "your answer mixes a matrix symbol with a numpy array (np.eye, np.array ...), "
                "which turns it into a numpy array of entries; write the numbers with sympy "
                "instead: sp.Identity(3) or sp.eye(3) for the identity.",
                "not allowed",
            )


def read_answer(answer, shape, symbols, numeric=False):
    """A checked answer: ``("explicit", ImmutableMatrix)`` or ``("matrix", MatrixExpr)``.

    Raises :class:`Rejected` with the message for the student.
    """
    if answer is None:
        raise Rejected("no answer yet (the answer variable is still None).", "no answer")
    answer = _plain(answer)
    kind = type(answer)
    if _is(kind, MatrixExpr) and kind not in _EXPLICIT:
        if kind not in _MATRIX_TYPES:
            raise _not_allowed(answer)
        _walk(answer, symbols, numeric)
        matrix_degree(answer)
        return "matrix", _fit_shape(
            answer, shape, f"a {answer.shape[0]}x{answer.shape[1]} matrix expression"
        )
    if kind in _EXPLICIT:
        _walk(answer, None, None)  # size, types and depth before the copy
        M, got = sp.ImmutableMatrix(answer), f"a {answer.rows}x{answer.cols} matrix"
    elif _is(kind, sp.MatrixBase) or (
        _is(kind, (list, tuple, np.ndarray)) and kind not in (list, tuple, np.ndarray)
    ):
        raise (
            _not_allowed(answer)
            if _is(kind, sp.Basic)
            else Rejected(
                f"not allowed here: an object of type {_type_name(kind)} (a class of your "
                "own); give a plain list, tuple, numpy array or sympy Matrix.",
                "not allowed",
            )
        )
    else:
        if kind is np.ndarray and answer.ndim == 0:  # a 0-d array is a scalar
            answer = answer.item()
            kind = type(answer)
        if kind is np.ndarray and answer.size > MAX_ENTRIES:
            raise Rejected(f"wrong shape: your array has shape {answer.shape}.")
        if kind is np.ndarray and answer.dtype == object:
            _refuse_numpy_of_matrix_expressions(answer)
        rows, got = _rows(answer)
        M = sp.ImmutableMatrix(rows)
    _walk(M, symbols, numeric)
    M = _fit_shape(M, shape, got)
    memo = {}
    for e in M:
        degree_bound(e, memo)
    return "explicit", M


def read_choice(answer, letters):
    """The letters of a choice answer, as a sorted string (a str, set, list or tuple)."""
    if answer is None:
        raise Rejected("no answer yet (the answer variable is still None).", "no answer")
    kind = type(answer)
    if kind in (str, set, frozenset, list, tuple) and len(answer) > 4 * len(letters):
        raise Rejected(f"give at most the {len(letters)} letters {', '.join(letters)}.")
    if kind is str:
        items = [c for c in answer if c not in " ,;"]
    elif kind in (set, frozenset, list, tuple):
        items = list(answer)
        if not all(type(c) is str for c in items):
            raise Rejected('give the letters as strings, e.g. {"a", "c"}.')
    else:
        raise Rejected(
            f'give a set of letters such as {{"a", "c"}}, not an object of type {kind.__name__}.'
        )
    items = [c.strip().lower() for c in items]
    bad = sorted({c for c in items if c not in letters})
    if bad:
        raise Rejected(
            f"{', '.join(map(repr, bad))} is not one of the letters {', '.join(letters)}."
        )
    return "".join(sorted(set(items)))
