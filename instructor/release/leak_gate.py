"""The leak gate of ``make release``: no worked solution in anything students get.

What counts as a worked solution (the *needles*):

* every line between nbgrader's solution markers in the instructor's notebooks
  (``notebooks/*.ipynb`` and ``problem_sets/*.ipynb``), and every line of every worked
  solution in ``instructor/answers/*.py`` (the string values of their ``SOLUTIONS`` dicts, read
  with ``ast``, never imported);
* of a line with a trailing comment, its code alone too (a copy without the comment is the
  same leak), and of an ``answer_x = <expression>`` line, the expression alone (the issue's
  docstring leak showed an answer's expression in a sentence).

Lines skipped, each counted by reason in the report:

* ``blank``: empty lines;
* ``punctuation``: lines of brackets, commas and colons only (``)``, ``]``, ``},``): they
  close a statement and say nothing;
* ``prefill``: ``answer_x = None``, the line the student's stub keeps on purpose;
* ``short``: under :data:`MIN_CHARS` characters without spaces (``R = Rz``, ``else:``): as
  common in ordinary code as in a solution, so a hit would mean nothing;
* ``public``: text that also stands outside every solution region in the instructor's
  notebooks (``import numpy as np``, ``result = check(...)``, an expression such as
  ``R_ab @ R_bc`` that a chapter computes in its reading part): students get those anyway.

A skipped variant (the code without its comment, an answer's expression) is dropped the same
way; the counts are of whole lines.

The gate then reads every file of the student edition's work tree, every blob and commit
message of its whole git history, every member of each wheel and every file of the website
(HTML also with its tags taken out, JSON and notebooks also by their strings) and fails on:
a needle found (naming the file, the line and where the solution comes from), a line with
one of nbgrader's markers, a folder named ``solutions``, ``answers`` or ``instructor``, and a class
roster (a file named ``roster*``, or a CSV with a Canvas gradebook's header): students' ids stay
with the instructor.

Command line: ``python -m instructor.release.leak_gate ROOT STUDENT_DIR DIST_DIR SITE_DIR`` (exit 1
on any hit, listing up to 50).
"""

from __future__ import annotations

import ast
import html
import json
import re
import subprocess
import sys
import zipfile
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

MIN_CHARS = 8
MARKER = re.compile(r"(BEGIN|END) (SOLUTION|HIDDEN TESTS|MARK SCHEME)")
PUNCTUATION = re.compile(r"^[\s()\[\]{},:;]*$")
PREFILL = re.compile(r"^answer_\w+\s*=\s*None$")
ANSWER_RHS = re.compile(r"^answer_\w+\s*=\s*(.+)$")
#: Folder names that nothing students get may hold: the instructor's answers live in
#: instructor/answers/ (issue 36), and the instructor package never ships.
SOLUTION_DIRS = {"solutions", "solution", "answers", "instructor"}
ROSTER_HEADER = re.compile(r"^\ufeff?\"?Student\"?,.*\bSIS (User|Login) ID\b", re.M)
_TAG = re.compile(r"<[^>]+>")


@dataclass
class Needles:
    """The solution lines to look for: {line: where it comes from}, and what was skipped."""

    lines: dict = field(default_factory=dict)
    skipped: Counter = field(default_factory=Counter)
    regions: int = 0


@dataclass
class Report:
    hits: list = field(default_factory=list)
    files: int = 0
    blobs: int = 0
    members: int = 0
    bytes: int = 0


# ------------------------------------------------------------------------------ the needles


def _regions(source):
    """(lines inside solution regions, lines outside) of one cell's source."""
    inside, outside, open_ = [], [], False
    for line in source.splitlines():
        if "BEGIN SOLUTION" in line:
            open_ = True
        elif "END SOLUTION" in line:
            open_ = False
        else:
            (inside if open_ else outside).append(line)
    return inside, outside


def _notebook_lines(path):
    nb = json.loads(path.read_text(encoding="utf-8"))
    inside, outside, regions = [], set(), 0
    for i, cell in enumerate(nb.get("cells", [])):
        source = "".join(cell.get("source", []))
        regions += source.count("BEGIN SOLUTION")
        ins, outs = _regions(source)
        inside += [(line, f"{path.parent.name}/{path.name} cell {i}") for line in ins]
        outside |= {line.strip() for line in outs}
    return inside, outside, regions


