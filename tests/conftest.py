"""Shared pytest set-up.

Hypothesis explores new examples on every run on a developer's machine; on CI (CI=true) it runs
derandomized, so a red CI is always reproducible from the same commit.
"""

import os

import matplotlib
import pytest
from hypothesis import settings

matplotlib.use("Agg")

import matplotlib.pyplot as plt
from mpl_toolkits.mplot3d import proj3d

settings.register_profile("ci", derandomize=True, deadline=None)
settings.register_profile("dev", deadline=None)
settings.load_profile("ci" if os.environ.get("CI") else "dev")


@pytest.fixture(autouse=True)
def _close_figures():
    """Every test closes the figures it opened (too many open figures is a warning: an error)."""
    before = set(plt.get_fignums())
    yield
    for num in set(plt.get_fignums()) - before:
        plt.close(num)


def _screen_box(text, ax, renderer):
    x0, y0 = text.get_position()
    xs, ys, _ = proj3d.proj_transform(*text.get_position_3d(), ax.get_proj())
    text.set_position((xs, ys))
    try:
        return text.get_window_extent(renderer)
    finally:
        text.set_position((x0, y0))


@pytest.fixture
def screen_box():
    """Display box of a 3D label where it is drawn (Text3D projects its position only while it
    draws itself, so its 2D position is moved there for the measurement and put back)."""
    return _screen_box


@pytest.fixture(scope="module")
def ax3():
    """One 3D axes shared by the property tests of a module (a figure per example is slow)."""
    from course_lib.plotting import axes3d

    fig, ax = axes3d("shared 3D axes")
    yield ax


@pytest.fixture(scope="module")
def ax2():
    """One 2D axes shared by the property tests."""
    from course_lib.plotting import axes2d

    fig, ax = axes2d("shared 2D axes")
    yield ax
