"""POST /api/jobs and the WebSocket stream: validation, event order, late listeners, failures,
and that the stored motion is exactly what was streamed."""

from __future__ import annotations

import threading
import time

import numpy as np
import pytest
from fastapi.testclient import TestClient
from starlette.websockets import WebSocketDisconnect

from interplay.api import app as app_module
from interplay.api.app import create_app
from interplay.api.digest import frame_digests
from tests.helpers.api import FakeGenerator, run_job

BAD_JOBS = [
    ({"prompt": "", "persons": 1, "seconds": 3}, "prompt"),
    ({"prompt": "   \n ", "persons": 1, "seconds": 3}, "prompt"),
    ({"prompt": "a person walks " * 40, "persons": 1, "seconds": 3}, "500"),
    ({"persons": 1, "seconds": 3}, "prompt"),
    ({"prompt": 42, "persons": 1, "seconds": 3}, "prompt"),
    ({"prompt": "a person walks", "persons": 0, "seconds": 3}, "persons"),
    ({"prompt": "a person walks", "persons": 3, "seconds": 3}, "persons"),
    ({"prompt": "a person walks", "persons": "two", "seconds": 3}, "persons"),
    ({"prompt": "a person walks", "persons": 1, "seconds": 0.5}, "seconds"),
    ({"prompt": "a person walks", "persons": 1, "seconds": 20.5}, "seconds"),
    ({"prompt": "a person walks", "persons": 1, "seconds": "long"}, "seconds"),
    ({"prompt": "a person walks", "persons": 1, "seconds": 3, "seed": -1}, "seed"),
    ({"prompt": "a person walks", "persons": 1, "seconds": 3, "seed": 2**40}, "seed"),
    (["a person walks"], "object"),
]


@pytest.mark.parametrize("body,word", BAD_JOBS)
def test_bad_job_requests_get_a_readable_4xx(fake_client, body, word):
    r = fake_client.post("/api/jobs", json=body)
    assert r.status_code == 422, r.text
    detail = r.json()["detail"]
    assert isinstance(detail, str) and word in detail


@pytest.mark.parametrize("raw", [b"{not json", b"", b'{"prompt": "walk", "seconds": NaN}'])
def test_unparseable_bodies_are_4xx(fake_client, raw):
    r = fake_client.post("/api/jobs", content=raw, headers={"content-type": "application/json"})
    assert r.status_code == 422 and isinstance(r.json()["detail"], str), r.text


def _check_stream(job: dict, events: list[dict], persons: int, frames: int) -> list[np.ndarray]:
    """Assert the contract's event order and shapes; return the streamed frames per person."""
    kinds = [e["type"] for e in events]
    assert kinds[0] == "plan" and kinds[-2:] == ["metrics", "done"], kinds
    assert {"frames", "highlights"} <= set(kinds[1:-2]) <= {"frames", "highlights", "segment",
                                                         "review", "correction", "replace"}
    segments = events[0]["plan"]["segments"]
    assert segments and all({"prompt", "start", "end", "persons"} <= set(s) for s in segments)
    streamed = np.full((persons, frames, 22, 3), np.nan)
    pairs = [(ev, events[i + 1]) for i, ev in enumerate(events) if ev["type"] in ("frames", "replace")]
    for ev, nxt in pairs:   # a replace event (a corrected segment) replaces those frames
        assert nxt["type"] == "highlights"
        assert len(ev["people"]) == persons and ev.get("total", frames) == frames
        arr = np.asarray(ev["people"], dtype=np.float64)
        n = arr.shape[1]
        assert arr.shape[2:] == (22, 3)
        streamed[:, ev["start"]:ev["start"] + n] = arr
        assert nxt["start"] == ev["start"]
        assert len(nxt["contacts"]) == len(nxt["penetration"]) == n
        if persons == 1:
            assert nxt["min_distance"] is None
        else:
            assert len(nxt["min_distance"]) == n
    assert not np.isnan(streamed).any(), "every frame is streamed"
    done = events[-1]
    assert {k: v for k, v in done.items() if "digest" not in k} == {
        "type": "done", "motion_id": job["motion_id"], "frames": frames}
    assert done["frame_digests"] == frame_digests(streamed)   # the stored frames' digests
    return list(streamed)


