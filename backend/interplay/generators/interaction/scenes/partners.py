"""Scenes where one person does something to the other by hand (issue 24): helping someone up
off the floor, handing something over, touching a named part of the partner's body. Each
person is a real clip (a captured get-up, quiet standing) and the hands are put where they
meet by two-bone IK on the fixed bones (`contacts.hand_to`): right hands joined as the one on
the floor rises (the helper leaning down to them, then back as they pull), two hands meeting
between the two with a thing passed from one to the other, a hand resting on the partner's
shoulder, back, arm, head or hand for over half a second. numpy only.

Person `actor` is the helper, the giver, the one who touches.
"""

from __future__ import annotations

import numpy as np

from interplay.catalogue.grammar import words_rx
from interplay.catalogue.load import catalogue
from interplay.generators.interaction import contacts as ct
from interplay.generators.interaction import moves as mv
from interplay.generators.interaction.bodies import facing_pair, on_shared, turn_to, yaw_of
from interplay.generators.interaction.scene import Cast, clear, standing_pair
from interplay.generators.interaction.scenes.gestures import _timed
from interplay.generators.interaction.timing import Beat
from interplay.motion import skeleton as sk
from interplay.motion.checks.measures import HAND_RADIUS_M
from interplay.motion.ik import ease, reach
from interplay.motion.pair import placement as pl
from interplay.motion.pair.body import SPHERE_JOINT, body_spheres
from interplay.motion.pair.resolve import pair_bounds

J = sk.JOINT_INDEX
UP = np.array([0.0, 1.0, 0.0])
XZ = np.array([1.0, 0.0, 1.0])
UPPER = [J[n] for n in ("spine1", "spine2", "spine3", "neck", "head", "left_collar", "right_collar",
                        "left_shoulder", "right_shoulder", "left_elbow", "right_elbow", "left_wrist",
                        "right_wrist")]
PARTS = ("shoulder", "back", "arm", "head", "hand")
PULL_BACK_DEG = 12.0        # the helper leans back this far as the other rises
TOUCH_M = {"head": (0.5, 0.56), "hand": (0.6, 0.7)}   # facing, pelvis to pelvis (else 0.6–0.7 m)
PAT_M, PAT_HZ = 0.03, 2.5   # a pat lifts the hand this far off, this often (it stays within 5 cm)
DEPTH_CM = 2.5              # a touch deeper into the other's body is drawn again (bound: 3 cm)


def _s(seconds: float) -> int:
    return int(round(seconds * sk.FPS))


def lean(j: np.ndarray, degrees: np.ndarray) -> np.ndarray:
    """The upper body (spine1 up) turned forward by `degrees` (T,) about the pelvis, on the
    person's own left-right axis (negative: leaning back); the bones kept."""
    fwd, left = pl.axes(j)
    th = np.radians(degrees)[:, None]
    out = j.copy()
    rel = j[:, UPPER] - j[:, [sk.PELVIS]]
    k = left[:, None]
    cross = np.cross(np.broadcast_to(k, rel.shape), rel)
    dot = (rel * k).sum(-1, keepdims=True)
    c, s = np.cos(th)[:, None], np.sin(th)[:, None]
    out[:, UPPER] = j[:, [sk.PELVIS]] + rel * c + cross * s + k * dot * (1.0 - c)
    return out


def _arm(j: np.ndarray, side: str = "right") -> float:
    return float(reach(j, f"{side}_arm").mean()) * 1.15


