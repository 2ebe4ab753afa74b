"""The answers, one module per chapter (``chNN.py``, named as in ``course_lib.exercise_bank``).

Each holds, for the exercises of its chapter:

- ``SOLUTIONS``: exercise name -> the worked solution, the code between the solution markers
  of the notebook's answer cell (text: the tools run it after the chapter's set-up code);
- ``MISTAKES``: exercise name -> {mistake id: an expression of the typical wrong answer};
- ``DRAWS``: variant key -> (draw, problems), how the variants' numbers are drawn
  (:mod:`instructor.build.variant_draws`); :mod:`.common` holds what the draws share.

This package is the one loader of them: the build steps, the grader and the tests read the
answers through :func:`load`, :func:`solutions`, :func:`mistakes` and :func:`draws`, and run a
worked solution with :func:`worked` only.
A Gradescope autograder holds this file and its own chapter's module only.

>>> sorted(solutions(1))[:2]
['angle_from_lengths', 'bac_cab']
"""

from __future__ import annotations

import copy
from importlib import import_module

from course_lib import exercise_bank
from course_lib.exercises import EXERCISES

__all__ = ["load", "solutions", "mistakes", "draws", "worked"]


def load(chapter):
    """The answers module of chapter ``chapter`` (an int of ``exercise_bank.CHAPTERS``).

    Raises
    ------
    KeyError
        If the bank has no chapter ``chapter``.
    ModuleNotFoundError
        If this copy of the answers lacks the chapter (a Gradescope zip holds one chapter).
    """
    return import_module(f"{__name__}.{exercise_bank.CHAPTERS[chapter]}")


def solutions(chapter):
    """``{exercise name: solution code}`` of chapter ``chapter``."""
    return load(chapter).SOLUTIONS


def mistakes(chapter):
    """``{exercise name: {mistake id: expression}}`` of chapter ``chapter`` ({} when none)."""
    return getattr(load(chapter), "MISTAKES", {})


def draws():
    """Every chapter's ``DRAWS`` in one dict (ValueError when two chapters define a key)."""
    out = {}
    for chapter in sorted(exercise_bank.CHAPTERS):
        found = getattr(load(chapter), "DRAWS", {})
        clash = set(out) & set(found)
        if clash:
            raise ValueError(f"chapter {chapter}: variant keys defined twice: {sorted(clash)}")
        out |= found
    return out


def worked(name, params=None):
    """The namespace of exercise ``name``'s worked solution: the chapter's set-up code run,
    then ``P`` set to ``params`` (a variant's parameters; None: the exercise's default numbers)
    for an exercise with variants, then its solution code run. The answer is
    ``ns[ex.answer_variable]``; a known mistake's expression is evaluated in ``ns``.

    >>> worked("hat_fifth")["answer_hat_fifth"].shape
    (3, 3)
    """
    ex = EXERCISES[name]
    ns = {}
    exec(exercise_bank.chapter_module(ex.chapter).SETUP, ns)  # the instructor's own code
    if ex.variants is not None:
        ns["P"] = copy.deepcopy(ex.variants.default if params is None else params)
    exec(solutions(ex.chapter)[name], ns)
    return ns
