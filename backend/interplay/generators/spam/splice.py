"""Putting model output and an input motion together so that what was not edited stays put.

Edits work in feature space (`interplay.motion.features`): the new features are taken for the
edited joints and frames and the original features elsewhere, then the body is posed by forward
kinematics on the original bone lengths. A joint's weight covers its local rotation (so
untouched joints keep their rotation relative to their parent), position, velocity and foot
contact; the root weight covers heading, ground velocity and pelvis height (the root path).

    w = joint_weights(["left_upper"], time_weights(T, a, b))      # (T, 22): the left arm
    feats = compose(original, new, w, root_w)                      # (T, 239)
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.features import FEATURE_DIM, ROT_JOINTS, SLICES, heading
from interplay.motion.rotations import yaw_matrix

RAMP = 4   # frames of cross-fade at each inner end of an edited time range (one token)


def time_weights(frames: int, start: int = 0, end: int | None = None, ramp: int = RAMP
                 ) -> np.ndarray:
    """(T,) weights of the new motion over time: 1 inside [start, end), 0 outside, with a
    linear ramp over `ramp` frames inside each end that borders kept frames."""
    end = frames if end is None else end
    w = np.zeros(frames)
    w[start:end] = 1.0
    span = end - start
    r = min(ramp, span // 2)
    if r > 0:
        up = np.arange(1, r + 1) / (r + 1)
        if start > 0:
            w[start:start + r] = up
        if end < frames:
            w[end - r:end] = up[::-1]
    return w


def edited_joints(parts: list[str]) -> np.ndarray:
    """(22,) bool: the joints an edit of `parts` may move on its own — those in no unedited
    part. Parts overlap (the torso is in both upper parts, the pelvis in both lower ones), and
    a shared joint stays with the part that is kept, so the kept parts keep all their joints."""
    out = np.ones(sk.NUM_JOINTS, dtype=bool)
    for p in sk.PART_NAMES:
        if p not in parts:
            out[sk.PART_JOINTS[p]] = False
    return out


def joint_weights(parts: list[str], time_w: np.ndarray) -> np.ndarray:
    """(T, 22): time_w for the joints `edited_joints(parts)`, 0 for the others."""
    return time_w[:, None] * edited_joints(parts)[None, :].astype(float)


def compose(original: np.ndarray, new: np.ndarray, joint_w: np.ndarray, root_w: np.ndarray
            ) -> np.ndarray:
    """Features (T, 239): per block, (1 − w)·original + w·new with the weight of the joint that
    owns the dims (root dims: root_w). 6D rotations are blended linearly; decoding
    re-orthonormalises them (Gram–Schmidt), fine for the short cross-fades used here."""
    original = np.asarray(original, dtype=np.float64)
    new = np.asarray(new, dtype=np.float64)
    if original.shape != new.shape or original.shape[1:] != (FEATURE_DIM,):
        raise ValueError(f"features must match: {original.shape} vs {new.shape}")
    t = original.shape[0]
    w = np.zeros((t, FEATURE_DIM))
    for name in ("root_angvel", "root_linvel", "root_height"):
        w[:, SLICES[name]] = root_w[:, None]
    w[:, SLICES["positions"]] = np.repeat(joint_w[:, 1:], 3, axis=1)
    w[:, SLICES["rotations"]] = np.repeat(joint_w[:, list(ROT_JOINTS)], 6, axis=1)
    w[:, SLICES["velocities"]] = np.repeat(joint_w, 3, axis=1)
    w[:, SLICES["foot_contacts"]] = joint_w[:, list(sk.FOOT_JOINTS)]
    return (1.0 - w) * original + w * new


def seam_corrected(middle: np.ndarray, left_delta: np.ndarray, right_delta: np.ndarray
                   ) -> np.ndarray:
    """A generated stretch of features (m, 239) shifted so that it meets both neighbours:
    + left_delta fading out and + right_delta fading in (each the neighbour's frame minus the
    model's own version of that frame)."""
    m = middle.shape[0]
    s = (np.arange(1, m + 1) / (m + 1))[:, None]
    return middle + (1.0 - s) * left_delta[None] + s * right_delta[None]


def yaw_between(src: np.ndarray, dst: np.ndarray) -> tuple[float, np.ndarray, np.ndarray]:
    """The rigid ground-plane move (yaw angle, pivot, XZ shift) that puts pose `src` (22, 3)
    where pose `dst` is: rotate about the vertical through src's pelvis, then shift."""
    dtheta = float(heading(dst[None])[0] - heading(src[None])[0])
    dtheta = (dtheta + np.pi) % (2 * np.pi) - np.pi
    pivot = src[sk.PELVIS] * np.array([1.0, 0.0, 1.0])
    shift = (dst[sk.PELVIS] - src[sk.PELVIS]) * np.array([1.0, 0.0, 1.0])
    return dtheta, pivot, shift


def ramp_move(joints: np.ndarray, start: int, end: int, dtheta: float, pivot: np.ndarray,
              shift: np.ndarray) -> np.ndarray:
    """Joints (T, 22, 3) with frames ≥ end moved by the full yaw/shift and frames in
    [start, end) by a linearly growing share of it: a drift correction spread over the edited
    stretch, one rigid move per frame (bone lengths are untouched)."""
    out = np.array(joints, dtype=np.float64)
    t = out.shape[0]
    share = np.zeros(t)
    n = max(end - start, 1)
    share[start:end] = np.arange(1, end - start + 1) / n
    share[end:] = 1.0
    rot = yaw_matrix(share * dtheta)                                      # (T, 3, 3)
    rel = out - pivot
    out = np.einsum("tij,tkj->tki", rot, rel) + pivot + share[:, None, None] * shift
    return out