def _solutions_file_lines(path):
    """Lines of the string values of ``SOLUTIONS = {...}`` in a instructor/answers module."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Assign) and any(
            isinstance(t, ast.Name) and t.id == "SOLUTIONS" for t in node.targets
        ):
            for key, value in zip(node.value.keys, node.value.values):
                if isinstance(value, ast.Constant) and isinstance(value.value, str):
                    name = key.value if isinstance(key, ast.Constant) else "?"
                    where = f"instructor/answers/{path.name} exercise {name}"
                    found += [(line, where) for line in value.value.splitlines()]
    return found


def _variants(line):
    """The stripped line, its code without a trailing comment, an answer's expression."""
    out = [line]
    code = line.split("  #")[0].rstrip() if "  #" in line else line
    if code != line:
        out.append(code)
    m = ANSWER_RHS.match(code)
    if m:
        out.append(m.group(1).strip())
    return out


def _skip_reason(text, public_text):
    if not text:
        return "blank"
    if PUNCTUATION.match(text):
        return "punctuation"
    if PREFILL.match(text):
        return "prefill"
    if len(re.sub(r"\s", "", text)) < MIN_CHARS:
        return "short"
    if text in public_text:
        return "public"
    return None


def collect_needles(root):
    """Every worked-solution line of the instructor's tree at ``root`` (see the module doc)."""
    root = Path(root)
    raw, public, needles = [], set(), Needles()
    for folder in ("notebooks", "problem_sets"):
        for path in sorted((root / folder).glob("*.ipynb")):
            inside, outside, regions = _notebook_lines(path)
            raw += inside
            public |= outside
            needles.regions += regions
    for path in sorted((root / "instructor" / "answers").glob("ch[0-9][0-9].py")):
        raw += _solutions_file_lines(path)
    public_text = "\n".join(sorted(public))
    for line, where in raw:
        for i, text in enumerate(_variants(line.strip())):
            reason = _skip_reason(text, public_text)
            if reason:
                if i == 0:
                    needles.skipped[reason] += 1
                continue
            needles.lines.setdefault(text, where)
    return needles


# ------------------------------------------------------------------------------ the scan


def _texts(name, data):
    """The texts of one file to search: as it is, and decoded (HTML tags out, JSON strings)."""
    text = data.decode("utf-8", errors="replace")
    texts = [text]
    if name.endswith((".html", ".htm", ".xml")):
        texts.append(html.unescape(_TAG.sub("", text)))
    elif name.endswith((".ipynb", ".json")):
        try:
            texts.append("\n".join(_strings(json.loads(text))))
        except ValueError:
            pass
    return texts


def _strings(obj):
    if isinstance(obj, str):
        yield obj
    elif isinstance(obj, list):
        for item in obj:
            yield from _strings(item)
    elif isinstance(obj, dict):
        for value in obj.values():
            yield from _strings(value)


def _line_of(text, index):
    start = text.rfind("\n", 0, index) + 1
    end = text.find("\n", index)
    line = text[start : end if end != -1 else len(text)]
    return text.count("\n", 0, index) + 1, line.strip()[:120]


# An answer record (course_lib.record) that the student's check judged right: an executed
# instructor notebook holds one per exercise, the worked answer in sympy's srepr.
RECORD = re.compile(r"application/vnd\.rotations-course\.answer\+json")
RIGHT = "\u2713"  # ✓, the verdict line of a right answer


def _right_records(text):
    """Indices of answer records in ``text`` whose verdict is ✓ (within the same output)."""
    for m in RECORD.finditer(text):
        window = text[m.start() : m.start() + 4000]
        if RIGHT in window or "\\u2713" in window:
            yield m.start()


def _roster(name, data):
    """Whether a file looks like a class roster (instructor/grading/identity.py): a file named
    roster*, or a CSV with a Canvas gradebook's identity header. Students never get one."""
    base = name.replace("\\", "/").rsplit("/", 1)[-1].lower()
    if base.startswith("roster"):
        return True
    head = data[:4096].decode("utf-8", "replace")
    return base.endswith(".csv") and bool(ROSTER_HEADER.search(head))


