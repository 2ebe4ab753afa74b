"""``nbgrader collect`` with the course's intake (:mod:`instructor.grading.intake`), named in the
course's ``nbgrader_config.py`` as ``c.ExchangeFactory.collect``.

nbgrader's own collect copies a student's exchange folder with ``shutil.copytree``, which
follows symbolic links: a student's ``inbound/`` folder holding ``ps01.ipynb ->
/home/instructor/course/source/ps01/ps01.ipynb`` (or ``/etc/shadow``) had the collecting
instructor copy *that* file into ``submitted/`` as the student's work. :class:`SafeCollect`
copies only regular files of one name inside the student's folder, each at most
:data:`instructor.grading.intake.MAX_BYTES` (checked before reading); a refused notebook is written
as a placeholder notebook that carries the note (graded 0 with it); any other refused file is left
out, with a warning in collect's log. A student folder that is itself a symbolic link, or a
user name that is not one plain path component, is not collected (a warning).

Nor is a submission that claims another student or a time to come (:func:`claim_problem`):
nbgrader names the student and the time from the folder's name
(``inbound/<user>+<assignment>+<time>``), which any student with write access to ``inbound/``
chooses: a folder ``alice+ps01+2099-...`` made by mallory was collected as alice's work, and
beat every later submission of alice's. A folder whose owner is not the local account of the
user it names, or whose time is later than the collect, is left out with a warning. Where
students have no local accounts (a JupyterHub whose servers all run as one uid), the owner
cannot tell them apart: the shared exchange is then as trustworthy as that hub's permissions
(docs/grading.md).
"""

from __future__ import annotations

import datetime
import glob
import itertools
import json
import os
import pwd
import re
import stat

from nbgrader.exchange.default.collect import ExchangeCollect

from .intake import MAX_ENTRIES, Refused, read_inside, refused_notebook, shown

__all__ = ["SafeCollect", "claim_problem", "copy_submission"]

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


#: How far a submission's time may be ahead of the collect's clock (clocks differ a little).
CLOCK_SLACK = datetime.timedelta(minutes=5)


def claim_problem(path, username, timestamp, now=None):
    """Why the exchange folder ``path`` cannot be taken as ``username``'s work at
    ``timestamp`` (a tz-aware time), or None: its owner is not that user's local account, or
    the time is later than ``now`` (plus :data:`CLOCK_SLACK`). A user with no local account
    cannot be checked by owner (None)."""
    now = now or datetime.datetime.now(datetime.timezone.utc)
    if timestamp is not None and timestamp.tzinfo is not None and timestamp > now + CLOCK_SLACK:
        return f"its time {timestamp.isoformat()} is later than now"
    try:
        uid = pwd.getpwnam(username).pw_uid
    except KeyError:
        return None
    owner = os.lstat(path).st_uid
    if owner != uid:
        return f"it was made by uid {owner}, not by {username!r} (uid {uid})"
    return None


class SafeCollect(ExchangeCollect):
    """nbgrader's collect; only submissions whose folder is the student's own and not from
    the future (:func:`claim_problem`), each copied through the course's intake."""

    def init_src(self):
        super().init_src()  # nbgrader's checks, the inbound folder and the due date
        student = self.coursedir.student_id or "*"
        pattern = os.path.join(self.inbound_path, f"{student}+{self.coursedir.assignment_id}+*")
        groups = {}
        for path in glob.glob(pattern):
            rec = self._path_to_record(path)
            name = str(rec["username"])
            if not _NAME.match(name) or name in (".", ".."):
                self.log.warning("collect: refused the user name %r (not one folder name)", name)
                continue
            problem = claim_problem(path, name, rec["timestamp"])
            if problem:
                self.log.warning("collect: %s not collected: %s", shown(path, 200), problem)
                continue
            groups.setdefault(name, []).append(rec)
        self.src_records = [self._newest(records) for records in groups.values()]

    def _newest(self, records):
        """nbgrader's choice among one student's submissions: the newest, or with a due date
        (``--before-duedate``) the newest before it."""
        records = self._sort_by_timestamp(records)
        if self.duedate is not None and self.before_duedate:
            before = [r for r in records if r["timestamp"] <= self.duedate]
            return (before or records)[0]
        return records[0]

    def do_copy(self, src, dest, log=None):
        mode = os.lstat(src).st_mode
        if not stat.S_ISDIR(mode):
            self.log.warning(
                "collect: %s is not a folder (a symbolic link?): not collected", shown(src, 200)
            )
            return
        copy_submission(src, dest, self.log)
