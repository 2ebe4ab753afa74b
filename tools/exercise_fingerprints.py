"""Make the checker's fingerprints from the instructor's reference solutions.

    python tools/exercise_fingerprints.py          # course_lib/exercise_bank/fingerprints.json
    python tools/exercise_fingerprints.py --check  # exit 1 if that file is out of date

For every exercise of the bank, runs the chapter's set-up code and the reference solution of
``tools/solutions/chNN.py`` (the code the notebook's answer cell holds between the solution
markers), then stores only what the checker needs: values at the seeded points and the salted
digest of the exact normal form (symbolic answers), salted digests of the entries (numbers),
a salted digest of the letters (choices), and the same for every known mistake. The solutions
themselves never enter the installed package.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from course_lib import exercise_bank  # noqa: E402
from course_lib.exercises import EXERCISES, Choice, Expr, Value  # noqa: E402
from course_lib.exercises import _engine as E  # noqa: E402
from course_lib.exercises._check import _numbers  # noqa: E402
from course_lib.exercises._reading import read_answer, read_choice  # noqa: E402

TARGET = ROOT / "course_lib" / "exercise_bank" / "fingerprints.json"


def solutions(chapter):
    """The SOLUTIONS and MISTAKES dicts of ``tools/solutions/chNN.py``."""
    path = ROOT / "tools" / "solutions" / f"{exercise_bank.CHAPTERS[chapter]}.py"
    spec = importlib.util.spec_from_file_location(f"_solutions_{chapter}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.SOLUTIONS, module.MISTAKES


def run(ex, code):
    """Namespace after the chapter's set-up cell and the solution code."""
    ns = {}
    exec(exercise_bank.chapter_module(ex.chapter).SETUP, ns)
    exec(code, ns)
    return ns


def _fingerprint_of(ex, answer):
    spec = ex.answer
    if isinstance(spec, Choice):
        return E.digest(ex.name, "choice", read_choice(answer, spec.letters))
    if isinstance(spec, Value):
        _, M = read_answer(answer, spec.shape, set(), numeric=True)
        return E.value_cells(ex.name, _numbers(M))
    syms = E.base_symbols(spec)
    readable = set(spec.allowed or ()) | set(spec.domain) | set(syms)
    form, M = read_answer(answer, spec.shape, readable)
    vals = E.values(form, M, syms, E.points(ex.name, spec))
    exact = E.exact_form(ex.name, M, spec.unit_omega) if form == "explicit" else None
    return {"values": vals.reshape(len(vals), -1).tolist(), "exact": exact}


def fingerprint(ex, code, mistakes):
    """The stored record of one exercise."""
    ns = run(ex, code)
    main = _fingerprint_of(ex, ns[ex.answer_variable])
    wrong = {}
    for mid, expr in mistakes.items():
        if mid not in ex.mistakes:
            raise ValueError(f"{ex.name}: mistake {mid!r} has no hint in the bank")
        fp = _fingerprint_of(ex, eval(expr, ns))
        wrong[mid] = fp["values"] if isinstance(ex.answer, Expr) else fp
    if set(ex.mistakes) - set(mistakes):
        raise ValueError(f"{ex.name}: hints without a mistake: {set(ex.mistakes) - set(mistakes)}")
    if isinstance(ex.answer, Expr):
        return {"values": main["values"], "exact": main["exact"], "mistakes": wrong}
    key = "digest" if isinstance(ex.answer, Choice) else "cells"
    return {key: main, "mistakes": wrong}


def build():
    """All fingerprints, as the JSON-ready dict."""
    out = {}
    for chapter in exercise_bank.CHAPTERS:
        sols, mistakes = solutions(chapter)
        for ex in (e for e in EXERCISES.values() if e.chapter == chapter):
            if ex.name not in sols:
                raise ValueError(f"{ex.name}: no reference solution in tools/solutions")
            out[ex.name] = fingerprint(ex, sols[ex.name], mistakes.get(ex.name, {}))
    return out


def dumps(data):
    """JSON with one exercise per line (diffs show which exercise changed)."""
    rows = [f"{json.dumps(k)}: {json.dumps(data[k], sort_keys=True)}" for k in sorted(data)]
    return "{\n" + ",\n".join(rows) + "\n}\n"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument(
        "--check",
        action="store_true",
        help="only compare with the stored file (exit 1 if it differs)",
    )
    args = parser.parse_args(argv)
    text = dumps(build())
    if args.check:
        same = TARGET.exists() and TARGET.read_text() == text
        print("fingerprints up to date" if same else "fingerprints out of date")
        return 0 if same else 1
    TARGET.write_text(text)
    print(f"wrote {TARGET.relative_to(ROOT)} ({len(json.loads(text))} exercises)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
