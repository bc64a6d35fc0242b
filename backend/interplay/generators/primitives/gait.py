"""Gaits the captures lack, made from a captured walk (`postures.posture("walk")`):

- asymmetric (a limp, one leg favoured): the walk re-timed so the favoured leg's single
  stance is played LIMP_FAST times faster and the good leg's LIMP_SLOW times slower (the
  person hurries off the sore leg), the trunk leaning over the sore leg while it carries; the
  total time is kept, the frames are the captured ones (re-posed on the same bones);
- perturbed: a stumble (the walk hesitates at the trip, the trunk pitches forward and the arms
  fly out, then recovers) or a sway (the trunk rolls side to side N times over the hips).

Shapes: joints (T, 22, 3) metres, Y up, 20 fps.
"""

from __future__ import annotations

import numpy as np

from interplay.generators.primitives.arms import hand_to
from interplay.generators.primitives.body import axes, turn, upper_body
from interplay.generators.primitives.timing import envelope, phase
from interplay.motion import skeleton as sk
from interplay.motion.bodyframe import body_frame
from interplay.motion.ik import ease
from interplay.motion.kinematics import fit_offsets, forward_kinematics, inverse_kinematics
from interplay.motion.signals import smooth

J = sk.JOINT_INDEX
SIDES = ("left", "right")
DOWN_M = 0.03          # a foot this close to its ground level carries weight
LIMP_FAST = 2.2        # the sore leg's single stance played this much faster …
LIMP_SLOW = 0.6        # … the good leg's this much (slower)
LIMP_LEAN_DEG = 7.0    # the trunk's lean over the sore leg while it carries
STUMBLE_S = 1.6        # a stumble's length: trip, pitch forward, recover
STUMBLE_DEG = 28.0
SWAY_DEG = 14.0


def stance(joints: np.ndarray) -> dict[str, np.ndarray]:
    """(T,) bool per side: that foot on the floor."""
    b = body_frame(np.asarray(joints, dtype=np.float64), sk.FPS)
    return {s: b.foot_height(s) < DOWN_M for s in SIDES}


def retime(joints: np.ndarray, rate: np.ndarray) -> np.ndarray:
    """The motion played at `rate` (T,) (source frames per output frame, relative), resampled
    to the same T frames (the total time is kept) and re-posed on its own bones."""
    j = np.asarray(joints, dtype=np.float64)
    t = len(j)
    out_time = np.concatenate([[0.0], np.cumsum(1.0 / np.maximum(rate[:-1], 1e-3))])
    out_time *= (t - 1) / out_time[-1]
    src = np.interp(np.arange(t), out_time, np.arange(t))
    lo = np.clip(np.floor(src).astype(int), 0, t - 2)
    w = (src - lo)[:, None, None]
    mixed = (1 - w) * j[lo] + w * j[lo + 1]
    off = fit_offsets(j)
    local, root = inverse_kinematics(mixed, off)
    return forward_kinematics(local, root, off)[0]


def gait_asymmetric(base: np.ndarray, side: str = "right", severity: float = 1.0) -> np.ndarray:
    """A walk with the `side` leg favoured (a limp): see the module's note."""
    if side not in SIDES:
        raise ValueError(f"side must be left or right, got {side!r}")
    j = np.asarray(base, dtype=np.float64)
    down = stance(j)
    good = "left" if side == "right" else "right"
    sore_only = down[side] & ~down[good]
    good_only = down[good] & ~down[side]
    rate = np.ones(len(j))
    rate[sore_only] = 1.0 + (LIMP_FAST - 1.0) * severity
    rate[good_only] = 1.0 - (1.0 - LIMP_SLOW) * severity
    rate = smooth(rate, 3)
    out = retime(j, rate)
    carry = smooth((stance(out)[side] & ~stance(out)[good]).astype(float), 5)
    fwd = axes(out)[2]
    sign = 1.0 if side == "left" else -1.0          # roll towards the sore side
    lean = sign * np.radians(LIMP_LEAN_DEG) * severity * carry * envelope(len(out))
    return turn(out, upper_body(), out[:, sk.PELVIS], fwd, -lean)


def gait_perturbed(base: np.ndarray, kind: str = "stumble", count: int = 3, at: float = 0.4
                   ) -> np.ndarray:
    """A walk that stumbles once at `at` of its length, or sways `count` times."""
    j = np.asarray(base, dtype=np.float64)
    t = len(j)
    left, up, fwd = axes(j)
    if kind == "sway":
        cycle, ph = phase(t, count)
        roll = np.where(cycle >= 0, np.sin(2 * np.pi * ph), 0.0) * np.radians(SWAY_DEG)
        return turn(j, upper_body(), j[:, sk.PELVIS], fwd, roll)
    if kind != "stumble":
        raise ValueError(f"kind must be stumble or sway, got {kind!r}")
    n = min(int(STUMBLE_S * sk.FPS), t - 2)
    s = int(np.clip(at * t, 1, t - n - 1))
    x = (np.arange(t) - s) / n                        # 0 … 1 over the stumble
    inside = (x >= 0) & (x <= 1)
    # hesitate at the trip (the caught foot), then hurry through the recovery step
    rate = np.where(inside, 1.0 - 0.6 * np.sin(np.pi * np.clip(x / 0.4, 0, 1)) * (x < 0.4)
                    + 0.5 * np.sin(np.pi * np.clip((x - 0.4) / 0.6, 0, 1)) * (x >= 0.4), 1.0)
    out = retime(j, rate)
    pitch = np.where(inside, np.minimum(ease(x / 0.3), ease((1 - x) / 0.55)), 0.0)
    out = turn(out, upper_body(), out[:, sk.PELVIS], left, np.radians(STUMBLE_DEG) * pitch)
    left, up, fwd = axes(out)
    for side, sign in (("left", 1.0), ("right", -1.0)):
        sh = out[:, J[f"{side}_shoulder"]]
        goal = sh + 0.35 * fwd + 0.25 * sign * left - 0.05 * up
        out = hand_to(out, side, goal, sh + 0.3 * sign * left - 0.2 * up, 0.9 * pitch)
    return out
