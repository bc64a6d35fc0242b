"""Durable jobs, against real `interplay serve` processes on SQLite (the embedded default):

- a server killed with `kill -9` mid-job, then started again: the running job runs again from
  its start (a `restart` event in its stream) and its motion is stored; with no attempts left
  (INTERPLAY_JOB_MAX_ATTEMPTS) it is `failed` with the reason (not 404 forever), its stream
  replays what was streamed and ends with an error event saying why, its motion id answers 409
  with the reason; the job that was queued behind it runs after the restart;
- SIGTERM: a job that finishes within INTERPLAY_DRAIN_S is done, a longer one ends with an
  error event ("the server is shutting down") and close code 1000, not a bare 1012;
- edits go through the job queue: at most `job_workers` heavy edits run at once, and beyond
  `max_pending_jobs` waiting jobs an edit gets 429 with Retry-After, as a job does.
"""

from __future__ import annotations

import json
import signal
import threading
import time

import httpx
import numpy as np
from fastapi.testclient import TestClient
from websockets.sync.client import connect

from interplay.api.app import create_app
from interplay.motion.skeleton import rest_joints
from tests.helpers.jobs import EditingGenerator, base_env, follow, start_server, wait_status


def _post(base: str, **body) -> dict:
    r = httpx.post(f"{base}/api/jobs", json={"prompt": "a person walks", **body}, timeout=20)
    assert r.status_code == 201, r.text
    return r.json()


def _read_until(ws, kind: str) -> list[dict]:
    events: list[dict] = []
    while not events or events[-1]["type"] != kind:
        events.append(json.loads(ws.recv(timeout=30)))
        assert events[-1]["type"] not in ("done", "error"), events[-1]
    return events


def test_a_restart_runs_the_running_job_again_from_its_start_and_it_is_stored(tmp_path):
    """Issue 26.2: the job a killed server was running is queued again when a server starts
    (attempt 2): its stored stream is what the dead attempt streamed, a `restart` event, then
    the new attempt from its plan to `done`; the motion is stored, the same as the same
    request (seed included) made in one go."""
    env = base_env(tmp_path, INTERPLAY_TEST_CHUNK_DELAY_S="0.2")
    server, base = start_server(tmp_path, env, name="first")
    try:
        running = _post(base, seconds=6, seed=1)
        with connect(base.replace("http", "ws") + running["stream"], max_size=None) as ws:
            before = _read_until(ws, "frames")
        time.sleep(0.3)                                 # the writer batches every 50 ms
        server.signal(signal.SIGKILL)
        server.popen.wait(10)
    finally:
        server.stop()
    server, base = start_server(tmp_path, env, name="second")
    try:
        status = wait_status(base, running["job_id"], ("done", "failed"))
        assert status["status"] == "done" and status["attempts"] == 2 and status["reason"] is None
        again = httpx.get(f"{base}/api/motions/{running['motion_id']}").json()
        fresh = _post(base, seconds=6, seed=1)
        wait_status(base, fresh["job_id"], ("done",))
        want = httpx.get(f"{base}/api/motions/{fresh['motion_id']}").json()
        assert again["people"] == want["people"]
    finally:
        server.stop()
    # Once the process that ran it is gone too, the stream comes from the database: the dead
    # attempt's events, the restart, the new attempt.
    server, base = start_server(tmp_path, env, name="third")
    try:
        events, code = follow(base, running["stream"])
        kinds = [e["type"] for e in events]
        assert code == 1000 and events[:len(before)] == before and kinds.count("restart") == 1
        restart = events[kinds.index("restart")]
        assert restart["attempt"] == 2 and "stopped before it finished" in restart["reason"]
        assert kinds[kinds.index("restart") + 1] == "plan" and kinds[-1] == "done"
        assert "done" not in kinds[:kinds.index("restart")]
    finally:
        server.stop()


