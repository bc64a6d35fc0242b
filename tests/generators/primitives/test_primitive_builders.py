"""Each primitive on its real captured base (generators/primitives): counts exact measured on
the joints, bones unchanged, feet (or the body) on the floor, nothing outside the moved parts
shifted."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.generators.primitives import contacts, exercise, gait, legs, reach
from interplay.generators.primitives.postures import found, posture
from interplay.motion import skeleton as sk
from interplay.motion.checks import measures as m
from interplay.motion.signals import runs

J = sk.JOINT_INDEX
LEG_JOINTS = [J[f"{s}_{p}"] for s in ("left", "right") for p in ("hip", "knee", "ankle", "foot")]


def bones_kept(out: np.ndarray, base: np.ndarray, tol: float = 1e-6) -> bool:
    return float(np.abs(sk.bone_lengths(out) - sk.bone_lengths(base)).max()) < tol


def on_floor(out: np.ndarray) -> bool:
    return float(out[..., 1].min()) > -0.01


@pytest.fixture(scope="module")
def stand():
    return posture("standing", 6.0)


def test_postures_are_captured_frames_with_their_measures():
    checks = {"standing": m.standing, "prone": m.lying, "supine": m.lying,
              "all_fours": m.on_all_fours, "kneeling": m.kneeling}
    for name, check in checks.items():
        j = posture(name, 2.0)
        assert check(m.frame_of(j)).all(), name
        assert found(name)[1].clip                    # a real clip, named
    chest = {n: posture(n, 1.0) for n in ("prone", "supine")}
    from interplay.generators.primitives.body import trunk_axes
    assert trunk_axes(chest["prone"])[2][:, 1].mean() < -0.8      # face down
    assert trunk_axes(chest["supine"])[2][:, 1].mean() > 0.8      # face up
    seat = posture("seated", 2.0, seat_m=0.45)
    hips = 0.5 * (seat[:, sk.LEFT_HIP, 1] + seat[:, sk.RIGHT_HIP, 1])
    assert np.allclose(hips, 0.53, atol=0.02)                      # on the seat
    assert seat[:, [sk.LEFT_ANKLE, sk.RIGHT_ANKLE], 1].max() < 0.12  # feet on the floor
    assert bones_kept(seat, posture("standing", 2.0), 1e-3)


@pytest.mark.parametrize("target,n", [("hands", 3), ("high_five", 2), ("chest", 4), ("head", 2)])
def test_hand_contacts_exact(stand, target, n):
    out = contacts.hand_contacts(stand, n, target)
    if target in ("hands", "high_five"):
        gap = np.linalg.norm(m.hand_point(out, "left") - m.hand_point(out, "right"), axis=1)
    else:
        gap = np.linalg.norm(m.hand_point(out, "right") - contacts._point(out, target, "right"), axis=1)
    assert len(runs(gap < 0.05)) == n and gap.min() < 0.035
    assert len(runs(gap > 0.15)) >= n - 1                          # apart between contacts
    assert bones_kept(out, stand)
    assert np.array_equal(out[:, LEG_JOINTS], stand[:, LEG_JOINTS])


def test_knee_taps_seated():
    base = posture("seated", 5.0)
    out = contacts.hand_contacts(base, 3, "knee")
    gap = np.linalg.norm(m.hand_point(out, "right") - contacts._point(out, "knee", "right"), axis=1)
    assert len(runs(gap < 0.05)) == 3 and bones_kept(out, base)


@pytest.mark.parametrize("side,n", [("alternate", 4), ("left", 3)])
def test_knee_lifts_exact(stand, side, n):
    out = legs.knee_lifts(stand, n, side)
    lifts = {s: len(runs(out[:, J[f"{s}_knee"], 1] > out[:, J[f"{s}_hip"], 1]))
             for s in ("left", "right")}
    assert sum(lifts.values()) == n
    if side == "left":
        assert lifts["right"] == 0
    assert bones_kept(out, stand) and on_floor(out)


def test_squats_and_lunges_exact(stand):
    for build, n in ((legs.squats, 3), (legs.lunges, 2)):
        out = build(stand, n)
        b = m.frame_of(out)
        assert len(m.squats(b)) == n, build.__name__
        assert bones_kept(out, stand) and on_floor(out)
    out = legs.lunges(stand, 2)
    knees = np.minimum(out[:, J["left_knee"], 1], out[:, J["right_knee"], 1])
    assert len(runs(knees < 0.2)) == 2                             # the back knee goes down


def test_push_ups_push(stand):
    base = posture("prone", 6.0)
    out = exercise.push_ups(base, 3)
    sh = out[:, [sk.LEFT_SHOULDER, sk.RIGHT_SHOULDER], 1].mean(axis=1)
    assert len(runs(sh > sh[0] + 0.15)) == 3                       # up ≥ 15 cm, three times
    toes = out[:, [sk.LEFT_FOOT, sk.RIGHT_FOOT]]
    assert np.abs(toes - toes[:1]).max() < 0.02                    # the feet stay
    wrists = out[:, [sk.LEFT_HAND, sk.RIGHT_HAND]]
    mid = slice(10, -10)
    assert np.abs(wrists[mid] - wrists[mid][:1]).max() < 0.01      # the hands stay planted
    assert bones_kept(out, base) and on_floor(out)


def test_sit_ups_curl():
    base = posture("supine", 6.0)
    out = exercise.sit_ups(base, 3)
    v = out[:, sk.NECK] - out[:, sk.PELVIS]
    torso = np.degrees(np.arctan2(v[:, 1], np.linalg.norm(v[:, [0, 2]], axis=1)))
    assert torso[0] < 20 and len(runs(torso > 45)) == 3
    assert bones_kept(out, base) and on_floor(out)


def test_jumping_jacks_and_arm_circles(stand):
    out = exercise.jumping_jacks(stand, 3)
    over = np.minimum(out[:, sk.LEFT_HAND, 1], out[:, sk.RIGHT_HAND, 1]) > out[:, sk.HEAD, 1] + 0.1
    assert len(runs(over)) == 3 and bones_kept(out, stand) and on_floor(out)
    feet = np.abs(out[:, sk.LEFT_ANKLE, 0] - out[:, sk.RIGHT_ANKLE, 0])
    assert feet.max() > feet[0] + 0.3                               # the feet jump out …
    assert len(m.jumps(m.frame_of(out))) == 6                       # … and in: two hops a jack
    out = exercise.arm_circles(stand, 3)
    from interplay.generators.primitives.body import axes
    left, up, fwd = axes(out)
    wr = (out[:, sk.LEFT_HAND] - out[:, sk.LEFT_SHOULDER])[10:-10]
    wr = wr - wr.mean(axis=0)                                       # about the circle's centre
    ang = np.unwrap(np.arctan2((wr * up[10:-10]).sum(-1), (wr * fwd[10:-10]).sum(-1)))
    assert abs(abs(ang[-1] - ang[0]) / (2 * np.pi) - 3) < 0.25      # three turns
    assert bones_kept(out, stand)


def test_reach_grasp_carry():
    base = posture("standing", 5.0)
    out = reach.reach_grasp_carry(base, ahead=0.45, height=0.9, carry=False)
    mid = 0.5 * (m.hand_point(out, "left") + m.hand_point(out, "right"))
    obj = base[:, sk.PELVIS] * [1, 0, 1] + [0, 0.9, 0.45]
    assert np.linalg.norm(mid - obj, axis=1).min() < 0.03           # the hands reach it
    walk = posture("walk", 6.0)
    out = reach.reach_grasp_carry(walk, carry=True)
    tail = slice(int(0.6 * len(out)), None)
    hands = 0.5 * (m.hand_point(out, "left") + m.hand_point(out, "right"))[tail]
    chest = out[tail, J["spine3"], 1]
    assert np.abs(hands[:, 1] - chest).max() < 0.15                 # held at chest height
    gap = np.linalg.norm(m.hand_point(out, "left") - m.hand_point(out, "right"), axis=1)[tail]
    assert np.ptp(gap) < 0.02                                       # both hands on the object
    assert np.linalg.norm(out[-1, 0, [0, 2]] - out[0, 0, [0, 2]]) > 2.0   # still walking
    low = reach.reach_grasp_carry(base, height=0.15, carry=False)
    mid = 0.5 * (m.hand_point(low, "left") + m.hand_point(low, "right"))
    assert mid[:, 1].min() < 0.2 and bones_kept(low, base) and on_floor(low)


def test_limp_favours_one_leg():
    base = posture("walk", 8.0)
    for side, good in (("right", "left"), ("left", "right")):
        out = gait.gait_asymmetric(base, side)
        down = gait.stance(out)
        assert down[side].mean() < 0.85 * down[good].mean(), side   # shorter stance on the sore leg
        assert np.abs(sk.bone_lengths(out) - np.median(sk.bone_lengths(base), axis=0)).max() < 0.01
        assert on_floor(out)
        travel = np.linalg.norm(out[-1, 0, [0, 2]] - out[0, 0, [0, 2]])
        assert travel > 0.9 * np.linalg.norm(base[-1, 0, [0, 2]] - base[0, 0, [0, 2]])


def test_stumble_and_sway():
    base = posture("walk", 6.0)
    out = gait.gait_perturbed(base, "stumble")
    lean = m.torso_lean(m.frame_of(out))
    assert lean.max() > m.torso_lean(m.frame_of(base)).max() + 15   # pitches forward …
    assert lean[-5:].mean() < 15                                    # … and recovers
    out = gait.gait_perturbed(base, "sway", count=3)
    from interplay.generators.primitives.body import axes
    left = axes(out)[0]
    roll = ((out[:, sk.NECK] - out[:, sk.PELVIS]) * left).sum(-1)
    assert len(runs(roll > 0.07)) == 3 and len(runs(roll < -0.07)) == 3
    assert np.array_equal(out[:, LEG_JOINTS], base[:, LEG_JOINTS])  # the legs walk on
