"""Inference-time contact refinement of a generated two-person motion: when the prompt's kind
needs a touch (`contact_kinds`: handshake, high five, push, hug, walking hand in hand), the
touching arms are eased onto their targets on the partner by two-bone IK over a window picked
from the motion itself. numpy only.

    a, b, report = refine_contact(joints_a, joints_b, "handshake")

1. Window. The hold length and ramps are the composer's for the kind (`TIMING`); the start lies
   in the kind's plausible timing (the composer's lead after the ramp in, widened by whatever a
   segment has beyond 4 s) where the touching hands are already closest to their targets on
   average over the hold. Hand in hand holds for the whole motion.
2. Reach. Arms are never stretched (two-bone IK keeps both bones: `motion.ik`). If a target lies
   beyond 95 % of an arm's reach on a held frame, both people move towards each other along
   the line between their pelvises (half each, eased in with the arms and held to the end, or
   eased out again when the motion goes on after it: `free_end`), at most MAX_APPROACH; beyond
   that the motion is returned unchanged with the reason.
3. Arms. Each touching arm follows IK to a wrist goal that puts its hand sphere's centre on the
   target (a few fixed-point rounds: the hand lies past the wrist along the forearm), blended by
   eased weights (`ik.window_weights`: zero velocity and acceleration at both ends), elbows
   towards the composer's hints. Frames with zero weight are returned bit for bit.
4. Check. IV and penetration depth (`motion.metrics.pair_geometry`) before and after; if either
   rises (beyond rounding tolerances) the motion is returned unchanged with the reason.

Shapes: joints (T, 22, 3) metres, Y up, 20 fps, both people in one world frame.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from interplay.generators.coda.contact_kinds import (
    HAND_EXT,
    KINDS,
    POLES,
    TIMING,
    Reach,
    candidates,
    hand_centre,
    hand_radius,
)
from interplay.motion import skeleton as sk
from interplay.motion.ik import reach, two_bone_ik, window_weights
from interplay.motion.metrics import pair_geometry
from interplay.motion.pair import placement as pl
from interplay.motion.signals import runs, smooth

MAX_APPROACH = 0.6         # m the two people may move towards each other in total
REACH_SHARE = 0.95         # of an arm's length (upper arm + forearm) a wrist may go from the shoulder
CONTACT_GAP = 0.03         # m: a hand this close to the partner touches (the eval's check)
ALREADY = (-0.01, CONTACT_GAP)   # gaps already touching without sinking in: nothing to do
IV_TOL, PEN_TOL = 0.5, 0.01      # cm³ per frame, cm: "not higher" up to this
CLIP_FRAMES = 80           # the composer's clip length (4 s), which TIMING's leads are for
FIT_ROUNDS = 4
MIN_HELD = 20              # frames (1 s): the shortest hand-in-hand stretch worth making


class Skip(Exception):
    """The refinement does not apply to this motion; the message says why."""


def pair_numbers(a: np.ndarray, b: np.ndarray) -> dict:
    """IV (cm³ per frame), penetration (cm, mean depth of the deepest overlap) and IF."""
    g = pair_geometry(a, b)
    return {"iv_cm3": float(g["volume"].mean()), "if": float(g["overlap"].mean()),
            "penetration_cm": float(np.clip(-g["min_distance"], 0.0, None).mean() * 100.0)}


def reach_gaps(a: np.ndarray, b: np.ndarray, rs: list[Reach]) -> np.ndarray:
    """(T, len(rs)) surface gap (m) of each touching hand: to the partner's hand it meets, or
    to the partner's body (nearest sphere, `pair_geometry` hand_gap)."""
    people, out = (a, b), []
    g = None
    for r in rs:
        me, other = people[r.person], people[1 - r.person]
        if r.hand is not None:
            d = np.linalg.norm(hand_centre(me, r.side) - hand_centre(other, r.hand), axis=1)
            out.append(d - hand_radius(me) - hand_radius(other))
        else:
            g = pair_geometry(a, b) if g is None else g
            out.append(g["hand_gap"][:, r.person, 0 if r.side == "left" else 1].astype(np.float64))
    return np.stack(out, axis=1)


