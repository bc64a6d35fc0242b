"""The two-person touching and distance checks (`motion/checks/contact.py`) on the processed
data's pairs (captured salsa, pairs composed from real single-person captures): each passes on
pairs that do the thing and fails on pairs that do not, or on the same pair changed so that it
no longer does."""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.checks import measures as M
from interplay.motion.checks.named import run_check
from interplay.motion.clip import default_clips


def pairs(kind: str) -> list[list[np.ndarray]]:
    out = [[np.asarray(p, np.float64) for p in c.people] for c in default_clips()
           if len(c.people) == 2 and c.meta.get("kind", c.label) == kind]
    assert out, kind
    return out


def check(people, **spec):
    return run_check(people, spec)


def test_a_hand_on_the_partner_s_back_or_trunk():
    hugs, pushes, waves = pairs("hug"), pairs("push"), pairs("wave")
    assert all(check(p, check="touches", target="back").passed for p in hugs)
    assert all(check(p, check="touches", target="trunk").passed for p in pushes)
    # Waving across the room touches nothing; a push's hands land on the front, not the back.
    for target in ("back", "trunk", "shoulder", "head"):
        assert not any(check(p, check="touches", target=target).passed for p in waves), target
    assert not any(check(p, check="touches", target="back").passed for p in pushes)


def test_a_touch_held_for_a_while_or_counted_apart():
    hugs = pairs("hug")
    assert np.mean([check(p, check="touches", target="back", min_s=1.0).passed for p in hugs]) >= 0.9
    # The composed push's hands rest on the trunk well under 2 s.
    assert not any(check(p, check="touches", target="trunk", min_s=2.0).passed for p in pairs("push"))


def test_a_hand_put_on_the_partner_s_head_counts_30_cm_off_it_does_not():
    a, b = pairs("walk_side_by_side")[0]
    a = a[:60].copy()
    b = b[:60].copy()
    hand = M.hand_point(a, "right")
    on = a + (b[:, [sk.HEAD]] + np.array([0.0, 0.12, 0.0]) - hand[:, None])   # hand on the crown
    assert check([on, b], check="touches", target="head", min_s=1.0).passed
    off = on + np.array([0.0, 0.30, 0.0])
    assert not check([off, b], check="touches", target="head").passed
    assert not check([a, b], check="touches", target="head").passed


def test_the_two_people_s_hands_meeting():
    for kind in ("handshake", "high_five"):
        assert all(check(p, check="hands_meet_partner").passed for p in pairs(kind)), kind
    assert not any(check(p, check="hands_meet_partner").passed for p in pairs("wave"))
    salsa = pairs("salsa dance")                  # hands joined, let go and joined again
    assert all(check(p, check="hands_meet_partner", at_least=2).passed for p in salsa)


def test_moving_apart():
    waves = pairs("wave")
    assert not any(check(p, check="separate", min_m=1.0).passed for p in waves)
    a, b = waves[0]
    d = (b[0, sk.PELVIS] - a[0, sk.PELVIS]) * np.array([1.0, 0.0, 1.0])
    away = b + np.linspace(0.0, 2.0, len(b))[:, None, None] * (d / np.linalg.norm(d))   # b backs off 2 m
    assert check([a, away], check="separate", min_m=1.5).passed
    # Coming together is not moving apart (the same pair played backwards in time).
    assert not check([a[::-1], away[::-1]], check="separate", min_m=1.0).passed


def piggyback(a: np.ndarray, lift: float) -> np.ndarray:
    """a's own motion lifted `lift` metres and moved 25 cm behind a's pelvis: a rider carried
    on a's back (the same body stands in for the rider)."""
    b = M.frame_of(a)
    return a - 0.25 * b.forward[:, None] + np.array([0.0, lift, 0.0])


def test_carried_on_the_back_means_feet_off_the_floor_over_the_carrier():
    for a, b in pairs("walk_side_by_side")[:5]:
        assert not check([a, b], check="carried").passed           # walking side by side
        assert check([a, piggyback(a, 0.45)], check="carried").passed
        assert check([piggyback(a, 0.45), a], check="carried").passed   # either may ride
        assert not check([a, piggyback(a, 0.10)], check="carried").passed   # feet on the floor
