"""Per-frame motion features in the spirit of HumanML3D's 263-d vector, and their exact decoding.

One row per frame (T rows for T frames), float32, in this order (`SLICES` names each block):

  root_angvel  (1)    heading change to the next frame, rad/frame (wrapped to (-pi, pi])
  root_linvel  (2)    pelvis XZ displacement to the next frame, m/frame, in the heading frame
                      (x = towards the person's left, z = forwards)
  root_height  (1)    pelvis height y, m (absolute: the floor is y = 0)
  positions    (63)   joints 1..21 relative to the pelvis in XZ (y absolute), heading frame
  rotations    (102)  6D local rotations of the 17 joints that move a child (leaves carry
                      nothing: their rotation does not change any joint position); the
                      pelvis's is its global rotation with the heading taken out
  velocities   (66)   all 22 joints' displacement to the next frame, m/frame, heading frame
  foot_contacts (4)   left ankle, left toe, right ankle, right toe on the ground (0/1)

The heading is the facing angle of `kinematics.facing_angle` (hips and shoulders), so every
block is invariant to rotating the whole motion about Y and translating it in XZ.

Velocities are forward differences; the last frame has no next frame, so its velocity blocks
repeat the previous frame's values (zeros for a single frame; decoding never reads them).
Decoding integrates the heading and the root trajectory in float64 from a start (x, z,
heading) and poses the body by forward kinematics of the 6D rotations on fixed offsets, so
bones cannot stretch; the pelvis rotation is heading @ its heading-free 6D, so the decoded
facing is exactly the integrated heading (a minute of motion drifts by micrometres). The
positions, velocities and contacts are redundant for decoding; they are there for the models.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterable

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import (
    facing_angle,
    fit_offsets,
    forward_kinematics,
    inverse_kinematics,
)
from interplay.motion.rotations import matrix_to_6d, sixd_to_matrix, yaw_matrix

# Joints whose local rotation moves a child: every joint that is someone's parent.
ROT_JOINTS: tuple[int, ...] = tuple(j for j in range(sk.NUM_JOINTS) if sk.children(j))

_BLOCKS = (
    ("root_angvel", 1), ("root_linvel", 2), ("root_height", 1),
    ("positions", 3 * (sk.NUM_JOINTS - 1)), ("rotations", 6 * len(ROT_JOINTS)),
    ("velocities", 3 * sk.NUM_JOINTS), ("foot_contacts", len(sk.FOOT_JOINTS)),
)


def _slices() -> dict[str, slice]:
    out, start = {}, 0
    for name, size in _BLOCKS:
        out[name] = slice(start, start + size)
        start += size
    return out


SLICES: dict[str, slice] = _slices()
# Blocks holding a difference to the next frame: the last frame repeats the one before it.
_VELOCITY_BLOCKS = ("root_angvel", "root_linvel", "velocities")
FEATURE_DIM: int = SLICES["foot_contacts"].stop  # 239

# Foot contact: a foot joint is on the ground when it is both slow and low. Speeds are central
# differences in m/s; heights are above the floor at y = 0 (the processed set is canonicalised
# so). Ankles sit higher than toes above the sole, hence separate height limits.
CONTACT_SPEED = 0.6                               # m/s
CONTACT_HEIGHT = np.array([0.15, 0.08, 0.15, 0.08])  # m, in FOOT_JOINTS order (ankle, toe, ankle, toe)


def foot_contacts(joints: np.ndarray, fps: float = sk.FPS) -> np.ndarray:
    """Ground contact (T, 4) bool of the left ankle, left toe, right ankle, right toe."""
    joints = _check_joints(joints)
    feet = joints[:, list(sk.FOOT_JOINTS)]                          # (T, 4, 3)
    if len(feet) > 1:
        speed = np.linalg.norm(np.gradient(feet, axis=0), axis=-1) * fps
    else:
        speed = np.zeros(feet.shape[:2])
    return (speed < CONTACT_SPEED) & (feet[..., 1] < CONTACT_HEIGHT)


def heading(joints: np.ndarray) -> np.ndarray:
    """Heading (T,) in radians: 0 facing +Z, positive towards +X."""
    return facing_angle(_check_joints(joints))


def start_of(joints: np.ndarray) -> np.ndarray:
    """Where a motion (T, 22, 3) starts, as decode's `start`: (pelvis x, pelvis z, heading)."""
    joints = _check_joints(joints)
    return np.array([joints[0, sk.PELVIS, 0], joints[0, sk.PELVIS, 2], heading(joints[:1])[0]])


