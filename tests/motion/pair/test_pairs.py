"""Two-person training windows and relative features on real salsa pairs and composed pairs."""

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.clip import default_clips
from interplay.motion.kinematics import facing_angle
from interplay.motion.pair import compose as C
from interplay.motion.pair import windows as P


@pytest.fixture(scope="module")
def salsa():
    clips = [c for c in default_clips() if c.source == "cmu-salsa"]
    assert len(clips) >= 10
    return clips[:3]


@pytest.fixture(scope="module")
def shakes():
    pool = C.pool_of([c for c in default_clips() if not c.synthetic], "train")
    return [C.compose("handshake", s, pool=pool) for s in range(3)]


def test_mirror_is_an_involution_that_keeps_bones_and_swaps_sides(salsa):
    j = salsa[0].people[0][:50].astype(np.float64)
    m = P.mirror(j)
    np.testing.assert_allclose(P.mirror(m), j)
    np.testing.assert_allclose(sk.bone_lengths(m), sk.bone_lengths(j)[:, _mirror_bones()], atol=1e-9)
    np.testing.assert_allclose(m[:, sk.LEFT_HAND], j[:, sk.RIGHT_HAND] * [-1, 1, 1])
    # Facing is mirrored too: the yaw changes sign.
    np.testing.assert_allclose(facing_angle(m), -facing_angle(j), atol=1e-9)
    with pytest.raises(ValueError):
        P.mirror(np.zeros((5, 21, 3)))


def _mirror_bones():
    index = {c: b for b, (c, _) in enumerate(sk.BONES)}
    return np.array([index[P.MIRROR_JOINTS[c]] for c, _ in sk.BONES])


def test_windows_hold_both_role_orders_and_mirrors(salsa, shakes):
    length, stride = 40, 20
    w = P.pair_windows(salsa + shakes, length, stride)
    per_clip = sum(len(range(0, c.frames - length + 1, stride)) for c in salsa + shakes)
    assert w.joints.shape == (4 * per_clip, 2, length, sk.NUM_JOINTS, 3) and len(w) == 4 * per_clip
    assert set(zip(w.swapped, w.mirrored)) == {(False, False), (False, True), (True, False), (True, True)}
    assert w.synthetic.sum() == 4 * sum(len(range(0, c.frames - length + 1, stride)) for c in shakes)
    # Canonical: every window's first person starts at the origin facing +Z.
    first = w.joints[:, 0, 0].astype(np.float64)
    assert np.abs(first[:, sk.PELVIS, [0, 2]]).max() < 1e-3
    assert np.abs(facing_angle(first)).max() < 1e-3
    only = P.pair_windows(salsa, length, stride, roles="as_is", mirror=False)
    assert len(only) == per_clip - sum(len(range(0, c.frames - length + 1, stride)) for c in shakes)
    assert not only.swapped.any() and not only.mirrored.any()
    with pytest.raises(ValueError):
        P.pair_windows(salsa, length, stride, roles="reversed")


def test_swapped_windows_put_the_second_person_first(salsa):
    w = P.pair_windows(salsa[:1], 40, 40, mirror=False)
    plain, swapped = w.joints[~w.swapped][0], w.joints[w.swapped][0]
    d_plain = P.distance_map(plain[0], plain[1])
    d_swap = P.distance_map(swapped[0], swapped[1])
    np.testing.assert_allclose(d_swap, np.swapaxes(d_plain, 1, 2), atol=2e-3)
    src = salsa[0].people[1][:40].astype(np.float64)
    np.testing.assert_allclose(sk.bone_lengths(swapped[0]), sk.bone_lengths(src), atol=2e-3)


def test_mirrored_windows_swap_the_shaking_hands(shakes):
    for clip in shakes:
        ct = clip.meta["contact"]
        w = P.pair_windows([clip], clip.frames, 1, roles="as_is")
        for joints, flipped in zip(w.joints, w.mirrored):
            a, b = joints[0, ct["start"]:ct["end"]], joints[1, ct["start"]:ct["end"]]
            right = np.linalg.norm(a[:, sk.RIGHT_HAND] - b[:, sk.RIGHT_HAND], axis=1).mean()
            left = np.linalg.norm(a[:, sk.LEFT_HAND] - b[:, sk.LEFT_HAND], axis=1).mean()
            shaking, idle = (left, right) if flipped else (right, left)
            assert shaking < 0.15 < idle, (clip.id, flipped, right, left)


def test_relative_root_and_distance_maps(shakes):
    pool = C.pool_of([c for c in default_clips() if not c.synthetic], "train")
    walk = C.compose("walk_side_by_side", 0, pool=pool)
    for clip, cos_sign in ((shakes[0], -1.0), (walk, 1.0)):
        a, b = (p.astype(np.float64) for p in clip.people)
        rel = P.relative_root(a, b)
        assert rel.shape == (clip.frames, 4)
        np.testing.assert_allclose(np.hypot(rel[:, 2], rel[:, 3]), 1.0, atol=1e-9)
        assert np.median(cos_sign * rel[:, 3]) > 0.9
        dist = np.linalg.norm((b[:, sk.PELVIS] - a[:, sk.PELVIS])[:, [0, 2]], axis=1)
        np.testing.assert_allclose(np.hypot(rel[:, 0], rel[:, 1]), dist, atol=1e-6)
    a, b = (p.astype(np.float64) for p in shakes[0].people)
    assert np.median(P.relative_root(a, b)[:, 1]) > 0.4             # the partner is in front
    full = P.distance_map(a, b)
    key = P.distance_map(a, b, sk.KEY_JOINTS)
    assert full.shape == (80, 22, 22) and key.shape == (80, 5, 5)
    np.testing.assert_allclose(key, full[:, list(sk.KEY_JOINTS)][:, :, list(sk.KEY_JOINTS)])
    np.testing.assert_allclose(P.distance_map(b, a), np.swapaxes(full, 1, 2))
    feats = P.interaction_features(a, b)
    assert feats.shape == (80, 4 + 25) and np.isfinite(feats).all()
