"""The checks on one notebook in the browser: open it, run all cells, then look at the model
(errors, stderr) and at the page (typeset math, figures, widgets, dialogs), and screenshot it.

``check_notebook(context, server, rel_path, out_dir, timeout)`` does all of it for one notebook
and returns its problems (and whether the kernel stalled); the widgets are checked by
:mod:`widget_checks`.
"""

import io
import secrets
import time
import urllib.parse
from pathlib import Path

from common import POLL, ROOT, CheckFailed, KernelStalled, js, log, poll
from view_checks import check_folds, check_players, check_stills, outside_requests
from widget_checks import check_widgets

VIEWPORT = {"width": 1280, "height": 900}
MAX_SCREENSHOT_HEIGHT = 16000  # Chromium's texture limit is a little above this
# A notebook whose first cell has not started this long after "run all" is stalled, not slow.
NO_START_SECONDS = 40
# How long one cell scrolled into view may take to typeset and load its images.
CELL_SETTLE_SECONDS = 20
# Cells queued while the kernel says idle this long: the queued cells will never run. Before
# the first cell has run, 10 s (a kernel that sat idle with every cell queued, "no kernel" on
# the server, cost 30 s before its retry in CI; an idle kernel is not running a cell).
IDLE_STALL = 30
IDLE_STALL_NONE_RAN = 10
MATH_MARKERS = ("$", "\\(", "\\[", "\\begin{")
WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"


def has_math(source):
    return any(m in source for m in MATH_MARKERS)


def wait_for_open(page, rel_path, timeout):
    """Wait for the notebook's kernel to be idle; fail at once if a dialog asks for something.

    A dialog at this point is the kernel picker (no or unknown kernelspec in the notebook's
    metadata) or a build prompt: a student would see it too.
    """
    from playwright.sync_api import Error as PlaywrightError

    dialog_since = None

    def opened():
        nonlocal dialog_since
        try:
            if page.evaluate(js("find_notebook"), rel_path):
                return True
            dialogs = page.evaluate(js("overlays"))["dialogs"]
        except PlaywrightError:  # the page is still loading (navigation in progress)
            return False
        if not dialogs:
            dialog_since = None
        elif dialog_since is None:
            dialog_since = time.monotonic()
        elif time.monotonic() - dialog_since > 3.0:
            raise CheckFailed(f"a dialog blocks the notebook while it opens: {dialogs[0]!r}")
        return False

    try:
        poll(opened, timeout, "the notebook to open with an idle kernel")
    except KernelStalled:
        raise
    except CheckFailed as exc:
        if "dialog" in str(exc):
            raise
        raise KernelStalled(str(exc)) from None


def wait_for_run(page, timeout):
    """Wait until every non-empty code cell ran (or one failed) and the kernel is idle."""
    stable = {"n": 0}
    start = time.monotonic()
    progress = {"ran": -1, "since": start}

    def done():
        state = page.evaluate(js("state"))
        code = [c for c in state["cells"] if c["type"] == "code" and c["source"].strip()]
        started = any(c["count"] is not None or c["state"] == "running" for c in code)
        if code and not started and time.monotonic() - start > NO_START_SECONDS:
            raise KernelStalled(
                f"no cell started within {NO_START_SECONDS} s of 'run all' "
                f"(kernel status {state['kernel']!r}); the cells stayed queued"
            )
        errored = any(o["type"] == "error" for c in code for o in c["outputs"])
        finished = all(c["count"] is not None for c in code)
        busy = state["kernel"] != "idle" or any(c["state"] == "running" for c in code)
        ran = sum(c["count"] is not None for c in code)
        if ran != progress["ran"] or state["kernel"] != "idle":
            progress.update(ran=ran, since=time.monotonic())
        elif not (finished or errored) and time.monotonic() - progress["since"] > (
            stall := IDLE_STALL if ran else IDLE_STALL_NONE_RAN
        ):
            raise KernelStalled(
                f"the kernel is idle and no cell has run for {stall} s, yet "
                f"{len(code) - ran} cell(s) are still queued"
            )
        if (finished or errored) and not busy:
            stable["n"] += 1
        else:
            stable["n"] = 0
        return state if stable["n"] >= 3 else None  # idle on three polls in a row

    try:
        return poll(done, timeout, "all cells to run and the kernel to go idle")
    except CheckFailed as exc:
        raise KernelStalled(f"{exc}; {run_progress(page.evaluate(js('state')))}") from None


