"""Commonsense and physics metrics on the processed capture set (models/data, via
interplay.motion.clip.default_clips): CMU and CMU 8-action walks, jumps, the salsa pairs."""

import json

import numpy as np
import pytest

from interplay.motion import metrics as m
from interplay.motion import skeleton as sk
from interplay.motion.clip import default_clips

SINGLE_KEYS = {"bone_deviation", "foot_skating", "skating_ratio", "ground_penetration", "floating",
               "com_distance", "com_angle"}
PAIR_KEYS = {"intersection_volume", "intersection_frequency", "contact_frames", "min_distance"}


@pytest.fixture(scope="module")
def walks():
    clips = [c.people[0].astype(np.float64) for c in default_clips()
             if (c.source, c.label) in {("cmu-bvh", "walk"), ("cmu-8action", "walking")}]
    assert len(clips) >= 20
    return clips


@pytest.fixture(scope="module")
def jumps():
    return [c.people[0].astype(np.float64) for c in default_clips()
            if c.source == "cmu-bvh" and "jump" in c.label]


@pytest.fixture(scope="module")
def salsa():
    pairs = [[p.astype(np.float64) for p in c.people] for c in default_clips() if c.source == "cmu-salsa"]
    assert len(pairs) >= 10
    return pairs


def test_captured_walks_are_rigid_grounded_and_barely_skate(walks, jumps):
    res = [m.clip_metrics([w]) for w in walks]
    assert all(r["bone_deviation"] < 1e-3 for r in res)            # fitted on fixed bones
    assert all(r["ground_penetration"] < 0.005 and r["floating"] < 0.06 for r in res)
    assert all(r["skating_ratio"] < 0.1 for r in res)
    # Planted feet of real walks still creep (CMU's stance toes wobble ±3 cm sideways), but
    # far slower than a sliding foot; standing jumps barely move while planted.
    skating = np.array([r["foot_skating"] for r in res])
    assert np.median(skating) < 0.25 and skating.max() < 0.45
    assert max(m.clip_metrics([j])["foot_skating"] for j in jumps) < 0.1


def test_sliding_the_whole_body_makes_planted_feet_skate(walks):
    for w in walks[:8]:
        base = m.clip_metrics([w])
        slide = w.copy()
        slide[..., 0] += np.arange(len(w))[:, None] / sk.FPS * 1.0      # drift 1 m/s sideways
        got = m.clip_metrics([slide])
        assert got["foot_skating"] > 0.8 and got["foot_skating"] > base["foot_skating"] + 0.5
        assert got["skating_ratio"] > base["skating_ratio"] + 0.05


def test_a_stretched_bone_raises_bone_deviation(walks):
    w = walks[0]
    base = m.bone_deviation(w)
    stretched = w.copy()
    frames = np.arange(0, len(w), 3)                                # a third of the frames
    elbow, wrist = sk.JOINT_INDEX["left_elbow"], sk.LEFT_HAND
    forearm = stretched[frames, wrist] - stretched[frames, elbow]
    stretched[frames, wrist] += 0.05 * forearm / np.linalg.norm(forearm, axis=-1, keepdims=True)
    dev = m.bone_deviation(stretched)
    bone = [c for c, _ in sk.BONES].index(wrist)
    # The stored set is float16: ~1 mm of length noise per frame at most.
    assert np.allclose(dev[frames, bone], 0.05, atol=2e-3) and base.max() < 2e-3
    rise = m.clip_metrics([stretched])["bone_deviation"] - m.clip_metrics([w])["bone_deviation"]
    assert rise == pytest.approx(0.05 * len(frames) / len(w) / len(sk.BONES), rel=0.05)


def test_pushing_below_the_floor_and_lifting_off_it(walks):
    w = walks[0]
    base = m.clip_metrics([w])
    sunk = m.clip_metrics([w - [0, 0.1, 0]])
    # Each frame's lowest joint (a sole ~2 cm up) ends 0.1 m lower, i.e. 0.08 m under.
    lowest = w[..., 1].min(axis=1)
    assert np.all(lowest < 0.1) and base["ground_penetration"] < 0.005
    assert sunk["ground_penetration"] == pytest.approx(0.1 - lowest.mean())
    assert m.ground_penetration(w - [0, 0.1, 0]).min() > 0.0      # every frame is under
    lifted = m.clip_metrics([w + [0, 0.3, 0]])
    assert lifted["floating"] > 0.3 and base["floating"] < 0.06
    assert lifted["ground_penetration"] == 0.0


