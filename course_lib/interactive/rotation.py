r"""The explorers of chapters 02 and 03: a frame turned about an axis, Rodrigues' formula.

The rotation axis is a unit vector :math:`\omega`, given to the sliders by two spherical
angles: the polar angle :math:`\varphi \in [0, \pi]` (measured from the z axis) and the azimuth
:math:`\lambda \in [-\pi, \pi]` (measured in the xy plane from the x axis). The rotation is the
notes' :math:`R(\omega, \theta) = e^{\hat\omega\theta}` (eq. 127), computed by
:func:`course_lib.so3.exp`; drawing uses the primitives of :mod:`course_lib.plotting`.
"""

import numpy as np
from matplotlib.lines import Line2D

from .. import plotting, so3
from .._arrays import as_count, as_unit_axes, as_vector3
from ..rodrigues import axis_from_spherical, rodrigues_terms, rodrigues_vectors
from ..tolerance import TOL
from .widgets import VIEW_AZIM, VIEW_ELEV, Explorer, SliderSpec, _scalar_angle, _view_angle

__all__ = [
    "POLAR_RANGE",
    "AZIMUTH_RANGE",
    "THETA_RANGE",
    "Q0",
    "rodrigues_readout",
    "draw_rotated_frame",
    "draw_rodrigues_terms",
    "rotation_explorer",
    "rodrigues_explorer",
]

#: Slider ranges, in radians: polar angle of the axis, its azimuth, and the rotation angle.
POLAR_RANGE = (0.0, np.pi)
AZIMUTH_RANGE = (-np.pi, np.pi)
THETA_RANGE = (0.0, 2.0 * np.pi)

#: The fixed point q0 that the Rodrigues explorer rotates (the tip of the world x axis).
Q0 = (1.0, 0.0, 0.0)

_TERM_COLORS = ("black", "#C04F00", "tab:purple")
_RESULT_COLOR = "#0072B2"
_AXIS_COLOR = "0.35"
_WORLD_AXES = ("x_A", "y_A", "z_A")
_RODRIGUES_LABELS = (
    r"$q_0$",
    r"$\sin\theta\,\hat\omega q_0$",
    r"$(1-\cos\theta)\,\hat\omega^2 q_0$",
    r"$e^{\hat\omega\theta}q_0$ (sum)",
)


def _fmt(x, decimals):
    """A number rounded for display, without a minus sign on zero."""
    return f"{round(float(x), decimals) + 0.0:.{decimals}f}"


def _bmatrix(M, decimals):
    rows = [" & ".join(_fmt(x, decimals) for x in row) for row in np.asarray(M)]
    return r"\begin{bmatrix} " + r" \\ ".join(rows) + r" \end{bmatrix}"


def rodrigues_readout(axis, theta, decimals=2, tol=TOL):
    r"""LaTeX of Rodrigues' formula with numbers: the three matrices and their sum.

    .. math::

        e^{\hat\omega\theta} = I + \sin\theta\,\hat\omega + (1-\cos\theta)\,\hat\omega^2
        = \begin{bmatrix}\cdot\end{bmatrix} + \begin{bmatrix}\cdot\end{bmatrix}
        + \begin{bmatrix}\cdot\end{bmatrix} = \begin{bmatrix}\cdot\end{bmatrix}

    with the entries rounded to ``decimals`` places. The sum on the right is
    :func:`course_lib.so3.exp`, computed independently of the three terms.

    Parameters
    ----------
    axis : array_like, shape (3,)
        One unit rotation axis.
    theta : float
        Angle in radians.
    decimals : int, default 2
        Number of decimals shown (0 to 6).
    tol : float, default TOL
        Largest accepted :math:`|\|\omega\| - 1|`.

    Returns
    -------
    str
        A LaTeX display, ready for ``IPython.display.Math``.

    Raises
    ------
    ValueError
        If the axis is not a single unit 3-vector, ``theta`` is not a single finite number,
        or ``decimals`` is outside 0..6.
    TypeError
        If an input is not numeric, or ``decimals`` is not an integer.

    Examples
    --------
    >>> tex = rodrigues_readout([0, 0, 1], 0.0)
    >>> tex.count(r"\begin{bmatrix}")
    4
    >>> "1.00 & 0.00 & 0.00" in tex
    True
    """
    decimals = as_count(decimals, "decimals")
    if decimals > 6:
        raise ValueError(f"decimals must be between 0 and 6, got {decimals}")
    w = as_unit_axes(as_vector3(axis, "axis"), "axis", tol)
    theta = _scalar_angle(theta, "theta")
    terms = rodrigues_terms(w, theta, tol)
    R = so3.exp(w, theta)
    th = _fmt(theta, decimals)
    head = (
        rf"\omega = ({', '.join(_fmt(x, decimals) for x in w)}),\ \theta = {th}:\quad "
        r"e^{\hat\omega\theta} = I + \sin\theta\,\hat\omega + (1-\cos\theta)\,\hat\omega^2"
    )
    body = " + ".join(_bmatrix(T, decimals) for T in terms) + " = " + _bmatrix(R, decimals)
    return r"\begin{gathered} " + head + r" \\ " + body + r" \end{gathered}"


