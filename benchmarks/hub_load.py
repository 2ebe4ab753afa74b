"""Classroom load on a real JupyterHub: N students run every chapter notebook at the same time.

``make hub-load STUDENTS=N`` (default 20, at most 50) runs this script. It starts a real
JupyterHub (``benchmarks/hub-requirements.txt``) and its configurable-http-proxy on 127.0.0.1
only, with a throw-away configuration in a temporary folder: the dummy authenticator with a random
shared password, local-process spawners whose single-user servers run this project's venv, each
user in a temporary home holding a copy of the notebooks as nbgitpuller would leave it
(``~/rotations-course/notebooks``). Through the hub's REST API it creates the users, starts their
servers and gives each a token; then every student, all at once, opens every chapter notebook
(``notebooks/*.ipynb``) the way JupyterLab does (a session through the proxy, the kernel's
websocket, the user's token, a reconnect when the websocket drops) and runs it cell by cell.
The servers are configured as docs/classroom.md deploys them for students (nbgrader's instructor
extensions off).

A notebook run fails on an error in any cell, or on a check cell (one whose stored output shows
``✓``, that calls ``check(`` or that nbgrader grades) whose output lacks ``✓``. Measured: the wall
time of every cell, notebook, server and kernel start; every 0.25 s the RSS of each student's
processes (single-user server plus kernel) and of the hub and the proxy; the CPU time of each
student's processes.

Everything started is stopped at the end, also on a failure, the deadline or Ctrl-C: servers,
kernels, the proxy and the hub; then the script checks that none of their processes is alive and
nothing listens on their ports, and removes the temporary folder. It prints a table and ends with
the line ``P passed, F failed`` (notebook runs); the exit status is 1 when anything failed.

Usage (``make hub-load`` installs JupyterHub and the proxy first)::

    python benchmarks/hub_load.py --students 20 --proxy PATH/configurable-http-proxy \
        [--json build/hub-load/students-20.json] [--log build/hub-load/hub-20.log]
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import json
import os
import platform
import secrets
import shutil
import signal
import socket
import statistics
import subprocess
import sys
import tempfile
import threading
import time
import uuid
from dataclasses import dataclass, field
from importlib.metadata import version
from pathlib import Path

import nbformat
import psutil
from jupyter_server.services.kernels.connection.base import deserialize_binary_message
from tornado.httpclient import AsyncHTTPClient, HTTPRequest
from tornado.websocket import WebSocketClosedError, websocket_connect

ROOT = Path(__file__).resolve().parent.parent
MAX_STUDENTS = 50
CHECK_MARK = "✓"
COURSE_DIR = "rotations-course"  # where nbgitpuller would put the repository
# The students' servers as docs/classroom.md deploys them (/etc/jupyter there): nbgrader's server
# extensions are the instructor's tools and cost each student's server about 40 MB.
STUDENT_SERVER_CONFIG = {
    "ServerApp": {
        "jpserver_extensions": {
            f"nbgrader.server_extensions.{name}": False
            for name in ("formgrader", "course_list", "assignment_list", "validate_assignment")
        }
    }
}


# --------------------------------------------------------------------------------- results


@dataclass
class NotebookRun:
    user: str
    notebook: str
    seconds: float = 0.0
    kernel_start: float = 0.0
    reconnects: int = 0  # websocket reconnects, as JupyterLab's
    cells: list = field(default_factory=list)  # (cell index, seconds)
    failures: list = field(default_factory=list)  # one line each

    @property
    def ok(self):
        return not self.failures and bool(self.cells)


@dataclass
class Student:
    name: str
    token: str = ""
    spawn_seconds: float = 0.0
    error: str = ""
    runs: list = field(default_factory=list)


def percentile(values, q):
    """The q-th percentile (0-100) by linear interpolation; nan for no values."""
    if not values:
        return float("nan")
    ordered = sorted(values)
    k = (len(ordered) - 1) * q / 100
    lo, hi = int(k), min(int(k) + 1, len(ordered) - 1)
    return ordered[lo] + (ordered[hi] - ordered[lo]) * (k - lo)


# --------------------------------------------------------------------------------- the hub


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def hub_config(tmp, ports, proxy, password, service_token):
    """The throw-away jupyterhub_config.py: loopback, dummy auth, local-process spawners."""
    singleuser = [str(Path(sys.executable).parent / "jupyterhub-singleuser")]
    args = ["--ServerApp.allow_root=True"] if os.geteuid() == 0 else []
    return f"""
