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

from . import animation, gimbal, rotation, widgets
from .animation import *  # noqa: F403
from .gimbal import *  # noqa: F403
from .rotation import *  # noqa: F403
from .widgets import *  # noqa: F403

# What each module exports, in the order of the table above: one list per module, kept there.
__all__ = [*rotation.__all__, *widgets.__all__, *animation.__all__, *gimbal.__all__]
