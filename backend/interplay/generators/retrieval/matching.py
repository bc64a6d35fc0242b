"""Pose matching for cutting pieces: where in a capture to start so that the new piece begins
in the pose (and gait phase) the previous piece ends in. Without it a walk could be joined
left foot forward onto right foot forward, and the cross-fade would slide the feet.

Features per frame, independent of where the person stands and which way they face: every
joint relative to the pelvis in the person's heading frame, plus the per-frame displacement of
the pelvis and feet in that frame (weighted up: the gait phase lives in the velocities).
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import facing_angle
from interplay.motion.rotations import yaw_matrix

VELOCITY_JOINTS = (sk.PELVIS,) + sk.FOOT_JOINTS
VELOCITY_WEIGHT = 4.0


def pose_features(joints: np.ndarray) -> np.ndarray:
    """Features (T, 22·3 + 5·3) of joints (T, 22, 3), T ≥ 1."""
    joints = joints.astype(np.float64)
    unturn = yaw_matrix(-facing_angle(joints))                       # (T, 3, 3)
    rel = np.einsum("tij,tkj->tki", unturn, joints - joints[:, sk.PELVIS:sk.PELVIS + 1])
    vel = np.diff(joints[:, VELOCITY_JOINTS], axis=0, prepend=joints[:1, VELOCITY_JOINTS])
    if len(joints) > 1:
        vel[0] = vel[1]                                             # no velocity before frame 0
    vel = np.einsum("tij,tkj->tki", unturn, vel) * VELOCITY_WEIGHT
    return np.concatenate([rel.reshape(len(joints), -1), vel.reshape(len(joints), -1)], axis=1)


def best_start(features: np.ndarray, target: np.ndarray, lo: int, hi: int) -> int:
    """The frame in [lo, hi] whose features are closest to target (D,)."""
    d = np.linalg.norm(features[lo:hi + 1] - target, axis=1)
    return lo + int(np.argmin(d))