c = get_config()  # noqa
c.JupyterHub.bind_url = "http://127.0.0.1:{ports["public"]}"
c.JupyterHub.hub_bind_url = "http://127.0.0.1:{ports["hub"]}"
c.ConfigurableHTTPProxy.api_url = "http://127.0.0.1:{ports["proxy_api"]}"
c.ConfigurableHTTPProxy.command = [{str(proxy)!r}]
c.ConfigurableHTTPProxy.pid_file = {str(tmp / "proxy.pid")!r}
c.JupyterHub.db_url = "sqlite:///{tmp / "jupyterhub.sqlite"}"
c.JupyterHub.cookie_secret_file = {str(tmp / "cookie_secret")!r}
c.JupyterHub.pid_file = {str(tmp / "hub.pid")!r}
c.JupyterHub.authenticator_class = "dummy"
c.DummyAuthenticator.password = {password!r}
c.Authenticator.allow_all = True   # the users are created through the REST API below
c.JupyterHub.spawner_class = "simple"
c.SimpleLocalProcessSpawner.home_dir_template = {str(tmp / "home" / "{username}")!r}
c.Spawner.ip = "127.0.0.1"
c.Spawner.cmd = {singleuser!r}
c.Spawner.args = {args!r}
c.Spawner.default_url = "/lab"
c.Spawner.environment = {{"JUPYTER_CONFIG_PATH": {str(tmp / "etc-jupyter")!r}}}
c.Spawner.start_timeout = 600
c.Spawner.http_timeout = 600
c.JupyterHub.concurrent_spawn_limit = {MAX_STUDENTS}
c.JupyterHub.cleanup_servers = True
c.JupyterHub.cleanup_proxy = True
c.JupyterHub.services = [{{"name": "hub-load", "api_token": {service_token!r}}}]
c.JupyterHub.load_roles = [{{
    "name": "hub-load",
    "scopes": ["admin:users", "admin:servers", "tokens", "list:users", "read:users"],
    "services": ["hub-load"],
}}]
"""


def make_homes(tmp, users, notebooks):
    (tmp / "etc-jupyter").mkdir()
    (tmp / "etc-jupyter" / "jupyter_server_config.json").write_text(
        json.dumps(STUDENT_SERVER_CONFIG, indent=1)
    )
    for user in users:
        course = tmp / "home" / user / COURSE_DIR / "notebooks"
        course.mkdir(parents=True)
        for nb in notebooks:
            shutil.copy2(nb, course / nb.name)


def start_hub(tmp, config):
    (tmp / "jupyterhub_config.py").write_text(config)
    log = open(tmp / "hub.log", "wb")  # noqa: SIM115 - closed by stop_everything
    env = dict(os.environ, PATH=f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}")
    # its own session: a Ctrl-C reaches this script, which then stops the hub in order
    hub = subprocess.Popen(
        [sys.executable, "-m", "jupyterhub", "-f", str(tmp / "jupyterhub_config.py")],
        cwd=tmp,
        stdout=log,
        stderr=subprocess.STDOUT,
        env=env,
        start_new_session=True,
    )
    hub.log_file = log
    return hub


class Api:
    """The hub's REST API and the users' servers, through the proxy as a browser reaches them."""

    def __init__(self, base, service_token):
        self.base, self.service_token = base, service_token
        self.http = AsyncHTTPClient(force_instance=True, max_clients=4 * MAX_STUDENTS)

    async def call(self, method, path, token=None, body=None, ok=(200, 201, 202, 204), timeout=120):
        request = HTTPRequest(
            self.base + path,
            method=method,
            headers={"Authorization": f"token {token or self.service_token}"},
            body=None if body is None else json.dumps(body),
            allow_nonstandard_methods=True,
            request_timeout=timeout,
        )
        response = await self.http.fetch(request, raise_error=False)
        if response.code not in ok:
            text = (response.body or b"").decode(errors="replace")[:200]
            raise RuntimeError(f"{method} {path}: HTTP {response.code} {text}")
        return json.loads(response.body) if response.body else None

    async def wait_for_hub(self, hub, deadline):
        while time.monotonic() < deadline:
            if hub.poll() is not None:
                raise RuntimeError(f"the hub exited with status {hub.returncode}")
            try:
                return await self.call("GET", "/hub/api/", timeout=5)
            except (RuntimeError, OSError):
                await asyncio.sleep(0.5)
        raise TimeoutError("the hub did not answer before the deadline")

    async def spawn(self, student, deadline):
        """Start the student's server and give them a token; record the spawn time."""
        start = time.monotonic()
        await self.call("POST", f"/hub/api/users/{student.name}/server")
        while True:
            model = await self.call("GET", f"/hub/api/users/{student.name}")
            server = model.get("servers", {}).get("", {})
            if server.get("ready"):
                break
            if not server:
                raise RuntimeError("the server stopped while starting")
            if time.monotonic() > deadline:
                raise TimeoutError("the server did not start before the deadline")
            await asyncio.sleep(0.5)
        student.spawn_seconds = time.monotonic() - start
        reply = await self.call(
            "POST",
            f"/hub/api/users/{student.name}/tokens",
            body={"note": "hub-load", "expires_in": 6 * 3600},
        )
        student.token = reply["token"]


