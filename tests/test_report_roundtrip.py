"""The class report's data through the real grading paths (issue 34): real ``nbgrader
autograde`` of a ``make course`` directory (marked ``slow_grading``) and the real Gradescope
``run_autograder`` (marked ``gradescope``), three students each: the instructor's solved copy
(its checks run), the solved copy with the known mistake ``swapped`` in ``bac_cab`` and
``lagrange_identity`` answered in the components (the wrong form), outputs cleared (checks
never run), and a blank copy. The report's counts are those planted. (The class of 30 goes
through the same preprocessors in process: tests/test_report.py.)"""

from __future__ import annotations

import copy
from pathlib import Path

import pytest
import yaml
from test_grading_gradescope import autograder, notebook, run_autograder  # noqa: F401

from course_lib.exercises import EXERCISES
from instructor.grading.report_data import from_course, from_gradescope, known
from instructor.grading.report_stats import set_stats

ROOT = Path(__file__).resolve().parents[1]
# the Gradescope module's fixture and helpers (its own tests are not collected here)


PS = "ps01"
MISTAKE = ("answer_bac_cab = [alpha_, beta_]", "answer_bac_cab = [beta_, alpha_]")
FORM = (
    "answer_lagrange_identity = guess",
    "answer_lagrange_identity = sp.expand(lhs)",
)


def mistaken(nb):
    """The solved copy with one known mistake and one answer in the wrong form, never run."""
    for cell in nb.cells:
        for old, new in (MISTAKE, FORM):
            if old in cell.source:
                cell.source = cell.source.replace(old, new)
        if cell.cell_type == "code":
            cell.outputs, cell.execution_count = [], None
    return nb


def ran(nb):
    """The solved copy as handed in after running its checks (an execution count each)."""
    for k, cell in enumerate(nb.cells):
        if cell.get("id", "").endswith("-check"):
            cell.execution_count = k + 1
    return nb


def assert_planted(ps, blank=1):
    """Students: solved (ran its checks), mistaken (never ran them), ``blank`` blank ones."""
    st = {e.name: e for e in set_stats(ps, known).exercises}
    assert len(ps.submissions) == 2 + blank
    bac, lag, first = st["bac_cab"], st["lagrange_identity"], st["coords_by_projection"]
    assert (bac.right, [(k, c) for k, c, _ in bac.mistakes], bac.no_answer) == (
        1,
        [("swapped", 1)],
        blank,
    )
    assert bac.mistakes[0][2] == EXERCISES["bac_cab"].mistakes["swapped"]  # the hint text
    assert (lag.right, lag.form, lag.unexplained) == (1, 1, [])
    assert (first.right, first.no_answer, first.checked_known) == (2, blank, 2 + blank)
    assert first.never_checked == 1 + blank  # the mistaken copy and the blank release copy
    assert all(e.unexplained == [] for e in st.values())
    assert all(v.students == 1 for v in first.variants)


@pytest.mark.slow_grading
@pytest.mark.notebook_exec
def test_nbgrader_autograde_keeps_what_the_report_needs(tmp_path):
    import nbformat
    from grading_helpers import TRUSTED_AUTOGRADE
    from test_grading_nbgrader import run

    from instructor.grading.course import write_course

    write_course(tmp_path)
    code, out = run(["generate_assignment", PS, "--create"], tmp_path)
    assert code == 0, out
    for student, kind in (("ada", "source"), ("bob", "source"), ("cyd", "release")):
        path = next((tmp_path / kind / PS).glob("*.ipynb"))
        nb = nbformat.read(path, as_version=4)
        dest = tmp_path / "submitted" / student / PS
        dest.mkdir(parents=True)
        nb = {"ada": ran, "bob": mistaken}.get(student, lambda nb: nb)(nb)
        nbformat.write(nb, dest / path.name)
    code, out = run(["autograde", PS, *TRUSTED_AUTOGRADE], tmp_path)
    assert code == 0, out
    (ps,) = from_course(tmp_path)
    assert ps.notes == []
    assert_planted(ps)


@pytest.mark.gradescope
@pytest.mark.notebook_exec
def test_gradescope_results_carry_the_notes_in_extra_data(autograder, tmp_path):  # noqa: F811
    """Two runs (the blank copy's notes are those of nbgrader's round trip above)."""
    _, solved = notebook(autograder, "solved")
    data = {}
    copies = (("ada", ran(copy.deepcopy(solved))), ("bob", mistaken(solved)))
    verdicts = {"ada": "correct", "bob": "wrong"}
    for k, (sid, nb) in enumerate(copies):
        results = run_autograder(autograder, sid, nb)
        extra = {t["name"]: t["extra_data"] for t in results["tests"]}
        assert results["extra_data"]["assignment"] == PS
        assert extra["bac_cab"]["verdict"] == verdicts[sid]
        assert extra["bac_cab"]["checked"] is (sid == "ada")
        data[f"submission_{k}"] = {
            ":submitters": [{":name": sid.title(), ":sid": sid}],
            ":score": results["score"],
            ":results": results,
        }
    (tmp_path / "submission_metadata.yml").write_text(yaml.safe_dump(data))
    ps = from_gradescope(tmp_path)
    assert ps.name == PS and ps.notes == []
    assert_planted(ps, blank=0)
