"""Candidates and draws for segments that ask for more than their words' nearest captures
(`intent.py`), chosen on what the captures measurably do (`measured.py`), in whichever view
(`views.py`) does it:

- travel (backwards, sideways): windows of a view that travel that way relative to facing for
  ≥ 1 s — a captured backward walk or side shuffle as it is, a forward walk or run reversed,
  a side shuffle mirrored or reversed for the other side;
- a named side: a view whose kicks / punches are of that side and none of the other (by
  measurement), or, for actions the measures do not count (waves, raised hands), whose words
  do not name the other side (mirrored otherwise);
- counts (`counts.py`) and postures (`postures.py`) build on the helpers here.

Every function scans candidates best text match first; the seed chooses among those within
the index's margin of the best that qualifies.
"""

from __future__ import annotations

import weakref

import numpy as np

from interplay.generators.retrieval.index import Candidate, RetrievalIndex
from interplay.generators.retrieval.intent import Intent
from interplay.generators.retrieval.measured import DIRECTIONS, Measures
from interplay.generators.retrieval.views import View
from interplay.motion import skeleton as sk
from interplay.motion.kinematics import facing_direction
from interplay.motion.signals import runs

SCAN = 400              # candidates looked at, best text match first
MIN_TRAVEL_S = 1.0      # a travel window lasts ≥ 1 s …
TRAVEL_SHARE = 0.75     # … with ≥ 75 % of its distance that way …
TRAVEL_M = 0.6          # … and ≥ 0.6 m of it, overall within 25° of that way (a diagonal walk,
TRAVEL_DEG = 25.0       # forward-left at ~60°, is no side step)
AIM = {"forward": 0.0, "left": 90.0, "right": -90.0, "backward": 180.0}
TRAVEL_MARGIN = 0.25    # few captures travel sideways or backwards: a wider text margin for them
MOVING = 0.01           # m per frame (0.2 m/s): slower pelvis steps have no direction
_CHEAP: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def profile(index: RetrievalIndex) -> dict[str, np.ndarray]:
    """Per clip (person 0), from the raw joints (cheap), so that only clips that can travel a
    way or get low are measured: metres travelled along and across the facing direction
    (any sign; `along`, `across`) and the lowest pelvis height as a share of its high one."""
    if index not in _CHEAP:
        along, across, low = [], [], []
        for c in index.clips:
            j = np.asarray(c.people[0], dtype=np.float64)
            p = j[:, sk.PELVIS]
            step = np.diff(p[:, [0, 2]], axis=0)
            fwd = facing_direction(j[:-1])[:, [0, 2]] if len(j) > 1 else np.zeros((0, 2))
            ahead = (step * fwd).sum(axis=1)
            side = step[:, 0] * fwd[:, 1] - step[:, 1] * fwd[:, 0]
            along.append(max(ahead.clip(0).sum(), (-ahead).clip(0).sum(), 0.0))
            across.append(max(side.clip(0).sum(), (-side).clip(0).sum(), 0.0))
            top = float(np.percentile(p[:, 1], 95)) if len(p) else 1.0
            low.append(float(p[:, 1].min() / max(top, 1e-6)) if len(p) else 1.0)
        _CHEAP[index] = {"along": np.array(along), "across": np.array(across), "low": np.array(low)}
    return _CHEAP[index]


def gather(index: RetrievalIndex, text: str, keep, make, first: tuple[int, ...] = (),
            margin: float | None = None) -> list:
    """What `make(candidate)` gives (a list) for candidates best text match first (single-person
    use, person 0) that pass the cheap filter `keep(clip index)`: the clips in `first`, then
    the rest until one gives something and the text match falls below that one's by more
    than the index's margin (or SCAN candidates were looked at)."""
    cands = index.candidates(text, pair=False)
    lead = [c for c in cands if c.clip in first]
    out, best = [], None
    margin = index.config.margin if margin is None else margin
    for n, c in enumerate(lead + [c for c in cands if c.clip not in first]):
        if n >= SCAN + len(lead) or (best is not None and c.score < best - margin):
            break
        if index.clips[c.clip].frames < 4 or not keep(c.clip):
            continue
        got = make(c)
        if got:
            out += got
            if best is None and n >= len(lead):
                best = c.score
    return out


def _close(mask: np.ndarray, gap: int) -> np.ndarray:
    """mask with False runs of ≤ gap frames between True frames set True."""
    out = mask.copy()
    for s, e in runs(~mask):
        if s > 0 and e < len(mask) and e - s <= gap:
            out[s:e] = True
    return out