# --------------------------------------------------------------------------------- a notebook


def is_check_cell(cell):
    """A cell whose verdict the run must show: stored ✓, a check() call or an nbgrader test."""
    if cell.get("metadata", {}).get("nbgrader", {}).get("grade") and cell.cell_type == "code":
        return True
    return "check(" in cell.source or CHECK_MARK in json.dumps(cell.get("outputs", []))


def output_text(msg):
    content = msg["content"]
    if msg["msg_type"] == "stream":
        return content.get("text", "")
    if msg["msg_type"] in ("execute_result", "display_data", "update_display_data"):
        return " ".join(v for v in content.get("data", {}).values() if isinstance(v, str))
    return ""


class Kernel:
    """One kernel's websocket (JupyterLab's protocol: JSON frames with a channel field).

    Like JupyterLab, it reconnects (up to 3 times) when the websocket closes, with the same
    session id, for which the server buffers the kernel's messages and replays them.
    """

    def __init__(self, url, token):
        self.session = uuid.uuid4().hex
        self.url, self.token = f"{url}?session_id={self.session}", token
        self.ws, self.reconnects = None, 0

    async def connect(self):
        self.ws = await websocket_connect(
            HTTPRequest(
                self.url, headers={"Authorization": f"token {self.token}"}, request_timeout=120
            ),
            max_message_size=256 * 1024 * 1024,
        )

    async def reconnect(self):
        if self.reconnects == 3:
            raise ConnectionError("the kernel's websocket closed, 3 reconnects failed")
        self.reconnects += 1
        await asyncio.sleep(1)
        await self.connect()

    async def read(self, timeout):
        while True:
            raw = await asyncio.wait_for(self.ws.read_message(), timeout)
            if raw is not None:
                return json.loads(raw) if isinstance(raw, str) else deserialize_binary_message(raw)
            await self.reconnect()

    async def send(self, text):
        while True:
            try:
                return await self.ws.write_message(text)
            except WebSocketClosedError:
                await self.reconnect()

    async def request(self, msg_type, content, timeout):
        """Send a shell request; return (reply content, [iopub messages]) once idle."""
        msg_id = uuid.uuid4().hex
        await self.send(
            json.dumps(
                {
                    "header": {
                        "msg_id": msg_id,
                        "msg_type": msg_type,
                        "session": self.session,
                        "username": "hub-load",
                        "version": "5.3",
                    },
                    "parent_header": {},
                    "metadata": {},
                    "content": content,
                    "channel": "shell",
                    "buffers": [],
                }
            )
        )
        reply, iopub, idle = None, [], False
        while reply is None or not idle:
            msg = await self.read(timeout)
            if msg.get("parent_header", {}).get("msg_id") != msg_id:
                continue
            if msg["channel"] == "shell":
                reply = msg["content"]
            elif msg["channel"] == "iopub":
                iopub.append(msg)
                idle = msg["msg_type"] == "status" and msg["content"]["execution_state"] == "idle"
        return reply, iopub

    def close(self):
        if self.ws is not None:
            self.ws.close()


