"""Arm moves shared by the primitives: a hand (its centre, `measures.hand_point`, not the
wrist joint) put on a target by two-bone IK on the performer's bones, and the torso leant
forward about the pelvis when a target is out of the arm's reach (tapping a knee while
standing, reaching to the floor).

Shapes: joints (T, 22, 3) metres; targets, poles (T, 3); weights (T,) in [0, 1].
"""

from __future__ import annotations

import numpy as np

from interplay.generators.primitives.body import turn, unit, upper_body
from interplay.motion import skeleton as sk
from interplay.motion.checks.measures import HAND_EXTENSION, hand_point
from interplay.motion.ik import reach, two_bone_ik

J = sk.JOINT_INDEX


def hand_to(joints: np.ndarray, side: str, target: np.ndarray, pole: np.ndarray,
            weight: np.ndarray, passes: int = 3) -> np.ndarray:
    """Joints with the `side` hand's centre moved onto `target` (blended by `weight`): the
    wrist is aimed short of the target by the hand's length along the forearm, refined over
    a few passes as the forearm turns."""
    j = np.asarray(joints, dtype=np.float64)
    w = np.asarray(weight, dtype=np.float64)
    on = w > 0
    if not on.any():
        return j.copy()
    out = j.copy()
    sub, tgt, pl, ww = j[on], target[on], pole[on], w[on]
    wrist = tgt.copy()
    res = sub
    for _ in range(passes):
        res = two_bone_ik(sub, f"{side}_arm", wrist, pole=pl, weight=np.ones(len(sub)))
        err = tgt - hand_point(res, side)
        wrist = wrist + err
    out[on] = two_bone_ik(sub, f"{side}_arm", wrist, pole=pl, weight=ww)
    return out


def arm_length(joints: np.ndarray, side: str) -> float:
    """Shoulder → hand centre reach (m), with the hand's extension."""
    upper_fore = float(np.median(reach(joints, f"{side}_arm")))
    fore = float(np.median(np.linalg.norm(joints[:, J[f"{side}_wrist"]]
                                          - joints[:, J[f"{side}_elbow"]], axis=1)))
    return upper_fore + HAND_EXTENSION * fore


def lean_to_reach(joints: np.ndarray, side: str, target: np.ndarray, weight: np.ndarray,
                  spare: float = 0.9) -> tuple[np.ndarray, np.ndarray]:
    """(joints with the trunk bent forward about the pelvis, the bend angle (T,)) so that the
    shoulder comes within `spare` of the arm's reach of the target; weight scales the bend."""
    j = np.asarray(joints, dtype=np.float64)
    sh, pel = j[:, J[f"{side}_shoulder"]], j[:, sk.PELVIS]
    length = spare * arm_length(j, side)
    left = unit(j[:, sk.LEFT_HIP] - j[:, sk.RIGHT_HIP])
    angles = np.linspace(0.0, np.radians(95), 40)
    best = np.zeros(len(j))
    for k in range(len(j)):
        r = sh[k] - pel[k]
        for a in angles:
            c, s = np.cos(a), np.sin(a)
            ax = left[k]
            rot = r * c + np.cross(ax, r) * s + ax * (ax @ r) * (1 - c)
            if np.linalg.norm(pel[k] + rot - target[k]) <= length:
                best[k] = a
                break
        else:
            best[k] = angles[-1]
    ang = best * np.asarray(weight, dtype=np.float64)
    return turn(j, upper_body(), pel, left, ang), ang
