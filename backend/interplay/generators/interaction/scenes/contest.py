"""Scenes of two people against each other (issue 24): sparring and a chase. numpy only.

Sparring: each plays a real clip of punches or kicks thrown from a fighting stance (the
library's `punch` / `kick` families), facing the other 1.2–1.6 m apart (pelvis to pelvis;
moved apart where the bodies, arms aside, would meet), the second's blows starting about
half a second after the first's so that they alternate. Chasing: both run the same way (real
runs, looped on their gait, `moves.walk`) from standing; the one chased starts a few metres
ahead and a moment earlier, the chaser's run is played faster so that the gap closes to about
a metre by the end (never nearer than CHASE_NEAREST_M), unlike `follow`, which keeps its gap.

Person `actor` throws the first blow / is the chaser.
"""

from __future__ import annotations

import numpy as np

from interplay.generators.interaction import moves as mv
from interplay.generators.interaction.bodies import facing_pair, on_shared, turn_to
from interplay.generators.interaction.scene import Cast, clear
from interplay.generators.interaction.scenes.gestures import _timed
from interplay.motion import skeleton as sk
from interplay.motion.checks import measures as m
from interplay.motion.checks.named import events
from interplay.motion.pair.bases import Base, face_forward

SPAR_M = (1.3, 1.5)          # pelvis to pelvis
CHASE_GAP_M = (2.6, 3.2)     # the chased one's head start
CHASE_END_M = (0.9, 1.2)     # the gap the chaser closes to
CHASE_NEAREST_M = 0.8
RATE = (0.8, 1.6)            # how much faster or slower a run may be played


def _s(seconds: float) -> int:
    return int(round(seconds * sk.FPS))


def spar(c: Cast) -> list[np.ndarray]:
    rng, frames = c.rng, c.frames
    first = c.script.actor
    kinds = ["punch", "kick"] if rng.random() < 0.5 else ["kick", "punch"]
    if rng.random() < 0.4:
        kinds = ["punch", "punch"]
    at = _s(rng.uniform(0.4, 0.8))
    people: list[np.ndarray] = [np.zeros(0), np.zeros(0)]
    timing = {}
    for person, kind, when in ((first, kinds[0], at), (1 - first, kinds[1], at + _s(rng.uniform(0.45, 0.7)))):
        clip = c.lib.pick(rng, kind, c.texts[person])
        j = face_forward(on_shared(clip.people[0], clip.offsets[0]))
        hits = events(m.frame_of(j))[kind]
        onset = max(0, hits[0] - _s(0.3)) if hits else len(j) // 4
        if person != first:      # another stretch of the same clip when both play one
            onset = max(0, (hits[1] if len(hits) > 1 else hits[0]) - _s(0.3)) if hits else onset
        people[person] = _timed(j, onset, when, frames)
        c.source(person, {"clip": clip.id, "start": 0, "end": clip.frames, "mirrored": False,
                          "licence": clip.licence}, kind)
        timing[str(person)] = {"kind": kind, "clip_onset": int(onset), "at": int(when)}
    dist = float(rng.uniform(*SPAR_M))
    a, b = facing_pair(people[0], people[1], dist)
    b, moved = clear(a, b)
    c.report["spar"] = {"blows": timing, "first": first, "distance_m": round(dist + moved, 3)}
    return [a, b]


def _runner(c: Cast, person: int, exclude: set[str]) -> tuple[np.ndarray, float, np.ndarray]:
    """(looped run along +Z, its speed m/s, a standing clip) for a person."""
    members = [i for i in c.lib.family("run") if c.lib.clips[i].id not in exclude] or c.lib.family("run")
    if not members:
        raise ValueError("no run clips in the data")
    clip = c.lib.clips[c.lib.choose(c.rng, members, c.texts[person])]
    w = mv.walk(c.rng, Base(clip, 0, clip.frames), 3 * c.frames)
    stand = mv.standing(c.rng, c.lib.pool, c.frames)
    c.source(person, w.source, "run")
    c.source(person, stand.source, "stand")
    return w.joints, mv.speed(w.joints), stand.joints


def chase(c: Cast) -> list[np.ndarray]:
    rng, frames = c.rng, c.frames
    chaser, chased = c.script.actor, 1 - c.script.actor
    wl, vl, stand_l = _runner(c, chased, set())
    wc, vc, stand_c = _runner(c, chaser, {s["clip"] for s in c.sources[chased]})
    go_l = _s(rng.uniform(0.3, 0.5))
    go_c = go_l + _s(rng.uniform(0.2, 0.4))
    gap0, gap1 = float(rng.uniform(*CHASE_GAP_M)), float(rng.uniform(*CHASE_END_M))
    scale_l = float(np.clip(1.0, *RATE))
    moving = max((frames - go_c) / sk.FPS - 0.5, 0.5)
    want = vl * scale_l + (gap0 - gap1 + vl * scale_l * (go_c - go_l) / sk.FPS) / moving
    scale_c = float(np.clip(want / max(vc, 1e-6), *RATE))
    jl, rl = mv.locomote(wl, stand_l, frames, mv.Gait(go=go_l, scale=scale_l))
    jc, rc = mv.locomote(wc, stand_c, frames, mv.Gait(go=go_c, scale=scale_c))
    side = float(rng.uniform(-0.2, 0.2))
    jl = turn_to(jl, 0.0, np.array([0.0, gap0]), current=0.0)
    jc = turn_to(jc, 0.0, np.array([side, 0.0]), current=0.0)
    gaps = np.linalg.norm((jl[:, sk.PELVIS] - jc[:, sk.PELVIS])[:, [0, 2]], axis=1)
    if gaps.min() < CHASE_NEAREST_M:     # never onto the heels of the one chased
        jc = jc - np.array([0.0, 0.0, CHASE_NEAREST_M - float(gaps.min())])
        gaps = np.linalg.norm((jl[:, sk.PELVIS] - jc[:, sk.PELVIS])[:, [0, 2]], axis=1)
    jc, _ = clear(jl, jc)
    c.report["walks"] = [rc, rl] if chaser == 0 else [rl, rc]
    c.report["chase"] = {"chaser": chaser, "start_gap_m": round(float(gaps[0]), 3),
                         "end_gap_m": round(float(gaps[-1]), 3), "nearest_m": round(float(gaps.min()), 3),
                         "rates": {"chaser": round(scale_c, 3), "chased": round(scale_l, 3)}}
    return [jc, jl] if chaser == 0 else [jl, jc]

