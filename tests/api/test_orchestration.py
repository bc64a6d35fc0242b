"""Jobs as CoMA's Algorithm 1 through the HTTP API: segment / review / correction events in
the agreed shapes, the review history stored with the motion, a drawn path followed, stage
errors, cancellation, and the request validation of the extensions (4xx, never 500)."""

from __future__ import annotations

import threading
import time

import numpy as np
import pytest
from fastapi.testclient import TestClient

from interplay.api.app import create_app
from tests.helpers.api import FakeGenerator, run_job

PARTS = {"body", "left_upper", "right_upper", "left_lower", "right_lower"}


def test_job_events_follow_algorithm_1_and_the_review_is_stored(real_client):
    job, events = run_job(real_client, prompt="a person walks forward, then jumps", seconds=6,
                          seed=3)
    assert events[-1]["type"] == "done", events[-1]
    segments = events[0]["plan"]["segments"]
    seg_events = [e for e in events if e["type"] == "segment"]
    assert [(e["index"], e["status"]) for e in seg_events] == [
        (s["index"], st) for s in segments for st in ("generating", "done")]
    assert all(e["generator"] == events[0]["plan"]["generator"] for e in seg_events)
    reviews = [e for e in events if e["type"] == "review"]
    assert {r["segment"] for r in reviews} == {s["index"] for s in segments}
    for r in reviews:
        assert set(r["captions"]) == PARTS and all(isinstance(t, str) for t in r["captions"].values())
        assert isinstance(r["score"], float) and -1 <= r["score"] <= 1
        assert r["verdict"] in ("ok", "correct", "failed", "not_covered", "unconfirmed")
        assert (r["verdict"] == "ok") == (not r["instructions"] and r["verdict"] not in
                                          ("not_covered", "unconfirmed"))
        if r["verdict"] == "failed":      # it says why
            assert r["checks"]["failed"] or r["instructions"]
        assert {"metrics", "failed", "windows"} <= set(r["checks"])
        for i in r["instructions"]:
            assert i["kind"] in ("edit_part", "inbetween", "regenerate") and i["reason"]
    # Every segment is reviewed after its frames and before it is done.
    order = [(e["type"], e.get("segment", e.get("index"))) for e in events
             if e["type"] in ("segment", "review")]
    for s in segments:
        i = s["index"]
        assert order.index(("segment", i)) < order.index(("review", i))
    for c in (e for e in events if e["type"] == "correction"):
        assert {"segment", "round", "instruction", "accepted", "score_before", "score_after"} <= set(c)
        assert c["round"] >= 1 and isinstance(c["accepted"], bool)
    m = real_client.get(f"/api/motions/{job['motion_id']}").json()
    assert m["edit"] is None and m["parent_id"] is None
    stored = m["review"]
    assert stored["rounds"] == 2 and stored["score_kind"] in ("evaluator", "caption_agreement")
    assert [s["segment"] for s in stored["segments"]] == [s["index"] for s in segments]
    first = [s["reviews"][0] for s in stored["segments"]]
    assert [r["score"] for r in first] == [r["score"] for r in reviews if r["round"] == 0]


def _distance_to_polyline(p: np.ndarray, pts: np.ndarray) -> np.ndarray:
    a, b = pts[:-1], pts[1:]
    ab = b - a
    t = np.clip(((p[:, None] - a) * ab).sum(-1) / (ab ** 2).sum(-1), 0, 1)
    closest = a + t[..., None] * ab
    return np.linalg.norm(p[:, None] - closest, axis=-1).min(axis=1)


def test_a_drawn_path_is_followed_and_stored_with_the_plan(real_client):
    pts = [[0.0, 0.0], [0.0, 2.0], [2.0, 4.0], [4.0, 4.0]]
    job, events = run_job(real_client, prompt="a person walks forward", seconds=6, seed=1,
                          trajectory={"person": 0, "points": pts})
    assert events[-1]["type"] == "done", events[-1]
    m = real_client.get(f"/api/motions/{job['motion_id']}").json()
    pelvis = np.asarray(m["people"][0]["joints"])[:, 0][:, [0, 2]]
    # The drawing keeps its size: along it while the walk lasts (past its end, straight on
    # along its last direction, +x).
    curve = np.asarray(pts)
    walked = np.r_[0, np.cumsum(np.linalg.norm(np.diff(pelvis, axis=0), axis=1))]
    along = walked < np.linalg.norm(np.diff(curve, axis=0), axis=1).sum() - 0.5
    assert along.sum() > 60
    assert _distance_to_polyline(pelvis[along], curve).max() < 0.5
    beyond = pelvis[~along]
    assert len(beyond) == 0 or np.all(np.diff(beyond[:, 0]) > -0.02)
    assert m["plan"]["trajectory"] == {"person": 0, "points": pts}
    # The moved frames were streamed again (as replacements): applied in order, the frames and
    # replace events are what is stored.
    streamed = np.full((120, 22, 3), np.nan)
    assert {e["cause"] for e in events if e["type"] == "replace"} >= {"trajectory"}
    for e in (e for e in events if e["type"] in ("frames", "replace")):
        arr = np.asarray(e["people"][0])
        streamed[e["start"]:e["start"] + len(arr)] = arr
    assert np.array_equal(streamed, np.asarray(m["people"][0]["joints"]))