def cell_failure(index, cell, reply, iopub):
    """What went wrong in one executed cell, or None."""
    where = f"cell {index} ({cell.get('id', '?')})"
    errors = [m["content"] for m in iopub if m["msg_type"] == "error"]
    if reply.get("status") == "error" or errors:
        err = errors[0] if errors else reply
        return f"{where}: {err.get('ename')}: {str(err.get('evalue'))[:120]}"
    if is_check_cell(cell) and CHECK_MARK not in "".join(output_text(m) for m in iopub):
        return f"{where}: check cell without {CHECK_MARK}"
    return None


async def run_notebook(api, student, path, cell_timeout):
    """Open ``path`` in the student's server as JupyterLab does and run every code cell."""
    run = NotebookRun(student.name, path.name)
    nb = nbformat.read(path, as_version=4)
    user = f"/user/{student.name}"
    start, where, kernel, model = time.monotonic(), "opening the notebook", None, None
    try:
        model = await api.call(
            "POST",
            f"{user}/api/sessions",
            token=student.token,
            body={
                "path": f"{COURSE_DIR}/notebooks/{path.name}",
                "name": path.name,
                "type": "notebook",
                "kernel": {"name": "python3"},
            },
        )
        kernel = Kernel(
            api.base.replace("http", "ws", 1)
            + f"{user}/api/kernels/{model['kernel']['id']}/channels",
            student.token,
        )
        await kernel.connect()
        await kernel.request("kernel_info_request", {}, 300)
        run.kernel_start = time.monotonic() - start
        for i, cell in enumerate(nb.cells):
            if cell.cell_type != "code":
                continue
            where, t0 = f"cell {i}", time.monotonic()
            reply, iopub = await kernel.request(
                "execute_request",
                {
                    "code": cell.source,
                    "silent": False,
                    "store_history": True,
                    "user_expressions": {},
                    "allow_stdin": False,
                    "stop_on_error": False,
                },
                cell_timeout,
            )
            run.cells.append((i, time.monotonic() - t0))
            failure = cell_failure(i, cell, reply, iopub)
            if failure:
                run.failures.append(failure)
    except Exception as err:  # noqa: BLE001 - this run's failure; the others go on
        run.failures.append(f"{where}: {type(err).__name__}: {err}"[:200])
    finally:
        if kernel is not None:
            kernel.close()
            run.reconnects = kernel.reconnects
        run.seconds = time.monotonic() - start
    if model is not None:  # not reached when cancelled: the hub's shutdown ends it then
        await close_session(api, student, model["id"], run)
    return run


async def close_session(api, student, session_id, run):
    """Shut the kernel down, as closing the notebook's tab with "shut down kernel" does."""
    try:
        await api.call(
            "DELETE", f"/user/{student.name}/api/sessions/{session_id}", token=student.token
        )
    except (RuntimeError, OSError) as err:
        run.failures.append(f"closing the session: {err}")


async def run_student(api, student, notebooks, deadline, cell_timeout):
    try:
        await api.spawn(student, deadline)
    except Exception as err:  # noqa: BLE001 - reported as this student's failure
        student.error = f"server start: {type(err).__name__}: {err}"
        return
    for path in notebooks:
        student.runs.append(await run_notebook(api, student, path, cell_timeout))


async def load(api, hub, students, notebooks, deadline, cell_timeout):
    await api.wait_for_hub(hub, deadline)
    await api.call("POST", "/hub/api/users", body={"usernames": [s.name for s in students]})
    tasks = [run_student(api, s, notebooks, deadline, cell_timeout) for s in students]
    await asyncio.wait_for(asyncio.gather(*tasks), max(1.0, deadline - time.monotonic()))


# --------------------------------------------------------------------------------- processes