def _rotation_view(ax, func, polar, azimuth, theta, elev, azim):
    """Check the angles, point the camera; the axis, the angle and the rotation to draw.

    Only the view changes with ``(elev, azim)``, not what is drawn.
    """
    plotting._require_3d(ax, func)
    polar = _scalar_angle(polar, "polar")
    azimuth = _scalar_angle(azimuth, "azimuth")
    theta = _scalar_angle(theta, "theta")
    ax.view_init(elev=_view_angle(elev, "elev"), azim=_view_angle(azim, "azim"))
    w = axis_from_spherical(polar, azimuth)
    return w, theta, so3.exp(w, theta)


def _moving_axes(w):
    """The world axes e_i (with their colours) that a rotation about the unit axis w moves."""
    for i, color in enumerate(plotting.FRAME_COLORS):
        e = np.eye(3)[i]
        if np.linalg.norm(e - (w @ e) * w) > TOL:
            yield e, color


def _draw_axis_line(ax, w, length=1.4):
    """The rotation axis: a dashed line through the origin and the arrow omega."""
    drawn = []
    drawn.extend(
        plotting.draw_segment(ax, -length * w, length * w, color=_AXIS_COLOR, style="dashed")
    )
    drawn.extend(plotting.draw_vector(ax, w, label=r"$\omega$", color=_AXIS_COLOR))
    return drawn


def draw_rotated_frame(ax, polar, azimuth, theta, *, elev=VIEW_ELEV, azim=VIEW_AZIM):
    r"""Draw the world frame A, the rotated body frame B and the axis of rotation.

    The body frame is :math:`R = e^{\hat\omega\theta}` (eq. 127): its axes are the columns of
    :math:`R`, the world axes carried about :math:`\omega` by :math:`\theta`. Each world axis
    tip travels along a dotted arc :math:`e^{\hat\omega t} e_i`, :math:`t \in [0, \theta]`,
    to the matching body axis tip (no arc is drawn for a world axis that lies on
    :math:`\omega`: it does not move). The camera is set to ``(elev, azim)``; it changes the
    view only, not the geometry drawn.

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.axes3d.Axes3D
        A 3D axes, e.g. from :func:`course_lib.plotting.axes3d`.
    polar, azimuth : float
        Spherical angles of the axis :math:`\omega`, see :func:`axis_from_spherical`.
    theta : float
        Rotation angle in radians.
    elev : float, keyword-only, default VIEW_ELEV = 20
        Camera elevation in degrees above the xy plane (matplotlib's ``view_init``). Not an
        angle of the rotation.
    azim : float, keyword-only, default VIEW_AZIM = -60
        Camera azimuth in degrees about the z axis. Not the azimuth :math:`\lambda` of
        :math:`\omega`.

    Returns
    -------
    course_lib.plotting.Drawn
        ``points``: the body axis tips, shape (3, 3), row i is :math:`R e_i`; ``R``: the
        rotation; ``axis``: :math:`\omega`; ``theta``; ``arcs``: the arc point arrays drawn
        (one per moving world axis).

    Raises
    ------
    ValueError
        If an angle (of the rotation or of the camera) is not a single finite number.
    TypeError
        If ``ax`` is not a 3D axes or an angle is not a real number.

    Examples
    --------
    >>> import numpy as np, matplotlib.pyplot as plt
    >>> from course_lib.plotting import axes3d
    >>> fig, ax = axes3d("Body frame")
    >>> drawn = draw_rotated_frame(ax, 0.0, 0.0, np.pi / 2)   # a quarter turn about z
    >>> np.round(drawn.points[0], 12)                        # body x axis = world y axis
    array([0., 1., 0.])
    >>> side = draw_rotated_frame(axes3d("Side")[1], 0.0, 0.0, np.pi / 2, elev=0, azim=-90)
    >>> side.points.tolist() == drawn.points.tolist()        # another camera, same frame
    True
    >>> plt.close("all")
    """
    w, theta, R = _rotation_view(ax, "draw_rotated_frame", polar, azimuth, theta, elev, azim)
    artists = []
    # World frame A: axis labels x_A, y_A, z_A but no name at the origin, where B's name goes.
    artists.extend(plotting.draw_frame(ax, label=None, style="dotted", axis_names=_WORLD_AXES))
    artists.extend(_draw_axis_line(ax, w))
    arcs = []
    moving = list(_moving_axes(w)) if theta != 0.0 else []  # a zero angle moves nothing
    for e, color in moving:
        arc = plotting.draw_arc(ax, w, e, theta, color=color, style="dotted", arrow=False)
        artists.extend(arc)
        arcs.append(arc.points)
    body = plotting.draw_frame(ax, R, label="B")
    artists.extend(body)
    return plotting.Drawn(
        "rotated_frame", artists, body.points, R=R, axis=w, theta=theta, arcs=arcs
    )


