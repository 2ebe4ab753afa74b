r"""Who the student is, and which variant of an exercise they get (issue 27).

A numeric exercise may come in a finite table of vetted variants (its parameters: an axis, an
angle, a matrix ...). Which one a student sees is decided by a stable hash of their
**normalised** id and the exercise's variant key: the same id always gives the same variant,
in the student's kernel and in the grader's process alike (the grader derives it from the id
it is given, never from the notebook).

The id comes, in this order, from :func:`set_student_id` (a code the instructor hands out),
the environment variable ``COURSE_STUDENT_ID``, or ``JUPYTERHUB_USER`` (a JupyterHub user, who
is usually also the nbgrader student id). With no id, every exercise shows its default
variant (index 0, the numbers of the course without variants) and :func:`identity_line` says
how to set one.

Examples
--------
>>> normalise_id("  Ada   Lovelace ")
'ada lovelace'
>>> normalise_id("")
''
>>> variant_index("coords_by_projection", 64, "ada") == variant_index(
...     "coords_by_projection", 64, "  ADA ")
True
>>> variant_index("coords_by_projection", 64, "")
0
"""

from __future__ import annotations

import copy
import hashlib
import json
import os
import unicodedata
from functools import lru_cache
from importlib import resources

__all__ = [
    "ENV_ID",
    "HUB_ID",
    "TABLE_FILE",
    "identity_line",
    "table",
    "variant_name",
    "variant_of",
    "variants_enabled",
    "normalise_id",
    "set_student_id",
    "student_id",
    "variant_index",
]

#: The environment variable an instructor (or a student, on Colab) sets to a handed-out code.
ENV_ID = "COURSE_STUDENT_ID"
#: The variable JupyterHub sets in every single-user server.
HUB_ID = "JUPYTERHUB_USER"
#: Salt of the variant hash; changing it gives every student other numbers.
_SALT = "rotations-course/variants/v1"
_state = {"id": None}


def normalise_id(raw):
    """The id as it is hashed: NFKC unicode, case folded, inner white space one blank.

    Any string is accepted (empty, unicode, 1,000 characters, spaces); ``None`` is ``""``.

    Raises
    ------
    TypeError
        If ``raw`` is not a string or None.

    Examples
    --------
    >>> normalise_id("Ｚｏë\tX")
    'zoë x'
    """
    if raw is None:
        return ""
    if not isinstance(raw, str):
        raise TypeError(f"student id must be a string, got {type(raw).__name__}")
    text = unicodedata.normalize("NFKC", raw).casefold()
    return " ".join(text.split())


def set_student_id(raw):
    """Set the student id of this kernel (a code from the instructor); ``None`` unsets it.

    Examples
    --------
    >>> set_student_id("ada"); student_id()
    ('ada', 'set_student_id')
    >>> set_student_id(None)
    """
    _state["id"] = None if raw is None else normalise_id(raw)


def student_id():
    """``(normalised id, where it came from)``; ``("", "none")`` when no id is set."""
    if _state["id"]:
        return _state["id"], "set_student_id"
    for var in (ENV_ID, HUB_ID):
        value = normalise_id(os.environ.get(var, ""))
        if value:
            return value, var
    return "", "none"


def variant_index(key, count, student=None, spread=None):
    """The variant (``0 <= index < count``) of the exercise variant key ``key`` for a student.

    ``student`` is an id (normalised here) or None for this kernel's :func:`student_id`. An
    empty id, or ``count`` 1, gives 0, the default variant. Stable across Python and numpy
    versions (SHA-256 of the salted, normalised id and the key). ``spread``: the key's
    displacements of the tables (``tools/variant_tables.py --roster`` chooses them so that
    no two students of a known class share a row; None: the plain hash).

    Raises
    ------
    ValueError
        If ``count`` is not a positive integer.
    """
    if type(count) is not int or count < 1:
        raise ValueError(f"count must be a positive integer, got {count!r}")
    sid = student_id()[0] if student is None else normalise_id(student)
    if not sid or count == 1:
        return 0
    return _row(sid, key, count, spread)


