"""POST /api/motions/{id}/segments/{index}/rerun: one planned segment generated again with a new
seed, in place — a new stored version (parent_id, edit, plan entry) of the same length whose
other segments' frames are exactly the parent's; listed in the client's "My motions"; 404 for
unknown motions, 422 for bad indices, seeds and motions without segments, 503 without a
generator. With the real generator (SPAM) too."""

from __future__ import annotations

import numpy as np
import pytest

from tests.helpers.api import run_job

PROMPT = "a person walks forward, then jumps, then sits down"
CLIENT = "rerun-client-0123456789"


def _three_segments(client) -> dict:
    job, events = run_job(client, prompt=PROMPT, persons=1, seconds=6, seed=5)
    assert events[-1]["type"] == "done", events[-1]
    motion = client.get(f"/api/motions/{job['motion_id']}").json()
    spans = [(s["start"], s["end"]) for s in motion["plan"]["segments"]]
    # three segments over the 120 frames, the walk longest (the planner gives time by need)
    assert len(spans) == 3 and spans[0][0] == 0 and spans[-1][1] == 120
    assert all(a < b for a, b in spans) and spans[0][1] - spans[0][0] > spans[1][1] - spans[1][0]
    return motion


def _span(motion: dict, i: int) -> tuple[int, int]:
    seg = motion["plan"]["segments"][i]
    return seg["start"], seg["end"]


def _joints(m: dict) -> np.ndarray:
    return np.asarray([p["joints"] for p in m["people"]])


def _check_rerun(client, parent: dict) -> dict:
    r = client.post(f"/api/motions/{parent['id']}/segments/1/rerun", json={"seed": 11},
                    headers={"X-Interplay-Client": CLIENT})
    assert r.status_code == 201, r.text
    made = r.json()
    assert made["parent_id"] == parent["id"] and made["id"] != parent["id"]
    assert made["edit"]["mode"] == "rerun" and made["edit"]["segment"] == 1
    a, b = _span(parent, 1)
    assert made["edit"]["frames"] == [a, b] and made["seed"] == 11
    assert made["plan"]["edits"][-1]["kind"] == "rerun_segment"
    assert made["plan"]["segments"] == parent["plan"]["segments"]
    old, new = _joints(parent), _joints(made)
    assert new.shape == old.shape
    assert np.array_equal(new[:, :a], old[:, :a]) and np.array_equal(new[:, b:], old[:, b:])
    assert np.abs(new[:, a + 2:b - 2] - old[:, a + 2:b - 2]).max() > 0.01
    assert len(made["highlights"]["contacts"]) == 120
    # stored as it was answered, and the history goes back to the parent (undo)
    assert _joints(client.get(f"/api/motions/{made['id']}").json()).tolist() == new.tolist()
    history = client.get(f"/api/motions/{made['id']}/history").json()["versions"]
    assert [v["id"] for v in history] == [parent["id"], made["id"]]
    listed = client.get("/api/motions", params={"client": CLIENT}).json()["motions"]
    assert listed[0]["id"] == made["id"] and listed[0]["edit"]["mode"] == "rerun"
    return made


def test_rerun_replaces_only_that_segment(fake_client):
    parent = _three_segments(fake_client)
    made = _check_rerun(fake_client, parent)
    # without a body the seed is random (and stored); the parent can be re-run again
    again = fake_client.post(f"/api/motions/{made['id']}/segments/2/rerun")
    assert again.status_code == 201, again.text
    assert isinstance(again.json()["seed"], int)
    a, _ = _span(made, 2)
    assert np.array_equal(_joints(again.json())[:, :a], _joints(made)[:, :a])


@pytest.mark.parametrize("path,body,status,match", [
    ("segments/3/rerun", {}, 422, "segment 3 does not exist"),
    ("segments/-1/rerun", {}, 422, "index"),
    ("segments/x/rerun", {}, 422, "index"),
    ("segments/0/rerun", {"seed": -1}, 422, "seed"),
    ("segments/0/rerun", {"seed": "7"}, 422, "seed"),
])
def test_bad_requests(fake_client, path, body, status, match):
    parent = run_job(fake_client, prompt="a person walks forward", seconds=2)[0]["motion_id"]
    r = fake_client.post(f"/api/motions/{parent}/{path}", json=body)
    assert r.status_code == status, r.text
    assert match in r.json()["detail"]


def test_unknown_motion_no_segments_and_no_generator(fake_client):
    r = fake_client.post("/api/motions/" + "n" * 22 + "/segments/0/rerun")
    assert r.status_code == 404 and "no motion" in r.json()["detail"]
    repo = fake_client.app.state.repo
    bare = repo.create(prompt="x", people=[np.zeros((20, 22, 3), np.float32)], seconds=1.0)
    r = fake_client.post(f"/api/motions/{bare.id}/segments/0/rerun")
    assert r.status_code == 422 and "no planned segments" in r.json()["detail"]
    parent = run_job(fake_client, prompt="a person walks forward", seconds=2)[0]["motion_id"]
    fake_client.app.state.generator, fake_client.app.state.generator_error = None, "gone"
    r = fake_client.post(f"/api/motions/{parent}/segments/0/rerun")
    assert r.status_code == 503 and "unavailable" in r.json()["detail"]


def test_rerun_with_the_real_generator(real_client):
    parent = _three_segments(real_client)
    assert parent["plan"]["generator"] == "retrieve_edit"        # the default for one person
    _check_rerun(real_client, parent)
