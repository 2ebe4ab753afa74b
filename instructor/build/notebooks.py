"""Execute and clean the course notebooks so that a re-run changes nothing in their JSON.

``make notebooks`` runs ``python -m instructor.build.notebooks --apply notebooks/[0-9]*.ipynb``.
For every notebook, ``--apply``:

1. puts the setup cell first (inserting it, or replacing an older version of it): a no-op where
   ``course_lib`` imports; in a checkout it imports the library from the repository root above
   the notebook; elsewhere (Colab, a notebook on its own) it installs the course with ``%pip``
   from the published address of ``pyproject.toml`` (a repository, or a wheel's URL ending in
   ``.whl``), or, while none is set, says in plain words what a student can do (ask for the
   course link, or open the notebook from the course's hub);
2. executes the notebook in a fresh kernel, in its own folder, without recording timings;
3. cleans it: no widget state, no execution timestamps, no script naming the explorers' slider
   handles (it needs the live widget), widget views without model ids,
   deterministic animation ids, PNGs re-encoded with a 128-colour palette;
4. writes the file only if its text changed, and prints the size and execution time.

``--check`` does steps 1 and 3 in memory without executing and exits 1 if a file would change
(the hygiene tests assert the same properties one by one).

Why executing does not stall after a widget cell: nbclient mimics the Output widget of a
browser (``ipywidgets.interactive`` draws into one) by sending ``comm_msg`` updates to the
kernel on the shell socket, from the coroutine that reads IOPub, while another coroutine
is waiting on the same socket for the next ``execute_reply``. The send consumes the
edge-triggered wake-up of that socket, so the wait lasts until the cell timeout
(jupyter/nbclient#312). Here the mimic is switched off: a widget's initial output is then
recorded as ordinary cell output (which is also what strict nbval sees), and nothing is ever
sent on the shell socket except ``execute_request``.
"""

from __future__ import annotations

import argparse
import base64
import hashlib
import io
import re
import sys
import time
from pathlib import Path

import nbformat

from instructor.build.course_links import repository_url

SETUP_ID = "course-setup"
WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"
#: Output metadata key of an explorer's stored still picture (its widget view removed).
EXPLORER_STILL = "explorer_still"
#: Output metadata key of the script that names an explorer's slider handles (not stored: it
#: has nothing to name without the live widget; course_lib.interactive.widgets.SLIDER_NAMES).
SLIDER_NAMES = "course_slider_names"
PNG_COLOURS = 128
CELL_TIMEOUT = 300  # seconds; a safety net, never reached (chapters take well under 60 s)
_UUID_HEX = re.compile(r"(?<![0-9a-f])[0-9a-f]{32}(?![0-9a-f])")
_FRAME = re.compile(r'"data:image/png;base64,([A-Za-z0-9+/=\\\n]+)"')

SETUP_TEMPLATE = """\
# Setup, run it first: makes the course library importable (laptop, JupyterHub, Binder, Colab).
import importlib.util
import pathlib
import sys

COURSE_URL = {url}  # [project.urls] of pyproject.toml
if importlib.util.find_spec("course_lib") is None:
    here = pathlib.Path.cwd().resolve()
    roots = [p for p in (here, *here.parents) if (p / "course_lib" / "__init__.py").is_file()]
    if roots:
        sys.path.insert(0, str(roots[0]))
    elif COURSE_URL:  # a wheel's address, or the repository of the student edition
        package = COURSE_URL if COURSE_URL.endswith(".whl") else "git+" + COURSE_URL
        %pip install --quiet {{package}}
    else:
        raise ModuleNotFoundError(
            "This notebook needs the course's own Python library, which is not installed here. "
            "Ask your instructor for the course link and open the notebook from it, "
            "or open it from the course's JupyterHub."
        )
if "google.colab" in sys.modules:  # Colab draws the explorers' ipympl figures only with this
    from google.colab import output

    output.enable_custom_widget_manager()"""


def setup_source(url=None):
    """Source of the setup cell for the repository URL ``url`` (None while unpublished)."""
    return SETUP_TEMPLATE.format(url="None" if url is None else f'"{url}"')


def setup_cell(url=None):
    cell = nbformat.v4.new_code_cell(setup_source(url))
    cell.id = SETUP_ID
    return cell


def put_setup_cell(nb, url=None):
    """Make the setup cell the first cell of ``nb`` (replacing any older copy of it)."""
    current = [c for c in nb.cells if c.get("id") == SETUP_ID and c.source == setup_source(url)]
    nb.cells = [c for c in nb.cells if c.get("id") != SETUP_ID]
    nb.cells.insert(0, current[0] if current else setup_cell(url))
    return nb


# ---------------------------------------------------------------------------------------------
# Cleaning
# ---------------------------------------------------------------------------------------------


def small_png(b64):
    """A PNG (base64) re-encoded with a 128-colour palette, if that is smaller.

    Matplotlib writes 8-bit RGBA truecolour; a figure of lines and text on white has far fewer
    distinct colours, and a palette PNG of it looks the same at 40-45 % of the bytes. Already
    palette-coded images are left as they are, so cleaning twice changes nothing.
    """
    from PIL import Image

    raw = base64.b64decode(b64)
    image = Image.open(io.BytesIO(raw))
    if image.mode == "P":
        return b64
    rgb = Image.new("RGB", image.size, "white")
    rgb.paste(image, mask=image.getchannel("A") if image.mode == "RGBA" else None)
    buf = io.BytesIO()
    rgb.quantize(PNG_COLOURS).save(buf, format="png", optimize=True)
    if buf.tell() >= len(raw):
        return b64
    return base64.b64encode(buf.getvalue()).decode("ascii") + "\n"


