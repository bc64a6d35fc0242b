"""Two-person geometry from CODA (sections 3.1, eq. 6 and 7): the joint distance map and its
Gaussian weights, the body-part chains with their axis-aligned bounding boxes and minimum
bone-to-bone distances, and hand/body contact against the other person's sphere body.

Shapes: joints (T, 22, 3) per person, metres, Y up. Parts follow skeleton.PART_NAMES (CoMA's
four overlapping parts); a part's chain is the bones whose two ends both lie in the part
(left_upper: spine1→spine2→spine3→neck→head and spine3→collar→shoulder→elbow→wrist, 8
bones; left_lower: pelvis→hip→knee→ankle→foot, 4 bones).
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.pair.body import HAND_SPHERES, Spheres, surface_gaps

TAU = 0.5          # CODA's temperature for the Gaussian distance weights (metres)
EPS = 1e-7         # CODA's ε in the denominators of eq. 6

_CHILD = np.array([c for c, _ in sk.BONES])
_PARENT = np.array([p for _, p in sk.BONES])
# (4, 21) bool: bone b belongs to part p's chain.
PART_BONES = np.array([[c in sk.PART_JOINTS[p] and q in sk.PART_JOINTS[p]
                        for c, q in sk.BONES] for p in sk.PART_NAMES])


def joint_distance_map(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distances (T, 22, 22) from every joint of a (rows) to every joint of b (columns)."""
    return np.linalg.norm(a[:, :, None, :] - b[:, None, :, :], axis=-1)


def gaussian_weights(dist: np.ndarray, tau: float = TAU) -> np.ndarray:
    """CODA eq. 6 weights w = exp(-D² / 2τ²): near 1 for touching joints, ~0 beyond ~2τ."""
    return np.exp(-np.square(dist) / (2.0 * tau * tau))


def gdm_error(pred: tuple[np.ndarray, np.ndarray], target: tuple[np.ndarray, np.ndarray],
              tau: float = TAU) -> float:
    """CODA eq. 6 between a predicted pair and a target pair (each (a, b) joints): the
    |D_pred - D_gt| error weighted by the predicted weights, plus the predicted distances
    weighted by the target's weights (small when the target's close joints are close),
    averaged over frames. Metres."""
    d_pred, d_gt = joint_distance_map(*pred), joint_distance_map(*target)
    w_pred, w_gt = gaussian_weights(d_pred, tau), gaussian_weights(d_gt, tau)
    first = (w_pred * np.abs(d_pred - d_gt)).sum(axis=(1, 2)) / (w_pred.sum(axis=(1, 2)) + EPS)
    second = (w_gt * d_pred).sum(axis=(1, 2)) / (w_gt.sum(axis=(1, 2)) + EPS)
    return float(np.mean(first + second))


def part_boxes(joints: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Axis-aligned boxes of each part's joints: (lo, hi), each (T, 4, 3)."""
    lo = np.stack([joints[:, sk.PART_JOINTS[p]].min(axis=1) for p in sk.PART_NAMES], axis=1)
    hi = np.stack([joints[:, sk.PART_JOINTS[p]].max(axis=1) for p in sk.PART_NAMES], axis=1)
    return lo, hi


def part_box_overlap(a: np.ndarray, b: np.ndarray, margin: float = 0.0) -> np.ndarray:
    """(T, 4, 4) bool: the AABB of a's part i meets the AABB of b's part j (boxes grown by
    `margin` metres, e.g. a limb's thickness, since the chains are bone lines)."""
    lo_a, hi_a = part_boxes(a)
    lo_b, hi_b = part_boxes(b)
    return np.all((lo_a[:, :, None] - margin <= hi_b[:, None] + margin)
                  & (lo_b[:, None] - margin <= hi_a[:, :, None] + margin), axis=-1)


def segment_distances(p1: np.ndarray, q1: np.ndarray, p2: np.ndarray, q2: np.ndarray) -> np.ndarray:
    """Shortest distances (...) between segments p1–q1 and p2–q2 (each (..., 3), broadcast),
    by the clamped closest-point parameters of Ericson, Real-Time Collision Detection §5.1.9."""
    d1, d2, r = q1 - p1, q2 - p2, p1 - p2
    a = np.maximum(np.einsum("...i,...i->...", d1, d1), 1e-12)
    e = np.maximum(np.einsum("...i,...i->...", d2, d2), 1e-12)
    b = np.einsum("...i,...i->...", d1, d2)
    c = np.einsum("...i,...i->...", d1, r)
    f = np.einsum("...i,...i->...", d2, r)
    denom = a * e - b * b
    s = np.where(denom > 1e-12, np.clip((b * f - c * e) / np.maximum(denom, 1e-12), 0, 1), 0.0)
    t = (b * s + f) / e
    # Clamp t to the second segment and recompute s for the clamped end.
    s = np.where(t < 0, np.clip(-c / a, 0, 1), np.where(t > 1, np.clip((b - c) / a, 0, 1), s))
    t = np.clip(t, 0, 1)
    gap = (p1 + s[..., None] * d1) - (p2 + t[..., None] * d2)
    return np.linalg.norm(gap, axis=-1)


def bone_distances(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distances (T, 21, 21) between every bone of a and every bone of b."""
    return segment_distances(a[:, _PARENT, None], a[:, _CHILD, None],
                             b[:, None, _PARENT], b[:, None, _CHILD])


def part_min_distance(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """CODA's minimum bone-to-bone distance (T, 4, 4) between a's part chain i and b's part
    chain j, metres (bone lines: 0 means the skeletons' bones cross)."""
    d = bone_distances(a, b)                                             # (T, 21, 21)
    out = np.empty((a.shape[0], 4, 4))
    for i in range(4):
        rows = d[:, PART_BONES[i]]
        for j in range(4):
            out[:, i, j] = rows[:, :, PART_BONES[j]].min(axis=(1, 2))
    return out


def penetration_penalty(d_pred: np.ndarray, d_gt: np.ndarray, overlap: np.ndarray) -> float:
    """CODA eq. 7 for chain distances and AABB overlap flags of matching shapes (e.g. (T, 4, 4)):
    mean over chain pairs of 1[overlap] (max(0, 0.9 d_gt - d_pred) + (d_pred - d_gt)²)."""
    term = np.maximum(0.0, 0.9 * d_gt - d_pred) + np.square(d_pred - d_gt)
    return float(np.mean(np.where(overlap, term, 0.0)))


def hand_gaps(hands_of: Spheres, other: Spheres) -> np.ndarray:
    """(T, 2) gap in metres from each hand sphere of one person (left, right) to the nearest
    sphere surface of the other person; negative when the hand sinks into them."""
    hands = Spheres(hands_of.centres[:, HAND_SPHERES], hands_of.radii[HAND_SPHERES],
                    hands_of.part[HAND_SPHERES], hands_of.joint[HAND_SPHERES])
    return surface_gaps(hands, other).min(axis=2)
