"""The pages on which nbgrader shows a submission run none of the submission's HTML.

Regression (attack 9a): a student's answer cell displayed a ``<script>`` that, once the
instructor opened the submission in the formgrader, set its own grades through the formgrader's
API (0/14 -> 14/14 in ``grades.csv``); the same script was in the feedback page. And with the
course's feedback template set on every ``HTMLExporter``, the formgrader's page of a submission
failed (HTTP 500, ``TemplateNotFound: bootstrap.min.css``).

Real nbgrader, a real Jupyter server with nbgrader's formgrader extension, a real submission.
"""

from __future__ import annotations

import json
import os
import re
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import nbformat
import pytest
from grading_helpers import TRUSTED_AUTOGRADE

from instructor.grading.course import write_course

ROOT = Path(__file__).resolve().parents[1]


pytestmark = pytest.mark.notebook_exec
BIN = Path(sys.executable).parent
PS = "ps01"
STUDENT = "mallory"
OUTPUT_SCRIPT = '<script>document.title = "PWNED-OUTPUT";</script>'
# What a student can put in a notebook for a page to run: outputs of several kinds, a markdown
# cell, a raw cell marked as HTML.
SHOW = f"""\
from IPython.display import HTML, SVG, Javascript, display
display(HTML({OUTPUT_SCRIPT!r}))
display(Javascript('document.title = "PWNED-JS";'))
display(SVG('<svg xmlns="http://www.w3.org/2000/svg" onload="go()"><script>go()</script></svg>'))
"""
MARKDOWN = (
    '<script>document.title = "PWNED-MARKDOWN";</script>\n\n<img src=x onerror="go()">\n\n'
    "[click](javascript:go())"
)
RAW = '<script>document.title = "PWNED-RAW";</script>'
# A live script or handler: a real tag (escaped text, "&lt;script&gt;", is what it should be).
LIVE = re.compile(
    r'<script>\s*document\.title = "PWNED|<[a-z]+[^<>]*\son(error|load)=|href="javascript:'
)


ENV = {**os.environ, "PATH": f"{BIN}{os.pathsep}{os.environ.get('PATH', '')}"}


def run(args, cwd):
    proc = subprocess.run(
        [str(BIN / "nbgrader"), *args],
        cwd=cwd,
        env=ENV,
        capture_output=True,
        text=True,
        timeout=300,
    )
    return proc.returncode, proc.stdout + proc.stderr


def hand_in(root):
    """The release copy, its first answer cell showing scripts, a markdown cell and a raw HTML
    cell with scripts in them."""
    (released,) = (root / "release" / PS).glob("*.ipynb")
    nb = nbformat.read(released, as_version=4)
    answer = next(c for c in nb.cells if c.get("id", "").endswith("-answer"))
    answer.source = SHOW + answer.source
    nb.cells.append(nbformat.v4.new_markdown_cell(MARKDOWN))
    nb.cells.append(nbformat.v4.new_raw_cell(RAW, metadata={"format": "text/html"}))
    folder = root / "submitted" / STUDENT / PS
    folder.mkdir(parents=True)
    nbformat.write(nb, folder / released.name)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def get(url, timeout=60):
    deadline = time.monotonic() + timeout
    while True:
        try:
            with urllib.request.urlopen(url, timeout=10) as response:
                return response.status, response.read().decode()
        except urllib.error.HTTPError as err:
            return err.code, err.read().decode(errors="replace")
        except OSError:
            if time.monotonic() > deadline:
                raise
            time.sleep(0.5)


def formgrader_page(root, submission_id):
    """(status, HTML) of the formgrader's page of the submitted notebook."""
    port, token = free_port(), "formgrader-test"
    args = [
        str(BIN / "jupyter"),
        "server",
        "--no-browser",
        f"--port={port}",
        f"--ServerApp.token={token}",
        f"--ServerApp.root_dir={root}",
        "--ServerApp.open_browser=False",
    ]
    if os.geteuid() == 0:
        args.append("--allow-root")
    server = subprocess.Popen(
        args, cwd=root, env=ENV, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
    )
    try:
        base = f"http://127.0.0.1:{port}"
        get(f"{base}/api/status?token={token}")
        return get(f"{base}/formgrader/submissions/{submission_id}/?token={token}")
    finally:
        server.terminate()
        server.wait(timeout=30)


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    root = tmp_path_factory.mktemp("formgrader") / "course"
    js = root.parent / "tex-svg.js"
    js.write_text("window.ROTATIONS_FAKE_MATHJAX = 1;\n")
    write_course(root, mathjax=js)  # the feedback template configured, as after `make site`
    autograde = ["autograde", PS, "--create", *TRUSTED_AUTOGRADE]
    for args in (["generate_assignment", PS, "--create"], None, autograde):
        if args is None:
            hand_in(root)
            continue
        code, out = run(args, root)
        assert code == 0, out
    return root


def test_the_submission_holds_the_scripts(graded):
    """What the other tests look for is there: not a vacuous pass."""
    (nb,) = (graded / "autograded" / STUDENT / PS).glob("*.ipynb")
    text = nb.read_text()
    assert json.dumps(OUTPUT_SCRIPT)[1:-1] in text and "PWNED-JS" in text and "onload" in text
    assert "PWNED-MARKDOWN" in text and "PWNED-RAW" in text


def test_regression_formgrader_page_shows_the_submission_and_runs_none_of_its_html(graded):
    from nbgrader.api import Gradebook

    with Gradebook(f"sqlite:///{graded / 'gradebook.db'}") as gb:
        (notebook,) = gb.find_submission(PS, STUDENT).notebooks
        submission_id = notebook.id
    status, html = formgrader_page(graded, submission_id)
    assert status == 200, html[-2000:]
    assert "PWNED-OUTPUT" in html  # shown as text ...
    m = LIVE.search(html)
    assert not m, html[m.start() - 800 : m.end() + 100]  # ... never as a script or a handler


def test_regression_feedback_runs_none_of_the_submissions_html(graded):
    code, out = run(["generate_feedback", PS], graded)
    assert code == 0, out
    (page,) = (graded / "feedback" / STUDENT / PS).glob("*.html")
    html = page.read_text()
    assert "ROTATIONS_FAKE_MATHJAX" in html  # the course's feedback template, math offline
    assert "PWNED-OUTPUT" in html and not LIVE.search(html)
