"""Leg primitives on a standing base, exactly N each: knee lifts (alternating or one side,
the knee above hip height at each), squats (the pelvis lowered with the feet planted) and
lunges (one leg steps forward, the pelvis drops until the back knee nears the floor, then the
front foot steps back). The pelvis and trunk move rigidly; the legs follow by two-bone IK on
the performer's bones, the standing feet kept where the base has them (`carry="keep"`).

Shapes: joints (T, 22, 3) metres, Y up, 20 fps.
"""

from __future__ import annotations

import numpy as np

from interplay.generators.primitives.body import axes, turn, upper_body
from interplay.generators.primitives.timing import bumps, phase
from interplay.motion import skeleton as sk
from interplay.motion.ik import ease, two_bone_ik

J = sk.JOINT_INDEX
SIDES = ("left", "right")
LIFT_DEG = 105.0        # the thigh's angle from hanging at the top of a knee lift (90: level)
SQUAT_DEPTH = 0.42      # a squat lowers the pelvis by this fraction of its standing height
SQUAT_LEAN_DEG = 25.0   # … leaning the trunk forward to balance
LUNGE_STEP_M = 0.70     # the front foot's step
LUNGE_DROP_M = 0.40     # the pelvis's drop at the bottom of a lunge


def _bone(j: np.ndarray, a: int, b: int) -> float:
    return float(np.median(np.linalg.norm(j[:, a] - j[:, b], axis=1)))


def _sides(count: int, side: str) -> list[str]:
    if side in SIDES:
        return [side] * count
    if side not in ("alternate", "both"):
        raise ValueError(f"side must be left, right or alternate, got {side!r}")
    return [SIDES[i % 2] for i in range(count)]


def knee_lifts(base: np.ndarray, count: int, side: str = "alternate") -> np.ndarray:
    """The base with `count` knee lifts (alternating sides from the left, or all one side)."""
    j = np.asarray(base, dtype=np.float64).copy()
    t = len(j)
    cycle, _ = phase(t, count)
    lift = bumps(t, count, hold=0.2)
    left, up, fwd = axes(j)
    theta = np.radians(LIFT_DEG)
    for s in SIDES:
        w = np.where(np.isin(cycle, [i for i, x in enumerate(_sides(count, side)) if x == s]), lift, 0.0)
        on = w > 0
        if not on.any():
            continue
        hip, knee, ankle = (J[f"{s}_{p}"] for p in ("hip", "knee", "ankle"))
        thigh, shin = _bone(j, knee, hip), _bone(j, ankle, knee)
        k = j[on, hip] + thigh * (np.cos(theta) * -up[on] + np.sin(theta) * fwd[on])
        target = k - shin * (0.97 * up[on] + 0.2 * fwd[on])
        # the ankle eased towards its target, the knee always bending forward (a blended bend
        # side would follow the straight standing leg's, which may point backwards)
        goal = j[on, ankle] + w[on, None] * (target - j[on, ankle])
        j[on] = two_bone_ik(j[on], f"{s}_leg", goal, pole=j[on, hip] + fwd[on])
    return j


def lower(j: np.ndarray, drop: np.ndarray, shift: np.ndarray, lean: np.ndarray,
           ankles: dict[str, np.ndarray], poles: dict[str, np.ndarray]) -> np.ndarray:
    """The whole body moved by (−drop up + shift), the trunk leant forward by `lean` radians
    about the pelvis, and each leg's ankle put back on `ankles[side]` by IK."""
    out = j.copy()
    out += (shift - drop[:, None] * np.array([0.0, 1.0, 0.0]))[:, None]
    left = out[:, sk.LEFT_HIP] - out[:, sk.RIGHT_HIP]
    out = turn(out, upper_body(), out[:, sk.PELVIS], left, lean)
    for s in SIDES:
        out = two_bone_ik(out, f"{s}_leg", ankles[s], pole=poles[s], carry="keep")
    return out


def squats(base: np.ndarray, count: int) -> np.ndarray:
    """The base with `count` squats: pelvis down by SQUAT_DEPTH of its height and back up,
    hips back, trunk leant forward, knees forward over the planted feet."""
    j = np.asarray(base, dtype=np.float64)
    t = len(j)
    d = bumps(t, count, hold=0.1)
    left, up, fwd = axes(j)
    drop = SQUAT_DEPTH * j[:, sk.PELVIS, 1] * d
    shift = -0.12 * d[:, None] * fwd
    ankles = {s: j[:, J[f"{s}_ankle"]] for s in SIDES}
    poles = {s: j[:, J[f"{s}_knee"]] + fwd + 0.3 * (1 if s == "left" else -1) * left for s in SIDES}
    return lower(j, drop, shift, np.radians(SQUAT_LEAN_DEG) * d, ankles, poles)


def lunges(base: np.ndarray, count: int, side: str = "alternate") -> np.ndarray:
    """The base with `count` forward lunges (alternating from the left, or one side): the
    front foot steps LUNGE_STEP_M forward, the pelvis drops LUNGE_DROP_M with the back knee
    going down towards the floor, then the front foot steps back."""
    j = np.asarray(base, dtype=np.float64)
    t = len(j)
    cycle, ph = phase(t, count)
    left, up, fwd = axes(j)
    step = np.where(cycle >= 0, np.minimum(ease(ph / 0.25), ease((1 - ph) / 0.25)), 0.0)
    low = np.where(cycle >= 0, np.minimum(ease((ph - 0.25) / 0.25), ease((0.75 - ph) / 0.25)), 0.0)
    arc = np.where(cycle >= 0, 0.08 * np.sin(np.pi * np.clip(np.where(ph < 0.5, ph, 1 - ph) / 0.25, 0, 1)), 0.0)
    fronts = _sides(count, side)
    front = np.array([fronts[c] == "left" if c >= 0 else False for c in cycle])
    drop = 0.12 * step + (LUNGE_DROP_M - 0.12) * low
    shift = 0.5 * LUNGE_STEP_M * step[:, None] * fwd
    ankles, poles = {}, {}
    for s in SIDES:
        a = j[:, J[f"{s}_ankle"]]
        is_front = front if s == "left" else ~front & (cycle >= 0)
        fw = np.where(is_front, LUNGE_STEP_M * step, 0.0)
        lift = np.where(is_front, arc * (low == 0), 0.06 * low)      # back heel rises
        ankles[s] = a + fw[:, None] * fwd + lift[:, None] * up
        knee = j[:, J[f"{s}_knee"]] + shift
        poles[s] = np.where(is_front[:, None], knee + fwd, knee + 0.4 * fwd - 0.6 * up)
    return lower(j, drop, shift, np.radians(8.0) * low, ankles, poles)
