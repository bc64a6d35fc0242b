"""The one rotation solver behind every export (BVH, GLB, JSON) and the studio's skinned
character: joints (T, 22, 3) → a `Rig` of rest offsets, root positions and local joint
rotations (unit quaternions w, x, y, z) that reproduce the joints by forward kinematics.
numpy only.

`kinematics.inverse_kinematics` (the IK behind the features) takes each bone's smallest
rotation from rest with zero twist, frame by frame. That is exact for positions but its
twist is arbitrary and unstable: near a 180° swing (a deep knee bend in the parent's frame,
an arm swung behind) the smallest rotation's axis spins, and every child inherits the spin,
so an ankle can turn 140° between two frames while its bone barely moves. Here each joint's
rotation is instead built from two directions in its parent's frame: the bone it moves (exact,
so positions do not change) and a secondary axis that fixes the twist:

- hips and shoulders with their knees and elbows, solved as hinges: the knee's (elbow's)
  rotation is a turn about a fixed side-to-side axis of the thigh (upper arm) by the angle
  that gives the shin (forearm) its observed angle to the thigh, and the hip's (shoulder's)
  twist is the one that puts the shin in that hinge's plane: knees and elbows stay hinges;
- ankles: the shin's side-to-side axis (the ankle flexes about it);
- spine1 / spine2: the pelvis's and the chest's side-to-side axes blended 2:1 and 1:2, so a
  torso twist spreads along the spine; neck: the chest's side-to-side axis; collars: the
  chest's forward axis;
- the pelvis and spine3: the frame of their children (hips / collars and the bone up), as IK.

Wherever that reference says little (a straight knee or elbow has no bend plane; a bone
pointing along its reference axis), the previous frame's axis, held in the parent's frame,
takes over smoothly: the twist is propagated along time, never re-solved from rest, so it does
not jump while the bone barely moves. The leaves (head, wrists, toes) carry no bone: their
rotations are `leaves.py`'s. Quaternions keep one sign through time (q and -q are the same
rotation; a reader interpolating them must not see a flip).
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import _FRAME_CHILDREN, _joint_frames, fit_offsets, floor_height
from interplay.motion.rig.base import Rig, _frame, _perp, _unit, continuous
from interplay.motion.rig.leaves import fill_leaves
from interplay.motion.rotations import axis_angle_to_matrix, matrix_to_quat, rotation_between

J = sk.JOINT_INDEX
# Below this size (the sine of the angle between the reference and the bone; for a hinge the
# sine of the bend) the previous frame's axis is blended in, alone at zero.
_SURE = 0.5
# The secondary axis turns at most this much per frame (rad): where the reference swings
# faster (a hinge's bend plane turning while the limb is almost straight) the twist follows
# over a few frames instead of in one, and the hinge is briefly not a pure hinge.
_STEP = np.deg2rad(15.0)
_X, _Z = np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0])
# Each solved joint: (kind, joint, child, reference joint, axis, weight), in an order where a
# joint's parent and reference are solved before it. Kinds: "spine" (reference: the pelvis's
# and spine3's side axes blended, `weight` on spine3), "frame" (reference: the reference
# joint's rotation applied to `axis`), "hinge" (a hip or shoulder and, with it, its knee or
# elbow; `axis`: the hinge's rest axis, before it is made perpendicular to the bone).
_PLAN: tuple[tuple[str, int, int, int, np.ndarray, float], ...] = (
    ("spine", J["spine1"], J["spine2"], -1, _X, 1.0 / 3.0),
    ("spine", J["spine2"], J["spine3"], -1, _X, 2.0 / 3.0),
    ("frame", J["neck"], J["head"], J["spine3"], _X, 0.0),
    ("frame", J["left_collar"], J["left_shoulder"], J["spine3"], _Z, 0.0),
    ("frame", J["right_collar"], J["right_shoulder"], J["spine3"], _Z, 0.0),
    # Knees fold the shin backwards (-Y towards -Z): positive turns about +X.
    ("hinge", J["left_hip"], J["left_knee"], -1, _X, 0.0),
    ("hinge", J["right_hip"], J["right_knee"], -1, _X, 0.0),
    ("frame", J["left_ankle"], J["left_foot"], J["left_knee"], _X, 0.0),
    ("frame", J["right_ankle"], J["right_foot"], J["right_knee"], _X, 0.0),
    # Elbows fold the forearm forwards (±X towards +Z): positive turns about -Y on the left.
    ("hinge", J["left_shoulder"], J["left_elbow"], -1, np.array([0.0, -1.0, 0.0]), 0.0),
    ("hinge", J["right_shoulder"], J["right_elbow"], -1, np.array([0.0, 1.0, 0.0]), 0.0),
)


def _any_perp(v: np.ndarray) -> np.ndarray:
    trial = np.array([1.0, 0.0, 0.0]) if abs(v[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    return _unit(_perp(trial, v))


def _hinge(bone: np.ndarray, child: np.ndarray, u: np.ndarray, v: np.ndarray, a: np.ndarray
           ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A two-bone chain (a hip and knee, a shoulder and elbow) as a hinge, in the upper
    joint's parent's frame: bone, child (T, 3) unit directions of the upper and lower bone;
    u, v their rest directions, a the hinge's rest axis (unit, perpendicular to u).

    The hinge angle theta (T,) is the turn about a that gives the lower bone the observed
    angle to the upper one, on the bending side (theta grows as the limb folds; the rest pose
    is theta = 0 for the template's directions, which rest slightly folded). Returns the
    upper joint's secondary axis that makes the lower joint exactly that hinge (where the
    angle is reachable), as long as the sine of the bend (how sure it is: a straight limb has
    no bend plane), theta, and the rest lower bone turned by theta, R(a, theta) v."""
    cos = np.sum(bone * child, axis=-1)
    av = a @ v
    v_perp = v - av * a
    big_a, big_b, big_c = av * (a @ u), u @ v_perp, u @ np.cross(a, v_perp)
    size, phi = np.hypot(big_b, big_c), np.arctan2(big_c, big_b)
    theta = phi + np.arccos(np.clip((cos - big_a) / max(size, 1e-12), -1.0, 1.0))
    turned = axis_angle_to_matrix(a[None] * theta[:, None]) @ v
    across = _perp(child, bone)                                  # its length: sin(bend)
    observed = _frame(bone, across)
    rest = _frame(np.broadcast_to(u, turned.shape), _perp(turned, u))
    axis = np.einsum("tij,tkj,k->ti", observed, rest, a)
    return axis * np.linalg.norm(across, axis=-1, keepdims=True), theta, turned