def _draw_orbit(ax, w, q0):
    """The dotted circle that q0 travels about the unit axis w, or None if q0 is on the axis."""
    center = (w @ q0) * w
    if np.linalg.norm(q0 - center) <= TOL:
        return None
    return plotting.draw_arc(
        ax,
        w,
        q0 - center,
        2.0 * np.pi,
        center=center,
        n=90,
        color="0.45",  # 4.7:1 on white (WCAG 1.4.11)
        style="dotted",
        arrow=False,
    )


def draw_rodrigues_terms(ax, polar, azimuth, theta, q0=Q0, *, elev=VIEW_ELEV, azim=VIEW_AZIM):
    r"""Draw Rodrigues' formula assembling :math:`e^{\hat\omega\theta} q_0` tip to tail.

    From the origin: :math:`q_0` (black), then from its tip :math:`\sin\theta\,\hat\omega q_0`
    (orange, tangent to the circle of :math:`q_0` about :math:`\omega`), then
    :math:`(1-\cos\theta)\,\hat\omega^2 q_0` (purple, towards the axis). The chain lands on
    :math:`e^{\hat\omega\theta} q_0` (blue arrow from the origin), a point of the dotted circle
    traced by :math:`q_0` about :math:`\omega` (eq. 125). The camera is set to
    ``(elev, azim)``; it changes the view only, not the geometry drawn.

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.axes3d.Axes3D
        A 3D axes, e.g. from :func:`course_lib.plotting.axes3d`.
    polar, azimuth : float
        Spherical angles of the axis :math:`\omega`, see :func:`axis_from_spherical`.
    theta : float
        Rotation angle in radians.
    q0 : array_like, shape (3,), default Q0
        The point being rotated.
    elev : float, keyword-only, default VIEW_ELEV = 20
        Camera elevation in degrees above the xy plane (matplotlib's ``view_init``). Not an
        angle of the rotation.
    azim : float, keyword-only, default VIEW_AZIM = -60
        Camera azimuth in degrees about the z axis. Not the azimuth :math:`\lambda` of
        :math:`\omega`.

    Returns
    -------
    course_lib.plotting.Drawn
        ``points``: the chain, shape (4, 3): :math:`0`, :math:`q_0`,
        :math:`q_0 + \sin\theta\,\hat\omega q_0` and the end of the third vector;
        ``terms``: the three vectors, shape (3, 3); ``q``: :math:`e^{\hat\omega\theta} q_0`
        from :func:`course_lib.so3.exp`; ``R``; ``axis``; ``theta``; ``circle``: the points of
        the dotted circle (``None`` when :math:`q_0` lies on the axis).

    Raises
    ------
    ValueError
        If an angle (of the rotation or of the camera) is not a single finite number or ``q0``
        is not a finite 3-vector.
    TypeError
        If ``ax`` is not a 3D axes or an input is not numeric.

    Examples
    --------
    >>> import numpy as np, matplotlib.pyplot as plt
    >>> from course_lib.plotting import axes3d
    >>> fig, ax = axes3d("Rodrigues")
    >>> drawn = draw_rodrigues_terms(ax, 0.7, 0.4, 2.0, elev=35, azim=-30)
    >>> np.allclose(drawn.points[-1], drawn.q)               # the chain lands on R q0
    True
    >>> float(ax.elev), float(ax.azim)                       # the camera asked for
    (35.0, -30.0)
    >>> plt.close(fig)
    """
    q0 = as_vector3(q0, "q0")
    w, theta, R = _rotation_view(ax, "draw_rodrigues_terms", polar, azimuth, theta, elev, azim)
    q = R @ q0
    terms = np.stack(rodrigues_vectors(w, theta, q0))
    chain = np.concatenate([np.zeros((1, 3)), np.cumsum(terms, axis=0)])
    artists = []
    artists.extend(_draw_axis_line(ax, w))
    circle = _draw_orbit(ax, w, q0)
    if circle is not None:
        artists.extend(circle)
        circle = circle.points
    for k in range(3):
        artists.extend(plotting.draw_vector(ax, terms[k], origin=chain[k], color=_TERM_COLORS[k]))
    artists.extend(plotting.draw_vector(ax, q, color=_RESULT_COLOR, linewidth=2.6))
    # A legend rather than labels at the tips: the last term and the result end at one point.
    handles = [Line2D([], [], color=c, linewidth=2.2) for c in _TERM_COLORS + (_RESULT_COLOR,)]
    artists.append(
        ax.legend(
            handles,
            _RODRIGUES_LABELS,
            loc="upper left",
            fontsize=plotting.FONT_SIZE - 2,
            frameon=False,
        )
    )
    return plotting.Drawn(
        "rodrigues", artists, chain, terms=terms, q=q, R=R, axis=w, theta=theta, circle=circle
    )


