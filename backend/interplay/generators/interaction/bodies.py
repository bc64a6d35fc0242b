"""Both people on one skeleton, and the small pose tools the composed scenes share. numpy only.

Every real clip a scene uses is re-posed onto SHARED, the SMPL template's bones (forearm
0.266 m, as every SPAM output): its local rotations are read by IK on the performer's own
bones and played by FK on the template's, with the root path scaled by the ratio of leg
lengths (so strides and pelvis height suit the new legs), then set on the floor. Two people of
a scene therefore have exactly the same bone offsets, whatever captures they came from
(issue 15: no 0.16 m forearms next to 0.19 m ones).

Shapes: joints (T, 22, 3) float64 metres, Y up, 20 fps.
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.checks.measures import clearance
from interplay.motion.kinematics import (
    facing_angle,
    fit_to_skeleton,
    forward_kinematics,
    inverse_kinematics,
)
from interplay.motion.rotations import yaw_matrix

SHARED = sk.REST_OFFSETS.copy()
FEET = sk.FOOT_JOINTS


def leg_length(offsets: np.ndarray) -> float:
    """Thigh + shin (mean of both legs) of rest offsets (22, 3)."""
    j = sk.JOINT_INDEX
    return float(np.mean([np.linalg.norm(offsets[j[f"{s}_knee"]]) + np.linalg.norm(offsets[j[f"{s}_ankle"]])
                          for s in ("left", "right")]))


def ground(joints: np.ndarray) -> np.ndarray:
    """Joints moved up or down so the feet rest on y = 0 (the 10th percentile over frames of
    the lowest foot joint's clearance, measures.clearance: robust to a lifted foot)."""
    gap = clearance(joints, FEET)
    return joints - np.array([0.0, float(np.percentile(gap, 10)), 0.0])


def level(joints: np.ndarray, window: int = 20) -> np.ndarray:
    """A walk captured on a tilted floor (several CMU walks rise 5–8 cm over a few metres)
    put on a level one: the lowest foot clearance of each `window`-frame stretch, fitted by
    a line over time, is taken off every frame."""
    gap = clearance(joints, FEET)
    n = len(gap) // window
    if n < 2:
        return ground(joints)
    t = np.array([i * window + window / 2 for i in range(n)])
    low = np.array([gap[i * window:(i + 1) * window].min() for i in range(n)])
    slope, icpt = np.polyfit(t, low, 1)
    y = icpt + slope * np.arange(len(gap))
    return joints - y[:, None, None] * np.array([0.0, 1.0, 0.0])


def on_shared(joints: np.ndarray, offsets: np.ndarray) -> np.ndarray:
    """A captured motion re-posed on the shared skeleton (see the module doc), on the floor."""
    j = np.asarray(joints, dtype=np.float64)
    local, root = inverse_kinematics(j, np.asarray(offsets, dtype=np.float64))
    scale = leg_length(SHARED) / max(leg_length(np.asarray(offsets, dtype=np.float64)), 1e-6)
    out, _ = forward_kinematics(local, root * scale, SHARED)
    return ground(out)


def refit(joints: np.ndarray) -> np.ndarray:
    """Blended or interpolated frames back on the shared bones (IK → FK), exactly."""
    return fit_to_skeleton(np.asarray(joints, dtype=np.float64), SHARED)[0]


def yaw_of(joints: np.ndarray) -> float:
    """Mean facing yaw (radians, 0 = +Z, positive towards +X) over the frames."""
    a = facing_angle(joints)
    return float(np.arctan2(np.sin(a).mean(), np.cos(a).mean()))


def turn_to(joints: np.ndarray, yaw: float, pelvis_xz: np.ndarray | None = None,
            frame: int = 0, current: float | None = None) -> np.ndarray:
    """Joints turned about the vertical through the pelvis of `frame` so that their heading
    (`current`, default their mean facing) becomes `yaw`, then moved so that pelvis lies at
    `pelvis_xz` (x, z) (default: where it was)."""
    pivot = joints[frame, sk.PELVIS] * np.array([1.0, 0.0, 1.0])
    rot = yaw_matrix(yaw - (yaw_of(joints) if current is None else current))
    out = (joints - pivot) @ rot.T
    dest = pivot if pelvis_xz is None else np.array([pelvis_xz[0], 0.0, pelvis_xz[1]])
    return out + dest


def facing_pair(a: np.ndarray, b: np.ndarray, distance: float, frame_a: int = 0,
                frame_b: int = 0, lateral: float = 0.0, current: float | None = None
                ) -> tuple[np.ndarray, np.ndarray]:
    """a at the origin facing +Z (its pelvis on `frame_a`), b `distance` m in front facing a
    (its pelvis on `frame_b`), shifted `lateral` m to a's left; `current`: both people's
    heading now (default: their mean facing; walkers pass 0, they walk along +Z)."""
    a = turn_to(a, 0.0, np.zeros(2), frame_a, current)
    b = turn_to(b, np.pi, np.array([lateral, distance]), frame_b, current)
    return a, b


def extend(joints: np.ndarray, before: int, after: int, quiet: int = 12) -> np.ndarray:
    """A clip that starts and ends standing quietly, lengthened by `before` / `after` frames
    played from its first / last `quiet` frames back and forth (cosine time warp: the speed
    falls to zero at each turn, so there is no jump)."""
    parts = []
    if before > 0:
        parts.append(_back_and_forth(joints[:quiet][::-1], before)[::-1])
    parts.append(joints)
    if after > 0:
        parts.append(_back_and_forth(joints[-quiet:][::-1], after))
    return np.concatenate(parts) if len(parts) > 1 else joints.copy()


def _back_and_forth(seq: np.ndarray, frames: int) -> np.ndarray:
    """`frames` frames starting at seq[0] and moving along seq and back (seq[0] is where the
    clip joins: for a prefix it is given reversed)."""
    n = len(seq)
    if n < 2:
        return np.repeat(seq[:1], frames, axis=0)
    t = np.arange(1, frames + 1) / (n - 1)
    tau = (n - 1) * 0.5 * (1.0 - np.cos(np.pi * t))
    lo = np.clip(np.floor(tau).astype(int), 0, n - 2)
    w = (tau - lo)[:, None, None]
    return seq[lo] * (1.0 - w) + seq[lo + 1] * w


def lerp_frames(joints: np.ndarray, tau: np.ndarray) -> np.ndarray:
    """Joints at fractional frames tau (T,) of a clip, linearly interpolated (clamped)."""
    n = len(joints)
    tau = np.clip(np.asarray(tau, dtype=np.float64), 0.0, n - 1.0)
    lo = np.minimum(np.floor(tau).astype(int), n - 2) if n > 1 else np.zeros(len(tau), int)
    if n == 1:
        return np.repeat(joints, len(tau), axis=0)
    w = (tau - lo)[:, None, None]
    return joints[lo] * (1.0 - w) + joints[lo + 1] * w
