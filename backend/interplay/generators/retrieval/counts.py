"""Counted actions ("jump three times", "kick twice with the right leg"): pieces that hold
exactly n of the action between them — one window with n where a capture has one, else single
repetitions chained, each starting in the pose the one before ends in — the last piece grown
into its capture's quiet frames, the rest of the segment its last pose held. Repetitions are
the benchmark's measured events (`measured.py`), of the named side and none of the other; a
side the captures lack is mirrored.
"""

from __future__ import annotations

import numpy as np

from interplay.generators.retrieval.constrained import gather
from interplay.generators.retrieval.index import Candidate, RetrievalIndex
from interplay.generators.retrieval.intent import Intent
from interplay.generators.retrieval.matching import best_start
from interplay.generators.retrieval.measured import Measures
from interplay.generators.retrieval.views import View

PRE, MIN_MARGIN = 12, 5   # frames of quiet kept before / after a counted action (at least)


def repetitions(ms: Measures, action: str, side: str | None) -> list[tuple[int, int, int, int, int]]:
    """(lo, s, e, hi, k): runs of k consecutive events of the action (of the side, none of the
    other between), spanning [s, e), with [lo, hi) the frames a window may grow to without
    touching another event."""
    ev = sorted([(s, e, True) for s, e in ms.events(action, side)]
                + [(s, e, False) for s, e in ms.other(action, side)])
    out = []
    for i in range(len(ev)):
        for j in range(i, len(ev)):
            if not ev[j][2]:
                break
            lo = ev[i - 1][1] if i > 0 else 0
            hi = ev[j + 1][0] if j + 1 < len(ev) else ms.frames
            if lo <= ev[i][0] and ev[j][1] <= hi:
                out.append((lo, ev[i][0], ev[j][1], hi, j - i + 1))
    return out


def count_options(index: RetrievalIndex, text: str, intent: Intent, frames: int
                  ) -> list[tuple[Candidate, tuple]]:
    """(view candidate, repetition) pairs for an action counted `intent.count` times, from the
    clips near the best text match that have one (the seed's shortlist), each repetition short
    enough to fit the segment."""
    assert intent.action is not None and intent.count is not None
    action, side, count = intent.action, intent.side, intent.count
    found: dict[int, list[tuple[Candidate, tuple]]] = {}
    flips = (False, True) if side is not None else (False,)

    def make(c: Candidate) -> list[tuple[Candidate, tuple]]:
        for mirrored in flips:
            view = View(index.clips[c.clip].id, mirrored)
            reps = [r for r in repetitions(index.measured(view.ref), action, side)
                    if r[4] <= count and r[2] - r[1] + 2 * MIN_MARGIN <= frames]
            found.setdefault(c.clip, []).extend(
                (Candidate(c.clip, c.window, c.score, view, (r[0], r[3])), r) for r in reps)
        return found.get(c.clip, [])
    gather(index, text, lambda i: True, make)
    best = {c: opts[0][0] for c, opts in found.items() if opts}
    keep = {c.clip for c in index.narrow(sorted(best.values(), key=lambda c: -c.score),
                                         np.random.default_rng(0))}
    return [o for c in keep for o in found[c]]


def count_draw(index: RetrievalIndex, options: list, frames: int, count: int,
               rng: np.random.Generator, after: dict | None) -> list[dict] | None:
    """Pieces with exactly `count` repetitions between them, from seeded picks among options
    (one window holding them all where one does, else as few pieces as can), the last one
    grown into its quiet frames; None if they cannot fit in `frames`."""
    for margin in (PRE, MIN_MARGIN):
        pieces: list[dict] = []
        his: list[int] = []
        left, target, used = count, index._target(after, [0]), 0
        while left > 0:
            fit = [o for o in options if o[1][4] <= left
                   and used + o[1][2] - o[1][1] + 2 * margin <= frames]
            if not fit:
                break
            k = left if any(o[1][4] == left for o in fit) else max(o[1][4] for o in fit)
            pool = [o for o in fit if o[1][4] == k]
            cand, (lo, s, e, hi, k) = pool[int(rng.integers(len(pool)))]
            ref = index.ref(cand)
            a_lo, a_hi = (max(lo, s - 2 * margin) if target is not None else lo), max(lo, s - margin)
            a = best_start(index.features(ref, (0,)), target, a_lo, a_hi) if target is not None \
                else _standing(index.measured(ref), a_lo, a_hi)
            b = min(hi, e + margin)
            pieces.append({"clip": ref, "people": [0], "start": int(a), "end": int(b),
                           "score": round(cand.score, 4)})
            his.append(hi)
            target, left, used = index.features(ref, (0,))[min(b, hi - 1)], left - k, used + b - a
        if left == 0 and used <= frames:
            pieces[-1]["end"] = int(min(his[-1], pieces[-1]["end"] + frames - used))
            return pieces
    return None


def _standing(ms: Measures, lo: int, hi: int) -> int:
    """The last frame in [lo, hi] standing (a first piece starts on its feet), else hi."""
    up = np.flatnonzero(ms.postures["standing"][lo:hi + 1])
    return lo + int(up[-1]) if len(up) else hi
