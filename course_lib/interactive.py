r"""Interactive and animated figures for the chapters on rotations and exponential coordinates.

Two slider widgets and one animation, each built on small pure functions that are tested
without any widget:

==============================  ===============================================================
Widget / animation              Pure functions behind it
==============================  ===============================================================
:func:`rotation_explorer`       :func:`axis_from_spherical`, :func:`rotated_frame`,
(notebook 02)                   :func:`draw_rotated_frame`
:func:`rodrigues_explorer`      :func:`rodrigues_terms`, :func:`rodrigues_vectors`,
(notebook 03)                   :func:`rodrigues_readout`, :func:`draw_rodrigues_terms`
:func:`spin_animation`          :func:`spin_rotations`, :func:`spin_times`
(unit angular velocity)
==============================  ===============================================================

The rotation axis is a unit vector :math:`\omega`, given to the sliders by two spherical
angles: the polar angle :math:`\varphi \in [0, \pi]` (measured from the z axis) and the azimuth
:math:`\lambda \in [-\pi, \pi]` (measured in the xy plane from the x axis). The rotation is the
notes' :math:`R(\omega, \theta) = e^{\hat\omega\theta}` (eq. 127), computed by
:func:`course_lib.so3.exp`; drawing uses the primitives of :mod:`course_lib.plotting`.

The widgets redraw a fresh PNG each time a slider is released (``continuous_update=False``),
so they work in JupyterLab with the default inline backend; in the stored notebooks their
outputs are marked ``NBVAL_IGNORE_OUTPUT`` because widget model ids are random.

The 3D view of both explorers can be turned: besides the three sliders of the rotation, two
camera sliders, ``view elev (°)`` and ``view azim (°)``, set matplotlib's viewing angles
(``Axes3D.view_init``, in degrees; defaults :data:`VIEW_ELEV`, :data:`VIEW_AZIM`, the view of
:func:`course_lib.plotting.axes3d`). They move the camera only, never the drawn geometry. The
course does not use the ``ipympl`` backend (mouse-draggable figures), which would store widget
state instead of static PNGs in the saved notebooks.
"""

import numpy as np

import matplotlib.pyplot as plt
from matplotlib import animation
from matplotlib.lines import Line2D

from . import plotting, so3
from ._arrays import as_angles, as_count, as_vectors
from .tolerance import TOL

__all__ = [
    "POLAR_RANGE",
    "AZIMUTH_RANGE",
    "THETA_RANGE",
    "Q0",
    "VIEW_ELEV",
    "VIEW_AZIM",
    "VIEW_ELEV_RANGE",
    "VIEW_AZIM_RANGE",
    "axis_from_spherical",
    "rotated_frame",
    "rodrigues_terms",
    "rodrigues_vectors",
    "rodrigues_readout",
    "draw_rotated_frame",
    "draw_rodrigues_terms",
    "rotation_explorer",
    "rodrigues_explorer",
    "spin_times",
    "spin_rotations",
    "spin_animation",
]

#: Slider ranges, in radians: polar angle of the axis, its azimuth, and the rotation angle.
POLAR_RANGE = (0.0, np.pi)
AZIMUTH_RANGE = (-np.pi, np.pi)
THETA_RANGE = (0.0, 2.0 * np.pi)

#: The fixed point q0 that the Rodrigues explorer rotates (the tip of the world x axis).
Q0 = (1.0, 0.0, 0.0)

#: Default camera of the 3D views, in degrees (``view_init``): the view of ``plotting.axes3d``.
VIEW_ELEV = 20.0
VIEW_AZIM = -60.0

#: Ranges of the camera sliders, in degrees: elevation from below (−90) to above (90) the xy
#: plane, azimuth once around the z axis.
VIEW_ELEV_RANGE = (-90.0, 90.0)
VIEW_AZIM_RANGE = (-180.0, 180.0)

_SLIDER_STEP = 0.01
_VIEW_STEP = 1.0
_EXPLORER_ZOOM = 0.85
_TERM_COLORS = ("black", "tab:orange", "tab:purple")
_RESULT_COLOR = "tab:blue"
_AXIS_COLOR = "0.35"
_WORLD_AXES = ("x_A", "y_A", "z_A")
_RODRIGUES_LABELS = (
    r"$q_0$",
    r"$\sin\theta\,\hat\omega q_0$",
    r"$(1-\cos\theta)\,\hat\omega^2 q_0$",
    r"$e^{\hat\omega\theta}q_0$ (sum)",
)


