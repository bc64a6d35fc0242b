""""My motions": GET /api/motions?client=<id> lists what one browser made (jobs, edits, re-runs
sent with its X-Interplay-Client header), newest first, with a first frame for a thumbnail;
never a global listing (no client, a malformed one or a bad limit is a 422), never another
client's motions, and a motion never gives its client id away. A database made before the
column existed gets it (and its index) in place, its rows kept."""

from __future__ import annotations

import numpy as np
import pytest
from sqlalchemy import create_engine, inspect, text

from interplay.motion.skeleton import rest_joints
from interplay.store import MotionRepository, make_engine
from tests.helpers.api import run_job

A = "A" * 11 + "b" * 11            # 22 URL-safe characters, as the studio makes them
B = "client_two-0123456789abc"


def _job(client, prompt: str, who: str | None, seconds: float = 1.0) -> str:
    headers = {"X-Interplay-Client": who} if who else {}
    r = client.post("/api/jobs", json={"prompt": prompt, "persons": 1, "seconds": seconds,
                                       "seed": 3}, headers=headers)
    assert r.status_code == 201, r.text
    job = r.json()
    with client.websocket_connect(job["stream"]) as ws:
        while ws.receive_json()["type"] not in ("done", "error"):
            pass
    return job["motion_id"]


def test_lists_only_this_clients_motions_newest_first(fake_client):
    made = [_job(fake_client, f"a person walks forward {i}", A) for i in range(6)]
    other = _job(fake_client, "a person jumps", B)
    anonymous = _job(fake_client, "a person waves", None)
    r = fake_client.get("/api/motions", params={"client": A, "limit": 5})
    assert r.status_code == 200, r.text
    items = r.json()["motions"]
    assert [m["id"] for m in items] == made[::-1][:5]
    first = items[0]
    assert first["prompt"] == "a person walks forward 5" and first["persons"] == 1
    assert first["seconds"] == 1.0 and first["frames"] == 20 and first["parent_id"] is None
    stored = fake_client.get(f"/api/motions/{first['id']}").json()
    assert first["first_frame"] == [stored["people"][0]["joints"][0]]
    assert np.asarray(first["first_frame"]).shape == (1, 22, 3)
    everything = [m["id"] for m in fake_client.get("/api/motions", params={"client": A}).json()["motions"]]
    assert everything == made[::-1] and other not in everything and anonymous not in everything
    assert [m["id"] for m in fake_client.get("/api/motions", params={"client": B}).json()["motions"]] == [other]
    assert fake_client.get("/api/motions", params={"client": "z" * 22}).json() == {
        "motions": [], "next": None, "total": 0}
    # the client id is never part of a motion (a share link must not list its owner's motions)
    assert "client" not in str(stored.keys())
    assert A not in fake_client.get(f"/api/motions/{first['id']}/history").text


def test_an_edit_made_with_the_header_is_listed_as_a_version(fake_client):
    mid = _job(fake_client, "a person walks forward", A, seconds=2)
    r = fake_client.post(f"/api/motions/{mid}/edit", headers={"X-Interplay-Client": A},
                         json={"trajectory": {"person": 0, "shape": "circle", "size_m": 2}})
    assert r.status_code == 201, r.text
    items = fake_client.get("/api/motions", params={"client": A}).json()["motions"]
    assert [m["id"] for m in items] == [r.json()["id"], mid]
    assert items[0]["parent_id"] == mid and items[0]["edit"]["trajectory"]["shape"] == "circle"


@pytest.mark.parametrize("params", [{}, {"client": ""}, {"client": "short"}, {"client": "x" * 65},
                                    {"client": "bad id with spaces!!"}, {"client": A, "limit": 0},
                                    {"client": A, "limit": 51}, {"client": A, "limit": "many"}])
def test_no_listing_without_a_valid_client_and_a_bounded_limit(fake_client, params):
    r = fake_client.get("/api/motions", params=params)
    assert r.status_code == 422, r.text
    assert isinstance(r.json()["detail"], str) and r.json()["detail"]


def test_a_malformed_client_header_is_refused(fake_client):
    r = fake_client.post("/api/jobs", json={"prompt": "a person walks", "seconds": 1},
                         headers={"X-Interplay-Client": "no spaces allowed here!"})
    assert r.status_code == 422 and "X-Interplay-Client" in r.json()["detail"]
    job, events = run_job(fake_client, prompt="a person walks", seconds=1)   # no header: fine
    assert events[-1]["type"] == "done"


def test_an_old_database_gets_the_column_and_keeps_its_rows(tmp_path):
    url = f"sqlite:///{tmp_path / 'old.db'}"
    old = create_engine(url)
    with old.begin() as conn:   # the motions table as it was before client_id
        conn.execute(text(
            "CREATE TABLE motions (id VARCHAR(64) PRIMARY KEY, prompt TEXT, persons INTEGER, "
            "seconds FLOAT, seed INTEGER, fps INTEGER, frames INTEGER, joints BLOB, plan JSON, "
            "metrics JSON, highlights JSON, review JSON, edit JSON, parent_id VARCHAR(64), "
            "created_at DATETIME)"))
        joints = np.repeat(rest_joints()[None], 4, axis=0).astype(np.float32)
        conn.execute(text("INSERT INTO motions (id, prompt, persons, seconds, fps, frames, joints, "
                          "created_at) VALUES (:id, 'an old one', 1, 0.2, 20, 4, :j, "
                          "'2026-01-01 00:00:00')"), {"id": "o" * 22, "j": joints.tobytes()})
    old.dispose()
    engine = make_engine(url)
    insp = inspect(engine)
    assert "client_id" in {c["name"] for c in insp.get_columns("motions")}
    assert any(ix["column_names"] == ["client_id"] for ix in insp.get_indexes("motions"))
    repo = MotionRepository(engine)
    assert repo.get("o" * 22).prompt == "an old one"
    assert repo.for_client(A) == []
    new = repo.create(prompt="a new one", people=[joints], seconds=0.2, client_id=A)
    assert [m.id for m in repo.for_client(A)] == [new.id]
    make_engine(url)                    # idempotent: a second start adds nothing
    with pytest.raises(ValueError, match="malformed client id"):
        repo.create(prompt="x", people=[joints], seconds=0.2, client_id="not valid!")
