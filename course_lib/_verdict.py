r"""The one verdict shape shared by every check in the package.

Every checker in ``course_lib`` (exercise checks, the rigid-body test of Definition 1, the group
axioms, the SO(3) membership test) answers with a :class:`Verdict`: whether the property holds,
and one sentence saying what was found. ``bool(verdict)`` is ``verdict.ok``; in a notebook it shows
as one bold-marked line beginning with ✓ or ✗; ``str`` gives the same line as plain text. Subclasses
add their own fields (a counterexample, the failed axiom, ...), may extend
:meth:`Verdict._details_markdown` with a table of them and :meth:`Verdict._headline_markdown`
with a word after the mark (``**✗ not rigid.**``). The message never carries the mark itself.

Examples
--------
>>> v = Verdict(False, "entry (1, 2) has the wrong sign.")
>>> bool(v)
False
>>> print(v)
✗ entry (1, 2) has the wrong sign.
>>> Verdict(True, "correct.")._repr_markdown_()
'**✓** correct.'
"""

from dataclasses import dataclass

__all__ = ["Verdict"]


@dataclass(frozen=True)
class Verdict:
    """Whether a property holds, and a sentence saying what was found.

    Parameters
    ----------
    ok : bool
        True when the property holds. ``bool(verdict)`` is ``verdict.ok``.
    message : str
        One sentence with the numbers that decided it; never a hidden expected answer.
    """

    ok: bool
    message: str

    def __bool__(self):
        return bool(self.ok)

    @property
    def mark(self):
        """``'✓'`` when the property holds, ``'✗'`` otherwise."""
        return "✓" if self.ok else "✗"

    def __str__(self):
        return f"{self.mark} {self.message}"

    def _headline_markdown(self):
        """The verdict line in markdown: the bold mark, then the message."""
        return f"**{self.mark}** {self.message}"

    def _details_markdown(self):
        """Extra markdown shown under the verdict line (none by default)."""
        return ""

    # What separates the verdict line from the details (a blank line: a new paragraph).
    _details_separator = "\n\n"

    def _repr_markdown_(self):
        details = self._details_markdown()
        line = self._headline_markdown()
        return f"{line}{self._details_separator}{details}" if details else line
