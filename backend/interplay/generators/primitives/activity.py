"""An everyday activity built from part instructions (CoMA's idea: each body part told what to
do), read from a catalogue entry's `made_by.moves` (`catalogue/schema.Moves`): hammering is
the right hand going up and down 30 cm in front of the chest, sweeping both hands together
swinging side to side low in front, eating a hand held at the mouth, pushing a cart both
hands ahead at the waist on a walk. Hands reach their targets by two-bone IK on the
performer's own bones (`arms.hand_to`); the trunk leans and the head pitches about their
joints (`body.turn`); legs march by the knee-lift primitive. Nothing is a clip: the base is a
captured posture (`postures.posture`), the rest is geometry, so a count of strokes is exact.

    activity(base, count=6, hands="right", at="chest", axis="up", amplitude_m=0.3)   # hammering

Shapes: base and result (T, 22, 3) metres, Y up; targets (T, 3).
"""

from __future__ import annotations

import numpy as np

from interplay.generators.primitives.arms import hand_to, lean_to_reach
from interplay.generators.primitives.body import axes, turn, turn_subtree, upper_body
from interplay.generators.primitives.legs import knee_lifts, lower
from interplay.generators.primitives.timing import envelope, phase
from interplay.motion import skeleton as sk
from interplay.motion.checks.measures import hand_point

J = sk.JOINT_INDEX
SIDES = {"left": 1.0, "right": -1.0}      # sign along the body's left axis
MAX_BEND_DEG = 35.0                       # the deepest trunk bend to a low target (a broom, a spade)
BOW_M = 0.25                              # how far forward the hand's way in and out bows
BOUNCE_M = 0.04                           # a bounce's dip (legs "bounce"), the feet kept down
HOP_M = 0.12                              # a hop's height (legs "hop")
APART_M = 0.15                            # each hand's offset from the midline (together: 0.05)


def _anchor(j: np.ndarray, at: str, side: str, reach_m: float, together: bool) -> np.ndarray:
    """(T, 3) where the `side` hand works, on the body's axes: `reach_m` ahead of the point."""
    left, up, fwd = axes(j)
    s = SIDES[side] * (0.05 if together else APART_M)
    head, chest, pel = j[:, sk.HEAD], j[:, J["spine3"]], j[:, sk.PELVIS]
    if at == "face":                       # the mouth: a hand's centre just before the face
        return head + 0.12 * fwd - 0.06 * up + 0.3 * s * left
    if at == "ear":
        return head + 0.03 * fwd + SIDES[side] * 0.11 * left
    if at == "overhead":
        return head + 0.30 * up + 0.10 * fwd + s * left
    if at == "waist":
        return pel + 0.10 * up + reach_m * fwd + s * left
    if at == "lap":                        # seated: over the thighs
        return pel + 0.15 * up + (reach_m + 0.1) * fwd + s * left
    if at == "low":                        # thigh-high ahead: the trunk bends to it
        return pel - 0.20 * up + reach_m * fwd + s * left
    if at == "hang":                       # hanging by the hips (bags, a suitcase)
        return pel - 0.05 * up + 0.05 * fwd + SIDES[side] * 0.28 * left
    if at == "side":
        return j[:, J[f"{side}_shoulder"]] + SIDES[side] * 0.45 * left - 0.10 * up + 0.10 * fwd
    return chest + reach_m * fwd + s * left   # chest


def _pole(j: np.ndarray, side: str, at: str) -> np.ndarray:
    """Where the elbow points: out and down, out and up for hands overhead."""
    left, up, fwd = axes(j)
    out = SIDES[side] * left
    sh = j[:, J[f"{side}_shoulder"]]
    if at in ("overhead", "ear"):
        return sh + 0.35 * out + 0.15 * up
    return sh + 0.30 * out - 0.30 * up - 0.05 * fwd


def _stroke(j: np.ndarray, axis: str, amplitude_m: float, wave: np.ndarray, wave90: np.ndarray
            ) -> np.ndarray:
    """(T, 3) the hand's offset from its anchor: `wave` in [-1, 1] along the axis (half the
    amplitude each way); a circle adds the quarter-turned wave on the vertical."""
    left, up, fwd = axes(j)
    half = 0.5 * amplitude_m
    if axis == "still":
        return np.zeros_like(left)
    if axis == "circle":
        return half * (wave[:, None] * left + wave90[:, None] * up)
    d = {"up": up, "forward": fwd, "side": left}[axis]
    return half * wave[:, None] * d


