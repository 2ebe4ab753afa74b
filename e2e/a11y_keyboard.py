"""An explorer driven with the keyboard alone, in a real JupyterLab (``make a11y`` runs it).

    python e2e/a11y_keyboard.py [NOTEBOOK]   (default: notebooks/02_rotations.ipynb)

The notebook is opened and run (e2e's :class:`run_e2e.Lab`); in its first explorer, from the
first slider the Tab key moves through every slider (each with a label that names it, the same
name on the focused handle itself, ``aria-label``, and a visible focus), the arrow keys change
each one, and the figure is redrawn after each change (WCAG 2.1.1, 2.4.7, 4.1.2). Then Tab
reaches the 3D view (ipympl's canvas): it has a name saying its keys and a visible focus ring,
ArrowLeft turns it and + zooms it (the figure is redrawn each time), and Tab, Shift+Tab and
Escape take the focus out of it (WCAG 2.1.2, no keyboard trap: ipympl swallows every key). The
first
slider is focused from the page with ``focus()`` (as a screen reader's "next control" would land
on it: Tab through a whole JupyterLab notebook passes hundreds of editor stops first); after
that no mouse and no click. Exit status 0 when it holds.
"""

import functools
import sys
from pathlib import Path

from common import ROOT, CheckFailed, js, log, poll

HANDLE = ".noUi-handle, input[type=range], [role=slider]"
FOCUS_JS = """() => {
  const el = document.activeElement;
  const s = getComputedStyle(el);
  const slider = el.closest('.widget-slider');
  const label = slider && slider.querySelector('.widget-label');
  return {inSlider: !!slider, label: label ? label.textContent.trim() : '',
          aria: el.getAttribute('aria-label') || el.getAttribute('aria-labelledby') || '',
          outline: s.outlineStyle !== 'none' && parseFloat(s.outlineWidth) > 0,
          shadow: s.boxShadow !== 'none', border: s.borderColor,
          index: slider ? [...slider.parentElement.querySelectorAll('.widget-slider')]
                          .indexOf(slider) : -1};
}"""


def _redrawn(page, before, i):
    """Widget 0's figure now, if it differs from ``before`` (slider i's readout with it)."""
    now = page.evaluate(js("widget_figure"), [0, i])
    return now if now["loaded"] and now["src"] != before["src"] else None


def drive(page, problems, timeout=60):
    n = page.evaluate(js("tag_widgets"))
    if n == 0:
        raise CheckFailed("no explorer on the page")
    box = page.locator('[data-e2e-widget="0"]')
    box.scroll_into_view_if_needed()
    labels = page.evaluate(js("widget_sliders"), 0)
    box.locator(HANDLE).first.focus()
    for s in range(len(labels)):
        focus = page.evaluate(FOCUS_JS)
        if not focus["inSlider"]:
            problems.append(f"Tab did not reach slider {s} ({labels[s]!r})")
            return
        name = focus["label"] or focus["aria"]
        if not name:
            problems.append(f"slider {s} has no label")
        elif focus["aria"] != focus["label"]:  # what a screen reader says on the handle
            problems.append(f"slider {s} ({name!r}): its handle is named {focus['aria']!r}")
        if not focus["outline"]:  # a ring drawn for the focus, not a shadow always there
            problems.append(f"slider {s} ({name!r}): no visible focus ring (outline)")
        before = page.evaluate(js("widget_figure"), [0, focus["index"]])
        for _ in range(3):
            page.keyboard.press("ArrowRight")
        try:
            after = poll(
                functools.partial(_redrawn, page, before, focus["index"]),
                timeout,
                f"the figure to redraw after the arrow keys on slider {name!r}",
            )
        except CheckFailed as exc:
            problems.append(str(exc))
            return
        log(
            f"  slider {s} {name!r}: arrow keys: {before['readout']} -> {after['readout']}, "
            "figure redrawn, focus ring shown"
        )
        for _ in range(4):  # Tab: past the slider's editable readout, to the next handle
            if s + 1 == len(labels):
                break
            page.keyboard.press("Tab")
            page.wait_for_timeout(200)
            now = page.evaluate(FOCUS_JS)
            on_handle = page.evaluate("document.activeElement.classList.contains('noUi-handle')")
            if now["index"] == focus["index"] + 1 and on_handle:
                break


CANVAS = ".jupyter-matplotlib-canvas-div"
VIEW_JS = """() => {
  const el = document.activeElement;
  const s = getComputedStyle(el);
  return {onView: el.matches('.jupyter-matplotlib-canvas-div'), role: el.getAttribute('role'),
          name: el.getAttribute('aria-label') || '',
          outline: s.outlineStyle !== 'none' && parseFloat(s.outlineWidth) >= 2,
          outlineColor: s.outlineColor};
}"""


def _view_redrawn(page, before):
    now = page.evaluate(js("widget_figure"), [0, 0])
    return now if now["loaded"] and now["src"] != before["src"] else None


def _leaves(page, key, problems):
    """Focus the 3D view, press ``key``: the focus must leave it."""
    page.locator(f'[data-e2e-widget="0"] {CANVAS}').first.focus()
    page.keyboard.press(key)
    page.wait_for_timeout(200)
    if page.evaluate(VIEW_JS)["onView"]:
        problems.append(f"{key} does not leave the 3D view (a keyboard trap, WCAG 2.1.2)")
    else:
        log(f"  3D view: {key} leaves it")


def drive_view(page, problems, timeout=60):
    """From the last slider: Tab to the 3D view, turn and zoom it, leave it."""
    for _ in range(4):
        page.keyboard.press("Tab")
        page.wait_for_timeout(200)
        if page.evaluate(VIEW_JS)["onView"]:
            break
    view = page.evaluate(VIEW_JS)
    if not view["onView"]:
        problems.append("Tab from the last slider does not reach the 3D view")
        return
    if view["role"] != "application" or "arrow keys" not in view["name"]:
        problems.append(f"the 3D view's name does not say its keys: {view['name']!r}")
    if not view["outline"]:
        problems.append("the 3D view shows no focus ring")
    for key, what in (("ArrowLeft", "turned"), ("+", "zoomed")):
        before = page.evaluate(js("widget_figure"), [0, 0])
        page.keyboard.press(key)
        try:
            poll(functools.partial(_view_redrawn, page, before), timeout, f"{key} to redraw")
        except CheckFailed as exc:
            problems.append(f"the 3D view: {exc}")
            continue
        log(f"  3D view: {key} {what} it (figure redrawn); name {view['name'][:70]!r}...")
    for key in ("Tab", "Shift+Tab", "Escape"):
        _leaves(page, key, problems)


def main(argv=None):
    from notebook_checks import open_and_run
    from playwright.sync_api import sync_playwright
    from run_e2e import Lab

    argv = sys.argv[1:] if argv is None else argv
    path = Path(argv[0]) if argv else ROOT / "notebooks" / "02_rotations.ipynb"
    problems = []
    with sync_playwright() as pw:
        lab = Lab(pw, [path.resolve()], fixtures=False)
        try:
            page = lab.context.new_page()
            open_and_run(page, lab.server, lab.notebooks[0], problems, 240)
            drive(page, problems)
            if not problems:
                drive_view(page, problems)
            page.evaluate(js("shutdown_kernel"))
        except CheckFailed as exc:
            problems.append(str(exc))
        finally:
            lab.close()
    for p in problems:
        log(f"FAIL keyboard: {p}")
    log(
        "keyboard-only explorer: "
        + ("FAILED" if problems else "every slider and the 3D view reached, operated, left")
    )
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
