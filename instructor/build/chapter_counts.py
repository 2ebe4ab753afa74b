"""What a reader has on screen in each chapter, against the targets a chapter must keep.

    python -m instructor.build.chapter_counts                 # every chapter in notebooks/
    python -m instructor.build.chapter_counts notebooks/01_rigid_body_motion.ipynb

"On screen" is what JupyterLab shows when a chapter opens: every cell except those under a
folded heading (a Markdown heading with ``"jp-MarkdownHeadingCollapsed": true`` in its cell
metadata folds every cell up to the next heading of the same or a higher level: the "Going
deeper" parts), and no source of a cell whose input is hidden (``"jupyter": {"source_hidden":
true}``). For each chapter it prints

- words: whitespace-separated tokens of the Markdown on screen (the way the notes' sections
  are counted: §0.1.1 has 2,057, §0.1.2 5,403, §0.1.3 3,190);
- code lines: non-blank source lines of the code cells on screen;
- longest output: lines of the longest text output on screen;
- notes on the notes: Markdown cells on screen with a "**Note on the notes" paragraph;
- the limits, and "ok" or what is over.

``--minutes`` prints instead an estimate of the reading time of the main path, per ``##``
section (:func:`minutes`; issue 37's goal: one sitting of 60 minutes or less).

Exit status 1 when a chapter is over a limit. Targets: chapters 01-03 at most 1.15 times the
words of their section of the notes; chapters beyond the notes at most 3,500 words; at most 150
lines of code, no output longer than 20 lines, at most 2 notes on the notes.
"""

from __future__ import annotations

import json
import re
import sys
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
# §0.1.1-§0.1.3 have 2,057, 5,403 and 3,190 words (whitespace-separated tokens); a chapter may
# have about 1.15 times its section's words on screen.
MAX_WORDS = {1: 2360, 2: 6200, 3: 3660}
WORDS_BEYOND_NOTES = 3500
MAX_CODE_LINES = 150
MAX_OUTPUT_LINES = 20
MAX_NOTES_ON_NOTES = 2
FOLD = "jp-MarkdownHeadingCollapsed"
HEADING = re.compile(r"^(#{1,6})\s", re.M)


@dataclass
class Counts:
    name: str
    words: int
    code_lines: int
    longest_output: int
    notes_on_notes: int
    folded_cells: int

    @property
    def chapter(self):
        return int(self.name[:2])

    def limits(self):
        return {
            "words": MAX_WORDS.get(self.chapter, WORDS_BEYOND_NOTES),
            "code_lines": MAX_CODE_LINES,
            "longest_output": MAX_OUTPUT_LINES,
            "notes_on_notes": MAX_NOTES_ON_NOTES,
        }

    def over(self):
        return {k: (getattr(self, k), v) for k, v in self.limits().items() if getattr(self, k) > v}


def _level(cell):
    """The level of the first heading of a Markdown cell (1-6), or None."""
    m = HEADING.search(_source(cell)) if cell["cell_type"] == "markdown" else None
    return len(m.group(1)) if m else None


def _source(cell):
    src = cell.get("source", "")
    return "".join(src) if isinstance(src, list) else src


def on_screen(cells):
    """The cells JupyterLab shows on opening: those under no folded heading."""
    shown, fold = [], None  # fold: the level of the folded heading we are under
    for cell in cells:
        level = _level(cell)
        if fold is not None and level is not None and level <= fold:
            fold = None
        if fold is None:
            shown.append(cell)
            if level is not None and cell.get("metadata", {}).get(FOLD):
                fold = level
    return shown


def _output_lines(output):
    if output.get("output_type") == "stream":
        text = output.get("text", "")
    else:
        data = output.get("data", {})
        text = data.get("text/plain", "") if "image/png" not in data else ""
        if "text/latex" in data or "text/markdown" in data:
            text = ""  # typeset math or Markdown: one display, counted by its words elsewhere
    text = "".join(text) if isinstance(text, list) else text
    return len(text.rstrip("\n").split("\n")) if text.strip() else 0


def count(path):
    """The :class:`Counts` of the chapter notebook at ``path``."""
    cells = json.loads(Path(path).read_text(encoding="utf-8"))["cells"]
    shown = on_screen(cells)
    markdown = [_source(c) for c in shown if c["cell_type"] == "markdown"]
    code = [
        c
        for c in shown
        if c["cell_type"] == "code"
        and not c.get("metadata", {}).get("jupyter", {}).get("source_hidden")
    ]
    outputs = [o for c in shown if c["cell_type"] == "code" for o in c.get("outputs", [])]
    return Counts(
        name=Path(path).name,
        words=sum(len(m.split()) for m in markdown),
        code_lines=sum(1 for c in code for line in _source(c).split("\n") if line.strip()),
        longest_output=max((_output_lines(o) for o in outputs), default=0),
        notes_on_notes=sum("**Note on the notes" in m for m in markdown),
        folded_cells=len(cells) - len(shown),
    )


