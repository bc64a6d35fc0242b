"""Job streams in the orders a page opens them (the real app, its real store): two jobs back to
back, a stream opened before its job starts (queued behind another), after its first events
were pushed, after its last one; and a job whose start fails before its runner (the database
refusing the claim) ends with an error event instead of leaving its stream waiting forever.

Why: path-draw's second Generate looked stuck in "connecting" in CI (6 Dec 2026). The cause was
the e2e helper (`waitDone` took the first job's "done", e2e/specs/studio.ts), not the server;
these pin down that the server side holds in each of those orders, and the one hole found by
reading (an exception in `JobManager._run` was lost in its thread pool's future)."""

from __future__ import annotations

import threading
import time

import pytest
from fastapi.testclient import TestClient
from sqlalchemy.exc import OperationalError

from interplay.api.app import create_app
from tests.helpers.api import FakeGenerator

pytestmark = pytest.mark.timeout(120)   # a stream that never ends fails here, not the suite
BODY = {"prompt": "a person walks forward", "seconds": 1}


class GatedGenerator(FakeGenerator):
    """Job number i (in the order they start) stops in `stream`, after its plan event is out,
    until `gates[i]` is set; `started[i]` says it got there."""

    def __init__(self, jobs: int = 4):
        super().__init__()
        self.gates = [threading.Event() for _ in range(jobs)]
        self.started = [threading.Event() for _ in range(jobs)]
        self._n = 0

    def stream(self, req, plan):
        i, self._n = self._n, self._n + 1
        self.started[i].set()
        assert self.gates[i].wait(30), f"job {i} was never released"
        yield from super().stream(req, plan)


def _until_end(ws) -> list[dict]:
    """Every event of an open stream up to its done / error."""
    events = [ws.receive_json()]
    while events[-1]["type"] not in ("done", "error"):
        events.append(ws.receive_json())
    return events


def _status(client: TestClient, job_id: str, want: tuple[str, ...], timeout: float = 20.0) -> str:
    deadline = time.monotonic() + timeout
    status = ""
    while time.monotonic() < deadline:
        status = client.get(f"/api/jobs/{job_id}").json()["status"]
        if status in want:
            return status
        time.sleep(0.02)
    raise AssertionError(f"job {job_id} is still {status!r} after {timeout} s")


def _check(job: dict, events: list[dict]) -> None:
    """One whole stream of `job`: its own plan first, its own done last."""
    kinds = [e["type"] for e in events]
    assert kinds[0] == "plan" and kinds[-2:] == ["metrics", "done"], kinds
    assert "frames" in kinds
    assert events[-1]["motion_id"] == job["motion_id"]


@pytest.fixture
def gated(settings):
    gen = GatedGenerator()
    with TestClient(create_app(settings, generator=gen)) as client:
        yield client, gen
        for gate in gen.gates:      # nothing left waiting when the app shuts down
            gate.set()


def test_two_jobs_back_to_back_each_stream_gets_its_own_events(gated):
    client, gen = gated
    # A: its plan is pushed before the page subscribes (the stream replays it)
    a = client.post("/api/jobs", json=BODY).json()
    assert gen.started[0].wait(10)
    with client.websocket_connect(a["stream"]) as ws_a:
        first = ws_a.receive_json()
        assert first["type"] == "plan"
        gen.gates[0].set()
        events_a = [first] + _until_end(ws_a)
    _check(a, events_a)
    # B: posted as soon as A is done, subscribed before it streams anything but its plan
    b = client.post("/api/jobs", json={**BODY, "prompt": "a person walks forward slowly"}).json()
    with client.websocket_connect(b["stream"]) as ws_b:
        assert gen.started[1].wait(10)
        gen.gates[1].set()
        events_b = _until_end(ws_b)
    _check(b, events_b)
    assert events_b[0]["plan"]["prompt"] == "a person walks forward slowly"
    # subscribing after the last event: the whole stream again, then closed
    for job, events in ((a, events_a), (b, events_b)):
        with client.websocket_connect(job["stream"]) as ws:
            assert _until_end(ws) == events


def test_a_stream_opened_while_its_job_waits_behind_another_follows_it(gated):
    client, gen = gated
    a = client.post("/api/jobs", json=BODY).json()
    assert gen.started[0].wait(10)
    b = client.post("/api/jobs", json=BODY).json()     # queued: one worker, A holds it
    assert client.get(f"/api/jobs/{b['job_id']}").json()["status"] == "queued"
    with client.websocket_connect(b["stream"]) as ws_b, \
            client.websocket_connect(a["stream"]) as ws_a:
        gen.gates[0].set()
        gen.gates[1].set()
        events_a, events_b = _until_end(ws_a), _until_end(ws_b)
    _check(a, events_a)
    _check(b, events_b)


def test_a_job_whose_start_fails_ends_with_an_error_event_and_the_next_one_runs(gated,
                                                                                  monkeypatch):
    client, gen = gated
    jobs = client.app.state.jobs
    claim = jobs.store.claim
    calls = []

    def locked_once(job_id, worker):
        calls.append(job_id)
        if len(calls) == 1:      # as SQLite says when another writer holds it past the timeout
            raise OperationalError("UPDATE jobs SET state=…", {}, Exception("database is locked"))
        return claim(job_id, worker)

    monkeypatch.setattr(jobs.store, "claim", locked_once)
    a = client.post("/api/jobs", json=BODY).json()
    # Before the fix the exception was lost in the pool's future: A stayed queued, with no
    # event, and its stream waited for ever.
    assert _status(client, a["job_id"], ("failed", "done", "cancelled")) == "failed"
    with client.websocket_connect(a["stream"]) as ws:
        events = _until_end(ws)
    assert [e["type"] for e in events] == ["error"]
    assert "database is locked" in events[0]["message"]
    assert "database is locked" in client.get(f"/api/jobs/{a['job_id']}").json()["reason"]
    # the worker thread is free: the next job runs to its end
    b = client.post("/api/jobs", json=BODY).json()
    gen.gates[0].set()
    with client.websocket_connect(b["stream"]) as ws:
        _check(b, _until_end(ws))