def _ramp(kind: str) -> int:
    return int(round(TIMING[kind][2] * sk.FPS))


def _timing(kind: str, t: int, free_start: bool, free_end: bool) -> tuple[int, int, int, int, int]:
    """(earliest start, latest start, hold, ramp in, ramp out) in frames for a motion of t."""
    (lead_lo, lead_hi), hold_s, ramp_s = TIMING[kind]
    ramp = int(round(ramp_s * sk.FPS))
    if hold_s is None:                                    # held all along
        r_in, r_out = (0 if free_start else ramp), (0 if free_end else ramp)
        if t - r_in - r_out < 2:
            raise Skip(f"{t} frames are too few to hold hands between the ramps")
        return r_in, r_in, t - r_in - r_out, r_in, r_out
    hold = max(2, int(round(hold_s * sk.FPS)))
    need = 2 * ramp + hold + 1
    if t < need:                                          # a short segment: scale it all down
        f = (t - 1) / need
        ramp, hold = int(ramp * f), int(hold * f)
        if hold < 2 or ramp < 2:
            raise Skip(f"{t} frames are too few for a {kind} (ramps and hold)")
    lo = ramp + int(round(lead_lo * sk.FPS))
    hi = ramp + int(round(lead_hi * sk.FPS)) + max(0, t - CLIP_FRAMES)
    hi = min(hi, t - ramp - hold - 1)
    return min(lo, hi), hi, hold, ramp, ramp


def _best_start(cost: np.ndarray, lo: int, hi: int, hold: int) -> int:
    """Start in [lo, hi] whose hold has the lowest mean cost (T,)."""
    cs = np.concatenate([[0.0], np.cumsum(cost)])
    starts = np.arange(lo, hi + 1)
    return int(starts[np.argmin(cs[starts + hold] - cs[starts])])


def _limits(people, rs: list[Reach]) -> np.ndarray:
    """(T, len(rs)) farthest a hand centre may be from its shoulder (arm not stretched)."""
    out = []
    for r in rs:
        j = people[r.person]
        forearm = np.linalg.norm(j[:, sk.JOINT_INDEX[r.wrist]]
                                 - j[:, sk.JOINT_INDEX[f"{r.side}_elbow"]], axis=1)
        out.append(REACH_SHARE * reach(j, f"{r.side}_arm") + HAND_EXT * forearm)
    return np.stack(out, axis=1)


def _over(people, rs: list[Reach]) -> np.ndarray:
    """(T,) largest distance (m) a target lies beyond its arm's limit, per frame."""
    far = []
    for r in rs:
        j = people[r.person]
        shoulder = j[:, sk.JOINT_INDEX[f"{r.side}_shoulder"]]
        far.append(np.linalg.norm(r.target(*people) - shoulder, axis=1))
    return (np.stack(far, axis=1) - _limits(people, rs)).max(axis=1)


def _excess(people, rs: list[Reach], held: slice) -> float:
    """Largest distance (m) a target lies beyond its arm's limit on the held frames."""
    return float(max(_over(people, rs)[held].max(), 0.0))


def _gain(rs: list[Reach]) -> float:
    """Reach gained per metre of approach: meeting hands both gain half of it."""
    return 2.0 if any(r.hand for r in rs) else 1.0


def _reachable_run(a, b, rs, timing, free_start: bool, free_end: bool) -> tuple[int, int]:
    """Hand in hand: the longest run of frames (at least MIN_HELD) on which MAX_APPROACH
    brings the hands within reach (generated walkers drift apart and back), inside the ramps
    where another segment joins."""
    t, ramp = len(a), timing[3] or timing[4] or _ramp("walk_side_by_side")
    ok = _gain(rs) * _over((a, b), rs) <= MAX_APPROACH
    if not free_start:
        ok[:ramp] = False
    if not free_end:
        ok[t - ramp:] = False
    best = max(runs(ok), key=lambda r: r[1] - r[0], default=(0, 0))
    if best[1] - best[0] < MIN_HELD:
        raise Skip(f"out of reach: on no {MIN_HELD} consecutive frames are the people near "
                   f"enough to hold hands with at most {MAX_APPROACH} m of approach "
                   f"(they walk {_apart(a, b):.2f} m apart, pelvis to pelvis, on average)")
    return best


