r"""Exercises of the course notebooks and the engine that checks them.

The exercises themselves are data, one module per chapter in :mod:`course_lib.exercise_bank`
(statement, level, points, the kind and form of answer asked for, hints). A notebook shows an
exercise from the bank and grades a student's answer with :func:`check`::

    answer_hat_fifth = ...                  # the student's matrix expression in W
    result = check("hat_fifth", answer_hat_fifth)
    assert result.ok, result.message        # the nbgrader test cell fails on a wrong answer

What is checked, and how (details in :mod:`course_lib.exercises._engine` and
:mod:`course_lib.exercises._digests`):

- **Only plain objects.** Sympy expressions and matrices, numpy arrays, lists, tuples and
  numbers, built from the exercise's own symbols and elementary functions, their types compared
  by identity before anything else is done with them (no method of a student's object is ever
  called). Subclasses and ``floor``, ``Heaviside``, ``Mod``, ``Piecewise``, ``Integral``,
  ``Abs`` ... are "not allowed here"; an answer too large, too deep or too big a number to
  check quickly is "too complex to check: simplify it first".
- **The form.** Where an exercise asks for a form (a matrix expression of degree at most 2 in
  ``W``; an expression in ``x·x``, ``y·y``, ``x·y`` only; no square root left), a right value in
  another form gets "right value, but the exercise asks for ...".
- **The value.** A symbolic answer is evaluated at seeded points over the whole domain (in
  pairs that redraw one symbol at a time, so that leaving a symbol out cannot pass), and the
  projections of its values are rounded and compared with stored digests; a number is compared
  entry by entry, within the package's one tolerance ``TOL``. There is no tolerance argument.

The expected answers are nowhere in the package, nor any value of them: the checker holds only
salted, key-stretched (scrypt) digests of rounded values, made by the repository tool
``python -m instructor.build.exercise_fingerprints`` from the instructor's reference
solutions. Hints come from transformations of the student's own answer (its negative, its
transpose, a known mistake undone ...) compared with those digests.

The symbols of the exercises are those of :mod:`course_lib.symbolic`, re-exported here.

Examples
--------
>>> print(check("hat_fifth", W**5))
✗ hat_fifth: right value, but the exercise asks for a matrix expression in W of degree at
most 2, with coefficients in omega_1, omega_2 and omega_3: reduce the higher powers first.
>>> check("hat_fifth", None).status
'no answer'
"""

from __future__ import annotations

import json
import warnings
from dataclasses import replace
from functools import lru_cache
from importlib import resources

import numpy as np

from .. import exercise_bank
from ..symbolic import (
    A,
    B,
    R,
    W,
    X,
    Y,
    a,
    alpha,
    beta,
    d,
    hat,
    omega,
    phi,
    t,
    theta,
    u,
    x,
    x_0,
    xx,
    xy,
    y,
    yy,
    z,
)
from ._check import expected_shape_phrase, judge
from ._identity import SETTINGS_FILE, check_domain, course_key, how_to_set_id, normalise_id
from ._model import LEVELS, CheckResult, Choice, Exercise, Expr, Value, Variants, format_parameter
from ._reading import Rejected
from ._store import Fingerprints
from ._variants import (
    identity_line,
    set_student_id,
    student_id,
    variant_index,
    variant_name,
    variant_of,
    variant_row,
    variants_enabled,
)

__all__ = [
    "EXERCISES",
    "LEVELS",
    "SETTINGS_FILE",
    "CheckResult",
    "Choice",
    "Exercise",
    "Expr",
    "Value",
    "Variants",
    "check",
    "check_domain",
    "course_key",
    "exercises",
    "get",
    "identity_line",
    "how_to_set_id",
    "names",
    "normalise_id",
    "parameters",
    "set_student_id",
    "show",
    "student_id",
    "variant",
    "variant_index",
    "variant_of",
    "variant_row",
    "variants_enabled",
    "your_numbers",
    "A",
    "B",
    "R",
    "W",
    "X",
    "Y",
    "a",
    "alpha",
    "beta",
    "d",
    "hat",
    "omega",
    "phi",
    "t",
    "theta",
    "u",
    "x",
    "x_0",
    "xx",
    "xy",
    "y",
    "yy",
    "z",
]


