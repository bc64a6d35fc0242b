"""The `Rig` (a person's motion as a skeleton animation) and what every part of the solver
and the exports share about it: reading it from Motion JSON, forward kinematics, slerp, and
quaternions kept continuous through time. numpy only."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import forward_kinematics
from interplay.motion.rotations import quat_to_matrix


@dataclass(frozen=True, eq=False)
class Rig:
    """A person's motion as a skeleton animation.

    offsets (22, 3): rest offsets (metres, parent → child in the parent's rest frame; the
    rest pose faces +Z, Y up; the root row is the rest pelvis height). root (T, 3): pelvis
    positions. rotations (T, 22, 4): local rotations, unit quaternions (w, x, y, z), each
    relative to its parent (the pelvis's is global), identity in the rest pose."""
    offsets: np.ndarray
    root: np.ndarray
    rotations: np.ndarray

    @property
    def frames(self) -> int:
        return int(self.root.shape[0])

    def matrices(self) -> np.ndarray:
        """Local rotation matrices (T, 22, 3, 3)."""
        return quat_to_matrix(self.rotations)


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.maximum(np.linalg.norm(v, axis=-1, keepdims=True), 1e-12)


def _perp(v: np.ndarray, axis: np.ndarray) -> np.ndarray:
    """v without its component along the unit axis."""
    return v - np.sum(v * axis, axis=-1, keepdims=True) * axis


def _frame(primary: np.ndarray, secondary: np.ndarray) -> np.ndarray:
    """Orthonormal frames (..., 3, 3), columns: the unit primary, the secondary made
    perpendicular to it, their cross product."""
    a = _unit(primary)
    b = _unit(_perp(secondary, a))
    return np.stack([a, b, np.cross(a, b)], axis=-1)


def continuous(q: np.ndarray) -> np.ndarray:
    """Quaternions (T, J, 4) with each one's sign flipped to agree with the frame before."""
    q = q.copy()
    for i in range(1, q.shape[0]):
        flip = np.sum(q[i] * q[i - 1], axis=-1) < 0
        q[i, flip] *= -1.0
    return q


def rig_from_json(person: dict) -> Rig:
    """The Rig of one person of a version-2 Motion JSON ({"rig": {"offsets", "root",
    "rotations"}}); ValueError when it is missing or malformed."""
    block = person.get("rig") if isinstance(person, dict) else None
    if not isinstance(block, dict):
        raise ValueError("the person has no 'rig' (a version-1 motion: solve_rig its joints)")
    try:
        offsets, root, rotations = (np.asarray(block[k], dtype=np.float64)
                                    for k in ("offsets", "root", "rotations"))
    except (KeyError, TypeError, ValueError) as exc:
        raise ValueError(f"'rig' needs numeric 'offsets', 'root' and 'rotations': {exc}") from None
    t = root.shape[0] if root.ndim == 2 else -1
    if offsets.shape != (sk.NUM_JOINTS, 3) or root.shape != (t, 3) or rotations.shape != (t, sk.NUM_JOINTS, 4):
        raise ValueError(f"'rig' shapes must be offsets (22, 3), root (T, 3), rotations (T, 22, 4); "
                         f"got {offsets.shape}, {root.shape}, {rotations.shape}")
    return Rig(offsets=offsets, root=root, rotations=rotations / np.linalg.norm(rotations, axis=-1, keepdims=True))


def global_rotations(rig: Rig) -> np.ndarray:
    """Global rotation matrices (T, 22, 3, 3) of every joint."""
    return forward_kinematics(rig.matrices(), rig.root, rig.offsets)[1]


def rig_positions(rig: Rig) -> np.ndarray:
    """Joint positions (T, 22, 3) by forward kinematics of the rig."""
    return forward_kinematics(rig.matrices(), rig.root, rig.offsets)[0]


def slerp(q0: np.ndarray, q1: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Spherical interpolation of unit quaternions (..., 4) by weights w (...) in [0, 1],
    along the shorter arc."""
    q0, q1 = np.asarray(q0, dtype=np.float64), np.asarray(q1, dtype=np.float64)
    w = np.asarray(w, dtype=np.float64)[..., None]
    dot = np.sum(q0 * q1, axis=-1, keepdims=True)
    q1 = np.where(dot < 0, -q1, q1)
    dot = np.abs(dot)
    theta = np.arccos(np.clip(dot, -1.0, 1.0))
    sin = np.sin(theta)
    near = sin < 1e-6
    a = np.where(near, 1 - w, np.sin((1 - w) * theta) / np.where(near, 1.0, sin))
    b = np.where(near, w, np.sin(w * theta) / np.where(near, 1.0, sin))
    out = a * q0 + b * q1
    return out / np.linalg.norm(out, axis=-1, keepdims=True)
