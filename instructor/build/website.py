"""Build the course website (``make site``; ``make site SOLUTIONS=1``; ``make release``).

    python -m instructor.build.website [--solutions] [--from DIR] [--out DIR]

1. The pages: the chapters (``notebooks/``) and the problem sets (``problem_sets/``, when there).
   By default their student copies (``instructor.build.student``: solutions replaced by stubs) into
   ``build/site/``; ``--from DIR`` takes them as they are from a student edition (``make
   release``: ``build/release/student``); ``--solutions`` takes the instructor's notebooks as
   they are and writes to ``build/site-instructor/`` (never over the student site), with a
   banner on every page.
2. Each notebook is prepared: the setup cell is dropped (the site needs no set-up), a line of
   launch links is put under the title, stub and check cells are tagged ``raises-exception`` and
   ``remove-output`` so that executing does not stop on them and shows no traceback.
3. Each notebook is executed and cleaned by instructor/build/notebooks.py (no stall after widget
cells,
   palette PNGs). An explorer's output keeps its still picture (the widget view goes: without a
   kernel no slider moves anything) and gets one line under it saying why it is still; every
   figure gets alt text: its caption as plain text (instructor/build/alt_text.py).
4. Sphinx + myst-nb render the pages offline: MathJax comes from the npm package installed in
   build/site-deps/, copied into the site's ``_static/``; site/static/course.css keeps every
   page within the window (wide formulas, code and outputs scroll inside their own box).
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import nbformat

from course_lib.plotting.display import figure_alt_and_png
from instructor.build import course_links
from instructor.build import notebooks as nbtool
from instructor.build.alt_text import figure_alt

ROOT = Path(__file__).resolve().parents[2]
#: The website's own files: Sphinx's conf.py, templates/, static/ (and its browser tests).
HERE = ROOT / "site"

BUILD = ROOT / "build"
DEPS = BUILD / "site-deps"
MATHJAX = "mathjax@3.2.2"
STUB = "raise NotImplementedError("
FOLDERS = ("notebooks", "problem_sets")
SIBLING_LINK = re.compile(r"\]\(\.\./(?:notebooks|problem_sets)/")  # a chapter <-> its problem set
STILL_NOTE = (
    "*A still picture of the explorer: its sliders and the 3D view you turn with the mouse need "
    "a running Jupyter kernel; run this chapter yourself to use them.*"
)


def install_scripts():
    """MathJax's es5 bundle from npm, in build/site-deps/static/, with the site's own CSS."""
    modules = DEPS / "node_modules"
    if not (modules / "mathjax" / "es5" / "tex-chtml.js").is_file():
        if shutil.which("npm") is None:
            raise SystemExit(
                f"make site: npm not found on PATH; the site serves MathJax itself, installed "
                f"once from npm ({MATHJAX}). Install Node.js with npm (Debian/Ubuntu: sudo "
                f"apt-get install npm; macOS: brew install node) and run it again."
            )
        subprocess.run(
            [
                "npm",
                "install",
                "--no-save",
                "--no-audit",
                "--no-fund",
                "--prefix",
                str(DEPS),
                MATHJAX,
            ],
            check=True,
        )
    static = DEPS / "static"
    shutil.rmtree(static, ignore_errors=True)
    shutil.copytree(modules / "mathjax" / "es5", static / "mathjax", ignore=_unused_mathjax)
    for name in ("course.css", "course.js"):
        shutil.copy(HERE / "static" / name, static / name)
    return static


def _unused_mathjax(folder, names):
    """MathJax's other combined bundles and its SVG output: the pages load tex-chtml.js only.

    (17 of its 24 MB; what tex-chtml.js loads on demand, fonts, a11y, sre, ui, is kept.)
    """
    top = Path(folder).name == "es5"
    return [
        n
        for n in names
        if (top and n.endswith(".js") and n != "tex-chtml.js")
        or (Path(folder).name == "output" and n in ("svg", "svg.js"))
    ]


def source_notebooks(src, solutions, student_dir):
    """Copy the chapters and problem sets to ``src`` (see the module docstring, step 1)."""
    shutil.rmtree(src, ignore_errors=True)
    src.mkdir(parents=True)
    base = Path(student_dir) if student_dir else ROOT
    for folder in FOLDERS:
        if not (base / folder).is_dir():
            continue
        if solutions or student_dir:
            for path in sorted((base / folder).glob("[0-9a-z]*.ipynb")):
                shutil.copy(path, src / path.name)
        else:
            subprocess.run(
                [
                    sys.executable,
                    "-m",
                    "instructor.build.student",
                    str(ROOT / folder),
                    str(src),
                    "--force",
                ],
                check=True,
                cwd=ROOT,
            )
    return sorted(src.glob("*.ipynb"))


def launch_line(url, name):
    if url is None:
        return f"*Run this chapter yourself: launch links are {course_links.UNSET}.*"
    links = [f"[Binder]({course_links.binder_url(url)})"]
    colab = course_links.colab_url(url, name)
    if colab:
        links.append(f"[Colab]({colab})")
    return "*Run this chapter yourself:* " + " · ".join(links)


def prepare(nb, name, url):
    nb.cells = [c for c in nb.cells if c.get("id") != nbtool.SETUP_ID]
    nb.cells.insert(1, nbformat.v4.new_markdown_cell(launch_line(url, name)))
    for cell in nb.cells:
        if cell.cell_type == "markdown":  # the site's pages are side by side
            cell.source = SIBLING_LINK.sub("](", cell.source)
        # a stub raises, and so does the check cell after it (an nbgrader test cell)
        graded = cell.metadata.get("nbgrader", {}).get("grade", False)
        if cell.cell_type == "code" and (STUB in cell.source or graded):
            tags = cell.metadata.setdefault("tags", [])
            tags += [t for t in ("raises-exception", "remove-output") if t not in tags]
    return nb


def _is_explorer(output):
    return nbtool.WIDGET_VIEW in output.get("data", {}) or output.get("metadata", {}).get(
        nbtool.EXPLORER_STILL
    )


def _still(output):
    """An explorer's output without its widget view: the PNG stays, then the line saying why.

    Returns (outputs, alt): the still's alt text is what the explorer showed in that state
    (``Explorer.alt_text``), not the text around the cell, which describes the sliders."""
    data = output["data"]
    data.pop(nbtool.WIDGET_VIEW, None)
    found = figure_alt_and_png(_html(data))
    data.pop("text/html", None)
    note = nbformat.v4.new_output("display_data", data={"text/markdown": STILL_NOTE})
    if found is None:
        return ([output, note] if "image/png" in data else [note]), None
    alt, data["image/png"] = found
    data["text/plain"] = alt
    return [output, note], alt


def _html(data):
    html = data.get("text/html")
    return "".join(html) if isinstance(html, list) else html or ""


def _figure_as_png(output):
    """A figure shown by ``plotting.show`` (an HTML <img> with its alt text) as an image/png
    output, as every other figure: Sphinx writes it to ``_images/`` with the same alt text."""
    data = output.get("data", {})
    found = figure_alt_and_png(_html(data))
    if found is None:
        return output
    alt, png = found
    output["data"] = {"image/png": png, "text/plain": alt}
    return output


def finish(nb):
    """Explorers to their still pictures, alt text for every figure, clean."""
    for i, cell in enumerate(nb.cells):
        outputs, alt = [], None
        for output in cell.get("outputs", []):
            if _is_explorer(output):
                still, alt = _still(output)
                outputs += still
            else:
                outputs.append(_figure_as_png(output))
        if "outputs" in cell:
            cell.outputs = outputs
        if any("image/png" in o.get("data", {}) for o in outputs):
            cell.metadata["mystnb"] = {"image": {"alt": alt or figure_alt(nb.cells, i)}}
    return nbtool.clean(nb)


def write_index(src, names, solutions, url):
    edition = (
        "**Instructor edition**: the worked solutions are shown."
        if solutions
        else "Student edition: the exercises are left for you to solve."
    )
    toc = "\n".join(Path(n).stem for n in names)
    launch = (
        f"[Launch the course on Binder]({course_links.binder_url(url)})"
        if url
        else f"Launch links are {course_links.UNSET}."
    )
    (src / "index.md").write_text(
        f"""# Rigid-body rotations