def travel_span(ms: Measures, way: str, within: tuple[int, int] | None = None
                ) -> tuple[int, int] | None:
    """The longest stretch of frames (inside `within`, when given) travelling `way` (forward
    / backward / left / right) on foot: no jump or leap in it."""
    col = DIRECTIONS.index(way)
    moving = ms.travel.sum(axis=1) > MOVING
    mask = moving & (ms.travel.argmax(axis=1) == col)
    if within is not None:
        mask[:max(0, within[0])] = False
        mask[max(0, within[1] - 1):] = False
    for s, e in ms.events("jump", None):
        mask[max(0, s - 1):e] = False
    mask = _close(mask, 3)
    best = None
    for s, e in runs(mask):
        if e - s < MIN_TRAVEL_S * 20:
            continue
        got = ms.travelled(s, e + 1)
        total = sum(got.values())
        off = abs((ms.angle(s, e + 1) - AIM[way] + 180.0) % 360.0 - 180.0)
        if got[way] >= TRAVEL_M and got[way] >= TRAVEL_SHARE * total and off <= TRAVEL_DEG and (
                best is None or e - s > best[1] - best[0]):
            best = (s, e + 1)
    return best


def travel_candidates(index: RetrievalIndex, text: str, way: str, frames: int) -> list[Candidate]:
    """View candidates whose span travels `way` (sideways: either side) relative to facing,
    best first; a longer stretch of that travel scores up to 0.1 more (a piece that covers
    more of the segment needs fewer seams)."""
    cheap = profile(index)["across" if way != "backward" else "along"]
    ways = ("left", "right") if way == "sideways" else (way,)
    flips = [(False, False), (False, True)] if way == "backward" else \
        [(False, False), (True, False), (False, True), (True, True)]

    def make(c: Candidate) -> list[Candidate]:
        out = []
        for mirrored, rev in flips:
            view = View(index.clips[c.clip].id, mirrored, rev)
            # A caption's words are about its own frames: the travel must be there.
            within = None if index.win_prompt[c.window] else _grown(
                index.window_span(Candidate(c.clip, c.window, c.score, view)), 10)
            spans = [sp for sp in (travel_span(index.measured(view.ref), w, within)
                                   for w in ways) if sp]
            if spans:
                span = max(spans, key=lambda sp: sp[1] - sp[0])
                bonus = 0.1 * min(1.0, (span[1] - span[0]) / max(frames, 1))
                out.append(Candidate(c.clip, c.window, c.score + bonus, view, span))
        return out
    found = gather(index, text, lambda i: cheap[i] >= TRAVEL_M, make, margin=TRAVEL_MARGIN)
    return sorted(found, key=lambda c: -c.score)


def _grown(span: tuple[int, int], n: int) -> tuple[int, int]:
    return span[0] - n, span[1] + n


def _names(words: str, side: str) -> bool:
    return f" {side} " in f" {words.lower().replace(',', ' ').replace('-', ' ')} "


def side_view(index: RetrievalIndex, cand: Candidate, intent: Intent) -> View | None:
    """The view of a candidate that does its action with the named side: by measurement for
    kicks and punches (its window's events), else by its words (None: neither view does)."""
    assert intent.side is not None
    side, other = intent.side, "right" if intent.side == "left" else "left"
    clip = index.clips[cand.clip]
    s, e = index.window_span(cand)
    if intent.action in ("kick", "punch"):
        ms = index.measured(clip.id)
        inside = lambda spans: [x for x in spans if x[0] < e and x[1] > s]  # noqa: E731
        mine, theirs = inside(ms.events(intent.action, side)), inside(ms.other(intent.action, side))
        if mine and not theirs:
            return View(clip.id)
        if theirs and not mine:
            return View(clip.id, mirrored=True)
        if mine or theirs:
            return None
    words = " ".join([index.win_text[cand.window], clip.prompt, clip.label])
    if _names(words, other) and not _names(words, side):
        return View(clip.id, mirrored=True)
    return View(clip.id)


def side_candidates(index: RetrievalIndex, text: str, intent: Intent) -> list[Candidate]:
    """Candidates in the view that acts with the named side; for kicks and punches only those
    where one is measured, when any is."""
    def make(c: Candidate) -> list[Candidate]:
        view = side_view(index, c, intent)
        return [Candidate(c.clip, c.window, c.score, view)] if view is not None else []
    found = gather(index, text, lambda i: True, make)
    if intent.action in ("kick", "punch"):
        acting = [c for c in found if _acts(index, c, intent)]
        found = acting or found
    return found


def _acts(index: RetrievalIndex, cand: Candidate, intent: Intent) -> bool:
    assert intent.action is not None
    s, e = index.window_span(cand)
    spans = index.measured(index.ref(cand)).events(intent.action, intent.side)
    return any(x[0] < e and x[1] > s for x in spans)