CONTRACT_METRICS = {"bone_deviation", "foot_skating", "ground_penetration", "floating",
                    "com_distance", "com_angle"}
PAIR_METRICS = {"intersection_volume", "intersection_frequency", "contact_frames", "min_distance"}


@pytest.mark.parametrize("persons,prompt", [(1, "a person walks forward, then jumps"),
                                            (2, "two people dance salsa")])
def test_job_streams_plan_frames_metrics_done_and_stores_what_it_streamed(real_client, persons,
                                                                          prompt):
    job, events = run_job(real_client, prompt=prompt, persons=persons, seconds=6, seed=3)
    streamed = _check_stream(job, events, persons, frames=120)
    segments = events[0]["plan"]["segments"]
    assert job["seed"] == 3 and job["stream"] == f"/api/jobs/{job['job_id']}/stream"
    assert len(events[0]["plan"]["segments"]) == (2 if persons == 1 else 1)
    assert len([e for e in events if e["type"] == "frames"]) >= 3   # streamed in chunks
    metrics = events[-2]["metrics"]
    assert CONTRACT_METRICS <= set(metrics) and (PAIR_METRICS <= set(metrics)) == (persons == 2)
    # Real captures: people stand on the floor at human height.
    for s in streamed:
        assert 0.6 < np.median(s[:, 0, 1]) < 1.2 and abs(s[..., 1].min()) < 0.1
    r = real_client.get(f"/api/motions/{job['motion_id']}")
    assert r.status_code == 200, r.text
    m = r.json()
    assert (m["prompt"], m["persons"], m["seconds"], m["seed"]) == (prompt, persons, 6.0, 3)
    assert m["fps"] == 20 and m["skeleton"] == "smpl22"
    for p, s in zip(m["people"], streamed):
        assert np.array_equal(np.asarray(p["joints"]), s)   # same rounding both ways: exact
    # The stored plan is the streamed one unless a review re-drew a segment's captures.
    same = [{k: s[k] for k in ("index", "prompt", "start", "end")} for s in m["plan"]["segments"]]
    assert same == [{k: s[k] for k in ("index", "prompt", "start", "end")} for s in segments]
    assert m["metrics"] == events[-2]["metrics"]
    contacts, penetration = [None] * 120, [None] * 120
    for e in (e for e in events if e["type"] == "highlights"):
        n = len(e["contacts"])
        contacts[e["start"]:e["start"] + n] = e["contacts"]
        penetration[e["start"]:e["start"] + n] = e["penetration"]
    assert m["highlights"]["contacts"] == contacts
    assert m["highlights"]["penetration"] == penetration
    status = real_client.get(f"/api/jobs/{job['job_id']}").json()
    assert status["status"] == "done" and status["events"] == len(events)


def test_omitted_seed_is_drawn_and_stored(real_client):
    job, events = run_job(real_client, prompt="a person jumps", seconds=1)
    assert events[-1]["type"] == "done" and events[0]["plan"]["seed"] == job["seed"]
    assert real_client.get(f"/api/motions/{job['motion_id']}").json()["seed"] == job["seed"]


def _wait_finished(client, job_id: str, timeout: float = 30.0) -> str:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        status = client.get(f"/api/jobs/{job_id}").json()["status"]
        if status in ("done", "failed", "cancelled"):
            return status
        time.sleep(0.02)
    raise AssertionError("job did not finish")


def test_late_and_repeated_listeners_replay_every_event(real_client):
    job = real_client.post("/api/jobs", json={"prompt": "a person runs", "seconds": 2}).json()
    assert _wait_finished(real_client, job["job_id"]) == "done"
    replays = []
    for _ in range(2):
        with real_client.websocket_connect(job["stream"]) as ws:
            events = [ws.receive_json()]
            while events[-1]["type"] != "done":
                events.append(ws.receive_json())
            with pytest.raises(WebSocketDisconnect):   # the server closes after done
                ws.receive_json()
        replays.append(events)
    assert replays[0] == replays[1]
    _check_stream(job, replays[0], 1, frames=40)


