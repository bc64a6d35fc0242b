"""Retargeting capture skeletons onto the 22-joint SMPL layout.

Every source family (Daz-style CMU BVH, Acclaim ASF/AMC, the 38-joint exp-map tree) first
runs its own forward kinematics to named global joint positions, then goes through
`to_smpl22`: pick/blend source joints per SMPL joint (a joint map), convert units and axes,
resample to 20 fps, and re-pose on fixed bone lengths (IK → FK) so bones cannot stretch.
Canonicalisation (floor, facing, origin) is separate because a pair shares one transform.
"""

from __future__ import annotations

from typing import Mapping, Sequence, Union, cast

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import canonicalize, fit_to_skeleton, resample

# A SMPL joint is one source joint, or a weighted blend of several (weights sum to 1).
JointSource = Union[str, Sequence[tuple[str, float]]]


def map_joints(named: Mapping[str, np.ndarray], joint_map: Mapping[str, JointSource]) -> np.ndarray:
    """Source positions {name: (T, 3)} → (T, 22, 3) in SMPL order via a joint map."""
    missing = [j for j in sk.JOINT_NAMES if j not in joint_map]
    if missing:
        raise ValueError(f"joint map lacks {missing}")
    out = []
    for name in sk.JOINT_NAMES:
        src = joint_map[name]
        if isinstance(src, str):
            out.append(named[src])
        else:
            # A weighted sum of (T, 3) arrays: src is never empty, so sum()'s start 0 never stays.
            out.append(cast(np.ndarray, sum(w * named[s] for s, w in src)))
    return np.stack(out, axis=1)


def to_smpl22(named: Mapping[str, np.ndarray], joint_map: Mapping[str, JointSource], fps: float,
              scale: float = 1.0, axes: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Named source positions at `fps` → (fitted joints (T', 22, 3) at 20 fps in metres, Y up;
    offsets (22, 3); raw mapped joints (T', 22, 3) before fitting, to measure the fit).

    scale converts source units to metres; axes (3, 3) maps source axes to ours (Y up),
    applied as p @ axes.T."""
    joints = map_joints(named, joint_map) * scale
    if axes is not None:
        joints = joints @ np.asarray(axes).T
    joints = resample(joints, fps, sk.FPS)
    fitted, offsets = fit_to_skeleton(joints)
    return fitted, offsets, joints


__all__ = ["JointSource", "map_joints", "to_smpl22", "canonicalize"]
