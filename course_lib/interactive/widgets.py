r"""What every explorer is made of: sliders above a live 3D figure, and its still picture.

**Turn it with the mouse.** An explorer is a few sliders above a live matplotlib figure drawn
by ``ipympl``, matplotlib's own Jupyter widget backend: drag the 3D view to look at it from
any side (the toolbar's home button goes back to the first view). Only the explorer's own
figure lives on an ipympl canvas; the notebook's backend and every other figure stay as they
are (static PNGs). Releasing a slider (``continuous_update=False``) redraws the figure in
place, keeping the camera the mouse chose.

**Stored output.** Displayed, an explorer gives the live widget view plus a PNG snapshot of
its first figure and a one-line text description, which pages without a kernel (the repository
viewer, a static site) show instead. The widget model ids are random on every run, so the
notebooks mark these cells ``NBVAL_IGNORE_OUTPUT``. Executed headless (nbval, nbconvert) no
browser ever attaches to the canvas, and nothing waits for one. There is no ``Output`` widget:
nbclient (nbconvert --execute) mimics that one by sending comm messages on the shell channel
from its output task while its reply task waits on the same socket, a race in which a cell can
wait for its reply until the timeout (jupyter/nbclient#312).
"""

import base64
import html
import io
import warnings

import ipywidgets
import matplotlib.pyplot as plt
from matplotlib.figure import Figure

from .. import plotting
from .._arrays import as_angles
from ..plotting.display import FIGURE_CLASS

__all__ = ["VIEW_ELEV", "VIEW_AZIM", "SliderSpec", "Explorer"]

#: Default camera of the 3D views, in degrees (``view_init``): the view of ``plotting.axes3d``.
VIEW_ELEV = 20.0
VIEW_AZIM = -60.0

_SLIDER_STEP = 0.01
_EXPLORER_SIZE = (5.2, 4.8)  # inches at plotting.DPI: 520 x 480 px on the page
# Turned by the mouse to look from below, the cube's tick labels go to its top: a little
# smaller, it keeps them clear of the title at every camera.
_EXPLORER_ZOOM = 0.9
_SNAPSHOT_COLORS = 96  # stored snapshots and animation frames are palette PNGs: fewer bytes


def _single(x, name, what="angle (a number)"):
    """A single finite real number; the message says what kind of number ``name`` is."""
    a = as_angles(x, name)
    if a.shape != ():
        raise ValueError(f"{name} must be a single {what}, got shape {a.shape}")
    return float(a)


def _scalar_angle(x, name):
    return _single(x, name)


def _view_angle(x, name):
    """A camera angle in degrees: a single finite real number (any value, as ``view_init``)."""
    return _single(x, name, "viewing angle in degrees (a number)")


class SliderSpec:
    """One slider of an explorer: its label, first value, range, step and unit.

    Parameters
    ----------
    description : str
        The slider's label, also the key of ``Explorer.sliders``.
    value : float
        The first value, inside ``bounds``.
    bounds : tuple of float
        (lowest, highest) value.
    step : float, default 0.01
    unit : str, default "radians"
        Named in the message when ``value`` is out of range.
    readout_format : str, default ".2f"
        How the slider prints its value.
    """

    def __init__(
        self, description, value, bounds, step=_SLIDER_STEP, unit="radians", readout_format=".2f"
    ):
        self.description, self.value, self.bounds = description, value, bounds
        self.step, self.unit, self.readout_format = step, unit, readout_format


