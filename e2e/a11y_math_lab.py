"""Math read as math in JupyterLab (``make a11y`` runs it): WCAG 1.3.1 for the formulas.

    python e2e/a11y_math_lab.py [NOTEBOOK]   (default: notebooks/03_exponential_coordinates.ipynb)

The chapter is opened and run in a real JupyterLab with its defaults (e2e's :class:`run_e2e.Lab`)
and scrolled through so that every cell is rendered; then Chromium's accessibility tree of the
notebook (Playwright's ``aria_snapshot``) is read, as a screen reader gets it. JupyterLab 4's own
MathJax 3 typesets with assistive MathML, so each formula is a ``math`` node: Rodrigues'
formula must be one (with sin, cos, θ and ω), and no math node may read raw LaTeX. Exit status
0 when it holds (the same check as ``site/test_a11y_site.py`` on the website).
"""

import re
import sys
from pathlib import Path

from common import ROOT, CheckFailed, js, log


def math_problems(tree):
    """What is wrong with the math of an accessibility tree (``aria_snapshot`` text)."""
    maths = [line.split("math:", 1)[1] for line in tree.splitlines() if "- math:" in line]
    if len(maths) < 20:
        return [f"only {len(maths)} math node(s): MathJax's assistive MathML is missing"]
    problems = []
    if not [m for m in maths if "sin" in m and "cos" in m and "θ" in m and "ω" in m]:
        problems.append("Rodrigues' formula is not in the accessibility tree as math")
    latex = [m for m in maths if re.search(r"\\[a-zA-Z]+", m)]
    if latex:
        problems.append(f"raw LaTeX read out as math: {latex[:2]}")
    log(f"  {len(maths)} math nodes in the accessibility tree")
    return problems


def main(argv=None):
    from notebook_checks import open_and_run
    from playwright.sync_api import sync_playwright
    from run_e2e import Lab

    argv = sys.argv[1:] if argv is None else argv
    path = Path(argv[0]) if argv else ROOT / "notebooks" / "03_exponential_coordinates.ipynb"
    problems = []
    with sync_playwright() as pw:
        lab = Lab(pw, [path.resolve()], fixtures=False)
        try:
            page = lab.context.new_page()
            open_and_run(page, lab.server, lab.notebooks[0], problems, 240)
            page.evaluate(js("sweep"))
            page.wait_for_timeout(500)
            problems += math_problems(page.locator(".jp-NotebookPanel-notebook").aria_snapshot())
            page.evaluate(js("shutdown_kernel"))
        except CheckFailed as exc:
            problems.append(str(exc))
        finally:
            lab.close()
    for p in problems:
        log(f"FAIL math in JupyterLab: {p}")
    log("math in JupyterLab: " + ("FAILED" if problems else "read as math, Rodrigues' formula too"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
