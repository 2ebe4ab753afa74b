"""How ``fingerprints.json`` holds the fingerprints of thousands of variant rows (issue 33).

An exercise's record without variants (and of its default, row 0) is stored as it is, under
its name. The records of the other rows of a variant table (``name@k``, k = 1, 2, ...) share
their shape: the same groups, the same known mistakes, mostly the same transformations; only
their digests differ. They are stored under :data:`FIELD`, per exercise, as a few *templates*
(a record with every digest replaced by :data:`SLOT`) and one line per row: the template's
index and the row's digests in the order of the template's slots (keys sorted, lists in order).
That is about a fifth of the size of a record per row, and holds exactly the same digests.

Examples
--------
>>> rows = [{"value": ["0123456789abcdef"], "size": 1, "mistakes": {}},
...         {"value": ["fedcba9876543210"], "size": 1, "mistakes": {}}]
>>> packed = pack(rows)
>>> packed["rows"]
['0 0123456789abcdef', '0 fedcba9876543210']
>>> unpack(packed, 1) == rows[1]
True
"""

from __future__ import annotations

import json
import re
from collections.abc import Mapping

__all__ = ["FIELD", "SLOT", "Fingerprints", "pack", "unpack"]

#: The key of fingerprints.json under which the variant rows are packed.
FIELD = "@variants"
#: What stands for a digest in a template.
SLOT = "#"
_DIGEST = re.compile(r"[0-9a-f]{16}")


def _walk(node, fill):
    """``node`` with every digest string replaced by ``fill(digest)`` (keys sorted)."""
    if isinstance(node, dict):
        return {k: _walk(node[k], fill) for k in sorted(node)}
    if isinstance(node, list):
        return [_walk(v, fill) for v in node]
    if isinstance(node, str) and (node == SLOT or _DIGEST.fullmatch(node)):
        return fill(node)
    return node


def pack(records):
    """The records of rows 1, 2, ... of one exercise as ``{"templates": [...], "rows": [...]}``.

    Raises
    ------
    ValueError
        If a record holds the template slot :data:`SLOT` as a value of its own.
    """
    templates, index, rows = [], {}, []
    for record in records:
        digests = []

        def take(value, digests=digests):
            if value == SLOT:
                raise ValueError(f"a fingerprint holds the template slot {SLOT!r}")
            digests.append(value)
            return SLOT

        template = json.dumps(_walk(record, take), sort_keys=True)
        if template not in index:
            index[template] = len(templates)
            templates.append(json.loads(template))
        rows.append(" ".join([str(index[template]), *digests]))
    return {"templates": templates, "rows": rows}


def unpack(packed, i):
    """The record of the ``i``-th packed row (0 for the table's row 1)."""
    t, *digests = packed["rows"][i].split(" ")
    it = iter(digests)
    return _walk(packed["templates"][int(t)], lambda _: next(it))


class Fingerprints(Mapping):
    """The fingerprints of fingerprints.json by exercise name, ``name@k`` unpacked on demand."""

    def __init__(self, data):
        self._plain = {k: v for k, v in data.items() if k != FIELD}
        self._packed = data.get(FIELD, {})
        self._unpacked = {}

    def __getitem__(self, name):
        if name in self._plain:
            return self._plain[name]
        if name not in self._unpacked:
            base, _, k = name.partition("@")
            packed = self._packed.get(base)
            if packed is None or not k.isdigit() or not 1 <= int(k) <= len(packed["rows"]):
                raise KeyError(name)
            self._unpacked[name] = unpack(packed, int(k) - 1)
        return self._unpacked[name]

    def __iter__(self):
        yield from self._plain
        for base, packed in self._packed.items():
            yield from (f"{base}@{k}" for k in range(1, len(packed["rows"]) + 1))

    def __len__(self):
        return len(self._plain) + sum(len(p["rows"]) for p in self._packed.values())