# --------------------------------------------------------------------------------------------
# Pure functions
# --------------------------------------------------------------------------------------------


def axis_from_spherical(polar, azimuth):
    r"""The unit rotation axis with the given polar angle and azimuth.

    .. math::

        \omega(\varphi, \lambda) = \begin{bmatrix} \sin\varphi\cos\lambda \\
        \sin\varphi\sin\lambda \\ \cos\varphi \end{bmatrix}, \qquad \|\omega\| = 1 .

    Parameters
    ----------
    polar : array_like
        Polar angle :math:`\varphi` in radians, measured from the z axis (any real value;
        the sliders use :math:`[0, \pi]`).
    azimuth : array_like
        Azimuth :math:`\lambda` in radians, measured in the xy plane from the x axis.
        Broadcast against ``polar``.

    Returns
    -------
    ndarray, shape (..., 3)
        Unit vectors, one per broadcast pair of angles.

    Raises
    ------
    ValueError
        If an angle is NaN or infinite, or the shapes do not broadcast.
    TypeError
        If an angle is not a real number.

    Examples
    --------
    >>> import numpy as np
    >>> np.round(axis_from_spherical(np.pi / 2, np.pi / 2), 12)
    array([0., 1., 0.])
    >>> axis_from_spherical([0.0, 1.0, 2.0], 0.3).shape
    (3, 3)
    """
    polar = as_angles(polar, "polar")
    azimuth = as_angles(azimuth, "azimuth")
    try:
        polar, azimuth = np.broadcast_arrays(polar, azimuth)
    except ValueError:
        raise ValueError(
            f"polar and azimuth must broadcast together, got shapes {np.shape(polar)} "
            f"and {np.shape(azimuth)}"
        ) from None
    s = np.sin(polar)
    return np.stack([s * np.cos(azimuth), s * np.sin(azimuth), np.cos(polar)], axis=-1)


def rotated_frame(polar, azimuth, theta):
    r"""The rotation by ``theta`` about the axis with spherical angles ``(polar, azimuth)``.

    .. math:: R = e^{\hat\omega\theta}, \qquad \omega = \omega(\varphi, \lambda)

    (eq. 127); its columns are the axes of the rotated body frame seen in the world frame
    (eq. 26).

    Parameters
    ----------
    polar, azimuth : array_like
        Spherical angles of the axis, see :func:`axis_from_spherical`.
    theta : array_like
        Rotation angle in radians, broadcast against the angles of the axis.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        Rotation matrices.

    Raises
    ------
    ValueError
        If an input is NaN or infinite, or the shapes do not broadcast.
    TypeError
        If an input is not a real number.

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib import so3
    >>> R = rotated_frame(0.0, 0.0, np.pi / 2)      # polar angle 0: the z axis
    >>> np.allclose(R, so3.rot_z(np.pi / 2))
    True
    """
    axis = axis_from_spherical(polar, azimuth)
    theta = as_angles(theta, "theta")
    return so3.exp(axis, theta)


def _unit_axis(axis, tol=TOL, name="axis"):
    """A (..., 3) array of unit vectors, or ValueError naming the norm that is off."""
    w = as_vectors(axis, name)
    norm = np.linalg.norm(w, axis=-1)
    off = np.abs(norm - 1.0)
    if not np.all(off <= tol):
        worst = np.unravel_index(np.argmax(off), off.shape) if off.ndim else ()
        where = f" at batch index {tuple(int(i) for i in worst)}" if worst else ""
        raise ValueError(
            f"{name} is not a unit vector: ‖{name}‖ = {float(norm[worst]):.6g}, "
            f"|‖{name}‖ − 1| = {float(off[worst]):.1e} > TOL = {tol:.0e}{where}; "
            f"expected ‖{name}‖ = 1 (divide by its norm)"
        )
    return w