def help_up(c: Cast) -> list[np.ndarray]:
    """The other lies on the floor and gets up (a captured get-up); the helper, standing in
    front, leans down, their right hands join as the other starts to rise, and the helper
    leans back as the other comes up to standing."""
    rng, frames = c.rng, c.frames
    helper, helped = c.script.actor, 1 - c.script.actor
    clip = c.lib.pick(rng, "getup", c.texts[helped])
    g = on_shared(clip.people[0], clip.offsets[0])
    c.source(helped, {"clip": clip.id, "start": 0, "end": clip.frames, "mirrored": False,
                      "licence": clip.licence}, "get up")
    y = g[:, sk.PELVIS, 1] - g[..., 1].min()
    lo, hi = float(y[:5].mean()), float(y[-5:].mean())
    onset = int(np.argmax(y > lo + 0.15 * (hi - lo)))
    up_at = int(np.argmax(y >= lo + 0.92 * (hi - lo)))
    at = min(_s(rng.uniform(1.2, 1.6)), max(frames - (up_at - onset) - _s(1.2), _s(0.6)))
    p = _timed(g, onset, at, frames)
    rise = (at, at + up_at - onset)
    s = mv.standing(rng, c.lib.pool, frames)
    c.source(helper, s.source, "stand")
    end = at + len(g) - 1 - onset
    if end < frames - 1:        # standing after the get-up: a real standing clip, blended in
        rest = mv.standing(rng, c.lib.pool, frames)
        c.source(helped, rest.source, "stand")
        p = _then_stand(p, end, rest.joints)
    p = turn_to(p, 0.0, np.zeros(2), frames - 1, current=yaw_of(p[-10:]))
    h = turn_to(s.joints, np.pi, np.zeros(2), 0, current=0.0)
    dist = float(rng.uniform(0.75, 0.85))
    h = h + np.array([float(rng.uniform(-0.05, 0.05)), 0.0, dist]) - h[0, sk.PELVIS] * XZ
    p, moved = clear(h, p)
    # The hands' beat: reach down before the rise, hold through it, let go after.
    bt = Beat(rise[0] - _s(0.2), min(rise[1] + _s(0.35), frames - _s(0.5)), _s(0.6), _s(0.5))
    w = bt.weights(frames)
    pull = np.clip((np.arange(frames) - rise[0]) / max(rise[1] - rise[0], 1), 0.0, 1.0)
    pull = np.sin(np.pi * np.clip(pull * 0.7, 0.0, 1.0)) * w
    need = _lean_needed(h, p, _arm(h) + _arm(p))
    h = lean(h, need * w - PULL_BACK_DEG * pull)
    sh, sp = h[:, J["right_shoulder"]], p[:, J["right_shoulder"]]
    along = sp - sh
    along /= np.maximum(np.linalg.norm(along, axis=1, keepdims=True), 1e-9)
    share = _arm(h) / (_arm(h) + _arm(p))
    meet = sh + share * (sp - sh)
    half = HAND_RADIUS_M - ct.TOUCH / 2
    h = ct.hand_to(h, "right", meet - half * along, w, pl.pole(h, "right", 0.15, 0.3, 0.1))
    p = ct.hand_to(p, "right", meet + half * along, w, pl.pole(p, "right", 0.15, 0.3, 0.1))
    held = ct.hand_gap(h, p, "right", "right")[bt.start:bt.end]
    if float((held > 0.03).mean()) > 0.2:
        raise ValueError("the helper's hand does not reach the other's as they rise")
    c.report["contact"] = {"kind": "help_up", **bt.to_json(), "hands": ["right", "right"],
                           "helper": helper, "rise": [int(rise[0]), int(rise[1])],
                           "lean_deg": round(float((need * w).max()), 1), "cleared_m": round(moved, 3)}
    return [h, p] if helper == 0 else [p, h]


def _then_stand(p: np.ndarray, end: int, stand: np.ndarray, blend: int = 12) -> np.ndarray:
    """p from frame `end` on: its pose there eased into the standing clip `stand`, turned to
    p's facing over its last frames and placed at its pelvis."""
    out = p.copy()
    at = p[end]
    st = turn_to(stand, yaw_of(p[max(0, end - 6):end + 1]), at[sk.PELVIS][[0, 2]], 0)
    st = st[:len(p) - end]
    w = ease(np.arange(len(st)) / blend)[:, None, None]
    out[end:] = (1.0 - w) * at[None] + w * st
    return out


def _lean_needed(h: np.ndarray, p: np.ndarray, arms: float) -> np.ndarray:
    """(T,) degrees the helper must lean forward for the two right shoulders to come within
    90 % of both arms' reach (0–55°, smoothed)."""
    sp = p[:, J["right_shoulder"]]
    need = np.full(len(h), 55.0)
    for deg in range(55, -1, -5):
        sh = lean(h, np.full(len(h), float(deg)))[:, J["right_shoulder"]]
        ok = np.linalg.norm(sh - sp, axis=1) <= 0.9 * arms
        need[ok] = deg
    k = np.ones(9) / 9
    return np.convolve(np.pad(need, 4, mode="edge"), k, mode="valid")


