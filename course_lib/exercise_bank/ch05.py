r"""Exercises of chapter 5 (orientation in practice: Euler angles, gimbal lock, quaternions)."""

from course_lib.exercises._model import Exercise, Expr, Value
from course_lib.symbolic import alpha, beta

CHAPTER = 5
SETUP = (
    "import numpy as np\nimport sympy as sp\n\n"
    "from course_lib import euler, quaternion\n"
    "from course_lib.exercises import alpha, beta, check"
)

EXERCISES = [
    Exercise(
        name="quaternion_of_turn",
        chapter=5,
        number=1,
        level="warm-up",
        title="The quaternion of a turn",
        statement=r"""
Give the unit quaternion $q = (w, x, y, z)$, scalar first, of the turn by $90°$ about the axis
through $(1, 2, 2)$ (a direction, not yet a unit vector), with $w > 0$. Give a 4-vector.
""",
        answer=Value(shape=(4,)),
        tip="q = (cos θ/2, ω sin θ/2) with a unit axis ω and θ in radians.",
        mistakes={
            "full_angle": "a quaternion holds half the angle: cos θ/2 and sin θ/2, not θ.",
            "not_unit": "the axis must be a unit vector first: divide (1, 2, 2) by its length.",
            "scalar_last": "this course writes the scalar first, (w, x, y, z), not ROS's "
            "(x, y, z, w).",
            "negated": "−q is the same rotation as q; the exercise fixes the sign by w > 0.",
        },
    ),
    Exercise(
        name="angle_from_ros",
        chapter=5,
        number=2,
        level="warm-up",
        title="The angle of a ROS orientation",
        statement=r"""
A ROS message holds the orientation `x: 0.0, y: 0.0, z: 0.6, w: 0.8` (scalar last). It is a
turn about the $z$ axis. By what angle $\theta$, in radians, between $0$ and $\pi$? Give a
number.
""",
        answer=Value(angle=True),
        tip="w = cos θ/2 and z = sin θ/2 for a turn about z; atan2 gives the half angle.",
        mistakes={
            "scalar_first": "ROS writes the scalar last: w = 0.8 is the fourth number, "
            "not the first.",
            "half": "that is θ/2: a quaternion holds half the angle.",
        },
    ),
    Exercise(
        name="compose_quaternions",
        chapter=5,
        number=3,
        level="core",
        title="Two turns as one quaternion",
        statement=r"""
A body starts at the identity. It turns by $90°$ about the **world** $x$ axis, then by $90°$
about the **world** $z$ axis. Give the unit quaternion $(w, x, y, z)$ of its final
orientation, with $w > 0$. Give a 4-vector.
""",
        answer=Value(shape=(4,)),
        tip="Quaternions compose like matrices: a turn about a fixed (world) axis multiplies "
        "from the left.",
        mistakes={
            "order": "the second turn is about a world axis, so its quaternion multiplies "
            "from the left.",
            "negated": "−q is the same rotation as q; the exercise fixes the sign by w > 0.",
        },
    ),
    Exercise(
        name="angles_of_matrix",
        chapter=5,
        number=4,
        level="core",
        title="Roll, pitch and yaw of a rotation",
        statement=r"""
A drone reports its orientation as the rotation matrix
$$R = \begin{bmatrix} -\tfrac{\sqrt3}{4} & \tfrac14 & -\tfrac{\sqrt3}{2}\\
\tfrac34 & -\tfrac{\sqrt3}{4} & -\tfrac12\\ -\tfrac12 & -\tfrac{\sqrt3}{2} & 0\end{bmatrix}.$$
Find its yaw $\psi$, pitch $\theta$ and roll $\phi$ (intrinsic Z-Y-X:
$R = R_z(\psi)R_y(\theta)R_x(\phi)$, pitch in $[-\pi/2, \pi/2]$), in radians. Give the
3-vector $(\psi, \theta, \phi)$.
""",
        answer=Value(shape=(3,), angle=True),
        tip="The bottom row is (−sin θ, cos θ sin φ, cos θ cos φ); the first column starts "
        "with cos θ cos ψ, cos θ sin ψ. Use atan2.",
        mistakes={
            "reversed": "the order asked for is (yaw, pitch, roll), the order of the turns.",
            "pitch_sign": "the entry r₃₁ is −sin θ: mind its sign.",
        },
    ),
    Exercise(
        name="proper_euler_lock",
        chapter=5,
        number=5,
        level="core",
        title="Where proper Euler angles lock",
        statement=r"""
Take the intrinsic Z-X-Z angles $(\alpha, \beta, \gamma)$: $R = R_z(\alpha)R_x(\beta)R_z(\gamma)$.
When they change at rates $(\dot\alpha, \dot\beta, \dot\gamma)$, the body's angular velocity in
body coordinates is $\omega_b = E\,(\dot\alpha, \dot\beta, \dot\gamma)^T$, where each column of
$E$ is the axis of one turn seen from the body (as for roll, pitch and yaw in the chapter).
Compute $\det E$. Give a scalar expression in `alpha` and `beta` (it may not need both).
""",
        answer=Expr(shape=(), domain=(alpha, beta)),
        tip="Each column is the axis of one turn in body coordinates, the last one e₃ "
        "(turns about body axes: later turns act on earlier axes by their transposes).",
        mistakes={
            "tait_bryan": "that is the determinant for roll, pitch and yaw; Z-X-Z turns about "
            "z twice.",
        },
    ),
    Exercise(
        name="slerp_third",
        chapter=5,
        number=6,
        level="challenge",
        title="A third of the way",
        statement=r"""
Let $q_0 = (1, 0, 0, 0)$ and let $q_1$ be the quaternion of the turn by $120°$ about $z$, with
$w > 0$. Give $\operatorname{slerp}(q_0, q_1, \tfrac13)$, a 4-vector.
""",
        answer=Value(shape=(4,)),
        tip="slerp turns at constant speed about one axis: after t = 1/3 the body has turned "
        "a third of 120°.",
        mistakes={
            "nlerp": "that is the normalised linear average; slerp moves along the arc at "
            "constant speed.",
            "full_angle": "a quaternion holds half the angle of its turn.",
            "negated": "−q is the same rotation as q; the exercise fixes the sign by w > 0.",
        },
    ),
    Exercise(
        name="angle_between_quaternions",
        chapter=5,
        number=7,
        level="challenge",
        title="How far apart are two orientations?",
        statement=r"""
Two orientations are given by the unit quaternions $q_0 = (0.6, 0.8, 0, 0)$ and
$q_1 = (-0.8, 0, 0, 0.6)$. Find the angle $\theta \in [0, \pi]$ of the rotation that takes the
first to the second, $R_0^TR_1$, in radians. Give a number.
""",
        answer=Value(angle=True),
        tip="The relative rotation is q₀* q₁, and its scalar part is q₀ · q₁ = cos θ/2 up to "
        "a sign.",
        mistakes={
            "long_way": "q and −q are the same rotation: take the absolute value of q₀ · q₁ "
            "to get the shorter angle.",
        },
    ),
]
