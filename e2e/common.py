"""What every part of the browser test shares: the log, polling, the page scripts, the errors."""

import functools
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
JS_DIR = HERE / "js"
POLL = 0.5


class CheckFailed(Exception):
    """A check failed; the message says which and why."""


class KernelStalled(CheckFailed):
    """The notebook's kernel never became idle, or never ran the queued cells.

    Seen intermittently on shared machines (cells stay queued as [*] with the kernel shown idle,
    or the kernel never reports idle when the notebook opens). A student would reload the page;
    the runner retries the notebook once on a new server with a new browser profile, and says
    so in its log.
    """


def log(msg):
    print(f"[e2e] {msg}", flush=True)


@functools.cache
def js(name):
    """The text of the page script ``js/<name>.js`` (a function, for ``page.evaluate``)."""
    return (JS_DIR / f"{name}.js").read_text()


def poll(fn, timeout, what):
    """Call ``fn`` until it returns something truthy; CheckFailed after ``timeout`` seconds."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        last = fn()
        if last:
            return last
        time.sleep(POLL)
    raise CheckFailed(f"timed out after {timeout:.0f} s waiting for {what}")
