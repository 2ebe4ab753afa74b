"""Build the course website in build/site/ (``make site``; ``make site SOLUTIONS=1``).

1. The pages come from the student copies (``python -m course_lib.student``: solutions
   replaced by stubs), or with ``--solutions`` from ``notebooks/`` as they are (instructors).
2. Each chapter is prepared: the setup cell is dropped (the site needs no set-up), a line of
   launch links is put under the title, stub and check cells are tagged ``raises-exception`` and
   ``remove-output`` so that executing does not stop on them and shows no traceback.
3. Each chapter is executed and cleaned by tools/notebooks.py (no stall after widget cells,
   palette PNGs); widget views are dropped (without a kernel a slider moves nothing; the
   figure of its first position stays) and every figure gets alt text: the first sentence of
   the markdown cell under it, the notebooks' one-line figure description.
4. Sphinx + myst-nb render the pages offline: MathJax comes from the npm package installed in
   build/site-deps/, copied into the site's ``_static/``; so do the icons of matplotlib's
   animation player (Font Awesome, which it links from a CDN).
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

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))

import course_links  # noqa: E402
import notebooks as nbtool  # noqa: E402

BUILD = ROOT / "build"
SRC, OUT, DEPS = BUILD / "site-src", BUILD / "site", BUILD / "site-deps"
# npm packages served from the site itself: MathJax, and the icons of matplotlib's animation
# player (which links them from a CDN).
MATHJAX, FONT_AWESOME = "mathjax@3.2.2", "font-awesome@4.7.0"
FA_CDN = "https://maxcdn.bootstrapcdn.com/font-awesome/4.4.0/css/font-awesome.min.css"
FA_LOCAL = "_static/font-awesome/css/font-awesome.min.css"
STUB = "raise NotImplementedError("


def install_scripts():
    """MathJax's es5 bundle and Font Awesome from npm, in build/site-deps/static/."""
    modules = DEPS / "node_modules"
    if not (modules / "mathjax" / "es5" / "tex-chtml.js").is_file() or \
            not (modules / "font-awesome" / "css").is_dir():
        subprocess.run(["npm", "install", "--no-save", "--no-audit", "--no-fund",
                        "--prefix", str(DEPS), MATHJAX, FONT_AWESOME], check=True)
    static = DEPS / "static"
    shutil.rmtree(static, ignore_errors=True)
    shutil.copytree(modules / "mathjax" / "es5", static / "mathjax")
    for part in ("css", "fonts"):
        shutil.copytree(modules / "font-awesome" / part, static / "font-awesome" / part)
    return static


def source_notebooks(solutions):
    """Copy the chapters (student copies unless ``solutions``) to build/site-src/."""
    shutil.rmtree(SRC, ignore_errors=True)
    SRC.mkdir(parents=True)
    if solutions:
        for path in sorted((ROOT / "notebooks").glob("[0-9]*.ipynb")):
            shutil.copy(path, SRC / path.name)
    else:
        subprocess.run([sys.executable, "-m", "course_lib.student", str(ROOT / "notebooks"),
                        str(SRC), "--force"], check=True, cwd=ROOT)
    return sorted(SRC.glob("[0-9]*.ipynb"))


def launch_line(url, name):
    if url is None:
        return f"*Run this chapter yourself: launch links are {course_links.UNSET}.*"
    links = [f"[Binder]({course_links.binder_url(url)})"]
    colab = course_links.colab_url(url, name)
    if colab:
        links.append(f"[Colab]({colab})")
    return "*Run this chapter yourself:* " + " · ".join(links)


def _alt_text(cells, i):
    for cell in cells[i + 1:i + 3]:
        if cell.cell_type == "markdown" and cell.source.strip():
            text = re.sub(r"[*_`$\\#>]", "", cell.source.strip().split("\n\n")[0])
            return " ".join(text.split())[:200]
    return "Figure"


def prepare(nb, name, url):
    nb.cells = [c for c in nb.cells if c.get("id") != nbtool.SETUP_ID]
    nb.cells.insert(1, nbformat.v4.new_markdown_cell(launch_line(url, name)))
    for cell in nb.cells:
        # a stub raises, and so does the check cell after it (an nbgrader test cell)
        graded = cell.metadata.get("nbgrader", {}).get("grade", False)
        if cell.cell_type == "code" and (STUB in cell.source or graded):
            tags = cell.metadata.setdefault("tags", [])
            tags += [t for t in ("raises-exception", "remove-output") if t not in tags]
    return nb


def finish(nb):
    """Drop widget views, give every figure alt text, clean."""
    for i, cell in enumerate(nb.cells):
        outputs = cell.get("outputs", [])
        cell.outputs = [o for o in outputs if nbtool.WIDGET_VIEW not in o.get("data", {})]
        for output in cell.outputs:
            html = output.get("data", {}).get("text/html")
            if html:
                output["data"]["text/html"] = "".join(html).replace(FA_CDN, FA_LOCAL)
        if any("image/png" in o.get("data", {}) for o in cell.outputs):
            cell.metadata["mystnb"] = {"image": {"alt": _alt_text(nb.cells, i)}}
    return nbtool.clean(nb)


def write_index(names, solutions, url):
    edition = ("**Instructor edition**: the worked solutions are shown." if solutions else
               "Student edition: the exercises are left for you to solve.")
    toc = "\n".join(Path(n).stem for n in names)
    launch = (f"[Launch the course on Binder]({course_links.binder_url(url)})" if url
              else f"Launch links are {course_links.UNSET}.")
    (SRC / "index.md").write_text(f"""# Rigid-body rotations

Notebooks for an introductory robotics course: rigid bodies, rotation matrices, exponential
coordinates, each chapter with a sympy proof, a numeric check and a figure for every result.

{edition} {launch}

```{{toctree}}
:maxdepth: 1

{toc}
```
""", encoding="utf-8")


def main(argv=None):
    parser = argparse.ArgumentParser(description="Build the course website in build/site/.")
    parser.add_argument("--solutions", action="store_true", help="instructor edition")
    args = parser.parse_args(argv)
    url = course_links.repository_url()
    static = install_scripts()
    paths = source_notebooks(args.solutions)
    for path in paths:
        nb = prepare(nbformat.read(path, as_version=4), path.name, url)
        seconds = nbtool.execute(nb, ROOT / "notebooks")
        nbformat.write(finish(nb), path)
        print(f"{path.name}: executed in {seconds:.1f} s")
    write_index([p.name for p in paths], args.solutions, url)
    shutil.copy(Path(__file__).with_name("conf.py"), SRC / "conf.py")
    shutil.rmtree(OUT, ignore_errors=True)
    env = {**os.environ, "COURSE_SITE_STATIC": str(static)}
    subprocess.run([sys.executable, "-m", "sphinx", "-b", "html", "-q", "-W", "--keep-going",
                    str(SRC), str(OUT)], check=True, env=env)
    print(f"site: {OUT / 'index.html'}" + (" (instructor edition)" if args.solutions else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
