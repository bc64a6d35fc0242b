"""The react job: a reactor streamed frame by frame next to a stored actor, stored as a new
two-person motion whose parent is the actor's motion."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.motion.skeleton import bone_lengths
from interplay.reaction.session import WEIGHTS_DIR
from tests.helpers.api import run_job

needs_weights = pytest.mark.skipif(not (WEIGHTS_DIR / "arflow.onnx").exists(),
                                   reason="no ARFlow weights")


@needs_weights
def test_react_job_streams_and_stores_the_pair(fake_client):
    actor_job, events = run_job(fake_client, prompt="a person walks", persons=1, seconds=2,
                                seed=3)
    assert events[-1]["type"] == "done"
    actor_id = actor_job["motion_id"]
    job, events = run_job(fake_client, prompt="shake hands", mode="react",
                          actor_motion_id=actor_id, seed=5)
    kinds = [e["type"] for e in events]
    assert kinds[0] == "plan" and kinds[-2:] == ["metrics", "done"], kinds
    assert events[0]["plan"]["mode"] == "react" and events[0]["plan"]["actor_motion_id"] == actor_id
    segs = [e for e in events if e["type"] == "segment"]
    assert [s["status"] for s in segs] == ["generating", "done"]
    frames = [e for e in events if e["type"] == "frames"]
    assert len(frames) > 1 and all(len(e["people"]) == 2 for e in frames)
    assert [e["start"] for e in frames] == sorted(e["start"] for e in frames)
    streamed = np.concatenate([np.asarray(e["people"][1]) for e in frames])

    stored = fake_client.get(f"/api/motions/{job['motion_id']}").json()
    actor = fake_client.get(f"/api/motions/{actor_id}").json()
    assert stored["parent_id"] == actor_id
    people = [np.asarray(p["joints"]) for p in stored["people"]]
    assert len(people) == 2 and people[1].shape == np.asarray(actor["people"][0]["joints"]).shape
    np.testing.assert_allclose(people[0], actor["people"][0]["joints"], atol=1e-4)
    np.testing.assert_allclose(people[1], streamed, atol=1e-4)
    # The reactor keeps its bone lengths (to the 0.1 mm the wire rounds to).
    assert np.ptp(bone_lengths(people[1]), axis=0).max() < 1e-3
    metrics = events[-2]["metrics"]
    assert 0.0 <= metrics["intersection_frequency"] <= 1.0


def test_react_needs_a_stored_actor(fake_client):
    r = fake_client.post("/api/jobs", json={"prompt": "react", "mode": "react",
                                            "actor_motion_id": "nope-not-there"})
    assert r.status_code == 404
    r = fake_client.post("/api/jobs", json={"prompt": "react", "mode": "react"})
    assert r.status_code == 422 and "actor_motion_id" in r.json()["detail"]


def test_react_intent_is_optional_and_generate_still_needs_a_prompt(fake_client):
    """The intent of a react job is optional (the reactor follows the actor unprompted, the
    model was trained with text dropout); a generate job without a prompt is a readable 422."""
    actor_job, events = run_job(fake_client, prompt="a person walks", persons=1, seconds=1,
                                seed=3)
    assert events[-1]["type"] == "done"
    r = fake_client.post("/api/jobs", json={"mode": "react",
                                            "actor_motion_id": actor_job["motion_id"]})
    assert r.status_code == 201, r.text
    r = fake_client.post("/api/jobs", json={"persons": 1, "seconds": 2})
    assert r.status_code == 422 and "prompt" in r.json()["detail"], r.text
    r = fake_client.post("/api/jobs", json={"mode": "react", "prompt": "   ",
                                            "actor_motion_id": actor_job["motion_id"]})
    assert r.status_code == 422 and "prompt" in r.json()["detail"], r.text


@needs_weights
def test_react_job_without_an_intent_stores_the_pair(fake_client):
    actor_job, _ = run_job(fake_client, prompt="a person walks", persons=1, seconds=1, seed=3)
    job, events = run_job(fake_client, mode="react", actor_motion_id=actor_job["motion_id"],
                          seed=2)
    assert events[-1]["type"] == "done", events[-1]
    assert events[0]["plan"]["prompt"] is None
    stored = fake_client.get(f"/api/motions/{job['motion_id']}").json()
    assert stored["persons"] == 2 and stored["parent_id"] == actor_job["motion_id"]
    assert stored["edit"]["mode"] == "react" and stored["edit"]["prompt"] is None
