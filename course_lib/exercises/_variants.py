r"""Who the student is, and which variant of an exercise they get (issue 27).

A numeric exercise may come in a finite table of vetted variants (its parameters: an axis, an
angle, a matrix ...). Which one a student sees is decided by a stable hash of their
**normalised** id and the exercise's variant key: the same id always gives the same variant,
in the student's kernel and in the grader's process alike (the grader derives it from the id
it is given, never from the notebook).

The id, and the one key per student it resolves to, are those of
:mod:`course_lib.exercises._identity` (re-exported here). With no id, every exercise shows
its default variant (index 0, the example numbers), and :func:`~course_lib.exercises.check`
refuses to say ✓ on an exercise with variants: it says how to set the id.

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
from functools import lru_cache
from importlib import resources

from ._identity import (
    ENV_ID,
    EXAMPLE_ID,
    GRADER_ID,
    HUB_ID,
    course_key,
    identity_line,
    normalise_id,
    set_student_id,
    student_id,
)

__all__ = [
    "ENV_ID",
    "EXAMPLE_ID",
    "GRADER_ID",
    "HUB_ID",
    "course_key",
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

#: Salt of the variant hash; changing it gives every student other numbers.
_SALT = "rotations-course/variants/v1"


def variant_index(key, count, student=None, spread=None):
    """The variant (``0 <= index < count``) of the exercise variant key ``key`` for a student.

    ``student`` is an id (made a key by :func:`course_key`; the grader passes the key its roster
    gives) or None for this kernel's :func:`student_id`. An empty id, :data:`EXAMPLE_ID`, or
    ``count`` 1, gives 0, the default variant. Stable across Python and numpy versions (SHA-256
    of the salted key and the variant key). ``spread``: the key's displacements of the tables
    (``python -m instructor.build.variant_tables --roster`` chooses them so that no two
    students of a known class share a row; None: the plain hash).

    Raises
    ------
    ValueError
        If ``count`` is not a positive integer.
    """
    if type(count) is not int or count < 1:
        raise ValueError(f"count must be a positive integer, got {count!r}")
    sid = student_id()[0] if student is None else course_key(student)
    if not sid or sid == EXAMPLE_ID or count == 1:
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


# --------------------------------------------------------------------------- the variant tables

#: The vetted variants of every variant key, package data of :mod:`course_lib.exercise_bank`,
#: written by ``python -m instructor.build.variant_tables``:
#: ``{"enabled": bool, "keys": {key: [parameters, ...]}}``
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
    instructor turns it off with ``python -m instructor.build.variant_tables --off``)."""
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


def variant_row(variants, index):
    """Row ``index`` of the table of an exercise's :class:`Variants` (row 0: the default),
    whether or not variants are on; with no table for its key, the default is the only row.
    A copy.

    Raises
    ------
    IndexError
        If the table has no row ``index``; the message says how many it has.
    """
    rows = table()["keys"].get(variants.key) or [variants.default]
    if type(index) is not int or not 0 <= index < len(rows):
        raise IndexError(
            f"variant {index!r} of {variants.key}: the table has rows 0 to {len(rows) - 1}"
        )
    return copy.deepcopy(rows[index])


def variant_name(name, index):
    """The name an exercise's variant is fingerprinted under: ``name`` for the default
    (index 0), ``name@index`` otherwise.

    Examples
    --------
    >>> variant_name("compose_frames", 0), variant_name("compose_frames", 7)
    ('compose_frames', 'compose_frames@7')
    """
    return name if index == 0 else f"{name}@{index}"
