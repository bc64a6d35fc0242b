"""What a two-person prompt's contact is, and where the hands go: the kind (the composer's
vocabulary, `motion.compose.KINDS`), its plausible timing, and per-frame hand targets on the
generated bodies, for the contact refinement (`contact_refine`). numpy only.

Kinds with a touch (compose.py's recipes):
  handshake          right hand to right hand, a little above pelvis height, between the people
  high_five          the closest pair of hands (one each) meeting above the higher shoulder
  push               both hands of the pusher on the chest of the other (the pusher: the one
                     whose hands are nearer the other's chest)
  hug                both arms of each person round the other's upper back
  walk_side_by_side  only when the hands are held: the near hands meet between them

A target is where the centre of a hand sphere (body.py: past the wrist along the forearm) should
be, CLEARANCE off the partner's surface (the hand touches, nothing overlaps). Targets are
recomputed from the (moved) bodies, so they follow the partner; they are smoothed over
SMOOTH frames so the decoder's jitter does not reach the wrists.

Shapes: joints (T, 22, 3) metres, Y up; targets (T, 3).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from interplay.catalogue.words import words
from interplay.motion import skeleton as sk
from interplay.motion.pair import placement as pl
from interplay.motion.pair.body import HAND_SPHERES, SPHERE_FRACTION, SPHERE_RADII, body_scale
from interplay.motion.pair.compose import CHEST_RADIUS, hug_targets
from interplay.motion.pair.windows import to_heading_frame
from interplay.motion.signals import smooth

CLEARANCE = 0.005                                  # m between touching surfaces
HAND_EXT = float(SPHERE_FRACTION[HAND_SPHERES[0]] - 1.0)   # hand centre past the wrist (× forearm)
HAND_RADIUS = float(SPHERE_RADII[HAND_SPHERES[0]])        # template build
SMOOTH = 5                                         # frames
PUSH_ANGLE = np.radians(35.0)                      # each hand this far round the chest
WALK_REACH = 0.85                                  # share of the arm held hands may use

# Detection, first said wins (held hands before "hand", push not "push-ups"): words.toml's
# lists, each also a contact of the reviewer (review_contact).
_SAID = (("walk_side_by_side", "contact_held_hands"), ("handshake", "contact_handshake"),
         ("high_five", "contact_high_five"), ("hug", "contact_hug"), ("push", "contact_push"))
KINDS = tuple(k for k, _ in _SAID)

# Timing (seconds), from compose.py's pl.timing calls: lead (earliest, latest) between the end
# of the ramp in and the touch, hold, ramp in/out (the middle of the composer's ranges).
# walk_side_by_side holds for the whole segment.
TIMING = {
    "handshake": ((0.1, 0.5), 1.5, 0.7),
    "high_five": ((0.2, 1.2), 0.2, 0.6),
    "hug": ((0.1, 0.5), 1.6, 0.8),
    "push": ((0.2, 0.6), 0.75, 0.6),
    "walk_side_by_side": ((0.0, 0.0), None, 0.5),
}
# Elbow hints per kind (placement.pole: out, down, back metres), the composer's.
POLES = {"handshake": (0.15, 0.4, 0.1), "high_five": (0.3, 0.3, 0.0), "hug": (0.45, 0.15, 0.1),
         "push": (0.2, 0.35, 0.15), "walk_side_by_side": (0.1, 0.4, 0.1)}


def contact_kind(text: str | None) -> str | None:
    """The contact kind a prompt asks for (KINDS), or None (no touch, e.g. a wave)."""
    for kind, said in _SAID:
        if text and any(not words("push_ups", ignore_case=True).starts(text, found.start)
                        for found in words(said, ignore_case=True).finditer(text)):
            return kind
    return None


@dataclass(frozen=True)
class Reach:
    """One arm's contact: person 0/1's `side` arm; target(a, b) → (T, 3) hand-centre targets;
    `hand` the partner's hand side it meets (None: the partner's body)."""
    person: int
    side: str
    target: Callable[[np.ndarray, np.ndarray], np.ndarray]
    hand: str | None = None

    @property
    def wrist(self) -> str:
        return f"{self.side}_wrist"


def hand_centre(j: np.ndarray, side: str) -> np.ndarray:
    """(T, 3) centre of the `side` hand sphere."""
    w, e = j[:, sk.JOINT_INDEX[f"{side}_wrist"]], j[:, sk.JOINT_INDEX[f"{side}_elbow"]]
    return w + HAND_EXT * (w - e)


def hand_radius(j: np.ndarray) -> float:
    return HAND_RADIUS * body_scale(j)


def _flat_unit(v: np.ndarray) -> np.ndarray:
    v = v * np.array([1.0, 0.0, 1.0])
    return v / np.maximum(np.linalg.norm(v, axis=-1, keepdims=True), 1e-9)


def _meeting(side_a: str, side_b: str, height: Callable) -> tuple[Reach, Reach]:
    """Two hands meeting between the two shoulders at height(a, b, sa, sb) (T,), each hand
    centre on its own side of the meeting point along the line between the people."""
    def centres(a, b):
        sa, sb = a[:, sk.JOINT_INDEX[f"{side_a}_shoulder"]], b[:, sk.JOINT_INDEX[f"{side_b}_shoulder"]]
        meet = 0.5 * (sa + sb)
        meet[:, 1] = height(a, b, sa, sb)
        u = _flat_unit(b[:, sk.PELVIS] - a[:, sk.PELVIS])
        half = 0.5 * (hand_radius(a) + hand_radius(b) + CLEARANCE)
        return smooth(meet - half * u, SMOOTH), smooth(meet + half * u, SMOOTH)
    return (Reach(0, side_a, lambda a, b: centres(a, b)[0], side_b),
            Reach(1, side_b, lambda a, b: centres(a, b)[1], side_a))


def _closest_hands(a: np.ndarray, b: np.ndarray) -> list[tuple[str, str]]:
    """(side of a, side of b) pairs, nearest hands on average first (right first on ties)."""
    pairs = [(sa, sb) for sa in ("right", "left") for sb in ("right", "left")]
    d = [np.linalg.norm(hand_centre(a, sa) - hand_centre(b, sb), axis=1).mean() for sa, sb in pairs]
    return [pairs[i] for i in np.argsort(d, kind="stable")]


def _chest(j: np.ndarray) -> np.ndarray:
    return j[:, pl.SPINE3] + 0.3 * (j[:, sk.NECK] - j[:, pl.SPINE3])     # body.py's chest sphere


def _push_targets(p: int, side: str) -> Callable:
    def target(a, b):
        me, other = (a, b) if p == 0 else (b, a)
        towards = _flat_unit(me[:, pl.SPINE3] - other[:, pl.SPINE3])
        out = pl.out_of(me, side)
        radius = CHEST_RADIUS * body_scale(other) + hand_radius(me) + CLEARANCE
        d = np.cos(PUSH_ANGLE) * towards + np.sin(PUSH_ANGLE) * out
        d /= np.linalg.norm(d, axis=1, keepdims=True)
        return smooth(_chest(other) + radius * d, SMOOTH)
    return target


def _pushers(a: np.ndarray, b: np.ndarray) -> list[int]:
    """[0, 1] or [1, 0]: whose two hands are nearer the other's chest on average first."""
    d = [np.mean([np.linalg.norm(hand_centre(me, s) - _chest(other), axis=1).mean()
                  for s in ("left", "right")]) for me, other in ((a, b), (b, a))]
    return [1, 0] if d[1] < d[0] else [0, 1]


