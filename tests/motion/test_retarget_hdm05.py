"""HDM05 → SMPL-22 on real clips (tests/fixtures/raw, made by tests/fixtures/make_fixtures.py)."""

from pathlib import Path

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import facing_angle
from interplay.motion.retarget import hdm05
from interplay.motion.retarget.hdm05 import HDM05_PROMPTS, hdm05_class, hdm05_prompt, load_hdm05

RAW = Path(__file__).resolve().parents[1] / "fixtures" / "raw" / "hdm05"
CLIPS = {
    "squat": ("squat1Reps/HDM_bd_squat1Reps_003_120.amc", "bd"),
    "kick": ("kickLFront1Reps/HDM_bk_kickLFront1Reps_011_120.amc", "bk"),
    "jog": ("jogLeftCircle4StepsRstart/HDM_bd_jogLeftCircle4StepsRstart_001_120.amc", "bd"),
}


@pytest.fixture(scope="module")
def clips():
    return {k: load_hdm05(RAW / f, RAW / "asf" / f"HDM_{a}.asf") for k, (f, a) in CLIPS.items()}


def test_shapes_rate_and_meta(clips):
    for name, (joints, offsets, meta) in clips.items():
        assert joints.shape[1:] == (22, 3) and offsets.shape == (22, 3)
        assert meta["source_fps"] == 120
        # 120 → 20 fps: one output frame per six source frames.
        assert joints.shape[0] == (meta["source_frames"] - 1) // 6 + 1
        assert meta["metres_per_unit"] == pytest.approx(0.0254 / 0.45)
        assert meta["fit_error_m"] < 0.03, name
    assert clips["kick"][2]["class"] == "kickLFront"


def test_canonical_frame_and_plausible_body(clips):
    for name, (joints, _offsets, _) in clips.items():
        first = joints[0]
        assert abs(facing_angle(first)) < 1e-6, name
        np.testing.assert_allclose(first[sk.PELVIS, [0, 2]], 0, atol=1e-9)
        assert first[sk.LEFT_HIP, 0] > first[sk.RIGHT_HIP, 0]        # left is +X when facing +Z
        # Standing first frame: pelvis ~1 m up, skull base (SMPL head) 1.35–1.75 m.
        assert 0.85 < first[sk.PELVIS, 1] < 1.15, name
        assert 1.35 < first[sk.HEAD, 1] - first[:, 1].min() < 1.75, name
        assert first[sk.HEAD, 1] > first[sk.NECK, 1] > first[sk.JOINT_INDEX["spine3"], 1] > first[sk.PELVIS, 1]


def test_bones_rigid_and_feet_on_floor(clips):
    for name, (joints, offsets, _) in clips.items():
        lengths = sk.bone_lengths(joints)
        np.testing.assert_allclose(lengths, np.broadcast_to(lengths[0], lengths.shape), atol=1e-9)
        np.testing.assert_allclose(lengths[0], [np.linalg.norm(offsets[c]) for c, _ in sk.BONES], atol=1e-9)
        lowest_foot = joints[:, list(sk.FOOT_JOINTS), 1].min(axis=1)
        assert lowest_foot.min() > -0.02, name                      # nothing sinks into the floor
        assert np.mean(lowest_foot < 0.05) > 0.7, name              # a foot is down most of the time


def test_squat_lowers_the_pelvis(clips):
    pelvis = clips["squat"][0][:, sk.PELVIS, 1]
    assert pelvis.min() < 0.6 * pelvis[0]
    assert pelvis[-1] > 0.9 * pelvis[0]                             # and stands back up
    assert 0.2 * len(pelvis) < pelvis.argmin() < 0.8 * len(pelvis)


def test_kick_raises_the_left_foot_forward(clips):
    joints = clips["kick"][0]
    left, right = joints[:, sk.LEFT_ANKLE, 1], joints[:, sk.RIGHT_ANKLE, 1]
    assert left.max() > 0.5 and right.max() < 0.2
    peak = left.argmax()
    assert joints[peak, sk.LEFT_FOOT, 2] - joints[peak, sk.PELVIS, 2] > 0.5   # forward is +Z


def test_jog_circles_to_the_left(clips):
    joints = clips["jog"][0]
    heading = np.unwrap(facing_angle(joints))                      # positive: turning towards +X, the left
    assert heading[-1] - heading[0] > np.radians(45)
    path = np.linalg.norm(np.diff(joints[:, sk.PELVIS, [0, 2]], axis=0), axis=-1).sum()
    assert path / ((len(joints) - 1) / sk.FPS) > 1.0               # jogging pace, m/s


def test_joint_map_covers_smpl():
    assert set(hdm05.JOINT_MAP) == set(sk.JOINT_NAMES)
    for src in hdm05.JOINT_MAP.values():
        if not isinstance(src, str):
            assert sum(w for _, w in src) == pytest.approx(1.0)


def test_prompts_for_classes_and_folder_spellings():
    folders = ["depositFloorR", "elbowToKnee1RepsLelbowStart", "grabHighR", "hopBothLegs1hops",
               "jogLeftCircle4StepsRstart", "kickLFront1Reps", "lieDownFloor",
               "rotateArmsBothBackward1Reps", "sneak2StepsLStart", "squat1Reps", "throwBasketball"]
    prompts = [hdm05_prompt(f) for f in folders]
    assert len(set(prompts)) == 11 and set(prompts) == set(HDM05_PROMPTS.values())
    assert hdm05_prompt("kickLFront1Reps") == "a person kicks forward with the left foot"
    assert hdm05_prompt("jogLeftCircle4StepsRstart") == "a person jogs in a circle to the left"
    assert hdm05_class("HDM_bd_sneak2StepsLStart_001_120") == "sneak"
    for prompt in prompts:                                          # the docstring table is complete
        assert prompt in hdm05.__doc__
    with pytest.raises(ValueError, match="unknown HDM05 class"):
        hdm05_prompt("cartwheel")
