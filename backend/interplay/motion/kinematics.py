"""Forward/inverse kinematics on the 22-joint skeleton, facing direction, canonical frame,
and resampling. numpy only.

Shapes: joints (T, 22, 3); local rotations (T, 22, 3, 3) (each joint's rotation relative to
its parent's frame; the root's is global); offsets (22, 3) per person, child-from-parent in
the parent's rest frame, the root row holding the rest pelvis height.
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.rotations import rotation_between, yaw_matrix

UP = np.array([0.0, 1.0, 0.0])
# Joints whose rotation is fit from several children (the rest are a single bone's swing).
_MULTI_CHILD = {j: sk.children(j) for j in range(sk.NUM_JOINTS) if len(sk.children(j)) > 1}
# Frame of a multi-child joint: x across its left/right children, y towards its up child.
_FRAME_CHILDREN = {
    sk.PELVIS: (sk.JOINT_INDEX["left_hip"], sk.JOINT_INDEX["right_hip"], sk.JOINT_INDEX["spine1"]),
    sk.JOINT_INDEX["spine3"]: (sk.JOINT_INDEX["left_collar"], sk.JOINT_INDEX["right_collar"], sk.NECK),
}


def forward_kinematics(local_rot: np.ndarray, root_pos: np.ndarray, offsets: np.ndarray,
                       parents=sk.PARENTS) -> tuple[np.ndarray, np.ndarray]:
    """Joint positions (T, J, 3) and global rotations (T, J, 3, 3) for any tree whose
    joints are ordered parents-first. The root's offset is ignored (root_pos places it)."""
    t, j = local_rot.shape[:2]
    glob = np.empty_like(local_rot)
    pos = np.empty((t, j, 3))
    for i, p in enumerate(parents):
        if p < 0:
            glob[:, i] = local_rot[:, i]
            pos[:, i] = root_pos
        else:
            glob[:, i] = glob[:, p] @ local_rot[:, i]
            pos[:, i] = pos[:, p] + glob[:, p] @ offsets[i]
    return pos, glob


def _frame_from_children(vec_lr: np.ndarray, vec_up: np.ndarray) -> np.ndarray:
    """Orthonormal frames (..., 3, 3), columns x (towards left), y (up), z (forward)."""
    x = vec_lr / np.maximum(np.linalg.norm(vec_lr, axis=-1, keepdims=True), 1e-12)
    z = np.cross(x, vec_up)
    z = z / np.maximum(np.linalg.norm(z, axis=-1, keepdims=True), 1e-12)
    y = np.cross(z, x)
    return np.stack([x, y, z], axis=-1)


def _joint_frames(joints: np.ndarray, joint: int) -> np.ndarray:
    left, right, up = _FRAME_CHILDREN[joint]
    return _frame_from_children(joints[..., left, :] - joints[..., right, :],
                                joints[..., up, :] - joints[..., joint, :])


def fit_offsets(joints: np.ndarray, template: np.ndarray = sk.REST_OFFSETS) -> np.ndarray:
    """A person's rest offsets (22, 3) from their motion (T, 22, 3): median bone lengths along
    the template's directions; the children of the pelvis and spine3 keep their measured
    placement in the parent's frame, so that IK can reproduce them exactly."""
    offsets = template.copy()
    lengths = np.median(sk.bone_lengths(joints), axis=0)
    for (child, _), length in zip(sk.BONES, lengths):
        d = template[child]
        offsets[child] = d / np.linalg.norm(d) * length
    rest = sk.rest_joints(template)
    for joint, (left, right, up) in _FRAME_CHILDREN.items():
        frames = _joint_frames(joints, joint)                  # (T, 3, 3)
        rest_frame = _joint_frames(rest, joint)                # (3, 3)
        med = {c: np.median(np.einsum("tji,tj->ti", frames, joints[:, c] - joints[:, joint]), axis=0)
               for c in sk.children(joint)}
        # Medians taken per child need not form an exact frame: re-express them in theirs,
        # so the rest frame built from the fitted offsets is exactly the template's.
        fix = _frame_from_children(med[left] - med[right], med[up])
        for c, m in med.items():
            offsets[c] = rest_frame @ (fix.T @ m)
    offsets[sk.PELVIS] = [0.0, np.median(joints[:, sk.PELVIS, 1] - joints[..., 1].min(axis=1)), 0.0]
    return offsets


def _ik_plan(parents=sk.PARENTS) -> list[tuple[str, np.ndarray, np.ndarray, np.ndarray]]:
    """IK's steps, one tree level at a time (a level needs only its parents' global rotations):
    per level ("frame", joint, -, parent) for the pelvis / spine3 frames, then one batched
    ("swing", joints, their single children, parents) and ("leaf", joints, -, parents)."""
    depth: list[int] = []
    for p in parents:
        depth.append(0 if p < 0 else depth[p] + 1)
    steps, none = [], np.zeros(0, dtype=int)
    for d in range(max(depth) + 1):
        level = [j for j in range(len(parents)) if depth[j] == d]
        for j in level:
            if j in _FRAME_CHILDREN:
                steps.append(("frame", np.array([j]), none, np.array([parents[j]])))
        swing = [j for j in level if j not in _FRAME_CHILDREN and len(sk.children(j)) == 1]
        leaf = [j for j in level if not sk.children(j) and parents[j] >= 0]
        if swing:
            steps.append(("swing", np.array(swing), np.array([sk.children(j)[0] for j in swing]),
                          np.array([parents[j] for j in swing])))
        if leaf:
            steps.append(("leaf", np.array(leaf), none, np.array([parents[j] for j in leaf])))
    return steps


_IK_PLAN = _ik_plan()