def scan_data(name, data, needles, report):
    """Search one file's bytes; append a hit per needle or marker found, one per line, and
    one for a class roster."""
    report.bytes += len(data)
    if _roster(name, data):
        report.hits.append(f"{name}: a class roster (students' ids): it stays with the instructor")
    seen = set()
    outputs = name.endswith((".ipynb", ".html"))  # where notebook outputs are stored or shown
    for text in _texts(name, data):
        for index in _right_records(text) if outputs else ():
            number, line = _line_of(text, index)
            report.hits.append(f"{name}:{number}: the record of a right answer: {line}")
        for m in MARKER.finditer(text):
            number, line = _line_of(text, m.start())
            if ("marker", number) not in seen:
                seen.add(("marker", number))
                report.hits.append(f"{name}:{number}: nbgrader marker {m.group(0)!r}: {line}")
        for needle, where in needles.lines.items():
            index = text.find(needle)
            if index != -1 and needle not in seen:
                seen.add(needle)
                number, line = _line_of(text, index)
                report.hits.append(f"{name}:{number}: solution line of {where}: {line}")


def _solution_dir(path_text):
    parts = path_text.replace("\\", "/").split("/")
    return any(p.lower() in SOLUTION_DIRS for p in parts[:-1])


def scan_tree(directory, needles, report, label):
    directory = Path(directory)
    for path in sorted(directory.rglob("*")):
        rel = path.relative_to(directory).as_posix()
        if rel == ".git" or rel.startswith(".git/"):
            continue
        name = f"{label}/{rel}"
        if path.is_dir():
            if path.name.lower() in SOLUTION_DIRS:
                report.hits.append(f"{name}: a solutions folder")
            continue
        if path.is_file():
            report.files += 1
            scan_data(name, path.read_bytes(), needles, report)


def scan_history(repo, needles, report, label):
    """Every blob and commit message ever committed in the git repository ``repo``."""
    git = ["git", "-C", str(repo)]
    objects = subprocess.run(
        [*git, "rev-list", "--all", "--objects"], capture_output=True, text=True, check=True
    ).stdout.splitlines()
    paths = {}
    for line in objects:
        sha, _, path = line.partition(" ")
        if path:
            paths.setdefault(sha, path)
            if any(part.lower() in SOLUTION_DIRS for part in path.split("/")):
                report.hits.append(f"{label} history {sha[:10]} {path}: in a solutions folder")
    batch = subprocess.run(
        [*git, "cat-file", "--batch"],
        input="\n".join(paths).encode() + b"\n",
        capture_output=True,
        check=True,
    ).stdout
    pos = 0
    while pos < len(batch):
        header_end = batch.index(b"\n", pos)
        sha, kind, size = batch[pos:header_end].decode().split()
        data = batch[header_end + 1 : header_end + 1 + int(size)]
        pos = header_end + 1 + int(size) + 1
        if kind == "blob":
            report.blobs += 1
            scan_data(f"{label} history {sha[:10]} {paths[sha]}", data, needles, report)
    messages = subprocess.run(
        [*git, "log", "--all", "--format=%H%n%B"], capture_output=True, check=True
    ).stdout
    scan_data(f"{label} history: commit messages", messages, needles, report)


def scan_wheel(wheel, needles, report):
    with zipfile.ZipFile(wheel) as zf:
        for info in zf.infolist():
            name = f"dist/{Path(wheel).name}!{info.filename}"
            if _solution_dir(info.filename):
                report.hits.append(f"{name}: in a solutions folder")
            report.members += 1
            scan_data(name, zf.read(info), needles, report)


def run_gate(root, student, dist, site):
    """Collect the needles from ``root`` and scan all three products; return (needles, report)."""
    needles = collect_needles(root)
    report = Report()
    scan_tree(student, needles, report, "student")
    scan_history(student, needles, report, "student")
    for wheel in sorted(Path(dist).glob("*.whl")):
        scan_wheel(wheel, needles, report)
    scan_tree(site, needles, report, "site")
    return needles, report


def summary(needles, report):
    skipped = ", ".join(f"{n} {reason}" for reason, n in sorted(needles.skipped.items()))
    return (
        f"leak gate: {len(needles.lines)} solution lines from {needles.regions} solution "
        f"regions and instructor/answers (skipped: {skipped}); scanned {report.files} files, "
        f"{report.blobs} history blobs, {report.members} wheel members, "
        f"{report.bytes / 1e6:.1f} MB: {len(report.hits)} hits"
    )


def main(argv=None):
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 4:
        print("usage: leak_gate.py ROOT STUDENT_DIR DIST_DIR SITE_DIR", file=sys.stderr)
        return 2
    needles, report = run_gate(*args)
    print(summary(needles, report))
    for hit in report.hits[:50]:
        print("  LEAK " + hit)
    return 1 if report.hits else 0


if __name__ == "__main__":
    sys.exit(main())
