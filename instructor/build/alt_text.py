r"""The alt text of a chapter's figure: its caption as plain text a screen reader reads well.

Every figure of a chapter has a caption, the markdown cell under it (``*Figure: ...*``). Its alt
text is that caption's first paragraph with the markdown and the LaTeX turned into plain
Unicode: ``$R_z(60^\circ)$`` reads "Rz(60°)", ``$\frac{\theta}{2}$`` "θ/2", ``$a \times b$``
"a × b". It keeps whole sentences (up to :data:`ALT_LIMIT` characters, at least the first): half
a sentence tells a screen-reader user less than the sighted reader gets. The site
(``instructor/build/website.py``) writes it as the ``alt`` of the figure's image; in the notebook
``plotting.show("...")`` carries the same text, and

    python -m instructor.build.alt_text --apply notebooks/[0-9]*.ipynb

rewrites each ``plotting.show`` call's text from the caption under it (then ``make notebooks``
re-runs the chapters; it does this first). Without ``--apply`` it lists the calls whose text is
not the caption's and exits 1.
"""

from __future__ import annotations

import argparse
import ast
import json
import re
import sys
import textwrap
import unicodedata
from pathlib import Path

import nbformat

__all__ = ["caption_text", "figure_alt", "show_call", "rewrite"]

_SYMBOLS = {
    "theta": "θ", "omega": "ω", "pi": "π", "rho": "ρ", "phi": "φ", "psi": "ψ", "alpha": "α",
    "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "mu": "μ", "sigma": "σ", "tau": "τ",
    "times": " × ", "cdot": " · ", "pm": " ± ", "dots": "…", "ldots": "…", "cdots": "…",
    "circ": "°", "approx": " ≈ ", "le": " ≤ ", "leq": " ≤ ", "ge": " ≥ ", "geq": " ≥ ",
    "neq": " ≠ ", "to": " → ",
    "infty": "∞", "in": "∈", "prime": "′", "quad": " ", "qquad": " ", ",": " ", ";": " ",
    "!": "", " ": " ", "|": "‖", "{": "{", "}": "}", "top": "ᵀ", "mathbb": "", "mathrm": "",
    "mathbf": "", "mathcal": "", "text": "", "operatorname": "", "left": "", "right": "",
    "big": "", "Big": "", "hat": "", "dot": "", "bar": "",
    **{f: f + " " for f in ("cos", "sin", "tan", "exp", "log", "det", "arccos", "arctan", "tr")},
}  # fmt: skip
#: Alt text keeps whole sentences of the caption up to this many characters (the caption, shown
#: under the figure, says the rest): a screen reader reads the alt, then the caption.
ALT_LIMIT = 300
_ACCENTS = {"hat": "\u0302", "dot": "\u0307", "bar": "\u0304"}  # combining marks
_SUPERSCRIPT = str.maketrans("0123456789-+()nT", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺⁽⁾ⁿᵀ")
_GROUP = r"(\{(?:[^{}]|\{[^{}]*\})*\}|\\[A-Za-z]+|[^\s{}\\])"  # {...}, \macro or one character


def _ungroup(arg):
    return arg[1:-1] if arg.startswith("{") and arg.endswith("}") else arg


def _math(tex):
    """One math span as plain text (the macros the course's captions use)."""
    tex = re.sub(rf"\\frac\s*{_GROUP}\s*{_GROUP}", lambda m: _frac(*m.groups()), tex)
    tex = re.sub(rf"\\sqrt\s*{_GROUP}", lambda m: "√" + _math(_ungroup(m.group(1))), tex)
    tex = re.sub(r"\\operatorname\s*\{([^{}]*)\}", r"\1 ", tex)
    for name, mark in _ACCENTS.items():  # \hat a -> â, \dot{\theta} -> θ̇
        accent = lambda m, k=mark: _math(_ungroup(m[1])) + k  # noqa: E731
        tex = re.sub(rf"\\{name}(?![A-Za-z])\s*{_GROUP}", accent, tex)
    tex = re.sub(r"\^\s*\\circ", "°", tex)
    tex = re.sub(rf"\^\s*{_GROUP}", lambda m: _power(_ungroup(m.group(1))), tex)
    tex = re.sub(rf"_\s*{_GROUP}", lambda m: _math(_ungroup(m.group(1))), tex)
    tex = re.sub(r"\\([A-Za-z]+|.)", lambda m: _SYMBOLS.get(m.group(1), m.group(1)), tex)
    return re.sub(r"[{}]", "", tex).replace("'", "′")


def _frac(num, den):
    num, den = _math(_ungroup(num)), _math(_ungroup(den))
    wrap = lambda s: f"({s})" if re.search(r"[\s+−-]", s.strip()) else s.strip()  # noqa: E731
    return f"{wrap(num)}/{wrap(den)}"


def _power(exponent):
    text = _math(exponent).replace("−", "-")
    if re.fullmatch(r"[0-9+\-()nT]+", text):
        return text.translate(_SUPERSCRIPT)
    return "^" + (text if len(text) == 1 else f"({text})")


def caption_text(markdown):
    r"""The first paragraph of ``markdown`` that is not a heading, as plain text.

    Examples
    --------
    >>> caption_text(r"*Figure: $R = R_z(60^\circ)$, and $w = \cos\frac{\theta}{2}$.*")
    'Figure: R = Rz(60°), and w = cos θ/2.'
    >>> caption_text(r"*Figure: $\hat a b = a \times b$, slope $N^{-4}$, $\sqrt{2}$.*")
    'Figure: â b = a × b, slope N⁻⁴, √2.'
    >>> caption_text("## A heading") is None
    True
    """
    paragraphs = [p for p in markdown.strip().split("\n\n") if p.strip()]
    paragraphs = [p for p in paragraphs if not p.lstrip().startswith("#")]
    if not paragraphs:
        return None
    parts = re.split(r"(\$\$.+?\$\$|\$.+?\$)", paragraphs[0], flags=re.S)
    text = "".join(_math(p.strip("$")) if p.startswith("$") else p for p in parts)
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)  # a link: its text
    text = re.sub(r"(?<!\w)[*_`]+|[*_`]+(?!\w)|^>\s*", "", text)
    return _whole_sentences(unicodedata.normalize("NFC", " ".join(text.split()))) or None


