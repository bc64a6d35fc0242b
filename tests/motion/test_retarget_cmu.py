from pathlib import Path

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.formats.bvh import read_bvh
from interplay.motion.kinematics import facing_direction
from interplay.motion.retarget import map_joints
from interplay.motion.retarget.cmu_daz import (
    CENTIMETRE,
    DAZ_MAP,
    SALSA_SCALED_UNIT,
    file_unit,
    load_cmu_bvh,
    load_salsa_pair,
    read_cmu_index,
    rest_height,
    skeleton_family,
)
from interplay.motion.retarget.frame_rate import (
    MAX_COM_ACCELERATION,
    SALSA_FPS,
    estimate_true_fps,
    gait_stats,
    lead_in_frames,
)

RAW = Path(__file__).resolve().parents[2] / "tests" / "fixtures" / "raw"
BVH = RAW / "cmu-bvh"
SALSA = (RAW / "cmu-salsa" / "60" / "60_01_scaled.bvh", RAW / "cmu-salsa" / "61" / "61_01_scaled.bvh")


@pytest.fixture(scope="module")
def walk():
    return load_cmu_bvh(BVH / "02" / "02_01.bvh")


@pytest.fixture(scope="module")
def salsa():
    return load_salsa_pair(*SALSA)


def test_walk_is_a_person_standing_on_the_floor_facing_plus_z(walk):
    joints, offsets, meta = walk
    assert joints.shape[1:] == (22, 3) and meta["native_fps"] == 120
    # 344 frames at 120 fps minus the T-pose lead-in → ~2.8 s at 20 fps.
    assert 50 <= joints.shape[0] <= 58 and meta["lead_in_frames"] > 0
    # The SMPL head joint sits ~0.15 m below the crown: 1.35–1.75 m ⇔ a 1.5–1.9 m person.
    head = np.median(joints[:, sk.HEAD, 1])
    assert 1.35 < head < 1.75
    lowest = joints[..., 1].min(axis=1)
    assert abs(np.percentile(lowest, 2)) < 1e-6 and np.median(lowest) < 0.06      # feet on y≈0
    assert facing_direction(joints[0])[2] > 0.99 and np.allclose(joints[0, sk.PELVIS, [0, 2]], 0)
    travel = joints[-1, sk.PELVIS] - joints[0, sk.PELVIS]
    assert travel[2] > 2.5 and abs(travel[0]) < 0.25 * travel[2]                   # forward, +Z
    speed = travel[2] / ((len(joints) - 1) / sk.FPS)
    assert 1.0 < speed < 1.6                                                        # m/s, a walk
    lengths = sk.bone_lengths(joints)
    assert np.abs(lengths - lengths[0]).max() < 1e-9
    assert np.allclose(sk.bone_lengths(sk.rest_joints(offsets)), lengths[0])
    # Left is +X when facing +Z.
    assert joints[0, sk.LEFT_SHOULDER, 0] > 0 > joints[0, sk.RIGHT_SHOULDER, 0]
    assert meta["fit_error_mean_mm"] < 1.0 and meta["fit_error_max_mm"] < 5.0
    assert meta["defects"] == []


def test_daz_joint_map_gives_smpl_like_proportions(walk):
    joints, offsets, _ = walk
    rest = sk.rest_joints(offsets)
    ours = rest[:, 1] - rest[sk.PELVIS, 1]
    smpl = sk.rest_joints()[:, 1] - sk.rest_joints()[sk.PELVIS, 1]
    # Heights of the spine, neck and head above the pelvis as fractions of pelvis→head.
    spine = [sk.JOINT_INDEX[n] for n in ("spine1", "spine2", "spine3", "neck")]
    assert np.allclose(ours[spine] / ours[sk.HEAD], smpl[spine] / smpl[sk.HEAD], atol=0.06)
    # SMPL's foot joint is the ball of the foot: ahead of and below the ankle.
    foot = rest[sk.LEFT_FOOT] - rest[sk.LEFT_ANKLE]
    assert foot[2] > 0.08 and foot[1] < 0


def test_run_is_a_run_at_120_fps_with_gravity_in_its_flight_phases():
    joints, _, meta = load_cmu_bvh(BVH / "09" / "09_01.bvh")
    assert meta["native_fps"] == 120 and meta["fps_estimate"] == 120
    g = meta["fps_evidence"]["120"]["flight_gravity"]
    assert 6 < g < 16                                              # free fall ≈ 9.81 m/s²
    speed = np.linalg.norm(joints[-1, 0, [0, 2]] - joints[0, 0, [0, 2]]) / ((len(joints) - 1) / sk.FPS)
    assert 2.5 < speed < 4.5


def test_acclaim_named_jump_with_a_wrong_header_is_read_at_120_fps():
    bvh = read_bvh(BVH / "16" / "16_01.bvh")
    assert skeleton_family(bvh) == "acclaim" and bvh.fps == pytest.approx(30, rel=1e-3)
    joints, _, meta = load_cmu_bvh(BVH / "16" / "16_01.bvh")
    # Gravity in the flight phase says 120 (the index's rate), not the header's 30.
    assert meta["native_fps"] == 120 and meta["header_fps"] == pytest.approx(30, rel=1e-3)
    assert 6 < meta["fps_evidence"]["120"]["flight_gravity"] < 16
    assert meta["fps_evidence"]["60"]["flight_gravity"] < 6
    assert 1.35 < np.median(joints[:, sk.HEAD, 1]) < 1.75
    lengths = sk.bone_lengths(joints)
    assert np.abs(lengths - lengths[0]).max() < 1e-9
    # The dropped thorax bone is restored: shoulders sit well above spine3.
    assert np.median(joints[:, sk.LEFT_SHOULDER, 1] - joints[:, sk.JOINT_INDEX["spine3"], 1]) > 0.08


