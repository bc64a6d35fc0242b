"""Writing one person of our 22-joint skeleton as BVH text (`write_bvh`): the rotations of
`rig.solve_rig` (continuous, knees and elbows as hinges, the exports' rig of
`presets.export_rigs`) → local Euler angles per joint (`channels.channel_order`), a standard
HIERARCHY/MOTION text that Blender and three.js's BVHLoader read, with presets: frame rate
(resampled: root positions linearly, rotations by slerp), units (m or cm), up axis (Y, or Z
with the character facing -Y as in Blender) and joint names (SMPL's, or Mixamo-style for rigs
that map bones by name). Reading is `formats/bvh.py`'s.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.formats.channels import channel_order
from interplay.motion.formats.presets import (
    UNITS,
    bone_axes,
    check_fps_units_names,
    export_rigs,
    joint_names,
    on_bone_axes,
)
from interplay.motion.rig import end_sites
from interplay.motion.rotations import matrix_to_euler

# Export presets (the CLI's flags and the API's query parameters offer these), shared with
# the GLB (`formats/presets.py`); the up axis is BVH's alone.
UP_AXES: tuple[str, ...] = ("y", "z")
# Y-up → Z-up: +90° about X, (x, y, z) → (x, -z, y): up +Y becomes +Z, forward +Z becomes
# -Y (Blender's front view looks along +Y at a character facing -Y).
Z_UP = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])


def _fmt(values: np.ndarray, digits: int) -> str:
    # Round, then add 0.0 so that -0.0 prints as 0.
    return " ".join(f"{v:.{digits}f}" for v in np.round(values, digits) + 0.0)


def _write_joint(j: int, depth: int, offsets: np.ndarray, local: np.ndarray, ends: dict,
                 names: tuple[str, ...], up: str, lines: list[str], columns: list[np.ndarray]) -> None:
    """Append joint j's HIERARCHY block (with its subtree) to lines and its Euler angles
    (T, 3) in degrees to columns, in the same depth-first order."""
    name, tab = names[j], "\t" * depth
    order = channel_order(sk.JOINT_NAMES[j], local[:, j], up)
    rot_channels = " ".join(f"{a}rotation" for a in order)
    root = j == sk.PELVIS
    lines += [f"{tab}{'ROOT' if root else 'JOINT'} {name}", f"{tab}{{",
              f"{tab}\tOFFSET {_fmt(np.zeros(3) if root else offsets[j], 6)}",
              f"{tab}\tCHANNELS {'6 Xposition Yposition Zposition' if root else '3'} {rot_channels}"]
    # Unwrapping keeps each angle continuous over time (same rotations, smoother curves).
    columns.append(np.rad2deg(np.unwrap(matrix_to_euler(local[:, j], order), axis=0)))
    for c in sk.children(j):
        _write_joint(c, depth + 1, offsets, local, ends, names, up, lines, columns)
    if j in ends:
        lines += [f"{tab}\tEnd Site", f"{tab}\t{{", f"{tab}\t\tOFFSET {_fmt(ends[j], 6)}", f"{tab}\t}}"]
    lines.append(f"{tab}}}")


def check_preset(out_fps: float | None = None, units: str = "m", up: str = "y",
                 names: str = "smpl") -> None:
    """ValueError naming the choices when a BVH preset value is not one we write."""
    check_fps_units_names(out_fps, units, names)
    if up not in UP_AXES:
        raise ValueError(f"up axis must be one of {', '.join(UP_AXES)}, got {up!r}")


def write_bvh(joints: np.ndarray, fps: float = sk.FPS, offsets: np.ndarray | None = None, *,
              out_fps: float | None = None, units: str = "m", up: str = "y", names: str = "smpl",
              floor: float | None = None, leaves: Mapping[str, np.ndarray] | None = None) -> str:
    """One person's joints (T, 22, 3) (metres, Y up, `fps` frames a second) → BVH text: our 22
    joints as a standard hierarchy (6 channels on the root, 3 rotation channels elsewhere,
    End Sites at head, wrists and toes), rest pose = the offsets (fitted from the motion when
    not given), the rig of `presets.export_rigs` (floor: the ground no hand, knee or foot
    goes under, for two people the shared one). Presets: out_fps (default fps; resampled over
    the same duration keeping the last pose, root linearly, rotations by slerp), units "m" or
    "cm", up "y" or "z", names "smpl" or "mixamo" (with Mixamo's rest axes: every OFFSET along
    its parent's local Y, `presets.on_bone_axes`). Re-reading reproduces joints that lie on
    those bone lengths, in those units and axes, up to the floor pass's lift of the root.
    leaves: explicit head / wrist rotations (`Motion.leaves_of`), in place of the derived."""
    joints = np.asarray(joints, dtype=np.float64)
    if joints.ndim != 3 or joints.shape[1:] != (sk.NUM_JOINTS, 3) or joints.shape[0] < 1:
        raise ValueError(f"joints must be (T, {sk.NUM_JOINTS}, 3) with T ≥ 1, got {joints.shape}")
    if not np.all(np.isfinite(joints)):
        raise ValueError("joints contain NaN or infinite values")
    if not fps > 0:
        raise ValueError(f"fps must be positive, got {fps}")
    check_preset(out_fps, units, up, names)
    if offsets is not None:
        offsets = np.asarray(offsets, dtype=np.float64)
        if offsets.shape != (sk.NUM_JOINTS, 3):
            raise ValueError(f"offsets must be ({sk.NUM_JOINTS}, 3), got {offsets.shape}")
    rate = fps if out_fps is None else float(out_fps)
    (rig,) = export_rigs([joints], fps, rate, [offsets], floor, body="joints", leaves=[leaves])
    local, root, offs = rig.matrices(), rig.root, rig.offsets
    ends = end_sites(offs)
    if names == "mixamo":
        # Mixamo's rest axes, as the GLB's: every frame is its bone's, so Z up turns the root only.
        local, offs, ends = on_bone_axes(local, offs, ends, bone_axes(offs, ends))
        if up == "z":
            local[:, sk.PELVIS] = Z_UP @ local[:, sk.PELVIS]
            root = root @ Z_UP.T
    elif up == "z":
        local = Z_UP @ local @ Z_UP.T
        root, offs = root @ Z_UP.T, offs @ Z_UP.T
        ends = {j: Z_UP @ e for j, e in ends.items()}
    scale = UNITS[units]
    root, offs = root * scale, offs * scale
    ends = {j: e * scale for j, e in ends.items()}

    lines, columns = ["HIERARCHY"], [root]
    _write_joint(sk.PELVIS, 0, offs, local, ends, joint_names(names), up, lines, columns)
    lines += ["MOTION", f"Frames: {rig.frames}", f"Frame Time: {1.0 / rate:.8f}"]
    data = np.concatenate(columns, axis=1)                        # (T, 3 + 22 * 3)
    lines += [_fmt(row[:3], 6) + " " + _fmt(row[3:], 4) for row in data]
    return "\n".join(lines) + "\n"
