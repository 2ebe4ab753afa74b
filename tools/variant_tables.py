"""Write the vetted variant tables: ``course_lib/exercise_bank/variants.json``.

    python tools/variant_tables.py          # write the tables (variants on or off, as they were)
    python tools/variant_tables.py --on     # each student their own numbers
    python tools/variant_tables.py --off    # the same tables, everyone the default numbers
    python tools/variant_tables.py --check  # exit 1 if the file is not what this would write

For every variant key of the bank (an exercise's ``Variants.key``), row 0 is the exercise's
default (the numbers of the course without variants) and rows 1 to ``COUNT - 1`` (fewer when
there are fewer different fit numbers, at least ``MIN_ROWS``) are drawn by
``tools/variant_draws.py`` from seeds derived from the key, each redrawn until fit and
different from the rows before it. The table
holds parameters only (what the statements show), never an answer. Then run
``tools/exercise_fingerprints.py`` (``make exercises`` does both): the checker needs the
fingerprints of every row.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
for path in (ROOT, ROOT / "tools"):
    if str(path) not in sys.path:
        sys.path.insert(0, str(path))

import variant_draws  # noqa: E402

from course_lib.exercises import EXERCISES  # noqa: E402
from course_lib.exercises._variants import TABLE_FILE  # noqa: E402

TARGET = ROOT / "course_lib" / "exercise_bank" / TABLE_FILE
#: Variants per key, the default included (issue 33: at least 1,000 per exercise; with a
#: hash of the id modulo COUNT, a student of a class of 200 shares a key's numbers with some
#: classmate with probability 1 − (1 − 1/COUNT)^199, 18 % here: docs/variants.md).
COUNT = 1024
#: Fewer different fit draws than this (in 40 x COUNT tries) is an error.
MIN_ROWS = 1000


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


def build(enabled=True):
    tables = {}
    for key, default in sorted(defaults().items()):
        if key not in variant_draws.DRAWS:
            raise ValueError(f"variant key {key} has no draw in tools/variant_draws.py")
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
    return {"enabled": enabled, "keys": tables}


def dumps(data):
    """One row per line (diffs show which variant changed)."""
    keys = ",\n".join(
        f"    {json.dumps(k)}: [\n" + ",\n".join(f"      {json.dumps(r)}" for r in rows) + "\n    ]"
        for k, rows in data["keys"].items()
    )
    return f'{{\n  "enabled": {json.dumps(data["enabled"])},\n  "keys": {{\n{keys}\n  }}\n}}\n'


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--on", action="store_true", help="variants on: each student their own")
    group.add_argument("--off", action="store_true", help="variants off: everyone the default")
    group.add_argument("--check", action="store_true", help="exit 1 if the file is out of date")
    args = parser.parse_args(argv)
    on = json.loads(TARGET.read_text())["enabled"] if TARGET.exists() else False
    if args.check:
        same = TARGET.exists() and TARGET.read_text() == dumps(build(on))
        print("variant tables up to date" if same else "variant tables out of date")
        return 0 if same else 1
    data = build(enabled=args.on or (on and not args.off))
    TARGET.write_text(dumps(data))
    state = "on" if data["enabled"] else "off"
    print(f"wrote {TARGET.relative_to(ROOT)}: {len(data['keys'])} keys x {COUNT} rows, {state}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