class Sampler(threading.Thread):
    """Every ``interval`` s: RSS of the hub, the proxy and each student's processes."""

    def __init__(self, hub_pid, interval=0.25):
        super().__init__(daemon=True)
        self.hub = psutil.Process(hub_pid)
        self.interval, self.stop = interval, threading.Event()
        self.seen = {}  # pid -> (process, role)
        self.peak = {}  # role -> peak RSS (sum over its processes) in bytes
        self.peak_pss = {}  # role -> peak PSS (shared pages divided among their users)
        self.kind_peak = {}  # "server" / "kernel" -> peak RSS of one such process
        self.cpu = {}  # pid -> last seen user+system CPU seconds
        self.ports = set()
        self.rounds = 0

    def role(self, proc):
        if proc.pid == self.hub.pid:
            return "hub"
        try:
            user = proc.environ().get("JUPYTERHUB_USER")
            name = proc.name()
        except (psutil.Error, OSError):
            return None
        return user or ("proxy" if "node" in name or "proxy" in name else "other")

    def sample(self):
        try:
            procs = [self.hub, *self.hub.children(recursive=True)]
        except psutil.Error:
            return
        totals, pss = {}, {}
        full = self.rounds % 4 == 0  # PSS reads smaps: once a second is enough
        self.rounds += 1
        for proc in procs:
            if proc.pid not in self.seen:
                self.seen[proc.pid] = (proc, self.role(proc))
            role = self.seen[proc.pid][1]
            try:
                rss = proc.memory_info().rss
                totals[role] = totals.get(role, 0) + rss
                if full:
                    pss[role] = pss.get(role, 0) + proc.memory_full_info().pss
                t = proc.cpu_times()
                self.cpu[proc.pid] = t.user + t.system
                if role not in ("hub", "proxy", "other"):
                    kind = "kernel" if "ipykernel" in " ".join(proc.cmdline()) else "server"
                    self.kind_peak[kind] = max(self.kind_peak.get(kind, 0), rss)
            except psutil.Error:
                continue
        for role, rss in totals.items():
            self.peak[role] = max(self.peak.get(role, 0), rss)
        for role, value in pss.items():
            self.peak_pss[role] = max(self.peak_pss.get(role, 0), value)

    def note_ports(self):
        for proc, _ in list(self.seen.values()):
            try:
                for conn in proc.net_connections(kind="inet"):
                    if conn.status == psutil.CONN_LISTEN:
                        self.ports.add(conn.laddr.port)
            except psutil.Error:
                continue

    def cpu_of(self, role):
        return sum(self.cpu.get(pid, 0.0) for pid, (_, r) in self.seen.items() if r == role)

    def run(self):
        while not self.stop.is_set():
            self.sample()
            self.stop.wait(self.interval)


def running(proc):
    """Alive and still the process we saw (psutil compares the start time: no reused pid)."""
    try:
        return proc.is_running() and proc.status() != psutil.STATUS_ZOMBIE
    except psutil.Error:
        return False


def stop_everything(hub, sampler, ports):
    """Stop the hub (which stops servers and proxy), then any process of ours still alive.

    Returns the problems left (processes alive, ports listening) as lines, and how many
    processes were seen.
    """
    if sampler is not None:
        sampler.sample()
        sampler.note_ports()
        sampler.stop.set()
        ports = ports | sampler.ports
    if hub.poll() is None:
        hub.send_signal(signal.SIGTERM)
        try:
            hub.wait(60)
        except subprocess.TimeoutExpired:
            hub.kill()
            hub.wait(10)
    hub.log_file.close()
    procs = [p for p, _ in (sampler.seen.values() if sampler else [])]
    for how, wait in (("terminate", 10), ("kill", 5)):
        alive = [p for p in procs if running(p)]
        for p in alive:
            with contextlib.suppress(psutil.Error):
                getattr(p, how)()
        psutil.wait_procs(alive, timeout=wait)
    problems = [f"process {p.pid} still running" for p in procs if running(p)]
    for port in sorted(ports):
        with socket.socket() as s:
            s.settimeout(1)
            if s.connect_ex(("127.0.0.1", port)) == 0:
                problems.append(f"port {port} still listening")
    return problems, len(procs)


# --------------------------------------------------------------------------------- report


def machine():
    cpu = platform.processor() or "?"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    mem = psutil.virtual_memory().total / 2**30
    return f"{os.cpu_count()} cores ({cpu}), {mem:.0f} GiB RAM, Python {platform.python_version()}"


def mb(nbytes):
    return f"{nbytes / 2**20:.0f} MB"