def _axis_angle_sliders(polar, azimuth, theta):
    names = ("axis polar φ", "axis azimuth λ", "angle θ")
    ranges = (POLAR_RANGE, AZIMUTH_RANGE, THETA_RANGE)
    return [SliderSpec(n, v, r) for n, v, r in zip(names, (polar, azimuth, theta), ranges)]


def _num(x, decimals=2):
    """A number for alt text: rounded, with a real minus sign."""
    return _fmt(x, decimals).replace("-", "−")


def _axis_words(polar, azimuth, theta):
    w = axis_from_spherical(polar, azimuth)
    return (
        f"θ = {_num(theta)} rad ({_num(np.degrees(theta), 0)}°) about the axis "
        f"ω = ({', '.join(_num(c) for c in w)}) (polar angle φ = {_num(polar)}, "
        f"azimuth λ = {_num(azimuth)} rad)"
    )


def _rotation_alt(polar, azimuth, theta):
    """What the rotation explorer shows at these slider values, in words (its alt text)."""
    return (
        f"Frame A (dotted axes x_A, y_A, z_A) and frame B (solid axes), frame A turned by "
        f"{_axis_words(polar, azimuth, theta)}; the axis is a dashed grey line through the "
        "origin and each axis tip of A travels to B's along a dotted arc."
    )


def _rodrigues_alt(q0):
    def alt(polar, azimuth, theta):
        q = so3.exp(axis_from_spherical(polar, azimuth), theta) @ q0
        return (
            f"Rodrigues' formula for a turn by {_axis_words(polar, azimuth, theta)}: "
            f"q0 = ({', '.join(_num(c) for c in q0)}) (black), sin θ ω̂q0 (orange) and "
            f"(1 − cos θ) ω̂²q0 (purple) drawn tip to tail land on e^(ω̂θ) q0 = "
            f"({', '.join(_num(c) for c in q)}) (blue), on the circle q0 turns along."
        )

    return alt


def _axis_angle_title(head):
    """The title function of an axis-angle explorer: ``head``, then the axis and the angle."""

    def title(polar, azimuth, theta):
        w = axis_from_spherical(polar, azimuth)
        return f"{head}\n" + (
            rf"$\omega$ = ({w[0]:.2f}, {w[1]:.2f}, {w[2]:.2f}),  $\theta$ = {theta:.2f} rad"
        )

    return title


