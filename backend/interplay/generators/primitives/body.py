"""Rigid pieces of a body turned about a joint, per frame, and the torso's axes: the moves every
primitive is made of. Turning a joint's whole subtree about the joint keeps every bone length
exactly (to float64 rounding), as two-bone IK (`motion.ik`) does for the limbs.

Shapes: joints (T, 22, 3) metres, Y up; axes (T, 3) unit; angles (T,) radians.
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.bodyframe import body_frame
from interplay.motion.ik import descendants

J = sk.JOINT_INDEX
UP = np.array([0.0, 1.0, 0.0])
LEGS = tuple(J[f"{s}_{p}"] for s in ("left", "right") for p in ("hip", "knee", "ankle", "foot"))


def unit(v: np.ndarray) -> np.ndarray:
    return v / np.maximum(np.linalg.norm(v, axis=-1, keepdims=True), 1e-12)


def rotation(axis: np.ndarray, angle: np.ndarray) -> np.ndarray:
    """Rotation matrices (T, 3, 3) about unit axes (T, 3) by angles (T,) (right hand)."""
    axis = unit(np.asarray(axis, dtype=np.float64))
    angle = np.asarray(angle, dtype=np.float64)
    x, y, z = axis[..., 0], axis[..., 1], axis[..., 2]
    c, s = np.cos(angle), np.sin(angle)
    C = 1.0 - c
    return np.stack([
        np.stack([c + x * x * C, x * y * C - z * s, x * z * C + y * s], -1),
        np.stack([y * x * C + z * s, c + y * y * C, y * z * C - x * s], -1),
        np.stack([z * x * C - y * s, z * y * C + x * s, c + z * z * C], -1)], -2)


def turn(joints: np.ndarray, which: list[int] | np.ndarray, pivot: np.ndarray, axis: np.ndarray,
         angle: np.ndarray) -> np.ndarray:
    """Joints with the joints `which` turned about `pivot` (T, 3) around `axis` (T, 3) by
    `angle` (T,) radians; a new array."""
    out = np.asarray(joints, dtype=np.float64).copy()
    t = len(out)
    rot = rotation(np.broadcast_to(axis, (t, 3)), np.broadcast_to(angle, (t,)))
    idx = np.asarray(which, dtype=int)
    rel = out[:, idx] - pivot[:, None]
    out[:, idx] = pivot[:, None] + np.einsum("tij,tkj->tki", rot, rel)
    return out


def turn_subtree(joints: np.ndarray, joint: int, axis: np.ndarray, angle: np.ndarray,
                 include_self: bool = False) -> np.ndarray:
    """Joints with everything below `joint` turned about it (the joint itself stays)."""
    which = descendants(joint) + ([joint] if include_self else [])
    return turn(joints, which, np.asarray(joints, dtype=np.float64)[:, joint], axis, angle)


def upper_body(joint: int = J["spine1"]) -> list[int]:
    """`joint` and every joint above it in the tree (the trunk, arms and head)."""
    return [joint] + descendants(joint)


def axes(joints: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The person's (left, up, forward) unit axes per frame (T, 3) on the ground (bodyframe's
    smoothed facing); a single frame is measured as two."""
    j = np.asarray(joints, dtype=np.float64)
    b = body_frame(j if len(j) > 1 else np.concatenate([j, j]), sk.FPS)
    t = len(j)
    return b.left[:t], np.broadcast_to(UP, (t, 3)).copy(), b.forward[:t]


def trunk_axes(joints: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The trunk's own (left, up = pelvis → neck, chest normal) unit axes per frame, which lie
    or lean with the body (lying supine, the chest normal points up)."""
    j = np.asarray(joints, dtype=np.float64)
    across = (j[:, sk.LEFT_SHOULDER] - j[:, sk.RIGHT_SHOULDER] + j[:, sk.LEFT_HIP]
              - j[:, sk.RIGHT_HIP])
    up = unit(j[:, sk.NECK] - j[:, sk.PELVIS])
    chest = unit(np.cross(across, up))
    left = unit(np.cross(up, chest))
    return left, up, chest


def bone_error(a: np.ndarray, b: np.ndarray) -> float:
    """Largest bone-length difference (m) between two motions of the same person."""
    return float(np.abs(sk.bone_lengths(a) - np.median(sk.bone_lengths(b), axis=0)).max())


def hold(frame: np.ndarray, t: int) -> np.ndarray:
    """One pose (22, 3) held for t frames."""
    return np.repeat(np.asarray(frame, dtype=np.float64)[None], t, axis=0)
