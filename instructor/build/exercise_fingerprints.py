"""Make the checker's fingerprints from the instructor's reference solutions.

    python -m instructor.build.exercise_fingerprints          # exercise_bank/fingerprints.json
    python -m instructor.build.exercise_fingerprints --check  # exit 1 if that file is out of date

For every exercise of the bank, runs the chapter's set-up code and the reference solution of
``instructor/answers/chNN.py`` (the code the notebook's answer cell holds between the solution
markers), then stores only key-stretched digests of rounded values (see
``course_lib/exercises/_digests.py``): of every entry of a numeric answer, of the letters of a
choice, of projections of a symbolic answer's values at the sample points and of the features
its hints use. No value is stored.

A known mistake is stored as the transformation (``course_lib/exercises/_transforms.py``) that
turns the mistaken answer into the right one; the checker applies it to the student's answer.
Only a mistake that no transformation of the library explains is stored as the digests of its
own values (the tool prints which ones).
"""

from __future__ import annotations

import argparse
import hashlib
import json
import sys
from concurrent.futures import ProcessPoolExecutor
from dataclasses import replace
from functools import lru_cache
from pathlib import Path

import numpy as np

from course_lib import exercise_bank
from course_lib.exercises import EXERCISES, Choice, Expr, Value
from course_lib.exercises import _digests as D
from course_lib.exercises import _engine as E
from course_lib.exercises._reading import read_answer, read_choice
from course_lib.exercises._store import FIELD, Fingerprints, pack
from course_lib.exercises._transforms import (
    EXPR_TRANSFORMS,
    NUMBER_OPS,
    PERMUTATIONS,
)
from course_lib.exercises._variants import TABLE_FILE, variant_name
from course_lib.exercises.compare import numbers as _numbers
from instructor import answers

ROOT = Path(__file__).resolve().parents[2]

TARGET = ROOT / "course_lib" / "exercise_bank" / "fingerprints.json"
#: What each exercise's variant fingerprints were made from (instructor side, not shipped).
INPUTS = Path(__file__).with_name("fingerprint_inputs.json")
TABLES = ROOT / "course_lib" / "exercise_bank" / TABLE_FILE


def solutions(chapter):
    """The SOLUTIONS and MISTAKES dicts of ``instructor/answers/chNN.py``."""
    return answers.solutions(chapter), answers.mistakes(chapter)