# WCAG 2.4.7: a focus ring the keyboard user sees on the slider handles and the 3D view
# (ipywidgets' own focus style on a handle is a faint shadow; #1a5fb4 is 6.4:1 on white).
# WCAG 1.4.11: ipywidgets' slider track and handle border (#c8c8c8 / #8a8a8a on white, 1.88:1)
# drawn in #6b6b6b (5.3:1), the filled part in #1a5fb4. Scoped to the explorers.
_FOCUS_STYLE = (
    "<style>.course-explorer .noUi-handle:focus, .course-explorer .widget-readout:focus, "
    ".course-explorer .jupyter-matplotlib-canvas-div:focus "
    "{outline: 3px solid #1a5fb4; outline-offset: 2px;}"
    ".course-explorer .noUi-target, .course-explorer .noUi-base "
    "{background: #fff; border: 1px solid #6b6b6b;}"
    ".course-explorer .noUi-connect {background: #1a5fb4;}"
    ".course-explorer .noUi-handle {border: 2px solid #6b6b6b; background: #fff;}"
    ".course-explorer .course-keys {color: #3d3d3d; margin: 0.2em 0;}</style>"
)
#: What the keyboard does on the 3D view, shown under it and said by its accessible name.
KEYS_HELP = "3D view: arrow keys turn it, + and − zoom in and out; Tab and Shift+Tab leave it."
_TURN_STEP = 10.0  # degrees per arrow key
_ZOOM_STEP = 1.15  # per + or − key
_ZOOM_RANGE = (0.5, 2.0)


# WCAG 4.1.2: ipywidgets 8 draws a FloatSlider's handle as a noUiSlider <div role="slider"> and
# its description as a <label> tied to nothing: a screen reader hears the value, not the name.
# The model has no trait that reaches the handle, so this script (run by JupyterLab for the
# trusted output of a cell just run, next to the explorer) names every handle of the explorers
# after its slider's label, now and whenever ipywidgets redraws one.
# WCAG 2.1.2 (no keyboard trap): ipympl's canvas <div tabindex=0> calls preventDefault() and
# stopPropagation() on every keydown, Tab included, to send the key to the kernel: focus could
# enter the 3D view and never leave. A capture-phase listener on the explorer lets Tab and
# Shift+Tab do what they do everywhere (it stops the event before ipympl sees it, without
# preventing its default), and Escape leaves the view (blur). The other keys go on to ipympl,
# and to Explorer._on_key in the kernel (arrow keys turn the view, + and − zoom). The view gets
# role "application" and a name saying so (KEYS_HELP). Installed once a page.
#: Output metadata key of that script's output (instructor/build/notebooks.py does not store it).
SLIDER_NAMES = "course_slider_names"
_SLIDER_NAMES_JS = """
(function () {
  if (window.courseSliderNames) { window.courseSliderNames(); return; }
  var pending = false;
  var CANVAS = '.jupyter-matplotlib-canvas-div';
  function keys(event) {
    var view = event.target.closest && event.target.closest(CANVAS);
    if (!view) return;
    if (event.key === 'Tab') { event.stopPropagation(); }
    else if (event.key === 'Escape') { event.stopPropagation(); view.blur(); }
  }
  function name() {
    pending = false;
    document.querySelectorAll('.course-explorer').forEach(function (box) {
      box.querySelectorAll('.widget-slider').forEach(function (slider) {
        var label = slider.querySelector('.widget-label');
        var text = label ? label.textContent.trim() : '';
        slider.querySelectorAll('.noUi-handle').forEach(function (handle) {
          if (text && handle.getAttribute('aria-label') !== text) {
            handle.setAttribute('aria-label', text);
          }
        });
      });
      var help = box.querySelector('.course-keys');
      box.querySelectorAll(CANVAS).forEach(function (view) {
        var text = help ? (help.getAttribute('data-state') || '') + ' ' +
          help.textContent.trim() : '';
        if (view.getAttribute('aria-label') !== text) {
          view.setAttribute('role', 'application');
          view.setAttribute('aria-label', text.trim());
        }
      });
      if (!box.courseKeys) {
        box.addEventListener('keydown', keys, true);
        box.addEventListener('keyup', keys, true);
        box.courseKeys = true;
      }
    });
  }
  window.courseSliderNames = name;
  new MutationObserver(function () {
    if (!pending) { pending = true; window.requestAnimationFrame(name); }
  }).observe(document.body, {childList: true, subtree: true});
  name();
})();
"""


