"""Scenes where the two walk: side by side (hands held or not), side by side until one stops,
one following the other, and walking up to each other. Each walker is a real level walk
(`moves.walk`, chosen by the person's text) that starts from and stops into real standing
(`moves.locomote`); a partner's walk is played faster or slower (by at most 25 %) to keep
pace with the other's. numpy only.
"""

from __future__ import annotations

import numpy as np

from interplay.generators.interaction import contacts as ct
from interplay.generators.interaction import moves as mv
from interplay.generators.interaction.bodies import facing_pair, turn_to
from interplay.generators.interaction.scene import Cast, clear
from interplay.motion import skeleton as sk
from interplay.motion.skeleton import FPS

PACE = (0.8, 1.25)     # how much faster or slower a partner's walk may be played
GAP_M = (0.75, 0.95)   # side by side: pelvis to pelvis …
HELD_GAP_M = (0.6, 0.75)  # … holding hands


def _walker(c: Cast, person: int, pace_of: float | None = None) -> tuple[np.ndarray, float, np.ndarray]:
    """(looped walk, rate scale, standing clip) for a person; with `pace_of` (m/s) the walk
    drawn (up to 8 tries) is one that can be played at that speed."""
    for _ in range(8):
        base = c.lib.walk_base(c.rng, c.walk_text(person), c.used())
        w = mv.walk(c.rng, base, 3 * c.frames)
        v = mv.speed(w.joints)
        scale = 1.0 if pace_of is None else pace_of / max(v, 1e-6)
        if PACE[0] <= scale <= PACE[1]:
            break
    scale = float(np.clip(scale, *PACE))
    stand = mv.standing(c.rng, c.lib.pool, c.frames)
    c.source(person, {**w.source, "speed_scale": round(scale, 3)}, "walk")
    c.source(person, stand.source, "stand")
    return w.joints, scale, stand.joints


def _go(c: Cast) -> int:
    return int(round(c.rng.uniform(0.5, 0.8) * FPS))


