"""The figures of the class report: matplotlib PNGs as ``data:`` URIs, each with its alt text.

Every figure says in its alt text what a reader would read off it (the bars and their
numbers), so the figure adds nothing that the text does not hold. Colours: the dark blue
``#1f4e79`` on white (contrast 9.4:1) and black text; nothing is told by colour alone.
"""

from __future__ import annotations

import base64
import io
from functools import lru_cache

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

__all__ = ["score_figure", "share_figure", "BAR"]

BAR = "#1f4e79"
DPI = 80


def _figure(width, height):
    """A figure and its axes, outside pyplot (no global state, no backend switch)."""
    fig = Figure(figsize=(width, height))
    FigureCanvasAgg(fig)
    return fig, fig.add_subplot()


def _png(fig):
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=DPI, bbox_inches="tight")
    return "data:image/png;base64," + base64.b64encode(buf.getvalue()).decode("ascii")


def _label(v):
    return f"{v:g}"


def score_figure(title, distribution, shown):
    """Bar chart of how many submissions got each number of points.

    ``distribution`` maps points to counts; ``shown(count)`` is the text of a count (the shared
    copy hides small ones: a bar of a hidden count is not drawn). Returns ``(uri, alt)``; the
    two copies of a report share a figure whose numbers they show alike.
    """
    levels = tuple(sorted(distribution))
    texts = tuple(shown(distribution[v]) for v in levels)
    counts = tuple(distribution[v] for v in levels)
    return _score_figure(title, levels, counts, texts)


@lru_cache(maxsize=256)
def _score_figure(title, levels, counts, texts):
    heights = [c if t == str(c) else 0 for c, t in zip(counts, texts)]
    fig, ax = _figure(3.6, 2.0)
    ax.bar([_label(v) for v in levels], heights, color=BAR)
    for i, (h, t) in enumerate(zip(heights, texts)):
        ax.annotate(t, (i, h), ha="center", va="bottom", fontsize=9)
    ax.set_xlabel("points")
    ax.set_ylabel("submissions")
    ax.set_ylim(0, max(heights + [1]) * 1.25)
    ax.spines[["top", "right"]].set_visible(False)
    parts = [f"{_label(v)} points: {t}" for v, t in zip(levels, texts)]
    alt = f"Bar chart of the points of {title}: " + "; ".join(parts) + "."
    return _png(fig), alt


def share_figure(rows):
    """Horizontal bars of the share right per exercise; ``rows`` = [(label, share or None)].
    Returns ``(uri, alt)``."""
    return _share_figure(tuple(rows))


@lru_cache(maxsize=64)
def _share_figure(rows):
    fig, ax = _figure(5.0, 0.35 * len(rows) + 0.8)
    labels = [label for label, _ in rows][::-1]
    values = [(share or 0.0) * 100 for _, share in rows][::-1]
    ax.barh(labels, values, color=BAR)
    for i, (v, (_, share)) in enumerate(zip(values, rows[::-1])):
        text = "hidden" if share is None else f"{v:.0f}%"
        ax.annotate(text, (v, i), va="center", xytext=(3, 0), textcoords="offset points")
    ax.set_xlim(0, 115)
    ax.set_xlabel("share right (%)")
    ax.spines[["top", "right"]].set_visible(False)
    parts = [
        f"{label}: {'hidden (fewer than 5)' if s is None else f'{s * 100:.0f}%'}"
        for label, s in rows
    ]
    alt = "Bar chart of the share of submissions right per exercise: " + "; ".join(parts) + "."
    return _png(fig), alt