def _slider(spec):
    lo, hi = spec.bounds
    value = _scalar_angle(spec.value, spec.description)
    if not lo <= value <= hi:
        raise ValueError(
            f"{spec.description} = {value:g} is outside the slider range "
            f"[{lo:.4g}, {hi:.4g}] ({spec.unit})"
        )
    return ipywidgets.FloatSlider(
        value=value,
        min=lo,
        max=hi,
        step=spec.step,
        description=spec.description,
        continuous_update=False,
        readout_format=spec.readout_format,
        style={"description_width": "8em"},
        layout=ipywidgets.Layout(width="30em"),
    )


def _ipympl_classes():
    """ipympl's canvas and figure manager, imported without switching pyplot's backend.

    ``import ipympl`` calls ``matplotlib.use("module://ipympl.backend_nbagg")`` when matplotlib
    is loaded: every later ``plt.show()`` of the notebook would then make a widget instead of
    a PNG. The backend the notebook had (or the unresolved default) is put back.
    (Switching backends closes pyplot's open figures, as ``import ipympl`` itself does.)
    """
    import sys

    if "ipympl.backend_nbagg" not in sys.modules:
        import matplotlib
        from matplotlib import rcsetup

        if "matplotlib.pyplot" in sys.modules:
            # Load the notebook's backend first: the inline backend hooks itself into IPython
            # when it is loaded as the current backend, and would not after the switch back.
            plt._get_backend_mod()
        backend = matplotlib.rcParams._get_backend_or_none()  # None: not chosen yet
        fallback = matplotlib.rcParams["backend_fallback"]
        import ipympl.backend_nbagg  # noqa: F401

        if backend is None:
            matplotlib.rcParams["backend"] = rcsetup._auto_backend_sentinel
        else:
            matplotlib.use(backend)
        matplotlib.rcParams["backend_fallback"] = fallback
    from ipympl.backend_nbagg import Canvas, FigureManager

    return Canvas, FigureManager


def _canvas_figure(figsize):
    """A figure on an ipympl canvas of its own, outside pyplot (no backend is switched).

    The canvas is a widget: matplotlib's 3D mouse rotation runs in the kernel and the browser
    shows the redrawn image.
    """
    Canvas, FigureManager = _ipympl_classes()
    fig = Figure(figsize=figsize, dpi=plotting.DPI)
    canvas = Canvas(fig)
    with warnings.catch_warnings():
        # ipympl 0.10's own toolbar passes its canvas on to traitlets, which warns about it
        warnings.filterwarnings(
            "ignore", r"Passing unrecognized arguments to super\(Toolbar\)", DeprecationWarning
        )
        manager = FigureManager(canvas, 0)  # not registered with pyplot: never shown again
    if manager.key_press_handler_id is not None:
        # matplotlib's own keys ("s" saves, "q" closes, "l" log scale...): Explorer has its own
        canvas.mpl_disconnect(manager.key_press_handler_id)
    canvas.header_visible = False  # no "Figure 0" line above the figure
    canvas.footer_visible = False  # no "x pane=1.2, y=..." cursor read-out below it
    canvas.resizable = False
    return fig


def _explorer_figure():
    """(figure, None) on a live ipympl canvas, or (plain figure, why) where ipympl is missing."""
    try:
        return _canvas_figure(_EXPLORER_SIZE), None
    except ImportError as err:
        why = (
            f"A still picture: the live explorer needs {err.name or 'ipympl'}, which is not "
            "installed here (pip install ipympl, then restart the kernel)."
        )
        return Figure(figsize=_EXPLORER_SIZE, dpi=plotting.DPI), why


def _palette_png(fig, colors=_SNAPSHOT_COLORS, **savefig_kwargs):
    """The figure as a palette PNG: the same picture in a third of the bytes or less."""
    from PIL import Image

    buf = io.BytesIO()
    fig.savefig(buf, format="png", **savefig_kwargs)
    out = io.BytesIO()
    Image.open(buf).convert("RGB").quantize(colors).save(out, format="png", optimize=True)
    return out.getvalue()


