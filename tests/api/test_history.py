"""Versions of a motion: edits (a drawn path, a preset) stored as children with what made
them, GET /api/motions/{id}/history from the root, and the store's columns added in place."""

from __future__ import annotations

import numpy as np
import pytest
from sqlalchemy import create_engine, text

from interplay.store import MotionRepository, make_engine
from tests.helpers.api import run_job


def _generated(client, persons: int = 1) -> str:
    job, events = run_job(client, prompt="a person walks", persons=persons, seconds=4, seed=5)
    assert events[-1]["type"] == "done", events[-1]
    return job["motion_id"]


def test_path_edits_make_versions_and_history_runs_from_the_root(fake_client):
    root = _generated(fake_client)
    r = fake_client.post(f"/api/motions/{root}/edit",
                         json={"trajectory": {"person": 0, "shape": "arc", "clockwise": False}})
    assert r.status_code == 201, r.text
    first = r.json()
    assert first["parent_id"] == root
    assert first["edit"] == {"part": None, "prompt": None, "frames": None,
                             "trajectory": {"person": 0, "shape": "arc", "clockwise": False}}
    before = np.asarray(fake_client.get(f"/api/motions/{root}").json()["people"][0]["joints"])
    after = np.asarray(first["people"][0]["joints"])
    assert before.shape == after.shape and not np.allclose(before[:, 0], after[:, 0], atol=0.05)
    pts = [[0.0, 0.0], [1.0, 1.0]]
    r = fake_client.post(f"/api/motions/{first['id']}/edit",
                         json={"trajectory": {"person": 0, "points": pts}})
    assert r.status_code == 201, r.text
    second = r.json()
    got = fake_client.get(f"/api/motions/{second['id']}").json()
    assert got["parent_id"] == first["id"] and got["edit"]["trajectory"]["points"] == pts
    h = fake_client.get(f"/api/motions/{second['id']}/history")
    assert h.status_code == 200, h.text
    versions = h.json()["versions"]
    assert [v["id"] for v in versions] == [root, first["id"], second["id"]]
    assert [v["parent_id"] for v in versions] == [None, root, first["id"]]
    assert versions[0]["edit"] is None and versions[2]["edit"]["trajectory"]["points"] == pts
    assert all(v["prompt"] == "a person walks" and v["created_at"] for v in versions)
    # The middle version's history stops at itself.
    mid = fake_client.get(f"/api/motions/{first['id']}/history").json()["versions"]
    assert [v["id"] for v in mid] == [root, first["id"]]


def test_a_path_for_the_second_person_moves_only_them(fake_client):
    root = _generated(fake_client, persons=2)
    r = fake_client.post(f"/api/motions/{root}/edit",
                         json={"trajectory": {"person": 1, "shape": "line", "direction": "left"}})
    assert r.status_code == 201, r.text
    old = fake_client.get(f"/api/motions/{root}").json()["people"]
    new = r.json()["people"]
    assert new[0] == old[0] and new[1] != old[1]
    r = fake_client.post(f"/api/motions/{root}/edit",
                         json={"trajectory": {"person": 1, "shape": "line", "speed": 3}})
    assert r.status_code == 422


@pytest.mark.parametrize("body,word", [
    ({}, "prompt, a trajectory"),
    ({"part": "left_arm"}, "prompt, a trajectory"),
    ({"part": "left_arm", "trajectory": {"person": 0, "shape": "circle"}}, "need a prompt"),
    ({"frames": [0, 10], "trajectory": {"person": 0, "shape": "circle"}}, "need a prompt"),
    ({"trajectory": {"person": 0, "points": [[0, 0]]}}, "points"),
    ({"trajectory": {"person": 0, "shape": "zigzag", "size_m": 0}}, "size_m"),
])
def test_bad_edits_are_422(fake_client, body, word):
    root = _generated(fake_client)
    r = fake_client.post(f"/api/motions/{root}/edit", json=body)
    assert r.status_code == 422, r.text
    assert word in r.json()["detail"]


def test_a_path_for_a_missing_person_is_422(fake_client):
    root = _generated(fake_client)
    r = fake_client.post(f"/api/motions/{root}/edit",
                         json={"trajectory": {"person": 1, "shape": "circle"}})
    assert r.status_code == 422 and "person 1" in r.json()["detail"]


@pytest.mark.parametrize("motion_id", ["GbOLvSrBj8d2ZVgyhbGUQA", "x", "a" * 200])
def test_history_of_unknown_motion_is_404(fake_client, motion_id):
    r = fake_client.get(f"/api/motions/{motion_id}/history")
    assert r.status_code == 404 and "no motion" in r.json()["detail"]


def test_an_older_database_gets_the_review_and_edit_columns(tmp_path):
    url = f"sqlite:///{tmp_path / 'old.db'}"
    old = create_engine(url)
    with old.begin() as conn:    # the table as the store created it before this change
        conn.execute(text(
            "CREATE TABLE motions (id VARCHAR(64) PRIMARY KEY, prompt TEXT, persons INTEGER, "
            "seconds FLOAT, seed INTEGER, fps INTEGER, frames INTEGER, joints BLOB, plan JSON, "
            "metrics JSON, highlights JSON, parent_id VARCHAR(64), created_at DATETIME)"))
    old.dispose()
    repo = MotionRepository(make_engine(url))
    joints = np.zeros((3, 22, 3), np.float32)
    m = repo.create(prompt="p", people=[joints], seconds=0.15, review={"segments": []},
                    edit={"prompt": "x"})
    back = repo.get(m.id)
    assert back.review == {"segments": []} and back.edit == {"prompt": "x"}