def rodrigues_terms(axis, theta, tol=TOL):
    r"""The three terms of Rodrigues' formula, whose sum is :math:`e^{\hat\omega\theta}`.

    .. math::

        e^{\hat\omega\theta} = \underbrace{I}_{\text{term 0}}
        + \underbrace{\sin\theta\,\hat\omega}_{\text{term 1}}
        + \underbrace{(1-\cos\theta)\,\hat\omega^2}_{\text{term 2}}
        \qquad \text{(eq. 159)} .

    Parameters
    ----------
    axis : array_like, shape (..., 3)
        Unit rotation axes :math:`\omega`.
    theta : array_like
        Angles in radians, broadcast against the batch shape of ``axis``.
    tol : float, default TOL
        Largest accepted :math:`|\|\omega\| - 1|`.

    Returns
    -------
    identity, sin_term, cos_term : ndarray, shape (..., 3, 3)
        :math:`I`, :math:`\sin\theta\,\hat\omega` and :math:`(1-\cos\theta)\,\hat\omega^2`.

    Raises
    ------
    ValueError
        If an axis is not a unit vector (the message gives its norm), a shape is wrong, or an
        input is NaN or infinite.
    TypeError
        If an input is not a real number.

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib import so3
    >>> I, S, C = rodrigues_terms([0, 0, 1], np.pi / 2)
    >>> np.round(S, 12) + 0.0                       # + 0.0 turns -0. into 0.
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  0.],
           [ 0.,  0.,  0.]])
    >>> np.allclose(I + S + C, so3.exp([0, 0, 1], np.pi / 2))
    True
    """
    w = _unit_axis(axis, tol)
    theta = as_angles(theta, "theta")
    W = so3.hat(w)
    W2 = W @ W
    try:
        shape = np.broadcast_shapes(w.shape[:-1], theta.shape)
    except ValueError:
        raise ValueError(
            f"theta of shape {theta.shape} does not broadcast against the batch shape "
            f"{w.shape[:-1]} of axis"
        ) from None
    s = np.sin(theta)[..., None, None]
    c = (1.0 - np.cos(theta))[..., None, None]
    identity = np.broadcast_to(np.eye(3), shape + (3, 3)).copy()
    sin_term = np.broadcast_to(s * W, shape + (3, 3)).copy()
    cos_term = np.broadcast_to(c * W2, shape + (3, 3)).copy()
    return identity, sin_term, cos_term


