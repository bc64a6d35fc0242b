"""Two-person checks of touching and distance the older ones cannot tell (registered in
`named.CHECKS`): a hand on a named part of the partner (a tap on the shoulder, a pat on the
back, a hand on the head), the two people's hands meeting (handing something over, clinking
glasses), moving apart, one carried on the other's back. Each takes (joints a, joints b,
BodyFrame a, BodyFrame b, **params) → (passed, value, bound); either person may be the one
who does it. Touching is measured between surfaces: the hand's sphere and the partner's body
spheres (`motion/pair/body.py`), as the interpenetration check measures them.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.bodyframe import BodyFrame
from interplay.motion.checks import measures as m
from interplay.motion.checks.everyday import meetings
from interplay.motion.pair.body import SPHERE_JOINT, body_spheres
from interplay.motion.signals import fill_gaps, runs

FPS = sk.FPS
J = sk.JOINT_INDEX

TOUCH_M = 0.05             # a hand on a body part: hand and part surfaces within 5 cm (sphere
                           # radii are the body's half-widths; a hand resting on a shoulder
                           # measures 0–3 cm) …
APART_M = 0.15             # … and off it by 15 cm before the next touch counts
HANDS_MEET_M = 0.10        # the two people's hands within 10 cm of each other: one hand passes
                           # a thing to the other, two glasses meet (a glass is 6–8 cm across)
RIDE_FEET_M = 0.25         # carried: the lower foot ≥ 25 cm off the floor (a step's swing foot
                           # rises ~15 cm, and one foot is always down when walking) …
RIDE_NEAR_M = 0.45         # … the pelvis within 45 cm (on the floor) of the carrier's …
RIDE_ABOVE_M = 0.05        # … and ≥ 5 cm higher (a rider sits on the carrier's hands at hip
                           # height or above)
TARGETS: dict[str, tuple[str, ...]] = {
    "shoulder": ("left_shoulder", "right_shoulder", "left_collar", "right_collar"),
    "head": ("head",),
    "arm": ("left_shoulder", "right_shoulder", "left_elbow", "right_elbow", "left_wrist",
            "right_wrist"),
    "trunk": ("pelvis", "spine1", "spine2", "spine3"),
    "back": ("spine1", "spine2", "spine3"),           # … from behind (see hand_on)
    "leg": ("left_knee", "right_knee", "left_hip", "right_hip"),
}


def hand_on(a: np.ndarray, b: np.ndarray, fb: BodyFrame, target: str) -> np.ndarray:
    """Gap (T,) from the surface of either of a's hands to the surface of b's `target` part
    (for "back", only where the hand is behind b's torso plane)."""
    sb = body_spheres(b)
    idx = np.flatnonzero(np.isin(SPHERE_JOINT, [J[n] for n in TARGETS[target]]))
    centres, radii = sb.centres[:, idx], sb.radii[idx]
    best = np.full(a.shape[0], np.inf)
    for side in m.SIDES:
        hand = m.hand_point(a, side)
        gap = (np.linalg.norm(centres - hand[:, None], axis=2) - radii[None]).min(axis=1) - m.HAND_RADIUS_M
        if target == "back":
            ahead = fb.local(hand - b[:, J["spine3"]])[2]
            gap = np.where(ahead < 0, gap, np.inf)
        best = np.minimum(best, gap)
    return best


def _who(a, b, fa, fb, who: str):
    """(doer, partner, partner's frame) pairs to try: "any", "first" (a) or "second" (b)."""
    both = [(a, b, fb), (b, a, fa)]
    return both if who == "any" else both[:1] if who == "first" else both[1:]


def touches(a, b, fa, fb, target: str = "shoulder", at_least: int = 1, min_s: float = 0.0,
            who: str = "any"):
    """A hand of one on a named part of the other (shoulder, head, arm, trunk, back, leg): ≥ `at_least` separate touches, each counted once it lasts ≥ `min_s` s."""
    best = 0
    for doer, partner, fp in _who(a, b, fa, fb, who):
        gap = hand_on(doer, partner, fp, target)
        if min_s > 0:
            n = sum(e - s >= min_s * FPS for s, e in runs(fill_gaps(gap <= TOUCH_M)))
        else:
            n = len(meetings(gap, TOUCH_M, APART_M))
        best = max(best, int(n))
    return best >= at_least, best, (
        f"a hand on the partner's {target} (≤ {TOUCH_M} m) ≥ {at_least} times" + (
            f" for ≥ {min_s} s" if min_s > 0 else ""))


def hands_meet_partner(a, b, fa, fb, at_least: int = 1, max_m: float = HANDS_MEET_M):
    """A hand of each comes within 10 cm of a hand of the other (a thing handed over, glasses clinked): ≥ `at_least` separate meetings."""
    gap = np.min([m.hand_gap(a, b, sa, sb) for sa in m.SIDES for sb in m.SIDES], axis=0)
    n = len(meetings(gap, max_m, max_m + APART_M))
    return n >= at_least, {"meetings": n, "closest_m": round(float(gap.min()), 3)}, (
        f"hands within {max_m} m ≥ {at_least} times")


def separate(a, b, fa, fb, min_m: float = 1.0):
    """The two move ≥ `min_m` m further apart (pelvis distance, from its closest to the end)."""
    dist = np.linalg.norm(a[:, sk.PELVIS][:, [0, 2]] - b[:, sk.PELVIS][:, [0, 2]], axis=1)
    got = float(dist[-1] - dist.min())
    return got >= min_m, round(got, 2), f"≥ {min_m} m further apart"


def riding(rider: np.ndarray, carrier: np.ndarray) -> np.ndarray:
    """(T,) bool: `rider` is up on `carrier` (feet ≥ 25 cm off the floor, pelvis within 45 cm
    of the carrier's and ≥ 5 cm over it), short gaps filled."""
    # Off the carrier's floor (its lowest joint: the toe on the ground), not the rider's
    # own: a body frame's floor follows the lowest joint, which a rider's feet are.
    feet = rider[:, list(sk.FOOT_JOINTS), 1].min(axis=1) - carrier[..., 1].min(axis=1)
    near = np.linalg.norm(rider[:, sk.PELVIS][:, [0, 2]] - carrier[:, sk.PELVIS][:, [0, 2]],
                          axis=1) <= RIDE_NEAR_M
    above = rider[:, sk.PELVIS, 1] - carrier[:, sk.PELVIS, 1] >= RIDE_ABOVE_M
    return fill_gaps((feet >= RIDE_FEET_M) & near & above)


def carried(a, b, fa, fb, min_s: float = 1.0):
    """One is carried by the other (a piggyback, a lift): feet ≥ 25 cm off the floor, pelvis close to and over the carrier's, for ≥ `min_s` s."""
    best = 0.0
    for rider, carrier in ((a, b), (b, a)):
        up = riding(rider, carrier)
        best = max(best, max((e - s for s, e in runs(up)), default=0) / FPS)
    return best >= min_s, round(best, 2), f"feet ≥ {RIDE_FEET_M} m up over the carrier ≥ {min_s} s"


PAIR: list[Callable[..., tuple[bool, Any, str]]] = [touches, hands_meet_partner, separate, carried]
