"""What one student's problem set asks and its answers (instructor side: it runs the solutions).

    python -m instructor.build.show_variant STUDENT psNN [--roster R]
    # or: make variant STUDENT=id PS=psNN

For each exercise of the problem set with variants: the variant the student gets (the same id
the grader is given: the nbgrader student id, the JupyterHub user or the e-mail, resolved to
the course's key by the roster when one is given, as the grader does), the statement with that
student's numbers, and the reference answer for them. With variants off
(``python -m instructor.build.variant_tables --off``) every student gets variant 0 and it says so.
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

import numpy as np

from course_lib.exercises import exercises, variant, variants_enabled
from instructor.grading.identity import load
from instructor.grading.verify import expected

ROOT = Path(__file__).resolve().parents[2]


def report(student, chapter, roster=()):
    """The lines of the report for ``student`` (an id, resolved to the course's key with the
    roster files ``roster``) and the problem set of ``chapter``."""
    state = "on" if variants_enabled() else "off (everyone gets variant 0)"
    who = load(list(roster)).resolve(student)
    student = who.key
    lines = [f"student {student!r} ({who.how}), problem set {chapter}; variants {state}"]
    varied = [ex for ex in exercises(chapter) if ex.variants is not None]
    if not varied:
        lines.append("no exercise of this problem set has variants")
    for ex in varied:
        shown, k = variant(ex.name, student=student)
        _, M = expected(ex.name, k)  # a numeric answer (exercises with variants are numeric)
        answer = np.array(M.tolist(), dtype=float).reshape(ex.answer.shape)
        lines += ["", f"## {ex.heading()}  [variant {k} of key {ex.variants.key}]",
                  shown.statement.strip(), f"answer: {np.array2string(answer)}"]  # fmt: skip
    return lines


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("student", help="the student id (as nbgrader knows it)")
    parser.add_argument("ps", help="the problem set: ps01 ... ps05 (or 1 ... 5)")
    parser.add_argument("--roster", help="the course's roster CSV (instructor/grading/identity.py)")
    args = parser.parse_args(argv)
    m = re.fullmatch(r"(?:ps)?0*([1-9][0-9]*)", args.ps.strip())
    if not m:
        parser.error(f"PS must name a problem set as ps01 ... ps05, got {args.ps!r}")
    try:
        print("\n".join(report(args.student, int(m.group(1)), [args.roster] * bool(args.roster))))
    except ValueError as err:
        parser.error(str(err))
    return 0


if __name__ == "__main__":
    sys.exit(main())
