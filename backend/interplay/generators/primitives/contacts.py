"""Repeated hand contacts, exactly N: both hands meeting (a clap in front of the chest, a
high five with oneself over the head) or one hand tapping a point of the body (chest, head,
knee), each contact a bump of the hands' IK targets (`timing.bumps`) held briefly at the
touch, the hand centres (`measures.hand_point`) within CONTACT_M there and apart by ≥ OPEN_M
between. The arms come from the base into the move over the segment's first border and go
back over its last (`timing.envelope`); a knee out of reach bends the trunk forward
(`arms.lean_to_reach`); nothing else moves.

    hand_contacts(base, count=3, target="hands")            # three claps
    hand_contacts(base, count=2, target="head", side="left")  # taps the head twice
"""

from __future__ import annotations

import numpy as np

from interplay.generators.primitives.arms import hand_to, lean_to_reach
from interplay.generators.primitives.body import axes
from interplay.generators.primitives.timing import bumps, envelope
from interplay.motion import skeleton as sk

J = sk.JOINT_INDEX
TARGETS = ("hands", "high_five", "chest", "head", "knee")
CONTACT_M = 0.03       # the hand centres' gap at a contact (two hands) or hand → point
OPEN_M = 0.40          # the hands' gap between claps; a tapping hand backs off OPEN_M / 2
HOLD = 0.15            # fraction of a cycle held at the touch


def _point(j: np.ndarray, target: str, side: str) -> np.ndarray:
    left, up, fwd = axes(j)
    if target == "hands":
        return j[:, J["spine3"]] + 0.30 * fwd + 0.02 * up
    if target == "high_five":
        return j[:, sk.HEAD] + 0.28 * up + 0.18 * fwd
    if target == "chest":
        return j[:, J["spine3"]] + 0.12 * fwd + 0.02 * up
    if target == "head":
        return j[:, sk.HEAD] + 0.13 * up + 0.02 * fwd
    knee = J[f"{side}_knee"]
    return j[:, knee] + 0.07 * fwd + 0.03 * up


def _pole(j: np.ndarray, side: str, target: str) -> np.ndarray:
    left, up, fwd = axes(j)
    out = (1.0 if side == "left" else -1.0) * left
    sh = j[:, J[f"{side}_shoulder"]]
    if target in ("head", "high_five"):
        return sh + 0.35 * out + 0.15 * up
    return sh + 0.3 * out - 0.3 * up - 0.05 * fwd


def hand_contacts(base: np.ndarray, count: int, target: str = "hands", side: str = "right"
                  ) -> np.ndarray:
    """The base (T, 22, 3) with `count` hand contacts laid over it (see the module's note)."""
    if target not in TARGETS:
        raise ValueError(f"unknown contact target {target!r}; expected one of {TARGETS}")
    j = np.asarray(base, dtype=np.float64)
    t = len(j)
    touch = bumps(t, count, HOLD)
    env = envelope(t)
    if target == "knee":
        knee = _point(j, target, side)
        j, _ = lean_to_reach(j, side, knee, env)
    left, up, fwd = axes(j)
    point = _point(j, target, side)
    apart = (1.0 - touch)[:, None]
    if target in ("hands", "high_five"):
        gap = CONTACT_M + (OPEN_M - CONTACT_M) * apart
        for s, sign in (("left", 1.0), ("right", -1.0)):
            goal = point + sign * 0.5 * gap * left
            j = hand_to(j, s, goal, _pole(j, s, target), env)
        return j
    away = {"chest": fwd, "head": up + 0.5 * fwd, "knee": fwd + up}[target]
    away = away / np.linalg.norm(away, axis=-1, keepdims=True)
    goal = point + (0.5 * OPEN_M * apart) * away
    return hand_to(j, side, goal, _pole(j, side, target), env)