def _hug_reach(p: int, side: str, height: float, window: slice) -> Reach:
    def target(a, b):
        me, other = (a, b) if p == 0 else (b, a)
        # hug_targets places the wrist; the hand sphere then lies further round the back,
        # so the wrist stays a hand radius (+ clearance) off the chest sphere.
        return smooth(hug_targets(me, other, side, height, window,
                                  clearance=hand_radius(me) + CLEARANCE),
                      SMOOTH)
    return Reach(p, side, target)


def _walk_height(a, b, sa, sb):
    """Held hands hang a little below the pelvis, rising when the people walk far apart
    (the hand centre stays within WALK_REACH of both shoulders)."""
    half = 0.5 * np.linalg.norm((sb - sa)[:, [0, 2]], axis=1)
    low = 0.5 * (a[:, sk.PELVIS, 1] + b[:, sk.PELVIS, 1]) - 0.04
    arm = np.minimum(*(WALK_REACH * _arm_length(j, s) for j, s in ((a, sa), (b, sb))))
    shoulder = np.minimum(sa[:, 1], sb[:, 1])
    return np.maximum(low, shoulder - np.sqrt(np.maximum(arm ** 2 - half ** 2, 0.0)))


def _arm_length(j: np.ndarray, shoulder: np.ndarray) -> np.ndarray:
    """Shoulder → hand centre length (T,) of the arm whose shoulder is at `shoulder` (T, 3)."""
    side = min(("left", "right"), key=lambda s: np.abs(j[:, sk.JOINT_INDEX[f"{s}_shoulder"]]
                                                      - shoulder).sum())
    n = lambda x, y: np.linalg.norm(j[:, sk.JOINT_INDEX[f"{side}_{x}"]]
                                    - j[:, sk.JOINT_INDEX[f"{side}_{y}"]], axis=1)
    return n("shoulder", "elbow") + (1.0 + HAND_EXT) * n("elbow", "wrist")


def candidates(kind: str, a: np.ndarray, b: np.ndarray, window: slice) -> list[list[Reach]]:
    """Ways to make `kind`'s touch on this pair, most natural first (sides and heights chosen
    from the generated motion); the refinement keeps the first that deepens no overlap."""
    mid_pelvis = lambda a, b, sa, sb: 0.5 * (a[:, sk.PELVIS, 1] + b[:, sk.PELVIS, 1])
    if kind == "handshake":
        return [list(_meeting("right", "right", lambda *x, h=h: mid_pelvis(*x) + h))
                for h in (0.13, 0.2, 0.06)]
    if kind == "high_five":
        return [list(_meeting(sa, sb, lambda a, b, s1, s2, h=h: np.maximum(s1[:, 1], s2[:, 1]) + h))
                for sa, sb in _closest_hands(a, b) for h in (0.18, 0.1)]
    if kind == "walk_side_by_side":
        left_of_a = to_heading_frame(a, b[:, [sk.PELVIS]])[:, 0, 0].mean() > 0
        sa, sb = ("left", "right") if left_of_a else ("right", "left")
        return [list(_meeting(sa, sb, _walk_height))]
    if kind == "push":
        return [[Reach(p, s, _push_targets(p, s)) for s in ("left", "right")]
                for p in _pushers(a, b)]
    if kind == "hug":
        # one person's arms over (upper back), the other's lower (the composer's heights)
        return [[_hug_reach(p, s, h, window) for p, h in heights for s in ("left", "right")]
                for heights in (((0, 0.015), (1, -0.11)), ((0, -0.11), (1, 0.015)))]
    raise ValueError(f"unknown contact kind {kind!r}; expected one of {KINDS}")
