"""What the tests of real nbgrader runs share.

The tests that check the confinement itself carry the ``confined`` marker (conftest.py): they
are skipped where bubblewrap is missing. The others grade notebooks the tests wrote
themselves (the instructor's own copies, a planted page script); where there is no confined
kernel they pass :data:`TRUSTED_AUTOGRADE`, the documented opt-in to unconfined grading, so
that the rest of nbgrader's round trip still runs on any machine.
"""

from traitlets.config import Config

from instructor.grading.sandbox import confinement_problem

#: Extra ``nbgrader autograde`` arguments for notebooks the tests trust.
TRUSTED_AUTOGRADE = ["--ConfinedKernelManager.unconfined=True"] if confinement_problem() else []
#: The same opt-in as traitlets configuration, for a preprocessor made in the test itself.
TRUSTED_CONFIG = Config({"ConfinedKernelManager": {"unconfined": bool(TRUSTED_AUTOGRADE)}})
