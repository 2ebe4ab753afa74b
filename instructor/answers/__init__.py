"""The answers, one module per chapter (``chNN.py``, named as in ``course_lib.exercise_bank``).

Each holds, for the exercises of its chapter:

- ``SOLUTIONS``: exercise name -> the worked solution, the code between the solution markers
  of the notebook's answer cell (text: the tools run it after the chapter's set-up code);
- ``MISTAKES``: exercise name -> {mistake id: an expression of the typical wrong answer};
- ``DRAWS``: variant key -> (draw, problems), how the variants' numbers are drawn
  (:mod:`instructor.build.variant_draws`); :mod:`.common` holds what the draws share.

This package is the one loader of them: the build steps, the grader and the tests read the
answers through :func:`load`, :func:`solutions`, :func:`mistakes` and :func:`draws` only.
A Gradescope autograder holds this file and its own chapter's module only.

>>> sorted(solutions(1))[:2]
['angle_from_lengths', 'bac_cab']
"""

from __future__ import annotations

from importlib import import_module

from course_lib import exercise_bank

__all__ = ["load", "solutions", "mistakes", "draws"]


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
