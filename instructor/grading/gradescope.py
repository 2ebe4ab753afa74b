"""``make gradescope``: a Gradescope autograder zip per problem set, ``build/gradescope/psNN.zip``.

    python -m instructor.grading.gradescope [--out build/gradescope] [--unconfined] [ps01 ...]

Each zip holds, at its root, what Gradescope's autograder specification asks for
(``setup.sh``, ``run_autograder``) and what grading needs:

- ``course_lib/``, ``pyproject.toml``, ``README.md``, the pins (``environment-student.txt``,
  ``requirements-grader.txt``: nbgrader's and nh3's pins from ``environment.txt``): setup.sh
  installs them into ``/opt/rotations-venv`` (outside ``/autograder``);
- of the ``instructor`` package, what grading needs (:func:`_grading_files`): ``grading/`` (the
  course's grader: the same preprocessors and verdicts as ``make course``), the problem-set
  sync that :mod:`instructor.grading.course` runs (``build/sync_exercises.py``,
  ``build/exercise_fingerprints.py``, ``build/student.py``) and the loader of the answers
  (``answers/__init__.py``, ``answers/common.py``: no answer in either); no other build or
  release step;
- ``roster.csv`` when built with ``--roster`` (``make gradescope ROSTER=...``): the class
  roster that maps Gradescope's e-mail or ``sid`` to the course's key
  (:mod:`instructor.grading.identity`),
  scanned by the leak gate like the rest; students never see the zip;
- **instructor only** (:data:`SECRET`): ``instructor/answers/chNN.py`` of this set's chapter
  only (the reference solutions that :mod:`instructor.grading.verify` re-checks every recorded
  answer against, at fresh points; never another chapter's) and
  ``problem_sets/psNN_*.ipynb`` (the instructor's solved copy, from which nbgrader builds its
  gradebook and the released cells it puts back).

The leak gate (``instructor/release/leak_gate.py``) scans every other member (:func:`leak_check`):
none may hold a worked-solution line or the record of a right answer, nor (but for the code and
README, which name the markers they handle) an nbgrader marker. Gradescope does not show the
zip to students; what they see is ``results.json``, which holds only points, the checker's
hints and the grader's notes (never cell outputs or the solutions); the tests run the leak
gate on the results of the solved copy and of attacks. The risk that stays: the solutions are
in the grading container, next to the student's code; the confined kernel cannot see them
(bubblewrap's view, or, in Gradescope's Docker container where bubblewrap cannot start, the
privilege drop: folders closed to the kernel's uid). With neither, the autograder refuses to
run the notebook and exits 1 (``--unconfined`` makes it run it anyway, with the solutions in
reach: docs/grading.md).
setup.sh brings a Python the pins install on (:data:`MIN_PYTHON`; Ubuntu 22.04's universe
``python3.11``) and ends with ``python -m instructor.grading.gradescope_run selftest``.
"""

from __future__ import annotations

import argparse
import io
import re
import sys
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

__all__ = ["members", "build_zip", "leak_check", "SECRET", "SETUP", "RUN", "MIN_PYTHON"]

VENV = "/opt/rotations-venv"
#: Zip members that hold the solutions on purpose (the leak gate does not scan them).
SECRET = re.compile(r"^(instructor/answers/ch\d\d\.py|problem_sets/ps\d\d_[^/]+\.ipynb)$")
#: The class roster, in the zip on purpose (Gradescope does not show the zip to students).
ROSTER_MEMBER = "roster.csv"

#: The oldest Python the grader's pins install on (nbgrader 0.9.6: Requires-Python >=3.11).
MIN_PYTHON = (3, 11)
_MIN = ".".join(map(str, MIN_PYTHON))

