"""``make release``: everything students get, in build/release/, checked by the leak gate.

1. ``student/``: the student edition, a git repository of its own
(instructor/release/student_edition.py);
2. ``dist/``: the course as a wheel, built from a clone of that repository (so it holds only
   what the edition holds: no instructor tool), with pip;
3. ``site/``: the student website, built from the edition's notebooks (``python -m
instructor.build.website --from``);
4. the leak gate (instructor/release/leak_gate.py) over all three; any hit fails the release (exit
1).

Prints the time of each step, the sizes and the gate's counts, and writes them to
build/release/REPORT.txt. ``--skip-site`` leaves the website out (the tests of the release use
it; the gate then scans an empty site folder).
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from instructor.build import website
from instructor.release import leak_gate, student_edition

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]


def build_wheel(student, dist):
    """The wheel of a fresh clone of the edition (its committed files only) into ``dist``."""
    shutil.rmtree(dist, ignore_errors=True)
    dist.mkdir(parents=True)
    with tempfile.TemporaryDirectory() as tmp:
        clone = Path(tmp) / "clone"
        subprocess.run(["git", "clone", "-q", str(student), str(clone)], check=True)
        subprocess.run(
            [
                sys.executable,
                "-m",
                "pip",
                "wheel",
                "--quiet",
                "--no-deps",
                "-w",
                str(dist),
                str(clone),
            ],
            check=True,
        )
    wheels = sorted(dist.glob("*.whl"))
    if len(wheels) != 1:
        raise RuntimeError(f"expected one wheel in {dist}, found {[w.name for w in wheels]}")
    return wheels[0]


def size(path):
    path = Path(path)
    if path.is_file():
        return path.stat().st_size
    return sum(p.stat().st_size for p in path.rglob("*") if p.is_file())


def _mb(n):
    return f"{n / 1e6:.2f} MB"


def release(out, with_site=True):
    """Build build/release (or ``out``); return (lines of the report, gate hits)."""
    out = Path(out)
    student, dist, site = out / "student", out / "dist", out / "site"
    times, lines = {}, []

    start = time.monotonic()
    made = student_edition.build_student_edition(ROOT, student)
    times["student edition"] = time.monotonic() - start
    lines.append(
        f"student/: {made['notebooks']} notebooks, {len(made['tests'])} test files; left out: "
        + "; ".join(f"{k} ({v})" for k, v in made["left_out"].items())
    )

    start = time.monotonic()
    wheel = build_wheel(student, dist)
    times["wheel"] = time.monotonic() - start

    start = time.monotonic()
    shutil.rmtree(site, ignore_errors=True)
    if with_site:
        website.build(student_dir=student, out=site)
    else:
        site.mkdir(parents=True)
    times["site"] = time.monotonic() - start

    start = time.monotonic()
    needles, report = leak_gate.run_gate(ROOT, student, dist, site)
    times["leak gate"] = time.monotonic() - start

    git_size = size(student / ".git")
    lines += [
        leak_gate.summary(needles, report),
        f"sizes: student/ {_mb(size(student) - git_size)} (+ .git {_mb(git_size)}), "
        f"wheel {wheel.name} {_mb(size(wheel))}, site/ {_mb(size(site))}",
        "times: " + ", ".join(f"{k} {v:.1f} s" for k, v in times.items()),
    ]
    lines += ["LEAK " + hit for hit in report.hits[:50]]
    return lines, report.hits


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=str(ROOT / "build" / "release"))
    parser.add_argument("--skip-site", action="store_true", help="no website (tests)")
    args = parser.parse_args(argv)
    lines, hits = release(args.out, with_site=not args.skip_site)
    text = "\n".join(lines) + "\n"
    (Path(args.out) / "REPORT.txt").write_text(text, encoding="utf-8")
    print(text, end="")
    if hits:
        print(f"make release: FAILED, the leak gate found {len(hits)} leaks", file=sys.stderr)
        return 1
    print(f"make release: {args.out} passed its leak gate")
    return 0


if __name__ == "__main__":
    sys.exit(main())
