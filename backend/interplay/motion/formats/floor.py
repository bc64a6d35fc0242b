"""The exports' floor pass: no hand, knee or foot more than TOLERANCE under the floor, of the
body each file holds — the GLB's skinned mesh (body="mesh"), the BVH's joints and end sites
(body="joints"). numpy only.

The rig keeps what it can with its leaves (`rig.solve_rig` pitches toes and hands up off the
floor); what remains — a knee on the floor (the mesh's knee is 5 cm round its joint), a sole
or heel under a standing foot, a hand whose wrist is already low — is taken out by lifting
the whole person (the root) on those frames only: the least lift that puts the lowest hand,
knee and foot vertex within LIFT_TO of the floor, widened over a few frames and smoothed so
the body does not jump (a lift never adds more than it must plus that smoothing).

    rig, lift = floor_pass(rig, floor, "mesh")   # lift (T,) metres added to the root's height
    depths(rig, floor, "joints")                  # {"hands"|"knees"|"feet": (T,) m under the floor}
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.formats.humanoid import humanoid, on_skeleton
from interplay.motion.rig import Rig, end_sites, global_rotations, rig_positions

TOLERANCE = 0.01     # m: what the issue allows under the floor
# m: the pass leaves at most this under the floor (slack for resampling and, for joints, the
# floor itself: `kinematics.floor_height` is a low percentile, so a few frames' lowest joint is
# a few millimetres under it by definition; the least lift keeps those as they are).
LIFT_TO = {"mesh": 0.004, "joints": 0.008}
WIDEN = 2            # frames either side a lift is held before it eases off
J = sk.JOINT_INDEX
REGIONS: dict[str, tuple[str, ...]] = {
    "hands": ("left_wrist", "right_wrist"),
    "knees": ("left_knee", "right_knee"),
    "feet": ("left_ankle", "right_ankle", "left_foot", "right_foot"),
}
KNEE_REACH = 0.13    # m: thigh vertices this near the knee count as the knee


@lru_cache(maxsize=1)
def _vertices() -> dict[str, np.ndarray]:
    """Indices of the template mesh's vertices in each region: those whose heaviest joint is
    the region's (a knee's: the shin, and the thigh's vertices near the knee)."""
    mesh = humanoid()
    top = mesh.joints[np.arange(len(mesh.joints)), np.argmax(mesh.weights, axis=1)]
    rest = sk.rest_joints()
    out = {}
    for region, names in REGIONS.items():
        idx = [J[n] for n in names]
        mask = np.isin(top, idx)
        if region == "knees":
            near = np.min([np.linalg.norm(mesh.positions - rest[k], axis=1) for k in idx], axis=0)
            mask |= near < KNEE_REACH
        out[region] = np.flatnonzero(mask)
    return out


def skinned_heights(rig: Rig, vertices: np.ndarray) -> np.ndarray:
    """Heights (T, V) of mesh vertices posed by the rig (linear blend skinning, as a glTF
    reader does)."""
    mesh = humanoid()
    glob, pos = global_rotations(rig), rig_positions(rig)
    rest = sk.rest_joints(rig.offsets)
    v = on_skeleton(mesh, rig.offsets).astype(np.float64)[vertices]
    joints, weights = mesh.joints[vertices].astype(int), mesh.weights[vertices].astype(np.float64)
    out = np.zeros((rig.frames, len(vertices)))
    for s in range(joints.shape[1]):
        j = joints[:, s]
        # Only the height row of each joint's rotation is needed.
        out += weights[:, s] * (np.einsum("tvj,vj->tv", glob[:, j, 1, :], v - rest[j]) + pos[:, j, 1])
    return out


def depths(rig: Rig, floor: float, body: str = "mesh") -> dict[str, np.ndarray]:
    """How far (T,) metres the lowest point of each region is under the floor (negative:
    above it): of the mesh's vertices, or of the joints and end sites (a hand: its wrist
    and the hand's end; a foot: ankle, ball and toe tip)."""
    if body == "mesh":
        return {region: floor - skinned_heights(rig, idx).min(axis=1)
                for region, idx in _vertices().items()}
    if body != "joints":
        raise ValueError(f"body must be mesh or joints, got {body!r}")
    pos, glob = rig_positions(rig), global_rotations(rig)
    tips = {j: pos[:, j, 1] + glob[:, j, 1, :] @ e for j, e in end_sites(rig.offsets).items()}
    out = {}
    for region, names in REGIONS.items():
        heights = [pos[:, J[n], 1] for n in names] + [tips[J[n]] for n in names if J[n] in tips]
        out[region] = floor - np.min(heights, axis=0)
    return out


def _lift(need: np.ndarray) -> np.ndarray:
    """A smooth lift at least `need` (T,) on every frame: held WIDEN frames either side, then
    eased by a [1, 2, 3, 2, 1] / 9 window, never below the need."""
    t = len(need)
    if not np.any(need > 0):
        return np.zeros(t)
    padded = np.pad(need, WIDEN, mode="edge")
    held = np.max(np.stack([padded[i:i + t] for i in range(2 * WIDEN + 1)]), axis=0)
    kernel = np.array([1.0, 2.0, 3.0, 2.0, 1.0]) / 9.0
    eased = np.convolve(np.pad(held, 2, mode="edge"), kernel, mode="valid")
    return np.maximum(eased, need)


def floor_pass(rig: Rig, floor: float, body: str = "mesh") -> tuple[Rig, np.ndarray]:
    """The rig lifted where a hand, knee or foot of the body ("mesh" or "joints", as
    `depths`) would be more than LIFT_TO under the floor, and the lift (T,) metres."""
    lowest = np.max(np.stack(list(depths(rig, floor, body).values())), axis=0)
    lift = _lift(np.maximum(lowest - LIFT_TO[body], 0.0))
    if not np.any(lift > 0):
        return rig, lift
    root = rig.root.copy()
    root[:, 1] += lift
    return Rig(offsets=rig.offsets, root=root, rotations=rig.rotations), lift


GOES_LOW = 0.25      # m: a clip "goes low" when a wrist or knee comes this near the floor


def goes_low(people: list[np.ndarray], floor: float) -> bool:
    """Whether any person's wrist or knee comes within GOES_LOW of the floor (acrobatics,
    kneeling, crawling, lying down: the clips a floor pass is for)."""
    low = [J[n] for n in REGIONS["hands"] + REGIONS["knees"]]
    return any(float(p[:, low, 1].min()) - floor < GOES_LOW for p in people)


def worst(rig: Rig, floor: float, body: str) -> dict[str, float]:
    """The deepest any frame's hand, knee and foot goes under the floor (m; negative: above)."""
    return {region: float(d.max()) for region, d in depths(rig, floor, body).items()}