@lru_cache(maxsize=1)
def _registry():
    """Every exercise of the bank, by name, in chapter order (loaded on first use, so that the
    bank's modules can import this package's classes without an import cycle)."""
    return {ex.name: ex for ex in exercise_bank.all_exercises()}


def __getattr__(name):
    if name == "EXERCISES":  # every exercise of the course, by name, in chapter order
        return _registry()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def get(name):
    """The exercise called ``name``; KeyError listing the known names otherwise.

    Examples
    --------
    >>> get("hat_fifth").label, get("hat_fifth").level, get("hat_fifth").points
    ('3.3', 'core', 2)
    """
    registry = _registry()
    if not isinstance(name, str) or name not in registry:
        raise KeyError(f"unknown exercise {name!r}; known exercises: {', '.join(registry)}")
    return registry[name]


def names(chapter=None):
    """Names of the exercises (of one chapter when ``chapter`` is given), in order."""
    return [ex.name for ex in exercises(chapter)]


def exercises(chapter=None):
    """The exercises of ``chapter`` (1-4), or all of them, in order.

    Raises
    ------
    ValueError
        If ``chapter`` is not one of the chapters of the bank.
    """
    if chapter is None:
        return list(_registry().values())
    if chapter not in exercise_bank.CHAPTERS:
        raise ValueError(
            f"chapter must be one of {sorted(exercise_bank.CHAPTERS)}, got {chapter!r}"
        )
    return [ex for ex in _registry().values() if ex.chapter == chapter]


def parameters(name, student=None):
    """The parameters of exercise ``name`` in a student's variant (a copy).

    ``student`` is an id, or None for this kernel's student (:func:`student_id`); with no id,
    or variants off, the default numbers.

    Raises
    ------
    KeyError
        If ``name`` is not an exercise; the message lists the known names.
    ValueError
        If the exercise has no variants (its numbers are in its statement).

    Examples
    --------
    >>> parameters("chain_vector", student="")["v_c"]
    [1, 2, 3]
    >>> parameters("hat_fifth")
    Traceback (most recent call last):
    ...
    ValueError: exercise hat_fifth has no variants: its numbers are in its statement
    """
    ex = get(name)
    if ex.variants is None:
        raise ValueError(f"exercise {name} has no variants: its numbers are in its statement")
    return variant_of(ex.variants, student)[1]


def variant(name, student=None):
    """Exercise ``name`` as ``student`` gets it (None: this kernel's student), and its index.

    Its statement, tip and hints show that variant's numbers, and its ``name`` is the one its
    fingerprints are stored under (:func:`~course_lib.exercises._variants.variant_name`). An
    exercise without variants is returned as it is, with index 0.

    Examples
    --------
    >>> ex, k = variant("chain_vector", student="")
    >>> k, "<<v_c>>" in ex.statement, "v_c = (1," in ex.statement
    (0, False, True)
    """
    ex = get(name)
    if ex.variants is None:
        return ex, 0
    k, values = variant_of(ex.variants, student)
    shown = {p: format_parameter(values[p]) for p in ex.placeholders()}
    return replace(ex.filled(shown), name=variant_name(name, k)), k


def _needs_id(ex):
    """Whether exercise ``ex`` has numbers of its own per student and no id is set here."""
    return ex.variants is not None and variants_enabled() and not student_id()[0]


#: Under a statement shown before the student id is set.
EXAMPLE_NOTE = "*Example numbers, not yours: set your student id at the top of the problem set.*"


def show(name):
    """The statement of exercise ``name`` with this student's numbers, as notebook markdown
    (whose numbers they are is said once, at the top of the problem set: :func:`your_numbers`;
    before an id is set, a line says these are example numbers)."""
    from IPython.display import Markdown

    ex, _ = variant(name)
    note = f"\n\n{EXAMPLE_NOTE}" if _needs_id(get(name)) else ""
    return Markdown(f"{ex.statement.strip()}{note}")


