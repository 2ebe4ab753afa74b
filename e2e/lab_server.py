"""The JupyterLab server of the browser test: started on a free localhost port with a random
token and a throw-away configuration (:mod:`lab_config`), stopped with everything it started
(kernels included).

``Server(tmp, root_dir)`` starts it (everything it writes stays under ``tmp``); ``wait_ready``
waits for its REST API; ``stop`` shuts it down, kernels first, and checks that no process of
it is left and its port is closed.
"""

import json
import os
import secrets
import signal
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request
from pathlib import Path

import lab_config
from common import POLL, CheckFailed


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def port_open(port):
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.settimeout(0.5)
        return s.connect_ex(("127.0.0.1", port)) == 0


class Server:
    """JupyterLab in its own process group, with everything it writes under ``tmp``."""

    def __init__(self, tmp, root_dir):
        self.port = free_port()
        self.token = secrets.token_hex(24)
        self.url = f"http://127.0.0.1:{self.port}"
        self.log_path = tmp / "jupyterlab.log"
        config_dir = tmp / "config"
        lab_config.write(config_dir)
        env = {
            k: v for k, v in os.environ.items() if k not in ("JUPYTERHUB_USER", "COURSE_GRADER_ID")
        }
        env.update(
            # the instructor's solved problem sets run as the course's example student (the
            # checks of exercises with per-student numbers refuse to pass without an id)
            COURSE_STUDENT_ID="(example)",
            JUPYTER_CONFIG_DIR=str(config_dir),
            JUPYTER_DATA_DIR=str(tmp / "data"),
            JUPYTER_RUNTIME_DIR=str(tmp / "runtime"),
            JUPYTER_PLATFORM_DIRS="1",
            IPYTHONDIR=str(tmp / "ipython"),
            BROWSER="true",
        )
        cmd = [
            sys.executable,
            "-m",
            "jupyterlab",
            "--no-browser",
            "--ServerApp.ip=127.0.0.1",
            f"--ServerApp.port={self.port}",
            "--ServerApp.port_retries=0",
            f"--IdentityProvider.token={self.token}",
            f"--ServerApp.root_dir={root_dir}",
        ]
        if hasattr(os, "geteuid") and os.geteuid() == 0:
            cmd.append("--allow-root")
        self.log_file = open(self.log_path, "w")
        self.proc = subprocess.Popen(
            cmd,
            cwd=root_dir,
            env=env,
            stdout=self.log_file,
            stderr=subprocess.STDOUT,
            stdin=subprocess.DEVNULL,
            start_new_session=True,
        )
        self.kernel_pids = set()

    def api(self, path, method="GET", timeout=5.0):
        req = urllib.request.Request(
            self.url + path,
            method=method,
            headers={"Authorization": f"token {self.token}"},
            data=b"" if method == "POST" else None,
        )
        with urllib.request.urlopen(req, timeout=timeout) as resp:
            body = resp.read()
        return json.loads(body) if body else None

    def wait_ready(self, timeout=90.0):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.proc.poll() is not None:
                raise CheckFailed(
                    f"JupyterLab exited with status {self.proc.returncode}:\n{self.log_tail()}"
                )
            try:
                self.api("/api/status")
                return
            except (urllib.error.URLError, ConnectionError, TimeoutError):
                time.sleep(POLL)
        raise CheckFailed(f"JupyterLab did not answer within {timeout:.0f} s:\n{self.log_tail()}")

    def log_tail(self, lines=40):
        try:
            return "\n".join(self.log_path.read_text(errors="replace").splitlines()[-lines:])
        except OSError:
            return "(no log)"

    def report(self):
        """What the server says of its kernels, and the warnings and errors of its log (for the
        log of a failed notebook)."""
        try:
            kernels = self.api("/api/kernels")
            said = ", ".join(
                f"kernel {k['id'][:8]} {k['execution_state']} ({k['connections']} connection(s))"
                for k in kernels
            )
            said = said or "no kernel"
        except (urllib.error.URLError, ConnectionError, TimeoutError, ValueError) as exc:
            said = f"no answer from /api/kernels ({exc})"
        marks = ("[W ", "[E ", "[C ", "Traceback")
        lines = [ln for ln in self.log_tail(400).splitlines() if any(m in ln for m in marks)]
        if lines:
            said += "; its log's warnings and errors, the last 10:\n" + "\n".join(lines[-10:])
        return said

    def note_kernels(self):
        """Remember the pids of the server's child processes (the kernels), to check at exit."""
        for pid in children_of(self.proc.pid):
            self.kernel_pids.add(pid)

    def stop(self):
        """Shut the server down (kernels first), then make sure nothing of it is left."""
        if self.proc.poll() is None:
            self.note_kernels()
            try:
                self.api("/api/shutdown", method="POST")
            except (urllib.error.URLError, ConnectionError, TimeoutError):
                pass
            try:
                self.proc.wait(timeout=20)
            except subprocess.TimeoutExpired:
                pass
        for sig, wait in ((signal.SIGTERM, 5), (signal.SIGKILL, 5)):
            if self.proc.poll() is not None:
                break
            try:
                os.killpg(self.proc.pid, sig)
            except ProcessLookupError:
                break
            try:
                self.proc.wait(timeout=wait)
            except subprocess.TimeoutExpired:
                pass
        # Kernels run in sessions of their own: end any that survived the shutdown, by pid.
        for pid in sorted(self.kernel_pids):
            if alive(pid):
                try:
                    os.kill(pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
        self.log_file.close()
        left = [pid for pid in self.kernel_pids if alive(pid)]
        if self.proc.poll() is None or left or port_open(self.port):
            raise CheckFailed(
                f"cleanup incomplete: server alive={self.proc.poll() is None}, "
                f"kernels left={left}, port {self.port} listening={port_open(self.port)}"
            )


def children_of(pid):
    """Pids of the direct children of ``pid`` (Linux /proc)."""
    kids = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text()
        except OSError:
            continue
        # the second field may contain spaces: parse after the closing parenthesis
        fields = stat[stat.rfind(")") + 2 :].split()
        if int(fields[1]) == pid:
            kids.append(int(entry.name))
    return kids


def alive(pid):
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return False
    return stat[stat.rfind(")") + 2 :].split()[0] != "Z"