#: The reading-time model of :func:`minutes`: rendered words per minute of maths prose, and
#: minutes per display equation, code cell (run it, read its output), code line on screen,
#: figure and live widget. Calibrated on issue 37's reader, who took 60-75 min for chapter 03
#: and 55-70 for chapter 05 as they were then: the model gives 67 and 60.
READING_MODEL = {"wpm": 140, "display": 0.6, "cell": 0.5, "line": 0.12, "figure": 1.5, "widget": 3}
_DISPLAY = re.compile(r"\$\$.*?\$\$", re.S)
_INLINE = re.compile(r"\$[^$]+\$")


def _section_minutes(sec):
    m = READING_MODEL
    return (
        sec["words"] / m["wpm"]
        + m["display"] * sec["displays"]
        + m["cell"] * sec["cells"]
        + m["line"] * sec["lines"]
        + m["figure"] * sec["figures"]
        + m["widget"] * sec["widgets"]
    )


def minutes(path):
    """The estimated reading time of the main path of a chapter, per ``##`` section.

    The cells on screen (:func:`on_screen`; the setup cell left out) are grouped under the
    level-1 and level-2 headings. A section counts rendered words (a display equation is timed
    on its own, an inline formula is one word), display equations, code cells, code lines on
    screen, figures (a ``plotting.show`` call) and widgets (an ``explorer(`` or
    ``animation(`` call); :data:`READING_MODEL` turns them into minutes.

    Returns
    -------
    list of (str, dict)
        The section's heading and its counts, with ``"minutes"``.
    """
    cells = json.loads(Path(path).read_text(encoding="utf-8"))["cells"]
    sections = []
    for cell in on_screen(cells):
        src = _source(cell)
        if cell.get("id") == "course-setup":
            continue
        heading = re.match(r"^#{1,2}\s+(.*)", src) if cell["cell_type"] == "markdown" else None
        if heading or not sections:
            keys = ("words", "displays", "cells", "lines", "figures", "widgets")
            sections.append((heading.group(1) if heading else "(top)", dict.fromkeys(keys, 0)))
        sec = sections[-1][1]
        if cell["cell_type"] == "markdown":
            sec["displays"] += len(_DISPLAY.findall(src))
            sec["words"] += len(_INLINE.sub(" M ", _DISPLAY.sub(" ", src)).split())
        else:
            hidden = cell.get("metadata", {}).get("jupyter", {}).get("source_hidden")
            sec["cells"] += 1
            sec["lines"] += 0 if hidden else sum(1 for ln in src.split("\n") if ln.strip())
            sec["figures"] += "plotting.show(" in src
            sec["widgets"] += "explorer(" in src or "animation(" in src
    for _, sec in sections:
        sec["minutes"] = _section_minutes(sec)
    return sections


def minutes_report(path):
    """A Markdown table of :func:`minutes`, with the total."""
    rows = ["| section | words | code lines | figures | minutes |", "|---|---|---|---|---|"]
    total = 0.0
    for name, sec in minutes(path):
        total += sec["minutes"]
        shown = sec["figures"] + sec["widgets"]
        rows.append(
            f"| {name} | {sec['words']} | {sec['lines']} | {shown} | {sec['minutes']:.1f} |"
        )
    rows.append(f"| **total** | | | | **{total:.0f}** |")
    return f"{Path(path).name}\n" + "\n".join(rows)


def report(counts):
    lim = counts.limits()
    over = counts.over()
    status = (
        "ok" if not over else "OVER: " + ", ".join(f"{k} {v[0]} > {v[1]}" for k, v in over.items())
    )
    return (
        f"{counts.name}: {counts.words} words (≤ {lim['words']}), {counts.code_lines} code lines "
        f"(≤ {MAX_CODE_LINES}), longest output {counts.longest_output} lines (≤ "
        f"{MAX_OUTPUT_LINES}), {counts.notes_on_notes} notes on the notes (≤ "
        f"{MAX_NOTES_ON_NOTES}), {counts.folded_cells} cells folded: {status}"
    )


def main(argv=None):
    args = list(argv if argv is not None else sys.argv[1:])
    timed = "--minutes" in args
    paths = [Path(p) for p in args if p != "--minutes"]
    paths = paths or sorted((ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb"))
    if timed:
        print("\n\n".join(minutes_report(p) for p in paths))
        return 0
    results = [count(p) for p in paths]
    for c in results:
        print(report(c))
    return 1 if any(c.over() for c in results) else 0


if __name__ == "__main__":
    sys.exit(main())
