"""Explicit head / wrist rotations in Motion JSON (issue 27): a head edit's turns reach every
export. "look up" through POST /api/motions/{id}/edit exports a BVH whose head channel (read
by bvhio, a parser nobody here wrote) pitches ≥ 25° over the stored motion's on the edited
frames (the derived half-neck rule alone gives ~17°); the JSON export carries the person's
"leaves"; a motion without leaves writes no "leaves" and exports exactly as before."""

from __future__ import annotations

import json

import numpy as np
import pytest
from fastapi.testclient import TestClient

from interplay.api.app import create_app
from interplay.generators.retrieval.index import RetrievalIndex
from interplay.generators.router import Router
from interplay.motion.clip import default_clips
from interplay.motion.formats.bvh import write_bvh
from interplay.motion.formats.gltf import write_glb
from interplay.motion.motion import Motion
from interplay.motion.rig import rig_from_json, solve_rig
from interplay.motion.rotations import quat_to_matrix
from interplay.text.encoder import get_encoder


@pytest.fixture(scope="module")
def walk():
    return next(c for c in default_clips() if len(c.people) == 1 and c.label == "walk"
                and c.frames >= 100)


@pytest.fixture
def client(settings, walk):
    router = Router(RetrievalIndex([walk], get_encoder()), spam=None, reason="no SPAM in this test")
    with TestClient(create_app(settings, generator=router)) as c:
        yield c


def bvhio_head(path) -> np.ndarray:
    """The head joint's local rotations (T, 3, 3) as bvhio reads them."""
    import bvhio
    root = bvhio.readAsHierarchy(str(path))
    joints = {j.Name: j for j, _, _ in root.layout()}
    out = []
    for f in range(bvhio.readAsBvh(str(path)).FrameCount):
        root.loadPose(f)
        q = joints["head"].Rotation
        out.append([q.w, q.x, q.y, q.z])
    return quat_to_matrix(np.asarray(out))


def pitch_between(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The turn (T,) in degrees from rotations a to b about their X axis (the head's pitch)."""
    r = np.swapaxes(a, -1, -2) @ b
    return np.degrees(np.arctan2(r[:, 2, 1], r[:, 1, 1]))


def test_a_head_edit_turns_the_exported_head_by_its_angles(client, walk, tmp_path):
    people = [walk.people[0][:100]]
    mid = client.app.state.repo.create(prompt=walk.prompt, people=people, seconds=5.0, seed=1,
                                       plan={"generator": "retrieval"}).id
    r = client.post(f"/api/motions/{mid}/edit", json={"part": "head", "prompt": "look up",
                                                      "frames": [20, 80], "seed": 2})
    assert r.status_code == 201, r.text
    new = r.json()["id"]
    heads = {}
    for key, motion in (("base", mid), ("edit", new)):
        got = client.get(f"/api/motions/{motion}/export", params={"format": "bvh"})
        assert got.status_code == 200
        (tmp_path / f"{key}.bvh").write_text(got.text)
        heads[key] = bvhio_head(tmp_path / f"{key}.bvh")
    rise = np.abs(pitch_between(heads["base"], heads["edit"]))
    assert rise[30:70].min() >= 25.0, rise[30:70].min()
    assert rise[:19].max() < 1.0 and rise[81:].max() < 1.0          # untouched frames: as before
    # The JSON export carries the leaf and drives its rig's head with it.
    doc = client.get(f"/api/motions/{new}/export", params={"format": "json"}).json()
    leaf = np.asarray(doc["people"][0]["leaves"]["head"])
    assert leaf.shape == (100, 4) and "leaves" not in doc["plan"]
    rig = rig_from_json(doc["people"][0])
    assert np.allclose(np.abs(np.sum(rig.rotations[:, 15] * leaf / np.linalg.norm(leaf, axis=-1,
                                                                                    keepdims=True), -1)), 1, atol=1e-5)
    # The GLB export takes it too (a different file from the leafless one).
    glb = client.get(f"/api/motions/{new}/export", params={"format": "glb"}).content
    stored = client.app.state.repo.get(new)
    joints = [p.astype(np.float64) for p in stored.people]
    assert glb == write_glb(joints, leaves=[Motion.from_json(doc).leaves_of(0)], name=walk.prompt)
    assert glb != write_glb(joints, name=walk.prompt)

def test_a_motion_without_leaves_exports_as_before(walk):
    joints = np.asarray(walk.people[0][:60], np.float64)
    motion = Motion(people=[joints])
    d = motion.to_json(rig=True)
    assert "leaves" not in d["people"][0] and motion.leaves is None
    back = Motion.from_json(json.loads(json.dumps(d)))
    assert back.leaves is None and back.leaves_of(0) == {}
    assert write_bvh(joints, leaves=back.leaves_of(0)) == write_bvh(joints)
    assert np.array_equal(solve_rig(joints, leaves={}).rotations, solve_rig(joints).rotations)


def test_leaves_round_trip_and_are_checked(walk):
    joints = np.asarray(walk.people[0][:40], np.float64)
    angle = np.linspace(0.0, 0.6, 40)
    q = np.stack([np.cos(angle / 2), np.sin(angle / 2), 0 * angle, 0 * angle], axis=-1)
    motion = Motion(people=[joints], leaves=[{"right_wrist": q}])
    d = json.loads(json.dumps(motion.to_json(rig=True)))
    assert np.allclose(d["people"][0]["leaves"]["right_wrist"], q, atol=1e-6)
    assert np.allclose(Motion.from_json(d).leaves_of(0)["right_wrist"], q, atol=1e-6)
    assert np.allclose(rig_from_json(d["people"][0]).rotations[:, 21], q, atol=1e-5)
    # An edit's plan carries them; Motion lifts them out of it.
    lifted = Motion(people=[joints], plan={"leaves": [{"right_wrist": q.tolist()}], "x": 1})
    assert lifted.plan == {"x": 1} and np.allclose(lifted.leaves_of(0)["right_wrist"], q)
    for bad in ([{"left_knee": q}], [{"head": q[:3]}], [{"head": q}, {}], [{"head": q * np.nan}]):
        with pytest.raises(ValueError):
            Motion(people=[joints], leaves=bad)
