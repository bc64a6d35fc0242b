"""Touches solved on the two placed bodies with two-bone IK (`motion.ik`, bones kept exactly):
where each hand goes for a handshake, a high five, a hug, a push or held hands, and the arm
moved there with eased weights (reach, hold, release). numpy only.

A target is for the centre of the hand (`checks.measures.hand_point`: 0.3 forearm lengths
past the wrist, where body.py's hand sphere sits), so the wrist goal is solved for it: the IK
is run again with the wrist goal moved back along the new forearm (three rounds converge to
a millimetre).

Shapes: joints (T, 22, 3) float64 metres, Y up; targets (T, 3); weights (T,) in [0, 1].
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.checks.measures import HAND_EXTENSION, HAND_RADIUS_M, hand_point
from interplay.motion.ik import reach, two_bone_ik
from interplay.motion.pair import placement as pl
from interplay.motion.pair.compose import hug_targets

UP = np.array([0.0, 1.0, 0.0])
J = sk.JOINT_INDEX
TOUCH = 0.01          # m the touching hand surfaces press into each other


def hand_to(j: np.ndarray, side: str, target: np.ndarray, weight: np.ndarray,
            pole: np.ndarray, rounds: int = 3) -> np.ndarray:
    """j with the `side` arm re-posed so the hand's centre reaches `target` (blended by
    `weight`, elbow towards `pole`)."""
    wr, el = J[f"{side}_wrist"], J[f"{side}_elbow"]
    goal = np.broadcast_to(target, (len(j), 3)).copy()
    out = j
    for _ in range(rounds):
        out = two_bone_ik(j, f"{side}_arm", goal, pole=pole, weight=weight)
        fore = out[:, wr] - out[:, el]
        goal = target - HAND_EXTENSION * fore
    return out


def within_reach(j: np.ndarray, side: str, target: np.ndarray, share: float = 0.97) -> np.ndarray:
    """(T,) bool: the hand's target is within `share` of the arm's reach (plus the hand)."""
    shoulder = j[:, J[f"{side}_shoulder"]]
    arm = reach(j, f"{side}_arm") * (1.0 + HAND_EXTENSION * 0.5)
    return np.linalg.norm(target - shoulder, axis=1) <= share * arm


def handshake(a: np.ndarray, b: np.ndarray, w: np.ndarray, height: float, pump: np.ndarray
              ) -> tuple[np.ndarray, np.ndarray]:
    """Right hands meet between the two at `height` over the mean pelvis height, moving up
    and down together by `pump` (T,) metres while held."""
    mid = 0.5 * (a[:, sk.PELVIS] + b[:, sk.PELVIS])
    ra, rb = a[:, J["right_shoulder"]], b[:, J["right_shoulder"]]
    meet = 0.5 * (ra + rb) * np.array([1.0, 0.0, 1.0])
    meet[:, 1] = mid[:, 1].mean() + height
    meet = meet + (pump * w)[:, None] * UP
    along = b[:, sk.PELVIS] - a[:, sk.PELVIS]
    along[:, 1] = 0.0
    along /= np.maximum(np.linalg.norm(along, axis=1, keepdims=True), 1e-9)
    half = HAND_RADIUS_M - TOUCH / 2
    a = hand_to(a, "right", meet - half * along, w, pl.pole(a, "right", 0.15, 0.4, 0.1))
    b = hand_to(b, "right", meet + half * along, w, pl.pole(b, "right", 0.15, 0.4, 0.1))
    return a, b


def high_five(a: np.ndarray, b: np.ndarray, w: np.ndarray, side_a: str, side_b: str,
              above: float) -> tuple[np.ndarray, np.ndarray]:
    """a's `side_a` hand meets b's `side_b` hand `above` metres over the higher shoulder,
    laterally between those two shoulders."""
    sa, sb = a[:, J[f"{side_a}_shoulder"]], b[:, J[f"{side_b}_shoulder"]]
    meet = 0.5 * (sa + sb)
    meet[:, 1] = max(float(sa[:, 1].max()), float(sb[:, 1].max())) + above
    along = b[:, sk.PELVIS] - a[:, sk.PELVIS]
    along[:, 1] = 0.0
    along /= np.maximum(np.linalg.norm(along, axis=1, keepdims=True), 1e-9)
    half = HAND_RADIUS_M - TOUCH / 2
    a = hand_to(a, side_a, meet - half * along, w, pl.pole(a, side_a, 0.3, 0.3, 0.0))
    b = hand_to(b, side_b, meet + half * along, w, pl.pole(b, side_b, 0.3, 0.3, 0.0))
    return a, b


def hug(a: np.ndarray, b: np.ndarray, w: tuple[np.ndarray, np.ndarray], window: slice,
        heights: tuple[float, float]) -> tuple[np.ndarray, np.ndarray]:
    """Both arms of each round the other's upper back (`compose.hug_targets`, wrists just off
    the partner's chest sphere): a's over, at heights[0] over b's chest, elbows out and up;
    b's under, at heights[1], elbows down (b's weights w[1] may lead a's w[0], so that the
    arms going under are round before the arms going over come down on them)."""
    out = []
    for me, other, h, wt, down in ((a, b, heights[0], w[0], -0.05), (b, a, heights[1], w[1], 0.3)):
        j = me
        for arm in ("left", "right"):
            target = hug_targets(me, other, arm, h, window)
            j = two_bone_ik(j, f"{arm}_arm", target, pole=pl.pole(me, arm, 0.45, down, 0.1), weight=wt)
        out.append(j)
    return out[0], out[1]


def turn_head(j: np.ndarray, w: np.ndarray, degrees: float) -> np.ndarray:
    """The head joint turned about the vertical through the neck by `degrees` × w (T,)
    (positive: to the person's left), so a hugging head rests beside the partner's."""
    out = j.copy()
    ang = np.radians(degrees) * w
    rel = j[:, sk.HEAD] - j[:, sk.NECK]
    c, s = np.cos(ang), np.sin(ang)
    out[:, sk.HEAD, 0] = j[:, sk.NECK, 0] + c * rel[:, 0] + s * rel[:, 2]
    out[:, sk.HEAD, 2] = j[:, sk.NECK, 2] - s * rel[:, 0] + c * rel[:, 2]
    return out


def chest(b: np.ndarray, height: float) -> np.ndarray:
    """A point (T, 3) on the front of b's chest, `height` m over spine3."""
    fwd = pl.axes(b)[0]
    return b[:, J["spine3"]] + 0.13 * fwd + height * UP


def push(a: np.ndarray, b: np.ndarray, w: np.ndarray, height: float, spread: float
         ) -> np.ndarray:
    """a's two hands on b's chest, `spread` m either side of its middle (b as it moves)."""
    front = chest(b, height) - HAND_RADIUS_M * pl.axes(b)[0]
    for arm in ("left", "right"):
        target = front + spread * pl.out_of(a, arm)
        a = hand_to(a, arm, target, w, pl.pole(a, arm, 0.2, 0.35, 0.15))
    return a


def held_hands(a: np.ndarray, b: np.ndarray, w: np.ndarray, side: float, drop: float
               ) -> tuple[np.ndarray, np.ndarray]:
    """The near hands (b on a's left when side > 0) held between the two, `drop` m under the
    mean pelvis height."""
    arm_a, arm_b = ("left", "right") if side > 0 else ("right", "left")
    mid = 0.5 * (a[:, J[f"{arm_a}_shoulder"]] + b[:, J[f"{arm_b}_shoulder"]])
    mid[:, 1] = 0.5 * (a[:, sk.PELVIS, 1] + b[:, sk.PELVIS, 1]) - drop
    across = b[:, sk.PELVIS] - a[:, sk.PELVIS]
    across[:, 1] = 0.0
    across /= np.maximum(np.linalg.norm(across, axis=1, keepdims=True), 1e-9)
    half = HAND_RADIUS_M - TOUCH
    a = hand_to(a, arm_a, mid - half * across, w, pl.pole(a, arm_a, 0.1, 0.4, 0.1))
    b = hand_to(b, arm_b, mid + half * across, w, pl.pole(b, arm_b, 0.1, 0.4, 0.1))
    return a, b


def hand_gap(a: np.ndarray, b: np.ndarray, side_a: str, side_b: str) -> np.ndarray:
    """Gap (T,) between two hands' surfaces (as the checks measure it)."""
    return np.linalg.norm(hand_point(a, side_a) - hand_point(b, side_b), axis=1) - 2 * HAND_RADIUS_M
