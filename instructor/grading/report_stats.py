r"""The numbers of the class report (issue 34): per exercise, per variant, per problem set.

- **Share right**: a submission is right on an exercise when it has the exercise's full points.
- **Known mistakes**: the grader's match (:mod:`instructor.grading.diagnose`), counted with the
  bank's hint (the default variant's wording).
- **Unexplained wrong answers**: wrong, no known mistake; grouped by the grader's group key
  (equal values or expressions together), largest group first.
- **Harder variants**: for each variant of an exercise, Fisher's exact test, one-sided, of
  "right" in that variant against all other variants of the exercise (a 2 × 2 table); a variant
  is flagged when :math:`p < 0.05 / m`, :math:`m` the number of variants that students had
  (Bonferroni). The p-value is exact (:func:`fisher_less`, integers via ``math.comb``).
- **Discrimination**: the upper-lower index :math:`D = p_U - p_L`, the share right among the
  27 % of submissions with the highest points on the *other* exercises minus that among the
  27 % with the lowest (ties broken by student id); :math:`D \ge 0.3` separates well,
  :math:`D < 0.2` poorly (Ebel's guide). Needs at least :data:`MIN_DISCRIMINATION`
  submissions.
- **Teach again**: the three known mistakes made most often in the set.
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass, field
from fractions import Fraction

__all__ = [
    "ExerciseStats",
    "SetStats",
    "fisher_less",
    "discrimination",
    "set_stats",
    "ALPHA",
    "SMALL",
]

ALPHA = 0.05
UPPER_LOWER = 0.27
MIN_DISCRIMINATION = 10
SMALL = 5  # the shared copy shows counts from 1 to SMALL - 1 as "<5"
OTHER = "other-numbers"  # instructor.grading.diagnose.OTHER: right for another variant's numbers


def fisher_less(a, b, c, d):
    """One-sided Fisher exact p-value that the first row has so few successes or fewer.

    The table is ``[[a, b], [c, d]]`` (row 1: ``a`` right, ``b`` not; row 2: ``c``, ``d``);
    the p-value is :math:`P(X \\le a)`, X hypergeometric with the table's margins.

    Examples
    --------
    >>> round(fisher_less(0, 6, 24, 0), 9)  # 6 of 6 wrong, 24 of 24 right
    1.684e-06
    >>> fisher_less(3, 0, 3, 0)
    1.0
    """
    for v in (a, b, c, d):
        if type(v) is not int or v < 0:
            raise ValueError(f"the table holds non-negative integers, got {(a, b, c, d)}")
    n, right, total = a + b, a + c, a + b + c + d
    if total == 0:
        return 1.0
    low = max(0, n - (total - right))
    num = sum(math.comb(right, x) * math.comb(total - right, n - x) for x in range(low, a + 1))
    return float(Fraction(num, math.comb(total, n)))


def discrimination(pairs):
    """Upper-lower index ``D`` of ``pairs`` = [(rest score, right?, student id)], or None when
    there are fewer than :data:`MIN_DISCRIMINATION`.

    Examples
    --------
    >>> discrimination([(i, i >= 5, str(i)) for i in range(10)])
    1.0
    """
    if len(pairs) < MIN_DISCRIMINATION:
        return None
    ranked = sorted(pairs, key=lambda p: (p[0], p[2]))
    k = max(1, round(UPPER_LOWER * len(ranked)))
    low, high = ranked[:k], ranked[-k:]
    return sum(p[1] for p in high) / k - sum(p[1] for p in low) / k


@dataclass
class Variant:
    index: int
    students: int
    right: int
    p: float
    harder: bool


@dataclass
class ExerciseStats:
    name: str
    points: float
    students: int
    right: int
    distribution: dict  # points -> count, every level from 0 to the maximum
    mistakes: list = field(default_factory=list)  # (key, count, hint)
    unexplained: list = field(default_factory=list)  # (text, count, [students])
    form: int = 0  # right value, not in the asked form
    no_answer: int = 0  # no answer, unreadable or a grading note's 0
    other_numbers: list = field(default_factory=list)  # students graded on other numbers
    checked_known: int = 0
    never_checked: int = 0
    variants: list = field(default_factory=list)  # Variant
    discrimination: float | None = None
    known: bool = True

    @property
    def share(self):
        return self.right / self.students if self.students else None


@dataclass
class SetStats:
    name: str
    students: int
    exercises: list  # ExerciseStats in problem-set order
    totals: dict  # total points -> count
    teach_again: list  # (exercise, key, count, hint)
    max_score: float

    def by_discrimination(self):
        """Exercises from the best separating to the worst (no index: last)."""
        return sorted(
            self.exercises,
            key=lambda e: (e.discrimination is None, -(e.discrimination or 0.0)),
        )


def _hints(name):
    try:
        from course_lib.exercises import variant

        return variant(name, student="")[0].mistakes
    except KeyError:
        return {}


def _variants(name, subs):
    per = {}
    for sub in subs:
        ans = sub.answers.get(name)
        if ans is not None and ans.variant is not None:
            n, r = per.get(ans.variant, (0, 0))
            per[ans.variant] = (n + 1, r + ans.right)
    total_n = sum(n for n, _ in per.values())
    total_r = sum(r for _, r in per.values())
    m = len(per)
    out = []
    for k in sorted(per):
        n, r = per[k]
        p = fisher_less(r, n - r, total_r - r, (total_n - n) - (total_r - r))
        out.append(Variant(k, n, r, p, m > 1 and p < ALPHA / m))
    return out


def _group(answers):
    groups = {}
    for sid, ans in answers:
        if ans.verdict == "wrong" and not ans.mistake and ans.group != OTHER:
            key = ans.group or ans.text or "?"
            text, who = groups.get(key, (ans.text or "(not recorded)", []))
            groups[key] = (text, [*who, sid])
    ranked = sorted(groups.values(), key=lambda g: (-len(g[1]), g[0]))
    return [(text, len(who), sorted(who)) for text, who in ranked]


def _who(sub):
    """How the instructor's copy names a student: name and id, or the id."""
    return f"{sub.name} ({sub.student})" if sub.name else sub.student