def _apart(a, b, held=slice(None)) -> float:
    return float(np.linalg.norm((b[held, sk.PELVIS] - a[held, sk.PELVIS])[:, [0, 2]], axis=1).mean())


def _shifted(a, b, u, amount):
    """Both people moved towards each other: a by +amount/2 along u (T, 3), b by -amount/2."""
    s = 0.5 * amount[:, None] * u
    return a + s[:, None], b - s[:, None]


def _approach(a, b, rs, held: slice, profile: np.ndarray) -> tuple[np.ndarray, np.ndarray, float]:
    """Move the people closer (eased by profile (T,)) until every target on the held frames is
    within reach; (a, b, total metres). Skip when that needs more than MAX_APPROACH."""
    u = smooth(b[:, sk.PELVIS] - a[:, sk.PELVIS], 9) * np.array([1.0, 0.0, 1.0])
    u /= np.maximum(np.linalg.norm(u, axis=1, keepdims=True), 1e-9)
    gain = _gain(rs)
    total = 0.0
    for _ in range(12):
        moved = _shifted(a, b, u, total * profile)
        over = _excess(moved, rs, held)
        if over < 1e-3:
            return *moved, total
        total += gain * over
        if total > MAX_APPROACH:
            raise Skip(f"out of reach: the people are {_apart(a, b, held):.2f} m apart (pelvis to "
                       f"pelvis); the touch needs more than {MAX_APPROACH} m of approach, and "
                       f"arms are not stretched")
    raise Skip("the approach did not bring the targets within reach")


def _solve_arm(j: np.ndarray, r: Reach, target: np.ndarray, w: np.ndarray, kind: str) -> np.ndarray:
    """j with r's arm eased onto `target` (hand centre) by the weights w."""
    arm, shoulder = f"{r.side}_arm", j[:, sk.JOINT_INDEX[f"{r.side}_shoulder"]]
    pole = pl.pole(j, r.side, *POLES[kind])
    forearm = np.linalg.norm(j[:, sk.JOINT_INDEX[r.wrist]] - j[:, sk.JOINT_INDEX[f"{r.side}_elbow"]], axis=1)
    to = target - shoulder
    goal = target - HAND_EXT * forearm[:, None] * to / np.maximum(np.linalg.norm(to, axis=1, keepdims=True), 1e-9)
    for _ in range(FIT_ROUNDS):               # the hand lies past the wrist: correct the goal
        full = two_bone_ik(j, arm, goal, pole=pole)
        goal = goal + (target - hand_centre(full, r.side))
    return two_bone_ik(j, arm, goal, pole=pole, weight=w)


