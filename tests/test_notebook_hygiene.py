"""The chapter and problem-set notebooks stay lean and stable, and open wherever a class works.

`make notebooks` (instructor/build/notebooks.py) puts the setup cell first, executes and cleans
every chapter and problem set; these tests check its result on the committed notebooks, one property
at a time, and the tool itself on small notebooks.
"""

import base64
import io
import re
import subprocess
import sys
from pathlib import Path

import nbformat
import numpy as np
import pytest
from IPython.core.inputtransformer2 import TransformerManager
from PIL import Image

from instructor.build import course_links
from instructor.build import notebooks as nbtool

ROOT = Path(__file__).resolve().parents[1]


CHAPTERS = sorted((ROOT / "notebooks").glob("[0-9]*.ipynb")) + sorted(
    (ROOT / "problem_sets").glob("ps[0-9]*.ipynb")
)
MAX_TOTAL_BYTES = 2_000_000  # five chapters and their problem sets (1.67 MB today)


def _read(path):
    return nbformat.read(path, as_version=4)


def _outputs(nb):
    for i, cell in enumerate(nb.cells):
        for output in cell.get("outputs", []):
            yield i, output


def _pins(path):
    lines = (line.split("#")[0].strip() for line in path.read_text().splitlines())
    return sorted(line for line in lines if "==" in line)


@pytest.fixture(params=CHAPTERS, ids=lambda p: p.name)
def chapter(request):
    return request.param


# ---------------------------------------------------------------------------------------------
# The committed notebooks
# ---------------------------------------------------------------------------------------------


def test_there_are_chapters():
    assert len(CHAPTERS) >= 3


def test_first_cell_is_the_current_setup_cell(chapter):
    first = _read(chapter).cells[0]
    assert first.get("id") == nbtool.SETUP_ID, f"{chapter.name}: run `make notebooks`"
    assert first.source == nbtool.setup_source(course_links.repository_url())
    assert [c.get("id") for c in _read(chapter).cells].count(nbtool.SETUP_ID) == 1


def test_setup_cell_is_short_and_readable():
    # 24: one import a line, the blank lines after imports that ruff asks for (`make lint`) and
    # a message in plain words, four lines, for a student whose notebook has no course around it
    lines = nbtool.setup_source("https://github.com/example/rotations-course").splitlines()
    assert len(lines) <= 24
    assert max(len(line) for line in lines) <= 100


def test_regression_no_widget_state_and_no_widget_view_that_would_hide_the_still(chapter):
    # A stored view (even with an empty model id) is what a trusted notebook shows instead of
    # the PNG, and JupyterLab hides a view whose model is gone: the explorer showed nothing.
    nb = _read(chapter)
    assert "widgets" not in nb.metadata
    for i, output in _outputs(nb):
        assert nbtool.WIDGET_VIEW not in output.get("data", {}), f"{chapter.name} cell {i}"
        if output.get("metadata", {}).get(nbtool.EXPLORER_STILL):
            # the still with its alt text (the state shown), not a bare image/png (no alt)
            assert "image/png" not in output["data"], f"{chapter.name} cell {i}"
            assert (
                'alt="' in output["data"]["text/html"]
                and "explorer" in output["data"]["text/plain"]
            )


def test_no_execution_timestamps(chapter):
    stamped = [i for i, c in enumerate(_read(chapter).cells) if "execution" in c.metadata]
    assert stamped == [], f"{chapter.name}: cells {stamped} carry execution timestamps"


def test_pngs_are_palette_coded(chapter):
    nb = _read(chapter)
    for i, output in _outputs(nb):
        if "image/png" in output.get("data", {}):
            image = Image.open(io.BytesIO(base64.b64decode(output["data"]["image/png"])))
            assert image.mode == "P", (
                f"{chapter.name} cell {i}: {image.mode} PNG, run `make notebooks`"
            )