def exercise_stats(ps, name, known=True):
    """The :class:`ExerciseStats` of exercise ``name`` of the problem set ``ps``."""
    answers = [(_who(s), s.answers[name]) for s in ps.submissions if name in s.answers]
    most = ps.points.get(name, 0.0)
    dist = Counter(a.score for _, a in answers)
    levels = range(int(most) + 1) if float(most).is_integer() else []
    distribution = {float(v): dist.get(float(v), 0) for v in levels}
    distribution.update({float(v): c for v, c in dist.items()})
    hints = _hints(name) if known else {}
    mistakes = Counter(a.mistake for _, a in answers if a.mistake)
    st = ExerciseStats(name, most, len(answers), sum(a.right for _, a in answers), distribution)
    st.known = known
    st.mistakes = [(k, c, hints.get(k, "")) for k, c in mistakes.most_common()]
    st.unexplained = _group(answers)
    st.form = sum(a.verdict == "form" for _, a in answers)
    st.no_answer = sum(
        a.verdict in ("no answer", "malformed", "forged", "zero", "unknown") for _, a in answers
    )
    st.other_numbers = sorted(
        sid
        for sid, a in answers
        if a.shown is not None and a.variant is not None and a.shown != a.variant
    )
    st.checked_known = sum(a.checked is not None for _, a in answers)
    st.never_checked = sum(a.checked is False for _, a in answers)
    st.variants = _variants(name, ps.submissions)
    pairs = [
        (s.score - s.answers[name].score, s.answers[name].right, s.student)
        for s in ps.submissions
        if name in s.answers
    ]
    st.discrimination = None if len(ps.exercises) < 2 else discrimination(pairs)
    return st


def set_stats(ps, known=None):
    """The :class:`SetStats` of a :class:`instructor.grading.report_data.ProblemSet`;
    ``known(name)`` says whether an exercise is of this course version (default: every one is)."""
    known = known or (lambda name: True)
    exercises = [exercise_stats(ps, n, known(n)) for n in ps.exercises]
    totals = Counter(round(s.score, 6) for s in ps.submissions)
    teach = [(e.name, k, c, hint) for e in exercises for k, c, hint in e.mistakes]
    order = {e.name: i for i, e in enumerate(exercises)}
    teach.sort(key=lambda t: (-t[2], order[t[0]], t[1]))
    return SetStats(
        ps.name,
        len(ps.submissions),
        exercises,
        dict(sorted(totals.items())),
        teach[:3],
        ps.max_score,
    )
