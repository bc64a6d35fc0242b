"""Scenes where the two touch: a handshake, a high five, a hug, a push; optionally after they
walk up to each other. Each person is a real standing clip (and a real walk that stops into
it); the touch is a beat (`timing`) solved on the placed bodies (`contacts`). A push knocks the
partner back: from the touch on they walk backwards (a real walk-backwards clip, sped up and
started abruptly, `moves.locomote`) a metre or so, while the pusher's hands follow their
chest as far as they reach. A hug starts an arm's length apart and each steps in
(`moves.step`) as the arms go round.

Each builder returns (a, b, report) with a facing +Z at the origin on the touch's first frame.
"""

from __future__ import annotations

import numpy as np

from interplay.generators.interaction import contacts as ct
from interplay.generators.interaction import moves as mv
from interplay.generators.interaction.bodies import facing_pair
from interplay.generators.interaction.scene import Cast, clear, standing_pair
from interplay.generators.interaction.timing import Beat, beat, pump
from interplay.motion import skeleton as sk
from interplay.motion.ik import ease
from interplay.motion.pair import placement as pl
from interplay.motion.pair.bases import Base

SPINE3 = sk.JOINT_INDEX["spine3"]
APPROACH_M = (1.6, 2.4)       # metres each walks when they walk up to each other
APPROACH_S = 3.0              # s the walking up takes (the start, the walk, the stop) …
TOUCH_SHARE = 0.55            # … and the least share of a touch's own time it leaves it
HUG_STEP_M = (0.16, 0.22)     # each steps in this far for a hug


def _arrive(c: Cast, person: int, stop_by: int) -> tuple[np.ndarray, np.ndarray, dict]:
    """A person who stands, walks about APPROACH_M and stops by `stop_by`: (joints in the
    walk's frame, the standing clip they end in, report)."""
    w = mv.walk(c.rng, c.lib.walk_base(c.rng, c.walk_text(person), c.used()), 3 * c.frames)
    stand = mv.standing(c.rng, c.lib.pool, c.frames)
    go = int(round(c.rng.uniform(0.5, 0.8) * sk.FPS))
    j, rep = mv.locomote(w.joints, stand.joints, c.frames,
                         mv.Gait(go=go, metres=float(c.rng.uniform(*APPROACH_M)), stop_by=stop_by))
    c.source(person, w.source, "walk")
    c.source(person, stand.source, "stand")
    return j, stand.joints, rep


def _bodies(c: Cast, kind: str, need_s: float) -> tuple[list[np.ndarray], list[np.ndarray], int]:
    """Both people, in their own frames (facing +Z): standing all along, or walking up and
    stopping by the frame that leaves `need_s` s for the touch. Returns (joints, the standing
    clips, the first frame both stand)."""
    if not c.script.approach:
        stands = standing_pair(c)
        return [s.copy() for s in stands], stands, 0
    # a short prompt ("walk over and hug", 6 s) gives the touch what the walk leaves, down to
    # TOUCH_SHARE of its own time (its beat is squeezed to fit: timing.beat)
    need_s = max(min(need_s, c.frames / sk.FPS - APPROACH_S), TOUCH_SHARE * need_s)
    stop_by = c.frames - int(round(need_s * sk.FPS)) - 10
    arrived = [_arrive(c, p, stop_by) for p in (0, 1)]
    c.report["approach"] = [r for _, _, r in arrived]
    begin = max(r["stop"] for _, _, r in arrived) + 10
    return [j for j, _, _ in arrived], [s for _, s, _ in arrived], begin


def _place(c: Cast, people: list[np.ndarray], distance: float, lateral: float = 0.0) -> list[np.ndarray]:
    last = c.frames - 1
    current = 0.0 if c.script.approach else None      # walkers walked along +Z
    a, b = facing_pair(people[0], people[1], distance, last, last, lateral, current)
    b, moved = clear(a, b)
    c.report["placement"] = {"distance_m": round(distance + moved, 3), "lateral_m": round(lateral, 3)}
    return [a, b]


