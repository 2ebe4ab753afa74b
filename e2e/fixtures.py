"""The browser test's own notebook, written at run time into the lab's temporary tree: folded
"Going deeper" headings (metadata ``"jp-MarkdownHeadingCollapsed": true``, one inside
another), to check that JupyterLab opens them collapsed and that a click shows what they hide,
whether or not the chapters have folds yet.
"""

import json

FOLDS_NOTEBOOK = "e2e_fixtures/folded_headings.ipynb"


def _md(text, folded=False):
    meta = {"jp-MarkdownHeadingCollapsed": True} if folded else {}
    return {"cell_type": "markdown", "metadata": meta, "source": text}


def _code(text):
    return {
        "cell_type": "code",
        "execution_count": None,
        "metadata": {},
        "outputs": [],
        "source": text,
    }


def folds_notebook():
    """The notebook (as a dict): a heading, a fold with a fold inside it, a heading after."""
    cells = [
        _md("# A chapter\n\nThe main flow: $R^\\top R = I$."),
        _code("x = 1"),
        _md("## Going deeper\n\nFolded on opening.", folded=True),
        _md("Under the fold: $\\det R = 1$."),
        _code("print('under the fold', x)"),
        _md("### Deeper still\n\nA fold inside the fold.", folded=True),
        _code("print('under both folds')"),
        _md("## After the fold\n\nShown on opening: the fold ends at this heading."),
        _code("print('after the fold')"),
    ]
    return {
        "cells": cells,
        "metadata": {
            "kernelspec": {"display_name": "Python 3", "language": "python", "name": "python3"},
            "language_info": {"name": "python"},
        },
        "nbformat": 4,
        "nbformat_minor": 5,
    }


def write_fixtures(root):
    """Write the fixture notebooks under ``root``; their paths relative to it."""
    path = root / FOLDS_NOTEBOOK
    path.parent.mkdir(parents=True, exist_ok=True)
    nb = folds_notebook()
    for k, cell in enumerate(nb["cells"]):
        cell["id"] = f"e2e-fold-{k}"
    path.write_text(json.dumps(nb, indent=1))
    return [FOLDS_NOTEBOOK]
