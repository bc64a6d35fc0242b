"""Job throughput with 1 and with 2 `interplay worker` processes, the real generator (the models
in models/weights), on a throw-away PostgreSQL (scripts/postgres.sh):

    .venv/bin/python scripts/bench_workers.py [--jobs 12] [--seconds 6] [--persons 1] [--workers 1 2]

For each worker count: one `interplay serve` process and N workers on an empty database; once
the workers are up, `--jobs` jobs are posted at once and every stream is followed to `done`.
Reported: jobs per minute (first POST to last done), and the p50 / p95 seconds from POST to
done. Run from the repository root.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import httpx  # noqa: E402
import numpy as np  # noqa: E402
import psycopg  # noqa: E402

from tests.helpers.jobs import base_env, follow, start_server, start_worker  # noqa: E402
from tests.helpers.postgres import reset  # noqa: E402

PROMPTS = {1: ["a person walks forward", "a person jogs in a circle", "a person jumps, then squats"],
           2: ["two people dance salsa", "two people shake hands", "two people walk side by side"]}


def wait_workers(url: str, n: int, timeout: float = 300.0) -> None:
    deadline = time.monotonic() + timeout
    with psycopg.connect(url, autocommit=True) as conn:
        while time.monotonic() < deadline:
            try:
                if conn.execute("SELECT count(*) FROM procrastinate_workers").fetchone()[0] >= n:
                    return
            except psycopg.errors.UndefinedTable:
                pass
            time.sleep(0.2)
    raise RuntimeError("the workers did not start")


def run(url: str, tmp: Path, workers: int, jobs: int, seconds: float, persons: int) -> dict:
    reset(url)
    env = base_env(tmp, url, INTERPLAY_MAX_PENDING_JOBS=str(max(16, jobs)))
    env.pop("INTERPLAY_GENERATOR_FACTORY")          # the real models
    server, base = start_server(tmp, env, name=f"api-{workers}")
    procs = [start_worker(tmp, env, name=f"worker-{workers}-{i}") for i in range(workers)]
    try:
        wait_workers(url, workers)
        time.sleep(2.0)                              # let the workers finish loading
        done: dict[int, float] = {}
        t0 = time.perf_counter()
        posted = []
        for i in range(jobs):
            r = httpx.post(f"{base}/api/jobs", json={"prompt": PROMPTS[persons][i % 3],
                                                     "persons": persons, "seconds": seconds,
                                                     "seed": i}, timeout=60)
            r.raise_for_status()
            posted.append((i, r.json(), time.perf_counter()))

        def one(i: int, job: dict, at: float) -> None:
            events, _ = follow(base, job["stream"], timeout=600)
            if events[-1]["type"] != "done":
                raise RuntimeError(f"job failed: {events[-1]}")
            done[i] = time.perf_counter() - at
        threads = [threading.Thread(target=one, args=p) for p in posted]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        wall = time.perf_counter() - t0
        lat = list(done.values())
        return {"workers": workers, "jobs": jobs, "completed": len(done), "wall_s": round(wall, 2),
                "jobs_per_min": round(60 * len(done) / wall, 2),
                "latency_p50_s": round(float(np.percentile(lat, 50)), 2),
                "latency_p95_s": round(float(np.percentile(lat, 95)), 2)}
    finally:
        for p in procs:
            p.stop()
        server.stop()


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--jobs", type=int, default=12)
    ap.add_argument("--seconds", type=float, default=6.0)
    ap.add_argument("--persons", type=int, choices=(1, 2), default=1)
    ap.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args()
    start = subprocess.run(["sh", str(ROOT / "scripts" / "postgres.sh"), "start"],
                           capture_output=True, text=True, check=True)
    url, _, where = start.stdout.strip().splitlines()[-1].partition(" ")
    rows = []
    try:
        with tempfile.TemporaryDirectory(prefix="interplay-bench-workers-") as tmp:
            for n in args.workers:
                rows.append(run(url, Path(tmp), n, args.jobs, args.seconds, args.persons))
    finally:
        subprocess.run(["sh", str(ROOT / "scripts" / "postgres.sh"), "stop", where],
                       capture_output=True)
    load = os.getloadavg()
    if args.json:
        print(json.dumps({"rows": rows, "cpus": os.cpu_count(), "load": load}, indent=1))
    else:
        print(f"{args.jobs} jobs of {args.seconds:g} s, {args.persons} person(s); "
              f"{os.cpu_count()} CPUs, load {load[0]:.1f}")
        print(f"{'workers':>7}  {'jobs/min':>8}  {'wall':>7}  {'p50':>6}  {'p95':>6}")
        for r in rows:
            print(f"{r['workers']:>7}  {r['jobs_per_min']:>8.2f}  {r['wall_s']:>6.1f}s  "
                  f"{r['latency_p50_s']:>5.1f}s  {r['latency_p95_s']:>5.1f}s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