def _whole_sentences(text, limit=ALT_LIMIT):
    """The first sentences of ``text`` that fit in ``limit`` characters (at least one)."""
    sentences = re.split(r"(?<=[.!?])\s+(?=[A-Z(])", text)
    kept = sentences[:1]
    for sentence in sentences[1:]:
        if len(" ".join([*kept, sentence])) > limit:
            break
        kept.append(sentence)
    return " ".join(kept)


def figure_alt(cells, i):
    """The alt text of the figure of cell ``i``: the caption under it (the first paragraph of
    the next markdown cell, when it is not a new section), else the text that introduces it
    (the markdown cell before, e.g. an explorer's "Explore" section), else "Figure" (which
    tests/test_a11y_rules.py rejects)."""
    for cell in cells[i + 1 : i + 3]:
        if cell.cell_type == "markdown" and cell.source.strip():
            if not cell.source.lstrip().startswith("#"):
                return caption_text(cell.source)
            break
    if i > 0 and cells[i - 1].cell_type == "markdown":
        text = caption_text(cells[i - 1].source)
        if text:
            return text
    return "Figure"


#: How the chapters call :func:`course_lib.plotting.show` (chapter 01 imports plotting as plot).
SHOW_CALLS = ("plotting.show", "plot.show")


def show_call(source):
    """The ``plotting.show(...)`` call of a code cell: ``(start, end, alt)``, or None.

    ``start`` and ``end`` are offsets into ``source`` (ast counts columns in UTF-8 bytes).
    """
    if not any(f"{name}(" in source for name in SHOW_CALLS):
        return None
    lines = source.encode().splitlines(keepends=True)

    def offset(line, col):
        return len(b"".join(lines[: line - 1]).decode()) + len(lines[line - 1][:col].decode())

    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Call) and ast.unparse(node.func) in SHOW_CALLS:
            alt = node.args[0].value if node.args else None
            start = offset(node.lineno, node.col_offset)
            return start, offset(node.end_lineno, node.end_col_offset), alt
    return None


def _call(function, alt, width=96):
    chunks = textwrap.wrap(alt, width - 6, drop_whitespace=False, break_on_hyphens=False)
    body = "".join(f"    {json.dumps(chunk, ensure_ascii=False)}\n" for chunk in chunks)
    return f"{function}(\n{body})"


def rewrite(nb):
    """Give every ``plotting.show`` call of ``nb`` its figure's caption; the cells changed."""
    changed = []
    for i, cell in enumerate(nb.cells):
        call = cell.cell_type == "code" and show_call(cell.source)
        if call and call[2] != figure_alt(nb.cells, i):
            start, end, _ = call
            function = cell.source[start : cell.source.index("(", start)]
            new = _call(function, figure_alt(nb.cells, i))
            cell.source = cell.source[:start] + new + cell.source[end:]
            changed.append(i)
    return changed


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("paths", nargs="+", type=Path)
    parser.add_argument("--apply", action="store_true", help="rewrite the calls (else: check)")
    args = parser.parse_args(argv)
    stale = 0
    for path in args.paths:
        nb = nbformat.read(path, as_version=4)
        changed = rewrite(nb)
        stale += len(changed)
        for i in changed:
            print(f"{path.name}: cell {i}: plotting.show's text is not the caption under it")
        if args.apply and changed:
            nbformat.write(nb, path)
    return 1 if stale and not args.apply else 0


if __name__ == "__main__":
    sys.exit(main())
