"""The course's public address, read from one place, and every link made from it.

The repository URL lives only in ``[project.urls]`` of ``pyproject.toml`` (key ``Repository``).
From it come the setup cell of every notebook (``instructor/build/notebooks.py``), the launch links
of the README (the block between the ``launch-links`` markers, rewritten by this script) and the
launch buttons of the course website (``site/conf.py``). While it is unset, all of them say so
instead of pointing nowhere.

Students open the *student edition*: the branch ``student`` of the same repository, which holds
the copies ``make student`` builds (README, "Releasing the student edition").

Command line::

    python -m instructor.build.course_links            # print the README block
    python -m instructor.build.course_links --readme   # rewrite the block in README.md
"""

from __future__ import annotations

import re
import sys
from pathlib import Path
from urllib.parse import quote

ROOT = Path(__file__).resolve().parents[2]
STUDENT_BRANCH = "student"
BEGIN = (
    "<!-- launch-links:begin (written by instructor/build/course_links.py from pyproject.toml) -->"
)
END = "<!-- launch-links:end -->"
UNSET = (
    "not published yet: set `Repository` in `[project.urls]` of `pyproject.toml`, "
    "then run `make notebooks`"
)
_GITHUB = re.compile(r"^https://github\.com/(?P<owner>[^/]+)/(?P<repo>[^/]+?)(?:\.git)?/?$")


def _project_urls(text):
    """The ``[project.urls]`` table of a pyproject.toml text (tomllib, or a line parser on 3.10)."""
    try:
        import tomllib
    except ImportError:  # Python 3.10: the table is flat ``key = "value"`` lines
        table = re.search(r"^\[project\.urls\]\s*$(.*?)(?=^\[|\Z)", text, re.M | re.S)
        pairs = re.findall(
            r'^\s*"?([\w .-]+?)"?\s*=\s*"([^"]*)"', table.group(1) if table else "", re.M
        )
        return dict(pairs)
    return tomllib.loads(text).get("project", {}).get("urls", {})


def repository_url(pyproject=ROOT / "pyproject.toml"):
    """The course repository URL from ``[project.urls] Repository``, or None while it is unset."""
    url = _project_urls(Path(pyproject).read_text(encoding="utf-8")).get("Repository")
    if url is not None and not re.match(r"^https://\S+$", url):
        raise ValueError(f"[project.urls] Repository must be an https:// URL, got {url!r}")
    return url or None


def binder_url(url, branch=STUDENT_BRANCH):
    """mybinder.org link that opens JupyterLab in ``notebooks/`` of ``branch``."""
    m = _GITHUB.match(url)
    spec = f"gh/{m['owner']}/{m['repo']}" if m else f"git/{quote(url, safe='')}"
    return f"https://mybinder.org/v2/{spec}/{branch}?urlpath=lab/tree/notebooks"


def colab_url(url, notebook, branch=STUDENT_BRANCH):
    """Colab link of one notebook (Colab opens GitHub repositories only: None elsewhere)."""
    m = _GITHUB.match(url)
    if not m:
        return None
    return (
        f"https://colab.research.google.com/github/{m['owner']}/{m['repo']}/blob/{branch}"
        f"/notebooks/{notebook}"
    )


def nbgitpuller_url(url, hub="https://HUB.example.edu", branch=STUDENT_BRANCH):
    """nbgitpuller link: the hub clones (later: merges) ``branch`` and opens its notebooks."""
    folder = url.rstrip("/").removesuffix(".git").rsplit("/", 1)[-1]
    return (
        f"{hub}/hub/user-redirect/git-pull?repo={quote(url, safe='')}&branch={branch}"
        f"&urlpath={quote(f'lab/tree/{folder}/notebooks', safe='')}"
    )


def readme_block(url, notebooks):
    """The README's launch links, between the markers."""
    if url is None:
        lines = [f"**Binder, Colab and hub links:** {UNSET}."]
    else:
        lines = [
            f"[![Binder](https://mybinder.org/badge_logo.svg)]({binder_url(url)}) "
            f"(student edition, branch `{STUDENT_BRANCH}`)",
            "",
        ]
        for nb in notebooks:
            colab = colab_url(url, nb)
            lines.append(
                f"- `{nb}`: "
                + (
                    f"[open in Colab]({colab})"
                    if colab
                    else "Colab opens notebooks from GitHub only"
                )
            )
        lines += ["", f"Hub link (replace the hub address): `{nbgitpuller_url(url)}`"]
    return "\n".join([BEGIN, *lines, END])


def write_readme(readme=ROOT / "README.md"):
    """Rewrite the launch-links block of README.md; return True if the file changed."""
    text = readme.read_text(encoding="utf-8")
    pattern = re.compile(re.escape(BEGIN) + r".*?" + re.escape(END), re.S)
    if not pattern.search(text):
        raise ValueError(f"{readme.name} has no launch-links block ({BEGIN} ... {END})")
    notebooks = sorted(p.name for p in (ROOT / "notebooks").glob("[0-9]*.ipynb"))
    new = pattern.sub(lambda _: readme_block(repository_url(), notebooks), text)
    if new != text:
        readme.write_text(new, encoding="utf-8")
    return new != text


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if argv == ["--readme"]:
        print("README.md: launch links " + ("updated" if write_readme() else "unchanged"))
    elif not argv:
        notebooks = sorted(p.name for p in (ROOT / "notebooks").glob("[0-9]*.ipynb"))
        print(readme_block(repository_url(), notebooks))
    else:
        print("usage: python -m instructor.build.course_links [--readme]", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
