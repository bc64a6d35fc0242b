"""Two-bone IK on real captured poses (CMU walks and HDM05 clips of the processed set)."""

import numpy as np
import pytest

from interplay.motion import ik
from interplay.motion import skeleton as sk
from interplay.motion.clip import default_clips


@pytest.fixture(scope="module")
def poses():
    """A few hundred real frames from walks and HDM05 clips (float64)."""
    rng = np.random.default_rng(0)
    clips = [c for c in default_clips() if not c.synthetic and len(c.people) == 1
             and c.source in ("cmu-bvh", "hdm05")]
    assert len(clips) >= 20
    picked = rng.choice(len(clips), 20, replace=False)
    frames = [clips[i].people[0][:: max(1, clips[i].frames // 15)] for i in picked]
    return np.concatenate(frames).astype(np.float64)


def _random_targets(poses, lb, rng, lo, hi):
    """Targets at a fraction in [lo, hi] of the limb's reach, in random directions."""
    d = rng.normal(size=(len(poses), 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    frac = rng.uniform(lo, hi, size=len(poses))
    return poses[:, lb.root] + d * (frac * ik.reach(poses, lb))[:, None]


@pytest.mark.parametrize("name", sorted(ik.LIMBS))
def test_reachable_targets_are_hit_and_bones_keep_their_length(poses, name):
    rng = np.random.default_rng(1)
    lb = ik.LIMBS[name]
    target = _random_targets(poses, lb, rng, 0.35, 0.98)
    pole = poses[:, lb.root] + rng.normal(size=(len(poses), 3))
    out = ik.two_bone_ik(poses, name, target, pole=pole)
    assert np.linalg.norm(out[:, lb.end] - target, axis=1).max() <= 1e-3
    np.testing.assert_allclose(sk.bone_lengths(out), sk.bone_lengths(poses), atol=1e-9)
    # Only the limb (and what hangs below its end) moved.
    moved = np.flatnonzero(np.abs(out - poses).max(axis=(0, 2)) > 0)
    assert set(moved) <= {lb.mid, lb.end, *ik.descendants(lb.end)}


def test_unreachable_targets_are_approached_along_the_line(poses):
    rng = np.random.default_rng(2)
    lb = ik.LIMBS["right_arm"]
    target = _random_targets(poses, lb, rng, 1.3, 3.0)
    out = ik.two_bone_ik(poses, lb, target)
    a = poses[:, lb.root]
    to_target = (target - a) / np.linalg.norm(target - a, axis=1, keepdims=True)
    to_wrist = out[:, lb.end] - a
    # The wrist lies on the shoulder→target line at full stretch, the elbow on it too.
    np.testing.assert_allclose(np.linalg.norm(to_wrist, axis=1), ik.reach(poses, lb), atol=1e-6)
    np.testing.assert_allclose(to_wrist / np.linalg.norm(to_wrist, axis=1, keepdims=True),
                               to_target, atol=1e-6)
    elbow = out[:, lb.mid] - a
    assert np.abs(np.cross(elbow, to_target)).max() < 1e-4
    np.testing.assert_allclose(sk.bone_lengths(out), sk.bone_lengths(poses), atol=1e-9)


def test_zero_weight_returns_the_pose_and_weights_blend_the_target(poses):
    lb = ik.LIMBS["left_arm"]
    target = poses[:, sk.HEAD] + [0.0, 0.3, 0.3]
    same = ik.two_bone_ik(poses, lb, target, pole=poses[:, sk.PELVIS], weight=0.0)
    np.testing.assert_allclose(same, poses, atol=1e-9)
    # Half weight: the wrist goes to the halfway point when that is within reach.
    half_goal = 0.5 * (poses[:, lb.end] + target)
    dist = np.linalg.norm(half_goal - poses[:, lb.root], axis=1)
    upper = np.linalg.norm(poses[:, lb.mid] - poses[:, lb.root], axis=1)
    lower = np.linalg.norm(poses[:, lb.end] - poses[:, lb.mid], axis=1)
    ok = (dist < 0.95 * (upper + lower)) & (dist > np.abs(upper - lower) + 0.02)
    half = ik.two_bone_ik(poses, lb, target, weight=0.5)
    assert ok.mean() > 0.5
    assert np.linalg.norm(half[ok, lb.end] - half_goal[ok], axis=1).max() <= 1e-3


def test_pole_chooses_the_bend_side(poses):
    lb = ik.LIMBS["right_arm"]
    a = poses[:, lb.root]
    fwd = np.cross([0.0, 1.0, 0.0], poses[:, sk.RIGHT_HIP] - poses[:, sk.LEFT_HIP])
    fwd /= np.linalg.norm(fwd, axis=1, keepdims=True)
    target = a + 0.6 * ik.reach(poses, lb)[:, None] * fwd
    for sign in (1.0, -1.0):
        pole = a + sign * np.array([0.0, 1.0, 0.0])
        out = ik.two_bone_ik(poses, lb, target, pole=pole)
        mid_line = 0.5 * (a + out[:, lb.end])
        assert np.all(sign * (out[:, lb.mid, 1] - mid_line[:, 1]) > 0.05)


def test_leg_ik_carries_the_foot_rigidly(poses):
    lb = ik.LIMBS["left_leg"]
    target = poses[:, lb.end] + [0.05, 0.10, -0.08]
    foot = sk.LEFT_FOOT
    before = poses[:, foot] - poses[:, lb.end]
    for carry in ("rotate", "keep"):
        out = ik.two_bone_ik(poses, lb, target, carry=carry)
        after = out[:, foot] - out[:, lb.end]
        np.testing.assert_allclose(np.linalg.norm(after, axis=1), np.linalg.norm(before, axis=1))
        if carry == "keep":
            np.testing.assert_allclose(after, before, atol=1e-12)
        else:
            # The foot turns with the shin: its angle to the shin is unchanged.
            def angle(j, rel):
                shin = j[:, lb.end] - j[:, lb.mid]
                return np.sum(shin * rel, 1) / np.linalg.norm(shin, axis=1) / np.linalg.norm(rel, axis=1)
            np.testing.assert_allclose(angle(out, after), angle(poses, before), atol=1e-9)


def test_window_weights_ease_in_hold_and_out():
    w = ik.window_weights(80, 30, 50, 10, 15)
    assert w.shape == (80,) and w.min() == 0.0 and w.max() == 1.0
    assert np.all(w[30:50] == 1.0) and np.all(w[:20] == 0.0) and np.all(w[64:] == 0.0)
    assert np.all(np.diff(w[19:31]) >= 0) and np.all(np.diff(w[49:65]) <= 0)
    # Smooth: no step larger than a linear ramp's peak slope × 1.9 (smootherstep peaks at 1.875).
    assert np.abs(np.diff(w)).max() <= 1.9 / 10 + 1e-9
    with pytest.raises(ValueError):
        ik.window_weights(80, 50, 30, 5)
    with pytest.raises(ValueError):
        ik.limb("left_tail")