def hand_over(c: Cast) -> list[np.ndarray]:
    """The giver holds a thing in front of their chest and reaches it out; the other reaches,
    their right hands meet between them (a thing between the palms, 3–5 cm apart) and the
    receiver draws it back to their own chest while the giver's arm drops."""
    rng, frames = c.rng, c.frames
    giver, taker = c.script.actor, 1 - c.script.actor
    stands = standing_pair(c)
    dist = float(rng.uniform(0.95, 1.1))
    a, b = facing_pair(stands[0], stands[1], dist)
    b, moved = clear(a, b)
    people = [a, b]
    g, r = people[giver], people[taker]
    t_hold = _s(rng.uniform(0.4, 0.7))
    t_meet = min(t_hold + _s(rng.uniform(1.4, 1.8)), frames - _s(2.4))
    t_rel = t_meet + _s(rng.uniform(0.6, 0.8))
    if t_meet <= t_hold + _s(0.6):
        raise ValueError(f"{frames} frames are too few to hand something over")
    y = 0.5 * (g[:, sk.PELVIS, 1].mean() + r[:, sk.PELVIS, 1].mean()) + float(rng.uniform(0.22, 0.3))
    sg, sr = g[:, J["right_shoulder"]], r[:, J["right_shoulder"]]
    along = (r[:, sk.PELVIS] - g[:, sk.PELVIS]) * XZ
    along /= np.maximum(np.linalg.norm(along, axis=1, keepdims=True), 1e-9)
    meet = 0.5 * (sg + sr) * XZ + y * UP
    gap = HAND_RADIUS_M + float(rng.uniform(0.015, 0.025))     # the thing between the palms
    held_g = _chest(g, 0.3, y - 0.05)
    held_r = _chest(r, 0.28, y - 0.05)
    t = np.arange(frames)
    out_g = ease((t - (t_meet - _s(0.9))) / _s(0.9))[:, None]
    goal_g = held_g + out_g * (meet - gap * along - held_g)
    w_g = Beat(t_hold, t_rel, t_hold, _s(0.7)).weights(frames)
    back = ease((t - t_rel) / _s(0.7))[:, None]
    goal_r = meet + gap * along + back * (held_r - meet - gap * along)
    w_r = ease((t - (t_meet - _s(0.8))) / _s(0.8))
    g = ct.hand_to(g, "right", goal_g, w_g, pl.pole(g, "right", 0.15, 0.35, 0.1))
    r = ct.hand_to(r, "right", goal_r, w_r, pl.pole(r, "right", 0.15, 0.35, 0.1))
    people[giver], people[taker] = g, r
    c.report["contact"] = {"kind": "hand_over", "giver": giver, "hold": int(t_hold), "meet": int(t_meet),
                           "release": int(t_rel), "hands": ["right", "right"],
                           "distance_m": round(dist + moved, 3)}
    return people


def _chest(j: np.ndarray, ahead: float, y: float) -> np.ndarray:
    """A point (T, 3) `ahead` m in front of the chest (slightly to the right hand), at height y."""
    fwd = pl.axes(j)[0]
    p = j[:, J["spine3"]] + ahead * fwd + 0.08 * pl.out_of(j, "right")
    p[:, 1] = y
    return p


def touch(c: Cast) -> list[np.ndarray]:
    """One (`actor`) lays a hand on the other's named part (script.part: shoulder, back, arm,
    head, hand) and keeps it there 1–1.5 s: facing them, or for the back beside them."""
    rng, frames = c.rng, c.frames
    doer, other = c.script.actor, 1 - c.script.actor
    part = c.script.part or "shoulder"
    stands = standing_pair(c)
    if part == "back":       # beside them, a little behind, facing the same way
        side = float(rng.choice([-1.0, 1.0]))
        d = turn_to(stands[doer], 0.0, np.array([side * float(rng.uniform(0.56, 0.62)), -0.15]), 0, 0.0)
        o = turn_to(stands[other], 0.0, np.zeros(2), 0, 0.0)
        hand = "right" if side > 0 else "left"
        o, moved = clear(d, o)
    else:
        dist = float(rng.uniform(*TOUCH_M.get(part, (0.6, 0.7))))
        d, o = facing_pair(stands[doer], stands[other], dist)
        o, moved = clear(d, o)
        hand = "right"
    start = _s(rng.uniform(0.6, 1.0))
    hold = _s(rng.uniform(1.0, 1.5))
    if start + hold + _s(1.0) > frames:
        raise ValueError(f"{frames} frames are too few for a touch")
    bt = Beat(start, start + hold, _s(0.6), _s(0.5))
    if part == "hand":       # the other's hand comes up a little to meet it, as hands are taken
        d, o = _take_hand(d, o, hand, bt.weights(frames), float(rng.uniform(0.0, 0.08)))
    else:
        goal, normal = _touch_point(d, o, part, hand)
        pats = tuple(catalogue().words.lists["touch_pats"])
        if words_rx(pats).search(c.texts[doer]):     # a pat or a tap: the hand lifts off and back
            t = (np.arange(frames) - bt.start) / sk.FPS
            inside = (np.arange(frames) >= bt.start) & (np.arange(frames) < bt.end)
            goal = goal + (PAT_M * 0.5 * (1.0 - np.cos(2 * np.pi * PAT_HZ * t)) * inside)[:, None] * normal
        d = ct.hand_to(d, hand, goal, bt.weights(frames), pl.pole(d, hand, 0.2, 0.3, 0.05))
    depth = pair_bounds(d, o, "hands")["depth_cm"]
    if depth > DEPTH_CM:
        raise ValueError(f"the toucher's arm goes {depth:.1f} cm into the other")
    people = [d, o] if doer == 0 else [o, d]
    c.report["contact"] = {"kind": "touch", "depth_cm": depth, "part": part, "toucher": doer, "hand": hand,
                           **bt.to_json(), "cleared_m": round(moved, 3)}
    return people


