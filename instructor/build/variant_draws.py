r"""How each variant key draws its parameters, and what makes a draw unfit (issue 27).

A *variant key* names the numbers one or more exercises share (``ch04_frames``: the two frames
of exercises 4.1 and 4.2). Each chapter's ``instructor/answers/chNN.py`` defines ``DRAWS``: each key
mapped to a pair, a function of a numpy Generator that returns one set of parameters (plain
lists and numbers, as the statement shows them, JSON-ready), and a function that lists why a
set is unfit: a degenerate case that would make the exercise
trivial, or a known mistake that would give the right answer (so its hint could never show).
:data:`DRAWS` collects them; :func:`problems` and :func:`draw` use it.
A draw is redrawn until it has no problem; ``instructor/build/variant_tables.py`` writes the vetted
table and tests/test_variant_draws.py checks 1,000 seeds per key.
"""

from __future__ import annotations

import numpy as np

from instructor import answers

__all__ = ["DRAWS", "problems", "draw"]

#: Redraws before a key is declared broken (a draw that fails this often is a bug).
MAX_TRIES = 200


#: Variant key -> (draw function of a Generator, problems function of the parameters).
DRAWS = answers.draws()


def problems(key, params):
    """Why the parameters ``params`` of variant key ``key`` are unfit ([] when fit)."""
    return DRAWS[key][1](params)


def draw(key, seed):
    """A fit set of parameters of ``key`` drawn from ``seed`` (an int or a sequence of ints).

    Raises
    ------
    RuntimeError
        If :data:`MAX_TRIES` draws in a row are unfit (the draw function is broken).
    """
    rng = np.random.default_rng(seed)
    make, check = DRAWS[key]
    for _ in range(MAX_TRIES):
        params = make(rng)
        if not check(params):
            return params
    raise RuntimeError(f"{key}: {MAX_TRIES} draws in a row were unfit: {check(params)}")
