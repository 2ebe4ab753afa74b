"""A pytest plugin: nbval's kernel started twice if it dies as it starts, its stderr kept.

nbval starts each notebook's kernel once, with the kernel's stderr sent to ``/dev/null`` (a
file it leaves open: a ResourceWarning that fails whichever test runs when it is collected).
A kernel that dies while it starts (two pytest workers, or a JupyterLab beside the tests, can
be handed the same free port by the system: the kernel cannot bind it and exits) failed every
cell of its notebook with "Kernel died before replying to kernel_info" and no reason. Here the
kernel's stderr goes to a temporary file, a kernel that died is started a second time, and a
second death fails with what the kernel printed. Loaded by the root ``conftest.py``
(``pytest_plugins``) of the repository and of the student edition.
"""

import os
import sys
import tempfile

try:
    import nbval.kernel as _nbval_kernel
except ImportError:  # no nbval: no notebook is run
    _nbval_kernel = None


def _start_kernel(startup_timeout=60, kernel_name="python", stderr=None, **kwargs):
    """nbval's ``start_new_kernel``, tried twice, the kernel's stderr kept for the error."""
    if stderr is not None:
        stderr.close()  # nbval's open(os.devnull): left open, a ResourceWarning in a later test
    for attempt in (1, 2):
        fd, path = tempfile.mkstemp(prefix="nbval-kernel-", suffix=".log")
        try:
            return _nbval_start_new_kernel(startup_timeout, kernel_name, stderr=fd, **kwargs)
        except RuntimeError as err:
            with open(path, errors="replace") as log:
                said = log.read()[-3000:].strip() or "(nothing)"
            if attempt == 2:
                raise RuntimeError(f"{err}, twice; the kernel's stderr:\n{said}") from err
            print(
                f"\nthe kernel died as it started; started again. It said: {said}", file=sys.stderr
            )
        finally:
            os.close(fd)  # the kernel holds its own copy
            os.unlink(path)


_start_kernel.retries = True

# Once per process: pytest's doctest collection imports this file a second time by its path.
if _nbval_kernel is not None and not hasattr(_nbval_kernel.start_new_kernel, "retries"):
    _nbval_start_new_kernel = _nbval_kernel.start_new_kernel
    _nbval_kernel.start_new_kernel = _start_kernel
