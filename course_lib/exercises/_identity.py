r"""Who the student is: one key per student, whatever the platform calls them (issue 33).

The course's **key** of a student is their institutional e-mail address (or login, where the
instructor says so), *normalised*: NFKC unicode, case folded, white space collapsed and
stripped, so that ``"Alice@Berkeley.edu "`` and ``"alice@berkeley.edu"`` are one key. When
the course sets an e-mail domain (:data:`SETTINGS_FILE`, ``"email_domain"``; the instructor's
``python -m instructor.grading.identity --domain berkeley.edu``), a bare login becomes
``login@domain``: the JupyterHub user ``alice`` and the e-mail ``alice@berkeley.edu`` are
then one student. The exercises' numbers are drawn from the key.

In a student's kernel the id comes, in this order, from the grader (``COURSE_GRADER_ID``, set
only in the grading kernel: the submission cannot change it), :func:`set_student_id`, the
environment variable ``COURSE_STUDENT_ID``, or ``JUPYTERHUB_USER``. The grader maps the id of
a submission (nbgrader's student, Gradescope's e-mail or ``sid``) to the key through the
instructor's roster, which never ships (``grader/identity.py``).

:data:`EXAMPLE_ID` is not a student: it stands for the course's example numbers (variant 0 of
every exercise); the instructor's solved copies and the tests run as it.

Examples
--------
>>> normalise_id("  Ada   Lovelace ")
'ada lovelace'
>>> course_key("Alice@Berkeley.EDU ", domain=None)
'alice@berkeley.edu'
>>> course_key("alice", domain="berkeley.edu")
'alice@berkeley.edu'
>>> course_key("Ada Lovelace", domain="berkeley.edu")  # not a login: kept as it is
'ada lovelace'
"""

from __future__ import annotations

import json
import os
import re
import unicodedata
from functools import lru_cache
from importlib import resources

__all__ = [
    "ENV_ID",
    "GRADER_ID",
    "HUB_ID",
    "EXAMPLE_ID",
    "SETTINGS_FILE",
    "course_key",
    "email_domain",
    "how_to_set_id",
    "identity_line",
    "normalise_id",
    "set_student_id",
    "student_id",
]

#: The environment variable a student (Colab, Binder) or a hub's spawner sets to the id.
ENV_ID = "COURSE_STUDENT_ID"
#: The variable JupyterHub sets in every single-user server.
HUB_ID = "JUPYTERHUB_USER"
#: Set by the grader in the grading kernel only: the key of the graded submission.
GRADER_ID = "COURSE_GRADER_ID"
#: The course's example numbers (variant 0 of every exercise): the instructor's copies, tests.
EXAMPLE_ID = "(example)"
#: The course's identity settings, package data of :mod:`course_lib.exercises`.
SETTINGS_FILE = "course_id.json"
_LOGIN = re.compile(r"[\w.+-]+")
_DOMAIN = re.compile(r"[a-z0-9-]+(\.[a-z0-9-]+)+")
_state = {"id": None}
_SOURCES = {
    GRADER_ID: "the grader",
    "set_student_id": "set_student_id",
    ENV_ID: ENV_ID,
    HUB_ID: "your JupyterHub user",
}


def normalise_id(raw):
    """The id as it is compared: NFKC unicode, case folded, inner white space one blank,
    stripped. Any string is accepted (empty, unicode, 1,000 characters); ``None`` is ``""``.

    Raises
    ------
    TypeError
        If ``raw`` is not a string or None.

    Examples
    --------
    >>> normalise_id("Ｚｏë\tX")
    'zoë x'
    """
    if raw is None:
        return ""
    if not isinstance(raw, str):
        raise TypeError(f"student id must be a string, got {type(raw).__name__}")
    text = unicodedata.normalize("NFKC", raw).casefold()
    return " ".join(text.split())


@lru_cache(maxsize=1)
def email_domain():
    """The course's e-mail domain (``"berkeley.edu"``), or None: :data:`SETTINGS_FILE`'s
    ``"email_domain"``.

    Raises
    ------
    ValueError
        If the setting is not a domain name such as ``berkeley.edu``.
    """
    path = resources.files("course_lib.exercises").joinpath(SETTINGS_FILE)
    data = json.loads(path.read_text(encoding="utf-8")) if path.is_file() else {}
    return check_domain(data.get("email_domain"))


def check_domain(value):
    """``value`` normalised when it is a domain name (or None); ValueError otherwise."""
    if value in (None, ""):
        return None
    text = normalise_id(value) if isinstance(value, str) else ""
    if not _DOMAIN.fullmatch(text):
        raise ValueError(f"email_domain must be a domain name such as berkeley.edu, got {value!r}")
    return text


def course_key(raw, domain=False):
    """The course's key of the id ``raw``: normalised, and a bare login (letters, digits and
    ``._+-``, no ``@``) followed by ``@domain`` when the course has an e-mail domain.

    ``domain``: the domain to use; False (default) for the course's :func:`email_domain`.
    """
    sid = normalise_id(raw)
    domain = email_domain() if domain is False else check_domain(domain)
    if domain and sid != EXAMPLE_ID and _LOGIN.fullmatch(sid):
        return f"{sid}@{domain}"
    return sid


def set_student_id(raw):
    """Set the student id of this kernel (your e-mail address); ``None`` or ``""`` unsets it.

    Examples
    --------
    >>> set_student_id("Ada@Example.org "); student_id()[0]
    'ada@example.org'
    >>> set_student_id(None)
    """
    _state["id"] = course_key(raw) or None


def student_id():
    """``(key, where it came from)`` of this kernel; ``("", "none")`` when no id is set."""
    grader = course_key(os.environ.get(GRADER_ID, ""))
    if grader:
        return grader, GRADER_ID
    if _state["id"]:
        return _state["id"], "set_student_id"
    for var in (ENV_ID, HUB_ID):
        value = course_key(os.environ.get(var, ""))
        if value:
            return value, var
    return "", "none"


def how_to_set_id():
    """How to set the student id, one line per platform (markdown).

    Examples
    --------
    >>> print(how_to_set_id().splitlines()[1])
    - laptop, Binder or Colab: `set_student_id("your e-mail")` in that cell;
    """
    return (
        "Set your student id (your institutional e-mail) in the cell at the top of the "
        "problem set, then run the cells again:\n"
        '- laptop, Binder or Colab: `set_student_id("your e-mail")` in that cell;\n'
        "- the course's JupyterHub: nothing to do, your hub user is used;\n"
        "- Gradescope or nbgrader: the grader uses the id of your submission."
    )


def identity_line():
    """Whose numbers the exercises show (once, at the top of a problem set), or how to set
    the id.

    Examples
    --------
    >>> set_student_id("ada@example.org"); print(identity_line())  # doctest: +ELLIPSIS
    Student id: **ada@example.org** (from set_student_id). The exercises show the numbers...
    >>> set_student_id(None)
    """
    sid, source = student_id()
    if sid == EXAMPLE_ID:
        return (
            "Student id: none, these are the course's example numbers (the instructor's copy "
            "and the tests run as the example student)."
        )
    if sid:
        return (
            f"Student id: **{sid}** (from {_SOURCES[source]}). The exercises show the numbers "
            "of this id; grading uses the id of your submission, so it must be yours."
        )
    return "**No student id is set**: the exercises show example numbers, not yours.\n\n" + (
        how_to_set_id()
    )