Notebooks for an introductory robotics course: rigid bodies, rotation matrices, exponential
coordinates, each chapter with a sympy proof, a numeric check and a figure for every result.

{edition} {launch}

```{{toctree}}
:maxdepth: 1

{toc}
```
""",
        encoding="utf-8",
    )


def build(solutions=False, student_dir=None, out=None):
    """Build the site; return its folder."""
    edition = "instructor" if solutions else "student"
    out = Path(out) if out else BUILD / ("site-instructor" if solutions else "site")
    src = BUILD / f"site-src-{edition}"
    url = course_links.repository_url()
    static = install_scripts()
    paths = source_notebooks(src, solutions, student_dir)
    cwd = Path(student_dir) / "notebooks" if student_dir else ROOT / "notebooks"
    if student_dir:  # the kernels import the student edition's own course_lib
        os.environ["PYTHONPATH"] = os.pathsep.join(
            [str(Path(student_dir).resolve()), os.environ.get("PYTHONPATH", "")]
        )
    for path in paths:
        nb = prepare(nbformat.read(path, as_version=4), path.name, url)
        seconds = nbtool.execute(nb, cwd, student="(example)" if solutions else None)
        nbformat.write(finish(nb), path)
        print(f"{path.name}: executed in {seconds:.1f} s")
    write_index(src, [p.name for p in paths], solutions, url)
    shutil.copy(HERE / "conf.py", src / "conf.py")
    shutil.copytree(HERE / "templates", src / "_templates", dirs_exist_ok=True)
    shutil.rmtree(out, ignore_errors=True)
    env = {**os.environ, "COURSE_SITE_STATIC": str(static), "COURSE_SITE_EDITION": edition}
    subprocess.run(
        [
            sys.executable,
            "-m",
            "sphinx",
            "-b",
            "html",
            "-q",
            "-W",
            "--keep-going",
            str(src),
            str(out),
        ],
        check=True,
        env=env,
    )
    print(f"site: {out / 'index.html'}" + (" (instructor edition)" if solutions else ""))
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(description="Build the course website.")
    parser.add_argument(
        "--solutions",
        action="store_true",
        help="instructor edition, in build/site-instructor/ with a banner",
    )
    parser.add_argument(
        "--from",
        dest="student_dir",
        metavar="DIR",
        help="take the notebooks of this student edition as they are",
    )
    parser.add_argument("--out", metavar="DIR", help="where the site goes")
    args = parser.parse_args(argv)
    if args.solutions and args.student_dir:
        parser.error("--solutions and --from exclude each other")
    build(args.solutions, args.student_dir, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