def _turn_at_most(a: np.ndarray, b: np.ndarray, axis: np.ndarray, limit: float) -> np.ndarray:
    """b, or a turned towards b about the unit axis by limit (rad) when they are further
    apart (a and b unit and perpendicular to the axis)."""
    cos = float(np.clip(a @ b, -1.0, 1.0))
    if cos >= np.cos(limit):
        return b
    side = np.cross(axis, a)
    sign = 1.0 if side @ b >= 0 else -1.0
    return np.cos(limit) * a + sign * np.sin(limit) * side


def _propagate(bone: np.ndarray, ref: np.ndarray, start: np.ndarray) -> np.ndarray:
    """Secondary axes (T, 3), unit and perpendicular to the unit bones (T, 3), all in the
    parent's frame: each frame's reference made perpendicular to the bone, with the previous
    frame's axis blended in where the reference is short (alone when it vanishes; below _SURE
    the reference weighs size² / _SURE against 1 - size / _SURE), turning at most _STEP per
    frame. The reference's size is the sine of the angle between it and the
    bone (a hinge's: the sine of the bend).

    The walk starts at the first frame whose reference is sure and goes forward from there
    and back to frame 0, so a motion that starts with a straight arm takes its axis from the
    first bend; with no sure frame it starts from the rest axis `start`."""
    t = bone.shape[0]
    ref_p = _perp(ref, bone)
    size = np.linalg.norm(ref_p, axis=-1)
    keep = np.clip(1.0 - size / _SURE, 0.0, 1.0)
    # A short reference counts for less still (its direction is noise when it nearly vanishes).
    ref_p = ref_p * np.clip(size / _SURE, 0.0, 1.0)[:, None]
    out = np.empty((t, 3))
    sure = np.flatnonzero(size >= _SURE)
    first = int(sure[0]) if len(sure) else 0
    prev = start
    if len(sure):
        prev = ref_p[first] / np.linalg.norm(ref_p[first])
    for order in (range(first, t), range(first - 1, -1, -1)):
        if order.start < first:
            prev = out[first]
        for i in order:
            b = bone[i]
            r = ref_p[i]
            p = prev - (prev @ b) * b
            s = r + keep[i] * p
            n = np.sqrt(s @ s)
            n_p = np.sqrt(p @ p)
            if n < 1e-9:
                s, n = (p, n_p) if n_p > 1e-9 else (_any_perp(b), 1.0)
            s = s / n
            if n_p > 1e-9:
                s = _turn_at_most(p / n_p, s, b, _STEP)
            prev = s
            out[i] = prev
    return out


