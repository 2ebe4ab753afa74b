"""plotting.show / figure_output: a figure shown with its alt text, stable from run to run."""

import base64
import io

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import pytest
from PIL import Image

from course_lib import plotting
from course_lib.plotting.display import figure_alt_and_png

ALT = 'Figure: the frame A and a point "p" in it.'


def _figure():
    fig, ax = plotting.axes3d("A")
    plotting.draw_frame(ax, label="A")
    return fig


def test_the_output_is_one_img_with_the_alt_text_and_a_palette_png():
    fig = _figure()
    data = plotting.figure_output(fig, ALT)
    plt.close(fig)
    assert set(data) == {"text/html", "text/plain"}  # no second copy as image/png
    alt, png = figure_alt_and_png(data["text/html"])
    assert alt == ALT == data["text/plain"]
    assert "&quot;p&quot;" in data["text/html"]  # escaped inside the attribute
    image = Image.open(io.BytesIO(base64.b64decode(png)))
    assert image.mode == "P" and image.size == tuple((fig.dpi * fig.get_size_inches()).astype(int))


def test_regression_the_html_is_the_same_on_every_run():
    """Strict nbval compares text/html: the PNG inside it must not change from run to run."""
    first, second = _figure(), _figure()
    assert plotting.figure_output(first, ALT) == plotting.figure_output(second, ALT)
    plt.close("all")


def test_show_closes_the_figure_so_the_inline_backend_does_not_show_it_again():
    _figure()
    plotting.show(ALT)
    assert plt.get_fignums() == []


@pytest.mark.parametrize("alt, error", [(None, TypeError), ("", ValueError), ("  ", ValueError)])
def test_missing_alt_text_is_refused(alt, error):
    fig = _figure()
    with pytest.raises(error, match="alt"):
        plotting.show(alt, fig=fig)
    plt.close(fig)


def test_no_figure_to_show_is_a_clear_error():
    plt.close("all")
    with pytest.raises(ValueError, match="no open figure"):
        plotting.show(ALT)


def test_not_a_figure_is_refused():
    with pytest.raises(TypeError, match="fig must be a matplotlib Figure"):
        plotting.figure_output("fig", ALT)


def test_other_html_is_not_taken_for_a_figure():
    assert figure_alt_and_png('<img alt="x" src="data:image/png;base64,AAAA">') is None
    assert (
        figure_alt_and_png('<img class="course-figure" alt="x" src="https://e.org/a.png">') is None
    )
