"""The throw-away Jupyter configuration of the browser test: JupyterLab's own defaults, except
for the few settings without which a run would not be offline or deterministic.

Everything a student sees in a default JupyterLab 4.6 is left as it is; in particular the
notebook's windowing (``windowingMode``, default ``contentVisibility``: cells off screen are
not rendered) and ``scrollPastEnd`` are NOT overridden, so the checks scroll each cell into
view as a student would. Each remaining override says why it is there.
"""

import json

# Server options (JUPYTER_CONFIG_DIR/jupyter_config.json).
SERVER_CONFIG = {
    "LabApp": {
        # The checks read the notebook model through window.jupyterapp; exposing it changes
        # nothing on the page.
        "expose_app_in_browser": True,
        # Offline: the server would otherwise ask PyPI whether a newer JupyterLab exists.
        "check_for_updates_class": "jupyterlab.NeverCheckForUpdate",
    },
}

# Default setting overrides (labconfig/default_setting_overrides.json).
SETTING_OVERRIDES = {
    "@jupyterlab/docmanager-extension:plugin": {
        # Deterministic: the test never saves, and an autosave of a multi-megabyte notebook
        # in the middle of a run (every 120 s by default) races the kernel's outputs on a
        # loaded machine; nothing on the page depends on it.
        "autosave": False,
    },
    "@jupyterlab/apputils-extension:notification": {
        # Offline: with these on, the page asks jupyter.org for news and updates; by default
        # it puts up a toast asking whether to, which the toast check would report on every
        # fresh profile although no course page caused it.
        "checkForUpdates": False,
        "fetchNews": "false",
    },
}


def write(config_dir):
    """Write the configuration into ``config_dir`` (a fresh JUPYTER_CONFIG_DIR)."""
    labconfig = config_dir / "labconfig"
    labconfig.mkdir(parents=True)
    (config_dir / "jupyter_config.json").write_text(json.dumps(SERVER_CONFIG, indent=2))
    (labconfig / "default_setting_overrides.json").write_text(
        json.dumps(SETTING_OVERRIDES, indent=2)
    )
