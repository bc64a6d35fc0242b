"""Placing two people for a composed clip (`compose.py`): the real bases of a split, a
standing person or a walker built from them, putting one in front of the other and clearing
their bodies, reach geometry, contact windows and the arm IK call. numpy only.

Shapes: joints (T, 22, 3) metres, Y up; a person is built facing +Z with the pelvis centred
(standing) or starting at the origin (walking) before placement.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.ik import reach, two_bone_ik
from interplay.motion.kinematics import facing_direction
from interplay.motion.pair.bases import (
    Base,
    base_joints,
    face_forward,
    loop_walk,
    play_back_and_forth,
    refit,
    standing_bases,
    walk_bases,
)
from interplay.motion.pair.body import SPHERE_JOINT, body_spheres, surface_gaps
from interplay.motion.rotations import yaw_matrix

UP = np.array([0.0, 1.0, 0.0])
SPINE3 = sk.JOINT_INDEX["spine3"]
# Spheres of body.py on the arms: contact arms may touch the partner, the rest may not.
ARM_SPHERES = np.isin(SPHERE_JOINT, [sk.JOINT_INDEX[f"{s}_{j}"] for s in ("left", "right")
                                     for j in ("shoulder", "elbow", "wrist")])
BODY_MARGIN = 0.01     # m between the non-arm spheres of the two people


@dataclass
class Pool:
    """The bases of one split."""
    split: str
    stand: list[Base]
    walk: list[Base]

    def can(self, kind: str) -> bool:
        return bool(self.walk) if kind == "walk_side_by_side" else bool(self.stand)


def pool_of(clips, split: str = "train") -> Pool:
    mine = [c for c in clips if c.split == split]
    return Pool(split, standing_bases(mine), walk_bases(mine))


@dataclass
class Person:
    joints: np.ndarray                 # (T, 22, 3)
    offsets: np.ndarray                # (22, 3)
    base: dict = field(default_factory=dict)


# ---- bases and placement -----------------------------------------------------------------

def standing(rng, pool: Pool, frames: int) -> Person:
    base = pool.stand[rng.integers(len(pool.stand))]
    flip = bool(rng.random() < 0.5)
    j, off = base_joints(base, flip)
    j = face_forward(refit(play_back_and_forth(j, frames, float(rng.random() * 2.0)), off))
    return Person(j, off, {"clip": base.clip.id, "start": base.start, "end": base.end,
                            "mirrored": flip, "licence": base.clip.licence})


def place(p: Person, yaw: float, x: float, z: float) -> None:
    p.joints = p.joints @ yaw_matrix(yaw).T + np.array([x, 0.0, z])


def body_gap(a: np.ndarray, b: np.ndarray) -> float:
    """Smallest surface gap (m) between the non-arm spheres of two people over the clip."""
    sa, sb = body_spheres(a), body_spheres(b)
    keep = ~ARM_SPHERES
    gaps = surface_gaps(sa, sb)[:, keep][:, :, keep]
    return float(gaps.min())


def separate(a: Person, b: Person, direction: np.ndarray) -> float:
    """Move b along `direction` (unit, horizontal) until the bodies clear by BODY_MARGIN;
    returns how far it moved."""
    moved = 0.0
    for _ in range(8):
        gap = body_gap(a.joints, b.joints)
        if gap >= BODY_MARGIN:
            break
        step = BODY_MARGIN - gap + 0.005
        b.joints = b.joints + step * direction
        moved += step
    return moved


def oppose(rng, a: Person, b: Person, distance: float, lateral: float = 0.0) -> dict:
    """Put b `distance` metres in front of a (pelvis to pelvis), facing a (±5°), shifted
    `lateral` metres along a's left; then clear their bodies (see separate)."""
    yaw = float(np.pi + np.radians(rng.uniform(-5.0, 5.0)))
    place(b, yaw, lateral, distance)
    moved = separate(a, b, np.array([0.0, 0.0, 1.0]))
    return {"distance": float(distance + moved), "lateral": float(lateral),
            "yaw_deg": float(np.degrees(yaw))}


def forward_at(j: np.ndarray, side: str, x: float, y: float, frac: float) -> float:
    """How far ahead (own frame: facing +Z, pelvis centred) a point at lateral x, height y
    must be for the `side` arm to reach it at `frac` of its full reach (mean pose)."""
    s = j[:, sk.JOINT_INDEX[f"{side}_shoulder"]].mean(axis=0)
    r = frac * float(reach(j, f"{side}_arm").mean())
    return float(s[2] + np.sqrt(max(r * r - (x - s[0]) ** 2 - (y - s[1]) ** 2, 0.01)))


# ---- frames of a person, per frame ---------------------------------------------------------

def axes(j: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Forward and left unit ground vectors (T, 3) of a person."""
    fwd = facing_direction(j)
    return fwd, np.cross(UP, fwd)


def out_of(j: np.ndarray, side: str) -> np.ndarray:
    """Unit vector (T, 3) out of the person's `side` ("left" / "right")."""
    left = axes(j)[1]
    return left if side == "left" else -left


def timing(rng, frames: int, hold: tuple[float, float], ramp: tuple[float, float],
            lead: tuple[float, float] = (0.1, 0.5)) -> tuple[int, int, int, int]:
    """Contact window [c0, c1) with ease-in/out ramps (frames), fitted inside the clip."""
    fps = sk.FPS
    r_in, r_out = (max(2, int(round(rng.uniform(*ramp) * fps))) for _ in range(2))
    c0 = r_in + int(round(rng.uniform(*lead) * fps))
    c1 = min(c0 + max(1, int(round(rng.uniform(*hold) * fps))), frames - r_out - 1)
    if c1 <= c0:
        raise ValueError(f"{frames} frames are too few for a contact window")
    return c0, c1, r_in, r_out


def contact(c0: int, c1: int, r_in: int, r_out: int, hands: list) -> dict:
    """Meta of a contact: window [start, end) at full IK weight, ramps (frames), and the
    [person, wrist] pairs that touch the other person in it."""
    return {"start": int(c0), "end": int(c1), "ramp_in": int(r_in), "ramp_out": int(r_out),
            "hands": hands}


def arm_ik(p: Person, side: str, target: np.ndarray, w: np.ndarray, pole: np.ndarray) -> None:
    p.joints = two_bone_ik(p.joints, f"{side}_arm", target, pole=pole, weight=w)


def pole(j: np.ndarray, side: str, out: float, down: float, back: float) -> np.ndarray:
    """An elbow hint: the shoulder moved out to the side, down and back (metres)."""
    fwd = axes(j)[0]
    return (j[:, sk.JOINT_INDEX[f"{side}_shoulder"]] + out * out_of(j, side) - down * UP
            - back * fwd)


def walker(rng, base: Base, frames: int) -> Person:
    flip = bool(rng.random() < 0.5)
    j, off = base_joints(base, flip)
    j = refit(loop_walk(j, frames), off)
    return Person(j, off, {"clip": base.clip.id, "start": base.start, "end": base.end,
                            "mirrored": flip, "licence": base.clip.licence})


def walk_speed(j: np.ndarray) -> float:
    return float(np.linalg.norm((j[-1, sk.PELVIS] - j[0, sk.PELVIS])[[0, 2]]) / (len(j) - 1) * sk.FPS)