def test_broken_root_track_is_reported_as_a_defect():
    _, _, meta = load_cmu_bvh(BVH / "07" / "07_12.bvh")
    assert meta["defects"] and "root" in meta["defects"][0]
    assert all(s["com_acceleration_p99"] > MAX_COM_ACCELERATION for s in meta["fps_evidence"].values())


def test_units_cm_for_cmu_bvh_and_cm_over_128_for_salsa():
    walk, lead = read_bvh(BVH / "02" / "02_01.bvh"), read_bvh(SALSA[0])
    assert file_unit(walk, "daz") == CENTIMETRE and file_unit(lead, "daz") == SALSA_SCALED_UNIT
    # Same figure: the salsa offsets are the cmu-bvh ones / 128 …
    assert np.allclose(lead.offsets * 128, walk.offsets, atol=1e-3)
    # … so read as metres the dancers would be 1.2 m to the eyes; converted, both are 1.53 m.
    assert rest_height(lead) < 1.25
    assert rest_height(lead) * SALSA_SCALED_UNIT == pytest.approx(rest_height(walk) * CENTIMETRE, abs=1e-3)


def test_salsa_pair_shares_one_world_at_60_fps(salsa):
    (lead, follow), offsets, meta = salsa
    assert lead.shape == follow.shape and meta["native_fps"] == SALSA_FPS
    # 900 frames at 60 fps minus the lead-in: ~15 s.
    assert 14.5 < len(lead) / sk.FPS <= 15.0
    assert meta["fps_estimate"] == [60, 60]
    # One transform: the lead is canonical, the follow is placed relative to the lead.
    assert np.allclose(lead[0, sk.PELVIS, [0, 2]], 0) and facing_direction(lead[0])[2] > 0.99
    assert np.linalg.norm(follow[0, sk.PELVIS, [0, 2]]) > 0.2
    # They start ~2 m apart, walk up to each other and dance at 0.5–1 m, never closer than
    # 0.3 m (bodies would overlap) nor further than arm's reach after meeting.
    dist = np.linalg.norm(lead[:, sk.PELVIS, [0, 2]] - follow[:, sk.PELVIS, [0, 2]], axis=-1)
    assert 0.3 < dist.min() and dist.max() < 2.3 and np.median(dist) < 1.0
    met = int(np.argmax(dist < 1.0))
    assert 0 < met and dist[met:].max() < 2.0
    # Facing each other most of the time.
    facing = np.sum(facing_direction(lead) * facing_direction(follow), axis=-1)
    assert np.mean(facing < 0) > 0.5
    for people in (lead, follow):
        lengths = sk.bone_lengths(people)
        assert np.abs(lengths - lengths[0]).max() < 1e-9
        assert 1.3 < np.median(people[:, sk.HEAD, 1]) < 1.75
    assert np.percentile(np.concatenate([lead, follow])[..., 1].min(axis=1), 50) < 0.06
    assert max(meta["fit_error_mean_mm"]) < 1.0 and max(meta["fit_error_max_mm"]) < 20
    assert meta["defects"] == []


def test_salsa_is_physical_at_60_fps_and_not_at_the_headers_120():
    bvh = read_bvh(SALSA[1])                         # the follow: the faster mover
    assert bvh.fps == pytest.approx(120, rel=1e-3)
    named = {k: v * SALSA_SCALED_UNIT for k, v in bvh.named_positions().items()}
    joints = map_joints(named, DAZ_MAP)
    joints = joints[lead_in_frames(joints):]
    at60, at120 = gait_stats(joints, 60), gait_stats(joints, 120)
    assert at60["com_acceleration_p99"] < MAX_COM_ACCELERATION < at120["com_acceleration_p99"]
    assert 1.0 < at60["cadence"] < 2.5 and 0.3 < at60["speed"] < 1.0
    assert estimate_true_fps(joints, prior=120)[0] == 60


def test_walk_cadence_and_speed_are_human_at_120_fps_only():
    bvh = read_bvh(BVH / "02" / "02_01.bvh")
    joints = map_joints({k: v * CENTIMETRE for k, v in bvh.named_positions().items()}, DAZ_MAP)
    joints = joints[lead_in_frames(joints):]
    at120, at60 = gait_stats(joints, 120), gait_stats(joints, 60)
    assert 1.2 < at120["cadence"] < 2.4 and 1.0 < at120["speed"] < 1.7
    assert at60["speed"] < 0.7                                     # too slow for a walk


def test_read_cmu_index():
    index = read_cmu_index(RAW / "cmu-index" / "cmu_index.csv")
    assert index[(2, 1)] == ("walk", 120)
    assert index[(9, 1)] == ("run", 120)
    assert index[(60, 1)] == ("salsa dance", 60) and index[(61, 15)] == ("salsa dance", 60)
    assert all(isinstance(k[0], int) and isinstance(v[1], int) for k, v in index.items())


def test_read_cmu_index_rejects_other_csv(tmp_path):
    bad = tmp_path / "x.csv"
    bad.write_text("a,b\n1,2\n")
    with pytest.raises(ValueError, match="header"):
        read_cmu_index(bad)