def activity(base: np.ndarray, count: int, hands: str = "right", at: str = "chest",
             axis: str = "up", amplitude_m: float = 0.25, reach_m: float = 0.3,
             together: bool = False, lean_deg: float = 0.0, head_deg: float = 0.0,
             legs: str = "still", side: str | None = None, cycle_s: float | None = None,
             posture: str | None = None) -> np.ndarray:
    """The base (T, 22, 3) with `count` strokes of the hands (see the module's note). `side`
    (a prompt's "with the left hand") overrides a one-handed entry's hand. `cycle_s` and
    `posture` are the entry's own (they set the base and its length) and are not used here."""
    j = np.asarray(base, dtype=np.float64)
    t = len(j)
    env = envelope(t)
    cyc, ph = phase(t, max(1, count))
    inside = (cyc >= 0).astype(np.float64)
    if legs == "march":
        j = knee_lifts(j, count=max(1, count), side="alternate")
    elif legs == "bounce":                   # a small dip each stroke, the feet kept down
        dip = BOUNCE_M * inside * (0.5 - 0.5 * np.cos(2 * np.pi * ph))
        left, up, fwd = axes(j)
        ankles = {s: j[:, J[f"{s}_ankle"]] for s in SIDES}
        poles = {s: j[:, J[f"{s}_knee"]] + fwd for s in SIDES}
        j = lower(j, dip, np.zeros_like(fwd), np.zeros(t), ankles, poles)
    elif legs == "hop":                      # a small jump each stroke (a skipping rope)
        lift = HOP_M * inside * np.sin(np.pi * ph) ** 2
        j = j + lift[:, None, None] * np.array([0, 1.0, 0])
    left, up, fwd = axes(j)
    if lean_deg:
        j = turn(j, upper_body(), j[:, sk.PELVIS], left, np.radians(lean_deg) * env)
    if head_deg:                             # + looks down at the hands
        j = turn_subtree(j, sk.NECK, left, -np.radians(head_deg) * env, include_self=False)
    if hands == "none":
        return j
    one = hands in ("right", "left")
    moving = ([side or hands] if one else ["left", "right"])
    for s in moving:
        shift = 0.5 if hands == "alternate" and s == "left" else 0.0
        # each wave 0 where the strokes start and end (the other hand half a turn on)
        wave = inside * (np.sin(2 * np.pi * (ph + shift)) - np.sin(2 * np.pi * shift))
        wave90 = inside * (np.cos(2 * np.pi * (ph + shift)) - np.cos(2 * np.pi * shift))
        if at == "low" and s == moving[0]:
            j = _bend_to(j, s, _anchor(j, at, s, reach_m, together), env)
        goal = _anchor(j, at, s, reach_m, together) + _stroke(j, axis, amplitude_m, wave, wave90)
        j = hand_to(j, s, _eased(j, s, goal, env), _pole(j, s, at), (env > 0).astype(np.float64))
    return j


def _bend_to(j: np.ndarray, side: str, point: np.ndarray, env: np.ndarray) -> np.ndarray:
    """The trunk bent forward, by one angle over the strokes (eased in and out by `env`), far
    enough for the `side` arm to reach `point` (at most MAX_BEND_DEG: a tool's handle makes up
    the rest): a bend searched per frame would jump between its steps as the stroke moves the
    hand."""
    _, ang = lean_to_reach(j, side, point, np.ones(len(j)))
    bend = float(np.percentile(ang[env >= 1.0], 90)) if (env >= 1.0).any() else 0.0
    bend = min(bend, np.radians(MAX_BEND_DEG))
    left = axes(j)[0]
    return turn(j, upper_body(), j[:, sk.PELVIS], left, bend * env)


def _eased(j: np.ndarray, side: str, goal: np.ndarray, env: np.ndarray) -> np.ndarray:
    """(T, 3) the hand's way from where it hangs to `goal` as `env` rises (and back as it
    falls), bowed forward in front of the body: a straight line from a hanging hand to a
    target overhead or low in front passes through the trunk, and blending the arm's
    rotations over ~180° flips the elbow half-way."""
    fwd = axes(j)[2]
    e = env[:, None]
    return (1 - e) * hand_point(j, side) + e * goal + (4 * e * (1 - e)) * BOW_M * fwd
