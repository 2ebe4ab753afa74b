"""Every figure of the course read for colour (WCAG 1.4.1, 1.4.3, 1.4.11), chapter cells included.

    python -m instructor.build.figure_audit [NOTEBOOK ...]   (default: notebooks/ and problem_sets/)

Each notebook is run (a copy, instructor/build/notebooks.py's kernel) with ``plotting.show``
audited: every figure it shows is read artist by artist before it becomes a PNG, and
:func:`figure_problems` says what a reader with a colour-vision deficiency, or with low contrast
sensitivity, would miss:

* a line, arrow or marker below 3:1 on its axes' background (1.4.11), a text below 4.5:1 (1.4.3);
* two series (lines, arrows, markers) with the same line style and marker whose colours are
  apart for normal vision but merge (CIE76 ΔE below :data:`MERGED`) once simulated for
  protanopia, deuteranopia or tritanopia (Machado, Oliveira & Fernandes 2009, severity 1.0, on
  linear RGB): colour alone would tell them apart (1.4.1).

Fills (alpha below 0.6), decoration behind the data (zorder 0 or below: the course's zero lines)
and artists without data are not judged. Prints one line per problem and exits 1 if any.
"""

import argparse
import contextlib
import itertools
import json
import os
import sys
import tempfile
from pathlib import Path

import matplotlib.colors as mc
import nbformat
import numpy as np

ROOT = Path(__file__).resolve().parents[2]

# Machado et al. 2009, Table 1, severity 1.0, acting on linear RGB.
MACHADO = {
    "protanopia": np.array(
        [[0.152286, 1.052583, -0.204868], [0.114503, 0.786281, 0.099216],
         [-0.003882, -0.048116, 1.051998]]
    ),
    "deuteranopia": np.array(
        [[0.367322, 0.860646, -0.227968], [0.280085, 0.672501, 0.047413],
         [-0.011820, 0.042940, 0.968881]]
    ),
    "tritanopia": np.array(
        [[1.255528, -0.076749, -0.178779], [-0.078411, 0.930809, 0.147602],
         [0.004733, 0.691367, 0.303900]]
    ),
}  # fmt: skip
#: CIE76 ΔE below which two colours read as one (about 2.3 is "just noticeable").
MERGED = 12.0
LINE_CONTRAST, TEXT_CONTRAST = 3.0, 4.5
FILL_ALPHA = 0.6


def linear(rgb):
    rgb = np.asarray(rgb, dtype=float)
    return np.where(rgb <= 0.04045, rgb / 12.92, ((rgb + 0.055) / 1.055) ** 2.4)


def simulate(rgb, kind):
    """``rgb`` (sRGB in [0, 1]) as seen with the deficiency ``kind`` (a key of MACHADO)."""
    lin = np.clip(linear(rgb) @ MACHADO[kind].T, 0.0, 1.0)
    return np.where(lin <= 0.0031308, 12.92 * lin, 1.055 * lin ** (1 / 2.4) - 0.055)


def lab(rgb):
    m = np.array([[0.4124, 0.3576, 0.1805], [0.2126, 0.7152, 0.0722], [0.0193, 0.1192, 0.9505]])
    xyz = linear(rgb) @ m.T / np.array([0.95047, 1.0, 1.08883])
    f = np.where(xyz > 0.008856, np.cbrt(xyz), 7.787 * xyz + 16 / 116)
    return np.stack([116 * f[..., 1] - 16, 500 * (f[..., 0] - f[..., 1]),
                     200 * (f[..., 1] - f[..., 2])], axis=-1)  # fmt: skip


def delta_e(a, b):
    """CIE76 distance of two sRGB colours."""
    return float(np.linalg.norm(lab(a) - lab(b)))


def contrast(a, b):
    """WCAG contrast ratio of two sRGB colours (1 to 21)."""
    la, lb = sorted(float(linear(c) @ [0.2126, 0.7152, 0.0722]) for c in (a, b))
    return (lb + 0.05) / (la + 0.05)


def _on(rgba, bg, alpha=None):
    """(colour as drawn on ``bg``, its alpha)."""
    r, g, b, a = mc.to_rgba(rgba)
    a = a if alpha is None else alpha
    return tuple(a * np.array([r, g, b]) + (1 - a) * np.asarray(bg)), a


def _series(ax, bg):
    """(name, drawn colour, alpha, style) of each line, arrow and marker set of ``ax``."""
    out = []
    for line in ax.get_lines():
        if line.get_zorder() <= 0 or not line.get_visible() or len(line.get_xdata()) == 0:
            continue
        colour, a = _on(line.get_color(), bg, line.get_alpha())
        out.append(
            (
                f"line {line.get_label()!r}",
                colour,
                a,
                (line.get_linestyle(), str(line.get_marker())),
            )
        )
    for patch in ax.patches:
        if type(patch).__name__ == "Arrow" and patch.get_visible():
            colour, a = _on(patch.get_edgecolor(), bg, patch.get_alpha())
            out.append(("arrow", colour, a, (str(patch.get_linestyle()), "arrow")))
    for coll in ax.collections:
        if type(coll).__name__ in ("PathCollection", "Path3DCollection") and coll.get_visible():
            faces = coll.get_facecolor()
            if len(faces):
                colour, a = _on(faces[0], bg, coll.get_alpha())
                out.append(("markers", colour, a, ("markers", str(coll.get_paths()[0])[:40])))
    return out