def _attempt(a0, b0, kind, rs: list[Reach], timing, free_start: bool, free_end: bool,
             before: dict) -> tuple[np.ndarray, np.ndarray, dict]:
    """One way (rs) of making the touch: (a, b, report items); Skip when it does not work."""
    t = len(a0)
    lo, hi, hold, r_in, r_out = timing
    if TIMING[kind][1] is None:                         # held: where the walkers are near
        start, end = _reachable_run(a0, b0, rs, timing, free_start, free_end)
        r_in = 0 if start == 0 else _ramp(kind)
        r_out = 0 if end == t else _ramp(kind)
        free_end = free_end and end == t
    else:
        cost = np.stack([np.linalg.norm(hand_centre((a0, b0)[r.person], r.side) - r.target(a0, b0),
                                        axis=1) for r in rs], axis=1).sum(axis=1)
        start = _best_start(cost, lo, hi, hold)
        end = start + hold
    gaps = reach_gaps(a0, b0, rs)                                          # (T, R)
    touching = np.all((gaps >= ALREADY[0]) & (gaps <= ALREADY[1]), axis=1)
    if touching[lo:hi + hold].sum() >= hold:
        raise Skip("the hands already touch in the window")
    held = slice(start, end)
    profile = window_weights(t, start, t if free_end else end, r_in, 0 if free_end else r_out)
    a, b, approach = _approach(a0, b0, rs, held, profile)
    w = window_weights(t, start, end, r_in, r_out)
    people = [a, b]
    targets = [r.target(a, b) for r in rs]              # from the moved bodies, before the arms
    for r, target in zip(rs, targets):
        people[r.person] = _solve_arm(people[r.person], r, target, w, kind)
    still = w == 0                   # IK at zero weight only rounds: keep those frames exact
    people[0][still], people[1][still] = a[still], b[still]
    a, b = people
    after = pair_numbers(a, b)
    if after["iv_cm3"] > before["iv_cm3"] + IV_TOL or \
            after["penetration_cm"] > before["penetration_cm"] + PEN_TOL:
        raise Skip(f"the touch would deepen the overlap (IV {before['iv_cm3']:.1f} → "
                   f"{after['iv_cm3']:.1f} cm³, penetration {before['penetration_cm']:.2f} → "
                   f"{after['penetration_cm']:.2f} cm)")
    return a, b, {"window": [start, end], "ramps": [r_in, r_out],
                  "hands": [[r.person, r.wrist] for r in rs], "approach_m": round(approach, 4),
                  "after": after,
                  "gap_cm": round(float(reach_gaps(a, b, rs)[held].max()) * 100.0, 2)}


def refine_contact(joints_a: np.ndarray, joints_b: np.ndarray, kind: str | None,
                   free_start: bool = True, free_end: bool = True
                   ) -> tuple[np.ndarray, np.ndarray, dict]:
    """(joints_a, joints_b, report) with the kind's touch made (module doc). free_start /
    free_end: the motion's first / last frame is the clip's own edge (the contact and the
    approach may hold there); False when another segment joins there (everything eases out).
    The kind's candidate ways (`contact_kinds.candidates`: hand pairs, heights, who pushes) are
    tried in order; the first that works is kept.
    report: kind, applied, reason (why not), tried, window [start, end), ramps, hands
    [[person, wrist]…], approach_m, gap_cm (largest touching-hand gap on the held frames),
    before / after (pair_numbers)."""
    a0, b0 = (np.asarray(x, np.float64) for x in (joints_a, joints_b))
    if a0.shape != b0.shape or a0.ndim != 3 or a0.shape[1:] != (sk.NUM_JOINTS, 3):
        raise ValueError(f"expected two (T, 22, 3) joint arrays, got {a0.shape} and {b0.shape}")
    report: dict[str, Any] = {"kind": kind, "applied": False, "reason": None}
    if kind is None:
        report["reason"] = "the prompt asks for no contact"
        return a0, b0, report
    if kind not in KINDS:
        raise ValueError(f"unknown contact kind {kind!r}; expected one of {KINDS}")
    before = pair_numbers(a0, b0)
    report.update({"before": before, "after": before, "tried": 0})
    try:
        timing = _timing(kind, len(a0), free_start, free_end)
    except Skip as why:
        report["reason"] = str(why)
        return a0, b0, report
    lo, hi, hold = timing[:3]
    reasons = []
    for rs in candidates(kind, a0, b0, slice(lo, hi + hold)):
        report["tried"] += 1
        try:
            a, b, got = _attempt(a0, b0, kind, rs, timing, free_start, free_end, before)
        except Skip as why:
            reasons.append(str(why))
            if str(why).startswith("the hands already touch"):
                break
            continue
        report.update(got, applied=True)
        return a, b, report
    report["reason"] = reasons[0] if len(set(reasons)) == 1 else "; ".join(dict.fromkeys(reasons))
    return a0, b0, report