def test_a_job_out_of_attempts_fails_with_a_reason_and_the_queued_one_runs(tmp_path):
    env = base_env(tmp_path, INTERPLAY_TEST_CHUNK_DELAY_S="0.25", INTERPLAY_JOB_MAX_ATTEMPTS="1")
    server, base = start_server(tmp_path, env, name="first")
    try:
        running = _post(base, seconds=8, seed=1)        # 16 chunks × 0.25 s
        queued = _post(base, seconds=1, seed=2)         # behind it (one worker thread)
        with connect(base.replace("http", "ws") + running["stream"], max_size=None) as ws:
            before = _read_until(ws, "frames")
        time.sleep(0.3)                                 # the writer batches every 50 ms
        server.signal(signal.SIGKILL)
        server.popen.wait(10)
    finally:
        server.stop()
    server, base = start_server(tmp_path, env, name="second")
    try:
        status = wait_status(base, running["job_id"], ("failed",))
        assert "stopped before it finished" in status["reason"] and status["attempts"] == 1
        events, code = follow(base, running["stream"])
        assert code == 1000 and events[:len(before)] == before     # replayed from the start
        assert events[-1]["type"] == "error" and "stopped" in events[-1]["message"]
        assert events[-1]["stage"] == "worker"
        r = httpx.get(f"{base}/api/motions/{running['motion_id']}")
        assert r.status_code == 409 and "stopped before it finished" in r.json()["detail"]
        # The job that had not started is run by the new process.
        assert wait_status(base, queued["job_id"], ("done",))["status"] == "done"
        events, code = follow(base, queued["stream"])
        assert events[0]["type"] == "plan" and events[-1]["type"] == "done" and code == 1000
        assert httpx.get(f"{base}/api/motions/{queued['motion_id']}").status_code == 200
        # Unknown stays unknown, not-done-yet is told apart.
        assert "unknown" in httpx.get(f"{base}/api/motions/{'A' * 22}").json()["detail"]
    finally:
        server.stop()


def test_sigterm_drains_short_jobs_and_fails_long_ones_with_an_error_event(tmp_path):
    env = base_env(tmp_path, INTERPLAY_TEST_CHUNK_DELAY_S="0.25", INTERPLAY_DRAIN_S="5",
                   INTERPLAY_JOB_WORKERS="2")
    server, base = start_server(tmp_path, env, name="first")
    got: dict[str, tuple[list[dict], int | None]] = {}
    try:
        long = _post(base, seconds=20, seed=1)          # 40 chunks × 0.25 s: outlasts the drain
        short = _post(base, seconds=1, seed=2)          # 2 chunks: done within it
        ready = threading.Barrier(3)

        def listen(name: str, job: dict) -> None:
            with connect(base.replace("http", "ws") + job["stream"], max_size=None) as ws:
                events = [json.loads(ws.recv(timeout=30))]
                ready.wait(30)
                try:
                    while events[-1]["type"] not in ("done", "error"):
                        events.append(json.loads(ws.recv(timeout=30)))
                    ws.recv(timeout=10)
                except Exception:
                    pass
                got[name] = (events, ws.close_code)
        threads = [threading.Thread(target=listen, args=a) for a in (("long", long),
                                                                      ("short", short))]
        for t in threads:
            t.start()
        ready.wait(30)
        server.signal(signal.SIGTERM)
        for t in threads:
            t.join(30)
        server.popen.wait(30)
    finally:
        server.stop()
    events, code = got["long"]
    assert events[-1] == {"type": "error", "message": "the server is shutting down"}, events[-3:]
    assert code == 1000
    events, code = got["short"]
    assert events[-1]["type"] == "done" and code == 1000, events[-1]
    server, base = start_server(tmp_path, env, name="second")
    try:
        status = httpx.get(f"{base}/api/jobs/{long['job_id']}").json()
        assert status["status"] == "failed" and "shutting down" in status["reason"]
        r = httpx.get(f"{base}/api/motions/{long['motion_id']}")
        assert r.status_code == 409 and "shutting down" in r.json()["detail"]
        assert httpx.get(f"{base}/api/motions/{short['motion_id']}").status_code == 200
    finally:
        server.stop()


def _stored(client) -> str:
    joints = np.repeat(rest_joints()[None], 40, axis=0)
    return client.app.state.repo.create(prompt="a person stands", people=[joints],
                                        seconds=2.0).id