def report(students, notebooks, sampler, wall, hub_version):
    runs = [r for s in students for r in s.runs]
    expected = len(students) * len(notebooks)
    passed = sum(r.ok for r in runs)
    failed = expected - passed
    nb_times = [r.seconds for r in runs if r.ok]
    cell_times = [t for r in runs for _, t in r.cells]
    spawn = [s.spawn_seconds for s in students if s.token]
    kstart = [r.kernel_start for r in runs if r.kernel_start]
    rss = [sampler.peak.get(s.name, 0) for s in students] if sampler else [0]
    pss = [sampler.peak_pss.get(s.name, 0) for s in students] if sampler else [0]
    kind = sampler.kind_peak if sampler else {}
    cpu = [sampler.cpu_of(s.name) for s in students] if sampler else [0]

    def p50_p95(values, digits=1):
        return f"{percentile(values, 50):.{digits}f} s / {percentile(values, 95):.{digits}f} s"

    rows = [
        ("students", f"{len(students)}"),
        ("notebooks run", f"{len(runs)} of {expected} ({len(notebooks)} per student)"),
        ("failures", f"{failed}"),
        ("server start p50 / p95", p50_p95(spawn)),
        ("kernel start p50 / p95", p50_p95(kstart)),
        ("notebook time p50 / p95", p50_p95(nb_times)),
        (
            "cell time p95 / max",
            f"{percentile(cell_times, 95):.2f} s / {max(cell_times, default=float('nan')):.2f} s",
        ),
        (
            "peak RSS per student p50 / max",
            f"{mb(statistics.median(rss))} / {mb(max(rss))}  (server + kernel)",
        ),
        (
            "  one server / one kernel (max)",
            f"{mb(kind.get('server', 0))} / {mb(kind.get('kernel', 0))}",
        ),
        (
            "peak PSS per student p50 / max",
            f"{mb(statistics.median(pss))} / {mb(max(pss))}  (shared pages divided)",
        ),
        (
            "CPU per student p50 / max",
            f"{statistics.median(cpu):.0f} s / {max(cpu):.0f} s  (all {len(notebooks)} notebooks)",
        ),
        ("websocket reconnects", f"{sum(r.reconnects for r in runs)}"),
        ("hub peak RSS", mb(sampler.peak.get("hub", 0)) if sampler else "?"),
        ("proxy peak RSS", mb(sampler.peak.get("proxy", 0)) if sampler else "?"),
        ("wall time, all students", f"{wall:.0f} s"),
    ]
    print(
        f"\nhub-load: JupyterHub {hub_version}, {len(students)} students at once, "
        f"machine: {machine()}"
    )
    width = max(len(k) for k, _ in rows)
    for k, v in rows:
        print(f"  {k:<{width}}  {v}")
    print(
        f"\n  {'notebook':34} {'runs':>4} {'failed':>6} {'p50':>8} {'p95':>8} {'slowest cell':>14}"
    )
    for path in notebooks:
        mine = [r for r in runs if r.notebook == path.name]
        times = [r.seconds for r in mine if r.ok]
        slow = max(((t, i) for r in mine for i, t in r.cells), default=(float("nan"), "-"))
        print(
            f"  {path.name:34} {len(mine):>4} {sum(not r.ok for r in mine):>6} "
            f"{percentile(times, 50):7.1f}s {percentile(times, 95):7.1f}s "
            f"{slow[0]:8.2f}s #{slow[1]}"
        )
    problems = [f"{s.name}: {s.error}" for s in students if s.error]
    problems += [f"{r.user} {r.notebook}: {f}" for r in runs for f in r.failures]
    for line in problems[:30]:
        print(f"  FAILED {line}")
    if len(problems) > 30:
        print(f"  ... and {len(problems) - 30} more")
    return passed, failed


def save_json(path, students, sampler):
    data = {
        "students": [
            {
                "name": s.name,
                "spawn_seconds": s.spawn_seconds,
                "error": s.error,
                "peak_rss": sampler.peak.get(s.name, 0) if sampler else None,
                "peak_pss": sampler.peak_pss.get(s.name, 0) if sampler else None,
                "cpu_seconds": sampler.cpu_of(s.name) if sampler else None,
                "runs": [
                    {
                        "notebook": r.notebook,
                        "seconds": r.seconds,
                        "kernel_start": r.kernel_start,
                        "reconnects": r.reconnects,
                        "cells": r.cells,
                        "failures": r.failures,
                    }
                    for r in s.runs
                ],
            }
            for s in students
        ],
        "hub_peak_rss": sampler.peak.get("hub") if sampler else None,
        "proxy_peak_rss": sampler.peak.get("proxy") if sampler else None,
    }
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(data, indent=1))


