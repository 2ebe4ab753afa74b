"""Checks of what a student sees beyond the outputs of a run: the animation player's first
frame (also on opening, before any cell runs), the explorers' stored still pictures on
opening, the folded "Going deeper" headings, and that no
request of the page leaves the loopback server.

``check_players(page, state, problems, when)``, ``check_stills(page, state, problems)``,
``check_folds(page, problems)`` and
``outside_requests(urls)`` are called by :mod:`notebook_checks`.
"""

import time
import urllib.parse

from common import POLL, js

# What the page may ask for without leaving the machine.
LOCAL_HOSTS = {"127.0.0.1", "localhost", "::1", "[::1]"}
NETWORK_SCHEMES = {"http", "https", "ws", "wss", "ftp"}
# The call that makes the animation player (matplotlib's JavaScript player, "jshtml").
PLAYER_CALL = "spin_animation("
PLAYER_SECONDS = 15
# The explorers' cells: on opening, before any cell runs, their stored still picture shows.
EXPLORER_CALL = "_explorer("


def outside_requests(urls):
    """The URLs among ``urls`` that leave the loopback server (in order, each once)."""
    out = []
    for url in urls:
        parts = urllib.parse.urlsplit(url)
        if parts.scheme in NETWORK_SCHEMES and parts.hostname not in LOCAL_HOSTS:
            if url not in out:
                out.append(url)
    return out


def check_players(page, state, problems, when):
    """Every animation player of the notebook shows its first frame without a click.

    The players are the outputs holding matplotlib's player (``<img id="_anim_img...">``) and
    the outputs of every cell that calls ``spin_animation(``. Each is scrolled into view and
    given ``PLAYER_SECONDS`` to show a loaded image of non-zero size. Returns how many players
    were looked at.
    """
    n = 0
    dom = page.evaluate(js("dom"), None)["cells"]
    for i, cell in enumerate(state["cells"]):
        if cell["type"] != "code" or not cell["outputs"]:
            continue
        calls = PLAYER_CALL in cell["source"]
        if not calls and not (i < len(dom) and any(o["player"] for o in dom[i]["outputs"])):
            continue
        n += 1
        page.evaluate(js("scroll_to_cell"), i)
        deadline = time.monotonic() + PLAYER_SECONDS
        while True:
            found = player_problems(i, page.evaluate(js("dom"), [i])["cells"][0])
            if not found or time.monotonic() > deadline:
                break
            time.sleep(POLL)
        problems.extend(f"{p} ({when})" for p in found)
    return n


def check_stills(page, state, problems):
    """On opening, every explorer cell shows its stored still picture (a loaded image), as a
    fresh copy of the course opens: untrusted. (The stored form that a *trusted* notebook would
    hide, a widget view without its model, is refused by tests/test_notebook_hygiene.py.)
    Returns how many stills were looked at.
    """
    n = 0
    for i, cell in enumerate(state["cells"]):
        if cell["type"] != "code" or EXPLORER_CALL not in cell["source"]:
            continue
        n += 1
        page.evaluate(js("scroll_to_cell"), i)
        deadline = time.monotonic() + PLAYER_SECONDS
        while True:
            shown = page.evaluate(js("dom"), [i])["cells"][0]["outputs"]
            if any(o["loaded"] for o in shown) or time.monotonic() > deadline:
                break
            time.sleep(POLL)
        if not any(o["loaded"] for o in shown):
            problems.append(f"cell {i}: the explorer's still picture is not shown on opening")
    return n


def player_problems(i, shown):
    """The problems of the players in cell i as displayed (``shown``, from js/dom.js)."""
    players = [(j, o["player"]) for j, o in enumerate(shown["outputs"]) if o["player"]]
    if not players:
        return [f"cell {i}: calls {PLAYER_CALL[:-1]} but no animation player is on the page"]
    found = (player_problem(f"cell {i} output {j}", p) for j, p in players)
    return [p for p in found if p]


def player_problem(where, player):
    """The player must show a frame without a click: its <img> loaded, with a size on the page."""
    width, height = player["size"]
    if player["loaded"] and width > 0 and height > 0:
        return None
    src = f"src {player['src']!r}..." if player["src"] else "no src"
    return (
        f"{where}: the animation shows no frame without a click: its <img> is "
        f"{width}x{height} px, {'loaded' if player['loaded'] else 'no image loaded'}, {src}"
    )


def fold_problems(fold, when, excused=()):
    """What is wrong with one fold as reported by js/folds.js, ``when`` collapsed or not;
    ``excused``: cells that stay hidden, being under a fold inside this one still closed."""
    i, out = fold["i"], []
    if fold["level"] == 0:
        return [f"cell {i}: folded in its metadata but not a heading (nothing to click)"]
    hidden = [u["i"] for u in fold["under"] if u["hidden"] and u["i"] not in excused]
    if not fold["under"]:
        return [
            f"cell {i}: folded heading hides nothing: no cell under it before the next heading "
            "(text in the heading's own cell stays shown; put it in cells of its own)"
        ]
    if when == "collapsed":
        if not fold["collapsed"]:
            out.append(f"cell {i}: heading folded in its metadata but shown expanded on opening")
        shown = [u["i"] for u in fold["under"] if not u["hidden"]]
        if shown:
            out.append(f"cell {i}: folded heading, yet the cells {shown} under it are shown")
        if not fold["button"]:
            out.append(f"cell {i}: folded heading without the button that expands it")
    elif fold["collapsed"] or hidden:
        out.append(f"cell {i}: clicked to expand, yet the cells {hidden} under it stay hidden")
    if fold["nextHidden"]:
        out.append(f"cell {i}: the fold hides cell {fold['next']}, the next heading after it")
    return out


def check_folds(page, problems):
    """Folded headings (``"jp-MarkdownHeadingCollapsed": true``) open collapsed, the cells
    under them hidden; a click on the heading's button shows them. Folds are expanded from the
    first to the last (a fold inside another is clicked once the outer one is open). Returns
    the number of folds.
    """
    folds = page.evaluate(js("folds"), None)
    for fold in folds:
        problems.extend(fold_problems(fold, "collapsed"))
    for fold in folds:
        if not fold["button"] or not fold["collapsed"]:
            continue
        page.evaluate(js("scroll_to_cell"), fold["i"])
        page.locator(f'[data-e2e-fold="{fold["i"]}"]').click()
        page.wait_for_timeout(300)
        now = page.evaluate(js("folds"), [f["i"] for f in folds])
        after = next(f for f in now if f["i"] == fold["i"])
        inside = {u["i"] for u in after["under"]}
        excused = {u["i"] for f in now if f["i"] in inside and f["collapsed"] for u in f["under"]}
        problems.extend(fold_problems(after, "expanded", excused))
        under = [u["i"] for u in after["under"]]
        if under and not page.evaluate(js("scroll_to_cell"), under[0]):
            problems.append(f"cell {fold['i']}: expanded, yet cell {under[0]} is not on the page")
    return len(folds)