def _small_frames(html):
    """The PNG frames of a jshtml animation, each re-encoded by :func:`small_png`."""

    def repl(m):
        b64 = m.group(1).replace("\\\n", "")
        return f'"data:image/png;base64,{small_png(b64).strip()}"'

    return _FRAME.sub(repl, html)


def _stable_ids(html, salt):
    """Replace random 32-hex ids (matplotlib's jshtml player) by ids derived from ``salt``."""
    seen = {}

    def repl(m):
        if m.group(0) not in seen:
            seen[m.group(0)] = hashlib.sha1(f"{salt}:{len(seen)}".encode()).hexdigest()[:32]
        return seen[m.group(0)]

    return _UUID_HEX.sub(repl, html)


def clean_output(output, cell_id):
    data = output.get("data", {})
    if WIDGET_VIEW in data:
        # A view of a widget whose state is not stored can show nothing: JupyterLab prefers the
        # view to the PNG in a trusted notebook, and hides a view whose model is gone. The view
        # goes; the explorer's still PNG and its description stay, marked for the website.
        del data[WIDGET_VIEW]
        output.setdefault("metadata", {})[EXPLORER_STILL] = True
    if "image/png" in data:
        data["image/png"] = small_png(data["image/png"])
    if "text/html" in data:
        html = data["text/html"]
        text = "".join(html) if isinstance(html, list) else html
        if "Animation(" in text:
            data["text/html"] = _stable_ids(_small_frames(text), cell_id)
    return output


def clean(nb):
    """Remove what changes from run to run; return ``nb``."""
    nb.metadata.pop("widgets", None)
    nb.metadata.get("language_info", {}).pop("version", None)
    for cell in nb.cells:
        cell.metadata.pop("execution", None)
        if "outputs" in cell:
            cell.outputs = [o for o in cell.outputs if not o.get("metadata", {}).get(SLIDER_NAMES)]
        for output in cell.get("outputs", []):
            clean_output(output, cell.get("id", ""))
    return nb


def text_of(nb):
    """The notebook as written to disk (nbformat's layout, newline at the end)."""
    return nbformat.writes(nb) + "\n"


# ---------------------------------------------------------------------------------------------
# Execution
# ---------------------------------------------------------------------------------------------


def _client_class():
    from nbclient import NotebookClient

    class Client(NotebookClient):
        """nbclient without the Output-widget mimic (see the module docstring)."""

        def on_comm_open_jupyter_widget(self, msg):
            return None

    return Client


#: The kernel's student id: the course's example numbers (course_lib.exercises._identity),
#: whatever id the instructor's own shell or hub sets, so the stored outputs are the same for all.
EXAMPLE_ID = "(example)"


def _kernel_id(student):
    import os

    for var in ("JUPYTERHUB_USER", "COURSE_GRADER_ID", "COURSE_STUDENT_ID"):
        os.environ.pop(var, None)
    if student:
        os.environ["COURSE_STUDENT_ID"] = student


def execute(nb, cwd, student=EXAMPLE_ID):
    """Run every cell of ``nb`` in a fresh kernel started in ``cwd``, as ``student`` (default
    the example student; None: no id, as a student's page on the site shows it); return the
    seconds."""
    _kernel_id(student)
    client = _client_class()(
        nb,
        timeout=CELL_TIMEOUT,
        record_timing=False,
        store_widget_state=False,
        coalesce_streams=True,
        kernel_name="python3",
        resources={"metadata": {"path": str(cwd)}},
    )
    start = time.monotonic()
    client.execute()
    return time.monotonic() - start


def process(path, url, run=True):
    """(new text, old text, seconds) for the notebook at ``path``."""
    old = path.read_text(encoding="utf-8")
    nb = nbformat.reads(old, as_version=4)
    put_setup_cell(nb, url)
    seconds = execute(nb, path.parent) if run else 0.0
    return text_of(clean(nb)), old, seconds


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument("--apply", action="store_true", help="set up, execute, clean, write")
    mode.add_argument(
        "--check",
        action="store_true",
        help="set up and clean in memory (no execution); exit 1 if a file would change",
    )
    parser.add_argument("notebooks", nargs="+", type=Path)
    args = parser.parse_args(argv)
    url = repository_url()
    changed = []
    for path in args.notebooks:
        new, old, seconds = process(path, url, run=args.apply)
        size = f"{len(old.encode()) / 1e3:.0f} kB -> {len(new.encode()) / 1e3:.0f} kB"
        if args.apply:
            if new != old:
                path.write_text(new, encoding="utf-8")
            print(
                f"{path}: executed in {seconds:.1f} s, {size}, "
                + ("rewritten" if new != old else "unchanged")
            )
        elif new != old:
            changed.append(path)
            print(f"{path}: not clean ({size} after cleaning); run `make notebooks`")
    return 1 if changed else 0


if __name__ == "__main__":
    sys.exit(main())