SETUP = f"""\
#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image (Ubuntu 22.04 or
# 24.04). Any failure stops the build with a message: a broken image never grades a student.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
fail() {{ echo "setup.sh: $*" >&2; exit 1; }}
apt-get update -q
apt-get install -y -q bubblewrap python3 python3-venv python3-pip
PY=python3
if ! python3 -c 'import sys; sys.exit(sys.version_info < {MIN_PYTHON})'; then
    # Ubuntu 22.04: python3 is 3.10, nbgrader 0.9.6 needs {_MIN}+: universe's python3.11
    apt-get install -y -q python3.11 python3.11-venv || fail "python3 is $(python3 -V 2>&1) \\
and python3.11 could not be installed: the grader needs Python {_MIN}+ (or Ubuntu 24.04)"
    PY=python3.11
fi
"$PY" -c 'import sys; sys.exit(sys.version_info < {MIN_PYTHON})' \\
    || fail "$("$PY" -V 2>&1) is older than {_MIN}"
"$PY" -m venv {VENV} || fail "$PY -m venv failed (is the venv package installed?)"
{VENV}/bin/python -m pip install --quiet --upgrade pip
{VENV}/bin/python -m pip install --quiet -r /autograder/source/environment-student.txt \\
    -r /autograder/source/requirements-grader.txt || fail "the pinned packages did not install"
# course_lib as a copy in the venv: the kernel sees the venv, never /autograder/source
{VENV}/bin/python -m pip install --quiet --no-deps /autograder/source
chmod 700 /autograder/source
cd /autograder/source
{VENV}/bin/python -m instructor.grading.gradescope_run prepare
# grade the solved copy (full marks) and a blank copy (0) as students will be graded
{VENV}/bin/python -m instructor.grading.gradescope_run selftest \\
    || fail "the self-test failed (above): this image would not grade students right"
"""

RUN = f"""\
#!/usr/bin/env bash
# Gradescope runs this for every submission; it always writes results/results.json.
# ROTATIONS_AUTOGRADER_ROOT and ROTATIONS_PYTHON: for the tests only.
ROOT="${{ROTATIONS_AUTOGRADER_ROOT:-/autograder}}"
PY="${{ROTATIONS_PYTHON:-{VENV}/bin/python}}"
cd "$ROOT/source"
exec "$PY" -m instructor.grading.gradescope_run grade
"""


#: What the grader needs beyond the student's environment: nbgrader, and nh3
# (instructor/grading/pages.py).
GRADER_PACKAGES = ("nbgrader", "nh3")


def _grading_files(root=ROOT):
    """What of the instructor package grading needs (no answers, no build or release step but
    the problem-set sync that :mod:`instructor.grading.course` runs): repository paths."""
    grading = sorted(
        p.relative_to(root).as_posix() for p in (root / "instructor" / "grading").glob("*.py")
    )
    return (
        "instructor/__init__.py",
        "instructor/answers/__init__.py",
        "instructor/answers/common.py",
        "instructor/build/__init__.py",
        "instructor/build/student.py",
        "instructor/build/sync_exercises.py",
        "instructor/build/exercise_fingerprints.py",
        *grading,
    )


def _grader_pins(root=ROOT):
    """The ``environment.txt`` pins of :data:`GRADER_PACKAGES`, one per line."""
    lines = (root / "environment.txt").read_text().splitlines()
    pins = []
    for name in GRADER_PACKAGES:
        found = [line.strip() for line in lines if line.startswith(f"{name}==")]
        if not found:
            raise ValueError(f"environment.txt: no {name}== pin")
        pins += found
    return "\n".join(pins)


