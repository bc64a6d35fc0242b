"""Scale-out, with real processes on 127.0.0.1:

- SQLite, `interplay serve --workers 2` (the issue: 30 % of streams closed 4404): every stream,
  whichever process it lands on, follows its job to the end;
- PostgreSQL (Debian's, started by tests/helpers/postgres.py) with procrastinate: 2 API
  processes + 2 `interplay worker` processes, 50 jobs, each stream opened on the other API
  process than the one that took the job; one worker is killed with `kill -9` in the middle of
  a job: an API process queues that job again (a `restart` event in its stream) and the other
  worker runs it to `done` (attempt 2); every job is done and its motion is stored (none
  lost), no stream is 4404, all of it in well under 90 s.

The workers use the small fake generator (INTERPLAY_GENERATOR_FACTORY): this is about the
queue, not the model; throughput with the real one is scripts/bench_workers.py.
"""

from __future__ import annotations

import signal
import sqlite3
import threading
import time
from contextlib import closing

import httpx
import psycopg

from tests.helpers.jobs import base_env, follow, start_server, start_worker


def _post(base: str, **body) -> dict:
    r = httpx.post(f"{base}/api/jobs", json={"prompt": "a person walks", **body}, timeout=30)
    assert r.status_code == 201, r.text
    return r.json()


def _follow_all(pairs: list[tuple[str, dict]]) -> dict[str, tuple[list[dict], int | None]]:
    """Follow every (base, job) stream at once; {job_id: (events, close code)}."""
    out: dict[str, tuple[list[dict], int | None]] = {}
    lock = threading.Lock()

    def one(base: str, job: dict) -> None:
        try:
            got = follow(base, job["stream"], timeout=60)
        except Exception as exc:    # recorded, asserted below
            got = ([{"type": "client-error", "message": repr(exc)}], None)
        with lock:
            out[job["job_id"]] = got
    threads = [threading.Thread(target=one, args=p) for p in pairs]
    for t in threads:
        t.start()
    for t in threads:
        t.join(120)
    return out


def test_streams_follow_jobs_across_uvicorn_workers_on_sqlite(tmp_path):
    env = base_env(tmp_path, INTERPLAY_TEST_CHUNK_DELAY_S="0.05", INTERPLAY_MAX_PENDING_JOBS="64")
    server, base = start_server(tmp_path, env, workers=2)
    try:
        jobs = [_post(base, seconds=1, seed=i) for i in range(16)]
        streams = _follow_all([(base, j) for j in jobs])
        for j in jobs:
            events, code = streams[j["job_id"]]
            assert code == 1000 and events[0]["type"] == "plan", (code, events[:1])
            done = {k: v for k, v in events[-1].items() if k not in ("digest", "frame_digests")}
            assert done == {"type": "done", "motion_id": j["motion_id"], "frames": 20}
            assert len(events[-1]["frame_digests"]) == 20      # what the page checks its copy by
            assert httpx.get(f"{base}/api/motions/{j['motion_id']}").status_code == 200
        with closing(sqlite3.connect(tmp_path / "jobs.db")) as conn:
            owners = {row[0] for row in conn.execute("SELECT owner FROM jobs")}
        assert len(owners) == 2            # both processes took jobs (and ran them)
    finally:
        server.stop()


def test_two_api_processes_two_workers_fifty_jobs_and_a_worker_killed(tmp_path, pg_url):
    t0 = time.monotonic()
    env = base_env(tmp_path, pg_url, INTERPLAY_TEST_CHUNK_DELAY_S="0.05",
                   INTERPLAY_MAX_PENDING_JOBS="64", INTERPLAY_JOB_STALE_S="20")
    workers = [start_worker(tmp_path, env, name=f"worker{i}") for i in range(2)]
    api = [start_server(tmp_path, env, name=f"api{i}") for i in range(2)]
    bases = [b for _, b in api]
    try:
        # A long job first (40 chunks), so that a worker is surely in the middle of one.
        jobs = [_post(bases[0], seconds=20, seed=0)]
        jobs += [_post(bases[i % 2], seconds=1 + (i % 3), seed=i) for i in range(1, 50)]
        took = {j["job_id"]: i % 2 for i, j in enumerate(jobs)}
        results: dict = {}
        listener = threading.Thread(target=lambda: results.update(_follow_all(
            [(bases[1 - took[j["job_id"]]], j) for j in jobs])))   # the other API process
        listener.start()
        victim = _kill_a_worker_mid_job(pg_url, workers)
        listener.join(120)
        assert not listener.is_alive()
        with psycopg.connect(pg_url) as conn:
            states = dict(conn.execute("SELECT id, state FROM jobs").fetchall())
            reasons = dict(conn.execute("SELECT id, reason FROM jobs").fetchall())
        assert victim in states and states[victim] == "done", reasons[victim]
        done = [j for j in jobs if states[j["job_id"]] == "done"]
        assert len(done) == 50, {s: list(states.values()).count(s) for s in set(states.values())}
        for j in jobs:
            events, code = results[j["job_id"]]
            assert code == 1000, (code, events[-1:])          # no 4404, no dropped stream
            assert events[0]["type"] == "plan"
            kinds = [e["type"] for e in events]
            assert events[-1]["type"] == "done", events[-1]
            assert events[-1]["motion_id"] == j["motion_id"]
            if j["job_id"] == victim:     # queued again by an API process, run by the other worker
                restart = events[kinds.index("restart")]
                assert restart["attempt"] == 2 and "stopped before it finished" in restart["reason"]
                assert kinds[kinds.index("restart") + 1] == "plan"
                status = httpx.get(f"{bases[1]}/api/jobs/{j['job_id']}").json()
                assert status["status"] == "done" and status["attempts"] == 2
            else:
                assert "restart" not in kinds
        for j in done:                                        # no completed motion lost
            r = httpx.get(f"{bases[hash(j['job_id']) % 2]}/api/motions/{j['motion_id']}")
            assert r.status_code == 200
        assert time.monotonic() - t0 < 90
    finally:
        for proc, _ in api:
            proc.stop()
        for w in workers:
            w.stop()


def _kill_a_worker_mid_job(pg_url: str, workers) -> str:
    """kill -9 the worker running a job that has streamed frames; that job's id."""
    pids = {w.pid: w for w in workers}
    deadline = time.monotonic() + 60
    with psycopg.connect(pg_url, autocommit=True) as conn:
        while time.monotonic() < deadline:
            row = conn.execute("SELECT id, worker FROM jobs WHERE state = 'running' AND events >= 4 "
                               "ORDER BY events DESC LIMIT 1").fetchone()
            if row is not None:
                job_id, worker = row
                pid = int(worker.split(":")[1])
                if pid in pids:
                    pids[pid].signal(signal.SIGKILL)
                    pids[pid].popen.wait(10)
                    return job_id
            time.sleep(0.02)
    raise AssertionError("no worker was seen in the middle of a job")
