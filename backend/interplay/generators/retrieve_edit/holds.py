"""Held whole-body poses laid over a captured stand or squat (issue 14 item 5: "a held pose
is held"), for what the words ask and no capture holds for long:

- **one leg** ("stand on one leg", "balance on your left foot"): the free leg's knee lifted
  forward and its foot held 25–30 cm off the floor by two-bone IK on the performer's bones,
  eased in and out; the stance leg, pelvis and arms as captured.
- **a squat held** ("hold a squat", "stay down in a low squat"): a captured squat played to
  its lowest pose, which is then held, gently eased, to the segment's end.
- **still** ("stand perfectly still", "don't move", "freeze"): the captured stand slowed to
  its sway: every joint low-passed over 2 s, so the fidgets of the hands go and the body
  still breathes and shifts its weight.

Shapes: joints (T, 22, 3) metres, Y up, 20 fps.

    hold = hold_of(seg)                      # "one_leg:right" | "squat" | "still" | None
    joints = apply_hold(joints, hold, seg.start, seg.end)
"""

from __future__ import annotations

import numpy as np

from interplay.generators.retrieval.intent import hold_of as intent_hold
from interplay.generators.retrieve_edit.arm_poses import weights
from interplay.motion import skeleton as sk
from interplay.motion.bodyframe import body_frame
from interplay.motion.ik import two_bone_ik
from interplay.planner.schema import Segment

J = sk.JOINT_INDEX
THIGH_DEG = 55.0       # the lifted thigh's angle from hanging
STILL_S = 2.0          # the low-pass window of a still stand
DOWN_RATIO = 0.75      # a squat is down under 75 % of standing pelvis height (the benchmark's)


def hold_of(seg: Segment) -> str | None:
    """The held pose a one-person segment's words ask for (`intent.hold_of`), or None."""
    if len(seg.persons) != 1:
        return None
    return intent_hold(f"{seg.prompt} {seg.base or ''}")


def query_of(hold: str) -> str:
    """What the captures for a held pose are looked up by."""
    return "a person squats down" if hold == "squat" else "a person stands still"


def reason(hold: str, seg: Segment) -> str:
    span = f"frames {seg.start}–{seg.end}"
    if hold.startswith("one_leg"):
        return f"{hold.split(':')[1]} leg lifted and held by IK over {span} (standing on the other)"
    if hold == "squat":
        return f"a captured squat held at its lowest pose to the end of {span}"
    return f"the captured stand low-passed over {STILL_S:g} s in {span} (standing still)"


def lift_leg(joints: np.ndarray, side: str, start: int, end: int) -> np.ndarray:
    """The `side` leg's knee lifted forward and held over [start, end), eased at the borders."""
    out = np.asarray(joints, dtype=np.float64).copy()
    w = weights(len(out), start, end)
    on = w > 0
    if not on.any():
        return out
    b = body_frame(out, sk.FPS)
    up = np.array([0.0, 1.0, 0.0])
    hip, knee, ankle = (J[f"{side}_{p}"] for p in ("hip", "knee", "ankle"))
    thigh = float(np.median(np.linalg.norm(out[:, knee] - out[:, hip], axis=1)))
    shin = float(np.median(np.linalg.norm(out[:, ankle] - out[:, knee], axis=1)))
    theta = np.radians(THIGH_DEG)
    fwd = b.forward[on]
    k = out[on, hip] + thigh * (np.cos(theta) * -up + np.sin(theta) * fwd)
    target = k - shin * (0.96 * up + 0.25 * fwd)            # the shin hangs, toes a little back
    out[on] = two_bone_ik(out[on], f"{side}_leg", target, pole=out[on, hip] + fwd, weight=w[on])
    return out


def hold_squat(joints: np.ndarray, start: int, end: int) -> np.ndarray:
    """From the bottom of the segment's first squat on (the lowest pelvis within 1 s of first
    going under 75 % of standing height over the feet), that pose held to `end` (eased in)."""
    out = np.asarray(joints, dtype=np.float64).copy()
    if end - start < 3:
        return out
    feet = [J[f"{s}_{p}"] for s in ("left", "right") for p in ("ankle", "foot")]
    # over the feet: stitched captures sit at their own floor heights until the floor pass
    pelvis = out[start:end, sk.PELVIS, 1] - out[start:end][:, feet, 1].min(axis=1)
    ratio = pelvis / max(float(np.percentile(pelvis, 95)), 1e-6)
    down = np.flatnonzero(ratio < DOWN_RATIO)
    if not len(down):
        return out
    first = int(down[0])
    low = start + first + int(np.argmin(ratio[first:first + sk.FPS]))   # that squat's bottom
    w = weights(len(out), low, end, ease_out=False)
    on = np.arange(len(out)) >= low
    on &= np.arange(len(out)) < end
    out[on] = out[on] * (1 - w[on, None, None]) + out[low][None] * w[on, None, None]
    return out


def calm(joints: np.ndarray, start: int, end: int) -> np.ndarray:
    """Every joint low-passed over `STILL_S` inside [start, end) (edge frames padded), eased."""
    out = np.asarray(joints, dtype=np.float64).copy()
    n = max(1, int(round(STILL_S * sk.FPS)))
    seg = out[start:end]
    if len(seg) < 3:
        return out
    pad = np.concatenate([np.repeat(seg[:1], n, 0), seg, np.repeat(seg[-1:], n, 0)])
    kernel = np.ones(n) / n
    smooth = np.apply_along_axis(lambda x: np.convolve(x, kernel, mode="same"), 0, pad)[n:n + len(seg)]
    w = weights(len(out), start, end)[start:end, None, None]
    out[start:end] = seg * (1 - w) + smooth * w
    return out


def apply_hold(joints: np.ndarray, hold: str | None, start: int, end: int) -> np.ndarray:
    if hold is None:
        return np.asarray(joints, dtype=np.float64)
    if hold.startswith("one_leg"):
        return lift_leg(calm(joints, start, end), hold.split(":")[1], start, end)
    if hold == "squat":
        return hold_squat(joints, start, end)
    return calm(joints, start, end)