def _texts(ax):
    texts = [*ax.texts, ax.title, ax._left_title, ax._right_title]
    texts += [ax.xaxis.label, ax.yaxis.label, *ax.get_xticklabels(), *ax.get_yticklabels()]
    if hasattr(ax, "zaxis"):
        texts += [ax.zaxis.label, *ax.get_zticklabels()]
    legend = ax.get_legend()
    if legend is not None:
        texts += list(legend.get_texts())
    return [t for t in texts if t.get_visible() and t.get_text().strip()]


def figure_problems(fig):
    """What a figure shows by colour alone or with too little contrast (see the module doc).

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> fig = Figure()
    >>> ax = fig.add_subplot()
    >>> _ = ax.plot([0, 1], [0, 1], color="tab:red", label="a")
    >>> _ = ax.plot([0, 1], [1, 0], color="tab:green", label="b")
    >>> figure_problems(fig)  # doctest: +NORMALIZE_WHITESPACE
    ["axes 1: line 'a' and line 'b' differ by colour alone and merge under deuteranopia
      (ΔE 7.3)"]
    """
    out = []
    for k, ax in enumerate(fig.axes, start=1):
        if not ax.get_visible():
            continue
        bg = mc.to_rgb(ax.get_facecolor())
        series = _series(ax, bg)
        for name, colour, a, _ in series:
            c = contrast(colour, bg)
            if a >= FILL_ALPHA and c < LINE_CONTRAST:
                out.append(f"axes {k}: {name} {mc.to_hex(colour)} is {c:.2f}:1 (3:1 needed)")
        for text in _texts(ax):
            colour, _ = _on(text.get_color(), bg, text.get_alpha())
            c = contrast(colour, bg)
            if c < TEXT_CONTRAST:
                out.append(
                    f"axes {k}: text {text.get_text()[:30]!r} {mc.to_hex(colour)} is {c:.2f}:1 "
                    "(4.5:1 needed)"
                )
        out += _merged(k, [s for s in series if s[2] >= FILL_ALPHA])
    return out


def _merged(k, series):
    out, seen = [], set()
    for (n1, c1, _, s1), (n2, c2, _, s2) in itertools.combinations(series, 2):
        if s1 != s2 or delta_e(c1, c2) < MERGED:
            continue  # told apart by style, or the same colour (one series drawn in parts)
        for kind in MACHADO:
            d = delta_e(simulate(c1, kind), simulate(c2, kind))
            key = (mc.to_hex(c1), mc.to_hex(c2), s1, kind)
            if d < MERGED and key not in seen:
                seen.add(key)
                out.append(
                    f"axes {k}: {n1} and {n2} differ by colour alone and merge under {kind} "
                    f"(ΔE {d:.1f})"
                )
    return out


_HOOK = """
import json as _json, os as _os
import course_lib.plotting.display as _display
from instructor.build.figure_audit import figure_problems as _problems
_figure_output = _display.figure_output
def _audited(fig, alt):
    with open(_os.environ["COURSE_FIGURE_AUDIT"], "a", encoding="utf-8") as _f:
        _f.write(_json.dumps({"alt": alt[:70], "problems": _problems(fig)}) + "\\n")
    return _figure_output(fig, alt)
_display.figure_output = _audited
"""


def audit(path):
    """[(figure alt text, problems)] of every figure the notebook at ``path`` shows."""
    from instructor.build import notebooks as nbtool

    nb = nbformat.read(path, as_version=4)
    nbtool.put_setup_cell(nb, None)
    nb.cells.insert(1, nbformat.v4.new_code_cell(_HOOK))
    for cell in nb.cells:  # the stubs of a problem set raise: go on
        cell.metadata.setdefault("tags", []).append("raises-exception")
    with tempfile.TemporaryDirectory() as tmp:
        log = Path(tmp) / "audit.jsonl"
        log.touch()
        # the kernel imports this module from the repository (it runs in the notebook's folder)
        with _env(COURSE_FIGURE_AUDIT=str(log), PYTHONPATH=str(ROOT)):
            nbtool.execute(nb, path.parent)
        rows = [json.loads(line) for line in log.read_text(encoding="utf-8").splitlines()]
    return [(r["alt"], r["problems"]) for r in rows]


@contextlib.contextmanager
def _env(**values):
    old = {k: os.environ.get(k) for k in values}
    os.environ.update(values)
    try:
        yield
    finally:
        for k, v in old.items():
            os.environ.pop(k) if v is None else os.environ.__setitem__(k, v)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("notebooks", nargs="*", type=Path)
    args = parser.parse_args(argv)
    paths = args.notebooks or sorted(
        p for d in ("notebooks", "problem_sets") for p in (ROOT / d).glob("[0-9a-z]*.ipynb")
    )
    bad = 0
    for path in paths:
        figures = audit(path)
        problems = [(alt, p) for alt, ps in figures for p in ps]
        print(f"{path.name}: {len(figures)} figures, {len(problems)} problem(s)")
        for alt, p in problems:
            print(f"  {alt!r}: {p}")
        bad += len(problems)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
