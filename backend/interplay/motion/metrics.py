"""Commonsense and physics metrics of a motion (one or two people), per frame and per clip.

Single person (joints (T, 22, 3), metres, Y up, floor at y = 0, 20 fps):
  bone deviation      |bone length - the clip's median length|, metres (stretching bones)
  centre of mass      skeleton.SEGMENT_MASS at segment midpoints; CODA eq. 4's quantities:
                      its distance to the pelvis (metres) and the elevation angle of the
                      pelvis→COM line above the horizontal plane (degrees; CODA uses its cosine).
                      The COM lies within a few cm of the pelvis joint, so the angle is noisy
  foot skating        horizontal speed of foot joints (ankles, toes) while planted, in the spirit
                      of HumanML3D/MDM (height threshold; skating frames are frames where a
                      planted joint moves faster than 0.5 m/s). The height threshold is taken
                      over a local floor (the joint's lowest height within ±1 s) so that
                      tilted capture floors do not count; see MetricConfig
  ground penetration  depth of the lowest joint below y = 0 (metres, 0 when above)
  floating            height of the lowest joint above y = 0 in frames with no foot joint in
                      contact (metres, 0 in frames with contact)
Two people (see body.py and interaction.py):
  intersection volume summed sphere-pair lens volume per frame, in cm³ (ARFlow's IV)
  intersection freq.  share of frames where the bodies overlap (ARFlow's IF)
  contact frames      frames where a hand is within `hand_contact` of the other's body surface
  min distance        smallest surface gap between the two sphere bodies (metres, < 0 inside)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.pair.body import (
    HAND_SPHERES,
    SPHERE_PART_MASK,
    body_spheres,
    centre_distances,
    lens_volume,
    surface_gaps,
)

M3_TO_CM3 = 1e6
# Leaf joints carry a segment that extends past them: its centre lies this fraction of the
# parent bone beyond the joint (head centre above the head joint, hand centre past the wrist).
_LEAF_EXTENSION = {sk.HEAD: 0.5, sk.LEFT_HAND: 0.25, sk.RIGHT_HAND: 0.25}


@dataclass(frozen=True)
class MetricConfig:
    # Ground contact (floating, highlights): height (metres above y = 0) of each of
    # skeleton.FOOT_JOINTS (left ankle, left toe, right ankle, right toe) below which the
    # joint touches the ground; the ankle sits higher above the sole than the ball of the foot.
    foot_heights: tuple[float, float, float, float] = (0.10, 0.05, 0.10, 0.05)
    # Planted feet (skating): within plant_margin of the lowest height that joint type reaches
    # within ±plant_window_s (so a tilted capture floor or a skeleton's own ankle height do
    # not matter), at most plant_max_height above y = 0, and not rising or sinking faster
    # than plant_vertical_speed.
    plant_margin: float = 0.03
    plant_window_s: float = 1.0
    plant_max_height: float = 0.15
    plant_vertical_speed: float = 0.1   # m/s
    skate_speed: float = 0.5       # m/s: a planted joint faster than this is skating (MDM)
    hand_contact: float = 0.03     # m: hand sphere within this of the other's body surface
    overlap_depth: float = 0.0     # m: spheres overlapping deeper than this intersect


DEFAULT = MetricConfig()


def _check(people: list[np.ndarray]) -> list[np.ndarray]:
    if not isinstance(people, (list, tuple)) or not 1 <= len(people) <= 2:
        raise ValueError("people must be a list of one or two (T, 22, 3) joint arrays")
    out = []
    for i, p in enumerate(people):
        p = np.asarray(p, dtype=np.float64)
        if p.ndim != 3 or p.shape[1:] != (sk.NUM_JOINTS, 3) or p.shape[0] < 1:
            raise ValueError(f"person {i}: expected joints of shape (T, 22, 3), got {p.shape}")
        if not np.all(np.isfinite(p)):
            raise ValueError(f"person {i}: joints contain NaN or infinite values")
        out.append(p)
    if len({p.shape[0] for p in out}) > 1:
        raise ValueError(f"people have different frame counts: {[p.shape[0] for p in out]}")
    return out


# ---- single person ---------------------------------------------------------------------

def bone_deviation(joints: np.ndarray) -> np.ndarray:
    """|length - median length over the clip| per frame and bone (T, 21), metres."""
    lengths = sk.bone_lengths(joints)
    return np.abs(lengths - np.median(lengths, axis=0))


def centre_of_mass(joints: np.ndarray) -> np.ndarray:
    """Centre of mass (T, 3): SEGMENT_MASS-weighted segment centres, each midway between a
    joint and the mean of its children (leaves: extended past the joint, see above).
    (CODA weighs every joint 1 instead; segment masses are closer to a real body.)"""
    centres = joints.copy()
    for j in range(sk.NUM_JOINTS):
        kids = sk.children(j)
        if kids:
            centres[:, j] = 0.5 * (joints[:, j] + joints[:, kids].mean(axis=1))
        elif j in _LEAF_EXTENSION:
            p = sk.PARENTS[j]
            centres[:, j] = joints[:, j] + _LEAF_EXTENSION[j] * (joints[:, j] - joints[:, p])
    return np.einsum("j,tjd->td", sk.SEGMENT_MASS, centres)


def com_to_pelvis(joints: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """CODA eq. 4: distance (T,) metres from pelvis to COM and the elevation angle (T,) in
    degrees of the pelvis→COM line above the horizontal (XZ) plane. The COM of a standing
    body sits only a few cm from the pelvis joint, so the angle is a noisy lean signal."""
    v = centre_of_mass(joints) - joints[:, sk.PELVIS]
    dist = np.linalg.norm(v, axis=-1)
    angle = np.degrees(np.arctan2(v[:, 1], np.linalg.norm(v[:, [0, 2]], axis=-1)))
    return dist, angle


def foot_contacts(joints: np.ndarray, cfg: MetricConfig = DEFAULT) -> np.ndarray:
    """(T, 4) bool: each of FOOT_JOINTS below its ground-contact height."""
    return joints[:, sk.FOOT_JOINTS, 1] < np.array(cfg.foot_heights)


def _rolling_min(x: np.ndarray, half: int) -> np.ndarray:
    """Minimum over a centred window of ±half frames along axis 0 (edges: shorter window)."""
    padded = np.pad(x, [(half, half)] + [(0, 0)] * (x.ndim - 1), mode="edge")
    return np.lib.stride_tricks.sliding_window_view(padded, 2 * half + 1, axis=0).min(axis=-1)


def planted_feet(joints: np.ndarray, fps: int = sk.FPS, cfg: MetricConfig = DEFAULT) -> np.ndarray:
    """(T, 4) bool: each of FOOT_JOINTS planted on the ground (see MetricConfig)."""
    h = joints[:, sk.FOOT_JOINTS, 1]                                    # (T, 4)
    # Local floor per joint type: both ankles share one, both toes another.
    kind = h.reshape(-1, 2, 2).min(axis=1)                              # (T, 2): ankle, toe
    floor = np.tile(_rolling_min(kind, max(1, round(cfg.plant_window_s * fps))), 2)
    vy = np.abs(np.gradient(h, axis=0)) * fps if len(h) > 1 else np.zeros_like(h)
    return ((h < floor + cfg.plant_margin) & (h < cfg.plant_max_height)
            & (vy < cfg.plant_vertical_speed))


def foot_skating(joints: np.ndarray, fps: int = sk.FPS,
                 cfg: MetricConfig = DEFAULT) -> tuple[np.ndarray, np.ndarray]:
    """Horizontal speed (T-2, 4) in m/s of each foot joint over the two frame steps around
    frames 1 … T-2 (a centred difference damps capture jitter), and whether the joint stays
    planted over those three frames."""
    feet = joints[:, sk.FOOT_JOINTS][..., [0, 2]]                       # (T, 4, 2)
    speed = np.linalg.norm(feet[2:] - feet[:-2], axis=-1) * fps / 2.0
    plant = planted_feet(joints, fps, cfg)
    return speed, plant[2:] & plant[1:-1] & plant[:-2]


def ground_penetration(joints: np.ndarray) -> np.ndarray:
    """Depth (T,) in metres of the lowest joint below the floor y = 0 (0 when above)."""
    return np.maximum(0.0, -joints[..., 1].min(axis=1))


def floating(joints: np.ndarray, cfg: MetricConfig = DEFAULT) -> np.ndarray:
    """Height (T,) of the lowest joint above y = 0 in frames with no foot joint in contact."""
    airborne = ~foot_contacts(joints, cfg).any(axis=1)
    return np.where(airborne, np.maximum(0.0, joints[..., 1].min(axis=1)), 0.0)


def key_joint_trajectory_error(pred: np.ndarray, target: np.ndarray,
                               key_joints=sk.KEY_JOINTS) -> float:
    """CODA eq. 5: (1/T) Σ_t ||m̂_k(t) - m_k(t)||₁ over the key joints' XZ coordinates
    (pelvis, hands, feet), metres summed over 5 joints × 2 axes."""
    if pred.shape != target.shape:
        raise ValueError(f"motions differ in shape: {pred.shape} and {target.shape}")
    k = list(key_joints)
    diff = pred[:, k][..., [0, 2]] - target[:, k][..., [0, 2]]
    return float(np.abs(diff).sum(axis=(1, 2)).mean())


def person_metrics(joints: np.ndarray, fps: int = sk.FPS, cfg: MetricConfig = DEFAULT) -> dict:
    """Clip-level single-person metrics (plain floats)."""
    speed, contact = foot_skating(joints, fps, cfg)
    skating = np.any(contact & (speed > cfg.skate_speed), axis=1)
    com_dist, com_angle = com_to_pelvis(joints)
    return {
        "bone_deviation": float(bone_deviation(joints).mean()),
        "foot_skating": float(speed[contact].mean()) if contact.any() else 0.0,
        "skating_ratio": float(skating.mean()) if len(skating) else 0.0,
        "ground_penetration": float(ground_penetration(joints).mean()),
        "floating": float(floating(joints, cfg).mean()),
        "com_distance": float(com_dist.mean()),
        "com_angle": float(com_angle.mean()),
    }


# ---- two people ------------------------------------------------------------------------

def pair_geometry(a: np.ndarray, b: np.ndarray, cfg: MetricConfig = DEFAULT) -> dict[str, np.ndarray]:
    """Per-frame two-person quantities from one sphere-distance computation:
    volume (T,) cm³, overlap (T,) bool, min_distance (T,) m, hand_gap (T, 2 people, 2 hands)
    m, penetration (T, 2 people, 4 parts) bool."""
    sa, sb = body_spheres(a), body_spheres(b)
    dist = centre_distances(sa, sb)                                      # (T, S, S) float32
    gaps = surface_gaps(sa, sb, dist)
    volume = lens_volume(dist, sa.radii[:, None], sb.radii[None, :]).sum(axis=(1, 2))
    hit = gaps < -cfg.overlap_depth
    hit_a, hit_b = np.any(hit, axis=2), np.any(hit, axis=1)              # (T, S) each
    penetration = np.stack([(h[:, :, None] & SPHERE_PART_MASK[None]).any(axis=1)
                            for h in (hit_a, hit_b)], axis=1)
    hand_gap = np.stack([gaps[:, HAND_SPHERES, :].min(axis=2),
                         gaps[:, :, HAND_SPHERES].min(axis=1)], axis=1)
    return {"volume": volume * M3_TO_CM3, "overlap": hit_a.any(axis=1),
            "min_distance": gaps.min(axis=(1, 2)).astype(np.float64), "hand_gap": hand_gap,
            "penetration": penetration}


def clip_metrics(people: list[np.ndarray], fps: int = sk.FPS, cfg: MetricConfig = DEFAULT) -> dict:
    """Clip-level metrics, JSON-serialisable: single-person keys averaged over people, and for
    two people intersection_volume (mean cm³ per frame), intersection_frequency (share of
    frames), contact_frames (count) and min_distance (metres, minimum over the clip)."""
    people = _check(people)
    each = [person_metrics(p, fps, cfg) for p in people]
    out = {k: float(np.mean([m[k] for m in each])) for k in each[0]}
    if len(people) == 2:
        g = pair_geometry(people[0], people[1], cfg)
        out["intersection_volume"] = float(g["volume"].mean())
        out["intersection_frequency"] = float(g["overlap"].mean())
        out["contact_frames"] = int((g["hand_gap"] <= cfg.hand_contact).any(axis=(1, 2)).sum())
        out["min_distance"] = float(g["min_distance"].min())
    return out


def frame_highlights(people: list[np.ndarray], cfg: MetricConfig = DEFAULT) -> dict:
    """Per frame: contacts [[person, joint], …] (foot joints on the ground, wrists whose hand
    touches the other person), penetration [[person, part_name], …] (parts intersecting the
    other person), min_distance [float] between the two bodies (None for one person)."""
    people = _check(people)
    t = people[0].shape[0]
    contacts: list[list[list[int]]] = [[] for _ in range(t)]
    penetration: list[list[list]] = [[] for _ in range(t)]
    for i, p in enumerate(people):
        for f, k in zip(*np.nonzero(foot_contacts(p, cfg))):
            contacts[f].append([i, int(sk.FOOT_JOINTS[k])])
    min_distance = None
    if len(people) == 2:
        g = pair_geometry(people[0], people[1], cfg)
        wrists = (sk.LEFT_HAND, sk.RIGHT_HAND)
        for f, i, h in zip(*np.nonzero(g["hand_gap"] <= cfg.hand_contact)):
            contacts[f].append([int(i), wrists[h]])
        for f, i, k in zip(*np.nonzero(g["penetration"])):
            penetration[f].append([int(i), sk.PART_NAMES[k]])
        min_distance = [float(x) for x in g["min_distance"]]
    return {"contacts": contacts, "penetration": penetration, "min_distance": min_distance}
