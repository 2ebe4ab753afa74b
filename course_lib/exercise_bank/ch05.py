r"""Exercises of chapter 5 (orientation in practice: Euler angles, gimbal lock, quaternions)."""

from math import pi

from course_lib.exercises._model import Exercise, Value, Variants

CHAPTER = 5
SETUP = (
    "import numpy as np\nimport sympy as sp\n\n"
    "from course_lib import euler, quaternion, so3\n"
    "from course_lib.exercises import check, parameters"
)

#: What problem set 5 needs besides chapter 5 (its header says so).
READS = (
    "Read chapter 5 first. Two exercises also use chapter 4: 5.3 its rule that a turn about a "
    "world axis multiplies on the left (§2), 5.6 its geodesic (§7) and chapter 2's "
    "Proposition 6."
)

EXERCISES = [
    Exercise(
        name="quaternion_of_turn",
        chapter=5,
        number=1,
        level="warm-up",
        title="The quaternion of a turn",
        statement=r"""
Give the unit quaternion $q = (w, x, y, z)$, scalar first, of the turn by $<<angle>>°$ about the
axis through $<<direction>>$ (a direction, not yet a unit vector), with $w > 0$. Give a 4-vector.
""",
        answer=Value(shape=(4,), unit=True),
        tip="q = (cos θ/2, ω sin θ/2) with a unit axis ω and θ in radians.",
        mistakes={
            "full_angle": "a quaternion holds half the angle: cos θ/2 and sin θ/2, not θ.",
            "not_unit": "the axis must be a unit vector first: divide the direction by its length.",
            "scalar_last": "this course writes the scalar first, (w, x, y, z), not ROS's "
            "(x, y, z, w).",
            "negated": "−q is the same rotation as q; the exercise fixes the sign by w > 0.",
            "degrees": "cos and sin take radians: convert the angle from degrees before "
            "halving it.",
        },
        variants=Variants("ch05_turn", {"angle": 90, "direction": [1, 2, 2]}),
    ),
    Exercise(
        name="angle_from_ros",
        chapter=5,
        number=2,
        level="warm-up",
        title="The angle of a ROS orientation",
        statement=r"""
A ROS message holds the orientation `x: <<x>>, y: <<y>>, z: <<z>>, w: <<w>>` (scalar last).
It is a turn about a fixed axis. By what angle $\theta$, in radians, between $0$ and
$\pi$? Give a number.
""",
        answer=Value(angle=True, ranges=(("θ", 0.0, pi),)),
        tip="Put the four numbers in this course's order first, then use what §4 says the "
        "scalar part of a turn's quaternion is.",
        mistakes={
            "scalar_first": "ROS writes the scalar last: w is the fourth number, not the first.",
            "half": "that is θ/2: a quaternion holds half the angle.",
        },
        variants=Variants("ch05_ros", {"x": 0.0, "y": 0.0, "z": 0.6, "w": 0.8}),
    ),
    Exercise(
        name="compose_quaternions",
        chapter=5,
        number=3,
        level="core",
        title="Two turns as one quaternion",
        statement=r"""
A body starts at the identity. It turns by $<<a1>>°$ about the **world** $<<axis1>>$ axis, then
by $<<a2>>°$ about the **world** $<<axis2>>$ axis. Give the unit quaternion $(w, x, y, z)$ of its
final orientation, with $w > 0$. Give a 4-vector.
""",
        answer=Value(shape=(4,), unit=True),
        tip="Quaternions compose like matrices: a turn about a fixed (world) axis multiplies "
        "from the left.",
        mistakes={
            "order": "the second turn is about a world axis, so its quaternion multiplies "
            "from the left.",
            "negated": "−q is the same rotation as q; the exercise fixes the sign by w > 0.",
        },
        variants=Variants("ch05_two_turns", {"a1": 90, "axis1": "x", "a2": 90, "axis2": "z"}),
    ),
    Exercise(
        name="proper_euler_angles",
        chapter=5,
        number=4,
        level="core",
        title="Proper Euler angles of a rotation",
        statement=r"""
A camera mount reports its orientation as the rotation matrix

$$R = <<R_tex>>.$$

Its angles are the intrinsic Z-Y-Z (proper Euler) angles $(\alpha, \beta, \gamma)$:
$R = R_z(\alpha)\,R_y(\beta)\,R_z(\gamma)$. Like the roll, pitch and yaw of the chapter's §2,
every such $R$ with $\sin\beta \ne 0$ has two triples: one with $\beta \in (0, \pi)$ and one
with $\beta \in (-\pi, 0)$. Multiply out the product for general angles, read the angles off
the entries, and give the triple with $\beta \in [-\pi, 0]$ and $\alpha, \gamma \in [-\pi, \pi]$:
the 3-vector $(\alpha, \beta, \gamma)$ in radians.
""",
        answer=Value(
            shape=(3,),
            angle=True,
            ranges=(("α", -pi, pi), ("β", -pi, 0.0), ("γ", -pi, pi)),
        ),
        tip="Write out R_z(α) R_y(β) R_z(γ) first (sympy helps). Look for the row and the "
        "column in which only two of the three angles appear. atan2 reads the quadrant from "
        "the signs of both its arguments: here sin β < 0, so mind the sign each entry gets.",
        mistakes={
            "reversed": "the order asked for is (α, β, γ), the order of the turns.",
            "gamma_sign": "check the sign of the entry you use for cos γ: in the product it "
            "comes as −sin β cos γ, and here sin β < 0.",
            "positive_beta": "that triple rebuilds R too, but its β is positive; the "
            "statement asks for the one with β in [−π, 0].",
            "beta_only": "negating β alone gives another rotation (rebuild R from your triple "
            "to see it): with sin β < 0 the entries you read α and γ from change sign too.",
        },
        variants=Variants(
            "ch05_euler",
            {
                "R": [
                    ["1/2", "sqrt(3)/2", "0"],
                    ["sqrt(3)/4", "-1/4", "-sqrt(3)/2"],
                    ["-3/4", "sqrt(3)/4", "-1/2"],
                ],
                "R_tex": r"\begin{bmatrix} \tfrac12 & \tfrac{\sqrt3}{2} & 0\\"
                "\n"
                r"\tfrac{\sqrt3}{4} & -\tfrac14 & -\tfrac{\sqrt3}{2}\\"
                "\n"
                r"-\tfrac34 & \tfrac{\sqrt3}{4} & -\tfrac12\end{bmatrix}",
            },
        ),
    ),
    Exercise(
        name="unreachable_omega",
        chapter=5,
        number=5,
        level="core",
        title="The angular velocity that angle rates cannot give",
        statement=r"""
A drone's yaw, pitch and roll (intrinsic Z-Y-X, as in the chapter) are yaw $0$, pitch $90°$ and
roll $<<roll>>°$. Whatever rates $(\dot\psi, \dot\theta, \dot\phi)$ its angles change at, its
angular velocity in body coordinates is $\omega_b = E\,(\dot\psi, \dot\theta, \dot\phi)^T$, and
at this orientation these $\omega_b$ do not fill space. Give the unit vector $n$, in body
coordinates, that is orthogonal to every $\omega_b$ the rates can produce; of the two such
unit vectors give the one with $n\cdot(1, 1, 1) > 0$. Give a 3-vector.
""",
        answer=Value(shape=(3,), unit=True),
        tip="Build E column by column at this orientation (each column is the axis of one turn "
        "in body coordinates, §3). Which columns span the same line? A vector orthogonal to "
        "two independent vectors comes from their cross product.",
        mistakes={
            "world_frame": "the rates do produce that vector: at this pitch the yaw and roll "
            "columns of E both lie along it. n must be orthogonal to every column of E, in body "
            "coordinates. (If you found it as the normal of the turn axes, those were written in "
            "world coordinates.)",
            "no_transpose": "a later turn acts on an earlier turn's axis through its "
            "transpose, R_x(φ)ᵀ, not R_x(φ): check the sign of the roll angle in your "
            "columns.",
            "parallel_columns": "the zero vector: two of the columns you crossed are "
            "parallel at this pitch. Use two independent ones.",
            "sign": "there are two unit normals; the statement picks the one with a positive "
            "dot product with (1, 1, 1).",
        },
        variants=Variants("ch05_gimbal", {"roll": 30}),
    ),
    Exercise(
        name="slerp_angular_velocity",
        chapter=5,
        number=6,
        level="challenge",
        title="How fast does slerp turn?",
        statement=r"""
In $T = <<T>>$ s, a body moves from the orientation $q_0 = <<q0_tex>>$
to $q_1 = <<q1_tex>>$ (scalar first) along $\operatorname{slerp}(q_0, q_1, t/T)$,
taking the shorter way as the chapter's slerp does. Its angular velocity is
constant. Give it in **world** coordinates, in rad/s: a 3-vector $\omega$ with
$\dot R = \hat\omega R$.
""",
        answer=Value(shape=(3,)),
        tip="slerp is chapter 4's geodesic (§7): one turn about a fixed axis at constant "
        "speed. Which relative rotation is that turn, and in which frame is its axis "
        "written? Then mind the time the move takes.",
        mistakes={
            "body_frame": "that is the angular velocity in body coordinates, the same vector "
            "seen from the body; the exercise asks for world coordinates.",
            "per_move": "that is the rotation vector of the whole move; the exercise asks "
            "for a rate in rad/s: the move takes <<T>> s.",
            "half_angle": "the quaternion of the relative turn holds half its angle: "
            "cos(θ/2), not cos θ.",
            "long_way": "that turns the long way round: q₀ · q₁ < 0, so −q₁ is the nearer "
            "quaternion of the same orientation.",
            "reverse": "that turn goes from q₁ back to q₀: the turn that takes R₀ to R₁, "
            "written in the world frame, is R₁R₀ᵀ, not its inverse.",
        },
        variants=Variants(
            "ch05_slerp",
            {
                "T": 3,
                "q0": [2**0.5 / 2, 2**0.5 / 2, 0.0, 0.0],
                "q1": [-(2**0.5) / 4, -(2**0.5) / 4, -(6**0.5) / 4, -(6**0.5) / 4],
                "q0_tex": r"\big(\tfrac{\sqrt2}{2}, \tfrac{\sqrt2}{2}, 0, 0\big)",
                "q1_tex": r"\big(-\tfrac{\sqrt2}{4}, -\tfrac{\sqrt2}{4}, -\tfrac{\sqrt6}{4},"
                r" -\tfrac{\sqrt6}{4}\big)",
            },
        ),
    ),
    Exercise(
        name="angle_between_quaternions",
        chapter=5,
        number=7,
        level="challenge",
        title="How far apart are two orientations?",
        statement=r"""
Two orientations arrive from two sources: $q_0 = <<q0>>$ from `course_lib`
(scalar first), and $q_1$ as a ROS message, `x: <<x>>, y: <<y>>, z: <<z>>, w: <<w>>`. Find the angle
$\theta \in [0, \pi]$ of the rotation that takes the first orientation to the second,
$R_0^TR_1$, in radians. Give a number.
""",
        answer=Value(angle=True, ranges=(("θ", 0.0, pi),)),
        tip="Put both in one order first. Which quaternion takes the first orientation to the "
        "second, what does its scalar part tell about its angle, and what does the double "
        "cover change?",
        mistakes={
            "long_way": "q and −q are the same rotation: of the two angles your formula can "
            "give, the statement asks for the one in [0, π].",
            "scalar_last": "q₁ came as a ROS message, scalar last: put it in the order "
            "(w, x, y, z) before computing with it.",
            "half_angle": "the scalar part of the quaternion that takes one orientation to the "
            "other is cos(θ/2), not cos θ: the angle is twice its arccos.",
        },
        variants=Variants(
            "ch05_two_sources",
            {"q0": [0.6, 0.8, 0.0, 0.0], "x": 0.0, "y": 0.0, "z": 0.6, "w": -0.8},
        ),
    ),
]
