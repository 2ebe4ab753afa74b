"""CSV cells that a spreadsheet never reads as a formula (OWASP, "CSV Injection").

A cell that begins with ``=``, ``+``, ``-``, ``@``, a tab or a carriage return is a formula to
Excel, LibreOffice and Google Sheets (``=HYPERLINK(...)``, ``@SUM(...)``, ``-2+3+cmd|...``).
Student names, ids and sections come from the student or the roster, so every CSV the grader
writes goes through :func:`neutralise`: such a cell gets a leading single quote, which the
spreadsheet shows as text and does not evaluate, as OWASP's guidance says; the ``csv`` module
then quotes the cell and doubles any ``"`` in it. A plain number (a score, ``-1.5``) is left as
it is, so scores stay numbers and Canvas's import reads them.

Examples
--------
>>> neutralise('=HYPERLINK("http://x","y")')
'\\'=HYPERLINK("http://x","y")'
>>> [neutralise(v) for v in ("-1.5", "12", "@SUM(A1)", "Ada", 3.0)]
['-1.5', '12', "'@SUM(A1)", 'Ada', '3.0']
"""

from __future__ import annotations

import csv
import re
from pathlib import Path

__all__ = ["FORMULA_START", "neutralise", "write_rows"]

#: The first characters that make a spreadsheet read a cell as a formula.
FORMULA_START = ("=", "+", "-", "@", "\t", "\r")
_NUMBER = re.compile(r"[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?\Z")


def neutralise(value):
    """``value`` as CSV text that no spreadsheet evaluates (see the module's docstring)."""
    text = "" if value is None else str(value)
    if text.startswith(FORMULA_START) and not _NUMBER.match(text):
        return "'" + text
    return text


def write_rows(path, rows):
    """Write ``rows`` (lists of cells) to ``path`` as UTF-8 CSV, every cell neutralised and
    every cell quoted; returns the path."""
    with open(path, "w", newline="", encoding="utf-8") as f:
        writer = csv.writer(f, quoting=csv.QUOTE_MINIMAL)
        for row in rows:
            writer.writerow([neutralise(cell) for cell in row])
    return Path(path)
