"""Helpers shared by the tests of course_lib.plotting (tests/test_plotting*.py)."""

import matplotlib
import matplotlib.text
import matplotlib.transforms
import numpy as np
from hypothesis import strategies as st

from course_lib import so3
from course_lib.plotting import Arrow

finite = st.floats(-3.0, 3.0, allow_nan=False, allow_infinity=False)
vec3 = st.tuples(finite, finite, finite).map(np.array)
seeds = st.integers(0, 2**32 - 1)
angles = st.floats(-2 * np.pi, 2 * np.pi, allow_nan=False)


def _rotation(seed):
    return so3.random_rotations(1, seed=seed)[0]


def _arrows(drawn):
    return [a for a in drawn if isinstance(a, Arrow)]


def _texts(drawn):
    return [a for a in drawn if isinstance(a, matplotlib.text.Text)]


def _render(fig):
    """Draw the figure for real (projects 3D artists); any warning fails the test."""
    fig.canvas.draw()


def _outside_canvas(fig, boxes):
    """Pixels by which the union of ``boxes`` (display coordinates) sticks out of the canvas.

    The notebooks show the whole canvas (``bbox_inches=None``), so anything outside is cut off.
    """
    union = matplotlib.transforms.Bbox.union([b for b in boxes if b is not None])
    canvas = fig.bbox
    return max(
        canvas.x0 - union.x0, canvas.y0 - union.y0, union.x1 - canvas.x1, union.y1 - canvas.y1
    )


def _decorations_2d(fig):
    """Tight boxes of every 2D axes: ticks, tick labels, axis labels, title, legend."""
    renderer = fig.canvas.get_renderer()
    return [ax.get_tightbbox(renderer) for ax in fig.axes]


def _axis_labels_3d(fig):
    """Boxes of the x, y, z axes of every 3D panel: tick labels and axis labels."""
    renderer = fig.canvas.get_renderer()
    return [
        axis.get_tightbbox(renderer) for ax in fig.axes for axis in (ax.xaxis, ax.yaxis, ax.zaxis)
    ]


def _signed_angle(k, u, v):
    """Angle from u to v about the unit axis k (right hand rule), in (-pi, pi]."""
    return np.arctan2(k @ np.cross(u, v), u @ v)


def _ax_texts(ax):
    """The strings of every text of ``ax``."""
    return [t.get_text() for t in ax.texts]


def _position(text):
    """Where a 3D text sits, in world coordinates."""
    return np.array([text._x, text._y, text._z], dtype=float)