def test_a_failing_stage_is_named(settings):
    class NoPlan(FakeGenerator):
        def plan(self, req):
            raise RuntimeError("planner down")

    with TestClient(create_app(settings, generator=NoPlan())) as client:
        job, events = run_job(client, prompt="a person walks", seconds=2)
        assert events[-1]["type"] == "error" and events[-1]["stage"] == "plan"
        assert "planner down" in events[-1]["message"]


class HeldGenerator(FakeGenerator):
    """Waits for `release` before each chunk."""

    def __init__(self):
        super().__init__(chunk=10)
        self.release = threading.Event()

    def stream(self, req, plan):
        for item in super().stream(req, plan):
            self.release.wait(10)
            yield item


def test_delete_cancels_a_running_job(settings):
    gen = HeldGenerator()
    with TestClient(create_app(settings, generator=gen)) as client:
        job = client.post("/api/jobs", json={"prompt": "a person walks", "seconds": 4}).json()
        with client.websocket_connect(job["stream"]) as ws:
            assert ws.receive_json()["type"] == "plan"
            r = client.delete(f"/api/jobs/{job['job_id']}")
            assert r.status_code == 200 and r.json()["cancelled"] is True
            gen.release.set()
            events = [ws.receive_json()]
            while events[-1]["type"] not in ("done", "error"):
                events.append(ws.receive_json())
        assert events[-1] == {"type": "error", "message": "cancelled", "cancelled": True}
        for _ in range(100):
            if client.get(f"/api/jobs/{job['job_id']}").json()["status"] == "cancelled":
                break
            time.sleep(0.05)
        assert client.get(f"/api/jobs/{job['job_id']}").json()["status"] == "cancelled"
        r = client.get(f"/api/motions/{job['motion_id']}")
        assert r.status_code == 409 and "cancelled" in r.json()["detail"]


def test_delete_unknown_job_is_404(fake_client):
    r = fake_client.delete("/api/jobs/unknownjobidunknownjob")
    assert r.status_code == 404 and "no job" in r.json()["detail"]


@pytest.mark.parametrize("extra,word", [
    ({"trajectory": {"person": 0}}, "points or shape"),
    ({"trajectory": {"person": 0, "points": [[0, 0]]}}, "points"),
    ({"trajectory": {"person": 0, "points": [[0, 0], [0, 0]]}}, "same"),
    ({"trajectory": {"person": 0, "points": [[0, 0], [1e6, 0]]}}, "within"),
    ({"trajectory": {"person": 0, "shape": "pentagon"}}, "shape"),
    ({"trajectory": {"person": 0, "shape": "circle", "size_m": -1}}, "size_m"),
    ({"trajectory": {"person": 0, "points": [[0, 0], [1, 1]], "shape": "line"}}, "points or shape"),
    ({"trajectory": {"person": 1, "shape": "circle"}}, "person 1"),
    ({"trajectory": {"person": 2, "shape": "circle"}}, "person"),
    ({"mode": "react"}, "actor_motion_id"),
    ({"mode": "dance"}, "mode"),
    ({"actor_motion_id": "GbOLvSrBj8d2ZVgyhbGUQA"}, "react"),
])
def test_bad_extensions_are_422(fake_client, extra, word):
    r = fake_client.post("/api/jobs", json={"prompt": "a person walks", "seconds": 2, **extra})
    assert r.status_code == 422, r.text
    assert word in r.json()["detail"]


def test_react_with_an_unknown_actor_is_404(fake_client):
    r = fake_client.post("/api/jobs", json={"prompt": "the other person reacts", "persons": 2,
                                            "mode": "react",
                                            "actor_motion_id": "GbOLvSrBj8d2ZVgyhbGUQA"})
    assert r.status_code == 404 and "react" in r.json()["detail"]


def test_a_preset_shape_job_runs_with_the_fake_generator(fake_client):
    job, events = run_job(fake_client, prompt="a person walks", seconds=3, seed=2,
                          trajectory={"person": 0, "shape": "arc", "clockwise": True})
    assert events[-1]["type"] == "done", events[-1]
    m = fake_client.get(f"/api/motions/{job['motion_id']}").json()
    assert m["plan"]["trajectory"] == {"person": 0, "shape": "arc", "clockwise": True}
