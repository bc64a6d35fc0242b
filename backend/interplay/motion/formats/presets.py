"""The export presets BVH and GLB share (numpy only): frame rate, units, joint names, and the
one way both turn a person's joints into the rig they write.

    rigs = export_rigs(people, fps=20, out_fps=30)   # solved, off the floor, resampled
    joint_names("mixamo")                             # ("mixamorig:Hips", …)
    bone_axes(offsets, ends)                          # Mixamo-style rest axes (GLB, BVH)

Frame rates: the motion's duration at the new rate with the last pose kept
(`resample_rig`: ceil(duration * fps) + 1 frames). Units: metres or centimetres. Names:
SMPL's, or Mixamo's (`mixamorig:` prefix, as Mixamo's own rigs, so a retargeting tool maps
bones by name), with Mixamo's end bones (HeadTop_End, LeftToe_End, …) at the leaves' tips.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.formats.floor import floor_pass
from interplay.motion.kinematics import floor_height
from interplay.motion.rig import Rig, continuous, slerp, solve_rig

FPS_CHOICES: tuple[int, ...] = (20, 24, 30, 60)
UNITS: dict[str, float] = {"m": 1.0, "cm": 100.0}          # file units per metre
NAMINGS: tuple[str, ...] = ("smpl", "mixamo")
MIXAMO_PREFIX = "mixamorig:"
# Mixamo's names of the 22 SMPL joints, in SMPL order. SMPL's collar is Mixamo's Shoulder,
# its shoulder the (upper) Arm, elbow the ForeArm, wrist the Hand; hip the UpLeg, knee the
# Leg, ankle the Foot, foot (the ball of the foot) the ToeBase; spine1-3 are Spine, Spine1,
# Spine2.
MIXAMO_NAMES: tuple[str, ...] = tuple(MIXAMO_PREFIX + n for n in (
    "Hips", "LeftUpLeg", "RightUpLeg", "Spine", "LeftLeg", "RightLeg",
    "Spine1", "LeftFoot", "RightFoot", "Spine2", "LeftToeBase", "RightToeBase",
    "Neck", "LeftShoulder", "RightShoulder", "Head", "LeftArm",
    "RightArm", "LeftForeArm", "RightForeArm", "LeftHand", "RightHand",
))
# End bones at the leaves' tips (`rig.end_sites`), by leaf joint: Mixamo's names where its rigs
# have one; the hands (whose fingers Mixamo has and we do not) end in Hand_End.
END_NAMES: dict[str, dict[int, str]] = {
    "smpl": {sk.HEAD: "head_end", sk.LEFT_HAND: "left_wrist_end", sk.RIGHT_HAND: "right_wrist_end",
             sk.LEFT_FOOT: "left_foot_end", sk.RIGHT_FOOT: "right_foot_end"},
    "mixamo": {sk.HEAD: MIXAMO_PREFIX + "HeadTop_End", sk.LEFT_HAND: MIXAMO_PREFIX + "LeftHand_End",
               sk.RIGHT_HAND: MIXAMO_PREFIX + "RightHand_End", sk.LEFT_FOOT: MIXAMO_PREFIX + "LeftToe_End",
               sk.RIGHT_FOOT: MIXAMO_PREFIX + "RightToe_End"},
}


def joint_names(naming: str = "smpl") -> tuple[str, ...]:
    """The 22 joints' names in SMPL order under a naming ("smpl" or "mixamo")."""
    if naming not in NAMINGS:
        raise ValueError(f"joint names must be one of {', '.join(NAMINGS)}, got {naming!r}")
    return sk.JOINT_NAMES if naming == "smpl" else MIXAMO_NAMES


def check_fps_units_names(out_fps: float | None = None, units: str = "m", names: str = "smpl") -> None:
    """ValueError naming the choices when a preset value is not one we write."""
    if out_fps is not None and not (np.isfinite(out_fps) and out_fps > 0):
        raise ValueError(f"fps must be positive, got {out_fps}")
    if units not in UNITS:
        raise ValueError(f"units must be one of {', '.join(UNITS)}, got {units!r}")
    joint_names(names)


def resampled_frames(n: int, src_fps: float, dst_fps: float) -> int:
    """How many frames n frames at src_fps become at dst_fps: the duration's, rounded up so
    that the end is included."""
    if n < 2 or abs(src_fps - dst_fps) < 1e-9:
        return n
    return int(np.ceil((n - 1) / src_fps * dst_fps - 1e-6)) + 1