def rotation_explorer(
    polar=np.pi / 4, azimuth=3 * np.pi / 4, theta=2 * np.pi / 3, *, elev=VIEW_ELEV, azim=VIEW_AZIM
):
    r"""Sliders for an axis and an angle, redrawing the body frame :math:`e^{\hat\omega\theta}`.

    Three sliders (polar angle :math:`\varphi` and azimuth :math:`\lambda` of the unit axis
    :math:`\omega`, rotation angle :math:`\theta`) redraw :func:`draw_rotated_frame`: the world
    frame A (dotted), the axis :math:`\omega`, and the body frame B with

    .. math:: R_{ab} = e^{\hat\omega\theta}, \qquad
              \omega = (\sin\varphi\cos\lambda, \sin\varphi\sin\lambda, \cos\varphi).

    Drag the figure with the mouse to look at the frames from another side; that moves the
    camera only, never the rotation.

    Parameters
    ----------
    polar : float, default π/4
        Initial polar angle, in ``POLAR_RANGE`` = [0, π].
    azimuth : float, default 3π/4
        Initial azimuth, in ``AZIMUTH_RANGE`` = [−π, π].
    theta : float, default 2π/3
        Initial rotation angle, in ``THETA_RANGE`` = [0, 2π].
    elev, azim : float, keyword-only, default VIEW_ELEV = 20, VIEW_AZIM = −60
        Initial camera, in degrees (matplotlib's ``view_init``).

    Returns
    -------
    Explorer
        The sliders and the live figure; ``.result`` holds the current rotation matrix
        :math:`R`.

    Raises
    ------
    ValueError
        If an initial angle is not a finite number inside its slider's range, or a camera
        angle is not a finite number.

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib.rodrigues import rotated_frame
    >>> w = rotation_explorer()
    >>> list(w.sliders)
    ['axis polar φ', 'axis azimuth λ', 'angle θ']
    >>> np.allclose(w.result, rotated_frame(np.pi / 4, 3 * np.pi / 4, 2 * np.pi / 3))
    True
    """
    return Explorer(
        draw_rotated_frame,
        lambda drawn: drawn.R,
        _axis_angle_title(r"Body frame B: $R_{ab} = e^{\hat\omega\theta}$"),
        "Rotation explorer: sliders for the axis ω (polar angle φ, azimuth λ) and the angle θ "
        "redraw frame B, frame A turned by θ about ω; drag the 3D view to turn it.",
        _axis_angle_sliders(polar, azimuth, theta),
        (elev, azim),
        lim=1.2,
        alt=_rotation_alt,
    )


def rodrigues_explorer(
    polar=np.pi / 3, azimuth=np.pi / 2, theta=np.pi / 2, q0=Q0, *, elev=VIEW_ELEV, azim=VIEW_AZIM
):
    r"""Sliders for an axis and an angle, showing Rodrigues' formula assemble the rotation.

    The figure is :func:`draw_rodrigues_terms`: :math:`q_0`, :math:`\sin\theta\,\hat\omega q_0`
    and :math:`(1-\cos\theta)\,\hat\omega^2 q_0` drawn tip to tail, landing on
    :math:`e^{\hat\omega\theta} q_0`; below it, :func:`rodrigues_readout` writes the matrices

    .. math:: e^{\hat\omega\theta} = I + \sin\theta\,\hat\omega + (1-\cos\theta)\,\hat\omega^2

    with numbers (eq. 159). Drag the figure with the mouse to turn the 3D view.

    Parameters
    ----------
    polar : float, default π/3
        Initial polar angle of the axis, in [0, π].
    azimuth : float, default π/2
        Initial azimuth of the axis, in [−π, π] (π/2: the axis is perpendicular to
        ``Q0``, whose circle is then as large as it can be).
    theta : float, default π/2
        Initial rotation angle, in [0, 2π].
    q0 : array_like, shape (3,), default Q0
        The point being rotated.
    elev, azim : float, keyword-only, default VIEW_ELEV = 20, VIEW_AZIM = −60
        Initial camera, in degrees.

    Returns
    -------
    Explorer
        The sliders, the live figure and the readout; ``.result`` holds the three vectors of
        :func:`course_lib.rodrigues.rodrigues_vectors`, shape (3, 3).

    Raises
    ------
    ValueError
        If an initial value is outside its slider's range, or ``q0`` is not a finite 3-vector.

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib import so3
    >>> from course_lib.rodrigues import axis_from_spherical
    >>> w = rodrigues_explorer(theta=1.0)
    >>> axis = axis_from_spherical(np.pi / 3, np.pi / 2)
    >>> np.allclose(w.result.sum(axis=0), so3.exp(axis, 1.0) @ Q0)
    True
    """
    q0 = as_vector3(q0, "q0")

    def draw(ax, polar, azimuth, theta, *, elev, azim):
        return draw_rodrigues_terms(ax, polar, azimuth, theta, q0, elev=elev, azim=azim)

    return Explorer(
        draw,
        lambda drawn: drawn.terms,
        _axis_angle_title(r"Rodrigues' formula applied to $q_0$"),
        "Rodrigues explorer: sliders for the axis ω and the angle θ; q0, sinθ ω̂q0 and "
        "(1 − cosθ) ω̂²q0 drawn tip to tail land on e^(ω̂θ) q0; the matrices below, with "
        "numbers; drag the 3D view to turn it.",
        _axis_angle_sliders(polar, azimuth, theta),
        (elev, azim),
        lim=1.3,
        readout=lambda polar, azimuth, theta: rodrigues_readout(
            axis_from_spherical(polar, azimuth), theta
        ),
        alt=_rodrigues_alt(q0),
    )
