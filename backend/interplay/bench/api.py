"""`interplay bench`: start the real app on a free loopback port (in this process, uvicorn in a
thread, a throw-away database), POST jobs through the real HTTP API, follow their WebSocket
streams, and report p50/p95 time to the first streamed frame and to a complete motion."""

from __future__ import annotations

import json
import os
import socket
import tempfile
import threading
import time
from contextlib import contextmanager
from pathlib import Path

import httpx
import numpy as np
import uvicorn
from websockets.sync.client import connect

from interplay.api.app import create_app
from interplay.settings import Settings, get_settings

PROMPTS = {
    1: ["a person walks forward", "a person jogs in a circle", "a person jumps, then squats"],
    2: ["two people dance salsa", "two people shake hands", "two people walk side by side"],
}


@contextmanager
def running_server(settings: Settings, generator=None):
    """Yield the base URL of the app served on 127.0.0.1:<free port> until the block ends."""
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    config = uvicorn.Config(create_app(settings, generator=generator), log_level="warning",
                            lifespan="on")
    server = uvicorn.Server(config)
    thread = threading.Thread(target=server.run, kwargs={"sockets": [sock]}, daemon=True)
    thread.start()
    deadline = time.monotonic() + 120   # the lifespan loads the generator
    while not server.started:
        if not thread.is_alive() or time.monotonic() > deadline:
            raise RuntimeError("the server did not start")
        time.sleep(0.05)
    try:
        yield f"http://127.0.0.1:{port}"
    finally:
        server.should_exit = True
        thread.join(30)
        sock.close()


def time_job(base: str, prompt: str, persons: int, seconds: float, seed: int) -> dict:
    """One job through the API: seconds to the first frames event and to done."""
    t0 = time.perf_counter()
    r = httpx.post(f"{base}/api/jobs", json={"prompt": prompt, "persons": persons,
                                             "seconds": seconds, "seed": seed}, timeout=60)
    r.raise_for_status()
    job = r.json()
    first = None
    with connect(base.replace("http://", "ws://") + job["stream"], open_timeout=30,
                 max_size=None) as ws:
        while True:
            event = json.loads(ws.recv(timeout=600))
            if event["type"] == "frames" and first is None:
                first = time.perf_counter() - t0
            elif event["type"] == "error":
                raise RuntimeError(f"job failed: {event['message']}")
            elif event["type"] == "done":
                return {"first_frame_s": first, "complete_s": time.perf_counter() - t0,
                        "frames": event["frames"]}


def _stats(values: list[float]) -> dict:
    return {"p50": round(float(np.percentile(values, 50)), 3),
            "p95": round(float(np.percentile(values, 95)), 3)}


def run_bench(runs: int = 3, seconds: float = 6.0, persons: tuple[int, ...] = (1, 2),
              warmup: int = 1, generator=None) -> dict:
    with tempfile.TemporaryDirectory(prefix="interplay-bench-") as tmp:
        settings = get_settings().model_copy(update={
            "var_dir": Path(tmp), "database_url": f"sqlite:///{tmp}/bench.db",
            "max_pending_jobs": 1000})
        t0 = time.perf_counter()
        with running_server(settings, generator) as base:
            startup = time.perf_counter() - t0
            for i in range(warmup):
                time_job(base, PROMPTS[persons[0]][0], persons[0], seconds, seed=i)
            results = []
            for n in persons:
                samples = [time_job(base, PROMPTS[n][i % len(PROMPTS[n])], n, seconds, seed=100 + i)
                           for i in range(runs)]
                results.append({
                    "persons": n, "runs": runs,
                    "first_frame_s": _stats([s["first_frame_s"] for s in samples]),
                    "complete_s": _stats([s["complete_s"] for s in samples]),
                    "frames": samples[0]["frames"], "samples": samples})
    return {"seconds": seconds, "warmup": warmup, "startup_s": round(startup, 3),
            "cpus": os.cpu_count(), "results": results}


def format_table(report: dict) -> str:
    head = (f"{'persons':>7}  {'runs':>4}  {'first frame p50':>15}  {'p95':>6}  "
            f"{'complete p50':>12}  {'p95':>6}")
    lines = [f"{report['seconds']:g} s motions through HTTP + WebSocket "
             f"({report['cpus']} CPUs, server start {report['startup_s']:.2f} s)", head]
    for r in report["results"]:
        lines.append(f"{r['persons']:>7}  {r['runs']:>4}  {r['first_frame_s']['p50']:>13.3f} s  "
                     f"{r['first_frame_s']['p95']:>6.3f}  {r['complete_s']['p50']:>10.3f} s  "
                     f"{r['complete_s']['p95']:>6.3f}")
    return "\n".join(lines)
