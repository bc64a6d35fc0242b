"""CMU on Reallusion's CC_Base rig → SMPL-22 on a committed (cut) raw file: twist, finger and
face bones ignored, 60 fps kept, the T-pose test."""

from pathlib import Path

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.formats.bvh import read_bvh
from interplay.motion.kinematics import facing_direction
from interplay.motion.retarget import map_joints
from interplay.motion.retarget.cmu_iclone import (
    CENTIMETRE,
    JOINT_MAP,
    is_tpose,
    load_cmu_iclone,
    read_cmu_index,
    tpose_lead_in,
    trial_of,
)

RAW = Path(__file__).resolve().parents[1] / "fixtures" / "raw" / "cmu-iclone"
DRIBBLE = RAW / "subjects" / "006" / "006_08.bvh"     # "basketball - sideways dribble", cut to 50 frames


@pytest.fixture(scope="module")
def dribble():
    return load_cmu_iclone(DRIBBLE)


def test_cc_base_dribble_stands_on_the_floor_facing_plus_z(dribble):
    joints, offsets, meta = dribble
    assert meta["source_fps"] == 60 and meta["header_fps"] == pytest.approx(60, abs=0.01)
    assert len(joints) == (50 - 1) * 20 // 60 + 1 and meta["tpose_frames_dropped"] == 0
    assert meta["defects"] == [] and meta["root"] in ("CC_Base_Hip", "RL_BoneRoot")
    first = joints[0]
    assert facing_direction(first)[2] > 0.99 and first[sk.LEFT_HIP, 0] > first[sk.RIGHT_HIP, 0]
    assert 1.4 < first[sk.HEAD, 1] < 1.75 and np.median(joints[..., 1].min(axis=1)) < 0.05
    lengths = sk.bone_lengths(joints)
    assert np.abs(lengths - lengths[0]).max() < 1e-9
    # Spine joints climb in SMPL's order, the neck above the shoulders.
    rest = sk.rest_joints(offsets)
    chain = [sk.JOINT_INDEX[n] for n in ("pelvis", "spine1", "spine2", "spine3", "neck", "head")]
    assert np.all(np.diff(rest[chain, 1]) > 0) and rest[sk.NECK, 1] > rest[sk.LEFT_SHOULDER, 1]


def test_index_labels_and_trial_names():
    index = read_cmu_index(RAW / "CMU data.csv")
    assert index[6, 8] == ("basketball - sideways dribble", 120)
    assert trial_of(DRIBBLE) == (6, 8)


def test_tpose_detection():
    named = read_bvh(DRIBBLE).named_positions(include_end_sites=False)
    native = map_joints(named, JOINT_MAP) * CENTIMETRE
    assert not is_tpose(native[0]) and tpose_lead_in(native) == 0   # these exports start mid-motion
    # A T-pose frame put in front: arms out level, then a jump into the motion.
    tpose = native[0].copy()
    across = tpose[sk.LEFT_SHOULDER] - tpose[sk.RIGHT_SHOULDER]
    across[1] = 0.0
    across /= np.linalg.norm(across)
    for s, w, e, side in ((sk.LEFT_SHOULDER, sk.LEFT_HAND, sk.JOINT_INDEX["left_elbow"], 1),
                          (sk.RIGHT_SHOULDER, sk.RIGHT_HAND, sk.JOINT_INDEX["right_elbow"], -1)):
        arm = np.linalg.norm(native[0, w] - native[0, s])
        tpose[e] = tpose[s] + side * across * arm / 2
        tpose[w] = tpose[s] + side * across * arm
    assert is_tpose(tpose) and tpose_lead_in(np.concatenate([tpose[None], native])) == 1
