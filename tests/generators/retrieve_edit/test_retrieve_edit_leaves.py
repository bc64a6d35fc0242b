"""Issue 27: a retrieve-then-edit motion (the default generator) exports the captures' own head
and hand turns (`generators/retrieve_edit/leaves.py`, `pipeline/leaves.py`), on real library
clips and real prompts: on frames a capture gives, the BVH's head and wrist channels are the
capture's; where an arm action or a primitive made the part, the rig's derived leaves turn it
(a wave's hand, a nod's head: they vary, not 0), blended at the edit's ends within the 30°
steps; a slowed walk plays its leaves at the rate it plays its joints; a user's later edit
leaves its part to the rig; the JSON export's rig carries the same leaves as the BVH."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.generators.base import Request
from interplay.generators.retrieve_edit.generator import RetrieveEditGenerator, _slowed
from interplay.generators.retrieve_edit.leaves import _played, retrieve_edit_leaves
from interplay.generators.retrieve_edit.pace import rate_of
from interplay.generators.router import load_generator
from interplay.motion import skeleton as sk
from interplay.motion.captured_leaves import LEAF_NAMES, piece_leaves, resample_leaves
from interplay.motion.formats.bvh import read_bvh, write_bvh
from interplay.motion.kinematics import floor_height
from interplay.motion.rig import solve_rig
from interplay.motion.rig.steps import leaf_excess
from interplay.motion.rotations import quat_to_matrix
from interplay.pipeline.leaves import _edited, export_leaves

J = sk.JOINT_INDEX


@pytest.fixture(scope="module")
def gen():
    return RetrieveEditGenerator(load_generator(use_spam=False).index)


@pytest.fixture(scope="module")
def made(gen):
    """prompt → (joints (T, 22, 3), plan JSON), 6 s, seed 0."""
    cache: dict[str, tuple[np.ndarray, dict]] = {}

    def make(prompt: str) -> tuple[np.ndarray, dict]:
        if prompt not in cache:
            m = gen.generate(Request(prompt, seconds=6, seed=0))
            cache[prompt] = (np.asarray(m.people[0], np.float64), m.plan)
        return cache[prompt]
    return make


def _angle(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Angles (T,) in degrees between rotation matrices (T, 3, 3)."""
    rel = np.swapaxes(a, -1, -2) @ b
    return np.degrees(np.arccos(np.clip((np.trace(rel, axis1=-2, axis2=-1) - 1) / 2, -1.0, 1.0)))


def _bvh(joints: np.ndarray, leaves: dict):
    """The BVH the export writes, read back: (its local rotations (T, J, 3, 3), the file)."""
    b = read_bvh(write_bvh(joints, floor=floor_height([joints]), leaves=leaves))
    return b.local_transforms()[0], b


WAVE = "a person walks forward while waving the right hand"


def test_a_wave_keeps_the_captured_head_and_other_hand(made):
    joints, plan = made(WAVE)
    t = len(joints)
    assert plan["generator"] == "retrieve_edit"
    captured = piece_leaves(plan, 1, t)[0]
    leaves = export_leaves(plan, 1, t)[0]
    # The waving hand is the IK's on every frame of the action (here all): left to the rig.
    assert "right_wrist" not in leaves
    rot, b = _bvh(joints, leaves)
    for leaf in ("head", "left_wrist"):
        known = np.isfinite(leaves[leaf][:, 0])
        assert known.all()                             # the join's frames cross-faded
        np.testing.assert_array_equal(leaves[leaf][known], captured[leaf][known])
        got = _angle(rot[known, b.index(leaf)], quat_to_matrix(captured[leaf][known]))
        assert got.max() < 0.01, (leaf, got.max())     # the BVH channel is the capture's
    # The wave turns the hand (the derived lag): its channel varies, not 0.
    cols = b._channel_columns[b.index("right_wrist")]
    assert np.ptp(b.motion[:, cols], axis=0).max() > 10.0
    # Leaves move no joint: the file rebuilds the motion's joints either way.
    plain = read_bvh(write_bvh(joints, floor=floor_height([joints])))
    np.testing.assert_allclose(b.positions(), plain.positions(), atol=1e-6)


def test_a_nod_turns_the_head(made):
    joints, plan = made("a person nods")
    assert plan["segments"][0]["coverage"]["how"] == "primitive"
    leaves = export_leaves(plan, 1, len(joints))[0]
    assert leaves == {}                       # a primitive's whole body: every leaf derived
    rot, b = _bvh(joints, leaves)
    cols = b._channel_columns[b.index("head")]
    assert np.ptp(b.motion[:, cols], axis=0).max() > 5.0
    rig = solve_rig(joints, floor=floor_height([joints]), leaves=leaves)
    assert max(float(e.max()) for e in leaf_excess(rig).values()) <= 0.0


