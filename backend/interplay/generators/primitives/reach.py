"""Reach, grasp and carry: both hands reach to an object at a point in front of the person
(in their own frame: metres ahead of the pelvis, height over the floor), close on it (the
grasp pose: the hand centres on either side of the object, the elbows out), then, carrying,
bring it to the chest and hold it there, in front at chest height, for the rest of the
segment, while the base walks on when it walks. A low object bends the trunk forward
(`arms.lean_to_reach`) for the reach and the grasp and straightens it for the carry.

Phases (fractions of the segment): reach 0 → REACH, grasp REACH → GRASP, lift to the chest
GRASP → LIFT, carry LIFT → 1 (without carrying the hands hold the object until the last
border and go back).

Shapes: joints (T, 22, 3) metres, Y up, 20 fps.
"""

from __future__ import annotations

import numpy as np

from interplay.generators.primitives.arms import hand_to, lean_to_reach
from interplay.generators.primitives.body import axes
from interplay.generators.primitives.legs import lower
from interplay.generators.primitives.timing import border
from interplay.motion import skeleton as sk
from interplay.motion.ik import ease

J = sk.JOINT_INDEX
REACH, GRASP, LIFT = 0.25, 0.35, 0.55
HALF_WIDTH_M = 0.14      # half the object's width: each hand's centre from its middle
LOW_M = 0.6              # an object under this height is reached squatting …
SQUAT_M = 0.35           # … by up to this much


def _ramp(x: np.ndarray, a: float, b: float) -> np.ndarray:
    return ease((x - a) / max(b - a, 1e-9))


def reach_grasp_carry(base: np.ndarray, ahead: float = 0.45, height: float = 0.95,
                      carry: bool = True) -> np.ndarray:
    """The base with both hands reaching to an object `ahead` m in front of the pelvis and
    `height` m over the floor, grasping it, and (carry) holding it at the chest."""
    j = np.asarray(base, dtype=np.float64)
    t = len(j)
    x = np.arange(t) / max(t - 1, 1)
    b = border(t) / max(t - 1, 1)
    into = _ramp(x, b, REACH)                          # the hands go out to the object
    if carry:
        lift = _ramp(x, GRASP, LIFT)
        weight = into
    else:
        lift = np.zeros(t)
        weight = np.minimum(into, _ramp(1 - x, b, 1 - GRASP - 0.2 * (1 - GRASP)))
    left, up, fwd = axes(j)
    pel = j[:, sk.PELVIS] * np.array([1.0, 0.0, 1.0])
    obj = pel + ahead * fwd + height * up
    bend = (1 - lift) * np.minimum(_ramp(x, b, REACH), 1.0)
    if not carry:
        bend = weight
    if height < LOW_M:                                 # a low object: squat to it as well
        drop = min(SQUAT_M, LOW_M - height) * bend
        ankles = {s: j[:, J[f"{s}_ankle"]] for s in ("left", "right")}
        poles = {s: j[:, J[f"{s}_knee"]] + fwd for s in ("left", "right")}
        j = lower(j, drop, np.zeros((t, 3)), np.zeros(t), ankles, poles)
    j, _ = lean_to_reach(j, "right", obj, bend)
    left, up, fwd = axes(j)
    chest = j[:, J["spine3"]] + 0.32 * fwd - 0.05 * up
    held = (1 - lift)[:, None] * obj + lift[:, None] * chest
    out = j
    for side, sign in (("left", 1.0), ("right", -1.0)):
        goal = held + sign * HALF_WIDTH_M * left
        sh = out[:, J[f"{side}_shoulder"]]
        pole = sh + sign * 0.35 * left - 0.3 * up - 0.1 * fwd
        out = hand_to(out, side, goal, pole, weight)
    return out
