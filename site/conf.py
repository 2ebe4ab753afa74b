"""Sphinx configuration of the course website (`make site`; instructor/build/website.py prepares
the pages).

Everything the pages load is served from the site itself: MathJax 3 comes from the npm package
that instructor/build/website.py installs into build/site-deps/, the theme is Sphinx's own
(alabaster). The instructor's edition (COURSE_SITE_EDITION=instructor) has a banner on every page.
"""

import os

project = "Rigid-body rotations"
author = "the rotations-course authors"
copyright = "2026, the rotations-course authors (text CC BY 4.0, code MIT)"

extensions = ["myst_nb"]
exclude_patterns = ["_build", "**.ipynb_checkpoints"]
html_theme = "alabaster"
html_title = project
html_theme_options = {"nosidebar": False, "show_powered_by": False}
html_static_path = [
    os.environ["COURSE_SITE_STATIC"]
]  # mathjax/, course.css (instructor/build/website.py)
mathjax_path = "mathjax/tex-chtml.js"  # relative to _static/
# WCAG 2.4.3: a formula is not a tab stop (MathJax 3 puts every one in the tab order for its
# expression explorer: 252-610 stops a chapter); screen readers still read its assistive MathML,
# and a formula that scrolls sideways gets its own tab stop from course.js.
mathjax3_config = {"options": {"menuOptions": {"settings": {"inTabOrder": False}}}}
html_css_files = ["course.css"]  # no page wider than the window; contrast (WCAG 1.4.3)
html_js_files = ["course.js"]  # a tab stop on every box that scrolls sideways (WCAG 2.1.1)
# Pygments' own default style meets WCAG AA contrast (4.5:1) on a light background; the
# theme's (alabaster) has string colours of 3.2:1.
pygments_style = "default"
templates_path = ["_templates"]  # site/templates: the instructor banner
html_context = {"course_instructor_edition": os.environ.get("COURSE_SITE_EDITION") == "instructor"}
html_show_sourcelink = False
html_copy_source = False  # no _sources/ copies of the notebooks: the pages are the site

# The notebooks are executed by instructor/build/website.py (instructor/build/notebooks.py, which
# does not stall on widget cells); myst-nb only renders them.
nb_execution_mode = "off"
nb_render_markdown_format = "myst"  # Markdown(...) outputs (tables) are parsed, math included
myst_enable_extensions = ["dollarmath", "amsmath"]
suppress_warnings = ["mystnb.unknown_mime_type"]


FOLDED = ("Going deeper", "Errata")  # the headings the chapters fold in JupyterLab


def _fold_going_deeper(app, pagename, templatename, context, doctree):
    """Fold every "Going deeper" part of a page, as JupyterLab folds it in the notebook.

    A notebook folds a part with a heading cell marked ``"jp-MarkdownHeadingCollapsed": true``,
    hiding everything up to the next heading of the same or a higher level. Sphinx puts exactly
    that span in one ``<section>``, whose id comes from the heading ("going-deeper-..."): the
    heading becomes the ``<summary>`` of a closed ``<details class="going-deeper">`` holding the
    rest of the section (found by its heading's text: a title used twice gets an id "idN").
    """
    body = context.get("body") or ""
    if not any(word in body for word in FOLDED):
        return
    from bs4 import BeautifulSoup  # installed with nbconvert

    soup = BeautifulSoup(body, "html.parser")
    for section in soup.find_all("section"):  # by its heading: a repeated title gets id="idN"
        heading = section.find(["h2", "h3", "h4", "h5", "h6"], recursive=False)
        if heading is None or not heading.get_text().startswith(FOLDED):
            continue
        details = soup.new_tag("details", attrs={"class": "going-deeper"})
        summary = soup.new_tag("summary")
        heading.wrap(summary)
        summary.wrap(details)
        for sibling in list(details.next_siblings):
            details.append(sibling.extract())
    context["body"] = str(soup)


def setup(app):
    app.connect("html-page-context", _fold_going_deeper)
