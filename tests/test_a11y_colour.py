"""Figures readable without colour (WCAG 1.4.1, 1.4.11): the frame palette simulated for
protanopia and deuteranopia (Machado, Oliveira & Fernandes 2009, severity 1.0) on the palette and
on a rendered PNG, its contrast on white, and what tells the axes apart besides colour."""

import io
import itertools

import matplotlib.colors as mc
import matplotlib.pyplot as plt
import numpy as np
import pytest
from PIL import Image

from course_lib import plotting
from course_lib.plotting.figures_orientation import double_cover
from instructor.build import figure_audit
from instructor.build.figure_audit import contrast, delta_e, lab, linear, simulate  # noqa: F401

# Machado et al. 2009 (instructor/build/figure_audit.py), severity 1.0: the two red-green
# deficiencies, which the frame palette is made for (tritanopia: instructor/build/figure_audit.py on
# every figure)
MACHADO = {k: figure_audit.MACHADO[k] for k in ("protanopia", "deuteranopia")}

MIN_DELTA_E = 20.0  # CIE76 distance in L*a*b*: about 2.3 is "just noticeable"; 20 is clearly apart


def test_machado_matrices_keep_white_and_black():
    for m in MACHADO.values():
        assert np.allclose(m.sum(axis=1), 1.0, atol=1e-3)  # grey stays grey


def test_regression_red_and_green_axes_merged_for_deuteranopes():
    """tab:red and tab:green, the old x and y axes, are 7 apart (CIE76) under deuteranopia."""
    red, green = mc.to_rgb("tab:red"), mc.to_rgb("tab:green")
    assert delta_e(simulate(red, "deuteranopia"), simulate(green, "deuteranopia")) < MIN_DELTA_E


@pytest.mark.parametrize("kind", sorted(MACHADO))
def test_frame_colours_stay_apart_under_colour_blindness(kind):
    for a, b in itertools.combinations(plotting.FRAME_COLORS, 2):
        d = delta_e(simulate(mc.to_rgb(a), kind), simulate(mc.to_rgb(b), kind))
        assert d >= MIN_DELTA_E, f"{a} and {b} are {d:.1f} apart under {kind}"


def test_line_colours_have_3_to_1_contrast_on_white():
    for c in (*plotting.FRAME_COLORS, "#C04F00", "tab:purple"):
        assert contrast(mc.to_rgb(c), (1, 1, 1)) >= 3.0, c


def test_text_is_black_enough_for_4_5_to_1():
    fig, ax = plotting.axes3d("A frame")
    try:
        colours = [ax.title.get_color(), ax.xaxis.label.get_color()]
        assert all(contrast(mc.to_rgb(c), (1, 1, 1)) >= 4.5 for c in colours), colours
    finally:
        plt.close(fig)


def _png_pixels(fig):
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=plotting.DPI)
    return np.asarray(Image.open(buf).convert("RGB"), dtype=float) / 255.0


@pytest.mark.parametrize("kind", sorted(MACHADO))
def test_rendered_frame_axes_stay_apart_on_the_png(kind):
    """The rendered PNG of a frame: the pixels of each axis, simulated, stay apart."""
    fig, ax = plotting.axes3d("A frame")
    plotting.draw_frame(ax, label="A")
    try:
        px = _png_pixels(fig).reshape(-1, 3)
    finally:
        plt.close(fig)
    groups = []
    for c in plotting.FRAME_COLORS:
        near = px[np.linalg.norm(px - mc.to_rgb(c), axis=1) < 0.08]
        assert len(near) > 30, f"axis colour {c} not found on the PNG"
        groups.append(simulate(near, kind).mean(axis=0))
    for (i, a), (j, b) in itertools.combinations(enumerate(groups), 2):
        assert delta_e(a, b) >= MIN_DELTA_E, f"axes {i} and {j} merge under {kind}"


def test_frame_axes_are_told_apart_by_their_names_too():
    fig, ax = plotting.axes3d("A frame")
    try:
        plotting.draw_frame(ax, label="A")
        names = {t.get_text() for t in ax.texts}
    finally:
        plt.close(fig)
    assert len([n for n in names if n]) >= 3, names  # x, y, z labels, not colour alone


def test_curves_of_the_double_cover_differ_in_line_style_and_label():
    fig = double_cover()
    try:
        ax = fig.axes[0]
        lines = [ln for ln in ax.get_lines() if not ln.get_label().startswith("_")]
        styles = {ln.get_linestyle() for ln in lines}
        labels = {ln.get_label() for ln in lines}
    finally:
        plt.close(fig)
    assert len(lines) >= 2 and len(styles) == len(lines) and len(labels) == len(lines)


# --- the chapters' own colours (course_lib/plotting/colours.py, instructor/build/figure_audit.py)
# ----------


def _audit():
    from instructor.build import figure_audit

    return figure_audit


def test_named_tab_colours_are_the_courses_readable_shades():
    """Regression: tab:orange lines were 2.5:1; tab:purple merged with the z axis for
    protanopes (ΔE 4); importing course_lib.plotting puts both on readable shades."""
    from course_lib.plotting.colours import NAMED

    audit = _audit()
    for name, shade in NAMED.items():
        assert mc.to_hex(name) == mc.to_hex(shade)
        assert contrast(mc.to_rgb(name), (1, 1, 1)) >= 4.5, name
    for frame in plotting.FRAME_COLORS:
        for kind in audit.MACHADO:
            d = audit.delta_e(
                audit.simulate(mc.to_rgb("tab:purple"), kind),
                audit.simulate(mc.to_rgb(frame), kind),
            )
            assert d >= audit.MERGED, f"tab:purple and {frame} are {d:.1f} apart for {kind}"


@pytest.mark.parametrize("colour", [*plotting.FRAME_COLORS, "tab:green", "tab:purple", "0.6"])
def test_labels_are_drawn_at_4_5_to_1_in_their_lines_hue(colour):
    text = plotting.readable(colour)
    assert contrast(mc.to_rgb(text), (1, 1, 1)) >= 4.5
    fig, ax = plotting.axes3d("labels")
    plotting.draw_vector(ax, [1.0, 0.0, 0.0], label="$v$", color=colour)
    assert [t.get_color() for t in ax.texts] == [text]
    plt.close(fig)


def test_default_series_differ_by_line_style_not_colour_alone():
    import matplotlib as mpl

    styles = [c["linestyle"] for c in mpl.rcParams["axes.prop_cycle"]]
    assert len(set(map(str, styles))) == len(styles) >= 5
    fig, ax = plt.subplots()
    lines = [ax.plot([0, 1], [k, k])[0] for k in range(3)]
    assert _audit().figure_problems(fig) == []
    assert len({line.get_linestyle() for line in lines}) == 3
    plt.close(fig)


def test_the_audit_finds_a_line_below_3_to_1_and_a_pair_told_apart_by_colour_alone():
    from matplotlib.figure import Figure

    fig = Figure()
    ax = fig.add_subplot()
    ax.plot([0, 1], [0, 1], "-", color="#ff7f0e", label="old orange")
    ax.plot([0, 1], [1, 0], "-", color="#d62728", label="red")
    ax.plot([0, 1], [0.5, 0.5], "-", color="#2ca02c", label="green")
    problems = _audit().figure_problems(fig)
    assert any("'old orange' #ff7f0e is 2.53:1" in p for p in problems)
    assert any("'red' and line 'green'" in p and "deuteranopia" in p for p in problems)