def solve_rig(joints: np.ndarray, offsets: np.ndarray | None = None, *, fps: float = sk.FPS,
              floor: float | None = None, leaves: Mapping[str, np.ndarray] | None = None) -> Rig:
    """A Rig (offsets, root, continuous local rotations) reproducing joints (T, 22, 3) by FK:
    exactly (to float precision) when the joints lie on the offsets' bone lengths, as every
    motion in Interplay does. offsets (22, 3) default to the motion's own (`fit_offsets`).
    floor: the ground's height (y, m) the toe tips keep above; the person's own
    (`kinematics.floor_height`) when None; pass the shared one for two people. fps: the
    motion's rate (the hands' lag is in seconds). leaves: explicit local rotations (T, 4),
    w x y z, of "head", "left_wrist", "right_wrist" (an edit's, a capture's) or the toes
    "left_foot", "right_foot" (a capture's, still kept off the floor), in place of the
    derived; rows of NaN keep the derived on those frames (blended into the given ones)."""
    joints = np.asarray(joints, dtype=np.float64)
    if joints.ndim != 3 or joints.shape[1:] != (sk.NUM_JOINTS, 3) or joints.shape[0] < 1:
        raise ValueError(f"joints must be (T >= 1, {sk.NUM_JOINTS}, 3), got {joints.shape}")
    if not np.all(np.isfinite(joints)):
        raise ValueError("joints contain NaN or infinite values")
    offsets = fit_offsets(joints) if offsets is None else np.asarray(offsets, dtype=np.float64)
    if offsets.shape != (sk.NUM_JOINTS, 3):
        raise ValueError(f"offsets must be ({sk.NUM_JOINTS}, 3), got {offsets.shape}")
    t = joints.shape[0]
    rest = sk.rest_joints(offsets)
    glob = np.tile(np.eye(3), (t, sk.NUM_JOINTS, 1, 1))
    local = glob.copy()
    # Frame joints: the rotation taking the rest frame of their children onto the observed.
    for j in _FRAME_CHILDREN:
        glob[:, j] = _joint_frames(joints, j) @ _joint_frames(rest, j).T
    local[:, sk.PELVIS] = glob[:, sk.PELVIS]

    for kind, j, c, ref_joint, vec, weight in _PLAN:
        p = sk.PARENTS[j]
        gp = glob[:, p]                                          # parent's global (T, 3, 3)
        to_parent = np.swapaxes(gp, -1, -2)
        bone_rest = _unit(offsets[c])
        bone = _unit(np.einsum("tij,tj->ti", to_parent, joints[:, c] - joints[:, j]))
        if kind == "hinge":
            (grand,) = sk.children(c)
            lower = _unit(np.einsum("tij,tj->ti", to_parent, joints[:, grand] - joints[:, c]))
            sec_rest = _unit(_perp(vec, bone_rest))
            ref_local, theta, turned = _hinge(bone, lower, bone_rest, _unit(offsets[grand]), sec_rest)
        elif kind == "frame":
            ref_local = np.einsum("tij,tjk,k->ti", to_parent, glob[:, ref_joint], vec)
            sec_rest = _unit(_perp(vec, bone_rest))
        else:                                                    # spine
            side = (1 - weight) * glob[:, sk.PELVIS, :, 0] + weight * glob[:, J["spine3"], :, 0]
            ref_local = np.einsum("tij,tj->ti", to_parent, side)
            sec_rest = _unit(_perp(vec, bone_rest))
        sec = _propagate(bone, ref_local, sec_rest)
        local[:, j] = _frame(bone, sec) @ _frame(bone_rest, sec_rest).T
        glob[:, j] = gp @ local[:, j]
        if kind == "hinge":
            # The lower joint: the hinge turn, then the (small; none where the upper joint
            # took the hinge's axis) swing onto the observed lower bone.
            hinge = axis_angle_to_matrix(sec_rest[None] * theta[:, None])
            lower_here = np.einsum("tji,tj->ti", local[:, j], lower)
            local[:, c] = rotation_between(turned, lower_here) @ hinge
            glob[:, c] = glob[:, j] @ local[:, c]
    # spine3's global is its children's frame; its local follows from spine2's.
    s3 = J["spine3"]
    local[:, s3] = np.swapaxes(glob[:, sk.PARENTS[s3]], -1, -2) @ glob[:, s3]
    ground = floor_height([joints]) if floor is None else float(floor)
    fill_leaves(joints, offsets, local, glob, fps, ground, leaves or {})
    quats = continuous(matrix_to_quat(local))
    return Rig(offsets=offsets.copy(), root=joints[:, sk.PELVIS].copy(), rotations=quats)
