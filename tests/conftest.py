"""Shared pytest set-up.

Hypothesis explores new examples on every run on a developer's machine; on CI (CI=true) it runs
derandomized, so a red CI is always reproducible from the same commit.
"""

import os

import matplotlib
from hypothesis import settings

matplotlib.use("Agg")

settings.register_profile("ci", derandomize=True, deadline=None)
settings.register_profile("dev", deadline=None)
settings.load_profile("ci" if os.environ.get("CI") else "dev")
