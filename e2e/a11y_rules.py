"""What the accessibility run judges besides axe-core: a page's structure and alt text.

Pure functions (no browser), so the default tests exercise them quickly
(tests/test_a11y_rules.py); :mod:`a11y` applies them to every page it opens.
"""

import re

#: axe-core's tags for the WCAG 2.0 and 2.1 level A and AA rules (WCAG 2.1 AA = all four).
WCAG_TAGS = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa"]
#: Link texts that say nothing of where the link goes (WCAG 2.4.4).
VAGUE_LINKS = {"here", "click here", "link", "this", "more", "read more", "this link", "this page"}
_GENERIC_ALT = re.compile(
    r"^\s*(figure|fig\.?|image|img|plot|picture|graph|chart)?\s*\d*\s*$", re.I
)
#: LaTeX left in alt text, or what is left of it once ``$`` and backslashes are stripped
#: ("cosfractheta2", "45^circ", "sqrt2").
_RAW_LATEX = re.compile(
    r"\\[A-Za-z]+|[_^]\{|\^circ|\bcirc\b|\bsqrt|\w*(?:frac(?!tion)|operatorname|mathbb)\w*"
)
_CODE_ALT = re.compile(
    r"(\b\w+\.\w+\(|^\s*(import\s|from\s+\w+\s+import|plt\.|fig\s*,|ax\s*=)|^\s*\w+\s*=\s*\w+[.(])"
)


def alt_text_problem(alt):
    """Why ``alt`` does not describe a figure, or None when it may.

    An image needs alt text that says what it shows (WCAG 1.1.1): not empty, not a generic
    word or number ("Figure", "figure 3", "image"), not the code that drew it, no raw LaTeX
    ("\\theta", "cosfrac"), whole sentences.

    Examples
    --------
    >>> alt_text_problem("Figure 3")
    "generic alt text 'Figure 3': say what the figure shows"
    >>> alt_text_problem("plotting.draw_frame(ax, R)")
    "alt text 'plotting.draw_frame(ax, R)' is code: say what the figure shows"
    >>> alt_text_problem("Frame B is frame A turned 90 degrees about z.") is None
    True
    """
    if not isinstance(alt, str):
        raise TypeError(f"alt must be a str, got {type(alt).__name__}")
    text = alt.strip()
    if not text:
        return "no alt text"
    if _GENERIC_ALT.match(text):
        return f"generic alt text {text!r}: say what the figure shows"
    if _CODE_ALT.search(text):
        return f"alt text {text!r} is code: say what the figure shows"
    if len(text.split()) < 3:
        return f"alt text {text!r} is too short to say what the figure shows"
    if _RAW_LATEX.search(text):
        return f"alt text {text!r} holds raw LaTeX: a screen reader spells it out letter by letter"
    if not text.endswith((".", "!", "?", ")")):
        return f"alt text {text!r} stops mid-sentence: end it with a whole sentence"
    return None


def structure_problems(info):
    """The problems of a page's structure, read by js/page_structure.js.

    ``info``: ``{"lang", "h1", "headings": [{"level", "text"}], "links": [{"text", "href"}]}``.
    The page language is set (WCAG 3.1.1), there is one h1 and no heading skips a level going
    down (1.3.1, 2.4.6), and every link has text that says where it goes (2.4.4).

    Examples
    --------
    >>> structure_problems({"lang": "en", "h1": 1, "links": [],
    ...     "headings": [{"level": 1, "text": "A"}, {"level": 3, "text": "B"}]})
    ["heading 'B' is h3 right after an h1 (a level skipped)"]
    """
    out = []
    if not (info.get("lang") or "").strip():
        out.append("the page has no language (<html lang>)")
    if info["h1"] != 1:
        out.append(f"{info['h1']} h1 headings on the page (one expected)")
    previous = None
    for h in info["headings"]:
        if previous is not None and h["level"] > previous + 1:
            out.append(
                f"heading {h['text']!r} is h{h['level']} right after an h{previous} "
                "(a level skipped)"
            )
        previous = h["level"]
    for link in info["links"]:
        text = " ".join(link["text"].split()).lower()
        if not text:
            out.append(f"a link with no text (to {link['href']})")
        elif text in VAGUE_LINKS:
            out.append(f"link text {link['text']!r} says nothing of where it goes")
    return out