def test_an_arm_pose_blends_into_the_captured_hand_at_its_ends(made):
    """"… then raises the left arm above the head": the left hand is the capture's until the
    IK eases in, the rig's after; across the change no leaf steps over max(30°, its parent's
    turn); the head and the right hand stay captured through it."""
    joints, plan = made("a person walks forward then raises the left arm above the head")
    t = len(joints)
    leaves = export_leaves(plan, 1, t)[0]
    start = plan["segments"][1]["start"]
    derived = np.flatnonzero(np.isnan(leaves["left_wrist"][:, 0]))
    assert list(derived) == list(range(start, t))          # the IK eases in from the start
    for leaf in ("head", "right_wrist"):
        assert np.isfinite(leaves[leaf][start:, 0]).all()
    rig = solve_rig(joints, floor=floor_height([joints]), leaves=leaves)
    excess = leaf_excess(rig)
    for leaf in ("head", "left_wrist", "right_wrist"):
        assert excess[leaf][start - 12:start + 12].max() <= 0.0, leaf


def test_a_slowed_walk_plays_its_leaves_at_its_rate(gen, made):
    """The slowed segment's rate, as the export measures it on the plan's pieces, is the rate
    the generator played the joints at, and its leaves are the capture's played at that rate."""
    joints, plan = made("a person walks slowly")
    req = Request("a person walks slowly", seconds=6, seed=0)
    gplan = gen.plan(req)
    slow = _slowed(gplan)
    assert slow is not None
    base = np.concatenate([c[0] for _, c in gen.retrieval.stream(req, gplan)]).astype(np.float64)
    rate = rate_of(base[slow.start:slow.end])
    assert rate < 0.9
    assert rate_of(_played(plan, slow.index)) == pytest.approx(rate, abs=1e-9)
    raw = piece_leaves(plan, 1, len(joints))[0]
    got = retrieve_edit_leaves(plan, 1, len(joints))[0]
    a, b = slow.start, slow.end
    for leaf in raw:
        want = resample_leaves(raw[leaf][a:b], rate, b - a)
        np.testing.assert_array_equal(np.isnan(got[leaf][a:b]), np.isnan(want))
        known = np.isfinite(want[:, 0])
        np.testing.assert_allclose(got[leaf][a:b][known], want[known])
    # Played slower, a frame's leaf is the capture's at frame i·rate.
    i = 40
    np.testing.assert_allclose(np.abs(np.sum(got["head"][a + i] * raw["head"][a + round(i * rate)])),
                               1.0, atol=0.02)


def test_resampling_leaves():
    q = np.tile([1.0, 0.0, 0.0, 0.0], (5, 1))
    q[2] = np.nan
    out = resample_leaves(q, 0.5, 12)
    assert out.shape == (12, 4)
    # output i at input time i/2: NaN where a neighbour is (times 1.5, 2, 2.5), the last held
    assert list(np.flatnonzero(np.isnan(out[:, 0]))) == [3, 4, 5]
    np.testing.assert_allclose(out[8:], np.tile([1.0, 0, 0, 0], (4, 1)))
    np.testing.assert_array_equal(resample_leaves(q, 1.0, 5), q)


def test_a_user_edit_leaves_its_part_to_the_rig():
    leaves = [{leaf: np.tile([1.0, 0.0, 0.0, 0.0], (50, 1)) for leaf in LEAF_NAMES}]

    def gaps(entry: dict) -> dict[str, object]:
        """Per leaf, the frames the edit left to the rig as (first, count), "all" when the
        leaf is left to it everywhere (dropped), None when none."""
        out = _edited(leaves, {"edits": [entry]})[0]
        got: dict[str, object] = {}
        for k in LEAF_NAMES:
            nan = np.flatnonzero(np.isnan(out[k][:, 0])) if k in out else None
            got[k] = "all" if nan is None else (int(nan[0]), len(nan)) if len(nan) else None
        return got

    kept = {leaf: None for leaf in LEAF_NAMES}
    ik = gaps({"generator": "ik_pose", "arms": ["left_arm"], "frames": [10, 20]})
    assert ik == {**kept, "left_wrist": (10, 10)}
    spam = gaps({"generator": "spam", "parts": ["left_upper"], "frames": [0, 50]})
    assert spam == {**kept, "head": "all", "left_wrist": "all"}
    assert gaps({"trajectory": {"person": 0}}) == kept
    assert gaps({"generator": "captured_kick", "frames": [0, 50]}) == kept
    rerun = gaps({"kind": "rerun_segment", "frames": [20, 30], "fade": 5})
    assert rerun == {leaf: (15, 20) for leaf in LEAF_NAMES}