def handshake(c: Cast) -> list[np.ndarray]:
    people, stands, begin = _bodies(c, "handshake", 4.2)
    rng = c.rng
    height = float(rng.uniform(0.15, 0.24))
    y = 0.5 * (stands[0][:, sk.PELVIS, 1].mean() + stands[1][:, sk.PELVIS, 1].mean()) + height
    frac = rng.uniform(0.85, 0.95, 2)
    dist = sum(pl.forward_at(s, "right", 0.0, y, f) + 0.06 for s, f in zip(stands, frac))
    a, b = _place(c, people, dist)
    bt = beat(rng, "handshake", begin, c.frames)
    w = bt.weights(c.frames)
    a, b = ct.handshake(a, b, w, height, pump(rng, c.frames, bt.start))
    c.report["contact"] = {"kind": "handshake", **bt.to_json(), "hands": ["right", "right"]}
    return [a, b]


def high_five(c: Cast) -> list[np.ndarray]:
    people, stands, begin = _bodies(c, "high_five", 2.6)
    rng = c.rng
    side_b = "right" if rng.random() < 0.5 else "left"
    sa, sb = sk.RIGHT_SHOULDER, sk.JOINT_INDEX[f"{side_b}_shoulder"]
    x = 0.5 * (stands[0][:, sa, 0].mean() - stands[1][:, sb, 0].mean())
    above = float(rng.uniform(0.08, 0.18))
    y = max(stands[0][:, sa, 1].max(), stands[1][:, sb, 1].max()) + above
    dist = (pl.forward_at(stands[0], "right", x, y, rng.uniform(0.9, 0.97))
            + pl.forward_at(stands[1], side_b, -x, y, rng.uniform(0.9, 0.97)))
    a, b = _place(c, people, dist)
    bt = beat(rng, "high_five", begin, c.frames)
    a, b = ct.high_five(a, b, bt.weights(c.frames), "right", side_b, above)
    c.report["contact"] = {"kind": "high_five", **bt.to_json(), "hands": ["right", side_b]}
    return [a, b]


def _step_profile(frames: int, start: int, n: int, back: int | None) -> np.ndarray:
    t = np.arange(frames)
    p = ease((t - start) / n)
    return p - ease((t - back) / n) if back is not None else p