def rodrigues_vectors(axis, theta, q0=Q0, tol=TOL):
    r"""Rodrigues' formula applied to a point: three vectors that add up to the rotated point.

    .. math::

        e^{\hat\omega\theta} q_0 = q_0 + \sin\theta\,\hat\omega q_0
        + (1-\cos\theta)\,\hat\omega^2 q_0 ,

    where :math:`\hat\omega q_0 = \omega \times q_0` is tangent to the circle that
    :math:`q_0` travels about the axis and :math:`\hat\omega^2 q_0 = \omega\,\omega^T q_0 - q_0`
    (eq. 141) points from :math:`q_0` towards the axis. Drawn tip to tail, the three vectors
    land on :math:`e^{\hat\omega\theta} q_0`.

    Parameters
    ----------
    axis : array_like, shape (..., 3)
        Unit rotation axes.
    theta : array_like
        Angles in radians.
    q0 : array_like, shape (..., 3), default Q0
        The point being rotated.
    tol : float, default TOL
        Largest accepted :math:`|\|\omega\| - 1|`.

    Returns
    -------
    q0, sin_vec, cos_vec : ndarray, shape (..., 3)
        :math:`q_0`, :math:`\sin\theta\,\hat\omega q_0` and
        :math:`(1-\cos\theta)\,\hat\omega^2 q_0`, broadcast to a common shape.

    Raises
    ------
    ValueError
        If an axis is not a unit vector, a shape is wrong, or an input is NaN or infinite.
    TypeError
        If an input is not a real number.

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib import so3
    >>> parts = rodrigues_vectors([0, 0, 1], np.pi / 2, q0=[1, 0, 0])
    >>> [np.round(p, 12).tolist() for p in parts]
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]]
    >>> np.allclose(sum(parts), so3.exp([0, 0, 1], np.pi / 2) @ [1, 0, 0])
    True
    """
    q0 = as_vectors(q0, "q0")
    identity, sin_term, cos_term = rodrigues_terms(axis, theta, tol)
    try:
        shape = np.broadcast_shapes(identity.shape[:-2], q0.shape[:-1])
    except ValueError:
        raise ValueError(
            f"q0 of shape {q0.shape} does not broadcast against the batch shape "
            f"{identity.shape[:-2]} of axis and theta"
        ) from None
    q = np.broadcast_to(q0, shape + (3,))
    return (
        q.copy(),
        np.einsum("...ij,...j->...i", sin_term, q),
        np.einsum("...ij,...j->...i", cos_term, q),
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
    w = _unit_axis(axis, tol)
    if w.shape != (3,):
        raise ValueError(f"axis must be a single 3-vector of shape (3,), got shape {w.shape}")
    theta = as_angles(theta, "theta")
    if theta.shape != ():
        raise ValueError(f"theta must be a single angle, got shape {theta.shape}")
    terms = rodrigues_terms(w, theta, tol)
    R = so3.exp(w, theta)
    th = _fmt(theta, decimals)
    head = (
        rf"\omega = ({', '.join(_fmt(x, decimals) for x in w)}),\ \theta = {th}:\quad "
        r"e^{\hat\omega\theta} = I + \sin\theta\,\hat\omega + (1-\cos\theta)\,\hat\omega^2"
    )
    body = " + ".join(_bmatrix(T, decimals) for T in terms) + " = " + _bmatrix(R, decimals)
    return r"\begin{gathered} " + head + r" \\ " + body + r" \end{gathered}"


# --------------------------------------------------------------------------------------------
# Drawing onto given axes
# --------------------------------------------------------------------------------------------


def _scalar_angle(x, name):
    a = as_angles(x, name)
    if a.shape != ():
        raise ValueError(f"{name} must be a single angle (a number), got shape {a.shape}")
    return float(a)


def _view_angle(x, name):
    """A camera angle in degrees: a single finite real number (any value, as ``view_init``)."""
    a = as_angles(x, name)
    if a.shape != ():
        raise ValueError(
            f"{name} must be a single viewing angle in degrees (a number), got shape {a.shape}"
        )
    return float(a)


def _set_view(ax, elev, azim):
    """Point the camera of a 3D axes; only the view changes, not what is drawn."""
    ax.view_init(elev=elev, azim=azim)


def _draw_axis_line(ax, w, length=1.4):
    """The rotation axis: a dashed line through the origin and the arrow omega."""
    drawn = []
    drawn.extend(plotting.draw_segment(ax, -length * w, length * w, color=_AXIS_COLOR, style="dashed"))
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
    plotting._require_3d(ax, "draw_rotated_frame")
    polar = _scalar_angle(polar, "polar")
    azimuth = _scalar_angle(azimuth, "azimuth")
    theta = _scalar_angle(theta, "theta")
    elev = _view_angle(elev, "elev")
    azim = _view_angle(azim, "azim")
    _set_view(ax, elev, azim)
    w = axis_from_spherical(polar, azimuth)
    R = so3.exp(w, theta)
    artists = []
    # World frame A: axis labels x_A, y_A, z_A but no name at the origin, where B's name goes.
    artists.extend(plotting.draw_frame(ax, label=None, style="dotted", axis_names=_WORLD_AXES))
    artists.extend(_draw_axis_line(ax, w))
    arcs = []
    for i, color in enumerate(plotting.FRAME_COLORS):
        e = np.eye(3)[i]
        if np.linalg.norm(e - (w @ e) * w) > TOL and theta != 0.0:
            arc = plotting.draw_arc(ax, w, e, theta, color=color, style="dotted", arrow=False)
            artists.extend(arc)
            arcs.append(arc.points)
    body = plotting.draw_frame(ax, R, label="B")
    artists.extend(body)
    return plotting.Drawn("rotated_frame", artists, body.points, R=R, axis=w, theta=theta, arcs=arcs)


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
    plotting._require_3d(ax, "draw_rodrigues_terms")
    polar = _scalar_angle(polar, "polar")
    azimuth = _scalar_angle(azimuth, "azimuth")
    theta = _scalar_angle(theta, "theta")
    q0 = as_vectors(q0, "q0")
    if q0.shape != (3,):
        raise ValueError(f"q0 must be a single 3-vector of shape (3,), got shape {q0.shape}")
    elev = _view_angle(elev, "elev")
    azim = _view_angle(azim, "azim")
    _set_view(ax, elev, azim)
    w = axis_from_spherical(polar, azimuth)
    R = so3.exp(w, theta)
    q = R @ q0
    terms = np.stack(rodrigues_vectors(w, theta, q0))
    chain = np.concatenate([np.zeros((1, 3)), np.cumsum(terms, axis=0)])
    artists = []
    artists.extend(_draw_axis_line(ax, w))
    center = (w @ q0) * w
    circle = None
    if np.linalg.norm(q0 - center) > TOL:
        arc = plotting.draw_arc(ax, w, q0 - center, 2.0 * np.pi, center=center, n=90,
                                color="0.6", style="dotted", arrow=False)
        artists.extend(arc)
        circle = arc.points
    for k in range(3):
        artists.extend(plotting.draw_vector(ax, terms[k], origin=chain[k], color=_TERM_COLORS[k]))
    artists.extend(plotting.draw_vector(ax, q, color=_RESULT_COLOR, linewidth=2.6))
    # A legend rather than labels at the tips: the last term and the result end at one point.
    handles = [Line2D([], [], color=c, linewidth=2.2) for c in _TERM_COLORS + (_RESULT_COLOR,)]
    artists.append(ax.legend(handles, _RODRIGUES_LABELS, loc="upper left", fontsize=plotting.FONT_SIZE - 2,
                             frameon=False))
    return plotting.Drawn("rodrigues", artists, chain, terms=terms, q=q, R=R, axis=w,
                          theta=theta, circle=circle)


# --------------------------------------------------------------------------------------------
# Widgets
# --------------------------------------------------------------------------------------------


def _in_ipython():
    """True inside an IPython shell or kernel (where ``display`` shows rich output)."""
    from IPython import get_ipython

    return get_ipython() is not None


def _show(*objs):
    """Display ``objs`` in a notebook (inside the widget's output area); no-op elsewhere.

    Outside IPython, ``display`` would print reprs to stdout, which tells nobody anything.
    """
    if _in_ipython():
        from IPython.display import clear_output, display

        clear_output(wait=True)
        display(*objs)


def _slider(value, bounds, description, unit="radians", step=_SLIDER_STEP, readout=".2f"):
    import ipywidgets

    lo, hi = bounds
    value = _scalar_angle(value, description)
    if not lo <= value <= hi:
        raise ValueError(
            f"{description} = {value:g} is outside the slider range [{lo:.4g}, {hi:.4g}] ({unit})"
        )
    return ipywidgets.FloatSlider(
        value=value,
        min=lo,
        max=hi,
        step=step,
        description=description,
        continuous_update=False,
        readout_format=readout,
        style={"description_width": "8em"},
        layout=ipywidgets.Layout(width="30em"),
    )


def _view_slider(value, bounds, description):
    return _slider(value, bounds, description, unit="degrees", step=_VIEW_STEP, readout=".0f")


def _explorer(callback, polar, azimuth, theta, elev, azim):
    import ipywidgets

    return ipywidgets.interactive(
        callback,
        polar=_slider(polar, POLAR_RANGE, "axis polar φ"),
        azimuth=_slider(azimuth, AZIMUTH_RANGE, "axis azimuth λ"),
        theta=_slider(theta, THETA_RANGE, "angle θ"),
        # The camera, in degrees; labelled "view" so it is not taken for the axis angles.
        elev=_view_slider(elev, VIEW_ELEV_RANGE, "view elev (°)"),
        azim=_view_slider(azim, VIEW_AZIM_RANGE, "view azim (°)"),
        # _show clears the output itself, only inside IPython (clear_output would print
        # escape codes elsewhere).
        clear_output=False,
    )


def _explorer_axes(title, w, theta):
    """A 3D figure whose second title line gives the current axis and angle."""
    angles = rf"$\omega$ = ({w[0]:.2f}, {w[1]:.2f}, {w[2]:.2f}),  $\theta$ = {theta:.2f} rad"
    fig, ax = plotting.axes3d(title + "\n" + angles)
    fig.subplots_adjust(top=0.86)
    # The camera sliders can look from below, where the x/y tick labels go to the top of the
    # cube: drawn a little smaller, the cube keeps its labels clear of the title and inside the
    # figure at every camera angle the sliders allow.
    ax.set_box_aspect((1, 1, 1), zoom=_EXPLORER_ZOOM)
    return fig, ax


def rotation_explorer(polar=np.pi / 4, azimuth=np.pi / 4, theta=np.pi / 3, *,
                      elev=VIEW_ELEV, azim=VIEW_AZIM):
    r"""Sliders for an axis and an angle, redrawing the body frame :math:`e^{\hat\omega\theta}`.

    Three sliders (polar angle :math:`\varphi` and azimuth :math:`\lambda` of the unit axis
    :math:`\omega`, rotation angle :math:`\theta`) redraw :func:`draw_rotated_frame`: the world
    frame A (dotted), the axis :math:`\omega`, and the body frame B with

    .. math:: R_{ab} = e^{\hat\omega\theta}, \qquad
              \omega = (\sin\varphi\cos\lambda, \sin\varphi\sin\lambda, \cos\varphi).

    Two more sliders, ``view elev (°)`` and ``view azim (°)``, turn the camera to look at the
    frames from another side; they do not change the rotation.

    Parameters
    ----------
    polar : float, default π/4
        Initial polar angle, in ``POLAR_RANGE`` = [0, π].
    azimuth : float, default π/4
        Initial azimuth, in ``AZIMUTH_RANGE`` = [−π, π].
    theta : float, default π/3
        Initial rotation angle, in ``THETA_RANGE`` = [0, 2π].
    elev : float, keyword-only, default VIEW_ELEV = 20
        Initial camera elevation in degrees, in ``VIEW_ELEV_RANGE`` = [−90, 90].
    azim : float, keyword-only, default VIEW_AZIM = −60
        Initial camera azimuth in degrees, in ``VIEW_AZIM_RANGE`` = [−180, 180].

    Returns
    -------
    ipywidgets.interactive
        A box with the five sliders and the figure; ``.result`` holds the current rotation
        matrix :math:`R`.

    Raises
    ------
    ValueError
        If an initial value is not a finite number inside its slider's range.

    Examples
    --------
    >>> import numpy as np
    >>> w = rotation_explorer()
    >>> [child.description for child in w.children[:5]]
    ['axis polar φ', 'axis azimuth λ', 'angle θ', 'view elev (°)', 'view azim (°)']
    >>> np.allclose(w.result, rotated_frame(np.pi / 4, np.pi / 4, np.pi / 3))
    True
    """

    def redraw(polar, azimuth, theta, elev, azim):
        w = axis_from_spherical(polar, azimuth)
        fig, ax = _explorer_axes(r"Body frame B: $R_{ab} = e^{\hat\omega\theta}$", w, theta)
        drawn = draw_rotated_frame(ax, polar, azimuth, theta, elev=elev, azim=azim)
        _show(fig)
        plt.close(fig)
        return drawn.R

    return _explorer(redraw, polar, azimuth, theta, elev, azim)


def rodrigues_explorer(polar=np.pi / 4, azimuth=np.pi / 4, theta=np.pi / 3, q0=Q0, *,
                       elev=VIEW_ELEV, azim=VIEW_AZIM):
    r"""Sliders for an axis and an angle, showing Rodrigues' formula assemble the rotation.

    The figure is :func:`draw_rodrigues_terms`: :math:`q_0`, :math:`\sin\theta\,\hat\omega q_0`
    and :math:`(1-\cos\theta)\,\hat\omega^2 q_0` drawn tip to tail, landing on
    :math:`e^{\hat\omega\theta} q_0`; below it, :func:`rodrigues_readout` writes the matrices

    .. math:: e^{\hat\omega\theta} = I + \sin\theta\,\hat\omega + (1-\cos\theta)\,\hat\omega^2

    with numbers (eq. 159). Two camera sliders, ``view elev (°)`` and ``view azim (°)``, turn
    the 3D view without changing the rotation.

    Parameters
    ----------
    polar : float, default π/4
        Initial polar angle of the axis, in [0, π].
    azimuth : float, default π/4
        Initial azimuth of the axis, in [−π, π].
    theta : float, default π/3
        Initial rotation angle, in [0, 2π].
    q0 : array_like, shape (3,), default Q0
        The point being rotated.
    elev : float, keyword-only, default VIEW_ELEV = 20
        Initial camera elevation in degrees, in [−90, 90].
    azim : float, keyword-only, default VIEW_AZIM = −60
        Initial camera azimuth in degrees, in [−180, 180].

    Returns
    -------
    ipywidgets.interactive
        The five sliders, the figure and the readout; ``.result`` holds the three vectors of
        :func:`rodrigues_vectors`, shape (3, 3).

    Raises
    ------
    ValueError
        If an initial value is outside its slider's range, or ``q0`` is not a finite 3-vector.

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib import so3
    >>> w = rodrigues_explorer(theta=1.0)
    >>> axis = axis_from_spherical(np.pi / 4, np.pi / 4)
    >>> np.allclose(w.result.sum(axis=0), so3.exp(axis, 1.0) @ Q0)
    True
    """
    q0 = as_vectors(q0, "q0")
    if q0.shape != (3,):
        raise ValueError(f"q0 must be a single 3-vector of shape (3,), got shape {q0.shape}")

    def redraw(polar, azimuth, theta, elev, azim):
        from IPython.display import Math

        w = axis_from_spherical(polar, azimuth)
        fig, ax = _explorer_axes(r"Rodrigues' formula applied to $q_0$", w, theta)
        drawn = draw_rodrigues_terms(ax, polar, azimuth, theta, q0, elev=elev, azim=azim)
        _show(fig, Math(rodrigues_readout(w, theta)))
        plt.close(fig)
        return drawn.terms

    return _explorer(redraw, polar, azimuth, theta, elev, azim)


# --------------------------------------------------------------------------------------------
# Animation
# --------------------------------------------------------------------------------------------


def spin_times(frames, duration=2.0 * np.pi):
    r"""The sample times of a spin animation: ``frames`` equal steps over ``duration``.

    .. math:: t_k = k\,\frac{T}{N}, \qquad k = 0, \dots, N-1,

    the end point :math:`T` left out so that a full turn (:math:`T = 2\pi`) loops without a
    repeated frame. With unit angular velocity the angle equals the time, :math:`\theta = t`.

    Parameters
    ----------
    frames : int
        Number of frames :math:`N` (at least 2).
    duration : float, default 2π
        Total time :math:`T` in seconds (> 0).

    Returns
    -------
    ndarray, shape (frames,)

    Raises
    ------
    ValueError
        If ``frames < 2`` or ``duration`` is not a positive finite number.
    TypeError
        If ``frames`` is not an integer.

    Examples
    --------
    >>> spin_times(4, duration=2.0)
    array([0. , 0.5, 1. , 1.5])
    """
    frames = as_count(frames, "frames", minimum=2)
    duration = _scalar_angle(duration, "duration")
    if not duration > 0:
        raise ValueError(f"duration must be > 0 seconds, got {duration:g}")
    return np.arange(frames) * (duration / frames)


def spin_rotations(axis, t):
    r"""Orientation of a body spinning at unit angular velocity about ``axis``, at times ``t``.

    With :math:`\omega = \mathrm{axis}/\|\mathrm{axis}\|` (unit magnitude: one radian per
    second), a point of the body moves as :math:`q(t) = e^{\hat\omega t} q_0` (eq. 123), so the
    body frame at time :math:`t` is

    .. math:: R(t) = e^{\hat\omega t}, \qquad \theta = t \quad \text{(eq. 125)} .

    Parameters
    ----------
    axis : array_like, shape (3,)
        Direction of the angular velocity (any non-zero length; it is normalised).
    t : array_like
        Times in seconds.

    Returns
    -------
    ndarray, shape t.shape + (3, 3)

    Raises
    ------
    ValueError
        If ``axis`` is not a 3-vector, has norm ``<= TOL``, or an input is not finite.
    TypeError
        If an input is not numeric.

    Examples
    --------
    >>> import numpy as np
    >>> R = spin_rotations([0, 0, 2], [0.0, np.pi / 2])   # the length of axis is ignored
    >>> np.round(R[1] @ [1, 0, 0], 12)
    array([0., 1., 0.])
    """
    w = as_vectors(axis, "axis")
    if w.shape != (3,):
        raise ValueError(f"axis must be a single 3-vector of shape (3,), got shape {w.shape}")
    norm = float(np.linalg.norm(w))
    if norm <= TOL:
        raise ValueError(
            f"axis must be non-zero to define a direction of spin: ‖axis‖ = {norm:.1e} "
            f"<= TOL = {TOL:.0e}"
        )
    t = as_angles(t, "t")
    return so3.exp(w / norm, t)


def spin_animation(axis=(0.0, 0.0, 1.0), frames=20, duration=2.0 * np.pi, dpi=60, size=3.2):
    r"""An HTML animation of a body frame spinning at unit angular velocity about ``axis``.

    Frame :math:`k` shows the body frame :math:`R(t_k) = e^{\hat\omega t_k}` at time
    :math:`t_k` (:func:`spin_times`, :func:`spin_rotations`), the world frame (dotted), the axis
    and the circles that the body axis tips travel on. The player advances at one frame per
    :math:`T/N` seconds, so the picture turns at one radian per second: the angle is the time
    (eq. 125).

    Built with matplotlib's ``FuncAnimation.to_jshtml`` (PNG frames embedded in the page, no
    ffmpeg); the figure is closed so no static copy is displayed as well. Keep ``frames``,
    ``dpi`` and ``size`` small: the HTML is stored in the notebook.

    Parameters
    ----------
    axis : array_like, shape (3,), default (0, 0, 1)
        Direction of the angular velocity (normalised).
    frames : int, default 20
        Number of frames (2 to 120).
    duration : float, default 2π
        Time covered, in seconds (= radians turned).
    dpi : int, default 60
        Resolution of the embedded frames (20 to 150).
    size : float, default 3.2
        Figure width and height in inches (1 to 8).

    Returns
    -------
    IPython.display.HTML
        The JavaScript player; its ``.data`` is the HTML text.

    Raises
    ------
    ValueError
        If ``axis`` is zero or not a 3-vector, or a size parameter is out of range.
    TypeError
        If ``frames`` or ``dpi`` is not an integer.

    Examples
    --------
    >>> html = spin_animation(frames=3, dpi=20)
    >>> html.data.count("data:image/png;base64") >= 3
    True
    """
    from IPython.display import HTML

    frames = as_count(frames, "frames", minimum=2)
    if frames > 120:
        raise ValueError(f"frames must be at most 120 (the frames are stored in the notebook), got {frames}")
    dpi = as_count(dpi, "dpi", minimum=20)
    if dpi > 150:
        raise ValueError(f"dpi must be between 20 and 150, got {dpi}")
    size = _scalar_angle(size, "size")
    if not 1.0 <= size <= 8.0:
        raise ValueError(f"size must be between 1 and 8 inches, got {size:g}")
    times = spin_times(frames, duration)
    rotations = spin_rotations(axis, times)
    w = as_vectors(axis, "axis")
    w = w / np.linalg.norm(w)

    fig, ax = plotting.axes3d(r"Spinning at $\|\omega\| = 1$ rad/s", lim=1.1, figsize=(size, size))
    ax.set_axis_off()  # panes and ticks would change nothing but triple the stored size
    fig.subplots_adjust(left=0.0, right=1.0, bottom=0.0, top=0.92)
    plotting.draw_frame(ax, label=None, style="dotted", axis_names=_WORLD_AXES)
    _draw_axis_line(ax, w)
    for i, color in enumerate(plotting.FRAME_COLORS):
        e = np.eye(3)[i]
        if np.linalg.norm(e - (w @ e) * w) > TOL:
            plotting.draw_arc(ax, w, e, 2.0 * np.pi, color=color, style="dotted", arrow=False, n=72)
    clock = ax.text2D(0.5, 0.02, "", transform=ax.transAxes, ha="center")
    body = []

    def update(k):
        for artist in body:
            artist.remove()
        body.clear()
        body.extend(plotting.draw_frame(ax, rotations[k], label="B"))
        clock.set_text(rf"$t = \theta = {times[k]:.2f}$")
        return body + [clock]

    interval_ms = 1000.0 * float(times[1] - times[0])
    anim = animation.FuncAnimation(fig, update, frames=frames, interval=interval_ms, blit=False)
    try:
        with plt.rc_context({"savefig.dpi": dpi}):
            html = anim.to_jshtml(default_mode="loop")
    finally:
        plt.close(fig)
    return HTML(html)
