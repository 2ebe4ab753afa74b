"""Going back in a chapter never breaks the page: a cell run again prints what it printed.

A reader runs a chapter top to bottom, then scrolls back and runs earlier cells again. Each
chapter is executed once in order and then a second time in the same kernel, after every later
cell has run: every code cell must print the same text (streams, text and LaTeX results, and no
error) both times. A later cell that rebinds a name of an earlier one (as the exercise set-up
once did with ``R``, ``A``, ``W``, ``omega``), or a cell that depends on state left by the cells
after it, fails here with the cell and both outputs. Cells marked NBVAL_IGNORE_OUTPUT (live
widgets, whose model ids change on every run) are compared on their text only.
"""

from pathlib import Path

import nbformat
import pytest

from instructor.build import notebooks as nbtool

ROOT = Path(__file__).resolve().parents[1]

pytestmark = pytest.mark.notebook_exec
CHAPTERS = sorted((ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb"))
TEXT = ("text/plain", "text/latex", "text/markdown")


def printed(cell):
    """What a cell printed, as text: streams, text results, errors (not images or widgets)."""
    out = []
    for o in cell.get("outputs", []):
        if o["output_type"] == "stream":  # chunks of one stream join up (they split by timing)
            if out and out[-1][0] == o["name"]:
                out[-1] = (o["name"], out[-1][1] + o["text"])
            else:
                out.append((o["name"], o["text"]))
        elif o["output_type"] == "error":
            out.append(("error", f"{o['ename']}: {o['evalue']}"))
        elif "application/vnd.jupyter.widget-view+json" not in o.get("data", {}):
            out += [(k, o["data"][k]) for k in TEXT if k in o.get("data", {})]
    return out


def run_twice(path):
    nb = nbformat.read(path, as_version=4)
    client = nbtool._client_class()(
        nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(path.parent)}}
    )
    code = [(i, c) for i, c in enumerate(nb.cells) if c.cell_type == "code"]
    passes = []
    with client.setup_kernel():
        for _ in range(2):
            for i, cell in code:
                cell.outputs = []
                client.execute_cell(cell, i, store_history=True)
            passes.append([printed(c) for _, c in code])
    return [i for i, _ in code], passes


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.name)
def test_every_cell_prints_the_same_when_run_again(path):
    indices, (first, second) = run_twice(path)
    errors = [(i, out) for i, out in zip(indices, first) if any(k == "error" for k, _ in out)]
    assert not errors, f"{path.name}: cells that fail on the first run: {errors}"
    changed = [(i, a, b) for i, a, b in zip(indices, first, second) if a != b]
    assert not changed, "\n".join(
        f"{path.name} cell {i}: first run {a!r}\n  run again {b!r}" for i, a, b in changed
    )
