"""How far the leaves (head, wrists, toes) turn between frames against their parent bone: the
measure behind issue 27's "head and wrist channels ≤ 30° frame to frame except where the
source itself moves faster". numpy only.

A leaf's channel is its local rotation, relative to its parent bone, so a step of the channel
is allowed up to STEP degrees, or as much as the parent bone itself turns that frame (its
whole rotation, twist included: a forearm that rolls 50° in a frame rolls a hand at rest in
the world by 50° in its channel). `interplay export-leaves` prints these on the library;
`tests/motion/test_rig_steps.py` holds every library clip to them.

    excess = leaf_excess(rig)           # {"left_wrist": (T-1,) degrees over the allowance, ...}
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.rig.base import Rig, global_rotations, rig_positions

STEP = 30.0                      # degrees a frame a leaf may always turn
J = sk.JOINT_INDEX
# Each leaf and the joint whose bone it hangs from (that joint's rotation turns the bone).
LEAF_PARENTS: dict[str, str] = {
    "head": "neck", "left_wrist": "left_elbow", "right_wrist": "right_elbow",
    "left_foot": "left_ankle", "right_foot": "right_ankle",
}


def quat_steps(q: np.ndarray) -> np.ndarray:
    """Angles (T-1, ...) in degrees between consecutive unit quaternions (T, ..., 4)."""
    dot = np.abs(np.sum(q[1:] * q[:-1], axis=-1))
    return np.degrees(2 * np.arccos(np.clip(dot, 0.0, 1.0)))


def matrix_steps(m: np.ndarray) -> np.ndarray:
    """Angles (T-1,) in degrees between consecutive rotation matrices (T, 3, 3)."""
    rel = np.einsum("tji,tjk->tik", m[:-1], m[1:])
    return np.degrees(np.arccos(np.clip((np.trace(rel, axis1=1, axis2=2) - 1) / 2, -1.0, 1.0)))


def direction_steps(joints: np.ndarray, a: int, b: int) -> np.ndarray:
    """Angles (T-1,) in degrees the bone a → b's direction turns between frames (no twist)."""
    d = joints[:, b] - joints[:, a]
    d = d / np.linalg.norm(d, axis=-1, keepdims=True)
    return np.degrees(np.arccos(np.clip(np.sum(d[1:] * d[:-1], axis=-1), -1.0, 1.0)))


def leaf_excess(rig: Rig, *, direction: bool = False) -> dict[str, np.ndarray]:
    """Per leaf (LEAF_PARENTS), degrees (T-1,) its local rotation's step exceeds max(STEP,
    the parent bone's turn that frame); ≤ 0 where it keeps within. direction=True: against
    the turn of the parent bone's direction only (parent joint → leaf joint, no twist; the
    stricter measure issue 27's first counts used)."""
    if rig.frames < 2:
        return {leaf: np.zeros(0) for leaf in LEAF_PARENTS}
    glob = None if direction else global_rotations(rig)
    joints = rig_positions(rig) if direction else None
    out = {}
    for leaf, parent in LEAF_PARENTS.items():
        if joints is not None:
            turn = direction_steps(joints, J[parent], J[leaf])
        else:
            assert glob is not None
            turn = matrix_steps(glob[:, J[parent]])
        out[leaf] = quat_steps(rig.rotations[:, J[leaf]]) - np.maximum(STEP, turn)
    return out
