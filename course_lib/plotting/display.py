r"""A figure shown in Jupyter with its alt text (WCAG 1.1.1), in place of ``plt.show()``.

JupyterLab's image renderer writes an ``<img>`` with no ``alt`` for an ``image/png`` output: a
screen reader then says "image" and nothing else. :func:`show` displays the figure as an HTML
``<img>`` that carries the alt text and the picture inline (a ``data:`` URI, which JupyterLab's
sanitizer keeps, trusted or not), plus the alt text as the ``text/plain`` of the output: one copy
of the picture, no ``image/png`` beside it. The PNG is palette-coded (as ``make notebooks``
stores every figure) and its bytes depend only on the figure, so a re-run gives the same HTML
and strict nbval can compare it. The website (``instructor/build/website.py``) turns such an output
back into an ``image/png`` with the same alt text.
"""

import base64
import html
import io
import re

__all__ = ["show", "figure_output", "FIGURE_CLASS", "figure_alt_and_png"]

#: The class of the ``<img>`` of a figure shown by :func:`show` (how the site and tests find it).
FIGURE_CLASS = "course-figure"
_COLOURS = 128  # the palette of every stored PNG (instructor/build/notebooks.py: PNG_COLOURS)
_IMG = re.compile(
    rf'^<img class="{FIGURE_CLASS}" alt="([^"]*)" '
    r'src="data:image/png;base64,([A-Za-z0-9+/=]+)">$'
)


def _palette_png(fig):
    """The whole canvas of ``fig`` (``bbox_inches=None``) as a 128-colour palette PNG."""
    from PIL import Image

    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=fig.dpi, bbox_inches=None, facecolor="white")
    image = Image.open(buf)
    rgb = Image.new("RGB", image.size, "white")
    rgb.paste(image, mask=image.getchannel("A") if image.mode == "RGBA" else None)
    out = io.BytesIO()
    rgb.quantize(_COLOURS).save(out, format="png", optimize=True)
    return out.getvalue()


def _check_alt(alt):
    if not isinstance(alt, str):
        raise TypeError(f"alt must be a str saying what the figure shows, got {type(alt).__name__}")
    if not alt.strip():
        raise ValueError("alt is empty: say what the figure shows and what to see in it")
    return " ".join(alt.split())


def figure_output(fig, alt):
    """The MIME bundle that shows ``fig`` with the alt text ``alt``.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    alt : str
        What the figure shows and what to see in it.

    Returns
    -------
    dict
        ``{"text/html": '<img class="course-figure" alt="..." src="data:image/png;...">',
        "text/plain": alt}``.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> fig = Figure(figsize=(1, 1), dpi=20)
    >>> data = figure_output(fig, "An empty square canvas.")
    >>> data["text/plain"], data["text/html"][:44]
    ('An empty square canvas.', '<img class="course-figure" alt="An empty squ')
    """
    from matplotlib.figure import Figure

    if not isinstance(fig, Figure):
        raise TypeError(f"fig must be a matplotlib Figure, got {type(fig).__name__}")
    alt = _check_alt(alt)
    png = base64.b64encode(_palette_png(fig)).decode("ascii")
    img = f'<img class="{FIGURE_CLASS}" alt="{html.escape(alt, quote=True)}" '
    return {"text/html": f'{img}src="data:image/png;base64,{png}">', "text/plain": alt}


def figure_alt_and_png(html_text):
    """(alt text, PNG base64) of an output made by :func:`show`, or None for any other HTML.

    Examples
    --------
    >>> out = '<img class="course-figure" alt="A &amp; B" src="data:image/png;base64,iVBO">'
    >>> figure_alt_and_png(out)
    ('A & B', 'iVBO')
    >>> figure_alt_and_png("<p>text</p>") is None
    True
    """
    m = _IMG.match(html_text.strip())
    return (html.unescape(m.group(1)), m.group(2)) if m else None


def show(alt, fig=None):
    """Show the figure with its alt text and close it (instead of ``plt.show()``).

    Parameters
    ----------
    alt : str
        What the figure shows and what to see in it (the chapters use the caption under the
        figure as plain text, ``instructor/build/alt_text.py``: the website's alt text for it).
    fig : matplotlib.figure.Figure, optional
        Default: pyplot's current figure (there must be one).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = plt.figure(figsize=(1, 1), dpi=20)
    >>> show("An empty square canvas.")  # doctest: +ELLIPSIS
    {'text/html': '<img class="course-figure" alt="An empty square canvas." src=...}
    >>> plt.fignum_exists(fig.number)  # closed: the inline backend does not show it again
    False
    """
    import matplotlib.pyplot as plt
    from IPython.display import display

    if fig is None:
        if not plt.get_fignums():
            raise ValueError("show: no open figure to show; draw one first (or pass fig=)")
        fig = plt.gcf()
    data = figure_output(fig, alt)
    plt.close(fig)  # pyplot's inline backend would show it again, without alt text
    display(data, raw=True)