def run_progress(state):
    """Where a run stands, for a stall report: how many cells ran, which one is at work."""
    code = [(i, c) for i, c in enumerate(state["cells"]) if c["type"] == "code"]
    code = [(i, c) for i, c in code if c["source"].strip()]
    ran = sum(c["count"] is not None for _, c in code)
    waiting = next((i for i, c in code if c["count"] is None), None)
    running = [i for i, c in code if c["state"] == "running"]
    return (
        f"{ran} of {len(code)} code cells ran, first not run: cell {waiting}, running: "
        f"{running or 'none'}, kernel status {state['kernel']!r}"
    )


def check_outputs(state, problems):
    """Every code cell ran, and no output of the model is an error or stderr."""
    for i, cell in enumerate(state["cells"]):
        if cell["type"] != "code":
            continue
        if cell["source"].strip() and cell["count"] is None:
            problems.append(f"cell {i} did not run")
        for o in cell["outputs"]:
            if o["type"] == "error":
                problems.append(f"cell {i}: error output {o['text'][:300]}")
            elif o["type"] == "stream" and o["name"] == "stderr":
                problems.append(f"cell {i}: stderr output {o['text'][:300]!r}")


def check_dom(page, state, problems, timeout):
    """MathJax, figures and widgets, as displayed.

    JupyterLab's windowing (on by default) renders a cell off screen late or not at all, and
    an image off screen has no size: so every cell that is not right at first look, and every
    cell with an image, an HTML output or a widget, is scrolled into view as a student would
    and looked at there (polled until it settles, within ``timeout`` for the whole notebook).
    """
    t0 = time.monotonic()
    deadline = t0 + timeout
    stops = page.evaluate(js("sweep"))
    dom = page.evaluate(js("dom"), None)
    if dom["n"] != len(state["cells"]):
        problems.append(f"{dom['n']} cells on the page, {len(state['cells'])} in the model")
        return dom
    shown = {d["i"]: d for d in dom["cells"]}
    visited = 0
    for i, cell in enumerate(state["cells"]):
        if not cell_problems(i, cell, shown[i], in_view=False) and not needs_view(shown[i]):
            continue
        visited += 1
        page.evaluate(js("scroll_to_cell"), i)
        cell_deadline = min(deadline, time.monotonic() + CELL_SETTLE_SECONDS)
        while True:
            shown[i] = page.evaluate(js("dom"), [i])["cells"][0]
            found = cell_problems(i, cell, shown[i], in_view=True)
            if not found or time.monotonic() > cell_deadline:
                break
            time.sleep(POLL)
        problems.extend(found)
    dom = page.evaluate(js("dom"), [])
    dom["cells"] = [shown[i] for i in range(len(state["cells"]))]
    log(
        f"  looked at the page: scrolled through it ({stops} screens), then {visited} cell(s) "
        f"in view, {time.monotonic() - t0:.1f} s"
    )
    for text in dom["stderr"]:
        problems.append(f"error/stderr shown on the page: {text[:300]!r}")
    for src in dom["broken"]:
        problems.append(f"image failed to load: {src}")
    for text in dom["widgetErrors"]:
        problems.append(f"widget failed to render: {text[:300]!r}")
    return dom


def needs_view(shown):
    """Whether a cell must be seen in view: it has an image, a player or a widget to size."""
    return any(o["imgs"] or o["widget"] or o["player"] for o in shown["outputs"])


def output_problem(i, j, o, d, in_view):
    """What is wrong with output j of cell i as displayed (d) for the model's output o, if any.
    Rendered sizes count only ``in_view`` (off screen an image may have no layout)."""
    images = [m for m in o["mimes"] if m.startswith("image/")]
    where = f"cell {i} output {j}"
    if WIDGET_VIEW in o["mimes"]:
        if not d["widget"]:
            return f"{where}: widget not rendered"
        if d["sliders"] and d["widgetLoaded"] == 0 and d["canvases"] == 0:
            return f"{where}: slider widget shows no figure"
    elif d["player"] is not None:
        return None  # the animation player: view_checks.check_players
    elif images and d["loaded"] < 1:
        return f"{where}: image output ({images[0]}) not displayed"
    elif "text/html" in o["mimes"] and d["loaded"] < d["imgs"]:
        return f"{where}: {d['imgs'] - d['loaded']} image(s) of an HTML output not loaded"
    elif in_view and d["shown"] < d["loaded"]:
        return f"{where}: {d['loaded'] - d['shown']} loaded image(s) shown at 0x0 px in view"
    return None


