r"""What an exercise is: its statement, level, points and the kind of answer it asks for.

The exercise bank (:mod:`course_lib.exercise_bank`) is data built from these classes; the engine
(:mod:`course_lib.exercises._engine`) checks answers against them. Nothing here holds an expected
answer: the engine compares with *fingerprints* (salted, key-stretched digests of rounded values)
that a repository tool generates from the instructor's reference solutions.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace

from .._verdict import Verdict

__all__ = [
    "CheckResult",
    "Choice",
    "Exercise",
    "Expr",
    "LEVELS",
    "Value",
    "Variants",
    "fill_placeholders",
    "format_parameter",
]

#: Levels in rising difficulty and the points an exercise of that level is worth.
LEVELS = {"warm-up": 1, "core": 2, "challenge": 3}


#: A placeholder of a variant's parameter in a statement, tip or hint: ``<<name>>``.
PLACEHOLDER = re.compile(r"<<([A-Za-z_][A-Za-z0-9_]*)>>")


def format_parameter(value):
    r"""A variant's parameter as the statement shows it (LaTeX, inside ``$...$``).

    An int as itself, a float with ``:g``, a string as it is (exact values are written as
    LaTeX strings), a list of numbers as a tuple, a list of lists as a matrix by rows.

    Raises
    ------
    TypeError
        If ``value`` is not an int, float, str or a (nested) list of them.

    Examples
    --------
    >>> format_parameter([1, -1, 0])
    '(1,\\ -1,\\ 0)'
    >>> format_parameter([[1, 0], [0, 1]])
    '\\begin{pmatrix} 1 & 0 \\\\ 0 & 1 \\end{pmatrix}'
    >>> format_parameter(0.5), format_parameter(3), format_parameter(r"\sqrt{13}")
    ('0.5', '3', '\\sqrt{13}')
    """
    if isinstance(value, bool) or not isinstance(value, (int, float, str, list)):
        raise TypeError(
            f"value must be an int, float, str or a list of them, got {type(value).__name__}"
        )
    if isinstance(value, str):
        return value
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return f"{value:g}"
    if value and all(isinstance(row, list) for row in value):
        rows = " \\\\ ".join(" & ".join(format_parameter(v) for v in row) for row in value)
        return f"\\begin{{pmatrix}} {rows} \\end{{pmatrix}}"
    return "(" + ",\\ ".join(format_parameter(v) for v in value) + ")"


@dataclass(frozen=True)
class Variants:
    """The variants of a numeric exercise: its variant ``key`` (exercises that share numbers
    share a key) and ``default``, the parameters of variant 0 (the numbers everyone had before
    variants; a student with no id, or a course with variants off, gets these).

    Examples
    --------
    >>> Variants("ch04_frames", {"v_c": [1, 2, 3]}).default["v_c"]
    [1, 2, 3]
    """

    key: str
    default: dict


def fill_placeholders(text, values):
    """``text`` with every ``<<name>>`` replaced by ``values[name]`` (a string).

    Raises
    ------
    ValueError
        If a placeholder of ``text`` has no value; the message names it.

    Examples
    --------
    >>> fill_placeholders("a turn by <<angle>> about <<axis>>", {"angle": "60°", "axis": "z"})
    'a turn by 60° about z'
    """
    missing = sorted(set(PLACEHOLDER.findall(text)) - set(values))
    if missing:
        raise ValueError(f"values has no entry for the placeholders {missing} of the text")
    return PLACEHOLDER.sub(lambda m: str(values[m.group(1)]), text)


@dataclass(frozen=True, repr=False)
class CheckResult(Verdict):
    """The verdict on one answer: ``ok``, the message (exercise name first) and a ``status``.

    ``status`` is one of ``"correct"``, ``"wrong"``, ``"form"`` (right value, asked form not
    met), ``"malformed"``, ``"not allowed"``, ``"too complex"``, ``"no answer"`` and ``"no id"``
    (an exercise with numbers of its own per student, and no student id set). The instructor's
    grader answers with this type too, adding ``"forged"`` (a record that no check wrote) and
    ``"unknown"`` (no such exercise).

    Examples
    --------
    >>> r = CheckResult(False, "hat_cubed: your answer is the negative of the right one.", "wrong")
    >>> print(r)
    ✗ hat_cubed: your answer is the negative of the right one.
    >>> bool(r), r.status
    (False, 'wrong')
    """

    status: str = "wrong"

    def __repr__(self):
        return str(self)  # plain-text front ends show the verdict line


@dataclass(frozen=True)
class Value:
    """A numeric answer: a number, a 3-vector or a 3x3 matrix, fixed by the statement.

    Parameters
    ----------
    shape : tuple of int
        ``()``, ``(n,)`` or ``(n, m)``.
    rotation : bool
        The answer is a rotation matrix: a wrong one is also tested for ``det = -1`` and for
        columns that are not orthonormal.
    angle : bool
        The answer is an angle in radians: a wrong one is also tested for degrees and for the
        other sign.
    unit : bool
        The answer is a unit vector (or unit quaternion): a wrong one whose length is not 1 is
        told so, with its length.
    ranges : tuple of (str, float, float)
        One ``(name, low, high)`` per entry, for entries the statement keeps in a range (angles
        in radians): a wrong answer with an entry outside its range is told which entry and
        which range.

    Examples
    --------
    >>> Value(shape=(3,), angle=True, ranges=(("β", -3.14, 0.0),) * 3).unit
    False
    """

    shape: tuple = ()
    rotation: bool = False
    angle: bool = False
    unit: bool = False
    ranges: tuple = ()


@dataclass(frozen=True)
class Expr:
    r"""A symbolic answer: a sympy expression or matrix in the exercise's symbols.

    Parameters
    ----------
    shape : tuple of int
        ``()``, ``(n,)`` or ``(n, m)``.
    domain : tuple of sympy.Symbol
        The symbols the answer is a function of (its values are compared over their whole
        range, at seeded points).
    allowed : tuple, optional
        The symbols (scalar or matrix) the asked *form* may use; default ``domain``. An answer
        in other symbols of ``domain`` has the right value in the wrong form.
    unit_omega : bool
        ω is a unit vector here (points on the unit sphere, exact comparison modulo
        :math:`\lVert\omega\rVert = 1`).
    matrix_degree : int or None
        When set, the answer must be a matrix *expression* in the matrix symbols of
        ``allowed`` (``W``, ``u``, ``A`` ...) of at most this degree; explicit entries are the
        wrong form.
    no_roots : bool
        The asked form has no square root of an expression in the symbols (simplify first).
    """

    shape: tuple = ()
    domain: tuple = ()
    allowed: tuple = None
    unit_omega: bool = False
    matrix_degree: int = None
    no_roots: bool = False


@dataclass(frozen=True)
class Choice:
    """A set of letters, e.g. the maps or matrices of a list that have some property."""

    letters: str = "abcdef"


@dataclass(frozen=True)
class Exercise:
    r"""One exercise of a chapter.

    Parameters
    ----------
    name : str
        Unique identifier; the notebook assigns the answer to ``answer_<name>``.
    chapter, number : int
        Chapter (1-4) and position in it; ``label`` is ``"<chapter>.<number>"``.
    level : {"warm-up", "core", "challenge"}
        Difficulty; fixes the points (:data:`LEVELS`).
    title, statement : str
        Heading and markdown statement (LaTeX between ``$...$``).
    answer : Value, Expr or Choice
        What kind of answer is asked for.
    tip : str
        A pointer to the notes, added to the message of a wrong answer.
    mistakes : dict
        Known mistakes: id -> hint; each is recognised by a transformation of the student's
        answer that its fingerprint names (or, failing one, by digests of its values).
    properties : tuple
        ``(residual, message)`` pairs for symbolic answers: ``residual(M)`` (M the answer as an
        explicit matrix) must vanish; the first that does not gives ``message`` as hint.
    variants : Variants or None
        For a numeric exercise drawn per student: its variant key and default parameters; the
        ``<<name>>`` placeholders of its texts name parameters.
    """

    name: str
    chapter: int
    number: int
    level: str
    title: str
    statement: str
    answer: object
    tip: str = ""
    mistakes: dict = field(default_factory=dict)
    properties: tuple = ()
    variants: Variants | None = None

    def __post_init__(self):
        if self.level not in LEVELS:
            raise ValueError(
                f"level of {self.name} must be one of {list(LEVELS)}, got {self.level!r}"
            )

    @property
    def label(self):
        """``"<chapter>.<number>"``, e.g. ``"3.3"``."""
        return f"{self.chapter}.{self.number}"

    @property
    def points(self):
        """Points of the exercise: 1 warm-up, 2 core, 3 challenge."""
        return LEVELS[self.level]

    @property
    def answer_variable(self):
        """Name of the notebook variable holding the answer: ``answer_<name>``."""
        return f"answer_{self.name}"

    def heading(self):
        """``Exercise 3.3 (core, 2 points): title``."""
        pts = "point" if self.points == 1 else "points"
        return f"Exercise {self.label} ({self.level}, {self.points} {pts}): {self.title}"

    def markdown(self):
        """The statement with its heading, as the markdown of the notebook cell."""
        return (
            f"### {self.heading()}\n\n{self.statement.strip()}\n\n"
            f"Assign your answer to `{self.answer_variable}`; the cell after it checks "
            "the answer and shows ✓, or an error with a hint."
        )

    def placeholders(self):
        """The names of the ``<<name>>`` placeholders of the statement, tip and hints."""
        texts = [self.statement, self.tip, *self.mistakes.values()]
        return sorted({n for text in texts for n in PLACEHOLDER.findall(text)})

    def filled(self, values):
        """This exercise with the placeholders of its statement, tip and hints filled in from
        ``values`` (name -> text: a variant's numbers as they are shown).

        Raises
        ------
        ValueError
            If a placeholder has no value, or ``values`` names one the texts do not have.
        """
        extra = sorted(set(values) - set(self.placeholders()))
        if extra:
            raise ValueError(f"{self.name}: values names placeholders the texts lack: {extra}")
        return replace(
            self,
            statement=fill_placeholders(self.statement, values),
            tip=fill_placeholders(self.tip, values),
            mistakes={k: fill_placeholders(v, values) for k, v in self.mistakes.items()},
        )

    def _repr_markdown_(self):
        return self.markdown()

    def __str__(self):
        return f"Exercise {self.label} ({self.name}): {self.title}"
