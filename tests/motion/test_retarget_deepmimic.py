"""DeepMimic's humanoid → SMPL-22 on committed clips: the character's FK, virtual joints, the
stated per-frame timing kept (with the centre of mass falling at gravity's rate)."""

from pathlib import Path

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import facing_direction
from interplay.motion.retarget.checks import gravity_agrees
from interplay.motion.retarget.deepmimic import (
    PROMPTS,
    Character,
    deepmimic_prompt,
    find_character,
    load_deepmimic,
    resample_times,
)

RAW = Path(__file__).resolve().parents[1] / "fixtures" / "raw" / "deepmimic"
JUMP, BACKFLIP = RAW / "motions" / "humanoid3d_jump.txt", RAW / "motions" / "humanoid3d_backflip.txt"


@pytest.fixture(scope="module")
def clips():
    return {"jump": load_deepmimic(JUMP), "backflip": load_deepmimic(BACKFLIP)}


def test_character_tree():
    char = Character.read(find_character(JUMP))
    assert char.names[:3] == ("root", "chest", "neck") and char.values_per_frame == 44
    assert char.kinds[char.names.index("right_knee")] == "revolute"
    assert char.offsets[char.names.index("right_hip"), 2] > 0          # right side at +Z


def test_standing_start_on_the_floor_facing_plus_z(clips):
    for name, (joints, offsets, meta) in clips.items():
        assert joints.shape[1:] == (22, 3) and meta["defects"] == [], name
        first = joints[0]
        assert facing_direction(first)[2] > 0.99 and np.allclose(first[sk.PELVIS, [0, 2]], 0)
        assert first[sk.LEFT_HIP, 0] > first[sk.RIGHT_HIP, 0]               # left is +X
        assert 1.2 < first[sk.HEAD, 1] < 1.6 and 0.8 < first[sk.PELVIS, 1] < 1.1, name
        assert abs(np.percentile(joints[..., 1].min(axis=1), 2)) < 1e-6
        foot = sk.rest_joints(offsets)[sk.LEFT_FOOT] - sk.rest_joints(offsets)[sk.LEFT_ANKLE]
        assert foot[2] > 0.05 and foot[1] < 0                               # ball of the foot, ahead
        lengths = sk.bone_lengths(joints)
        assert np.abs(lengths - lengths[0]).max() < 1e-9


def test_stated_timing_kept_and_gravity_agrees(clips):
    jump, backflip = clips["jump"][2], clips["backflip"][2]
    assert jump["source_fps"] == 60 and backflip["source_fps"] == 16
    # 106 frames of 1/60 s → 1.77 s → 36 frames at 20 fps.
    assert len(clips["jump"][0]) == 36
    assert gravity_agrees(jump, 60) and gravity_agrees(backflip, 16)
    assert not gravity_agrees(backflip, 32) and not gravity_agrees(backflip, 8)
    # The pelvis-based estimate would retime the flip (the pelvis turns about the COM).
    assert backflip["fps_estimate"] != 16
    # The backflip goes backwards and over: feet above the head mid-air.
    joints = clips["backflip"][0]
    assert joints[-1, sk.PELVIS, 2] < -0.5
    assert (joints[:, sk.LEFT_FOOT, 1] > joints[:, sk.HEAD, 1]).any()


def test_prompts_and_resampling():
    assert deepmimic_prompt("spinkick") == "a person does a spinning kick"
    assert deepmimic_prompt("humanoid3d_walk.txt") == PROMPTS["walk"]
    x = np.arange(5.0)[:, None]
    out = resample_times(x, np.array([0.0, 0.1, 0.2, 0.35, 0.4]), fps=10)
    np.testing.assert_allclose(out[:, 0], [0, 1, 2, 2 + 2 / 3, 4])