def cell_problems(i, cell, shown, in_view):
    """What is wrong with cell i as displayed (``shown``, from js/dom.js) for the model's
    ``cell``: LaTeX not typeset, outputs missing, images not displayed."""
    out = []
    if cell["type"] == "markdown" and has_math(cell["source"]):
        if shown["mjx"] == 0:
            out.append(f"markdown cell {i} has LaTeX but no MathJax output (mjx-container)")
        if shown["merror"]:
            out.append(f"markdown cell {i}: {shown['merror']} MathJax error(s) (mjx-merror)")
    if cell["type"] != "code":
        return out
    if len(shown["outputs"]) != len(cell["outputs"]):
        n_model, n_page = len(cell["outputs"]), len(shown["outputs"])
        return out + [f"cell {i}: {n_model} outputs in the model, {n_page} on the page"]
    for j, (o, d) in enumerate(zip(cell["outputs"], shown["outputs"])):
        problem = output_problem(i, j, o, d, in_view)
        if problem:
            out.append(problem)
    return out


def check_overlays(page, problems, when):
    overlays = page.evaluate(js("overlays"))
    for text in overlays["dialogs"]:
        problems.append(f"dialog on screen {when}: {text!r}")
    for text in overlays["toasts"]:
        problems.append(f"notification on screen {when}: {text!r}")


def screenshot(page, path):
    """A PNG of the whole notebook, however long: JupyterLab, with the notebook unrolled.

    The viewport is made as tall as the notebook. A notebook taller than Chromium can capture
    in one go (``MAX_SCREENSHOT_HEIGHT``) is shot in tiles, scrolling the notebook between
    them, and the tiles are stacked into one image.
    """
    geo = page.evaluate(js("scroller"), None)
    if geo is None:
        page.screenshot(path=str(path), full_page=True)
        return
    chrome = geo["viewport"] - geo["clientHeight"]
    height = int(min(max(geo["scrollHeight"] + chrome, VIEWPORT["height"]), MAX_SCREENSHOT_HEIGHT))
    page.set_viewport_size({"width": VIEWPORT["width"], "height": height})
    try:
        page.wait_for_timeout(1000)  # relayout
        geo = page.evaluate(js("scroller"), 0)
        page.wait_for_timeout(500)
        if geo["scrollHeight"] <= geo["clientHeight"]:
            page.screenshot(path=str(path), full_page=True)
            return
        # compress_level=1: the sheet is big, and a full zlib pass on it took seconds of CPU.
        stack_tiles(page, geo).save(path, compress_level=1)
    finally:
        page.set_viewport_size(VIEWPORT)


def stack_tiles(page, geo):
    """Shoot the notebook one viewport at a time and stack the pieces into one image."""
    from PIL import Image  # Pillow comes with matplotlib

    top, view, total = geo["top"], geo["clientHeight"], geo["scrollHeight"]
    pieces, offset = [], 0
    while offset < total:
        geo = page.evaluate(js("scroller"), offset)
        page.wait_for_timeout(400)
        shot = Image.open(io.BytesIO(page.screenshot(type="jpeg", quality=90)))
        skip = offset - geo["scrollTop"]  # the last tile stops short: drop what was shot twice
        if offset == 0:
            pieces.append(shot.crop((0, 0, shot.width, top)))  # menu bar and toolbar
        pieces.append(shot.crop((0, top + skip, shot.width, top + view)))
        offset += view
    pieces.append(shot.crop((0, top + view, shot.width, shot.height)))  # status bar
    sheet = Image.new("RGB", (pieces[0].width, sum(p.height for p in pieces)), "white")
    y = 0
    for piece in pieces:
        sheet.paste(piece, (0, y))
        y += piece.height
    return sheet


