"""Motion features: layout, invariances, exact decoding (synthetic FK motions and every real clip
of the processed set), foot contacts on real walks, part masks and the normalizer."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.motion import features as F
from interplay.motion import skeleton as sk
from interplay.motion.clip import DATA_DIR, default_clips
from interplay.motion.kinematics import forward_kinematics
from interplay.motion.rotations import axis_angle_to_matrix, yaw_matrix

HAVE_DATA = (DATA_DIR / "index.json").exists()
needs_data = pytest.mark.skipif(not HAVE_DATA, reason=f"processed data set not built yet: no "
                                f"{DATA_DIR / 'index.json'} (run `make data`)")


def synthetic_motion(frames: int, seed: int = 0, fps: int = sk.FPS, with_rotations: bool = False):
    """FK on the rest skeleton of smooth random local rotations (sums of sinusoids), with the
    body turning (~0.3 rad/s plus a wobble) and walking forward along its heading."""
    rng = np.random.default_rng(seed)
    t = np.arange(frames) / fps
    shape = (3, sk.NUM_JOINTS, 3)
    freq, phase, amp = rng.uniform(0.2, 1.5, shape), rng.uniform(0, 2 * np.pi, shape), rng.uniform(0.05, 0.4, shape)
    aa = (amp * np.sin(2 * np.pi * freq * t[:, None, None, None] + phase)).sum(axis=1)
    local = axis_angle_to_matrix(aa)
    yaw = 0.3 * t + 0.5 * np.sin(0.7 * t) + rng.uniform(-np.pi, np.pi)
    local[:, sk.PELVIS] = yaw_matrix(yaw) @ local[:, sk.PELVIS]
    forward = np.stack([np.sin(yaw), np.zeros(frames), np.cos(yaw)], axis=-1)
    root = np.cumsum(forward * 1.3 / fps, axis=0) + rng.uniform(-3, 3, 3)
    root[:, 1] = 0.9 + 0.05 * np.sin(3 * t)
    joints, _ = forward_kinematics(local, root, sk.REST_OFFSETS)
    return (joints, local) if with_rotations else joints


def test_layout_is_contiguous_and_named():
    spans = sorted((s.start, s.stop) for s in F.SLICES.values())
    assert spans[0][0] == 0 and spans[-1][1] == F.FEATURE_DIM
    assert all(a[1] == b[0] for a, b in zip(spans, spans[1:]))
    assert F.SLICES["rotations"].stop - F.SLICES["rotations"].start == 6 * len(F.ROT_JOINTS)
    # Leaves (toes, head, wrists) carry no rotation; every parent does.
    assert set(F.ROT_JOINTS) == {p for p in sk.PARENTS if p >= 0}


def test_minute_long_synthetic_round_trip_does_not_drift():
    joints = synthetic_motion(60 * sk.FPS, seed=1)
    feats = F.encode(joints, sk.REST_OFFSETS)
    assert feats.shape == (len(joints), F.FEATURE_DIM) and feats.dtype == np.float32
    back = F.decode(feats, sk.REST_OFFSETS, start=F.start_of(joints))
    err = np.linalg.norm(back - joints, axis=-1)
    # float32 features, float64 integration: after ~80 m of walking in turns, still exact.
    assert err.max() < 1e-4, err.max()
    assert np.linalg.norm(np.diff(joints[:, 0, [0, 2]], axis=0), axis=-1).sum() > 50.0


def test_decode_without_offsets_fits_them_and_uses_rest_skeleton():
    joints = synthetic_motion(100, seed=2)
    back = F.decode(F.encode(joints), start=F.start_of(joints))  # offsets fit, then rest
    assert np.abs(back - joints).max() < 1e-4


def test_given_rotations_keep_their_twist():
    joints, local = synthetic_motion(100, seed=9, with_rotations=True)
    feats = F.encode(joints, rotations=local)
    rot = F.SLICES["rotations"]
    # The 6D block is the given rotations (twist about bones included), not IK's swing-only ones.
    assert np.abs(feats[:, rot] - F.encode(joints, sk.REST_OFFSETS)[:, rot]).max() > 0.1
    elbow = sk.JOINT_INDEX["left_elbow"]
    np.testing.assert_allclose(feats[:, rot].reshape(100, -1, 6)[:, F.ROT_JOINTS.index(elbow)],
                               np.concatenate([local[:, elbow, :, 0], local[:, elbow, :, 1]], -1), atol=1e-6)
    assert np.abs(F.decode(feats, start=F.start_of(joints)) - joints).max() < 1e-4


def test_features_invariant_to_yaw_and_ground_translation():
    joints = synthetic_motion(150, seed=3)
    feats = F.encode(joints)
    for angle, shift in [(0.9, (2.0, 0.0, -5.0)), (-2.5, (-0.3, 0.0, 7.0)), (np.pi, (0.0, 0.0, 0.0))]:
        moved = joints @ yaw_matrix(angle).T + np.array(shift)
        assert np.abs(F.encode(moved) - feats).max() < 1e-5, angle
        # Decoding from the moved start lands exactly on the moved motion.
        assert np.abs(F.decode(feats, start=F.start_of(moved)) - moved).max() < 1e-4


def test_height_shift_changes_only_heights():
    joints = synthetic_motion(80, seed=4)
    diff = np.abs(F.encode(joints + [0.0, 0.3, 0.0]) - F.encode(joints)) > 1e-5
    changed = np.flatnonzero(diff.any(axis=0))
    pos_y = np.arange(F.SLICES["positions"].start + 1, F.SLICES["positions"].stop, 3)
    contacts = np.arange(F.SLICES["foot_contacts"].start, F.FEATURE_DIM)
    assert F.SLICES["root_height"].start in changed
    assert set(changed) <= {F.SLICES["root_height"].start, *pos_y, *contacts}


def test_decoded_bones_keep_their_lengths_even_for_noisy_features():
    joints = synthetic_motion(60, seed=5)
    noisy = F.encode(joints) + np.random.default_rng(0).normal(0, 0.3, (60, F.FEATURE_DIM))
    offsets = sk.REST_OFFSETS * 1.1
    out = F.decode(noisy.astype(np.float32), offsets)
    want = sk.bone_lengths(sk.rest_joints(offsets))
    assert np.abs(sk.bone_lengths(out) - want).max() < 1e-9


def test_last_frame_repeats_velocities_and_prefixes_agree():
    joints = synthetic_motion(50, seed=6)
    feats, head = F.encode(joints, sk.REST_OFFSETS), F.encode(joints[:30], sk.REST_OFFSETS)
    assert head.shape == (30, F.FEATURE_DIM)
    # All but the prefix's last row match the full clip; there the velocities repeat.
    assert np.abs(head[:-1] - feats[:29]).max() < 1e-5
    for name in ("root_angvel", "root_linvel"):
        s = F.SLICES[name]
        np.testing.assert_array_equal(head[-1, s], head[-2, s])
    one = F.encode(joints[:1], sk.REST_OFFSETS)
    assert one.shape == (1, F.FEATURE_DIM) and not one[0, F.SLICES["velocities"]].any()
    assert np.abs(F.decode(one, sk.REST_OFFSETS, F.start_of(joints)) - joints[:1]).max() < 1e-5


def test_bad_shapes_raise_clear_errors():
    with pytest.raises(ValueError, match="joints must be"):
        F.encode(np.zeros((10, 21, 3)))
    with pytest.raises(ValueError, match="features must be"):
        F.decode(np.zeros((10, F.FEATURE_DIM - 1)))
    with pytest.raises(ValueError, match="offsets must be"):
        F.decode(np.zeros((10, F.FEATURE_DIM)), offsets=np.zeros((21, 3)))
    with pytest.raises(ValueError, match="start must be"):
        F.decode(np.zeros((10, F.FEATURE_DIM)), start=(0.0, 0.0))
    with pytest.raises(ValueError, match="rotations must be"):
        F.encode(np.zeros((10, 22, 3)), rotations=np.zeros((9, 22, 3, 3)))


def test_part_masks_follow_coma_parts():
    masks = {p: F.part_feature_mask(p) for p in sk.PART_NAMES}
    assert np.logical_or.reduce(list(masks.values())).all()       # every dim has a part
    root = np.r_[F.SLICES["root_angvel"], F.SLICES["root_linvel"], F.SLICES["root_height"]]
    assert masks["left_lower"][root].all() and masks["right_lower"][root].all()
    assert not masks["left_upper"][root].any() and not masks["right_upper"][root].any()
    contacts = masks["left_lower"][F.SLICES["foot_contacts"]]
    np.testing.assert_array_equal(contacts, [True, True, False, False])
    # The arms' dims are disjoint; the shared torso is exactly the spine, neck and head.
    both = masks["left_upper"] & masks["right_upper"]
    torso = {sk.JOINT_INDEX[n] for n in ("spine1", "spine2", "spine3", "neck", "head")}
    pos = F.SLICES["positions"]
    shared = {1 + i // 3 for i in np.flatnonzero(both[pos])}
    assert shared == torso
    np.testing.assert_array_equal(F.part_feature_mask("left arm"), masks["left_upper"])
    with pytest.raises(ValueError):
        F.part_feature_mask("tail")


def test_normalizer_fits_saves_and_inverts(tmp_path):
    feats = [F.encode(synthetic_motion(n, seed=s)) for s, n in ((7, 90), (8, 120))]
    norm = F.Normalizer.fit(feats)
    z = norm.normalize(np.concatenate(feats))
    varying = np.concatenate(feats).std(axis=0) > 1e-2
    assert np.abs(z.mean(axis=0)).max() < 1e-3
    np.testing.assert_allclose(z.std(axis=0)[varying], 1.0, atol=1e-3)
    assert np.isfinite(z).all()
    norm.save(tmp_path / "norm.npz")
    again = F.Normalizer.load(tmp_path / "norm.npz")
    np.testing.assert_array_equal(again.mean, norm.mean)
    assert again.meta["frames"] == 210
    np.testing.assert_allclose(again.denormalize(z), np.concatenate(feats), atol=1e-4)
    pooled = F.Normalizer.fit(feats, pooled=True)
    assert len(np.unique(pooled.std[F.SLICES["positions"]])) == 1


@needs_data
def test_round_trip_on_every_real_clip():
    clips = default_clips()
    assert clips, "the processed data set is empty"
    means, worst = [], (0.0, "")
    for clip in clips:
        for person, (joints, offsets) in enumerate(zip(clip.people, clip.offsets)):
            joints = joints.astype(np.float64)
            back = F.decode(F.encode(joints, offsets), offsets, start=F.start_of(joints))
            err = np.linalg.norm(back - joints, axis=-1)              # (T, 22) metres
            means.append(err.mean())
            assert err.mean() < 0.01, f"{clip.id} person {person}: mean {err.mean():.4f} m"
            if err.max() > worst[0]:
                worst = (err.max(), f"{clip.id} person {person}")
    # float16 storage noise (~2 mm at 4 m from the origin) bent through IK: millimetres, and a
    # heading or drift bug would show up as decimetres.
    assert worst[0] < 0.03, f"worst joint error {worst[0]:.4f} m in {worst[1]}"
    print(f"\nround trip over {len(means)} people: mean {np.mean(means) * 1000:.2f} mm, "
          f"worst clip mean {np.max(means) * 1000:.2f} mm, max {worst[0] * 1000:.2f} mm ({worst[1]})")


@needs_data
def test_foot_contacts_alternate_on_real_walks():
    # CMU walks on flat ground (on "uneven terrain" the feet stand on blocks above y = 0).
    walks = [c for c in default_clips() if c.source == "cmu-bvh" and "walk" in c.label
             and "uneven" not in c.label]
    assert len(walks) >= 10, "too few CMU walks in the processed set"
    for clip in walks:
        contact = F.foot_contacts(clip.people[0])                   # (T, 4)
        left, right = contact[:, :2].any(axis=1), contact[:, 2:].any(axis=1)
        assert (left | right).mean() > 0.8, clip.id                  # someone is on the ground
        assert (left & right).mean() < 0.6, clip.id                  # but not both all the time
        # Lift-offs alternate: between two lift-offs of one foot, the other lifts off once.
        events = sorted([(t, "L") for t in np.flatnonzero(left[:-1] & ~left[1:])]
                        + [(t, "R") for t in np.flatnonzero(right[:-1] & ~right[1:])])
        sides = [s for _, s in events]
        assert len(sides) >= 3, (clip.id, sides)
        assert sum(a == b for a, b in zip(sides, sides[1:])) <= len(sides) // 4, (clip.id, sides)
