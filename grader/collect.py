"""``nbgrader collect`` with the course's intake (:mod:`grader.intake`), named in the course's
``nbgrader_config.py`` as ``c.ExchangeFactory.collect``.

nbgrader's own collect copies a student's exchange folder with ``shutil.copytree``, which
follows symbolic links: a student's ``inbound/`` folder holding ``ps01.ipynb ->
/home/instructor/course/source/ps01/ps01.ipynb`` (or ``/etc/shadow``) had the collecting
instructor copy *that* file into ``submitted/`` as the student's work. :class:`SafeCollect`
copies only regular files of one name inside the student's folder, each at most
:data:`grader.intake.MAX_BYTES` (checked before reading); a refused notebook is written as a
placeholder notebook that carries the note (graded 0 with it); any other refused file is left
out, with a warning in collect's log. A student folder that is itself a symbolic link, or a
user name that is not one plain path component, is not collected (a warning).
"""

from __future__ import annotations

import itertools
import json
import os
import re
import stat

from nbgrader.exchange.default.collect import ExchangeCollect

from .intake import MAX_ENTRIES, Refused, read_inside, refused_notebook, shown

__all__ = ["SafeCollect", "copy_submission"]

MAX_DEPTH = 8
_NAME = re.compile(r"^[^/\\\0]+$")


def copy_submission(src, dest, log, depth=0, top=None):
    """Copy the student folder ``src`` to ``dest`` through the intake (see the module)."""
    top = top or src
    os.makedirs(dest, exist_ok=True)
    with os.scandir(src) as it:
        entries = list(itertools.islice(it, MAX_ENTRIES))
    for entry in entries:
        target = os.path.join(dest, entry.name)
        if entry.is_dir(follow_symlinks=False) and depth < MAX_DEPTH:
            copy_submission(entry.path, target, log, depth + 1, top)
            continue
        try:
            data = read_inside(entry.path, top)
        except Refused as err:
            log.warning("collect: %s: refused: %s", shown(entry.path, 200), err)
            if entry.name.lower().endswith(".ipynb"):
                with open(target, "w", encoding="utf-8") as f:
                    json.dump(refused_notebook(f"0 points: {err}"), f)
            continue
        with open(target, "xb") as f:
            f.write(data)


class SafeCollect(ExchangeCollect):
    """nbgrader's collect; the copy goes through the course's intake."""

    def init_src(self):
        super().init_src()
        kept = []
        for rec in self.src_records:
            name = str(rec["username"])
            if not _NAME.match(name) or name in (".", ".."):
                self.log.warning("collect: refused the user name %r (not one folder name)", name)
                continue
            kept.append(rec)
        self.src_records = kept

    def do_copy(self, src, dest, log=None):
        mode = os.lstat(src).st_mode
        if not stat.S_ISDIR(mode):
            self.log.warning(
                "collect: %s is not a folder (a symbolic link?): not collected", shown(src, 200)
            )
            return
        copy_submission(src, dest, self.log)