def _take_hand(d: np.ndarray, o: np.ndarray, hand: str, w: np.ndarray, rise: float
               ) -> tuple[np.ndarray, np.ndarray]:
    """d's `hand` and the other's nearest hand meet between the two, `rise` m over the mean
    pelvis height, their surfaces just touching."""
    near = d[:, J[f"{hand}_shoulder"]]
    side = min(("left", "right"), key=lambda s: float(np.linalg.norm(o[:, J[f"{s}_shoulder"]] - near, axis=1).mean()))
    meet = 0.5 * (near + o[:, J[f"{side}_shoulder"]]) * XZ
    meet[:, 1] = 0.5 * (d[:, sk.PELVIS, 1] + o[:, sk.PELVIS, 1]) + rise
    along = (o[:, sk.PELVIS] - d[:, sk.PELVIS]) * XZ
    along /= np.maximum(np.linalg.norm(along, axis=1, keepdims=True), 1e-9)
    half = HAND_RADIUS_M - ct.TOUCH / 2
    d = ct.hand_to(d, hand, meet - half * along, w, pl.pole(d, hand, 0.15, 0.4, 0.1))
    o = ct.hand_to(o, side, meet + half * along, w, pl.pole(o, side, 0.15, 0.4, 0.1))
    return d, o


def _touch_point(d: np.ndarray, o: np.ndarray, part: str, hand: str) -> tuple[np.ndarray, np.ndarray]:
    """Where the centre of `hand` goes (T, 3): on the surface of the partner's part, the
    hand's sphere just touching the part's (1 cm into it), and the outward direction there (T, 3);
    a limb on the side nearest the hand (part: shoulder, arm, head or back)."""
    toward = (d[:, sk.PELVIS] - o[:, sk.PELVIS]) * XZ
    toward /= np.maximum(np.linalg.norm(toward, axis=1, keepdims=True), 1e-9)
    near = d[:, J[f"{hand}_shoulder"]]
    side = min(("left", "right"), key=lambda s: float(np.linalg.norm(o[:, J[f"{s}_shoulder"]] - near, axis=1).mean()))
    if part == "shoulder":
        (centre, radius), direction = _sphere(o, J[f"{side}_shoulder"]), UP + 0.4 * toward
    elif part == "arm":
        centre = 0.5 * (o[:, J[f"{side}_shoulder"]] + o[:, J[f"{side}_elbow"]])
        radius, direction = _sphere(o, J[f"{side}_elbow"])[1], toward + 0.2 * UP
    elif part == "head":
        (centre, radius), direction = _sphere(o, sk.HEAD), UP + 1.2 * toward
    else:                    # the upper back, from behind
        (centre, radius), direction = _sphere(o, J["spine3"]), -pl.axes(o)[0] + 0.2 * UP
    direction = direction / np.maximum(np.linalg.norm(direction, axis=-1, keepdims=True), 1e-9)
    return centre + (radius + HAND_RADIUS_M - 0.01) * direction, direction


def _sphere(o: np.ndarray, joint: int) -> tuple[np.ndarray, float]:
    """The partner's body sphere nearest a joint: its centre (T, 3) and radius."""
    sp = body_spheres(o)
    idx = np.flatnonzero(SPHERE_JOINT == joint)
    k = idx[int(np.argmin(np.linalg.norm(sp.centres[:, idx] - o[:, [joint]], axis=2).mean(0)))]
    return sp.centres[:, k], float(sp.radii[k])
