"""Durable-job test helpers: generators that take their time (or can edit), built by
`INTERPLAY_GENERATOR_FACTORY=tests.helpers.jobs:slow_generator` in server and worker
subprocesses, and real `interplay serve` / `interplay worker` processes on free loopback ports.
"""

from __future__ import annotations

import json
import os
import signal
import socket
import subprocess
import sys
import threading
import time
from dataclasses import dataclass
from pathlib import Path

import httpx
import numpy as np
from websockets.sync.client import connect

from tests.helpers.api import FakeGenerator

ROOT = Path(__file__).resolve().parents[2]
INTERPLAY = str(Path(sys.executable).with_name("interplay"))


class SlowGenerator(FakeGenerator):
    """The fake generator, `delay` seconds per 10-frame chunk (INTERPLAY_TEST_CHUNK_DELAY_S)."""

    def __init__(self, delay: float | None = None):
        super().__init__(chunk=10)
        self.delay = float(os.environ.get("INTERPLAY_TEST_CHUNK_DELAY_S", "0.1")
                           if delay is None else delay)

    def stream(self, req, plan):
        for item in super().stream(req, plan):
            time.sleep(self.delay)
            yield item


def slow_generator() -> SlowGenerator:
    return SlowGenerator()


def slow_real_generator():
    """The real models (`load_generator`), `INTERPLAY_TEST_CHUNK_DELAY_S` seconds per streamed
    chunk (40 frames): a job that is surely still running when a test kills its server
    (e2e/specs/restart.spec.ts)."""
    from interplay.generators.router import load_generator
    gen = load_generator()
    inner, delay = gen.stream, float(os.environ.get("INTERPLAY_TEST_CHUNK_DELAY_S", "0.1"))

    def stream(req, plan):
        for item in inner(req, plan):
            time.sleep(delay)
            yield item
    gen.stream = stream      # type: ignore[method-assign]
    return gen


@dataclass
class FakeEdit:
    joints: np.ndarray


class EditingGenerator(FakeGenerator):
    """Can edit: `delay` seconds per edit, counting how many run at once (a heavy edit)."""
    reason = None

    def __init__(self, delay: float = 0.3):
        super().__init__()
        self.delay = delay
        self.running = 0
        self.most = 0
        self._lock = threading.Lock()

    @property
    def can_edit(self) -> bool:
        return True

    def edit(self, joints, part, prompt, frames=None, seed=None, context=None):
        with self._lock:
            self.running += 1
            self.most = max(self.most, self.running)
        try:
            time.sleep(self.delay)
            out = np.asarray(joints, dtype=np.float64).copy()
            out[..., 1] += 0.01
            return FakeEdit(out), {"generator": "fake", "part": part, "prompt": prompt,
                                   "frames": list(frames) if frames else None,
                                   "seed": seed if seed is not None else 1}
        finally:
            with self._lock:
                self.running -= 1


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def base_env(tmp: Path, database_url: str | None = None, **extra: str) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items()
           if not k.startswith("INTERPLAY_") and k != "DATABASE_URL"}
    # This checkout's code, whatever the virtual environment's editable install points at.
    env.update({"PYTHONPATH": f"{ROOT / 'backend'}{os.pathsep}{ROOT}", "INTERPLAY_VAR_DIR": str(tmp),
                "DATABASE_URL": database_url or f"sqlite:///{tmp / 'jobs.db'}",
                "INTERPLAY_FRONTEND_DIST": str(tmp / "dist"),
                "INTERPLAY_GENERATOR_FACTORY": "tests.helpers.jobs:slow_generator"})
    env.update(extra)
    return env


class Proc:
    """A subprocess whose output goes to a log file (read on failure)."""

    def __init__(self, args: list[str], env: dict[str, str], log: Path):
        self.log = log
        self._out = open(log, "wb")
        self.popen = subprocess.Popen(args, env=env, cwd=ROOT, stdout=self._out,
                                      stderr=subprocess.STDOUT, start_new_session=True)

    @property
    def pid(self) -> int:
        return self.popen.pid

    def tail(self, n: int = 4000) -> str:
        if not self._out.closed:
            self._out.flush()
        return self.log.read_text(errors="replace")[-n:]

    def signal(self, sig: int) -> None:
        if self.popen.poll() is None:
            os.kill(self.popen.pid, sig)

    def stop(self, timeout: float = 15.0) -> int | None:
        if self.popen.poll() is None:
            self.signal(signal.SIGTERM)
            try:
                self.popen.wait(timeout)
            except subprocess.TimeoutExpired:
                self.popen.kill()
                self.popen.wait(5)
        self._out.close()
        return self.popen.returncode


def start_server(tmp: Path, env: dict[str, str], workers: int = 1, name: str = "server",
                 port: int | None = None, timeout: float = 60.0) -> tuple[Proc, str]:
    port = port or free_port()
    args = [INTERPLAY, "serve", "--host", "127.0.0.1", "--port", str(port)]
    if workers > 1:
        args += ["--workers", str(workers)]
    proc = Proc(args, env, tmp / f"{name}.log")
    base = f"http://127.0.0.1:{port}"
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if proc.popen.poll() is not None:
            raise AssertionError(f"{name} exited {proc.popen.returncode}:\n{proc.tail()}")
        try:
            if httpx.get(f"{base}/api/skeleton", timeout=2).status_code == 200:
                return proc, base
        except httpx.HTTPError:
            pass
        time.sleep(0.1)
    proc.stop()
    raise AssertionError(f"{name} did not start:\n{proc.tail()}")


def start_worker(tmp: Path, env: dict[str, str], name: str = "worker") -> Proc:
    return Proc([INTERPLAY, "worker", "--concurrency", "1"], env, tmp / f"{name}.log")


def follow(base: str, stream: str, timeout: float = 60.0) -> tuple[list[dict], int | None]:
    """Every event of a job's stream and the close code."""
    from websockets.exceptions import ConnectionClosed
    events: list[dict] = []
    with connect(base.replace("http://", "ws://") + stream, open_timeout=20,
                 max_size=None) as ws:
        try:
            while True:
                events.append(json.loads(ws.recv(timeout=timeout)))
        except ConnectionClosed:
            pass
        code = ws.close_code
    return events, code


def wait_status(base: str, job_id: str, states: tuple[str, ...], timeout: float = 30.0) -> dict:
    deadline = time.monotonic() + timeout
    last: dict = {}
    while time.monotonic() < deadline:
        r = httpx.get(f"{base}/api/jobs/{job_id}", timeout=10)
        if r.status_code == 200:
            last = r.json()
            if last["status"] in states:
                return last
        time.sleep(0.1)
    raise AssertionError(f"job {job_id} did not reach {states}: {last}")