def test_centre_of_mass_follows_the_body(walks):
    for w in walks[:5]:
        com = m.centre_of_mass(w)
        pelvis = w[:, sk.PELVIS]
        # Near the pelvis (within a hand's width), between the knees and the neck.
        assert np.all(np.linalg.norm(com - pelvis, axis=-1) < 0.12)
        assert np.all((com[:, 1] > w[:, sk.JOINT_INDEX["left_knee"], 1])
                      & (com[:, 1] < w[:, sk.NECK, 1]))
        # Eq. 4's quantities do not change when the whole clip turns and moves on the floor.
        yaw = np.array([[0.0, 0, 1], [0, 1, 0], [-1, 0, 0]])       # 90° about the vertical
        moved = w @ yaw.T + [2.0, 0, -1.0]
        for a, b in zip(m.com_to_pelvis(w), m.com_to_pelvis(moved)):
            assert np.allclose(a, b)


def test_key_joint_trajectory_error_is_the_xz_l1_of_eq5(walks):
    w = walks[1]
    assert m.key_joint_trajectory_error(w, w) == 0.0
    assert m.key_joint_trajectory_error(w + [0.1, 0, 0], w) == pytest.approx(5 * 0.1)
    assert m.key_joint_trajectory_error(w + [0.1, 0, -0.2], w) == pytest.approx(5 * 0.3)
    assert m.key_joint_trajectory_error(w + [0, 0.4, 0], w) == 0.0     # XZ plane only
    with pytest.raises(ValueError):
        m.key_joint_trajectory_error(w[:-1], w)


def test_salsa_pairs_touch_hands_and_sometimes_overlap(salsa):
    for pair in salsa:
        r = m.clip_metrics(pair)
        assert set(r) == SINGLE_KEYS | PAIR_KEYS
        assert r["contact_frames"] > 0 and isinstance(r["contact_frames"], int)
        assert 0 <= r["intersection_frequency"] < 0.5 and r["intersection_volume"] >= 0
        assert r["min_distance"] < 0.03                              # they do touch
        assert r["bone_deviation"] < 1e-3


def test_frame_highlights_agree_with_clip_metrics(salsa):
    pair = salsa[0]
    t = pair[0].shape[0]
    h = m.frame_highlights(pair)
    r = m.clip_metrics(pair)
    assert len(h["contacts"]) == len(h["penetration"]) == len(h["min_distance"]) == t
    hands = [any(j in (sk.LEFT_HAND, sk.RIGHT_HAND) for _, j in f) for f in h["contacts"]]
    assert sum(hands) == r["contact_frames"]
    feet = [any(j in sk.FOOT_JOINTS for _, j in f) for f in h["contacts"]]
    assert np.mean(feet) > 0.9                                       # dancers stay on their feet
    assert np.mean([bool(f) for f in h["penetration"]]) == pytest.approx(r["intersection_frequency"])
    assert {part for f in h["penetration"] for _, part in f} <= set(sk.PART_NAMES)
    assert min(h["min_distance"]) == pytest.approx(r["min_distance"])
    json.dumps(h)                                                     # plain JSON types
    assert all(isinstance(x, int) for f in h["contacts"] for pj in f for x in pj)


def test_stepping_one_dancer_into_the_other_raises_iv_and_if(salsa):
    lead, follow = salsa[1]
    gap = lead[:, sk.PELVIS] - follow[:, sk.PELVIS]
    gap[:, 1] = 0
    res = [m.clip_metrics([lead, follow + f * gap[:, None]]) for f in (0.0, 0.25, 0.5, 0.75, 0.95)]
    iv = [r["intersection_volume"] for r in res]
    freq = [r["intersection_frequency"] for r in res]
    assert np.all(np.diff(iv) > 0) and np.all(np.diff(freq) >= 0) and freq[-1] == 1.0
    assert res[-1]["min_distance"] < res[0]["min_distance"]
    unit = gap / np.linalg.norm(gap, axis=1, keepdims=True)
    far = m.clip_metrics([lead, follow - 3 * unit[:, None]])
    assert far["intersection_volume"] == 0 and far["intersection_frequency"] == 0
    assert far["contact_frames"] == 0 and far["min_distance"] > 0.5


def test_one_person_json_and_contract(walks):
    r = m.clip_metrics([walks[0]])
    assert set(r) == SINGLE_KEYS
    assert all(type(v) is float for v in r.values())
    json.dumps(r)
    h = m.frame_highlights([walks[0]])
    assert h["min_distance"] is None and not any(h["penetration"])
    assert all(p == 0 and j in sk.FOOT_JOINTS for f in h["contacts"] for p, j in f)


def test_bad_input_is_refused(walks):
    w = walks[0]
    with pytest.raises(ValueError, match="one or two"):
        m.clip_metrics([w, w, w])
    with pytest.raises(ValueError, match="one or two"):
        m.clip_metrics([])
    with pytest.raises(ValueError, match="frame counts"):
        m.clip_metrics([w, w[:-3]])
    with pytest.raises(ValueError, match="shape"):
        m.frame_highlights([w[:, :21]])
    bad = w.copy()
    bad[4, 2, 0] = np.inf
    with pytest.raises(ValueError, match="NaN or infinite"):
        m.clip_metrics([bad])
