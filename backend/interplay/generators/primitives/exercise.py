"""Exercise cycles, exactly N each, on the base they need:

- push-ups on a prone base: the body turned as a plank about the toes (they stay on the
  floor) so the shoulders rise PUSH_RISE_M and come back down, the hands planted on the floor
  beside the shoulders and the arms bending and straightening by IK;
- sit-ups on a supine base: the knees bent up (feet flat), the trunk curled about the pelvis
  from lying to SITUP_DEG and back;
- jumping jacks on a standing base: the arms swung out and up over the head while the feet
  step out, and back;
- arm circles on a standing base: both arms held out to the side, the hands circling.

Shapes: joints (T, 22, 3) metres, Y up, 20 fps.
"""

from __future__ import annotations

import numpy as np

from interplay.generators.primitives.arms import hand_to
from interplay.generators.primitives.body import axes, trunk_axes, turn, unit, upper_body
from interplay.generators.primitives.timing import bumps, envelope, phase
from interplay.motion import skeleton as sk
from interplay.motion.ik import reach, two_bone_ik

J = sk.JOINT_INDEX
SIDES = ("left", "right")
UP = np.array([0.0, 1.0, 0.0])
PUSH_RISE_M = 0.30      # the shoulders' rise at the top of a push-up
SITUP_DEG = 70.0        # the trunk's curl at the top of a sit-up
JACK_FEET_M = 0.22      # each foot's step out in a jumping jack …
JACK_HOP_M = 0.12       # … on a hop: the body lifted while the feet go out and while they come in
CIRCLE_M = 0.15         # the radius of an arm circle


def _plank_angle(j0: np.ndarray, pivot: np.ndarray, axis: np.ndarray, rise: float) -> float:
    """The signed angle about `axis` through `pivot` that lifts the shoulders by `rise`."""
    sh = 0.5 * (j0[sk.LEFT_SHOULDER] + j0[sk.RIGHT_SHOULDER])
    best, best_err = 0.0, np.inf
    for a in np.radians(np.linspace(-40, 40, 321)):
        y = turn(j0[None], [sk.LEFT_SHOULDER, sk.RIGHT_SHOULDER], pivot[None], axis[None],
                 np.array([a]))[0, [sk.LEFT_SHOULDER, sk.RIGHT_SHOULDER], 1].mean()
        err = abs(y - (sh[1] + rise))
        if err < best_err:
            best, best_err = a, err
    return float(best)


def push_ups(base: np.ndarray, count: int) -> np.ndarray:
    """The prone base with `count` push-ups (see the module's note)."""
    j = np.asarray(base, dtype=np.float64)
    t = len(j)
    up_w = bumps(t, count, hold=0.1)
    env = envelope(t)
    toes = 0.5 * (j[:, sk.LEFT_FOOT] + j[:, sk.RIGHT_FOOT])
    left = unit(j[:, sk.LEFT_SHOULDER] - j[:, sk.RIGHT_SHOULDER] + j[:, sk.LEFT_HIP] - j[:, sk.RIGHT_HIP])
    left[:, 1] = 0.0
    left = unit(left)
    angle = _plank_angle(j[0], toes[0], left[0], PUSH_RISE_M)
    top = turn(j[:1], list(range(sk.NUM_JOINTS)), toes[:1], left[:1], np.array([angle]))[0]
    out = turn(j, list(range(sk.NUM_JOINTS)), toes, left, angle * up_w)
    head_dir = unit(j[:, sk.NECK] - j[:, sk.PELVIS])
    for s, sign in (("left", 1.0), ("right", -1.0)):
        sh = top[J[f"{s}_shoulder"]]
        plant = np.array([sh[0], 0.0, sh[2]]) + sign * 0.10 * left[0] - 0.02 * head_dir[0]
        plant[1] = 0.035
        wrist = np.broadcast_to(plant, (t, 3))
        pole = out[:, J[f"{s}_shoulder"]] + sign * 0.25 * left - 0.15 * head_dir + 0.15 * UP
        out = two_bone_ik(out, f"{s}_arm", wrist, pole=pole, weight=env)
    return out