def inverse_kinematics(joints: np.ndarray, offsets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Local rotations (T, 22, 3, 3) and root positions (T, 3) that reproduce joints (T, 22, 3)
    on a skeleton with these offsets (exact for bone directions; twist about a single bone is
    left at zero, as in HumanML3D). Leaf joints get the identity."""
    t = joints.shape[0]
    rest = sk.rest_joints(offsets)
    glob = np.tile(np.eye(3), (t, sk.NUM_JOINTS, 1, 1))
    local = glob.copy()
    for kind, js, cs, ps in _IK_PLAN:
        if kind == "frame":
            # Rotation taking the rest frame onto the observed frame (global).
            j, p = int(js[0]), int(ps[0])
            g = _joint_frames(joints, j) @ _joint_frames(rest, j).T
            local[:, j] = g if p < 0 else np.swapaxes(glob[:, p], -1, -2) @ g
            glob[:, j] = g
        elif kind == "swing":
            parent_glob = glob[:, ps]                                    # (T, m, 3, 3)
            target = np.einsum("tmji,tmj->tmi", parent_glob, joints[:, cs] - joints[:, js])
            local[:, js] = rotation_between(np.broadcast_to(offsets[cs], target.shape), target)
            glob[:, js] = parent_glob @ local[:, js]
        else:                                    # leaves: identity, so the parent's rotation
            glob[:, js] = glob[:, ps]
    return local, joints[:, sk.PELVIS].copy()


def fit_to_skeleton(joints: np.ndarray, offsets: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Joints re-posed by IK → FK on fixed bone lengths (so bones cannot stretch); returns
    (fitted joints, offsets)."""
    if offsets is None:
        offsets = fit_offsets(joints)
    local, root = inverse_kinematics(joints, offsets)
    fitted, _ = forward_kinematics(local, root, offsets)
    return fitted, offsets


def facing_direction(joints: np.ndarray) -> np.ndarray:
    """Unit forward vectors on the ground (..., 3) from hips and shoulders (HumanML3D)."""
    across = (joints[..., sk.RIGHT_HIP, :] - joints[..., sk.LEFT_HIP, :]
              + joints[..., sk.RIGHT_SHOULDER, :] - joints[..., sk.LEFT_SHOULDER, :])
    fwd = np.cross(UP, across)
    fwd[..., 1] = 0.0
    return fwd / np.maximum(np.linalg.norm(fwd, axis=-1, keepdims=True), 1e-12)


def facing_angle(joints: np.ndarray) -> np.ndarray:
    """Yaw (...) in radians of the facing direction, 0 when facing +Z, positive towards +X."""
    fwd = facing_direction(joints)
    return np.arctan2(fwd[..., 0], fwd[..., 2])


def continue_from(joints: np.ndarray, old_end: np.ndarray, b: int) -> np.ndarray:
    """Frames b: of `joints` (T, 22, 3) moved rigidly (a turn about Y and a shift on the
    floor) so that they continue from joints[b-1] the way they continued from `old_end`
    (22, 3), the pose frame b-1 had before frames up to b were replaced."""
    if b >= len(joints):
        return joints
    turn = float(facing_angle(joints[b - 1]) - facing_angle(old_end))
    rot = yaw_matrix(np.array(turn))
    c_old, c_new = old_end[sk.PELVIS] * [1, 0, 1], joints[b - 1, sk.PELVIS] * [1, 0, 1]
    out = joints.copy()
    out[b:] = (joints[b:] - c_old) @ rot.T + c_new
    return out


def floor_height(people: list[np.ndarray]) -> float:
    """Ground level under people (each (T, 22, 3)): a low percentile of each frame's lowest
    joint, so a single glitchy frame does not lift everyone."""
    lowest = np.concatenate([p[..., 1].min(axis=1) for p in people])
    return float(np.percentile(lowest, 2))


def canonicalize(people: list[np.ndarray]) -> tuple[list[np.ndarray], dict]:
    """One rigid transform for everyone: the floor at y=0, the first person's pelvis at the
    XZ origin and facing +Z on the first frame. Returns the moved people and the transform
    (yaw in radians, translation applied after rotation)."""
    first = people[0][0]
    yaw = -facing_angle(first)
    rot = yaw_matrix(yaw)
    rotated = [p @ rot.T for p in people]
    shift = -rotated[0][0, sk.PELVIS].copy()
    shift[1] = -floor_height(rotated)
    return [p + shift for p in rotated], {"yaw": float(yaw), "translation": shift.tolist()}


def resample(x: np.ndarray, src_fps: float, dst_fps: float = sk.FPS) -> np.ndarray:
    """Linear resampling along axis 0 from src_fps to dst_fps (positions, not rotations)."""
    n = x.shape[0]
    if n < 2 or abs(src_fps - dst_fps) < 1e-9:
        return x.copy()
    duration = (n - 1) / src_fps
    t_new = np.arange(int(np.floor(duration * dst_fps + 1e-6)) + 1) / dst_fps
    pos = t_new * src_fps
    lo = np.clip(np.floor(pos).astype(int), 0, n - 1)
    hi = np.clip(lo + 1, 0, n - 1)
    w = (pos - lo).reshape((-1,) + (1,) * (x.ndim - 1))
    return x[lo] * (1 - w) + x[hi] * w


def rest_rotations(t: int) -> np.ndarray:
    """Identity local rotations (t, 22, 3, 3)."""
    return np.tile(np.eye(3), (t, sk.NUM_JOINTS, 1, 1))


def swing_to(offsets: np.ndarray, joint: int, direction: np.ndarray) -> np.ndarray:
    """Local rotation taking a single-child joint's rest bone onto a direction (in its
    parent's frame); used by IK solvers and tests."""
    (child,) = sk.children(joint)
    return rotation_between(offsets[child], direction)
