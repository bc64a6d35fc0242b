"""CMU 8-action (38-joint exp-map text) → SMPL-22 on real files (tests/fixtures/raw, made by
tests/fixtures/make_fixtures.py): the walk moves forward at walking speed and cadence at the
chosen frame rate."""

from pathlib import Path

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import facing_angle
from interplay.motion.retarget.cmu_8action import (
    FPS_8ACTION,
    PROMPTS,
    ExpMapSkeleton,
    cmu_8action_prompt,
    forward_kinematics,
    load_cmu_8action,
    read_frames,
)

RAW = Path(__file__).resolve().parents[1] / "fixtures" / "raw" / "cmu-8action"
WALK = RAW / "train" / "walking" / "walking_4.txt"
RUN = RAW / "train" / "running" / "running_5.txt"


@pytest.fixture(scope="module")
def walk():
    return load_cmu_8action(WALK)


def forward_speed(joints):
    """Mean pelvis speed along +Z (the first frame's facing), m/s at 20 fps."""
    return (joints[-1, sk.PELVIS, 2] - joints[0, sk.PELVIS, 2]) / ((len(joints) - 1) / sk.FPS)


def cadence(joints, band=0.1):
    """Steps per second: the left-minus-right ankle separation along +Z swings through ±band
    once per step (hysteresis, so jitter near zero is not counted)."""
    sep = joints[:, sk.LEFT_ANKLE, 2] - joints[:, sk.RIGHT_ANKLE, 2]
    sep = sep - np.median(sep)
    state, flips = 0, []
    for t, s in enumerate(sep):
        side = 1 if s > band else -1 if s < -band else 0
        if side and side != state:
            if state:
                flips.append(t)
            state = side
    assert len(flips) >= 3, "too few steps to measure"
    return (len(flips) - 1) / ((flips[-1] - flips[0]) / sk.FPS)


def test_reads_the_file_and_drops_the_rest_line():
    values = read_frames(WALK)
    assert values.shape[1] == 117
    assert (values[0, 3:] == 0).mean() > 0.9 and (values[1, 3:] == 0).mean() < 0.5
    joints, offsets, meta = load_cmu_8action(WALK)
    assert meta["dropped_rest_frames"] == 1 and meta["source_frames"] == len(values) - 1
    assert meta["source_fps"] == FPS_8ACTION == 120
    assert joints.shape == ((len(values) - 2) // 6 + 1, 22, 3) and offsets.shape == (22, 3)
    assert meta["fit_error_m"] < 0.02


def test_fk_follows_the_row_vector_convention():
    skel = ExpMapSkeleton.from_json(RAW / "skeleton.json")
    values = read_frames(WALK)[1:4]
    pos = forward_kinematics(values, skel)
    # Bones keep their rest lengths; the root sits at its position × 70.
    for j, p in enumerate(skel.parents):
        if p >= 0:
            np.testing.assert_allclose(np.linalg.norm(pos[:, j] - pos[:, p], axis=-1),
                                       np.linalg.norm(skel.offsets[j]), rtol=1e-9)
    np.testing.assert_allclose(pos[:, 0], values[:, :3] * 70)
    # A rotation at the root turns every child offset with it (row vector · Rg).
    rot = values.copy()
    rot[:, 3:] = 0
    rot[:, 3:6] = [0, np.pi / 2, 0]                  # root: 90° about +y
    p = forward_kinematics(rot, skel)
    # Row-vector v · Rg is Rgᵀ v: the left hip offset (+x) turns to +z, not -z.
    hip = p[0, 2] - p[0, 0]
    np.testing.assert_allclose(hip, [-skel.offsets[2, 2], skel.offsets[2, 1], skel.offsets[2, 0]], atol=1e-9)


def test_walk_moves_forward_at_walking_speed_and_cadence(walk):
    joints = walk[0]
    assert abs(facing_angle(joints[0])) < 1e-6
    speed = forward_speed(joints)
    assert 1.0 < speed < 1.6                                   # m/s
    assert abs(joints[-1, sk.PELVIS, 0]) < 0.3 * joints[-1, sk.PELVIS, 2]   # straight ahead
    assert 1.6 < cadence(joints) < 2.2                         # steps/s
    # Read as 60 fps, the same walk would be half as fast and half the cadence: not a walk.
    slow = load_cmu_8action(WALK, fps=60)[0]
    assert forward_speed(slow) == pytest.approx(speed / 2, rel=0.05)
    assert cadence(slow) < 1.2


def test_run_is_faster_than_the_walk(walk):
    run = load_cmu_8action(RUN)[0]
    assert forward_speed(run) > 2.0 > forward_speed(walk[0])


def test_plausible_body_rigid_bones_feet_on_floor(walk):
    joints, offsets, _ = walk
    first = joints[0]
    assert 0.85 < first[sk.PELVIS, 1] < 1.1
    assert 1.35 < first[sk.HEAD, 1] < 1.7
    assert first[sk.LEFT_HIP, 0] > first[sk.RIGHT_HIP, 0]
    lengths = sk.bone_lengths(joints)
    np.testing.assert_allclose(lengths, np.broadcast_to(lengths[0], lengths.shape), atol=1e-9)
    lowest_foot = joints[:, list(sk.FOOT_JOINTS), 1].min(axis=1)
    assert lowest_foot.min() > -0.02 and np.mean(lowest_foot < 0.05) > 0.6


def test_thorax_restored_gives_human_torso_proportions(walk):
    def torso_to_leg(joints):
        j = joints[0]
        return (j[sk.NECK, 1] - j[sk.PELVIS, 1]) / (j[sk.PELVIS, 1] - j[sk.LEFT_ANKLE, 1])
    # HDM05 clips measure 0.50–0.54 on their standing first frames; the file's torso is 12 cm short.
    assert 0.45 < torso_to_leg(walk[0]) < 0.6
    assert torso_to_leg(load_cmu_8action(WALK, restore_thorax=False)[0]) < 0.42


def test_bad_input(tmp_path):
    bad = tmp_path / "bad.txt"
    bad.write_text("1,2,3\n")
    with pytest.raises(ValueError, match="117"):
        read_frames(bad)
    with pytest.raises(ValueError, match="skeleton.json"):
        load_cmu_8action(bad)
    with pytest.raises(ValueError, match="fps"):
        load_cmu_8action(WALK, fps=0)


def test_prompts():
    actions = ["basketball", "basketball_signal", "directing_traffic", "jumping", "running",
               "soccer", "walking", "washwindow"]
    assert len({cmu_8action_prompt(a) for a in actions}) == 8 and set(PROMPTS) == set(actions)
    assert cmu_8action_prompt("walking_3") == cmu_8action_prompt("walking_extra") == "a person walks forward"
    assert cmu_8action_prompt("basketball_signal") != cmu_8action_prompt("basketball")
    with pytest.raises(ValueError, match="unknown"):
        cmu_8action_prompt("swimming")