class Explorer(ipywidgets.VBox):
    r"""Sliders above a 3D view that turns with the mouse, redrawn when a slider is released.

    Built by :func:`~course_lib.interactive.rotation_explorer`,
    :func:`~course_lib.interactive.rodrigues_explorer` and
    :func:`~course_lib.interactive.gimbal_explorer`. Releasing a slider redraws the figure in
    place with ``draw(ax, *values, elev=, azim=)``, at the camera the mouse left it at.
    ``result`` holds what the drawing computed (``pick(drawn)``).

    Parameters
    ----------
    draw : callable
        ``draw(ax, *values, elev=, azim=)`` draws onto the 3D axes and returns a
        :class:`course_lib.plotting.Drawn`.
    pick : callable
        ``pick(drawn)``: what ``result`` holds.
    title : callable
        ``title(*values)``: the figure's title.
    description : str
        One line saying what the explorer shows.
    sliders : sequence of SliderSpec
    camera : tuple of float
        (elev, azim) of the first view, in degrees.
    lim : float
        Half the side of the plotted cube.
    readout : callable, optional
        ``readout(*values)``: LaTeX shown below the figure, rewritten on every redraw.
    alt : callable, optional
        ``alt(*values)``: what the figure shows at these values, in words (its alt text, with
        the camera added); default: the description's first part and the slider values.

    The 3D view also turns from the keyboard (:data:`KEYS_HELP`, shown under it): the arrow
    keys turn the camera by 10° (left/right: azimuth, up/down: elevation), + and − zoom.

    Attributes
    ----------
    sliders : dict of str to ipywidgets.FloatSlider
        The sliders, by description.
    figure : matplotlib.figure.Figure
        The live figure; ``figure.canvas`` is the ipympl canvas widget.
    ax : mpl_toolkits.mplot3d.axes3d.Axes3D
    readout : ipywidgets.HTMLMath or None
        A formula below the figure, rewritten on every redraw.
    result : numpy.ndarray
        What the current drawing computed.
    description : str
        One line saying what the explorer shows: the text pages without widgets display.
    """

    def __init__(
        self, draw, pick, title, description, sliders, camera, lim, readout=None, alt=None
    ):
        self.sliders = {s.description: _slider(s) for s in sliders}
        elev, azim = (_view_angle(a, n) for a, n in zip(camera, ("elev", "azim")))
        self.figure, self.why_still = _explorer_figure()
        self.figure.subplots_adjust(left=0.0, right=0.94, bottom=0.02, top=0.86)
        self.ax = self.figure.add_subplot(projection="3d")
        self._drawn = None
        self.description = description
        self._draw, self._pick, self._title, self._lim = draw, pick, title, lim
        self._readout, self._alt, self._zoom = readout, alt, _EXPLORER_ZOOM
        self.readout = ipywidgets.HTMLMath() if readout else None
        self.key_help = ipywidgets.HTML()
        children = []
        if self.live:
            children = [ipywidgets.HTML(_FOCUS_STYLE), *self.sliders.values()]
            children += [self.figure.canvas, self.key_help] + ([self.readout] if readout else [])
        super().__init__(children=children)
        self.add_class("course-explorer")
        self._redraw(elev, azim)
        self._update_readout()
        for slider in self.sliders.values():
            slider.observe(self._on_release, names="value")
        if self.live:
            self.figure.canvas.mpl_connect("key_press_event", self._on_key)
            # the camera the mouse left: in the view's accessible name too
            self.figure.canvas.mpl_connect("button_release_event", lambda _: self._update_keys())

    @property
    def live(self):
        """Whether the figure is a live widget (False: only its still picture can be shown)."""
        return self.why_still is None

    @property
    def values(self):
        """The current values of the sliders, in their order."""
        return tuple(float(s.value) for s in self.sliders.values())

    def _redraw(self, elev, azim):
        """Replace the drawing (not the axes: its ticks and panes are costly to rebuild)."""
        title = self._title(*self.values)
        if self._drawn is None:
            plotting.axes3d(title, ax=self.ax, lim=self._lim)
            self.ax.set_box_aspect((1, 1, 1), zoom=_EXPLORER_ZOOM)
        else:
            for artist in self._drawn:
                artist.remove()
            self.ax.set_title(title, fontsize=plotting.TITLE_SIZE)
        self._drawn = self._draw(self.ax, *self.values, elev=elev, azim=azim)
        self.result = self._pick(self._drawn)
        self._update_keys()

    def alt_text(self):
        """What the figure shows now, in words: the state the sliders and the camera chose.

        The still picture's alt text (stored in the notebook, on the site) and the 3D view's
        accessible name in a live session.
        """
        if self._alt is not None:
            what = self._alt(*self.values).strip()
        else:
            values = ", ".join(f"{k} = {s.value:.2f}" for k, s in self.sliders.items())
            what = f"{self.description.split(':')[0]} at {values}."
        elev, azim = (f"{a:.0f}".replace("-", "−") for a in (self.ax.elev, self.ax.azim))
        return f"{what.rstrip('.')}; seen from elevation {elev}°, azimuth {azim}°."

    def _update_keys(self):
        state = html.escape(self.alt_text(), quote=True)
        self.key_help.value = f'<p class="course-keys" data-state="{state}">{KEYS_HELP}</p>'

    def _on_key(self, event):
        """Arrow keys turn the camera by 10°, + and − zoom (the view's keyboard, KEYS_HELP)."""
        elev, azim = self.ax.elev, self.ax.azim
        turn = {"left": (0, -1), "right": (0, 1), "up": (1, 0), "down": (-1, 0)}
        if event.key in turn:
            de, da = turn[event.key]
            elev = max(-90.0, min(90.0, elev + de * _TURN_STEP))
            azim = (azim + da * _TURN_STEP + 180.0) % 360.0 - 180.0
            self.ax.view_init(elev=elev, azim=azim)
        elif event.key in ("+", "=", "-", "_", "−"):
            factor = _ZOOM_STEP if event.key in ("+", "=") else 1 / _ZOOM_STEP
            self._zoom = max(_ZOOM_RANGE[0], min(_ZOOM_RANGE[1], self._zoom * factor))
            self.ax.set_box_aspect((1, 1, 1), zoom=self._zoom)
        else:
            return
        self._update_keys()
        self.figure.canvas.draw()

    def _update_readout(self):
        if self.readout is not None:
            self.readout.value = "$$" + self._readout(*self.values) + "$$"

    def _on_release(self, change):
        self._redraw(self.ax.elev, self.ax.azim)
        # Render and send the image now: draw_idle() would first ask the browser for a redraw.
        # The readout comes after it: typesetting it would hold the browser up.
        self.figure.canvas.draw()
        self._update_readout()

    def snapshot(self):
        """The figure as it is now, as PNG bytes (a small palette image)."""
        return _palette_png(self.figure)

    def _ipython_display_(self):
        from IPython.display import display

        display(self._repr_mimebundle_(), raw=True)
        if self.live:
            display(
                {"application/javascript": _SLIDER_NAMES_JS},
                raw=True,
                metadata={SLIDER_NAMES: True},
            )

    def _repr_mimebundle_(self, **kwargs):
        """The widget view, and the still picture with its alt text for pages without a kernel.

        The still is an HTML ``<img>`` in :func:`course_lib.plotting.figure_output`'s form (alt
        text: :meth:`alt_text`, the state shown), not an ``image/png`` output: JupyterLab opens
        a stored notebook without the widget state and would show an ``image/png`` with no alt.
        """
        png = base64.b64encode(self.snapshot()).decode("ascii")
        alt = html.escape(" ".join(self.alt_text().split()), quote=True)
        img = f'<img class="{FIGURE_CLASS}" alt="{alt}" src="data:image/png;base64,{png}">'
        if not self.live:  # the still picture, and one line saying why
            return {
                "text/plain": f"{self.description}\n{self.why_still}",
                "text/html": f"{img}<p><em>{html.escape(self.why_still)}</em></p>",
            }
        data = super()._repr_mimebundle_(**kwargs)
        data["text/plain"] = self.description
        data["text/html"] = img
        return data
