"""A piggyback ride (issue 24): one person carries the other on their back. numpy only.

The carrier is a real clip (quiet standing, or a real walk played a little slower when their
words say they walk), leaning forward a little under the load, with both arms hooked back
and the hands under the rider's knees (two-bone IK). The rider is a real standing clip
re-posed as a rider: the upper body leaning onto the carrier's back, the thighs splayed
forward round the carrier's hips and the shins hanging (leg IK), the arms round the
carrier's shoulders with the hands on the upper chest (arm IK, the hand's sphere resting on
the chest's). Every frame that pose is placed in the carrier's own frame (their smoothed
facing): the rider's pelvis behind and over the carrier's, as far back as keeps the two
trunks and legs from sinking > 1.5 cm into each other (`motion/pair/body.py`'s spheres).

The rider first stands behind the carrier, then climbs on: their joints eased from standing
to riding over about a second (the legs a little after the pelvis, as a hop up), the
carrier's arms reaching back as the rider comes up. Person `actor` carries.

Shapes: joints (T, 22, 3) float64 metres, Y up, 20 fps.
"""

from __future__ import annotations

import numpy as np

from interplay.catalogue.words import Phrases
from interplay.generators.interaction import contacts as ct
from interplay.generators.interaction import moves as mv
from interplay.generators.interaction.bodies import turn_to
from interplay.generators.interaction.scene import Cast
from interplay.generators.interaction.scenes import travel
from interplay.generators.interaction.scenes.partners import lean
from interplay.motion import skeleton as sk
from interplay.motion.checks.measures import HAND_RADIUS_M
from interplay.motion.ik import ease, two_bone_ik
from interplay.motion.pair import placement as pl
from interplay.motion.pair.body import HAND_SPHERES, SPHERE_PARENT, body_spheres, surface_gaps

J = sk.JOINT_INDEX
UP = np.array([0.0, 1.0, 0.0])
XZ = np.array([1.0, 0.0, 1.0])
WALKS = Phrases(["walk*", "stroll*", "carr* * (around|across|along|home|up|down|through)",
                 "(around|across|along) the"], ignore_case=True)
RISE_M = (0.16, 0.2)        # the rider's pelvis over the carrier's
BACKS_M = np.arange(0.14, 0.42, 0.01)   # how far behind the carrier's pelvis to try
DEPTH_M = 0.015             # trunks and legs sink no deeper into each other than this
CARRIER_LEAN = (10.0, 16.0)  # degrees forward under the load
RIDER_LEAN = (12.0, 18.0)    # degrees forward onto the carrier's back
HEAD_TILT = (20.0, 30.0)     # degrees the rider's head tilts aside, past the carrier's
THIGH = np.array([0.55, -0.12, 0.8])   # the rider's thigh: out, up, forward (unit after scaling)
SHIN = np.array([0.12, -0.95, -0.05])  # the shin hangs, a little out and back
MOUNT_S = (0.9, 1.2)        # climbing on
STAND_S = (0.4, 0.7)        # standing behind first
BEHIND_M = 0.5              # where the rider stands before climbing on (pelvis to pelvis)


def _s(seconds: float) -> int:
    return int(round(seconds * sk.FPS))


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.maximum(np.linalg.norm(v, axis=-1, keepdims=True), 1e-9)


