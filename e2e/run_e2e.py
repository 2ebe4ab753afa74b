"""End-to-end check of the course notebooks in a real JupyterLab, driven by headless Chromium.

    python e2e/run_e2e.py [NOTEBOOKS_DIR] [--out DIR] [--timeout SECONDS]

(``make e2e`` runs it on ``notebooks/`` with the project's venv.) For every ``*.ipynb`` in
NOTEBOOKS_DIR the script

1. starts JupyterLab from this Python on a free localhost port with a random token, against a
   temporary COPY of the notebooks (nothing is ever saved into NOTEBOOKS_DIR) and a throw-away
   Jupyter configuration (``e2e/jupyter_config.json``, ``e2e/page_config.json``,
   ``e2e/setting_overrides.json``: no news pop-up, no build prompt, no autosave, all cells
   rendered);
2. opens the notebook in Chromium (the system's ``/usr/bin/chromium`` through Playwright),
   runs all cells and waits until every code cell has executed and the kernel is idle, reading
   the state from the notebook model (``window.jupyterapp``), not from the DOM;
3. checks: no dialog and no notification on screen; no error or stderr output anywhere (also
   inside widgets); every markdown cell with LaTeX typeset by MathJax (``mjx-container``, no
   ``mjx-merror``); every image output of the model displayed as a loaded ``<img>``; every
   image inside HTML outputs loaded (the JavaScript animation player); every widget rendered,
   and in every slider widget, dragging the first slider changes the figure, and so does
   dragging each camera slider (labelled ``view ...``: the 3D view turns);
4. saves a full-page screenshot to ``build/e2e/<notebook>.png``.

The server, its kernels and the browser are stopped in ``finally`` blocks, also when a check
fails or the run is interrupted. Exit status 0 when every check passed, 1 otherwise.
"""

import argparse
import io
import json
import os
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.parse
import urllib.request
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
CHROMIUM = Path("/usr/bin/chromium")
CHROMIUM_FLAGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]
VIEWPORT = {"width": 1280, "height": 900}
MAX_SCREENSHOT_HEIGHT = 16000  # Chromium's texture limit is a little above this
POLL = 0.5


class CheckFailed(Exception):
    """A check on a notebook failed; the message says which and why."""


# A notebook whose first cell has not started this long after "run all" is stalled, not slow.
NO_START_SECONDS = 40


class KernelStalled(CheckFailed):
    """The notebook's kernel never became idle, or never ran the queued cells.

    Seen intermittently on this machine for the first notebook a fresh server opens (cells stay
    queued as [*] with the kernel shown idle). A student would reload the page; the runner retries
    the notebook once with a fresh page and kernel, and says so in its log.
    """


def log(msg):
    print(f"[e2e] {msg}", flush=True)


# --------------------------------------------------------------------------------------------
# The JupyterLab server
# --------------------------------------------------------------------------------------------


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def port_open(port):
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.settimeout(0.5)
        return s.connect_ex(("127.0.0.1", port)) == 0


def write_jupyter_config(config_dir):
    """The throw-away JUPYTER_CONFIG_DIR: server options, page config and setting overrides."""
    labconfig = config_dir / "labconfig"
    labconfig.mkdir(parents=True)
    shutil.copy(HERE / "jupyter_config.json", config_dir / "jupyter_config.json")
    shutil.copy(HERE / "page_config.json", labconfig / "page_config.json")
    shutil.copy(HERE / "setting_overrides.json", labconfig / "default_setting_overrides.json")