def _side_by_side(c: Cast, stopper: int | None) -> list[np.ndarray]:
    frames, rng = c.frames, c.rng
    go = _go(c)
    wa, sa, stand_a = _walker(c, 0)
    wb, sb, stand_b = _walker(c, 1, pace_of=mv.speed(wa))
    gaits = [mv.Gait(go=go, scale=sa), mv.Gait(go=go, scale=sb)]
    if stopper is not None:
        gaits[stopper].stop_by = frames - min(int(round(2.3 * FPS)) + 10, frames // 3)
    a, ra = mv.locomote(wa, stand_a, frames, gaits[0])
    b, rb = mv.locomote(wb, stand_b, frames, gaits[1])
    side = 1.0 if rng.random() < 0.5 else -1.0            # b on a's left (+X) or right
    gap = float(rng.uniform(*(HELD_GAP_M if c.script.held else GAP_M)))
    a = turn_to(a, 0.0, np.zeros(2), current=0.0)
    b = turn_to(b, 0.0, np.array([side * gap, 0.0]), current=0.0)
    b, moved = clear(a, b)
    c.report["walks"] = [ra, rb]
    c.report["placement"] = {"side": "left" if side > 0 else "right", "gap_m": round(gap + moved, 3)}
    if stopper is not None:
        c.report["stops"] = stopper
    if c.script.held:
        w = np.ones(frames)
        a, b = ct.held_hands(a, b, w, side, float(rng.uniform(0.0, 0.08)))
        c.report["contact"] = {"kind": "hands_held", "contact": [0, frames]}
    return [a, b]


def side_by_side(c: Cast) -> list[np.ndarray]:
    return _side_by_side(c, None)


def one_stops(c: Cast) -> list[np.ndarray]:
    """Side by side; person `actor` stops ≥ 2.3 s before the end, the other walks on."""
    return _side_by_side(c, c.script.actor)


def follow(c: Cast) -> list[np.ndarray]:
    """Person `actor` leads; the other starts 1–1.4 m behind, a moment later, at the same pace."""
    frames, rng = c.frames, c.rng
    lead = c.script.actor
    go = _go(c)
    wl, sl, stand_l = _walker(c, lead)
    wf, sf, stand_f = _walker(c, 1 - lead, pace_of=mv.speed(wl))
    later = go + int(round(rng.uniform(0.6, 1.0) * FPS))
    jl, rl = mv.locomote(wl, stand_l, frames, mv.Gait(go=go, scale=sl))
    jf, rf = mv.locomote(wf, stand_f, frames, mv.Gait(go=later, scale=sf))
    behind = float(rng.uniform(1.0, 1.4))
    jl = turn_to(jl, 0.0, np.zeros(2), current=0.0)
    jf = turn_to(jf, 0.0, np.array([float(rng.uniform(-0.15, 0.15)), -behind]), current=0.0)
    people = [jl, jf] if lead == 0 else [jf, jl]
    c.report["walks"] = [rl, rf] if lead == 0 else [rf, rl]
    c.report["follow"] = {"leader": lead, "behind_m": round(behind, 3), "delay_s": round((later - go) / FPS, 2)}
    return people


def approach(c: Cast) -> list[np.ndarray]:
    """Both walk towards each other from standing and stop facing 0.9–1.3 m apart."""
    frames, rng = c.frames, c.rng
    out, reports = [], []
    for person in (0, 1):
        w, s, stand = _walker(c, person)
        metres = float(rng.uniform(0.3, 0.4)) * frames / FPS
        j, rep = mv.locomote(w, stand, frames, mv.Gait(go=_go(c), metres=metres, stop_by=frames - min(25, frames // 5), scale=s))
        out.append(j)
        reports.append(rep)
    end = float(rng.uniform(0.9, 1.3))
    a, b = facing_pair(out[0], out[1], end, frames - 1, frames - 1, current=0.0)
    b, moved = clear(a, b)
    c.report["walks"] = reports
    c.report["placement"] = {"end_distance_m": round(end + moved, 3),
                             "start_distance_m": round(float(np.linalg.norm((b[0, sk.PELVIS] - a[0, sk.PELVIS])[[0, 2]])), 3)}
    return [a, b]


LEAD_BEHIND_M = (0.45, 0.55)   # leading by the hand: the led one this far behind the leader …
LEAD_SIDE_M = (0.28, 0.34)     # … and this far to the side, so their near hands meet between


def lead(c: Cast) -> list[np.ndarray]:
    """Person `actor` leads the other by the hand: both walk from standing at the same pace,
    the led one half a step behind and to one side, the leader's near hand reaching back and
    the other's forward, held between them from the first frame to the last (two-bone IK)."""
    frames, rng = c.frames, c.rng
    lead_, led = c.script.actor, 1 - c.script.actor
    go = _go(c)
    wl, sl, stand_l = _walker(c, lead_)
    wf, sf, stand_f = _walker(c, led, pace_of=mv.speed(wl))
    jl, rl = mv.locomote(wl, stand_l, frames, mv.Gait(go=go, scale=sl))
    jf, rf = mv.locomote(wf, stand_f, frames, mv.Gait(go=go + int(round(rng.uniform(0.05, 0.15) * FPS)), scale=sf))
    side = 1.0 if rng.random() < 0.5 else -1.0             # the led one on the leader's left (+X) or right
    behind, across = float(rng.uniform(*LEAD_BEHIND_M)), float(rng.uniform(*LEAD_SIDE_M))
    jl = turn_to(jl, 0.0, np.zeros(2), current=0.0)
    jf = turn_to(jf, 0.0, np.array([side * across, -behind]), current=0.0)
    jf, moved = clear(jl, jf)
    jl, jf = ct.held_hands(jl, jf, np.ones(frames), side, float(rng.uniform(-0.12, -0.06)))
    gap = ct.hand_gap(jl, jf, *(("left", "right") if side > 0 else ("right", "left")))
    if float((gap > 0.03).mean()) > 0.1:
        raise ValueError("the two hands do not reach each other while they walk")
    c.report["walks"] = [rl, rf] if lead_ == 0 else [rf, rl]
    c.report["contact"] = {"kind": "hands_held", "contact": [0, frames], "leader": lead_,
                           "behind_m": round(behind, 3), "side_m": round(across + moved, 3)}
    return [jl, jf] if lead_ == 0 else [jf, jl]