def test_failed_generation_sends_error_and_stores_nothing(settings):
    with TestClient(create_app(settings, generator=FakeGenerator(fail_after=1))) as client:
        job, events = run_job(client, prompt="a person walks", seconds=3)
        assert [e["type"] for e in events if e["type"] != "segment"][:2] == ["plan", "frames"]
        assert events[-1]["type"] == "error" and "broke on purpose" in events[-1]["message"]
        assert events[-1]["stage"] == "generate"
        status = client.get(f"/api/jobs/{job['job_id']}").json()
        assert status["status"] == "failed" and "broke on purpose" in status["reason"]
        # The motion id says its job failed, and why (not the 404 of "not done yet").
        r = client.get(f"/api/motions/{job['motion_id']}")
        assert r.status_code == 409 and "broke on purpose" in r.json()["detail"], r.text


@pytest.mark.parametrize("job_id", ["unknownjobidunknownjob", "x", "a" * 200])
def test_unknown_job_stream_and_status(fake_client, job_id):
    with fake_client.websocket_connect(f"/api/jobs/{job_id}/stream") as ws:
        event = ws.receive_json()
        assert event["type"] == "error" and "no job" in event["message"]
        with pytest.raises(WebSocketDisconnect) as exc:
            ws.receive_json()
        assert exc.value.code == 4404
    r = fake_client.get(f"/api/jobs/{job_id}")
    assert r.status_code == 404 and "no job" in r.json()["detail"]


class BlockingGenerator(FakeGenerator):
    """Holds every job in `stream` until released, to fill the queue."""

    def __init__(self):
        super().__init__()
        self.release = threading.Event()

    def stream(self, req, plan):
        self.release.wait(10)
        yield from super().stream(req, plan)


def test_full_queue_answers_429_and_the_loop_stays_free(settings):
    gen = BlockingGenerator()
    with TestClient(create_app(settings.model_copy(update={"max_pending_jobs": 2}),
                               generator=gen)) as client:
        body = {"prompt": "a person walks", "seconds": 1}
        jobs = [client.post("/api/jobs", json=body) for _ in range(2)]
        assert all(r.status_code == 201 for r in jobs)
        # While a worker thread is busy generating, the event loop still answers.
        assert client.get("/api/skeleton").status_code == 200
        r = client.post("/api/jobs", json=body)
        assert r.status_code == 429 and "waiting" in r.json()["detail"]
        gen.release.set()
        assert all(_wait_finished(client, j.json()["job_id"]) == "done" for j in jobs)


def test_generator_that_cannot_load_gives_503_not_500(settings, monkeypatch):
    def broken(_settings):
        raise FileNotFoundError("weights missing")
    monkeypatch.setattr(app_module, "_load_generator", broken)
    with TestClient(create_app(settings)) as client:
        r = client.post("/api/jobs", json={"prompt": "a person walks", "seconds": 2})
        assert r.status_code == 503 and "weights missing" in r.json()["detail"]
        # Bad input is still told apart from the missing generator.
        r = client.post("/api/jobs", json={"prompt": "", "seconds": 2})
        assert r.status_code == 422 and "prompt" in r.json()["detail"]
        assert client.get("/api/skeleton").status_code == 200


def test_a_listener_leaving_early_does_not_stop_the_job(settings):
    gen = BlockingGenerator()
    with TestClient(create_app(settings, generator=gen)) as client:
        job = client.post("/api/jobs", json={"prompt": "a person walks", "seconds": 2}).json()
        with client.websocket_connect(job["stream"]) as ws:
            assert ws.receive_json()["type"] == "plan"
        gen.release.set()
        assert _wait_finished(client, job["job_id"]) == "done"
        assert client.get(f"/api/motions/{job['motion_id']}").json()["people"][0]["joints"]
