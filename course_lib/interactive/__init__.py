r"""The explorers and the animation of the chapters.

==============================  ===============================================================
Widget / animation              What it draws (module)
==============================  ===============================================================
:func:`rotation_explorer`       :func:`draw_rotated_frame`: frames A and B = A turned by
(notebook 02)                   :math:`\theta` about :math:`\omega` (:mod:`.rotation`)
:func:`rodrigues_explorer`      :func:`draw_rodrigues_terms` and :func:`rodrigues_readout`:
(notebook 03)                   the three terms of Rodrigues' formula, tip to tail
                                (:mod:`.rotation`)
:func:`spin_animation`          a body frame spinning at unit angular velocity
(notebook 03)                   (:mod:`.animation`)
:func:`gimbal_explorer`         :func:`draw_gimbal` and :func:`gimbal_readout`: the axes of
(notebook 05)                   yaw, pitch and roll, and gimbal lock at pitch ±90°
                                (:mod:`.gimbal`)
==============================  ===============================================================

:mod:`.widgets` holds what every explorer is made of (:class:`Explorer`: sliders above a live
ipympl figure that turns with the mouse, and its still picture where ipympl is missing).
The maths is in :mod:`course_lib.rodrigues`, :mod:`course_lib.so3` and :mod:`course_lib.euler`.
"""

from .animation import SPIN_PIXELS, spin_animation
from .gimbal import (
    PITCH_RANGE,
    ROLL_RANGE,
    YAW_RANGE,
    draw_gimbal,
    gimbal_explorer,
    gimbal_readout,
    rates_matrix,
    turn_axes,
)
from .rotation import (
    AZIMUTH_RANGE,
    POLAR_RANGE,
    Q0,
    THETA_RANGE,
    draw_rodrigues_terms,
    draw_rotated_frame,
    rodrigues_explorer,
    rodrigues_readout,
    rotation_explorer,
)
from .widgets import VIEW_AZIM, VIEW_ELEV, Explorer, SliderSpec

__all__ = [
    "POLAR_RANGE",
    "AZIMUTH_RANGE",
    "THETA_RANGE",
    "Q0",
    "VIEW_ELEV",
    "VIEW_AZIM",
    "rodrigues_readout",
    "draw_rotated_frame",
    "draw_rodrigues_terms",
    "Explorer",
    "SliderSpec",
    "rotation_explorer",
    "rodrigues_explorer",
    "SPIN_PIXELS",
    "spin_animation",
    "YAW_RANGE",
    "PITCH_RANGE",
    "ROLL_RANGE",
    "turn_axes",
    "rates_matrix",
    "gimbal_readout",
    "draw_gimbal",
    "gimbal_explorer",
]