def _close(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and bool(np.all(np.abs(a - b) <= 1e-10 * np.maximum(1, np.abs(b))))


# ------------------------------------------------------------------------------ numbers


#: Operations that only make sense for a single number or an angle.
_SCALAR_OPS = {"acos", "cos", "pi_minus", "two_pi_minus", "minus_two_pi", "plus_two_pi"}


def _number_transform(spec, right, wrong):
    """The permutation and per-entry operations that turn ``wrong`` into ``right``, or None:
    the one that explains most entries, with most entries left as they are."""
    shape, best = spec.shape, None
    ops_allowed = {
        k: op for k, op in NUMBER_OPS.items() if shape == () or spec.angle or k not in _SCALAR_OPS
    }
    for pname, perm in PERMUTATIONS.items():
        idx = perm(shape)
        if idx is None:
            continue
        moved = wrong[idx]
        ops = []
        for m, e in zip(moved, right):
            found = [k for k, op in ops_allowed.items() if _close(op(m), e)]
            ops.append(found[0] if found else None)
        changed = pname != "identity" or any(op not in (None, "same") for op in ops)
        score = (sum(op is not None for op in ops), ops.count("same"))
        enough = 2 * score[0] >= len(ops)  # a transform explains at least half of the entries
        if changed and enough and (best is None or score > best[0]):
            best = (score, {"perm": pname, "ops": ops})
    return None if best is None else best[1]


def _numbers_of(ex, answer):
    _, M = read_answer(answer, ex.answer.shape, set(), numeric=True)
    return _numbers(M)


def value_fingerprint(ex, answer, mistakes):
    """The digests of the right answer's groups of entries (``E.number_digests``); a known mistake
    is a transformation of the student's answer that explains every entry, or else the digest
    of the mistaken value."""
    name, shape = ex.name, ex.answer.shape
    right = _numbers_of(ex, answer)
    fp = {"size": len(right), "value": E.number_digests(name, "value", right, shape)}
    fp["mistakes"] = {}
    for mid, wrong_answer in mistakes.items():
        wrong = _numbers_of(ex, wrong_answer)
        transform = _number_transform(ex.answer, right, wrong)
        taken = [rec.get("transform") for rec in fp["mistakes"].values()]
        if transform is None or None in transform["ops"] or transform in taken:
            digests = E.number_digests(name, f"mistake {mid} ", wrong, shape)
            fp["mistakes"][mid] = {"value": digests}
        else:
            fp["mistakes"][mid] = {"transform": transform}
    return fp


# ------------------------------------------------------------------------------ choices


def choice_fingerprint(ex, answer, mistakes):
    letters = read_choice(answer, ex.answer.letters)
    fp = {"letters": D.stretched(ex.name, "letters", letters), "mistakes": {}}
    for mid, wrong in mistakes.items():
        mask = "".join(sorted(set(letters) ^ set(read_choice(wrong, ex.answer.letters))))
        fp["mistakes"][mid] = {"mask": mask}
    return fp


# ------------------------------------------------------------------------------ expressions


def expr_values(ex, answer):
    spec = ex.answer
    syms = E.base_symbols(spec)
    readable = set(spec.allowed or ()) | set(spec.domain) | set(syms)
    form, M = read_answer(answer, spec.shape, readable)
    pts, _ = E.points(ex.name, spec)
    vals = E.values(form, M, syms, pts)
    return vals.reshape((len(vals), *spec.shape))


def _expr_transform(ex, right, wrong):
    pts, _ = E.points(ex.name, ex.answer)
    for tname, f in EXPR_TRANSFORMS.items():
        moved = f(wrong, pts)
        if moved is not None and _close(moved, right):
            return tname
    return None


def expr_fingerprint(ex, answer, mistakes):
    name, spec = ex.name, ex.answer
    pts, near = E.points(name, spec)
    A = expr_values(ex, answer)
    which = ("value", "near", "entries", "scaled", "direction", "traceless", "coefficients")
    feats = E.features(name, spec, A, pts, near, which)
    fp = {
        label: D.cell_digest(name, label, z, E.step_of(label))
        for label, z in feats.items()
        if not label.startswith("-")
    }
    fp["structure"] = E.structure(A)
    fp["mistakes"] = {}
    for mid, wrong_answer in mistakes.items():
        wrong = expr_values(ex, wrong_answer)
        tname = _expr_transform(ex, A, wrong)
        taken = [rec.get("transform") for rec in fp["mistakes"].values()]
        if tname is None or tname in taken:
            z = D.projections(name, "value", wrong, 2)
            fp["mistakes"][mid] = {"value": D.cell_digest(name, f"mistake {mid}", z, E.STEP_VALUE)}
        else:
            fp["mistakes"][mid] = {"transform": tname}
    return fp


FINGERPRINTS = {Value: value_fingerprint, Choice: choice_fingerprint, Expr: expr_fingerprint}


def fingerprint(ex, mistakes, params=None):
    """The stored record of one exercise (of one variant's ``params``: ``ex`` named after the
    variant, :func:`course_lib.exercises._variants.variant_name`), from its worked solution
    (:func:`instructor.answers.worked`) and its known ``mistakes``."""
    ns = answers.worked(ex.name.split("@")[0], params)
    wrong = {}
    for mid, expr in mistakes.items():
        if mid not in ex.mistakes:
            raise ValueError(f"{ex.name}: mistake {mid!r} has no hint in the bank")
        wrong[mid] = eval(expr, ns)
    if set(ex.mistakes) - set(mistakes):
        raise ValueError(f"{ex.name}: hints without a mistake: {set(ex.mistakes) - set(mistakes)}")
    answer = ns[f"answer_{ex.name.split('@')[0]}"]  # a variant's answer cell is the exercise's
    return FINGERPRINTS[type(ex.answer)](ex, answer, wrong)


def build(sample=None, jobs=None, reuse=False, checkpoint=None):
    """All fingerprints, as the JSON-ready dict; ``sample(count)``: only the default and these
    row indices of every variant table (a test's deterministic sample). The rows are
    fingerprinted by ``jobs`` processes (all cores by default; every row is its own task).
    ``reuse``: an exercise whose inputs (:func:`inputs_digest`) are those recorded in
    :data:`INPUTS` keeps the rows stored in :data:`TARGET` (what ``make exercises`` does).
    ``checkpoint(out)`` is called after each exercise's rows (``main`` writes the files then,
    so that a run cut short resumes where it stopped)."""
    out, todo = {}, []
    old = _reusable() if reuse else {}
    for chapter in exercise_bank.CHAPTERS:
        sols, mistakes = solutions(chapter)
        for ex in (e for e in EXERCISES.values() if e.chapter == chapter):
            if ex.name not in sols:
                raise ValueError(f"{ex.name}: no reference solution in instructor/answers")
            out[ex.name] = fingerprint(ex, mistakes.get(ex.name, {}))
            rows = variant_rows(ex)
            if not rows:
                continue
            if _can_reuse(old.get(ex.name), inputs_digest(ex, sols, mistakes, rows), ex, rows):
                stored = old[ex.name][1]
                out |= {variant_name(ex.name, k): stored[variant_name(ex.name, k)]
                        for k in range(1, len(rows))}  # fmt: skip
                continue
            indices = range(1, len(rows)) if sample is None else sorted(set(sample(len(rows))))
            todo.append([(ex.name, k, rows[k]) for k in indices if 0 < k < len(rows)])
    pool = None if jobs == 1 or sample is not None else ProcessPoolExecutor(max_workers=jobs)
    try:
        for tasks in todo:
            done = (
                map(_row_fingerprint, tasks)
                if pool is None
                else pool.map(_row_fingerprint, tasks, chunksize=16)
            )
            out |= {variant_name(name, k): fp for (name, k, _), fp in zip(tasks, done)}
            if checkpoint is not None:
                checkpoint(out)
    finally:
        if pool is not None:
            pool.shutdown(cancel_futures=True)
    return out


def _row_fingerprint(task):
    """The fingerprint of row ``k`` of the variant table of exercise ``name`` (a task of
    :func:`build`, run in a worker process)."""
    name, k, params = task
    ex = EXERCISES[name]
    mistakes = answers.mistakes(ex.chapter)
    named = replace(ex, name=variant_name(name, k))
    try:
        return fingerprint(named, mistakes.get(name, {}), params)
    except Exception as err:
        raise ValueError(f"{named.name} ({params}): {err}") from err


def variant_rows(ex):
    """The rows of the variant table of ``ex`` (``[]`` without variants), read from the file
    ``instructor/build/variant_tables.py`` writes; every row is fingerprinted, variants on or
    off."""
    if ex.variants is None:
        return []
    rows = _tables().get(ex.variants.key)
    if not rows or rows[0] != ex.variants.default:
        raise ValueError(
            f"{ex.name}: no variant table or a stale one: run instructor/build/variant_tables.py"
        )
    return rows


def inputs_digest(ex, sols, mistakes, rows):
    """SHA-256 of what an exercise's variant fingerprints are made from: its chapter's set-up,
    its answer, solution and known mistakes, and the rows of its table. (The library's digest
    code is not in it: after changing that, run with ``--full``.)"""
    setup = exercise_bank.chapter_module(ex.chapter).SETUP
    parts = [setup, repr(ex.answer), sols[ex.name], json.dumps(mistakes.get(ex.name, {}))]
    parts.append(json.dumps(rows, sort_keys=True))
    return hashlib.sha256("\x00".join(parts).encode()).hexdigest()


def inputs_of(data):
    """The :func:`inputs_digest` of every exercise with variants (instructor side, in
    :data:`INPUTS`: never shipped)."""
    out = {}
    for chapter in exercise_bank.CHAPTERS:
        sols, mistakes = solutions(chapter)
        for ex in (e for e in EXERCISES.values() if e.chapter == chapter):
            rows = variant_rows(ex)
            if rows and variant_name(ex.name, 1) in data:
                out[ex.name] = inputs_digest(ex, sols, mistakes, rows)
    return out


def _can_reuse(old, digest, ex, rows):
    """Were the stored rows of ``ex`` made from these inputs, and are they all there?"""
    if old is None or old[0] != digest:
        return False
    last, beyond = variant_name(ex.name, len(rows) - 1), variant_name(ex.name, len(rows))
    return last in old[1] and beyond not in old[1]


def _reusable():
    """Exercise -> (inputs digest, the stored fingerprints) from the last run."""
    if not (TARGET.exists() and INPUTS.exists()):
        return {}
    stored = Fingerprints(json.loads(TARGET.read_text()))
    return {name: (digest, stored) for name, digest in json.loads(INPUTS.read_text()).items()}


@lru_cache(maxsize=1)
def _tables():
    return json.loads(TABLES.read_text())["keys"] if TABLES.exists() else {}


def dumps(data):
    """JSON with one exercise per line (diffs show which exercise changed), the rows of the
    variant tables packed (``course_lib/exercises/_store.py``), one row per line."""
    plain = sorted(k for k in data if "@" not in k)
    lines = [f"{json.dumps(k)}: {json.dumps(data[k], sort_keys=True)}" for k in plain]
    packed = []
    for base in plain:
        records = [data[f"{base}@{k}"] for k in range(1, _count(data, base))]
        if records:
            p = pack(records)
            rows = ",\n".join(f"      {json.dumps(r)}" for r in p["rows"])
            packed.append(
                f'    {json.dumps(base)}: {{"templates": {json.dumps(p["templates"])}, '
                f'"rows": [\n{rows}\n    ]}}'
            )
    if packed:
        lines.append(f"{json.dumps(FIELD)}: {{\n" + ",\n".join(packed) + "\n  }")
    return "{\n" + ",\n".join(lines) + "\n}\n"


def _count(data, base):
    """1 + the number of rows ``base@1``, ``base@2``, ... in ``data`` (they must be
    consecutive: a gap is an error)."""
    n = sum(1 for k in data if k.startswith(f"{base}@"))
    if any(f"{base}@{k}" not in data for k in range(1, n + 1)):
        raise ValueError(f"{base}: the rows of its variant table are not consecutive")
    return n + 1


def _write(data):
    """Write the fingerprints and what each exercise's rows were made from; the text."""
    text = dumps(data)
    TARGET.write_text(text)
    INPUTS.write_text(json.dumps(inputs_of(data), indent=1, sort_keys=True) + "\n")
    return text


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument(
        "--check",
        action="store_true",
        help="only compare with the stored file (exit 1 if it differs)",
    )
    parser.add_argument("--jobs", type=int, default=None, help="worker processes (all cores)")
    parser.add_argument(
        "--full", action="store_true", help="recompute every row (not only changed exercises)"
    )
    args = parser.parse_args(argv)
    if args.check:
        same = TARGET.exists() and TARGET.read_text() == dumps(build(jobs=args.jobs))
        print("fingerprints up to date" if same else "fingerprints out of date")
        return 0 if same else 1
    data = build(jobs=args.jobs, reuse=not args.full, checkpoint=_write)
    text = _write(data)
    stored = Fingerprints(json.loads(text))
    for name in sorted(n for n in stored if "@" not in n):
        fp = stored[name]
        kept = [
            m for m, rec in fp["mistakes"].items() if "transform" not in rec and "mask" not in rec
        ]
        if kept:
            print(f"{name}: mistakes stored as digests of their values: {', '.join(kept)}")
    print(f"wrote {TARGET.relative_to(ROOT)} ({len(stored)} exercises and variants)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