def sit_ups(base: np.ndarray, count: int) -> np.ndarray:
    """The supine base with `count` sit-ups (see the module's note)."""
    j = np.asarray(base, dtype=np.float64).copy()
    t = len(j)
    env = envelope(t)
    curl = bumps(t, count, hold=0.1)
    left, body_up, chest = trunk_axes(j)
    flat_up = unit(body_up * np.array([1.0, 0.0, 1.0]))       # towards the head, on the floor
    for s in SIDES:                                           # knees up, feet flat
        ankle = j[:, J[f"{s}_ankle"]]
        hip = j[:, J[f"{s}_hip"]]
        toward = unit((hip - ankle) * np.array([1.0, 0.0, 1.0]))
        goal = ankle + 0.38 * toward
        j = two_bone_ik(j, f"{s}_leg", goal, pole=j[:, J[f"{s}_knee"]] + 0.5 * UP, weight=env,
                        carry="keep")
    axis = np.cross(flat_up, UP)                               # turns the head end upwards
    out = turn(j, upper_body(), j[:, sk.PELVIS], axis, np.radians(SITUP_DEG) * curl)
    return out


def jumping_jacks(base: np.ndarray, count: int) -> np.ndarray:
    """The standing base with `count` jumping-jack cycles: hands from the sides to over the
    head and back, the feet jumping out and back in time (two hops a cycle, the body lifted
    JACK_HOP_M at the middle of each move of the feet)."""
    j = np.asarray(base, dtype=np.float64)
    t = len(j)
    env = envelope(t)
    open_ = bumps(t, count, hold=0.1)
    left, up, fwd = axes(j)
    out = j.copy()
    for s, sign in (("left", 1.0), ("right", -1.0)):          # the feet step out
        ankle = j[:, J[f"{s}_ankle"]]
        goal = ankle + (sign * JACK_FEET_M * open_)[:, None] * left
        out = two_bone_ik(out, f"{s}_leg", goal, pole=out[:, J[f"{s}_knee"]] + fwd, carry="keep")
    for s, sign in (("left", 1.0), ("right", -1.0)):          # the arms swing up
        sh = out[:, J[f"{s}_shoulder"]]
        length = 0.97 * float(np.median(reach(out, f"{s}_arm")))
        a = np.radians(25.0 + 150.0 * open_)                  # from hanging out to overhead
        d = np.cos(a)[:, None] * -up + np.sin(a)[:, None] * sign * left
        goal = sh + length * unit(d + 0.05 * fwd)
        out = hand_to(out, s, goal + 0.2 * (goal - sh), sh - 0.3 * fwd + 0.0 * up, env)
    cycle, ph = phase(t, count)
    # each half-cycle: on the floor, then a flight over its middle 60 % (a falling arc), then
    # the floor again, so the hops stay apart
    u = np.clip(((2.0 * ph) % 1.0 - 0.2) / 0.6, 0.0, 1.0)
    lift = JACK_HOP_M * np.where(cycle >= 0, 4.0 * u * (1.0 - u), 0.0)
    return out + lift[:, None, None] * up[:, None, :]


def arm_circles(base: np.ndarray, count: int, side: str = "both") -> np.ndarray:
    """The standing base with both arms (or one) held out to the side and the hands drawing
    `count` circles (forward over the top)."""
    j = np.asarray(base, dtype=np.float64)
    t = len(j)
    env = envelope(t)
    cycle, ph = phase(t, count)
    turns = np.where(cycle >= 0, cycle + ph, np.where(np.arange(t) < t // 2, 0.0, count))
    left, up, fwd = axes(j)
    out = j.copy()
    for s, sign in (("left", 1.0), ("right", -1.0)):
        if side not in ("both", s):
            continue
        sh = out[:, J[f"{s}_shoulder"]]
        length = 0.9 * float(np.median(reach(out, f"{s}_arm")))
        centre = sh + length * sign * left
        ang = 2 * np.pi * turns
        goal = centre + CIRCLE_M * (np.sin(ang)[:, None] * up + np.cos(ang)[:, None] * -fwd) + CIRCLE_M * fwd
        out = two_bone_ik(out, f"{s}_arm", goal, pole=sh - 0.3 * up - 0.2 * fwd, weight=env)
    return out