def _hashes(sid, key, move=0):
    """Two 64-bit hashes of a normalised, non-empty id and a key (with ``move``, another
    draw): the row, and the bucket of the id."""
    tail = f"\x00{move}" if move else ""
    digest = hashlib.sha256(f"{_SALT}\x00{sid}\x00{key}{tail}".encode()).digest()
    return int.from_bytes(digest[:8], "big"), int.from_bytes(digest[8:16], "big")


def _row(sid, key, count, spread=None):
    """The row of :func:`variant_index` for a normalised, non-empty id ``sid``: the hash
    modulo ``count``; with a ``spread``, the ids of a bucket whose entry is m > 0 draw again
    with m."""
    h, bucket = _hashes(sid, key)
    move = spread[bucket % len(spread)] if spread else 0
    return (_hashes(sid, key, move)[0] if move else h) % count


def identity_line():
    """One line for the top of a problem set: whose numbers it shows, or how to set the id.

    Examples
    --------
    >>> set_student_id("ada"); print(identity_line())  # doctest: +ELLIPSIS
    Student id: ada (from set_student_id): the exercises show the numbers of this id...
    >>> set_student_id(None)
    """
    sid, source = student_id()
    if sid:
        return (
            f"Student id: {sid} (from {source}): the exercises show the numbers of this id; "
            "grading uses your course id, so it must be yours."
        )
    return (
        "No student id is set: the exercises show their default numbers. If your instructor "
        f"gave you an id, run `from course_lib.exercises import set_student_id; "
        f'set_student_id("your id")` in a new cell (or set the environment variable {ENV_ID}), '
        "then run all cells again; on the course's JupyterHub your user name is used."
    )


# --------------------------------------------------------------------------- the variant tables

#: The vetted variants of every variant key, package data of :mod:`course_lib.exercise_bank`,
#: written by ``tools/variant_tables.py``: ``{"enabled": bool, "keys": {key: [parameters, ...]}}``
#: with row 0 of each key the exercise's default, and ``"spread": {key: [displacement, ...]}``
#: when the instructor spread a class over the rows (``variant_tables.py --roster``).
#: Parameters only: no answer, no value of one.
TABLE_FILE = "variants.json"


@lru_cache(maxsize=1)
def table():
    """The variant tables (read once); ``{"enabled": False, "keys": {}}`` when there are none."""
    from .. import exercise_bank

    path = resources.files(exercise_bank).joinpath(TABLE_FILE)
    if not path.is_file():
        return {"enabled": False, "keys": {}}
    return json.loads(path.read_text(encoding="utf-8"))


def variants_enabled():
    """Whether this course gives each student their own numbers (the tables' ``enabled``; the
    instructor turns it off with ``python tools/variant_tables.py --off``)."""
    return bool(table().get("enabled"))


def variant_of(variants, student=None):
    """``(index, parameters)`` of an exercise's :class:`Variants` for ``student``.

    ``student`` is an id, or None for this kernel's :func:`student_id`. With variants off, no
    table for the key, or no id, it is ``(0, default)``. The parameters are a copy.
    """
    rows = table()["keys"].get(variants.key) if variants_enabled() else None
    if not rows:
        return 0, copy.deepcopy(variants.default)
    k = variant_index(variants.key, len(rows), student, table().get("spread", {}).get(variants.key))
    return k, copy.deepcopy(rows[k])


def variant_name(name, index):
    """The name an exercise's variant is fingerprinted under: ``name`` for the default
    (index 0), ``name@index`` otherwise.

    Examples
    --------
    >>> variant_name("compose_frames", 0), variant_name("compose_frames", 7)
    ('compose_frames', 'compose_frames@7')
    """
    return name if index == 0 else f"{name}@{index}"
