r"""The animation of chapter 03: a body frame spinning at unit angular velocity (eq. 125)."""

import base64
import re
import tempfile
from html import escape as html_escape
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
from matplotlib import animation

from .. import plotting
from .._arrays import as_count, as_direction, as_scalar
from ..rodrigues import spin_rotations, spin_times
from .rotation import _WORLD_AXES, _draw_axis_line, _moving_axes
from .widgets import _palette_png

__all__ = ["SPIN_PIXELS", "spin_animation"]

#: The frame width of :func:`spin_animation` by default, in pixels: below it the title and the
#: labels cannot be read.
SPIN_PIXELS = 360


class _PaletteHTMLWriter(animation.HTMLWriter):
    """matplotlib's JavaScript player, with palette PNG frames (the HTML is stored)."""

    def grab_frame(self, **savefig_kwargs):
        png = _palette_png(self.fig, dpi=self.dpi, **savefig_kwargs)
        self._saved_frames.append(base64.encodebytes(png).decode("ascii"))


def spin_animation(axis=(0.0, 0.0, 1.0), frames=16, duration=2.0 * np.pi, dpi=100, size=3.6):
    r"""An HTML animation of a body frame spinning at unit angular velocity about ``axis``.

    Frame :math:`k` shows the body frame :math:`R(t_k) = e^{\hat\omega t_k}` at time
    :math:`t_k` (:func:`course_lib.rodrigues.spin_times`,
    :func:`course_lib.rodrigues.spin_rotations`), the world frame (dotted), the axis and the
    circles that the body axis tips travel on. The player advances at one frame per
    :math:`T/N` seconds, so the picture turns at one radian per second: the angle is the time
    (eq. 125).

    Built with matplotlib's JavaScript player (``HTMLWriter``: the frames are palette PNGs
    embedded in the page, no ffmpeg); the figure is closed so no static copy is displayed as
    well. The player loads nothing from outside the page (its buttons are characters, not
    Font Awesome icons from a CDN) and shows the first frame before any script runs. The
    default frames are :data:`SPIN_PIXELS` = 360 pixels wide, the smallest at which the title
    and the labels can be read.

    Parameters
    ----------
    axis : array_like, shape (3,), default (0, 0, 1)
        Direction of the angular velocity (normalised).
    frames : int, default 16
        Number of frames (2 to 120).
    duration : float, default 2π
        Time covered, in seconds (= radians turned).
    dpi : int, default 100
        Resolution of the embedded frames (20 to 150).
    size : float, default 3.6
        Figure width and height in inches (1 to 8); ``size * dpi`` is the frame width in
        pixels (360 by default).

    Returns
    -------
    IPython.display.HTML
        The JavaScript player; its ``.data`` is the HTML text.

    Raises
    ------
    ValueError
        If ``axis`` is zero or not a 3-vector, or a size parameter is out of range.
    TypeError
        If ``frames`` or ``dpi`` is not an integer.

    Examples
    --------
    >>> html = spin_animation(frames=3)
    >>> html.data.count("data:image/png;base64")  # the three frames, and the first as the still
    4
    >>> "font-awesome" in html.data or "https://" in html.data  # nothing from outside the page
    False
    """
    from IPython.display import HTML

    frames = as_count(frames, "frames", minimum=2)
    if frames > 120:
        raise ValueError(
            f"frames must be at most 120 (the frames are stored in the notebook), got {frames}"
        )
    dpi = as_count(dpi, "dpi", minimum=20)
    if dpi > 150:
        raise ValueError(f"dpi must be between 20 and 150, got {dpi}")
    size = as_scalar(size, "size")
    if not 1.0 <= size <= 8.0:
        raise ValueError(f"size must be between 1 and 8 inches, got {size:g}")
    times = spin_times(frames, duration)
    rotations = spin_rotations(axis, times)
    w = as_direction(axis, "axis")
    fig, ax, clock = _spin_scene(w, size)
    body = []

    def update(k):
        for artist in body:
            artist.remove()
        body.clear()
        body.extend(plotting.draw_frame(ax, rotations[k], label="B"))
        clock.set_text(rf"$t = \theta = {times[k]:.2f}$")
        return body + [clock]

    interval_ms = 1000.0 * float(times[1] - times[0])
    anim = animation.FuncAnimation(fig, update, frames=frames, interval=interval_ms, blit=False)
    try:
        return HTML(_html_player(anim, 1000.0 / interval_ms, dpi, _spin_alt(w, duration)))
    finally:
        plt.close(fig)


def _spin_scene(w, size):
    """What stays still in the spin animation: world frame, axis, circles; and the clock text."""
    fig, ax = plotting.axes3d(r"Spinning at $\|\omega\| = 1$ rad/s", lim=1.1, figsize=(size, size))
    ax.set_axis_off()  # panes and ticks would change nothing but triple the stored size
    fig.subplots_adjust(left=0.0, right=1.0, bottom=0.0, top=0.92)
    plotting.draw_frame(ax, label=None, style="dotted", axis_names=_WORLD_AXES)
    _draw_axis_line(ax, w)
    for e, color in _moving_axes(w):
        plotting.draw_arc(ax, w, e, 2.0 * np.pi, color=color, style="dotted", arrow=False, n=72)
    clock = ax.text2D(0.5, 0.02, "", transform=ax.transAxes, ha="center")
    return fig, ax, clock