def open_and_run(page, server, rel_path, problems, timeout, expect_folds=False):
    """Open the notebook in a fresh workspace, check what it shows on opening (the folded
    headings, which are then expanded, then the stored animation players and explorer stills:
    since issue 37 some sit in a fold), run all cells, return the model's final state."""
    workspace = f"e2e-{secrets.token_hex(4)}"
    url = f"{server.url}/lab/workspaces/{workspace}/tree/{urllib.parse.quote(rel_path)}"
    page.goto(f"{url}?reset&token={server.token}")
    t0 = time.monotonic()
    wait_for_open(page, rel_path, timeout=90)
    check_overlays(page, problems, "after opening")
    t1 = time.monotonic()
    opened = page.evaluate(js("state"))
    n_folds = check_folds(page, problems)  # expands every fold: a player may sit in one
    n_players = check_players(page, opened, problems, "on opening, before any cell runs")
    n_stills = check_stills(page, opened, problems)
    if expect_folds and not n_folds:
        problems.append("no folded heading found in a notebook made to have folds")
    log(
        f"  opened in {t1 - t0:.1f} s; checked {n_players} animation player(s), {n_stills} "
        f"explorer still(s) and {n_folds} folded heading(s) in {time.monotonic() - t1:.1f} s"
    )
    t0 = time.monotonic()
    page.evaluate(js("run_all"))
    state = wait_for_run(page, timeout)
    n_code = sum(1 for c in state["cells"] if c["type"] == "code")
    log(f"  ran {n_code} code cells in {time.monotonic() - t0:.1f} s")
    return state


def check_notebook(
    context,
    server,
    rel_path,
    out_dir,
    timeout,
    expect_folds=False,
    all_screenshots=False,
    more_checks=None,
):
    """Open, run and check one notebook (``expect_folds``: it must have a folded heading).
    A full-page screenshot is saved when it fails, or always with ``all_screenshots`` (each
    takes 10-25 s on a loaded 2-core machine: a third of the run for all of them).
    ``more_checks(page, rel_path)``, when given, runs last on the same page and returns more
    problems (``run_e2e --axe``: axe-core on the notebook's content, :mod:`a11y`).

    Returns the problems found (empty: passed), whether the kernel stalled, and the slider
    release -> redrawn figure latencies measured (ms).
    """
    from playwright.sync_api import Error as PlaywrightError

    problems, latencies = [], []
    stalled = False
    urls, page_errors = [], []
    # Every request of the browser (pages and workers), and the page's websockets.
    on_request = lambda request: urls.append(request.url)  # noqa: E731
    context.on("request", on_request)
    page = context.new_page()
    page.on("websocket", lambda ws: urls.append(ws.url))
    page.on("pageerror", lambda exc: page_errors.append(str(exc)))
    try:
        state = open_and_run(page, server, rel_path, problems, timeout, expect_folds)
        check_outputs(state, problems)
        check_players(page, state, problems, "after running all cells")
        dom = check_dom(page, state, problems, timeout=60)
        n_math = sum(c["mjx"] for c in dom["cells"])
        n_img = sum(o["loaded"] + o["widgetLoaded"] for c in dom["cells"] for o in c["outputs"])
        n_live = sum(o["canvases"] > 0 for c in dom["cells"] for o in c["outputs"])
        log(f"  {n_math} typeset formulas, {n_img} images displayed, {n_live} live figure(s)")
        expected = sum(
            WIDGET_VIEW in o["mimes"]
            for c in state["cells"]
            if c["type"] == "code"
            for o in c["outputs"]
        )
        shots = out_dir / Path(rel_path).stem
        latencies = check_widgets(page, expected, problems, timeout=60, shot_prefix=shots)
        check_overlays(page, problems, "after running")
        if more_checks is not None:
            problems.extend(more_checks(page, rel_path))
    except KernelStalled as exc:
        problems.append(str(exc))
        stalled = True
    except CheckFailed as exc:
        problems.append(str(exc))
    except PlaywrightError as exc:  # e.g. a slider that cannot be found or dragged
        problems.append(f"browser automation failed: {str(exc).splitlines()[0]}")
    finally:
        problems.extend(f"JavaScript error on the page: {e[:300]}" for e in page_errors)
        shot = out_dir / f"{Path(rel_path).stem}.png"
        finish_page(page, shot if problems or all_screenshots else None, problems)
        context.remove_listener("request", on_request)
        for url in outside_requests(urls):
            problems.append(f"a request leaves the loopback server: {url}")
    return problems, stalled, latencies


def finish_page(page, shot, problems):
    """Screenshot the page (unless ``shot`` is None), shut its kernel down and close it (a
    failure here is a problem too, but must not hide the ones found before)."""
    try:
        if shot is None:
            raise LookupError("no screenshot wanted")
        t0 = time.monotonic()
        screenshot(page, shot)
        name = shot.relative_to(ROOT) if shot.is_relative_to(ROOT) else shot
        log(f"  screenshot {name} ({time.monotonic() - t0:.1f} s)")
    except LookupError:
        pass
    except Exception as exc:
        problems.append(f"screenshot failed: {exc}")
    try:
        page.evaluate(js("shutdown_kernel"))
    except Exception:
        pass
    page.close()
