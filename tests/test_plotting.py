"""Tests for course_lib.plotting as a package: a whole scene, and what it re-exports."""

import matplotlib

matplotlib.use("Agg")

import io  # noqa: E402

import numpy as np  # noqa: E402
from hypothesis import settings  # noqa: E402
from plotting_helpers import (  # noqa: E402
    _arrows,
    _render,
)

from course_lib import so3  # noqa: E402
from course_lib.plotting import (  # noqa: E402
    axes_row,
    draw_arc,
    draw_box,
    draw_curve,
    draw_frame,
    draw_plane,
    draw_point,
    draw_vector,
)

FAST = settings(max_examples=25, deadline=None)


# --- a whole scene ----------------------------------------------------------------------------


def test_a_full_scene_renders_without_warnings_and_arrows_project_in_3d():
    fig, axes = axes_row(["A and B", "phone"])
    frame = draw_frame(axes[0], so3.rot_y(np.pi), label="B")
    draw_frame(axes[0], label="A", style="dashed")
    draw_vector(axes[0], [1, 1, 3], label="$v$")
    draw_plane(axes[0], [1, 0, 0], [0, 1, 0])
    draw_arc(axes[0], [0, 0, 1], [1, 0, 0], 2.0, label=r"$\theta$")
    draw_curve(axes[0], np.eye(3), arrow=True)
    draw_box(axes[1], so3.rot_x(0.5), marks=[[0.1, 0.2, 0.05]], frame="B")
    draw_point(axes[1], [[2.0, 2.0, 2.0], [0.0, 0.0, 0.0]])  # outside the cube: still no rescale
    _render(fig)
    # drawing never rescales the axes: the cube stays equal and fixed, as axes_row made it
    for ax in axes:
        for lim in (ax.get_xlim(), ax.get_ylim(), ax.get_zlim()):
            assert np.allclose(lim, (-1.5, 1.5))
    # after drawing, each 3D arrow has been projected to finite display positions
    for arrow in _arrows(frame):
        verts = arrow.get_path().vertices
        assert verts.size and np.all(np.isfinite(verts))
    buf = io.BytesIO()
    fig.savefig(buf, format="png", bbox_inches="tight")  # what the inline backend does
    assert buf.getvalue()[:8] == b"\x89PNG\r\n\x1a\n"