def test_edits_wait_in_the_job_queue_and_its_limit_holds(settings):
    gen = EditingGenerator(delay=0.4)
    capped = settings.model_copy(update={"max_pending_jobs": 3, "job_workers": 1})
    with TestClient(create_app(capped, generator=gen)) as client:
        mid = _stored(client)
        answers: list[httpx.Response] = []
        lock = threading.Lock()

        def edit(i: int) -> None:
            r = client.post(f"/api/motions/{mid}/edit",
                            json={"part": "left_arm", "prompt": "raises the left arm", "seed": i})
            with lock:
                answers.append(r)
        threads = [threading.Thread(target=edit, args=(i,)) for i in range(8)]
        for t in threads:
            t.start()
        for t in threads:
            t.join(60)
        codes = sorted(r.status_code for r in answers)
        assert set(codes) <= {201, 429} and codes.count(201) >= 3 and 429 in codes, codes
        assert gen.most == 1                          # one worker thread: one heavy edit at once
        for r in answers:
            if r.status_code == 429:
                assert "waiting" in r.json()["detail"] and int(r.headers["Retry-After"]) >= 1
            else:
                m = r.json()
                assert m["parent_id"] == mid and m["plan"]["edits"][-1]["part"] == "left_arm"
                assert client.get(f"/api/motions/{m['id']}").status_code == 200


def test_jobs_and_edits_share_one_queue(settings):
    from tests.api.test_jobs import BlockingGenerator

    class Both(BlockingGenerator, EditingGenerator):
        def __init__(self):
            EditingGenerator.__init__(self, delay=0.0)
            self.release = threading.Event()
    gen = Both()
    with TestClient(create_app(settings.model_copy(update={"max_pending_jobs": 2}),
                               generator=gen)) as client:
        mid = _stored(client)
        jobs = [client.post("/api/jobs", json={"prompt": "a person walks", "seconds": 1})
                for _ in range(2)]
        assert [r.status_code for r in jobs] == [201, 201]
        r = client.post(f"/api/motions/{mid}/edit", json={"prompt": "raises the left arm"})
        assert r.status_code == 429 and r.headers["Retry-After"].isdigit()
        r = client.post("/api/jobs", json={"prompt": "a person walks", "seconds": 1})
        assert r.status_code == 429 and r.headers["Retry-After"].isdigit()
        gen.release.set()
        for j in jobs:
            deadline = time.monotonic() + 30
            while client.get(f"/api/jobs/{j.json()['job_id']}").json()["status"] != "done":
                assert time.monotonic() < deadline
                time.sleep(0.05)
        r = client.post(f"/api/motions/{mid}/edit", json={"prompt": "raises the left arm"})
        assert r.status_code == 201, r.text


def test_segment_reruns_share_the_job_queue(settings):
    """A segment re-run is a job too: with the queue full it answers 429 with Retry-After
    (it used to run in the request thread, outside every limit)."""
    from tests.api.test_jobs import BlockingGenerator

    gen = BlockingGenerator()
    with TestClient(create_app(settings.model_copy(update={"max_pending_jobs": 2}),
                               generator=gen)) as client:
        joints = np.repeat(rest_joints()[None], 40, axis=0)
        plan = {"segments": [{"index": 0, "start": 0, "end": 20, "prompt": "a person stands"},
                             {"index": 1, "start": 20, "end": 40, "prompt": "a person waves"}]}
        mid = client.app.state.repo.create(prompt="a person stands, then waves", people=[joints],
                                           seconds=2.0, plan=plan).id
        jobs = [client.post("/api/jobs", json={"prompt": "a person walks", "seconds": 1})
                for _ in range(2)]
        assert [r.status_code for r in jobs] == [201, 201]
        r = client.post(f"/api/motions/{mid}/segments/1/rerun", json={"seed": 3})
        assert r.status_code == 429 and r.headers["Retry-After"].isdigit(), r.text
        gen.release.set()
        for j in jobs:
            deadline = time.monotonic() + 30
            while client.get(f"/api/jobs/{j.json()['job_id']}").json()["status"] != "done":
                assert time.monotonic() < deadline
                time.sleep(0.05)
