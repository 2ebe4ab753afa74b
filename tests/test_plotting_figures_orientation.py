"""Tests for course_lib.plotting.figures_orientation: the Euler-turn panels of chapter 5."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.colors import to_rgb

from course_lib.plotting import euler_steps
from course_lib.plotting.primitives import Arrow


def _arrows(ax):
    return [a for a in ax.get_children() if isinstance(a, Arrow)]


def test_euler_steps_before_frame_differs_by_style_and_length_not_colour_alone():
    """Regression (issue 37): the dashed "before" frames were short and hard to see."""
    fig = euler_steps(np.radians([40, 30, 50]), "ZYX")
    try:
        for ax in fig.axes:
            arrows = _arrows(ax)
            grey = [a for a in arrows if np.allclose(to_rgb(a.get_edgecolor()), (0.35,) * 3)]
            coloured = [a for a in arrows if a not in grey]
            assert len(grey) == 3 and len(coloured) == 3
            assert all(a.get_linestyle() != "-" for a in grey)  # dashed, not solid
            assert all(a.get_linewidth() > max(c.get_linewidth() for c in coloured) for a in grey)
        legend_texts = [t.get_text() for legend in fig.legends for t in legend.get_texts()]
        assert any("before" in t and "dashed" in t for t in legend_texts)
        assert any("after" in t and "solid" in t for t in legend_texts)
    finally:
        plt.close(fig)