def test_cleaning_the_committed_notebooks_changes_nothing(chapter):
    text = chapter.read_text(encoding="utf-8")
    nb = nbformat.reads(text, as_version=4)
    nbformat.validate(nb)
    assert (
        nbtool.text_of(nbtool.clean(nbtool.put_setup_cell(nb, course_links.repository_url())))
        == text
    )


def test_all_chapters_together_are_small():
    sizes = {p.name: p.stat().st_size for p in CHAPTERS}
    assert sum(sizes.values()) <= MAX_TOTAL_BYTES, sizes


# ---------------------------------------------------------------------------------------------
# One URL, everywhere; Binder has the same pins
# ---------------------------------------------------------------------------------------------


def test_readme_launch_links_follow_pyproject():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    block = re.search(
        re.escape(course_links.BEGIN) + ".*?" + re.escape(course_links.END), text, re.S
    )
    assert block, "README.md has no launch-links block"
    names = [p.name for p in CHAPTERS if p.parent.name == "notebooks"]
    assert block.group(0) == course_links.readme_block(course_links.repository_url(), names)


def test_unset_url_says_so_instead_of_pointing_nowhere():
    block = course_links.readme_block(None, ["01_a.ipynb"])
    assert "not published yet" in block and "http" not in block


def test_links_of_a_github_repository_open_the_student_edition():
    url = "https://github.com/example/rotations-course"
    assert course_links.binder_url(url) == (
        "https://mybinder.org/v2/gh/example/rotations-course/student?urlpath=lab/tree/notebooks"
    )
    assert course_links.colab_url(url + ".git", "01_a.ipynb") == (
        "https://colab.research.google.com/github/example/rotations-course/blob/student/notebooks/01_a.ipynb"
    )
    assert "branch=student" in course_links.nbgitpuller_url(url)
    assert course_links.colab_url("https://gitlab.com/example/course", "01_a.ipynb") is None
    assert course_links.binder_url("https://gitlab.com/example/course").startswith(
        "https://mybinder.org/v2/git/https%3A%2F%2Fgitlab.com%2Fexample%2Fcourse/student"
    )


def test_repository_url_must_be_https(tmp_path):
    bad = tmp_path / "pyproject.toml"
    bad.write_text('[project]\nname = "x"\n[project.urls]\nRepository = "git@host:x.git"\n')
    with pytest.raises(ValueError, match="Repository must be an https:// URL"):
        course_links.repository_url(bad)


def test_python310_fallback_reads_project_urls():
    text = (
        '[project]\nname = "x"\n\n[project.urls]\nRepository = "https://h/x"\n\n[tool.y]\nz = "1"\n'
    )
    assert course_links._project_urls(text) == {"Repository": "https://h/x"}


def test_binder_installs_the_student_environment_not_the_instructors():
    reqs = (ROOT / "binder" / "requirements.txt").read_text().splitlines()
    assert "-r ../environment-student.txt" in reqs
    student = {pin.split("==")[0] for pin in _pins(ROOT / "environment-student.txt")}
    assert {"jupyterlab", "ipympl", "ipywidgets", "numpy", "sympy", "matplotlib"} <= student
    assert not {"nbgrader", "pytest", "nbval", "hypothesis", "ruff", "playwright"} & student
    # the instructor's environment is the student's plus the tools, with the same pins
    assert "-r environment-student.txt" in (ROOT / "environment.txt").read_text().splitlines()


def test_binder_uses_python_311_and_installs_the_course_editable():
    assert (ROOT / "binder" / "runtime.txt").read_text().strip() == "python-3.11"
    reqs = (ROOT / "binder" / "requirements.txt").read_text().splitlines()
    assert "-e ." in reqs


def test_not_notebook_exec_deselects_every_notebook_cell():
    """Regression: `-m 'not notebook_exec'` used to keep all nbval cells (3 of 920 deselected)."""
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "pytest",
            "--collect-only",
            "-q",
            "-m",
            "not notebook_exec",
            "notebooks",
        ],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert ".ipynb::" not in run.stdout
    assert re.search(r"no tests collected \(\d+ deselected\)|0 selected", run.stdout), run.stdout[
        -300:
    ]