class Server:
    """JupyterLab in its own process group, with everything it writes under ``tmp``."""

    def __init__(self, tmp, root_dir):
        self.port = free_port()
        self.token = secrets.token_hex(24)
        self.url = f"http://127.0.0.1:{self.port}"
        self.log_path = tmp / "jupyterlab.log"
        config_dir = tmp / "config"
        write_jupyter_config(config_dir)
        env = dict(os.environ)
        env.update(
            JUPYTER_CONFIG_DIR=str(config_dir),
            JUPYTER_DATA_DIR=str(tmp / "data"),
            JUPYTER_RUNTIME_DIR=str(tmp / "runtime"),
            JUPYTER_PLATFORM_DIRS="1",
            IPYTHONDIR=str(tmp / "ipython"),
            BROWSER="true",
        )
        cmd = [
            sys.executable, "-m", "jupyterlab",
            "--no-browser",
            "--ServerApp.ip=127.0.0.1",
            f"--ServerApp.port={self.port}",
            "--ServerApp.port_retries=0",
            f"--IdentityProvider.token={self.token}",
            f"--ServerApp.root_dir={root_dir}",
        ]
        if hasattr(os, "geteuid") and os.geteuid() == 0:
            cmd.append("--allow-root")
        self.log_file = open(self.log_path, "w")
        self.proc = subprocess.Popen(
            cmd, cwd=root_dir, env=env, stdout=self.log_file, stderr=subprocess.STDOUT,
            stdin=subprocess.DEVNULL, start_new_session=True,
        )
        self.kernel_pids = set()

    def api(self, path, method="GET", timeout=5.0):
        req = urllib.request.Request(
            self.url + path, method=method, headers={"Authorization": f"token {self.token}"},
            data=b"" if method == "POST" else None,
        )
        with urllib.request.urlopen(req, timeout=timeout) as resp:
            body = resp.read()
        return json.loads(body) if body else None

    def wait_ready(self, timeout=90.0):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.proc.poll() is not None:
                raise CheckFailed(f"JupyterLab exited with status {self.proc.returncode}:\n{self.log_tail()}")
            try:
                self.api("/api/status")
                return
            except (urllib.error.URLError, ConnectionError, TimeoutError):
                time.sleep(POLL)
        raise CheckFailed(f"JupyterLab did not answer within {timeout:.0f} s:\n{self.log_tail()}")

    def log_tail(self, lines=40):
        try:
            return "\n".join(self.log_path.read_text(errors="replace").splitlines()[-lines:])
        except OSError:
            return "(no log)"

    def note_kernels(self):
        """Remember the pids of the server's child processes (the kernels), to check at exit."""
        for pid in children_of(self.proc.pid):
            self.kernel_pids.add(pid)

    def stop(self):
        """Shut the server down (kernels first), then make sure nothing of it is left."""
        if self.proc.poll() is None:
            self.note_kernels()
            try:
                self.api("/api/shutdown", method="POST")
            except (urllib.error.URLError, ConnectionError, TimeoutError):
                pass
            try:
                self.proc.wait(timeout=20)
            except subprocess.TimeoutExpired:
                pass
        for sig, wait in ((signal.SIGTERM, 5), (signal.SIGKILL, 5)):
            if self.proc.poll() is not None:
                break
            try:
                os.killpg(self.proc.pid, sig)
            except ProcessLookupError:
                break
            try:
                self.proc.wait(timeout=wait)
            except subprocess.TimeoutExpired:
                pass
        # Kernels run in sessions of their own: end any that survived the shutdown, by pid.
        for pid in sorted(self.kernel_pids):
            if alive(pid):
                try:
                    os.kill(pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
        self.log_file.close()
        left = [pid for pid in self.kernel_pids if alive(pid)]
        if self.proc.poll() is None or left or port_open(self.port):
            raise CheckFailed(
                f"cleanup incomplete: server alive={self.proc.poll() is None}, kernels left={left}, "
                f"port {self.port} listening={port_open(self.port)}"
            )


def children_of(pid):
    """Pids of the direct children of ``pid`` (Linux /proc)."""
    kids = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text()
        except OSError:
            continue
        # the second field may contain spaces: parse after the closing parenthesis
        fields = stat[stat.rfind(")") + 2:].split()
        if int(fields[1]) == pid:
            kids.append(int(entry.name))
    return kids


def alive(pid):
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return False
    return stat[stat.rfind(")") + 2:].split()[0] != "Z"


# --------------------------------------------------------------------------------------------
# JavaScript run inside the page (the notebook model is read through window.jupyterapp)
# --------------------------------------------------------------------------------------------

JS_FIND_NOTEBOOK = """(path) => {
  const app = window.jupyterapp;
  if (!app || !app.shell) return false;
  for (const w of app.shell.widgets('main')) {
    if (w.context && w.context.path === path && w.content && w.content.model) {
      if (!w.context.isReady) return false;
      const kernel = w.sessionContext.session && w.sessionContext.session.kernel;
      if (!kernel || kernel.status !== 'idle') return false;
      window.__e2e_nb = w;
      app.shell.activateById(w.id);
      app.shell.collapseLeft();  // the file browser adds nothing to the screenshots
      return true;
    }
  }
  return false;
}"""

JS_RUN_ALL = """() => {
  // started, not awaited: the promise resolves only when every cell has run
  window.jupyterapp.commands.execute('notebook:run-all-cells');
  return true;
}"""

JS_STATE = """() => {
  const w = window.__e2e_nb;
  const kernel = w.sessionContext.session && w.sessionContext.session.kernel;
  const cells = [];
  const model = w.content.model;
  for (let i = 0; i < model.cells.length; i++) {
    const c = model.cells.get(i);
    const info = {type: c.type, source: c.sharedModel.getSource()};
    if (c.type === 'code') {
      info.count = c.executionCount;
      info.state = c.executionState || null;
      info.outputs = [];
      for (let j = 0; j < c.outputs.length; j++) {
        const o = c.outputs.get(j).toJSON();
        const mimes = Object.keys(o.data || {});
        let text = '';
        if (o.output_type === 'error') text = o.ename + ': ' + o.evalue;
        else if (o.output_type === 'stream') text = Array.isArray(o.text) ? o.text.join('') : o.text;
        info.outputs.push({type: o.output_type, name: o.name || null, mimes: mimes, text: text});
      }
    }
    cells.push(info);
  }
  return {kernel: kernel ? kernel.status : 'none', cells: cells};
}"""

# Per cell: what the DOM shows. Output children map one-to-one onto the model's outputs.
JS_DOM = """() => {
  const w = window.__e2e_nb;
  const cells = [];
  w.content.widgets.forEach((cell, i) => {
    const node = cell.node;
    const info = {
      mjx: node.querySelectorAll('.jp-MarkdownOutput mjx-container').length,
      merror: node.querySelectorAll('mjx-merror').length,
      rendered: node.classList.contains('jp-mod-rendered'),
      outputs: [],
    };
    const area = node.querySelector('.jp-OutputArea');
    if (area) {
      for (const child of area.querySelectorAll(':scope > .jp-OutputArea-child')) {
        const imgs = Array.from(child.querySelectorAll('img'));
        const own = imgs.filter(im => !im.closest('.jupyter-widgets'));
        const widget = child.querySelector('.jupyter-widgets');
        info.outputs.push({
          imgs: own.length,
          loaded: own.filter(im => im.complete && im.naturalWidth > 0).length,
          widget: !!widget,
          widgetText: widget ? widget.innerText.slice(0, 200) : '',
          sliders: child.querySelectorAll('.widget-slider').length,
          widgetImgs: imgs.length - own.length,
          widgetLoaded: imgs.filter(im => im.closest('.jupyter-widgets') && im.complete && im.naturalWidth > 0).length,
        });
      }
    }
    cells.push(info);
  });
  const errs = Array.from(document.querySelectorAll(
    '.jp-NotebookPanel [data-mime-type="application/vnd.jupyter.stderr"]'));
  const broken = Array.from(document.querySelectorAll('.jp-NotebookPanel img'))
    .filter(im => im.complete && im.naturalWidth === 0 && im.getAttribute('src'));
  return {
    cells: cells,
    stderr: errs.map(e => e.innerText.slice(0, 500)),
    broken: broken.map(im => (im.getAttribute('src') || '').slice(0, 80)),
    widgetErrors: Array.from(document.querySelectorAll('.jp-NotebookPanel .jupyter-widgets'))
      .map(e => e.innerText).filter(t => t.includes('Error displaying widget')
        || t.includes('Error rendering widget') || t.includes('model not found')),
  };
}"""

JS_OVERLAYS = """() => {
  const texts = sel => Array.from(document.querySelectorAll(sel))
    .filter(e => e.offsetParent !== null || getComputedStyle(e).position === 'fixed')
    .map(e => e.innerText.trim().slice(0, 300));
  return {dialogs: texts('.jp-Dialog'), toasts: texts('.Toastify__toast')};
}"""

JS_TAG_WIDGETS = """() => {
  // Tag every slider widget (an interact box) so Playwright can address it.
  const w = window.__e2e_nb;
  const boxes = Array.from(w.content.node.querySelectorAll('.jp-OutputArea-child .jupyter-widgets'))
    .filter(b => b.querySelector('.widget-slider') && !b.parentElement.closest('.jupyter-widgets'));
  boxes.forEach((b, k) => b.setAttribute('data-e2e-widget', String(k)));
  return boxes.length;
}"""

JS_WIDGET_SLIDERS = """(k) => {
  // The labels (descriptions) of the sliders of widget k, in order.
  const box = document.querySelector(`[data-e2e-widget="${k}"]`);
  return box ? Array.from(box.querySelectorAll('.widget-slider')).map(s => {
    const label = s.querySelector('.widget-label');
    return label ? label.innerText.trim() : '';
  }) : [];
}"""

JS_WIDGET_FIGURE = """([k, s]) => {
  // The figure of widget k and the readout of its slider s.
  const box = document.querySelector(`[data-e2e-widget="${k}"]`);
  const img = box && box.querySelector('img');
  const slider = box && box.querySelectorAll('.widget-slider')[s];
  const readout = slider && slider.querySelector('.widget-readout');
  return {
    src: img ? img.getAttribute('src') : null,
    loaded: !!(img && img.complete && img.naturalWidth > 0),
    readout: readout ? readout.innerText : null,
    stderr: box ? box.querySelectorAll('[data-mime-type="application/vnd.jupyter.stderr"]').length : 0,
  };
}"""

MATH_MARKERS = ("$", "\\(", "\\[", "\\begin{")


def has_math(source):
    return any(m in source for m in MATH_MARKERS)


# --------------------------------------------------------------------------------------------
# Checks on one notebook
# --------------------------------------------------------------------------------------------


def poll(fn, timeout, what):
    """Call ``fn`` until it returns something truthy; CheckFailed after ``timeout`` seconds."""
    deadline = time.monotonic() + timeout
    last = None
    while time.monotonic() < deadline:
        last = fn()
        if last:
            return last
        time.sleep(POLL)
    raise CheckFailed(f"timed out after {timeout:.0f} s waiting for {what}")


def wait_for_run(page, timeout):
    """Wait until every non-empty code cell ran (or one failed) and the kernel is idle."""
    stable = {"n": 0}
    start = time.monotonic()

    def done():
        state = page.evaluate(JS_STATE)
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
        if (finished or errored) and not busy:
            stable["n"] += 1
        else:
            stable["n"] = 0
        return state if stable["n"] >= 3 else None  # idle on three polls in a row

    try:
        return poll(done, timeout, "all cells to run and the kernel to go idle")
    except CheckFailed as exc:
        raise KernelStalled(str(exc)) from None


def check_outputs(state, problems):
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
    """MathJax, figures and widgets, as displayed. Waits for typesetting and images to load."""

    def settled():
        dom = page.evaluate(JS_DOM)
        missing = dom_problems(state, dom)
        return (dom, []) if not missing else None

    try:
        dom, _ = poll(settled, timeout, "math, figures and widgets to render")
    except CheckFailed:
        dom = page.evaluate(JS_DOM)
        problems.extend(dom_problems(state, dom))
    for text in dom["stderr"]:
        problems.append(f"error/stderr shown on the page: {text[:300]!r}")
    for src in dom["broken"]:
        problems.append(f"image failed to load: {src}")
    for text in dom["widgetErrors"]:
        problems.append(f"widget failed to render: {text[:300]!r}")
    return dom


def dom_problems(state, dom):
    out = []
    if len(dom["cells"]) != len(state["cells"]):
        return [f"{len(dom['cells'])} cells on the page, {len(state['cells'])} in the model"]
    for i, (cell, shown) in enumerate(zip(state["cells"], dom["cells"])):
        if cell["type"] == "markdown" and has_math(cell["source"]):
            if shown["mjx"] == 0:
                out.append(f"markdown cell {i} has LaTeX but no MathJax output (mjx-container)")
            if shown["merror"]:
                out.append(f"markdown cell {i}: {shown['merror']} MathJax error(s) (mjx-merror)")
        if cell["type"] != "code":
            continue
        if len(shown["outputs"]) != len(cell["outputs"]):
            out.append(f"cell {i}: {len(cell['outputs'])} outputs in the model, "
                       f"{len(shown['outputs'])} on the page")
            continue
        for j, (o, d) in enumerate(zip(cell["outputs"], shown["outputs"])):
            images = [m for m in o["mimes"] if m.startswith("image/")]
            widget = "application/vnd.jupyter.widget-view+json" in o["mimes"]
            if widget:
                if not d["widget"]:
                    out.append(f"cell {i} output {j}: widget not rendered")
                elif d["sliders"] and d["widgetLoaded"] == 0:
                    out.append(f"cell {i} output {j}: slider widget shows no figure")
            elif images and d["loaded"] < 1:
                out.append(f"cell {i} output {j}: image output ({images[0]}) not displayed")
            elif "text/html" in o["mimes"] and d["loaded"] < d["imgs"]:
                out.append(f"cell {i} output {j}: {d['imgs'] - d['loaded']} image(s) of an HTML "
                           "output not loaded")
    return out


def check_overlays(page, problems, when):
    overlays = page.evaluate(JS_OVERLAYS)
    for text in overlays["dialogs"]:
        problems.append(f"dialog on screen {when}: {text!r}")
    for text in overlays["toasts"]:
        problems.append(f"notification on screen {when}: {text!r}")


def drag_slider(page, k, s=0):
    """Drag slider ``s`` (default: the first) of widget k to the other side of its track."""
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


def check_sliders(page, state, problems, timeout):
    expected = sum(
        1 for c in state["cells"] if c["type"] == "code"
        for o in c["outputs"] if "application/vnd.jupyter.widget-view+json" in o["mimes"]
    )
    n = page.evaluate(JS_TAG_WIDGETS)
    if expected and n == 0:
        problems.append(f"{expected} widget output(s) in the model but no slider on the page")
    for k in range(n):
        labels = page.evaluate(JS_WIDGET_SLIDERS, k)
        # The first slider (a parameter of the figure) and every camera slider ("view elev",
        # "view azim": they turn the 3D view); each of them must redraw the figure.
        to_drag = [0] + [s for s, label in enumerate(labels) if s > 0 and label.startswith("view ")]
        for s in to_drag:
            if not drag_and_check(page, k, s, labels[s] if s < len(labels) else "?", problems,
                                  timeout):
                break
    return n


def drag_and_check(page, k, s, label, problems, timeout):
    """Drag slider ``s`` of widget k; check the figure is redrawn. False if it is not."""
    name = f"slider widget {k}, slider {s} ({label!r})"
    before = page.evaluate(JS_WIDGET_FIGURE, [k, s])
    if not before["loaded"]:
        problems.append(f"{name}: no figure displayed before moving the slider")
        return False
    drag_slider(page, k, s)

    def changed():
        now = page.evaluate(JS_WIDGET_FIGURE, [k, s])
        kernel = page.evaluate(JS_STATE)["kernel"]
        ok = now["loaded"] and now["src"] != before["src"] and kernel == "idle"
        return now if ok else None

    try:
        after = poll(changed, timeout, f"the figure of {name} to change")
    except CheckFailed as exc:
        now = page.evaluate(JS_WIDGET_FIGURE, [k, s])
        problems.append(f"{name}: {exc} (readout {before['readout']} -> {now['readout']})")
        return False
    ok = True
    if after["readout"] == before["readout"]:
        problems.append(f"{name}: the slider readout did not change")
        ok = False
    if after["stderr"]:
        problems.append(f"{name}: error output after moving the slider")
        ok = False
    log(f"  {name}: readout {before['readout']} -> {after['readout']}, figure redrawn")
    return ok


JS_SCROLLER = """(top) => {
  // The element that scrolls the notebook: the notebook node or, in JupyterLab 4, its outer
  // panel. Optionally scroll it to ``top``; report its geometry.
  const w = window.__e2e_nb;
  if (!w) return null;
  const nodes = [w.content.node, ...w.content.node.querySelectorAll('.jp-WindowedPanel-outer')];
  const el = nodes.reduce((a, b) => (b.scrollHeight > a.scrollHeight ? b : a));
  if (top !== null) {
    for (const n of nodes) n.scrollTop = 0;
    el.scrollTop = top;
    if (document.activeElement) document.activeElement.blur();
  }
  const r = el.getBoundingClientRect();
  return {scrollHeight: el.scrollHeight, clientHeight: el.clientHeight, scrollTop: el.scrollTop,
          top: Math.round(r.top), viewport: window.innerHeight};
}"""


def screenshot(page, path):
    """A PNG of the whole notebook, however long: JupyterLab, with the notebook unrolled.

    The viewport is made as tall as the notebook. A notebook taller than Chromium can capture
    in one go (``MAX_SCREENSHOT_HEIGHT``) is shot in tiles, scrolling the notebook between
    them, and the tiles are stacked into one image.
    """
    geo = page.evaluate(JS_SCROLLER, None)
    if geo is None:
        page.screenshot(path=str(path), full_page=True)
        return
    chrome = geo["viewport"] - geo["clientHeight"]
    height = int(min(max(geo["scrollHeight"] + chrome, VIEWPORT["height"]), MAX_SCREENSHOT_HEIGHT))
    page.set_viewport_size({"width": VIEWPORT["width"], "height": height})
    try:
        page.wait_for_timeout(1000)  # relayout
        geo = page.evaluate(JS_SCROLLER, 0)
        page.wait_for_timeout(500)
        if geo["scrollHeight"] <= geo["clientHeight"]:
            page.screenshot(path=str(path), full_page=True)
            return
        from PIL import Image  # Pillow comes with matplotlib

        top, view, total = geo["top"], geo["clientHeight"], geo["scrollHeight"]
        pieces, offset = [], 0
        while offset < total:
            geo = page.evaluate(JS_SCROLLER, offset)
            page.wait_for_timeout(400)
            shot = Image.open(io.BytesIO(page.screenshot()))
            skip = offset - geo["scrollTop"]  # the last tile stops short: drop what was shot
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
        sheet.save(path, optimize=True)
    finally:
        page.set_viewport_size(VIEWPORT)


def wait_for_open(page, rel_path, timeout):
    """Wait for the notebook's kernel to be idle; fail at once if a dialog asks for something.

    A dialog at this point is the kernel picker (no or unknown kernelspec in the notebook's
    metadata) or a build prompt: a student would see it too.
    """
    dialog_since = None

    from playwright.sync_api import Error as PlaywrightError

    def opened():
        nonlocal dialog_since
        try:
            if page.evaluate(JS_FIND_NOTEBOOK, rel_path):
                return True
            dialogs = page.evaluate(JS_OVERLAYS)["dialogs"]
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


def check_notebook(context, server, rel_path, out_dir, timeout):
    """Open, run and check one notebook.

    Returns the list of problems (empty: passed) and whether the kernel stalled.
    """
    from playwright.sync_api import Error as PlaywrightError

    problems = []
    stalled = False
    page = context.new_page()
    page_errors = []
    page.on("pageerror", lambda exc: page_errors.append(str(exc)))
    name = Path(rel_path).stem
    try:
        workspace = f"e2e-{secrets.token_hex(4)}"
        url = f"{server.url}/lab/workspaces/{workspace}/tree/{urllib.parse.quote(rel_path)}"
        page.goto(f"{url}?reset&token={server.token}")
        t0 = time.monotonic()
        wait_for_open(page, rel_path, timeout=90)
        check_overlays(page, problems, "after opening")
        page.evaluate(JS_RUN_ALL)
        state = wait_for_run(page, timeout)
        n_code = sum(1 for c in state["cells"] if c["type"] == "code")
        log(f"  ran {n_code} code cells in {time.monotonic() - t0:.1f} s")
        check_outputs(state, problems)
        dom = check_dom(page, state, problems, timeout=60)
        n_math = sum(c["mjx"] for c in dom["cells"])
        n_img = sum(o["loaded"] + o["widgetLoaded"] for c in dom["cells"] for o in c["outputs"])
        log(f"  {n_math} typeset formulas, {n_img} images displayed")
        check_sliders(page, state, problems, timeout=60)
        check_overlays(page, problems, "after running")
    except KernelStalled as exc:
        problems.append(str(exc))
        stalled = True
    except CheckFailed as exc:
        problems.append(str(exc))
    except PlaywrightError as exc:  # e.g. a slider that cannot be found or dragged
        problems.append(f"browser automation failed: {str(exc).splitlines()[0]}")
    finally:
        problems.extend(f"JavaScript error on the page: {e[:300]}" for e in page_errors)
        try:
            shot = out_dir / f"{name}.png"
            screenshot(page, shot)
            log(f"  screenshot {shot.relative_to(ROOT) if shot.is_relative_to(ROOT) else shot}")
        except Exception as exc:  # a failed screenshot must not hide the real problem
            problems.append(f"screenshot failed: {exc}")
        try:
            page.evaluate("() => window.__e2e_nb && window.__e2e_nb.sessionContext.shutdown()")
        except Exception:
            pass
        page.close()
    return problems, stalled


# --------------------------------------------------------------------------------------------
# Main
# --------------------------------------------------------------------------------------------


def _interrupt(signum, frame):
    raise KeyboardInterrupt(f"signal {signum}")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("notebooks", nargs="?", default=str(ROOT / "notebooks"),
                        help="directory of .ipynb files (default: notebooks/)")
    parser.add_argument("--out", default=str(ROOT / "build" / "e2e"),
                        help="where the screenshots go (default: build/e2e/)")
    parser.add_argument("--timeout", type=float, default=180.0,
                        help="seconds allowed to run all cells of one notebook (default 180)")
    args = parser.parse_args(argv)

    src = Path(args.notebooks).resolve()
    notebooks = sorted(p.relative_to(src) for p in src.glob("*.ipynb"))
    if not notebooks:
        log(f"no notebooks (*.ipynb) in {src}")
        return 1
    if not CHROMIUM.exists():
        log(f"{CHROMIUM} is missing: install Debian's chromium package (apt-get install chromium)")
        return 1
    out_dir = Path(args.out).resolve()
    out_dir.mkdir(parents=True, exist_ok=True)

    from playwright.sync_api import sync_playwright

    # SIGTERM (e.g. from a CI timeout) unwinds through the finally blocks like Ctrl-C does.
    signal.signal(signal.SIGTERM, _interrupt)

    results = {}
    tmp = Path(tempfile.mkdtemp(prefix="course-e2e-"))
    server = None
    try:
        work = tmp / "notebooks"
        shutil.copytree(src, work, ignore=shutil.ignore_patterns(".ipynb_checkpoints"))
        server = Server(tmp, work)
        server.wait_ready()
        log(f"JupyterLab on 127.0.0.1:{server.port}, {len(notebooks)} notebook(s) from a copy of {src.name}/")
        with sync_playwright() as pw:
            context = pw.chromium.launch_persistent_context(
                str(tmp / "chromium-profile"),
                executable_path=str(CHROMIUM),
                headless=True,
                args=CHROMIUM_FLAGS,
                viewport=VIEWPORT,
            )
            try:
                for nb in notebooks:
                    log(f"{nb}")
                    problems, stalled = check_notebook(context, server, nb.as_posix(), out_dir, args.timeout)
                    if problems:
                        # A browser on a shared machine flakes now and then (most often a kernel
                        # that never runs the queued cells): one retry, said out loud. A real
                        # defect fails twice and is reported with the second run's problems.
                        why = "kernel stalled" if stalled else "failed"
                        log(f"  {why}: {'; '.join(problems)}")
                        log("  retrying once with a fresh page and kernel")
                        problems, _ = check_notebook(context, server, nb.as_posix(), out_dir, args.timeout)
                    results[str(nb)] = problems
                    server.note_kernels()
            finally:
                context.close()
    except CheckFailed as exc:
        results["(setup)"] = [str(exc)]
    finally:
        if server is not None:
            try:
                server.stop()
            except CheckFailed as exc:
                results.setdefault("(cleanup)", []).append(str(exc))
        shutil.rmtree(tmp, ignore_errors=True)

    failed = {k: v for k, v in results.items() if v}
    for nb, problems in results.items():
        log(f"{'FAIL' if problems else 'ok  '} {nb}")
        for p in problems:
            log(f"       - {p}")
    if failed:
        log(f"{len(failed)} of {len(results)} failed")
        return 1
    log(f"all {len(results)} notebook(s) passed; screenshots in {out_dir}")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except KeyboardInterrupt as exc:
        log(f"interrupted ({exc or 'Ctrl-C'}); server and browser stopped")
        sys.exit(130)
