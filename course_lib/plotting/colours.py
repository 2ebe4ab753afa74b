"""Colours every reader can tell apart (WCAG 1.4.1, 1.4.3, 1.4.11).

* :func:`readable`: a label's colour, darkened (hue kept) to 4.5:1 on white; the primitives draw
  every label with it, so a label may take its line's colour (a line needs only 3:1).
* :data:`NAMED`: matplotlib's ``tab:`` colours that the chapters' own cells name, put on shades
  that meet the contrast rules and stay apart from the frame axes (:data:`FRAME_COLORS`) under
  protanopia, deuteranopia and tritanopia. :func:`use_named` (run when ``course_lib.plotting``
  is imported) makes ``color="tab:orange"`` mean the course's shade in every figure of the
  session, the chapters' own ``ax.text`` and ``ax.plot`` included.
* :data:`CYCLE`: the series of a plot without explicit colours differ by line style too, not by
  colour alone (:func:`use_named` sets it as matplotlib's default property cycle).

``instructor/build/figure_audit.py`` reads every figure of the course against these rules.
"""

import matplotlib as mpl
import matplotlib.colors as mc
import numpy as np
from cycler import cycler

__all__ = ["readable", "NAMED", "CYCLE", "use_named"]

#: matplotlib's name -> the course's shade (contrast on white; the old one in brackets).
NAMED = {
    "tab:orange": "#C04F00",  # 4.8:1 (#ff7f0e: 2.5:1)
    "tab:purple": "#A0288C",  # 6.6:1 (#9467bd 4.3:1, one colour with the z axis for protanopes)
    "tab:gray": "#6B6B6B",  # 5.3:1 (#7f7f7f: 4.0:1)
}
# tab:green (3.4:1) stays: a line needs 3:1, its labels are drawn darker (readable), and a
# darker green merges with the x axis (#D55E00) for protanopes.
#: The default series of a plot: Okabe & Ito's blue, vermillion, bluish green, then purple and
#: black, each with its own line style (readable without colour; no markers: dense curves).
CYCLE = cycler(
    color=["#0072B2", "#C04F00", "#008661", "#A0288C", "#000000"],
    linestyle=["-", "--", ":", "-.", (0, (5, 2, 1, 2, 1, 2))],
)


def _contrast_on_white(rgb):
    lin = np.where(rgb <= 0.04045, rgb / 12.92, ((rgb + 0.055) / 1.055) ** 2.4)
    return 1.05 / (float(lin @ [0.2126, 0.7152, 0.0722]) + 0.05)


def readable(color, ratio=4.5):
    """``color`` darkened, hue kept, until it has ``ratio``:1 contrast on white (WCAG 1.4.3).

    Examples
    --------
    >>> readable("#0072B2")  # already 5.2:1
    '#0072b2'
    >>> readable("#009E73")  # the y axis: 3.4:1 as a line, its label 4.5:1
    '#008460'
    """
    rgb = np.array(mc.to_rgb(color))
    for _ in range(100):
        if _contrast_on_white(rgb) >= ratio:
            break
        rgb = rgb * 0.97
    return mc.to_hex(rgb)


def use_named():
    """Put :data:`NAMED` into matplotlib's colour names and :data:`CYCLE` into its defaults.

    Examples
    --------
    >>> import matplotlib.colors as mc
    >>> use_named()
    >>> mc.to_hex("tab:orange")
    '#c04f00'
    """
    mc._colors_full_map.update(NAMED)  # the table to_rgba reads (its cache is cleared)
    mc._colors_full_map.cache.clear()
    mpl.rcParams["axes.prop_cycle"] = CYCLE
