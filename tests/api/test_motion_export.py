"""GET /api/motions/{id}/export (api/routes/motions.py): the BVH presets as query parameters
(fps, units, up, names) written by the same writer as the CLI, 422 with the choices on bad
values, and the version-2 Motion JSON with each person's rig."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.formats.bvh import MIXAMO_NAMES, read_bvh, write_bvh
from interplay.motion.kinematics import floor_height
from interplay.motion.motion import Motion
from interplay.motion.rig import rig_from_json, rig_positions, solve_rig
from tests.helpers.api import run_job

MISSING = "AAAAAAAAAAAAAAAAAAAAAA"


@pytest.fixture
def pair(fake_client):
    job, events = run_job(fake_client, prompt="two people walk towards each other", persons=2,
                          seconds=2, seed=4)
    assert events[-1]["type"] == "done"
    return job["motion_id"]


def stored_people(client, motion_id) -> list[np.ndarray]:
    return [np.asarray(p["joints"], dtype=np.float32).astype(np.float64)
            for p in client.get(f"/api/motions/{motion_id}").json()["people"]]


@pytest.mark.parametrize("query,preset", [
    ({}, {}),
    ({"fps": 60, "units": "cm", "up": "z", "names": "mixamo", "person": 1},
     {"out_fps": 60, "units": "cm", "up": "z", "names": "mixamo"}),
    ({"fps": 24}, {"out_fps": 24}), ({"fps": 30, "names": "mixamo"}, {"out_fps": 30, "names": "mixamo"}),
])
def test_bvh_presets_are_the_writers(fake_client, pair, query, preset):
    r = fake_client.get(f"/api/motions/{pair}/export", params={"format": "bvh", **query})
    assert r.status_code == 200, r.text
    people = stored_people(fake_client, pair)
    person = query.get("person", 0)
    # The route writes what the writer writes for these presets, with the pair's one floor
    # (from the stored joints; the page's copy is rounded to 0.1 mm, hence not to the digit).
    want = read_bvh(write_bvh(people[person], fps=20, floor=floor_height(people), **preset))
    bvh = read_bvh(r.text)
    assert bvh.names == want.names and bvh.channels == want.channels
    assert np.abs(bvh.positions(True) - want.positions(True)).max() < 2e-3 * (100 if "units" in query else 1)
    fps = query.get("fps", 20)
    assert bvh.fps == pytest.approx(fps, rel=1e-6)
    assert bvh.num_frames == int(np.ceil((len(people[0]) - 1) / 20 * fps - 1e-6)) + 1   # the end kept
    assert bvh.names[0] == ("mixamorig:Hips" if query.get("names") == "mixamo" else "pelvis")
    if query.get("names") == "mixamo":
        assert set(bvh.names) == set(MIXAMO_NAMES)


@pytest.mark.parametrize("query,word", [
    ("format=bvh&fps=25", "fps"), ("format=bvh&fps=sixty", "fps"), ("format=bvh&units=mm", "units"),
    ("format=bvh&up=x", "up"), ("format=bvh&names=unreal", "names")])
def test_bad_presets_are_422_with_the_parameter_named(fake_client, query, word):
    r = fake_client.get(f"/api/motions/{MISSING}/export?{query}")
    assert r.status_code == 422 and word in r.json()["detail"], r.text


def test_json_export_is_version_2_with_each_persons_rig(fake_client, pair):
    r = fake_client.get(f"/api/motions/{pair}/export", params={"format": "json"})
    assert r.status_code == 200, r.text
    d = r.json()
    assert d["schema"] == "interplay.motion/2" and d["id"] == pair
    assert d["joint_names"] == list(sk.JOINT_NAMES) and d["parents"] == list(sk.PARENTS)
    people = [np.asarray(p["joints"], dtype=np.float64) for p in d["people"]]
    floor = floor_height(people)
    for person, joints in zip(d["people"], people):
        rig = rig_from_json(person)
        assert rig.rotations.shape == (len(joints), 22, 4)
        # The rig is the solver's for these joints (the fake generator's joints are jittered
        # off fixed bones, so FK does not give them back exactly; real motions' do, as
        # tests/motion/test_motion_json.py checks).
        want = solve_rig(joints, floor=floor)
        assert np.abs(rig_positions(rig) - rig_positions(want)).max() < 1e-3
    assert len(Motion.from_json(d).people) == 2


def test_the_routes_choices_are_the_writers():
    from interplay.api.routes.motions import BvhFps
    from interplay.motion.formats.bvh import FPS_CHOICES
    assert tuple(int(f) for f in BvhFps) == FPS_CHOICES


def test_glb_takes_the_presets(fake_client, pair):
    from tests.helpers.gltf_files import load
    r = fake_client.get(f"/api/motions/{pair}/export",
                        params={"format": "glb", "fps": 30, "units": "cm", "names": "mixamo", "mesh": False})
    assert r.status_code == 200, r.text
    doc, _ = load(r.content)
    frames = len(stored_people(fake_client, pair)[0])
    assert doc.extras["fps"] == 30 and doc.extras["units"] == "cm" and doc.extras["names"] == "mixamo"
    assert doc.extras["frames"] == int(np.ceil((frames - 1) / 20 * 30 - 1e-6)) + 1   # the end kept
    skin_names = [doc.nodes[n].name for n in doc.skins[1].joints]
    assert skin_names[0] == "person2_mixamorig:Hips" and "person2_mixamorig:LeftToe_End" in skin_names