def encode(joints: np.ndarray, offsets: np.ndarray | None = None,
           rotations: np.ndarray | None = None) -> np.ndarray:
    """Features (T, FEATURE_DIM) float32 of one person's joints (T, 22, 3).

    offsets (22, 3) are the person's rest offsets (fit from the motion when None); rotations
    (T, 22, 3, 3) local rotations (solved by IK on the offsets when None)."""
    joints = _check_joints(joints)
    t = joints.shape[0]
    if rotations is None:
        if offsets is None:
            offsets = fit_offsets(joints)
        rotations, _ = inverse_kinematics(joints, np.asarray(offsets, dtype=np.float64))
    elif rotations.shape != (t, sk.NUM_JOINTS, 3, 3):
        raise ValueError(f"rotations must be ({t}, {sk.NUM_JOINTS}, 3, 3), got {rotations.shape}")

    theta = heading(joints)                                          # (T,)
    to_local = np.swapaxes(yaw_matrix(theta), -1, -2)                # world → heading frame
    root = joints[:, sk.PELVIS]                                      # (T, 3)
    out = np.zeros((t, FEATURE_DIM))

    # Forward differences, each in its own frame's heading frame (T-1 rows; padded below).
    step = np.diff(root, axis=0) * np.array([1.0, 0.0, 1.0])         # (T-1, 3)
    out[:-1, SLICES["root_angvel"]] = _wrap(np.diff(theta))[:, None]
    out[:-1, SLICES["root_linvel"]] = np.einsum("tij,tj->ti", to_local[:-1], step)[:, [0, 2]]
    vel = np.einsum("tij,tkj->tki", to_local[:-1], np.diff(joints, axis=0))
    out[:-1, SLICES["velocities"]] = vel.reshape(t - 1, 3 * sk.NUM_JOINTS)
    if t > 1:
        for name in _VELOCITY_BLOCKS:
            out[-1, SLICES[name]] = out[-2, SLICES[name]]

    out[:, SLICES["root_height"]] = root[:, 1:2]
    rel = joints[:, 1:] - root[:, None] * np.array([1.0, 0.0, 1.0])  # (T, 21, 3), y absolute
    out[:, SLICES["positions"]] = np.einsum("tij,tkj->tki", to_local, rel).reshape(t, -1)

    local = np.array(rotations, dtype=np.float64)[:, list(ROT_JOINTS)]  # (T, 17, 3, 3)
    local[:, 0] = to_local @ local[:, 0]                             # pelvis: heading removed
    out[:, SLICES["rotations"]] = matrix_to_6d(local).reshape(t, -1)
    out[:, SLICES["foot_contacts"]] = foot_contacts(joints)
    return out.astype(np.float32)


def decode(features: np.ndarray, offsets: np.ndarray | None = None,
           start: np.ndarray | None = None) -> np.ndarray:
    """Joints (T, 22, 3) float64 from features (T, FEATURE_DIM), by forward kinematics on
    offsets (22, 3) (the rest skeleton when None). start = (x, z, heading) of the pelvis on the
    first frame (see `start_of`); None starts at the XZ origin facing +Z, the canonical frame."""
    f = np.asarray(features, dtype=np.float64)
    if f.ndim != 2 or f.shape[1] != FEATURE_DIM:
        raise ValueError(f"features must be (T, {FEATURE_DIM}), got {f.shape}")
    offsets = sk.REST_OFFSETS if offsets is None else np.asarray(offsets, dtype=np.float64)
    if offsets.shape != (sk.NUM_JOINTS, 3):
        raise ValueError(f"offsets must be ({sk.NUM_JOINTS}, 3), got {offsets.shape}")
    start = np.zeros(3) if start is None else np.asarray(start, dtype=np.float64)
    if start.shape != (3,):
        raise ValueError(f"start must be (x, z, heading), got shape {start.shape}")
    x0, z0, theta0 = start
    t = f.shape[0]

    # Heading and root trajectory: sums over the previous frames' steps (float64, so a
    # minute-long clip drifts by micrometres, not centimetres).
    theta = theta0 + np.concatenate([[0.0], np.cumsum(f[:-1, SLICES["root_angvel"]][:, 0])])
    to_world = yaw_matrix(theta)                                     # (T, 3, 3)
    step = np.zeros((t, 3))
    step[:, [0, 2]] = f[:, SLICES["root_linvel"]]
    step = np.einsum("tij,tj->ti", to_world, step)
    root = np.zeros((t, 3))
    root[:, 0] = x0 + np.concatenate([[0.0], np.cumsum(step[:-1, 0])])
    root[:, 2] = z0 + np.concatenate([[0.0], np.cumsum(step[:-1, 2])])
    root[:, 1] = f[:, SLICES["root_height"]][:, 0]

    local = np.tile(np.eye(3), (t, sk.NUM_JOINTS, 1, 1))
    local[:, list(ROT_JOINTS)] = sixd_to_matrix(f[:, SLICES["rotations"]].reshape(t, -1, 6))
    local[:, sk.PELVIS] = to_world @ local[:, sk.PELVIS]
    joints, _ = forward_kinematics(local, root, offsets)
    return joints