def resample_rig(rig: Rig, src_fps: float, dst_fps: float) -> Rig:
    """The rig at another frame rate over the same duration: root positions linearly,
    rotations by slerp, keys at i / dst_fps up to the first at or after the end, which holds
    the last pose (so no pose is dropped: ceil(duration * dst_fps) + 1 frames). Same rate:
    unchanged."""
    n = rig.frames
    if n < 2 or abs(src_fps - dst_fps) < 1e-9:
        return rig
    pos = np.minimum(np.arange(resampled_frames(n, src_fps, dst_fps)) / dst_fps * src_fps, n - 1)
    lo = np.clip(np.floor(pos + 1e-9).astype(int), 0, n - 1)
    hi = np.clip(lo + 1, 0, n - 1)
    w = np.clip(pos - lo, 0.0, 1.0)
    root = rig.root[lo] * (1 - w[:, None]) + rig.root[hi] * w[:, None]
    rot = slerp(rig.rotations[lo], rig.rotations[hi], np.broadcast_to(w[:, None], (len(w), sk.NUM_JOINTS)))
    return Rig(offsets=rig.offsets, root=root, rotations=continuous(rot))


def export_rigs(people: Sequence[np.ndarray], fps: float = sk.FPS, out_fps: float | None = None,
                offsets: Sequence[np.ndarray | None] | None = None,
                floor: float | None = None, body: str = "mesh",
                leaves: Sequence[Mapping[str, np.ndarray] | None] | None = None) -> list[Rig]:
    """Each person's rig as the exports write it: `solve_rig` (head and wrists turned, toes
    and hands pitched off the floor), resampled to out_fps keeping the last pose, then
    `floor.floor_pass` (lifted where a hand, knee or foot of the file's body — "mesh" for the
    GLB, "joints" for the BVH — would still be under it). floor: the
    people's one ground (default: `kinematics.floor_height` of them all). leaves: per person,
    explicit head / wrist rotations (`Motion.leaves`), at the motion's rate."""
    people = [np.asarray(p, np.float64) for p in people]
    ground = floor_height(people) if floor is None else float(floor)
    rate = fps if out_fps is None else float(out_fps)
    out = []
    for k, joints in enumerate(people):
        rig = solve_rig(joints, None if offsets is None else offsets[k], fps=fps, floor=ground,
                        leaves=None if leaves is None else leaves[k])
        # Lifted after resampling, so that no interpolated frame dips either.
        out.append(floor_pass(resample_rig(rig, fps, rate), ground, body)[0])
    return out


def _child_direction(offsets: np.ndarray, j: int, ends: dict[int, np.ndarray]) -> np.ndarray:
    """Where joint j's bone points at rest (world): to its child (the spine's next joint where
    it has several: the pelvis to spine1, spine3 to the neck), or to its end site."""
    main = {sk.PELVIS: sk.JOINT_INDEX["spine1"], sk.JOINT_INDEX["spine3"]: sk.NECK}
    kids = sk.children(j)
    if j in main:
        return offsets[main[j]]
    if kids:
        return offsets[kids[0]]
    return ends[j]


def bone_axes(offsets: np.ndarray, ends: dict[int, np.ndarray]) -> np.ndarray:
    """Rest (bind) rotations (22, 3, 3), world, Mixamo-style: each joint's Y axis along its
    bone (towards its child or end), Z towards the character's front (+Z; feet and toes,
    which point forward, towards up instead), X = Y × Z. With these, a reader that shows
    bones by their local Y (Blender) draws them along the limbs."""
    out = np.empty((sk.NUM_JOINTS, 3, 3))
    for j in range(sk.NUM_JOINTS):
        y = _child_direction(offsets, j, ends)
        y = y / np.linalg.norm(y)
        ref = np.array([0.0, 0.0, 1.0])
        if abs(y @ ref) > 0.7:
            ref = np.array([0.0, 1.0, 0.0])
        z = ref - (ref @ y) * y
        z /= np.linalg.norm(z)
        out[j] = np.stack([np.cross(y, z), y, z], axis=1)
    return out


def on_bone_axes(local: np.ndarray, offsets: np.ndarray, ends: dict[int, np.ndarray],
                 bind: np.ndarray) -> tuple[np.ndarray, np.ndarray, dict[int, np.ndarray]]:
    """A rig written on rest axes `bind` (22, 3, 3, world; `bone_axes`) in a format with no
    rest rotations (BVH): each joint's frame is its bind frame, so its channels turn
    parent_bind^T · local · bind (the root: local · bind) and its OFFSET (and End Site) lies
    in its parent's (its own) bind frame: bind_parent^T · offset. Forward kinematics of the
    result gives the same positions; at zero rotations the figure is not a T-pose but every
    bone runs along its parent's local Y, as in Mixamo's rigs. local (T, 22, 3, 3), offsets
    (22, 3), ends {leaf: (3,)} → the same, on the axes."""
    parent = np.stack([np.eye(3) if p < 0 else bind[p] for p in sk.PARENTS])
    out = np.swapaxes(parent, -1, -2)[None] @ local @ bind[None]
    offs = np.einsum("jki,jk->ji", parent, offsets)
    return out, offs, {j: bind[j].T @ e for j, e in ends.items()}