# ---------------------------------------------------------------------------------------------
# The setup cell, run as IPython runs it
# ---------------------------------------------------------------------------------------------


class _Shell:
    def __init__(self):
        self.magics = []

    def run_line_magic(self, name, line, _stack_depth=1):
        self.magics.append((name, line))


def _run_setup(url, monkeypatch, cwd, importable):
    import importlib.util

    real = importlib.util.find_spec
    monkeypatch.setattr(
        importlib.util,
        "find_spec",
        lambda name, *a: real(name, *a) if importable or name != "course_lib" else None,
    )
    monkeypatch.setattr(sys, "path", list(sys.path))
    monkeypatch.chdir(cwd)
    shell = _Shell()
    code = TransformerManager().transform_cell(nbtool.setup_source(url))
    shell.namespace = {"get_ipython": lambda: shell}
    exec(code, shell.namespace)
    return shell


def test_setup_cell_is_a_no_op_where_course_lib_imports(monkeypatch, tmp_path):
    path_before = list(sys.path)
    shell = _run_setup("https://github.com/example/c", monkeypatch, tmp_path, importable=True)
    assert shell.magics == [] and sys.path == path_before


def test_setup_cell_imports_from_the_checkout_above_the_notebook(monkeypatch, tmp_path):
    (tmp_path / "course_lib").mkdir()
    (tmp_path / "course_lib" / "__init__.py").write_text("")
    (tmp_path / "notebooks").mkdir()
    shell = _run_setup(None, monkeypatch, tmp_path / "notebooks", importable=False)
    assert shell.magics == [] and sys.path[0] == str(tmp_path.resolve())


def test_setup_cell_installs_from_the_repository_url_elsewhere(monkeypatch, tmp_path):
    shell = _run_setup("https://github.com/example/c", monkeypatch, tmp_path, importable=False)
    assert shell.magics == [("pip", "install --quiet {package}")]
    assert shell.namespace["package"] == "git+https://github.com/example/c"


def test_setup_cell_installs_a_published_wheel_as_it_is(monkeypatch, tmp_path):
    wheel = "https://example.org/course_lib-0.1.0-py3-none-any.whl"
    shell = _run_setup(wheel, monkeypatch, tmp_path, importable=False)
    assert shell.namespace["package"] == wheel


def test_setup_cell_without_an_address_says_in_plain_words_what_to_do(monkeypatch, tmp_path):
    """Issue 16: Colab was told to open the notebook in 'the course folder (README)'."""
    with pytest.raises(ModuleNotFoundError) as err:
        _run_setup(None, monkeypatch, tmp_path, importable=False)
    message = str(err.value)
    assert "course link" in message and "JupyterHub" in message
    assert "README" not in message and "folder" not in message


def test_setup_cell_turns_on_colabs_widget_manager_for_ipympl(monkeypatch, tmp_path):
    import types

    calls = []
    colab = types.ModuleType("google.colab")
    colab.output = types.SimpleNamespace(enable_custom_widget_manager=lambda: calls.append(1))
    monkeypatch.setitem(sys.modules, "google", types.ModuleType("google"))
    monkeypatch.setitem(sys.modules, "google.colab", colab)
    _run_setup(None, monkeypatch, tmp_path, importable=True)
    assert calls == [1]


# ---------------------------------------------------------------------------------------------
# The tool on small notebooks
# ---------------------------------------------------------------------------------------------


def _rgba_png():
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(3, 3), dpi=100)
    ax.plot([0, 1], [0, 1])
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    plt.close(fig)
    return base64.b64encode(buf.getvalue()).decode()