def _spin_alt(w, duration):
    """The alt text of every frame of the spin animation: what it shows, what to see in it."""
    axis = ", ".join(f"{c:.2g}" for c in w)
    return (
        f"A body frame B spinning about the axis ({axis}) at 1 radian per second for "
        f"{duration:.2f} seconds; the world frame is dotted. Each frame shows B at time t, "
        "turned by the angle t: the tips of its axes travel on the dotted circles around the "
        "axis, and the axis itself does not move."
    )


def _html_player(anim, fps, dpi, alt):
    """The HTML text of matplotlib's JavaScript player for ``anim``, palette PNG frames inside.

    It never plays by itself: it shows the first frame until Play is pressed, and Pause stops it.
    """
    writer = _PaletteHTMLWriter(fps=fps, embed_frames=True, default_mode="loop")
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp, "spin.html")
        anim.save(str(path), writer=writer, dpi=dpi)
        return _offline_player(path.read_text(), alt)


# matplotlib's player draws its buttons with Font Awesome icons, linked from a CDN: a page that
# shows it would ask a server outside the course. The same buttons as plain characters.
_ICONS = {
    "fa-minus": "&minus;",
    "fa-plus": "+",
    "fa-fast-backward": "&#x23EE;",
    "fa-step-backward": "&#x23F4;&#x2223;",
    "fa-play fa-flip-horizontal": "&#x23F4;",
    "fa-pause": "&#x23F8;",
    "fa-play": "&#x23F5;",
    "fa-step-forward": "&#x2223;&#x23F5;",
    "fa-fast-forward": "&#x23ED;",
}
_FA_LINK = re.compile(r"<link[^>]*font-awesome[^>]*>\s*", re.S)
_FA_ICON = re.compile(r'<i class="fa (fa-[a-z-]+(?: fa-flip-horizontal)?)"></i>')
_FIRST_FRAME = re.compile(r'frames\[0\] = "(data:image/png;base64,[A-Za-z0-9+/=\\\n]+)"')
_PLAYER_IMG = re.compile(r'<img id="(_anim_img[0-9a-f]+)">')
_SLIDER = re.compile(r'(<input id="_anim_slider[0-9a-f]+" type="range")')
# The repetition mode (Once, Loop, Reflect) is a <form> with no submit button (HTML_CodeSniffer:
# WCAG 3.2.2, H32.2) that the player reads as document[name].state: a radio group instead, its
# radios named after the player (radios outside a form share a group page-wide by name).
_LOOP_FORM = re.compile(
    r'<form title="Repetition mode" aria-label="Repetition mode" action="#n" '
    r'name="(_anim_loop_select[0-9a-f]+)"\s*class="anim-state">(.*?)</form>',
    re.S,
)
_LOOP_READ = "document[this.loop_select_id].state"
_LOOP_READ_NEW = (
    "document.getElementById(this.loop_select_id).querySelectorAll('input[type=radio]')"
)


_RADIO = re.compile(
    r'(<input type="radio"[^>]*id="([^"]+)"[^>]*>)\s*<label for="\2">([^<]*)</label>'
)


def _radio_group(m):
    radios = m.group(2).replace('name="state"', f'name="{m.group(1)}_state"')
    # each radio inside its label and named by aria-label too: IBM's engine in JupyterLab
    # associated neither the label's for= nor the wrapping label with the radio
    radios = _RADIO.sub(
        lambda r: (
            f'<label for="{r.group(2)}">{r.group(1)[:-1].rstrip()} '
            f'aria-label="{r.group(3).strip()}"> {r.group(3)}</label>'
        ),
        radios,
    )
    return (
        f'<div role="radiogroup" aria-label="Repetition mode" id="{m.group(1)}" '
        f'class="anim-state">{radios}</div>'
    )


def _offline_player(html, alt):
    """The player with no request outside the page, showing its first frame before any script.

    The Font Awesome link goes, its icons become characters (:data:`_ICONS`); the ``<img>``
    gets frame 0 as its ``src``, so the picture is there where scripts do not run (an untrusted
    notebook, a viewer) and before the player starts, with ``alt`` as its alt text (WCAG
    1.1.1), and the frame slider gets a label (4.1.2); the repetition mode is a radio group,
    not a form without a submit button (3.2.2).
    """
    html = _FA_LINK.sub("", html)
    html = _FA_ICON.sub(lambda m: f'<span aria-hidden="true">{_ICONS[m.group(1)]}</span>', html)
    first = _FIRST_FRAME.search(html)
    if first:
        src = first.group(1).replace("\\\n", "")
        alt = html_escape(alt, quote=True)
        html = _PLAYER_IMG.sub(lambda m: f'<img id="{m.group(1)}" src="{src}" alt="{alt}">', html)
    html = _LOOP_FORM.sub(_radio_group, html).replace(_LOOP_READ, _LOOP_READ_NEW)
    return _SLIDER.sub(r'\1 aria-label="Frame of the animation (time)"', html)