def _heading(j: np.ndarray, window: int = 15) -> np.ndarray:
    """(T,) the person's facing yaw (0 = +Z, positive towards +X), smoothed over `window` frames."""
    fwd = pl.axes(j)[0]
    k = np.ones(window) / window
    sm = np.stack([np.convolve(np.pad(fwd[:, i], window // 2, mode="edge"), k, mode="valid")
                   for i in (0, 2)], axis=1)
    return np.arctan2(sm[:, 0], sm[:, 1])


def _placed(local: np.ndarray, yaw: np.ndarray, at: np.ndarray) -> np.ndarray:
    """A pose in its own frame (pelvis at the origin, facing +Z) turned to `yaw` (T,) and
    moved to `at` (T, 3), frame by frame."""
    c, s = np.cos(yaw)[:, None], np.sin(yaw)[:, None]
    x, z = local[..., 0], local[..., 2]
    out = local.copy()
    out[..., 0] = c * x + s * z
    out[..., 2] = -s * x + c * z
    return out + at[:, None]


def rider_pose(stand: np.ndarray, lean_deg: float, tilt_deg: float = 0.0) -> np.ndarray:
    """A standing clip (facing +Z) re-posed as riding on a back, in its own frame (pelvis at
    the origin): leaning forward, the head tilted `tilt_deg` to its left (negative: right)
    so it rests beside the carrier's, thighs forward and out, shins hanging."""
    j = stand - stand[:, [sk.PELVIS]]
    j = lean(j, np.full(len(j), lean_deg))
    rel = j[:, sk.HEAD] - j[:, sk.NECK]
    c, s = np.cos(np.radians(tilt_deg)), np.sin(np.radians(tilt_deg))
    j[:, sk.HEAD, 0] = j[:, sk.NECK, 0] + c * rel[:, 0] + s * rel[:, 1]
    j[:, sk.HEAD, 1] = j[:, sk.NECK, 1] - s * rel[:, 0] + c * rel[:, 1]
    for side, out in (("left", 1.0), ("right", -1.0)):
        hip, knee0, ankle0 = J[f"{side}_hip"], J[f"{side}_knee"], J[f"{side}_ankle"]
        thigh = float(np.linalg.norm(j[0, knee0] - j[0, hip]))
        shin = float(np.linalg.norm(j[0, ankle0] - j[0, knee0]))
        knee = j[:, hip] + thigh * _unit(THIGH * np.array([out, 1.0, 1.0]))
        ankle = knee + shin * _unit(SHIN * np.array([out, 1.0, 1.0]))
        pole = knee + 0.5 * (knee - 0.5 * (j[:, hip] + ankle))
        j = two_bone_ik(j, f"{side}_leg", ankle, pole=pole)
    return j


def _trunk_depth(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """(T,) the deepest overlap (m) of two bodies' spheres, the arms (shoulder down: they
    are solved after the placement) left out."""
    arms = [J[f"{s}_{n}"] for s in ("left", "right") for n in ("shoulder", "elbow")]
    keep = ~np.isin(SPHERE_PARENT, arms)
    keep[HAND_SPHERES] = False
    sa, sb = body_spheres(a), body_spheres(b)
    gaps = surface_gaps(sa, sb)[:, keep][:, :, keep]
    return np.maximum(0.0, -gaps.min(axis=(1, 2)))


def _chest(j: np.ndarray) -> tuple[np.ndarray, float]:
    """The centre (T, 3) and radius of the chest's sphere (spine3 → neck, 0.3 along)."""
    sp = body_spheres(j)
    k = int(np.argmin(np.linalg.norm(sp.centres[0] - (0.7 * j[0, J["spine3"]] + 0.3 * j[0, sk.NECK]), axis=1)))
    return sp.centres[:, k], float(sp.radii[k])


def _carrier(c: Cast, who: int, start_walk: int) -> tuple[np.ndarray, bool]:
    """The carrier's own motion (facing +Z, pelvis at the origin on frame 0): a real walk
    from `start_walk` when their words say they walk, else quiet standing."""
    text = c.texts[who]
    if WALKS.search(text):
        w, scale, stand = travel._walker(c, who)
        j, rep = mv.locomote(w, stand, c.frames, mv.Gait(go=start_walk, scale=min(scale, 0.9)))
        c.report["walk"] = rep
        return turn_to(j, 0.0, np.zeros(2), current=0.0), True
    s = mv.standing(c.rng, c.lib.pool, c.frames)
    c.source(who, s.source, "stand")
    return s.joints, False


def piggyback(c: Cast) -> list[np.ndarray]:
    """Person `actor` gives the other a piggyback ride (see the module doc)."""
    rng, frames = c.rng, c.frames
    who, rider_i = c.script.actor, 1 - c.script.actor
    stand_for, mount = _s(rng.uniform(*STAND_S)), _s(rng.uniform(*MOUNT_S))
    up_at = stand_for + mount
    if up_at + _s(1.5) > frames:
        raise ValueError(f"{frames} frames are too few to climb on and ride")
    carrier, walks = _carrier(c, who, up_at + _s(0.3))
    t = np.arange(frames)
    loaded = ease((t - stand_for - mount // 2) / max(mount // 2, 1))
    carrier = lean(carrier, loaded * float(rng.uniform(*CARRIER_LEAN)))
    s = mv.standing(rng, c.lib.pool, frames)
    c.source(rider_i, s.source, "stand, then ride")
    tilt = float(rng.uniform(*HEAD_TILT)) * float(rng.choice([-1.0, 1.0]))
    local = rider_pose(s.joints, float(rng.uniform(*RIDER_LEAN)), tilt)
    yaw = _heading(carrier)
    fwd = np.stack([np.sin(yaw), np.zeros(frames), np.cos(yaw)], axis=1)
    rise = float(rng.uniform(*RISE_M))
    seat_of = lambda back: carrier[:, sk.PELVIS] - back * fwd + rise * UP   # noqa: E731
    back = next((float(b) for b in BACKS_M
                 if np.percentile(_trunk_depth(carrier[up_at:], _placed(local, yaw, seat_of(b))[up_at:]), 90)
                 <= DEPTH_M),
                float(BACKS_M[-1]))
    riding = _placed(local, yaw, seat_of(back))
    # The rider's hands on the carrier's upper chest, left and right of the middle.
    centre, radius = _chest(carrier)
    left = np.cross(UP, fwd)
    arm_w = ease((t - stand_for - mount // 3) / max(mount // 2, 1))
    for side, out in (("left", 1.0), ("right", -1.0)):
        goal = centre + (radius + HAND_RADIUS_M - 0.01) * _unit(fwd + 0.25 * UP) + 0.07 * out * left
        pole = riding[:, J[f"{side}_shoulder"]] + 0.45 * out * left + 0.3 * UP
        riding = ct.hand_to(riding, side, goal, np.ones(frames), pole)
    # Before and while climbing on: standing behind, eased into the ride (legs a bit later).
    behind = turn_to(s.joints, float(yaw[stand_for]), (carrier[stand_for, sk.PELVIS] - BEHIND_M * fwd[stand_for])[[0, 2]],
                     stand_for, 0.0)
    w = ease((t - stand_for) / mount)[:, None, None]
    w_legs = ease((t - stand_for - _s(0.15)) / max(mount - _s(0.15), 1))[:, None, None]
    legs = np.zeros(sk.NUM_JOINTS, bool)
    legs[[J[f"{s_}_{n}"] for s_ in ("left", "right") for n in ("knee", "ankle", "foot")]] = True
    weight = np.where(legs[None, :, None], w_legs, w)
    rider = (1.0 - weight) * behind + weight * riding
    # The carrier's hands hooked under the rider's thighs, just behind the knees (the shin
    # hangs from the knee itself), as the rider comes up.
    for side, out in (("left", 1.0), ("right", -1.0)):
        under = rider[:, J[f"{side}_hip"]] + 0.6 * (rider[:, J[f"{side}_knee"]] - rider[:, J[f"{side}_hip"]])
        goal = under - (0.06 + HAND_RADIUS_M - 0.01) * _unit(UP - 0.9 * out * left)
        pole = carrier[:, J[f"{side}_shoulder"]] + 0.6 * out * left - 0.2 * fwd - 0.3 * UP
        carrier = ct.hand_to(carrier, side, goal, arm_w, pole)
    c.report["contact"] = {"kind": "carry", "carrier": who, "rider": rider_i, "climb": [stand_for, up_at],
                           "behind_m": round(back, 3), "above_m": round(rise, 3), "walks": walks}
    return [carrier, rider] if who == 0 else [rider, carrier]
