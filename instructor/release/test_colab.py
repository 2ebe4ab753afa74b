"""A chapter on its own, the way Colab runs it (CI: ``pytest instructor/release/test_colab.py``).

Outside ``make test`` (it builds a venv from PyPI: 3 to 6 minutes on a loaded 2-core machine),
like site/test_site.py; marked ``colab``.

A fresh virtualenv holds only what Colab has by default for the course's purposes (numpy, sympy,
matplotlib, ipykernel, ipywidgets, at the student environment's pins) and is a Jupyter kernel of
its own. One chapter of the student edition is copied alone into an empty folder, with no
course around it, and executed with nbconvert in that kernel:

1. while the course has no published address (``COURSE_URL = None``), the setup cell stops with
   a message in plain words (ask for the course link, or open it from the hub), no README;
2. with the release's wheel as the published address, the setup cell installs the course with
   ``%pip`` (pulling in ipympl), and the chapter runs with no error (but a problem-set stub,
   where a chapter still holds its exercises, and the check cell after it);
3. its problem set, alone the same way, runs up to its stubs (``NotImplementedError``) and
   the check cells of the exercises not yet solved, and fails nowhere else.
"""

import json
import os
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest

from instructor.build import notebooks as nbtool
from instructor.release import make_release, student_edition

ROOT = Path(__file__).resolve().parents[2]

pytestmark = [pytest.mark.colab, pytest.mark.notebook_exec]
COLAB_DEFAULTS = ("numpy", "sympy", "matplotlib", "ipykernel", "ipywidgets")
CHAPTER = "03_exponential_coordinates.ipynb"  # an explorer, the animation
PROBLEM_SET = ROOT / "problem_sets" / "ps03_exponential_coordinates.ipynb"
KERNEL = "colab-like"
STUB = "raise NotImplementedError("


@pytest.fixture(scope="module")
def release(tmp_path_factory):
    out = tmp_path_factory.mktemp("colab-release")
    student_edition.build_student_edition(ROOT, out / "student")
    return out / "student", make_release.build_wheel(out / "student", out / "dist")


@pytest.fixture(scope="module")
def colab_kernel(tmp_path_factory):
    """A fresh venv with Colab's defaults only, registered as the kernel ``colab-like``."""
    tmp = tmp_path_factory.mktemp("colab-venv")
    venv, prefix = tmp / "venv", tmp / "jupyter"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    python = venv / "bin" / "python"
    pins = student_edition._pins(ROOT / "environment-student.txt", COLAB_DEFAULTS)
    assert len(pins) == len(COLAB_DEFAULTS), pins
    subprocess.run([python, "-m", "pip", "install", "--quiet", *pins], check=True)
    subprocess.run(
        [python, "-m", "ipykernel", "install", "--prefix", str(prefix), "--name", KERNEL],
        check=True,
        capture_output=True,
    )
    return python, prefix / "share" / "jupyter"


def _alone(chapter, folder, url):
    """The chapter alone in an empty folder, its setup cell given the address ``url``."""
    folder.mkdir()
    nb = nbformat.read(chapter, as_version=4)
    setup = nb.cells[0]
    assert setup.id == nbtool.SETUP_ID and "COURSE_URL = None" in setup.source
    setup.source = setup.source.replace("COURSE_URL = None", f"COURSE_URL = {url!r}")
    nbformat.write(nb, folder / chapter.name)
    return folder / chapter.name


def _execute(path, jupyter_path):
    env = {**os.environ, "JUPYTER_PATH": str(jupyter_path), "PYTHONPATH": ""}
    subprocess.run(
        [sys.executable, "-m", "jupyter", "nbconvert", "--to", "notebook", "--execute",
         "--allow-errors", f"--ExecutePreprocessor.kernel_name={KERNEL}",
         "--ExecutePreprocessor.timeout=600", "--output", "executed.ipynb", str(path)],
        check=True, capture_output=True, env=env, cwd=path.parent,
    )  # fmt: skip
    return json.loads((path.parent / "executed.ipynb").read_text(encoding="utf-8"))


def _errors(nb):
    return {
        i: o["ename"] + ": " + o["evalue"]
        for i, cell in enumerate(nb["cells"])
        for o in cell.get("outputs", [])
        if o.get("output_type") == "error"
    }


def test_a_chapter_alone_runs_as_in_colab(release, colab_kernel, tmp_path):
    student, wheel = release
    python, jupyter_path = colab_kernel
    chapter = student / "notebooks" / CHAPTER
    clean_env = {**os.environ, "PYTHONPATH": ""}
    installed = subprocess.run(
        [python, "-c", "import course_lib"], capture_output=True, env=clean_env, cwd=tmp_path
    )
    assert installed.returncode != 0, "the fresh venv must not have the course yet"

    # 1. No address yet: one plain message from the setup cell, and no README to look for.
    nb = _execute(_alone(chapter, tmp_path / "unpublished", None), jupyter_path)
    errors = _errors(nb)
    assert list(errors)[0] == 0, errors
    assert "Ask your instructor for the course link" in errors[0] and "README" not in errors[0]

    # 2. The release's wheel as the published address: installed by the setup cell, then run.
    nb = _execute(_alone(chapter, tmp_path / "published", str(wheel)), jupyter_path)
    errors = _errors(nb)
    cells = nb["cells"]
    stubs = {i for i, c in enumerate(cells) if STUB in "".join(c["source"])}
    checks = {
        i for i, c in enumerate(cells) if c["metadata"].get("nbgrader", {}).get("grade")
    } - stubs
    unexpected = {i: e for i, e in errors.items() if i not in stubs | checks}
    assert unexpected == {}, unexpected
    assert all(errors.get(i, "").startswith("NotImplementedError") for i in stubs), errors
    for i in checks:
        assert not errors.get(i, "").startswith(("NameError", "ModuleNotFoundError")), errors[i]
    shown = json.dumps([c.get("outputs", []) for c in cells])
    assert "application/vnd.jupyter.widget-view+json" in shown  # the live explorer (ipympl)
    assert "font-awesome" not in shown and "A still picture" not in shown

    # 3. Its problem set alone, the same way: it runs up to its stubs, and stops only there.
    if PROBLEM_SET.is_file():
        path = _alone(student / "problem_sets" / PROBLEM_SET.name, tmp_path / "ps", str(wheel))
        nb = _execute(path, jupyter_path)
        errors, cells = _errors(nb), nb["cells"]
        stubs = {i for i, c in enumerate(cells) if STUB in "".join(c["source"])}
        graded = {i for i, c in enumerate(cells) if c["metadata"].get("nbgrader", {}).get("grade")}
        assert stubs and {i: e for i, e in errors.items() if i not in stubs | graded} == {}
        assert all(errors[i].startswith("NotImplementedError") for i in stubs), errors