def part_feature_mask(part: str) -> np.ndarray:
    """Which feature dims (FEATURE_DIM,) bool belong to a CoMA body part (aliases such as
    "left_arm" accepted). A joint's position, velocity, rotation and contact dims go to every
    part holding the joint; the root dims (pelvis) go to both lower parts."""
    part = sk.resolve_part(part)
    joints = set(int(j) for j in sk.PART_JOINTS[part])
    mask = np.zeros(FEATURE_DIM, dtype=bool)
    if sk.PELVIS in joints:
        for name in ("root_angvel", "root_linvel", "root_height"):
            mask[SLICES[name]] = True
    blocks = {  # block → (joint of each group of dims, group size)
        "positions": (range(1, sk.NUM_JOINTS), 3),
        "rotations": (ROT_JOINTS, 6),
        "velocities": (range(sk.NUM_JOINTS), 3),
        "foot_contacts": (sk.FOOT_JOINTS, 1),
    }
    for name, (owners, size) in blocks.items():
        start = SLICES[name].start
        for i, j in enumerate(owners):
            if j in joints:
                mask[start + i * size:start + (i + 1) * size] = True
    return mask


@dataclass(frozen=True, eq=False)
class Normalizer:
    """Per-dim mean and std (FEATURE_DIM,) over a data set, for the models' inputs/targets."""
    mean: np.ndarray
    std: np.ndarray
    meta: dict = field(default_factory=dict)

    @classmethod
    def fit(cls, features: np.ndarray | Iterable[np.ndarray], min_std: float = 1e-3,
            pooled: bool = False) -> "Normalizer":
        """From (T, D) arrays (or one (N, D) array), accumulated in float64. Dims that barely
        vary get std min_std, so they are not blown up. pooled=True shares one std per block
        (the block's mean std, as HumanML3D does), which keeps ratios inside a block."""
        arrays = [features] if isinstance(features, np.ndarray) else list(features)
        if not arrays or any(a.ndim != 2 or a.shape[1] != FEATURE_DIM for a in arrays):
            raise ValueError(f"Normalizer.fit needs (T, {FEATURE_DIM}) arrays")
        n = sum(a.shape[0] for a in arrays)
        if n == 0:
            raise ValueError("Normalizer.fit got no frames")
        mean = sum(a.sum(axis=0, dtype=np.float64) for a in arrays) / n
        var = sum(((a - mean) ** 2).sum(axis=0, dtype=np.float64) for a in arrays) / n
        std = np.sqrt(var)
        if pooled:
            for s in SLICES.values():
                std[s] = std[s].mean()
        std = np.maximum(std, min_std)
        return cls(mean.astype(np.float32), std.astype(np.float32),
                   {"frames": int(n), "clips": len(arrays), "pooled": pooled, "min_std": min_std})

    def normalize(self, features: np.ndarray) -> np.ndarray:
        return ((features - self.mean) / self.std).astype(np.float32)

    def denormalize(self, features: np.ndarray) -> np.ndarray:
        return (features * self.std + self.mean).astype(np.float32)

    def save(self, path: str | Path) -> None:
        np.savez(path, mean=self.mean, std=self.std, frames=self.meta.get("frames", 0),
                 clips=self.meta.get("clips", 0), pooled=self.meta.get("pooled", False),
                 min_std=self.meta.get("min_std", 0.0))

    @classmethod
    def load(cls, path: str | Path) -> "Normalizer":
        with np.load(path) as z:
            mean, std = z["mean"].astype(np.float32), z["std"].astype(np.float32)
            meta = {k: z[k].item() for k in ("frames", "clips", "pooled", "min_std") if k in z}
        if mean.shape != (FEATURE_DIM,) or std.shape != (FEATURE_DIM,):
            raise ValueError(f"{path}: normalizer is for {mean.shape[0]}-d features, "
                             f"these are {FEATURE_DIM}-d")
        return cls(mean, std, meta)


def _check_joints(joints: np.ndarray) -> np.ndarray:
    joints = np.asarray(joints, dtype=np.float64)
    if joints.ndim != 3 or joints.shape[1:] != (sk.NUM_JOINTS, 3) or joints.shape[0] < 1:
        raise ValueError(f"joints must be (T >= 1, {sk.NUM_JOINTS}, 3), got {joints.shape}")
    return joints


def _wrap(angle: np.ndarray) -> np.ndarray:
    return (angle + np.pi) % (2 * np.pi) - np.pi
