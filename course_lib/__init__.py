"""course_lib: the shared library of the rigid-body rotations course.

Modules, named after the ideas of the course notes (section 0.1):

- :mod:`course_lib.so3` - numeric SO(3): hat/vee, Rodrigues' formula (exp), log, checks.
- :mod:`course_lib.quaternion` - unit quaternions (w, x, y, z): products, R(q), Shepperd, slerp.
- :mod:`course_lib.euler` - Euler angles in scipy's seq convention, gimbal lock.
- :mod:`course_lib.frames` - orthonormal right-handed frames, coordinates by projection.
- :mod:`course_lib.rigid` - is a map g: R³ → R³ a rigid body transformation (Definition 1)?
- :mod:`course_lib.groups` - the four group axioms (Definition 4) checked on samples.
- :mod:`course_lib.symbolic` - sympy derivations (hat map identities, Rodrigues' series).
- :mod:`course_lib.symbolic_orientation` - sympy quaternions, Euler angles and their rates.
- :mod:`course_lib.plotting` - matplotlib helpers that redraw the notes' figures.
- :mod:`course_lib.exercises` - checkers for the notebooks' exercises.

The tolerance policy is stated once, in :mod:`course_lib.tolerance`, as ``TOL``.
"""

from .tolerance import TOL

__all__ = ["TOL"]
