"""Write the vetted variant tables: ``course_lib/exercise_bank/variants.json``.

    python -m instructor.build.variant_tables          # the tables (variants on/off as they were)
    python -m instructor.build.variant_tables --on     # each student their own numbers
    python -m instructor.build.variant_tables --off    # the same tables, everyone the default
    python -m instructor.build.variant_tables --check  # exit 1 if the file is out of date
    python -m instructor.build.variant_tables --roster ids.txt  # tune the assignment to a class

For every variant key of the bank (an exercise's ``Variants.key``), row 0 is the exercise's
default (the numbers of the course without variants) and rows 1 to ``COUNT - 1`` (fewer when
there are fewer different fit numbers, at least ``MIN_ROWS``) are drawn by
``instructor/build/variant_draws.py`` from seeds derived from the key, each redrawn until fit and
different from the rows before it. The table
holds parameters only (what the statements show), never an answer. Then run
``instructor/build/exercise_fingerprints.py`` (``make exercises`` does both): the checker needs the
fingerprints of every row.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import sys
from collections import Counter
from pathlib import Path

from course_lib.exercises import EXERCISES
from course_lib.exercises._variants import TABLE_FILE, _hashes, _row, course_key
from instructor.build import variant_draws

ROOT = Path(__file__).resolve().parents[2]

TARGET = ROOT / "course_lib" / "exercise_bank" / TABLE_FILE
#: Variants per key, the default included (issue 33: at least 1,000 per exercise; with a
#: hash of the id modulo COUNT, a student of a class of 200 shares a key's numbers with some
#: classmate with probability 1 − (1 − 1/COUNT)^199, 18 % here: docs/variants.md).
COUNT = 1024
#: Fewer different fit draws than this (in 40 x COUNT tries) is an error.
MIN_ROWS = 1000
#: At most this share of a class may share a key's numbers with a classmate (issue 33).
SHARE = 0.05
#: Displacement buckets per key of ``--roster`` (64 small numbers per key in the tables).
BUCKETS = 64


def key_seed(key):
    """A seed of the key's draws, stable across Python and numpy versions."""
    return int.from_bytes(hashlib.sha256(f"variants/{key}".encode()).digest()[:4], "big")


def defaults():
    """Variant key -> the default parameters its exercises agree on."""
    out = {}
    for ex in EXERCISES.values():
        if ex.variants is None:
            continue
        key, default = ex.variants.key, ex.variants.default
        if out.setdefault(key, default) != default:
            raise ValueError(f"{ex.name}: the exercises of key {key} disagree on the default")
    return out


def class_share(key, count, sids, spread=None):
    """The share of the normalised ids ``sids`` whose row of ``key`` (of ``count`` rows,
    moved by ``spread``) is also another id's: what a class of them shares."""
    rows = [_row(s, key, count, spread) for s in sids]
    seen = Counter(rows)
    return sum(seen[r] > 1 for r in rows) / len(rows)


def spread_class(key, count, sids, buckets=BUCKETS):
    """A spread (a number per bucket of ids) that gives the normalised ids ``sids`` different
    rows of ``key``: the buckets, largest first, each take the smallest number m whose draw
    (:func:`course_lib.exercises._variants._row`) puts all their ids on rows no id has yet,
    as perfect hashing does. Ids that are the same after normalising are one student.

    Raises
    ------
    ValueError
        If there are no ids, or more ids than rows.
    """
    sids = sorted(set(sids) - {""})
    if not sids:
        raise ValueError("the roster has no student ids")
    if len(sids) > count:
        raise ValueError(f"{key}: {len(sids)} students, only {count} rows: some must share")
    groups = {}
    for s in sids:
        groups.setdefault(_hashes(s, key)[1] % buckets, []).append(s)
    spread, taken = [0] * buckets, set()
    for b, group in sorted(groups.items(), key=lambda item: (-len(item[1]), item[0])):
        for move in range(100_000):
            rows = {_hashes(s, key, move)[0] % count for s in group}
            if len(rows) == len(group) and not rows & taken:
                break
        else:  # pragma: no cover - a bucket of a few ids among >= 1,000 rows always finds one
            raise ValueError(f"{key}: no spread separates the ids of bucket {b}")
        spread[b], taken = move, taken | rows
    return spread


