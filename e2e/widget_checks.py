"""The checks on the widgets of a notebook in the browser: every slider of every explorer
redraws its figure when released (timed: release -> redrawn figure, by the page's clock), the
live figure turns when dragged with the mouse, and the formula readout is typeset.

``check_widgets(page, expected, problems, timeout)`` returns the latencies measured (ms) and can
save a screenshot of each widget.
"""

import time

from common import CheckFailed, js, log, poll

SLIDER_ROUNDS = 2  # each slider is dragged to the other side of its track and back
CANVAS_DRAG = (90, 45)  # pixels right and down


def check_widgets(page, expected, problems, timeout, shot_prefix=None):
    """Check every slider widget of the page; ``shot_prefix``: where to save a screenshot of
    each (``<prefix>-widget<k>.png``) after its checks. Returns the latencies (ms)."""
    n = page.evaluate(js("tag_widgets"))
    if expected and n == 0:
        problems.append(f"{expected} widget output(s) in the model but no slider on the page")
    latencies = []
    for k in range(n):
        # Seen as a student sees it: in view (JupyterLab does not render cells off screen).
        page.locator(f'[data-e2e-widget="{k}"]').scroll_into_view_if_needed()
        page.wait_for_timeout(300)
        labels = page.evaluate(js("widget_sliders"), k)
        first = page.evaluate(js("widget_figure"), [k, 0])
        if first["math"] and first["mathTypeset"] < first["math"]:
            problems.append(f"slider widget {k}: formula readout not typeset by MathJax")
        drags = [s for _ in range(SLIDER_ROUNDS) for s in range(len(labels))]
        for s in drags:
            latency = drag_and_check(page, k, s, labels[s], problems, timeout)
            if latency is None:
                break
            if latency >= 0:
                latencies.append(latency)
        if first["canvas"]:
            drag_canvas_and_check(page, k, problems, timeout)
        if shot_prefix is not None:
            shot = shot_prefix.with_name(f"{shot_prefix.name}-widget{k}.png")
            page.locator(f'[data-e2e-widget="{k}"]').screenshot(path=str(shot))
    return latencies


def drag_slider(page, k, s):
    """Drag slider ``s`` of widget k to the other side of its track and release it."""
    box = page.locator(f'[data-e2e-widget="{k}"]')
    slider = box.locator(".widget-slider").nth(s)
    slider.scroll_into_view_if_needed()
    track = slider.locator(".noUi-target, .slider").first.bounding_box()
    handle = slider.locator(".noUi-handle").first.bounding_box()
    if not track or not handle:
        raise CheckFailed(f"slider widget {k}: slider track or handle not found on the page")
    hx, hy = handle["x"] + handle["width"] / 2, handle["y"] + handle["height"] / 2
    left = (hx - track["x"]) / max(track["width"], 1.0) < 0.5
    tx = track["x"] + track["width"] * (0.8 if left else 0.2)
    page.mouse.move(hx, hy)
    page.mouse.down()
    page.mouse.move(tx, hy, steps=8)
    page.mouse.up()


def wait_for_new_figure(page, k, s, before, timeout, what):
    """Poll until widget k shows a figure other than ``before`` with the kernel idle."""

    def changed():
        now = page.evaluate(js("widget_figure"), [k, s])
        kernel = page.evaluate(js("state"))["kernel"]
        ok = now["loaded"] and now["src"] != before["src"] and kernel == "idle"
        return now if ok else None

    return poll(changed, timeout, what)


def drag_and_check(page, k, s, label, problems, timeout):
    """Drag slider ``s`` of widget k and check the figure is redrawn.

    Returns the release -> redrawn figure time in ms (-1 when the figure is not a live canvas,
    whose draws the page can time), or None when the check failed.
    """
    name = f"slider widget {k}, slider {s} ({label!r})"
    before = page.evaluate(js("widget_figure"), [k, s])
    if not before["loaded"]:
        problems.append(f"{name}: no figure displayed before moving the slider")
        return None
    drag_slider(page, k, s)
    try:
        after = wait_for_new_figure(page, k, s, before, timeout, f"the figure of {name} to change")
    except CheckFailed as exc:
        now = page.evaluate(js("widget_figure"), [k, s])
        problems.append(f"{name}: {exc} (readout {before['readout']} -> {now['readout']})")
        return None
    if after["readout"] == before["readout"]:
        problems.append(f"{name}: the slider readout did not change")
        return None
    if after["stderr"]:
        problems.append(f"{name}: error output after moving the slider")
        return None
    latency = after["drawn"] - after["released"] if after["drawn"] else -1.0
    timing = f", redrawn {latency:.0f} ms after the release" if latency >= 0 else ", figure redrawn"
    log(f"  {name}: readout {before['readout']} -> {after['readout']}{timing}")
    return latency


def drag_canvas(page, k):
    """Press on the middle of widget k's live figure, drag it, release it.

    The moves are spaced out: the page sends at most one mouse move per 33 ms to the kernel
    (ipympl's throttle), and a release that overtook the last move would lose it.
    """
    box = page.evaluate(js("canvas_box"), k)
    if not box or box["width"] < 50 or box["height"] < 50:
        raise CheckFailed(f"slider widget {k}: its live figure is not on the page ({box})")
    x0, y0 = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x0, y0)
    page.mouse.down()
    steps = 10
    for i in range(1, steps + 1):
        page.mouse.move(x0 + CANVAS_DRAG[0] * i / steps, y0 + CANVAS_DRAG[1] * i / steps)
        page.wait_for_timeout(50)
    page.wait_for_timeout(100)
    page.mouse.up()


def drag_canvas_and_check(page, k, problems, timeout):
    """Drag widget k's figure with the mouse: the view must turn (the picture changes)."""
    name = f"slider widget {k}, figure"
    before = page.evaluate(js("widget_figure"), [k, 0])
    t0 = time.monotonic()
    try:
        drag_canvas(page, k)
        wait_for_new_figure(page, k, 0, before, timeout, f"{name} to turn when dragged")
    except CheckFailed as exc:
        problems.append(f"{name}: {exc}")
        return
    log(
        f"  {name}: dragged {CANVAS_DRAG[0]} px right and {CANVAS_DRAG[1]} px down, the 3D view "
        f"turned (new picture after {time.monotonic() - t0:.1f} s)"
    )
