r"""Matplotlib helpers that redraw the figures of the course notes (section 0.1).

The notes describe their figures with "Above: ..." captions. Every one of them is built here from
a small set of primitives, so that a notebook cell stays three to six lines long:

=====================================================  ============================================
Figure in the notes                                    Composition
=====================================================  ============================================
a particle in a reference frame                        :func:`axes3d`, :func:`draw_frame`,
                                                       :func:`draw_point`, :func:`draw_vector`
a trajectory :math:`p(t)`, eq. (6)                     :func:`draw_curve` (``arrow=True``)
a point seen from frames A and B                       two :func:`draw_frame` with different origins
a free vector :math:`v = p - q = r - s`, eq. (7)-(8)   :func:`draw_point`, :func:`draw_vector`
a rigid body made of particles                         :func:`draw_point` with an ``(n, 3)`` array
the phone before and after a rotation, eq. (9)         :func:`axes_row`, :func:`draw_box` (marks),
                                                       :func:`draw_segment`
rotation about z by 90° versus a reflection            :func:`axes_row`, :func:`draw_frame`
frames A, B, C of the :math:`R_{ab}, R_{ac}` example   :func:`draw_frame` with ``R=``
:math:`v` in frames A and B, eq. (64)                  :func:`draw_frame`, :func:`draw_vector`
:math:`a \times b` normal to the plane of a and b      :func:`draw_plane`, :func:`draw_vector`
a particle orbiting the origin about :math:`\omega`    :func:`plot_orbit`
a body spinning about :math:`\omega`, eq. (121)        :func:`plot_spinning_body`
the pendulum, :math:`\|v\| = |r\omega|`, eq. (118)     :func:`axes2d`, :func:`draw_pendulum`
unit angular velocity: angle = time, eq. (125)         :func:`draw_arc`, :func:`draw_point`
convergence of the series (124)/(126)                  :func:`plot_convergence`
=====================================================  ============================================

Conventions
-----------
* Figures are created by :func:`axes3d`, :func:`axes2d`, :func:`axes_row` or
  :func:`plot_convergence`; each sets a title and axis labels, a fixed size, dpi and font, and
  equal, fixed axis limits, so the same cell always gives the same picture. Nothing is random.
* Figures lay themselves out, so a notebook needs no ``fig.tight_layout()`` and can show the
  full canvas (``bbox_inches=None``): 2D figures use matplotlib's constrained layout, which
  makes room for long tick labels, tall axis labels, a legend or a colour bar when the figure is
  drawn. 3D figures get fixed margins instead (constrained layout does not measure the axis
  labels of 3D axes); those of :func:`axes_row` leave room for the tick labels at any camera
  elevation.
* ``draw_*`` functions work on 3D axes with 3-vectors and (where it makes sense) on 2D axes
  with 2-vectors. They return a :class:`Drawn`: the list of artists they added (iterate over it)
  and, in ``.points``, the geometry they drew in world coordinates, so that a notebook can
  compute with it (for example the distance between the two marked points on the phone).
* Bad input (wrong shape, NaN or inf, a zero axis, parallel vectors spanning no plane, a box
  orientation that is not a rotation) raises a ``ValueError``/``TypeError`` that names the
  failed property; degeneracy is judged with the package tolerance ``TOL``.

Modules
-------
One concern per module; everything public is re-exported here, so ``from course_lib import
plotting`` and ``plotting.draw_frame(...)`` work as they always did.

==============================  ===============================================================
module                          what it holds
==============================  ===============================================================
:mod:`.axes`                    figure and axes set-up: sizes, fonts, views, limits
:mod:`.primitives`              :class:`Arrow`, :class:`Drawn`, frames, vectors, points,
                                segments, curves
:mod:`.shapes`                  a patch of a plane, the arc of a rotation, a rigid box
:mod:`.figures_exponential`     chapter 03: the pendulum, an orbit, a spinning body, Rodrigues'
                                circle
:mod:`.figures_accuracy`        error plots: the series' convergence, errors near a limit
:mod:`.figures_composition`     chapter 04: frames side by side, the geodesic
:mod:`.figures_orientation`     chapter 05: Euler turns, gimbal lock, the double cover, slerp
:mod:`.display`                 :func:`show`: a figure shown with its alt text (not ``plt.show()``)
:mod:`.colours`                 colours every reader tells apart (labels 4.5:1, no colour alone)
==============================  ===============================================================

Input is checked by the one validation layer, :mod:`course_lib._arrays`.
"""

from .axes import DPI, FONT_SIZE, TITLE_SIZE, axes2d, axes3d, axes_row
from .axes import FIGSIZE as FIGSIZE
from .axes import PANEL_SIZE as PANEL_SIZE
from .axes import _require_3d as _require_3d  # course_lib.interactive checks its axes with it
from .colours import readable, use_named
from .display import figure_output, show
from .figures_accuracy import plot_convergence, plot_error_curves
from .figures_composition import frame_panels, plot_geodesic
from .figures_exponential import (
    draw_pendulum,
    plot_orbit,
    plot_rodrigues_circle,
    plot_spinning_body,
)
from .figures_orientation import (
    angle_streams,
    double_cover,
    euler_steps,
    gimbal_axes,
    slerp_speed,
)
from .primitives import ARROW_HEAD as ARROW_HEAD
from .primitives import (
    FRAME_COLORS,
    Arrow,
    Drawn,
    draw_curve,
    draw_frame,
    draw_point,
    draw_segment,
    draw_vector,
)
from .shapes import draw_arc, draw_box, draw_plane

__all__ = [
    "DPI",
    "FONT_SIZE",
    "TITLE_SIZE",
    "FRAME_COLORS",
    "Arrow",
    "Drawn",
    "axes3d",
    "axes2d",
    "axes_row",
    "draw_frame",
    "draw_vector",
    "draw_point",
    "draw_segment",
    "draw_curve",
    "draw_plane",
    "draw_arc",
    "draw_box",
    "draw_pendulum",
    "plot_convergence",
    "frame_panels",
    "plot_error_curves",
    "plot_geodesic",
    "euler_steps",
    "gimbal_axes",
    "double_cover",
    "slerp_speed",
    "angle_streams",
    "plot_orbit",
    "plot_rodrigues_circle",
    "plot_spinning_body",
    "show",
    "figure_output",
    "readable",
]

use_named()  # tab:orange, tab:purple, tab:gray on readable shades; series differ by line style
