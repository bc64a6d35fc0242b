"""Two-person training data: windows cut from two-person clips (captured salsa pairs and
composed synthetic pairs) with both role orders and left/right mirroring, and the relative
features interaction (CODA) and reaction (ARFlow) models condition on. numpy only.

Shapes: a person's joints (T, 22, 3) metres, Y up; windows (N, 2, L, 22, 3).
Mirroring is the reflection x → -x with every left_* joint swapped with its right_* partner,
applied to both people: a right-hand handshake becomes a left-hand one.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.clip import Clip
from interplay.motion.kinematics import facing_angle
from interplay.motion.pair.interaction import joint_distance_map
from interplay.motion.rotations import yaw_matrix

# Index of each joint's mirror image (left_* ↔ right_*; centre joints map to themselves).
MIRROR_JOINTS = np.array([
    sk.JOINT_INDEX[n.replace("left_", "right_") if n.startswith("left_")
                   else n.replace("right_", "left_") if n.startswith("right_") else n]
    for n in sk.JOINT_NAMES])
_FLIP_X = np.array([-1.0, 1.0, 1.0])


def mirror(joints: np.ndarray) -> np.ndarray:
    """Left/right mirror image of joints or rest offsets (..., 22, 3): x → -x, sides swapped."""
    joints = np.asarray(joints)
    if joints.shape[-2:] != (sk.NUM_JOINTS, 3):
        raise ValueError(f"expected (..., 22, 3) joints, got {joints.shape}")
    return joints[..., MIRROR_JOINTS, :] * _FLIP_X


def heading_frame(joints: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per-frame heading frame of one person: origin (T, 3) the pelvis on the floor plane
    (y = 0) and yaw (T,) radians of the facing direction (0 = facing +Z)."""
    origin = np.asarray(joints, dtype=np.float64)[:, sk.PELVIS].copy()
    origin[:, 1] = 0.0
    return origin, facing_angle(joints)


def to_heading_frame(first: np.ndarray, other: np.ndarray) -> np.ndarray:
    """`other` (T, J, 3) expressed per frame in `first`'s heading frame: first's pelvis at the
    XZ origin, first facing +Z, first's left at +X (heights unchanged)."""
    origin, yaw = heading_frame(first)
    rot = yaw_matrix(-yaw)                                               # (T, 3, 3)
    return np.einsum("tij,tkj->tki", rot, np.asarray(other, dtype=np.float64) - origin[:, None])


def relative_root(first: np.ndarray, second: np.ndarray) -> np.ndarray:
    """The second person's root in the first's heading frame, per frame (T, 4): lateral x
    (+ = first's left) and forward z of the second's pelvis, and sin, cos of the second's
    facing yaw relative to the first's (cos = -1 when they face each other)."""
    pos = to_heading_frame(first, second[:, [sk.PELVIS]])[:, 0]
    dyaw = facing_angle(second) - facing_angle(first)
    return np.stack([pos[:, 0], pos[:, 2], np.sin(dyaw), np.cos(dyaw)], axis=1)


def distance_map(first: np.ndarray, second: np.ndarray, joints=None) -> np.ndarray:
    """Joint distance map (T, J, J) between the two people (CODA's D; rows first's joints),
    over all 22 joints or the given subset (e.g. skeleton.KEY_JOINTS)."""
    idx = list(range(sk.NUM_JOINTS)) if joints is None else list(joints)
    return joint_distance_map(np.asarray(first)[:, idx], np.asarray(second)[:, idx])


def interaction_features(first: np.ndarray, second: np.ndarray, joints=sk.KEY_JOINTS) -> np.ndarray:
    """Per-frame vector (T, 4 + J²): relative_root and the flattened key-joint distance map."""
    d = distance_map(first, second, joints)
    return np.concatenate([relative_root(first, second), d.reshape(len(d), -1)], axis=1)


def canonical_window(people: np.ndarray) -> np.ndarray:
    """A window (2, L, 22, 3) moved rigidly so the first person's pelvis is at the XZ origin
    facing +Z on its first frame (heights unchanged: clips are already on the floor)."""
    first = people[0, 0]
    rot = yaw_matrix(-facing_angle(first))
    shift = -(rot @ first[sk.PELVIS])
    shift[1] = 0.0
    return people @ rot.T + shift


@dataclass
class PairWindows:
    joints: np.ndarray      # (N, 2, L, 22, 3) float32
    clip_ids: list[str]     # (N,) clip of each window
    starts: np.ndarray      # (N,) first frame in the clip
    swapped: np.ndarray     # (N,) bool: people in reversed role order (clip's second first)
    mirrored: np.ndarray    # (N,) bool: left/right mirrored
    synthetic: np.ndarray   # (N,) bool: from a composed clip

    def __len__(self) -> int:
        return len(self.clip_ids)


def pair_windows(clips: Iterable[Clip], length: int, stride: int, roles: str = "both",
                 mirror: bool = True, canonical: bool = True) -> PairWindows:
    """Training windows of `length` frames every `stride` frames from every two-person clip.

    roles: "both" adds each window with the people swapped (the follower as first person),
    "as_is" keeps the clip's order. mirror adds the left/right mirror of every window. canonical: each window is moved so its first person starts at the origin
    facing +Z. Clips shorter than `length` give no window."""
    if length < 1 or stride < 1:
        raise ValueError(f"length and stride must be positive, got {length} and {stride}")
    if roles not in ("both", "as_is"):
        raise ValueError(f"roles must be 'both' or 'as_is', got {roles!r}")
    out, ids, starts, swapped, mirrored, synth = [], [], [], [], [], []
    for c in clips:
        if len(c.people) != 2 or c.frames < length:
            continue
        both = np.stack([np.asarray(p, dtype=np.float64) for p in c.people])   # (2, T, 22, 3)
        for s in range(0, c.frames - length + 1, stride):
            win = both[:, s:s + length]
            for swap in ((False, True) if roles == "both" else (False,)):
                w = win[::-1] if swap else win
                w = canonical_window(w) if canonical else w
                for flip in ((False, True) if mirror else (False,)):
                    out.append(_mirror_people(w) if flip else w)
                    ids.append(c.id)
                    starts.append(s)
                    swapped.append(swap)
                    mirrored.append(flip)
                    synth.append(c.synthetic)
    joints = (np.stack(out).astype(np.float32) if out
              else np.zeros((0, 2, length, sk.NUM_JOINTS, 3), np.float32))
    return PairWindows(joints, ids, np.array(starts, dtype=int), np.array(swapped, dtype=bool),
                       np.array(mirrored, dtype=bool), np.array(synth, dtype=bool))


def _mirror_people(people: np.ndarray) -> np.ndarray:
    return people[..., MIRROR_JOINTS, :] * _FLIP_X