def tune_spread(tables, ids):
    """``{key: spread}`` for every key of ``tables`` (key -> rows) and the roster ``ids``."""
    sids = [course_key(s) for s in ids]  # as the kernel hashes them (variant_index)
    return {key: spread_class(key, len(rows), sids) for key, rows in tables.items()}


def read_roster(path):
    """The course keys of a roster, made as the kernel makes them (``course_key``): the
    instructor's class roster (a ``.csv``: a Canvas gradebook export or ``key,alias,...``, read
    by :mod:`instructor.grading.identity`, which refuses a row it cannot trust), or one id per line
    (blank lines and lines starting with # skipped)."""
    from course_lib.exercises._identity import course_key

    if str(path).endswith(".csv"):
        from instructor.grading.identity import load

        return sorted(set(load([path]).aliases.values()))
    text = Path(path).read_text(encoding="utf-8-sig")
    ids = [line.strip() for line in text.splitlines() if line.strip() and line[0] != "#"]
    return sorted({course_key(i) for i in ids})


def build(enabled=True, spread=None):
    tables = {}
    for key, default in sorted(defaults().items()):
        if key not in variant_draws.DRAWS:
            raise ValueError(f"variant key {key} has no draw in instructor/build/variant_draws.py")
        unfit = variant_draws.problems(key, default)
        if unfit:
            raise ValueError(f"variant key {key}: its default is unfit: {unfit}")
        rows, seen = [default], {json.dumps(default, sort_keys=True)}
        for seed in range(1, 40 * COUNT):  # every row different: a repeat is drawn again
            row = variant_draws.draw(key, [key_seed(key), seed])
            if json.dumps(row, sort_keys=True) not in seen:
                seen.add(json.dumps(row, sort_keys=True))
                rows.append(row)
            if len(rows) == COUNT:
                break
        if len(rows) < MIN_ROWS:  # a small space of fit numbers: too many students share
            raise ValueError(f"variant key {key}: only {len(rows)} different fit draws")
        tables[key] = rows
    out = {"enabled": enabled, "keys": tables}
    return out | ({"spread": dict(sorted(spread.items()))} if spread else {})


def dumps(data):
    """One row per line (diffs show which variant changed)."""
    keys = ",\n".join(
        f"    {json.dumps(k)}: [\n" + ",\n".join(f"      {json.dumps(r)}" for r in rows) + "\n    ]"
        for k, rows in data["keys"].items()
    )
    spread = f',\n  "spread": {json.dumps(data["spread"])}' if data.get("spread") else ""
    head = f'{{\n  "enabled": {json.dumps(data["enabled"])}{spread},\n'
    return head + f'  "keys": {{\n{keys}\n  }}\n}}\n'


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--on", action="store_true", help="variants on: each student their own")
    group.add_argument("--off", action="store_true", help="variants off: everyone the default")
    group.add_argument("--check", action="store_true", help="exit 1 if the file is out of date")
    parser.add_argument(
        "--roster",
        help="file of the class's student ids (one per line, or a CSV with a column 'key'): "
        "spread them so that no two of them share a key's numbers",
    )
    args = parser.parse_args(argv)
    old = json.loads(TARGET.read_text()) if TARGET.exists() else {}
    on, spread = old.get("enabled", False), old.get("spread")
    if args.check:
        same = TARGET.exists() and TARGET.read_text() == dumps(build(on, spread))
        print("variant tables up to date" if same else "variant tables out of date")
        return 0 if same else 1
    data = build(enabled=args.on or (on and not args.off), spread=spread)
    if args.roster:
        ids = read_roster(args.roster)
        data["spread"] = tune_spread(data["keys"], ids)
        print(f"spread over the rows: no two of the roster's {len(ids)} ids share numbers")
    TARGET.write_text(dumps(data))
    state = "on" if data["enabled"] else "off"
    print(f"wrote {TARGET.relative_to(ROOT)}: {len(data['keys'])} keys x {COUNT} rows, {state}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
