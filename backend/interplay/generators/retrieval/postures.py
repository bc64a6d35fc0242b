"""Postures at the start and the end of a segment ("get up from lying on the floor", "sit
down", "lie down, then sit up"): one piece that starts in the posture asked (or the one the
previous segment left the body in: pose-matched, and in the same capture where that capture
can make the change — a stand-up after a sit-down is the sit-down played backwards) and ends
once the posture asked at the end is reached: a sit-down is cut once seated, a lie-down once
lying, a get-up a second after standing; the generator then holds the last pose to the
segment's end. Postures are the benchmark's (`motion/checks/measures.py`), found in the capture
or in it played backwards (a lie-down reversed is a get-up).
"""

from __future__ import annotations

import numpy as np

from interplay.generators.retrieval.constrained import gather, profile
from interplay.generators.retrieval.index import Candidate, RetrievalIndex
from interplay.generators.retrieval.intent import LOW
from interplay.generators.retrieval.matching import best_start
from interplay.generators.retrieval.measured import Measures
from interplay.generators.retrieval.views import View
from interplay.motion.signals import runs

LEAD = 10               # frames of the starting posture before a change of posture
SAME_CLIP = 1.0         # score bonus (so: always preferred) for going on with the capture the
                        # previous piece was cut from: its own frames continue the pose exactly,
                        # where another capture's sitting or lying pose needs a fade


def posture_at(index: RetrievalIndex, piece: dict | None) -> str:
    """The posture a piece ends in (measured on its view's person 0), standing without one."""
    if not piece:
        return "standing"
    try:
        ms = index.measured(piece["clip"])
    except ValueError:
        return "standing"
    f = max(0, min(int(piece["end"]) - 1, ms.frames - 1))
    return next((k for k in LOW if ms.postures[k][f]), "standing")


def posture_options(index: RetrievalIndex, text: str, start: str, end: str, frames: int,
                    after: dict | None) -> list[tuple[Candidate, tuple[int, int, int, int]]]:
    """(view candidate, (a_lo, a_hi, a, end frame)) of windows that start in `start` and reach
    `end` within the segment: a ∈ [a_lo, a_hi] is where the piece may begin (a by default)."""
    low = profile(index)["low"]
    same = View.parse(after["clip"]).clip if after else None

    def make(c: Candidate) -> list[tuple[Candidate, tuple[int, int, int, int]]]:
        out = []
        for rev in (False, True):
            view = View(index.clips[c.clip].id, reversed=rev)
            found = _transition(index.measured(view.ref), start, end, frames)
            if found is not None:
                bonus = SAME_CLIP if view.clip == same else 0.0
                out.append((Candidate(c.clip, c.window, c.score + bonus, view, None), found))
        return out
    lead = (index.by_id[same],) if same in index.by_id else ()
    return sorted(gather(index, text, lambda i: low[i] < 0.55, make, lead),
                  key=lambda o: -o[0].score)


def _transition(ms: Measures, start: str, end: str, frames: int) -> tuple[int, int, int, int] | None:
    """The first change from `start` to `end` in a capture's measures that fits in `frames`."""
    for s0, e0 in runs(ms.postures[start]):
        later = [(s, e) for s, e in runs(ms.postures[end]) if s >= e0 - 2 and s - e0 <= 80]
        later = [(s, e) for s, e in later if e - s >= 6 or e == ms.frames]
        if not later:
            continue
        s1, e1 = later[0]
        if end in LOW:
            stop = s1 + int(np.clip((e1 - s1) // 3, 5, 20)) + 1
            a_lo = max(s0, stop - frames)
        else:
            stop = e1
            a_lo = max(s0, s1 + 20 - frames)
        a_hi = e0 - 1
        if a_lo <= a_hi and stop > a_lo:
            return a_lo, a_hi, max(a_lo, min(a_hi, e0 - LEAD)), stop
    return None


def posture_draw(index: RetrievalIndex, options: list, frames: int, rng: np.random.Generator,
                 after: dict | None) -> list[dict]:
    """One piece from a seeded pick among the options near the best: from its starting
    posture (pose-matched to `after` when there is one) to where its end posture is reached,
    at most `frames` long (the rest of the segment holds its last pose)."""
    cands = index.narrow([o[0] for o in options], rng)
    cand = cands[int(rng.integers(len(cands)))]
    a_lo, a_hi, a, stop = next(o[1] for o in options if o[0] is cand)
    target = index._target(after, [0])
    ref = index.ref(cand)
    if target is not None:
        a = best_start(index.features(ref, (0,)), target, a_lo, a_hi)
    return [{"clip": ref, "people": [0], "start": int(a), "end": int(min(stop, a + frames)),
             "score": round(cand.score, 4)}]