def hug(c: Cast) -> list[np.ndarray]:
    people, stands, begin = _bodies(c, "hug", 5.0)
    rng = c.rng
    steps = rng.uniform(*HUG_STEP_M, 2)
    close = float(rng.uniform(0.26, 0.3))
    lateral = float(rng.choice([-1.0, 1.0]) * rng.uniform(0.18, 0.22))
    a, b = _place(c, people, close + steps.sum(), lateral)
    bt = beat(rng, "hug", begin, c.frames)
    n = bt.ramp_in + 4
    back = bt.release_end if bt.release_end + n + 6 <= c.frames else None
    toward = (b[bt.start, sk.PELVIS] - a[bt.start, sk.PELVIS]) * np.array([1.0, 0.0, 1.0])
    toward /= np.linalg.norm(toward)
    # b stands a little to one side of a: each steps in with the foot on the open side.
    feet = ["right", "right"] if lateral > 0 else ["left", "left"]
    a = mv.step(a, _step_profile(c.frames, bt.reach_start - 4, n, back), steps[0] * toward, feet[0])
    b = mv.step(b, _step_profile(c.frames, bt.reach_start - 4, n, back), -steps[1] * toward, feet[1])
    # Heads turned away from each other, each resting beside the other's.
    hw = (Beat(bt.start, c.frames if back is None else back + n // 2, bt.ramp_in + 4, 0 if back is None else n // 2)
          ).weights(c.frames)
    a = ct.turn_head(a, hw, -45.0 if lateral > 0 else 45.0)
    b = ct.turn_head(b, hw, -45.0 if lateral > 0 else 45.0)
    b, moved = clear(a, b)
    heights = (float(rng.uniform(-0.02, 0.05)), float(rng.uniform(-0.14, -0.08)))
    lead = Beat(bt.start - 4, bt.end + 4, bt.ramp_in, bt.ramp_out)
    a, b = ct.hug(a, b, (bt.weights(c.frames), lead.weights(c.frames)), slice(bt.start, bt.end), heights)
    c.report["contact"] = {"kind": "hug", **bt.to_json(), "hands": ["both", "both"],
                           "steps_m": [round(float(s), 3) for s in steps], "stepped_feet": feet,
                           "steps_back": back is not None, "cleared_m": round(moved, 3)}
    return [a, b]


def push(c: Cast) -> list[np.ndarray]:
    """Person `actor` pushes; the other is knocked back (see the module doc)."""
    rng, frames = c.rng, c.frames
    pusher, pushed = c.script.actor, 1 - c.script.actor
    stands = standing_pair(c)
    bt = beat(rng, "push", 0, frames, tail=2.2)
    # The pushed person: standing until the touch, then walking backwards, then standing.
    back = c.lib.pick(rng, "walk_back", c.texts[pushed])
    wj = mv.walk(rng, Base(back, 0, back.frames), 3 * frames, along="facing")
    c.source(pushed, wj.source, "walk backwards")
    scale = float(np.clip(1.5 / max(mv.speed(wj.joints), 0.3), 1.0, 1.8))
    g = mv.Gait(go=bt.start + 4, metres=float(rng.uniform(1.0, 1.4)), stop_by=frames - 12,
                scale=scale, ramp_in=4, ramp_out=12, settle=10, settle_in=4)
    hit, rep = mv.locomote(wj.joints, stands[pushed], frames, g)
    c.report["pushed"] = dict(rep, person=pushed, speed_scale=round(scale, 2))
    # Where the hands go: the pushed one's chest, arms bent (65–75 % of their reach).
    s_p = stands[pusher]
    chest_y = float(s_p[:, SPINE3, 1].mean() + rng.uniform(0.02, 0.08))
    spread = float(rng.uniform(0.09, 0.13))
    frac = float(rng.uniform(0.65, 0.75))
    reach_z = max(pl.forward_at(s_p, arm, sg * spread, chest_y, frac) for arm, sg in (("left", 1.0), ("right", -1.0)))
    chest_z = float(stands[pushed][:, SPINE3, 2].mean() + 0.13)
    pair = [s_p.copy(), hit] if pusher == 0 else [hit, s_p.copy()]
    a, b = facing_pair(pair[0], pair[1], reach_z + chest_z, bt.start, bt.start)
    b, moved = clear(a, b)
    people = [a, b]
    pp, pd = people[pusher], people[pushed]
    # The pusher steps into the push as the other gives way.
    toward = (pd[bt.start, sk.PELVIS] - pp[bt.start, sk.PELVIS]) * np.array([1.0, 0.0, 1.0])
    toward /= max(float(np.linalg.norm(toward)), 1e-9)
    lunge = float(rng.uniform(0.12, 0.2))
    pp = mv.step(pp, _step_profile(frames, bt.start - 3, 10, None), lunge * toward,
                 str(rng.choice(["left", "right"])))
    height = chest_y - float(pd[bt.start, SPINE3, 1])
    front = ct.chest(pd, height)
    ok = np.all([ct.within_reach(pp, arm, front + spread * pl.out_of(pp, arm), 0.97) for arm in ("left", "right")], axis=0)
    lost = np.flatnonzero(~ok[bt.start:])
    end = bt.start + (int(lost[0]) if len(lost) else bt.end - bt.start)
    end = int(np.clip(end, bt.start + 2, bt.start + 8))
    bt = Beat(bt.start, end, bt.ramp_in, bt.ramp_out)
    people[pusher] = ct.push(pp, pd, bt.weights(frames), height, spread)
    c.report["contact"] = {"kind": "push", **bt.to_json(), "hands": ["both", None],
                           "pusher": pusher, "pusher_step_m": round(lunge, 3), "cleared_m": round(moved, 3)}
    return people
