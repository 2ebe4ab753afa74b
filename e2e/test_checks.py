"""Unit tests of the browser test's own logic (no browser): which requests leave the machine,
what a fold or an animation player must look like, the staging of the notebooks.

    PYTHONPATH=e2e python -m pytest e2e/test_checks.py -q
"""

import json

import nbformat
import pytest
from fixtures import FOLDS_NOTEBOOK, folds_notebook, write_fixtures
from run_e2e import stage
from view_checks import fold_problems, outside_requests, player_problem


@pytest.mark.parametrize(
    "url",
    [
        "http://127.0.0.1:8888/lab/api/settings",
        "ws://127.0.0.1:8888/api/kernels/abc/channels",
        "http://localhost:9/x",
        "http://[::1]:8888/static/x.js",
        "data:image/png;base64,AAAA",
        "blob:http://127.0.0.1:8888/1234",
        "about:blank",
    ],
)
def test_local_requests_pass(url):
    assert outside_requests([url]) == []


def test_outside_requests_named_once_in_order():
    cdn = "https://maxcdn.bootstrapcdn.com/font-awesome/4.4.0/css/font-awesome.min.css"
    urls = ["http://127.0.0.1:1/a", cdn, "wss://example.org/socket", cdn]
    assert outside_requests(urls) == [cdn, "wss://example.org/socket"]


def test_player_zero_size_without_src_is_a_problem():
    """Regression: chapter 03's player on opening (untrusted output: the script never runs)."""
    msg = player_problem("cell 68 output 0", {"size": [0, 0], "loaded": False, "src": ""})
    assert "0x0 px" in msg and "no src" in msg and "cell 68 output 0" in msg


def test_player_loaded_but_not_laid_out_is_a_problem():
    msg = player_problem("cell 1 output 0", {"size": [0, 0], "loaded": True, "src": "data:x"})
    assert msg is not None and "0x0" in msg


def test_player_showing_a_frame_passes():
    assert player_problem("c", {"size": [360, 360], "loaded": True, "src": "data:x"}) is None


def fold(collapsed, hidden, next_hidden=False, level=2, button=True):
    under = [{"i": 3 + k, "hidden": h} for k, h in enumerate(hidden)]
    return {
        "i": 2,
        "level": level,
        "collapsed": collapsed,
        "under": under,
        "button": button,
        "next": 3 + len(hidden),
        "nextHidden": next_hidden,
    }


def test_fold_as_it_should_open_and_expand():
    assert fold_problems(fold(True, [True, True]), "collapsed") == []
    assert fold_problems(fold(False, [False, False]), "expanded") == []


def test_fold_shown_expanded_on_opening():
    found = fold_problems(fold(False, [False, True]), "collapsed")
    assert any("shown expanded" in p for p in found)
    assert any("[3]" in p for p in found)


def test_fold_that_stays_closed_when_clicked():
    assert any("stay hidden" in p for p in fold_problems(fold(True, [True]), "expanded"))


def test_fold_inside_a_closed_fold_is_excused():
    assert fold_problems(fold(False, [False, True]), "expanded", excused={4}) == []
    assert fold_problems(fold(False, [False, True]), "expanded") != []


def test_fold_hiding_the_next_heading_and_fold_without_button():
    found = fold_problems(fold(True, [True], next_hidden=True, button=False), "collapsed")
    assert any("next heading" in p for p in found)
    assert any("without the button" in p for p in found)
    assert "not a heading" in fold_problems(fold(True, [True], level=0), "collapsed")[0]


def test_fixture_notebook_is_valid_and_folded(tmp_path):
    assert write_fixtures(tmp_path) == [FOLDS_NOTEBOOK]
    nb = nbformat.read(tmp_path / FOLDS_NOTEBOOK, as_version=4)
    nbformat.validate(nb)
    folded = [c for c in folds_notebook()["cells"] if c["metadata"]]
    assert len(folded) == 2
    assert all(c["source"].startswith("#") for c in folded)


def test_stage_copies_folders_and_single_notebooks(tmp_path):
    src = tmp_path / "src"
    (src / "notebooks").mkdir(parents=True)
    (src / "ps").mkdir()
    for path in (src / "notebooks" / "01_a.ipynb", src / "ps" / "ps01.ipynb"):
        path.write_text(json.dumps({"cells": []}))
    (src / "notebooks" / "notes.txt").write_text("not a notebook")
    root = tmp_path / "root"
    notebooks, fixtures = stage([src / "notebooks", src / "ps" / "ps01.ipynb"], root, True)
    assert notebooks == ["notebooks/01_a.ipynb", "ps/ps01.ipynb"]
    assert fixtures == [FOLDS_NOTEBOOK] and (root / FOLDS_NOTEBOOK).is_file()
    assert not (root / "notebooks" / "notes.txt").exists()
    assert stage([src / "ps"], tmp_path / "root2", False) == (["ps/ps01.ipynb"], [])


def test_fold_with_nothing_under_it():
    """Regression: a 'Going deeper: Errata' heading folded with its text in its own cell and the
    next heading right after it; JupyterLab then hides nothing and shows no button."""
    found = fold_problems(fold(True, [], button=False), "collapsed")
    assert len(found) == 1 and "hides nothing" in found[0]