def numbers_text(chapter):
    """The markdown of :func:`your_numbers`: whose numbers, then every statement of the
    chapter's exercises with variants, with those numbers (none before an id is set).

    Examples
    --------
    >>> set_student_id("Ada@Example.org")
    >>> print(numbers_text(1).splitlines()[0])  # doctest: +ELLIPSIS
    Student id: **ada@example.org** (from set_student_id). The exercises show the numbers...
    >>> set_student_id(None)
    """
    varied = [ex for ex in exercises(chapter) if ex.variants is not None]
    if not varied:
        return "Every student has the same numbers in this problem set: no student id is needed."
    if not variants_enabled():
        head = "Every student has the same numbers in this course (variants are off)."
    elif not student_id()[0]:
        return identity_line()
    else:
        head = identity_line()
    parts = [head, "The statements with your numbers (each is shown again above its answer):"]
    for ex in varied:
        shown, _ = variant(ex.name)
        parts.append(f"**Exercise {ex.label} · {ex.title}.** {shown.statement.strip()}")
    return "\n\n".join(parts)


def your_numbers(chapter):
    """Whose numbers the problem set of ``chapter`` shows, and all its statements with those
    numbers, so that they can be read before any answer cell runs (notebook markdown: the
    text of :func:`numbers_text`).

    Examples
    --------
    >>> your_numbers(1).data == numbers_text(1)
    True

    Raises
    ------
    ValueError
        If ``chapter`` is not one of the chapters of the bank.
    """
    from IPython.display import Markdown

    return Markdown(numbers_text(chapter))


@lru_cache(maxsize=1)
def _fingerprints():
    text = resources.files(exercise_bank).joinpath("fingerprints.json").read_text()
    return Fingerprints(json.loads(text))  # the variant rows unpacked on demand (_store)


def check(name, answer):
    r"""Check a student's answer to the exercise ``name``.

    Parameters
    ----------
    name : str
        The exercise's name (see :func:`names`).
    answer : object
        A sympy expression, Matrix or matrix expression; a number, list, tuple or numpy
        array; a set of letters; ``None`` when there is no answer yet.

    Returns
    -------
    CheckResult
        ``ok``, ``status`` and a message beginning with the exercise's name. A wrong or
        unreadable answer gives ``ok=False`` and a hint that does not reveal the expected
        answer. Never raises for a bad answer.

    Raises
    ------
    KeyError
        If ``name`` is not an exercise; the message lists the known names.

    Examples
    --------
    >>> print(check("which_are_rigid", "a"))  # doctest: +ELLIPSIS
    ✗ which_are_rigid: that is not the right set of letters. Hint: ...
    """
    ex, _ = variant(name)
    if _needs_id(get(name)):  # never ✓ on numbers that may not be the student's
        text = "no student id is set, so these are not your numbers. " + how_to_set_id()
        return CheckResult(False, f"{name}: {text}", "no id")
    try:
        fp = _fingerprints()[ex.name]
        with np.errstate(all="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore")
            status, text = judge(ex, fp, answer)
    except Rejected as err:
        status, text = err.status, str(err)
        if status == "no answer":
            text = f"no answer yet: assign your answer to `answer_{name}`."
    except KeyError:
        status, text = (
            "malformed",
            (
                "this exercise has no stored fingerprint; the instructor "
                "regenerates them with python -m instructor.build.exercise_fingerprints."
            ),
        )
    except Exception as err:  # noqa: BLE001 - a bad answer must never raise from deep inside
        status, text = (
            "malformed",
            (
                f"could not check your answer ({type(err).__name__}); "
                f"give {expected_shape_phrase(ex)} as the exercise asks."
            ),
        )
    if status == "wrong" and ex.tip:
        text = f"{text} Hint: {ex.tip}"
    return CheckResult(status == "correct", f"{name}: {text}", status)