def members(ps, root=ROOT, unconfined=False, roster=None):
    """``{name in the zip: bytes}`` of the autograder of problem set ``ps`` (``"ps01"``);
    ``roster``: the course's roster CSV (checked), as ``roster.csv``."""
    made = sorted((root / "problem_sets").glob(f"{ps}_*.ipynb"))
    if len(made) != 1:
        raise ValueError(f"ps: expected one problem_sets/{ps}_*.ipynb, found {len(made)}")
    out = {"setup.sh": SETUP.encode(), "run_autograder": RUN.encode()}
    for name in ("pyproject.toml", "README.md", "LICENSE", "environment-student.txt"):
        out[name] = (root / name).read_bytes()
    out["requirements-grader.txt"] = (_grader_pins(root) + "\n").encode()
    for path in sorted((root / "course_lib").rglob("*")):
        if path.is_file() and "__pycache__" not in path.parts and path.suffix != ".pyc":
            out[path.relative_to(root).as_posix()] = path.read_bytes()
    for name in _grading_files(root):
        out[name] = (root / name).read_bytes()
    # the answers of this set's chapter only, through their one loader (instructor.answers)
    answers = f"instructor/answers/ch{int(ps[2:]):02d}.py"
    if not (root / answers).is_file():
        raise ValueError(f"{ps}: no answers {answers}")
    out[answers] = (root / answers).read_bytes()
    out[f"problem_sets/{made[0].name}"] = made[0].read_bytes()
    if unconfined:
        out["UNCONFINED"] = b"students' code runs unconfined (docs/grading.md)\n"
    if roster:
        from instructor.grading.identity import load

        load([roster])  # RosterError naming the line: no zip that grades on a guess
        out["roster.csv"] = Path(roster).read_bytes()
    return out


def leak_check(files, root=ROOT):
    """Leak-gate hits in the zip members that are not :data:`SECRET` (a list of lines)."""
    from instructor.release import leak_gate

    needles = leak_gate.collect_needles(root)
    package = set(_grading_files(root))
    report = leak_gate.Report()
    for name, data in sorted(files.items()):
        if SECRET.match(name):
            continue
        # the instructor package's grading parts are in the zip on purpose (_grading_files)
        if leak_gate._solution_dir(name) and name not in package:
            report.hits.append(f"{name}: in a solutions folder")
        found = leak_gate.Report()
        leak_gate.scan_data(name, data, needles, found)
        code = name.endswith((".py", ".md"))  # the grader's code names the markers it handles
        roster = name == ROSTER_MEMBER  # the roster is here on purpose; its text is scanned
        report.hits += [
            h
            for h in found.hits
            if not (code and "nbgrader marker" in h) and not (roster and "class roster" in h)
        ]
    return report.hits


def build_zip(ps, out, root=ROOT, unconfined=False, roster=None):
    """Write ``out/psNN.zip``; refuses (ValueError) when the leak gate finds anything."""
    files = members(ps, root, unconfined, roster)
    hits = leak_check(files, root)
    if hits:
        raise ValueError(f"{ps}: the leak gate found solutions in the zip: {hits[:5]}")
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as zf:
        for name, data in sorted(files.items()):
            info = zipfile.ZipInfo(name, date_time=(2026, 1, 1, 0, 0, 0))
            info.external_attr = (0o755 if name in ("setup.sh", "run_autograder") else 0o644) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            zf.writestr(info, data)
    path = out / f"{ps}.zip"
    path.write_bytes(buf.getvalue())
    return path


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("sets", nargs="*", help="problem sets (default: all)")
    parser.add_argument("--out", default=str(ROOT / "build" / "gradescope"))
    parser.add_argument(
        "--unconfined",
        action="store_true",
        help="run submissions even where bubblewrap cannot confine them (docs/grading.md)",
    )
    parser.add_argument("--roster", help="the course's roster CSV (docs/variants.md)")
    args = parser.parse_args(argv)
    found = sorted(p.name[:4] for p in (ROOT / "problem_sets").glob("ps[0-9][0-9]_*.ipynb"))
    sets = args.sets or found
    for ps in sets:
        if ps not in found:
            parser.error(f"no problem set {ps!r}; there are {', '.join(found)}")
    try:
        for ps in sets:
            path = build_zip(ps, args.out, unconfined=args.unconfined, roster=args.roster)
            print(f"{path}: {path.stat().st_size // 1024} kB, leak gate: 0 hits outside SECRET")
    except (OSError, ValueError) as err:
        print(f"make gradescope: {err}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
