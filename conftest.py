"""Root pytest hooks: every strict-nbval cell is a notebook_exec test.

nbval collects each notebook cell as a test item without markers, so `-m 'not notebook_exec'`
used to keep all of them; with the marker added here it deselects notebook execution whole.
"""

import pytest


def pytest_collection_modifyitems(items):
    for item in items:
        if type(item).__name__ == "IPyNbCell":  # nbval's item class
            item.add_marker(pytest.mark.notebook_exec)
