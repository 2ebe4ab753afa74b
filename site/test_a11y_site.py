"""Accessibility of the built site in headless Chromium (``make a11y`` runs it; browser marker).

Math is read as math by a screen reader (MathJax's assistive MathML: Rodrigues' formula is a
``math`` node of the accessibility tree, not raw LaTeX); every page has its language, one h1,
headings in order and meaningful link text; the animation player works from the keyboard alone
with a visible focus. The axe-core rules run in ``e2e/a11y.py``.
"""

import re
from pathlib import Path

import pytest
import test_site
from a11y_rules import structure_problems

HERE = Path(__file__).resolve().parent

# the site's fixtures: one server, one browser, each page loaded once
server, browser, visit = test_site.server, test_site.browser, test_site.visit
PAGES = test_site.PAGES

pytestmark = pytest.mark.browser
STRUCTURE_JS = (HERE.parent / "e2e" / "js" / "page_structure.js").read_text()


def test_rodrigues_formula_is_math_in_the_accessibility_tree(visit):
    page, _ = visit("03_exponential_coordinates")
    tree = page.locator("div.body").aria_snapshot()
    maths = [line.split("math:", 1)[1] for line in tree.splitlines() if "- math:" in line]
    assert len(maths) >= 20, "MathJax's assistive MathML is missing: no math in the tree"
    rodrigues = [m for m in maths if "sin" in m and "cos" in m and "θ" in m and "ω" in m]
    assert rodrigues, "Rodrigues' formula is not in the accessibility tree as math"
    latex = [m for m in maths if re.search(r"\\[a-zA-Z]+", m)]
    assert latex == [], f"raw LaTeX read out as math: {latex[:2]}"


@pytest.mark.parametrize("name", PAGES)
def test_language_headings_and_link_text(visit, name):
    page, _ = visit(name)
    info = page.evaluate(STRUCTURE_JS, "div.body")
    assert structure_problems(info) == [], name


#: Is the focus on the summary of a closed fold that holds the animation player?
_CLOSED_FOLD_WITH_PLAYER = (
    "(() => { const e = document.activeElement; return e.tagName === 'SUMMARY' "
    "&& !e.parentElement.open && e.parentElement.querySelector('.anim-slider') !== null; })()"
)


def test_animation_player_works_from_the_keyboard_with_visible_focus(visit):
    """Tab to the frame slider, the arrow keys change the frame; Tab to Play, then Pause.

    The animation sits in a folded "Going deeper" part (issue 37: chapter 3's main path in an
    hour): a keyboard user opens the fold with Enter on its summary, then tabs on.
    """
    page, _ = visit("03_exponential_coordinates")
    slider = page.locator("input.anim-slider").first
    assert slider.get_attribute("aria-label")
    img = page.locator("div.animation img").first
    assert img.get_attribute("alt")
    page.locator("body").focus()
    for _ in range(400):  # Tab, and Enter on the fold that holds the player: no mouse
        page.keyboard.press("Tab")
        if page.evaluate("document.activeElement.classList.contains('anim-slider')"):
            break
        if page.evaluate(_CLOSED_FOLD_WITH_PLAYER):
            page.keyboard.press("Enter")
    else:
        pytest.fail("the animation's slider cannot be reached with Tab")
    outline = page.evaluate("getComputedStyle(document.activeElement).outlineStyle")
    assert outline != "none", "no visible focus on the slider"
    before = img.get_attribute("src")
    page.keyboard.press("ArrowRight")
    page.wait_for_timeout(200)
    assert slider.input_value() == "1" and img.get_attribute("src") != before
    names = []
    for _ in range(6):
        page.keyboard.press("Tab")
        names.append(page.evaluate("document.activeElement.getAttribute('aria-label')"))
    assert "Pause" in names and "Play" in names, names


def test_animation_repetition_mode_is_a_radio_group_the_keyboard_enters_operates_and_leaves(visit):
    """Tab reaches the checked radio of Once / Loop / Reflect, ArrowRight checks the next one,
    Tab leaves the group and Shift+Tab comes back (WCAG 2.1.1, 2.1.2, 4.1.2)."""
    page, _ = visit("03_exponential_coordinates")
    group = page.locator('div.animation [role="radiogroup"]').first
    assert group.get_attribute("aria-label") == "Repetition mode"
    in_group = "!!document.activeElement.closest('[role=radiogroup]')"
    page.locator("input.anim-slider").first.focus()
    for _ in range(20):
        page.keyboard.press("Tab")
        if page.evaluate(in_group):
            break
    else:
        pytest.fail("Tab does not reach the repetition mode")
    before = page.evaluate("document.activeElement.value")
    page.keyboard.press("ArrowRight")
    after = page.evaluate("[document.activeElement.value, document.activeElement.checked]")
    assert after[0] != before and after[1] is True
    outline = page.evaluate("getComputedStyle(document.activeElement).outlineStyle")
    assert outline != "none", "no visible focus on the radio"
    page.keyboard.press("Tab")
    assert not page.evaluate(in_group), "Tab does not leave the radio group"
    page.keyboard.press("Shift+Tab")
    assert page.evaluate(in_group), "Shift+Tab does not come back to the radio group"