def test_small_png_is_smaller_looks_the_same_and_is_stable():
    png = _rgba_png()
    small = nbtool.small_png(png)
    assert len(small) < 0.7 * len(png)
    assert nbtool.small_png(small) == small
    before = np.asarray(Image.open(io.BytesIO(base64.b64decode(png))).convert("RGB"), float)
    after = np.asarray(Image.open(io.BytesIO(base64.b64decode(small))).convert("RGB"), float)
    assert after.shape == before.shape and np.abs(after - before).max() <= 24


def test_animation_ids_are_deterministic_and_distinct_per_cell():
    uid = "0123456789abcdef0123456789abcdef"
    html = f'new Animation(frames, "{uid}"); id="{uid}"'
    a = nbtool._stable_ids(html, "cell-a")
    assert a == nbtool._stable_ids(html, "cell-a") != nbtool._stable_ids(html, "cell-b")
    assert len(set(re.findall("[0-9a-f]{32}", a))) == 1


def test_put_setup_cell_replaces_an_old_copy():
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_markdown_cell("# Title")])
    nbtool.put_setup_cell(nb, None)
    nb.cells.append(nb.cells.pop(0))  # an old copy, moved to the end
    nb.cells[-1].source = "# an older setup cell"
    nbtool.put_setup_cell(nb, "https://github.com/example/c")
    assert [c.get("id") for c in nb.cells].count(nbtool.SETUP_ID) == 1
    assert nb.cells[0].source == nbtool.setup_source("https://github.com/example/c")


def test_clean_strips_widget_state_timestamps_and_widget_views():
    cell = nbformat.v4.new_code_cell("w")
    cell.metadata["execution"] = {"iopub.status.idle": "2026-01-01T00:00:00Z"}
    cell.outputs = [
        nbformat.v4.new_output(
            "execute_result",
            data={
                nbtool.WIDGET_VIEW: {"model_id": "3cb279597a744bb5", "version_major": 2},
                "text/plain": "w",
            },
        )
    ]
    nb = nbformat.v4.new_notebook(cells=[cell], metadata={"widgets": {"state": {}}})
    nbtool.clean(nb)
    assert "widgets" not in nb.metadata and "execution" not in cell.metadata
    assert nbtool.WIDGET_VIEW not in cell.outputs[0]["data"]
    assert cell.outputs[0]["metadata"][nbtool.EXPLORER_STILL] is True


@pytest.mark.notebook_exec
def test_widget_cells_do_not_stall_the_executor(tmp_path):
    """Regression: nbclient's Output-widget mimic made the cell after a slider wait 300 s."""
    cells = [nbformat.v4.new_code_cell("from course_lib.interactive import rodrigues_explorer")]
    for _ in range(8):
        cells += [
            nbformat.v4.new_code_cell("rodrigues_explorer()"),
            nbformat.v4.new_code_cell("1 + 1"),
        ]
    nb = nbformat.v4.new_notebook(cells=cells)
    nb.metadata["kernelspec"] = {
        "name": "python3",
        "display_name": "Python 3",
        "language": "python",
    }
    seconds = nbtool.execute(nb, tmp_path)
    assert seconds < 60
    assert nb.cells[-1].outputs[0]["data"]["text/plain"] == "2"
    # the slider's first figure, recorded as ordinary output (an <img> with its alt text)
    assert any(
        '<img class="course-figure"' in o.get("data", {}).get("text/html", "")
        for o in nb.cells[1].outputs
    )


@pytest.mark.notebook_exec
def test_a_rerun_changes_nothing(tmp_path):
    """Execute the smallest chapter again with the tool: the JSON is byte for byte the same."""
    smallest = min(CHAPTERS, key=lambda p: p.stat().st_size)
    copy = tmp_path / "notebooks" / smallest.name
    copy.parent.mkdir()
    copy.write_bytes(smallest.read_bytes())
    new, old, seconds = nbtool.process(copy, course_links.repository_url())
    assert seconds < 60
    assert new == old, (
        "re-executing changed the notebook: run `make notebooks` and look at the diff"
    )