# --------------------------------------------------------------------------------- main


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--students", type=int, default=20, help=f"1 to {MAX_STUDENTS}")
    parser.add_argument(
        "--proxy",
        default=shutil.which("configurable-http-proxy"),
        help="the configurable-http-proxy executable",
    )
    parser.add_argument(
        "--notebooks",
        default=str(ROOT / "notebooks"),
        help="folder of the chapter notebooks (*.ipynb)",
    )
    parser.add_argument(
        "--deadline",
        type=float,
        default=1800,
        help="seconds for everything, start to clean-up (default 1800)",
    )
    parser.add_argument("--cell-timeout", type=float, default=300)
    parser.add_argument("--json", help="also write every measurement to this file")
    parser.add_argument("--log", help="keep the hub's log (with the servers') in this file")
    args = parser.parse_args(argv)
    if not 1 <= args.students <= MAX_STUDENTS:
        parser.error(f"--students must be between 1 and {MAX_STUDENTS}, not {args.students}")
    if not args.proxy or not Path(args.proxy).exists():
        parser.error("configurable-http-proxy not found (make hub-load installs it)")
    if not (Path(sys.executable).parent / "jupyterhub-singleuser").exists():
        parser.error("jupyterhub is not installed in this venv (make hub-load installs it)")
    return args


def interrupt(*_):
    raise KeyboardInterrupt


def main(argv=None):
    args = parse_args(argv)
    notebooks = sorted(Path(args.notebooks).glob("*.ipynb"))
    if not notebooks:
        sys.exit(f"hub_load: no notebooks in {args.notebooks}")
    students = [Student(f"student{i:02d}") for i in range(1, args.students + 1)]
    deadline = time.monotonic() + args.deadline
    ports = {k: free_port() for k in ("public", "hub", "proxy_api")}
    service_token = secrets.token_hex(32)
    tmp = Path(tempfile.mkdtemp(prefix="hub-load-"))
    hub = sampler = None
    aborted = ""
    signal.signal(signal.SIGINT, signal.default_int_handler)  # even when started in background
    signal.signal(signal.SIGTERM, interrupt)
    start = time.monotonic()
    try:
        make_homes(tmp, [s.name for s in students], notebooks)
        hub = start_hub(
            tmp,
            hub_config(
                tmp, ports, Path(args.proxy).resolve(), secrets.token_urlsafe(24), service_token
            ),
        )
        sampler = Sampler(hub.pid)
        sampler.start()
        api = Api(f"http://127.0.0.1:{ports['public']}", service_token)
        asyncio.run(load(api, hub, students, notebooks, deadline, args.cell_timeout))
    except KeyboardInterrupt:
        aborted = "interrupted (Ctrl-C or SIGTERM)"
    except (asyncio.TimeoutError, TimeoutError):
        aborted = f"deadline of {args.deadline:.0f} s reached"
    except Exception as err:  # noqa: BLE001 - reported, then cleaned up
        aborted = f"{type(err).__name__}: {err}"
    finally:
        wall = time.monotonic() - start
        problems, nprocs, t_stop = [], 0, time.monotonic()
        if hub is not None:
            problems, nprocs = stop_everything(hub, sampler, set(ports.values()))
        t_stop = time.monotonic() - t_stop
        log = tmp / "hub.log"
        log_tail = log.read_text(errors="replace").splitlines()[-15:] if log.exists() else []
        if args.log and log.exists():
            Path(args.log).parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(log, args.log)
        shutil.rmtree(tmp, ignore_errors=True)
    passed, failed = report(students, notebooks, sampler, wall, version("jupyterhub"))
    if args.json:
        save_json(Path(args.json), students, sampler)
    print(
        f"\n  clean-up: {nprocs} processes stopped in {t_stop:.0f} s, "
        f"{'nothing left running or listening' if not problems else '; '.join(problems)}, "
        f"temporary homes {'removed' if not tmp.exists() else 'NOT removed: ' + str(tmp)}"
    )
    if aborted:
        print(f"  ABORTED: {aborted}")
        if log_tail:
            print("  last lines of the hub's log:\n    " + "\n    ".join(log_tail))
    print(f"{passed} passed, {failed} failed")
    return 0 if not (failed or problems or aborted or tmp.exists()) else 1


if __name__ == "__main__":
    sys.exit(main())
