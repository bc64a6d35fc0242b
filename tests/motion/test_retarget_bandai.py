"""Bandai Namco → SMPL-22 on a committed raw clip (tests/fixtures/raw, made by
tests/fixtures/make_fixtures.py): labels from JSON + name, prompts with the style kept, the
body re-posed on measured proportions with the legs untouched, frame-rate evidence."""

from pathlib import Path

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import facing_direction
from interplay.motion.retarget.bandai_namco import (
    UPPER_BODY,
    bandai_prompt,
    load_bandai,
    parse_name,
    read_labels,
)

RAW = Path(__file__).resolve().parents[1] / "fixtures" / "raw" / "bandai-namco"
WAVE = RAW / "dataset-2" / "data" / "dataset-2_wave-right-hand_normal_001.bvh"


@pytest.fixture(scope="module")
def wave():
    return load_bandai(WAVE), load_bandai(WAVE, plausible_body=False)


def test_labels_and_prompts_keep_the_style():
    assert read_labels(WAVE) == {"dataset": 2, "content": "wave-right-hand", "style": "normal", "take": 1}
    assert parse_name("dataset-1_walk-back_not-confident_003.bvh")["style"] == "not-confident"
    assert bandai_prompt("walk", "old") == "an old person walks"
    assert bandai_prompt("walk", "happy") == "a person walks happily"
    assert bandai_prompt("bow", "normal") == "a person bows"
    assert bandai_prompt("wave-right-hand", "normal") == "a person waves with the right hand"
    assert bandai_prompt("wave-left-hand", "happy") == "a person happily waves with the left hand"
    assert bandai_prompt("run", "giant") == "a person runs like a giant"
    with pytest.raises(ValueError):
        bandai_prompt("moonwalk", "normal")


def test_standing_on_the_floor_facing_plus_z_and_the_right_hand_waves(wave):
    (joints, offsets, meta), _ = wave
    assert joints.shape[1:] == (22, 3) and meta["source_fps"] == 30 and meta["defects"] == []
    assert abs(len(joints) - (meta["frames_native"] - 1) / 30 * 20) <= 1
    lowest = joints[..., 1].min(axis=1)
    assert abs(np.percentile(lowest, 2)) < 1e-6 and np.median(lowest) < 0.05
    assert facing_direction(joints[0])[2] > 0.99 and np.allclose(joints[0, sk.PELVIS, [0, 2]], 0)
    assert joints[0, sk.LEFT_SHOULDER, 0] > 0 > joints[0, sk.RIGHT_SHOULDER, 0]    # left is +X
    above = joints[:, [sk.LEFT_HAND, sk.RIGHT_HAND], 1] - joints[:, [sk.HEAD], 1]
    assert above[:, 1].max() > 0.1 and above[:, 0].max() < -0.3          # the right hand, not the left
    assert meta["contact_check"]["unsupported_s"] == 0 and meta["contact_check"]["skating_ratio"] < 0.1


def test_upper_body_on_measured_proportions_legs_untouched(wave):
    (joints, offsets, meta), (raw_joints, raw_offsets, _) = wave
    j = sk.JOINT_INDEX
    leg = np.linalg.norm(offsets[j["left_knee"]]) + np.linalg.norm(offsets[j["left_ankle"]])
    rest = sk.rest_joints(offsets)
    hips = (rest[j["left_hip"]] + rest[j["right_hip"]]) / 2
    shoulders = rest[[j["left_shoulder"], j["right_shoulder"]]]
    assert shoulders[:, 1].mean() - hips[1] == pytest.approx(UPPER_BODY["trunk"] * leg, rel=1e-4)
    assert np.linalg.norm(shoulders[0] - shoulders[1]) == pytest.approx(UPPER_BODY["shoulders"] * leg, rel=1e-4)
    # The figure as captured: a 0.50 trunk and a 0.25 shoulder width (module docstring).
    raw_rest = sk.rest_joints(raw_offsets)
    raw_leg = np.linalg.norm(raw_offsets[j["left_knee"]]) + np.linalg.norm(raw_offsets[j["left_ankle"]])
    assert np.linalg.norm(raw_rest[j["left_shoulder"]] - raw_rest[j["right_shoulder"]]) / raw_leg < 0.3
    legs = [j[n] for n in ("left_knee", "right_knee", "left_ankle", "right_ankle", "left_foot", "right_foot")]
    np.testing.assert_allclose(offsets[legs], raw_offsets[legs])
    # The same legs and root track, to a millimetre (the canonical yaw differs slightly: the
    # facing uses the shoulders too).
    np.testing.assert_allclose(joints[:, legs, 1], raw_joints[:, legs, 1], atol=1e-3)   # floor: ±0.2 mm
    dist = np.linalg.norm(joints[:, legs] - joints[:, [sk.PELVIS]], axis=-1)
    raw_dist = np.linalg.norm(raw_joints[:, legs] - raw_joints[:, [sk.PELVIS]], axis=-1)
    np.testing.assert_allclose(dist, raw_dist, atol=1e-3)    # ≤ 1 mm: the pelvis frame leans on spine1
    lengths = sk.bone_lengths(joints)
    assert np.abs(lengths - lengths[0]).max() < 1e-9


def test_frame_rate_evidence(wave):
    (_, _, meta), _ = wave
    ev = meta["fps_evidence"]
    assert set(ev) == {"30", "60"} and meta["fps_estimate"] == 30
    assert ev["60"]["speed"] == pytest.approx(2 * ev["30"]["speed"], abs=2e-3)     # rounded in meta