def test_the_json_export_rig_carries_the_captured_leaves(made):
    """The JSON export (`motion_file`) drives its rig with the BVH's leaves: its head is the
    capture's on the captured frames, where before it was the derived one."""
    from interplay.motion.rig import rig_from_json
    from interplay.pipeline.motion_json import motion_file
    from interplay.store import StoredMotion
    joints, plan = made(WAVE)
    stored = StoredMotion(id="m", prompt=WAVE, persons=1, seconds=6.0, seed=0,
                          people=[joints.astype(np.float32)], plan=plan)
    doc = motion_file(stored)
    rig = rig_from_json(doc["people"][0])
    j32 = stored.people[0].astype(np.float64)
    leaves = export_leaves(plan, 1, len(joints))[0]
    want = solve_rig(j32, floor=floor_height([j32]), leaves=leaves).rotations[:, J["head"]]
    np.testing.assert_allclose(np.abs(np.sum(rig.rotations[:, J["head"]] * want, -1)), 1.0, atol=1e-5)
    derived = solve_rig(j32, floor=floor_height([j32])).rotations[:, J["head"]]
    assert np.median(np.degrees(2 * np.arccos(np.clip(np.abs(np.sum(derived * want, -1)), 0, 1)))) > 5.0
    assert "leaves" not in doc["people"][0]         # NaN rows: the rig carries them


def test_the_api_exports_the_captured_turns(made, tmp_path):
    """GET /api/motions/{id}/export of a stored retrieve-then-edit wave: the BVH's head channel
    is the capture's on every frame, the GLB differs from one with derived leaves only."""
    from fastapi.testclient import TestClient

    from interplay.api.app import create_app
    from interplay.generators.retrieval.index import RetrievalIndex
    from interplay.generators.router import Router
    from interplay.motion.clip import default_clips
    from interplay.motion.formats.gltf import write_glb
    from interplay.settings import Settings
    from interplay.text.encoder import get_encoder
    (tmp_path / "var").mkdir()
    settings = Settings(var_dir=tmp_path / "var", frontend_dist=tmp_path / "dist",
                        database_url=f"sqlite:///{tmp_path / 'var' / 'test.db'}", job_queue="embedded")
    joints, plan = made(WAVE)
    router = Router(RetrievalIndex(list(default_clips()[:2]), get_encoder()), spam=None, reason="test")
    with TestClient(create_app(settings, generator=router)) as client:
        people = [joints.astype(np.float32)]
        mid = client.app.state.repo.create(prompt=WAVE, people=people, seconds=6.0, seed=0, plan=plan).id
        got = client.get(f"/api/motions/{mid}/export", params={"format": "bvh"})
        assert got.status_code == 200
        b = read_bvh(got.text)
        glb = client.get(f"/api/motions/{mid}/export", params={"format": "glb"}).content
    j32 = people[0].astype(np.float64)
    captured = piece_leaves(plan, 1, len(j32))[0]
    rot, _ = b.local_transforms()
    assert _angle(rot[:, b.index("head")], quat_to_matrix(captured["head"])).max() < 0.01
    assert glb != write_glb([j32], name=WAVE)


def test_the_cli_json_export_carries_them_too(made, tmp_path):
    """`interplay export --format json` of the same motion file: its rig's head is the API's."""
    import json

    from interplay.cli.main import main
    from interplay.motion.motion import Motion
    from interplay.motion.rig import rig_from_json
    joints, plan = made(WAVE)
    path, out = tmp_path / "m.json", tmp_path / "out.json"
    path.write_text(json.dumps(Motion(people=[joints.astype(np.float32)], plan=plan, prompt=WAVE).to_json()))
    assert main(["export", str(path), "--format", "json", "--out", str(out)]) == 0
    rig = rig_from_json(json.loads(out.read_text())["people"][0])
    j32 = joints.astype(np.float32).astype(np.float64)
    want = solve_rig(j32, floor=floor_height([j32]), leaves=export_leaves(plan, 1, len(j32))[0])
    np.testing.assert_allclose(np.abs(np.sum(rig.rotations[:, J["head"]] * want.rotations[:, J["head"]], -1)),
                               1.0, atol=1e-5)
