"""A person's own frame of reference over a motion: facing axes, heights above the local floor,
velocities and the standing pelvis height, the quantities every pose code is measured in.

Axes: forward is `kinematics.facing_direction` (hips and shoulders) smoothed over a quarter
second, left = up × forward (+X for a person facing +Z, the skeleton's convention), so
mirroring a motion mirrors every lateral coordinate. numpy only.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import facing_direction
from interplay.motion.signals import smooth, window_percentile

J = sk.JOINT_INDEX
HIPS = [J["left_hip"], J["right_hip"]]
KNEES = [J["left_knee"], J["right_knee"]]
ANKLES = [J["left_ankle"], J["right_ankle"]]
TOES = [J["left_foot"], J["right_foot"]]
DOWN = np.array([0.0, -1.0, 0.0])

FACING_SMOOTH_S = 0.25   # hips/shoulders jitter frame to frame; a quarter second keeps turns sharp
FLOOR_WINDOW_S = 1.0     # the floor under a frame: the lowest point within ±1 s (every gait
                         # cycle touches down in that time, a jump is shorter) …
FLOOR_PERCENTILE = 10.0  # … as its 10th percentile, robust to a bad frame
GROUND_PERCENTILE = 3.0  # a foot joint's ground level: a low percentile of its height …
UPRIGHT_TILT_DEG = 30.0  # … over frames with the torso this close to vertical (lying on the
                         # floor puts the ankles lower than standing on them does)


def frames(seconds: float, fps: float) -> int:
    """A duration in whole frames (at least one)."""
    return max(1, int(round(seconds * fps)))


def angle(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Angle in degrees between vectors (..., 3)."""
    cos = (u * v).sum(-1) / np.maximum(np.linalg.norm(u, axis=-1) * np.linalg.norm(v, axis=-1), 1e-9)
    return np.degrees(np.arccos(np.clip(cos, -1.0, 1.0)))


@dataclass(frozen=True)
class BodyFrame:
    joints: np.ndarray       # (T, 22, 3) metres
    fps: float
    forward: np.ndarray      # (T, 3) unit, on the ground
    left: np.ndarray         # (T, 3) unit, up × forward
    height: np.ndarray       # (T, 22) metres above the local floor
    velocity: np.ndarray     # (T, 22, 3) m/s
    tilt: np.ndarray         # (T,) torso (pelvis → neck) angle from vertical, degrees
    ankle_ground: float      # ankle / toe joint heights when standing on the floor (m)
    toe_ground: float
    stand: float             # pelvis height when standing straight (m)

    def local(self, v: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(towards the left, up, forward) components of world vectors (T, 3)."""
        return (v * self.left).sum(-1), v[:, 1], (v * self.forward).sum(-1)

    @property
    def hspeed(self) -> np.ndarray:
        """Horizontal speed of every joint (T, 22), m/s."""
        return np.linalg.norm(self.velocity[..., [0, 2]], axis=-1)

    def foot_height(self, side: str) -> np.ndarray:
        """Height (T,) of a foot off the ground: the lower of its ankle and toe joints, each
        above its own standing level."""
        return np.minimum(self.height[:, J[f"{side}_ankle"]] - self.ankle_ground,
                          self.height[:, J[f"{side}_foot"]] - self.toe_ground)


def body_frame(joints: np.ndarray, fps: float) -> BodyFrame:
    """The body frame of one person's motion (T ≥ 2, 22, 3)."""
    t = joints.shape[0]
    fwd = smooth(facing_direction(joints), frames(FACING_SMOOTH_S, fps))
    fwd /= np.maximum(np.linalg.norm(fwd, axis=-1, keepdims=True), 1e-9)
    left = np.stack([fwd[:, 2], np.zeros(t), -fwd[:, 0]], axis=-1)
    # Heights above the local floor: a low percentile of the lowest joint within ±1 s, so a
    # sloped capture floor or a raised step is the ground while a jump still rises off it.
    floor = window_percentile(joints[..., 1].min(axis=1), 2 * frames(FLOOR_WINDOW_S, fps) + 1,
                              FLOOR_PERCENTILE)
    y = joints[..., 1] - floor[:, None]
    tilt = angle(joints[:, sk.NECK] - joints[:, sk.PELVIS], -DOWN)
    # Standing pelvis height: hip drop below the pelvis + straight legs + ankle height.
    legs = np.median(np.linalg.norm(joints[:, HIPS] - joints[:, KNEES], axis=-1)
                     + np.linalg.norm(joints[:, KNEES] - joints[:, ANKLES], axis=-1))
    hip_bone = np.median(np.linalg.norm(joints[:, HIPS] - joints[:, [sk.PELVIS]], axis=-1))
    upright = (tilt < UPRIGHT_TILT_DEG) & (y[:, sk.PELVIS] > 0.7 * (legs + hip_bone))
    ref = y[upright] if upright.sum() >= 5 else y
    ankle_ground = float(np.percentile(ref[:, ANKLES], GROUND_PERCENTILE))
    toe_ground = float(np.percentile(ref[:, TOES], GROUND_PERCENTILE))
    drop = joints[:, sk.PELVIS, 1] - joints[:, HIPS, 1].mean(1)
    hip_drop = max(float(np.median(drop[upright])) if upright.any() else 0.0, 0.6 * hip_bone)
    return BodyFrame(joints=joints, fps=fps, forward=fwd, left=left, height=y,
                     velocity=np.gradient(joints, 1.0 / fps, axis=0), tilt=tilt,
                     ankle_ground=ankle_ground, toe_ground=toe_ground,
                     stand=float(hip_drop + legs + ankle_ground))
