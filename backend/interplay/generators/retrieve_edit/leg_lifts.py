"""High knees laid over a captured walk or march: in each swing of a leg (its foot off the
floor in the capture), the knee is lifted towards hip height and the shin hangs under it,
peaking mid-swing, by two-bone IK on the performer's bones (`ik.two_bone_ik`); the stance
leg, the pelvis and the arms stay as captured, so the steps land where they did.

Shapes: joints (T, 22, 3) metres, Y up, 20 fps.
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.bodyframe import body_frame
from interplay.motion.ik import two_bone_ik
from interplay.motion.signals import runs

J = sk.JOINT_INDEX
LIFT_DEG = 80.0        # the thigh's angle from hanging at the top of a lift (90: horizontal)
SWING_M = 0.03         # a foot this far off its ground level is swinging
MIN_SWING = 4          # frames: shorter lifts are shuffles, left alone


def swings(joints: np.ndarray, side: str) -> list[tuple[int, int]]:
    """(start, end) frames of each swing of one leg."""
    b = body_frame(joints, sk.FPS)
    return [(s, e) for s, e in runs(b.foot_height(side) > SWING_M) if e - s >= MIN_SWING]


def lift_knees(joints: np.ndarray, sides: tuple[str, ...] = ("left", "right"),
               start: int = 0, end: int | None = None) -> np.ndarray:
    """Joints with the knees of `sides` lifted in every swing inside [start, end)."""
    out = np.asarray(joints, dtype=np.float64).copy()
    end = len(out) if end is None else end
    b = body_frame(out, sk.FPS)
    up = np.array([0.0, 1.0, 0.0])
    theta = np.radians(LIFT_DEG)
    for side in sides:
        hip, knee, ankle = (J[f"{side}_{p}"] for p in ("hip", "knee", "ankle"))
        thigh = float(np.median(np.linalg.norm(out[:, knee] - out[:, hip], axis=1)))
        shin = float(np.median(np.linalg.norm(out[:, ankle] - out[:, knee], axis=1)))
        w = np.zeros(len(out))
        for s, e in swings(out, side):
            s, e = max(s, start), min(e, end)
            if e - s < MIN_SWING:
                continue
            w[s:e] = np.sin(np.pi * (np.arange(s, e) - s + 0.5) / (e - s))
        on = w > 0
        if not on.any():
            continue
        fwd = b.forward[on]
        k = out[on, hip] + thigh * (np.cos(theta) * -up + np.sin(theta) * fwd)
        target = k - shin * (0.97 * up + 0.15 * fwd)          # shin hanging, toes a little back
        pole = out[on, hip] + fwd                             # the knee bends forward
        out[on] = two_bone_ik(out[on], f"{side}_leg", target, pole=pole, weight=w[on])
    return out
