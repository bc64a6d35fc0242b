"""How long each segment lasts: what its action needs, fitted to the requested total, then
whole frames at 20 fps that sum exactly to it.

    need(VERBS["jump"])                    → Need(want=2.0, least=1.2, elastic=False)
    need(VERBS["walk"], line of 5 m)       → Need(want=3.85, least=2.0, elastic=False)   5 m at 1.3 m/s
    need(VERBS["walk"])                    → Need(want=4.0, least=2.0, elastic=True)     a free walk
    fit([walk, jump], total=160)           → frames [120, 40]: the free walk takes the spare time

Each action has a time it typically takes (`want`), a shortest time in which it still reads as
done (`least`: a sprint needs to reach speed, a jump its take-off, flight and landing, each
repetition of a count its own), and whether it can fill spare time (`elastic`: a free walk,
a wave, a dance, a held pose — not a jump, a sit-down or a walk of a set distance). Fitting:
  total ≥ Σ want   every action its want; the spare goes to the elastic ones (to all, in
                   proportion, when none is)
  Σ least ≤ total  every action its least, plus a share of the rest in proportion to
                   (want − least)
  total < Σ least  in proportion to least (the caller folds steps that do not fit at all)
Proportional scaling alone gave a sprint 1.4 s of an 8 s clip next to a long free walk.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.catalogue import grammar as g
from interplay.catalogue.words import lists, tokens, words
from interplay.motion.skeleton import FPS
from interplay.planner.schema import TrajectorySpec
from interplay.planner.trajectory_text import path_length
from interplay.planner.verbs import Verb, lookup

MIN_SECONDS, MAX_SEGMENT = 0.5, 15.0      # one segment: ≥ half a second, ≤ 15 s
_MANNER = [("slow_words", 1.4), ("fast_words", 0.75)]        # (words.toml's list, time factor)
# Seconds one performance needs at least (per repetition): take-off to landing, down and up,
# speed reached and held for a few strides. Verbs not listed: 60 % of their typical time.
LEAST = {"sprint": 2.5, "run": 2.0, "jog": 2.0, "walk": 2.0, "march": 2.0, "stroll": 2.0,
         "step": 0.8, "hop": 0.8, "skip": 1.5, "crawl": 2.0, "moonwalk": 2.0, "jump": 1.2,
         "leap": 1.2, "squat": 1.5, "sit": 1.8, "stand": 1.5, "rise": 1.5, "lie": 2.0,
         "kneel": 1.5, "crouch": 1.2, "fall": 1.2, "stumble": 1.2, "stagger": 1.2, "wave": 1.5,
         "kick": 1.0, "punch": 0.6, "clap": 0.6, "bow": 1.5, "spin": 1.2, "turn": 1.2,
         "stop": 1.5, "push": 1.0, "pull": 1.0, "hug": 2.0, "dance": 2.0, "cartwheel": 1.5}
# Actions that can go on for longer than they need (the spare time of a clip is theirs):
# words.toml's `elastic_verbs`.
# A partner turned under a raised arm (a couple's spin): captured salsa followers take
# 1.5–2.5 s for one, more than a spin on one's own
PARTNER_SPIN_S = 2.5
_SPEED_BACK = 0.7     # a backwards or sideways gait covers ground at ~70 % of its forward speed
STRIDE_S = 0.6        # seconds a walking step takes, and 0.5 s to start and stop
_COUNTS = {"a few": 3, "few": 3, "several": 4, "a couple of": 2, "one": 1, "two": 2, "three": 3,
           "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8, "nine": 9, "ten": 10}


def _count(word: str) -> int:
    word = " ".join(word.split())                  # "a  couple of": a count's words
    return int(word) if word.isdigit() else _COUNTS[word]


@dataclass(frozen=True)
class Need:
    want: float        # seconds it typically takes
    least: float       # seconds it needs at least (≤ want)
    elastic: bool      # may take spare time


def estimate(verb: Verb | None, trajectory: TrajectorySpec | None = None, repeat: int = 1,
             text: str = "", metres: float | None = None, sideways: bool = False) -> float:
    """Seconds one segment typically takes: the verb's typical duration, a travel's path
    length (or the `metres` a dropped straight path stated) over its speed, times the repeat
    count, slower or faster by its adverbs."""
    steps = g.DURATION_STEPS.search(text)
    if verb is None:
        seconds = 2.0
    elif verb.kind == "travel" and steps and trajectory is None and not metres:
        seconds = 0.5 + STRIDE_S * _count(steps.group(1))      # "walks a few steps": 3 strides
    elif verb.kind == "travel":
        length = metres or (path_length(trajectory) if trajectory is not None else None)
        speed = (verb.speed or 1.0) * (_SPEED_BACK if sideways else 1.0)
        seconds = length / speed if length else verb.seconds
    else:
        seconds = verb.seconds
    for said, factor in _MANNER:
        if words(said).search(text):
            seconds *= factor
    if repeat > 1 and not _counted_by_path(verb, trajectory):
        seconds *= repeat
    return float(np.clip(seconds, MIN_SECONDS, MAX_SEGMENT))


def _counted_by_path(verb: Verb | None, trajectory: TrajectorySpec | None) -> bool:
    """Travel repeats ("walks in a circle twice") are already in the path length via turns."""
    return verb is not None and verb.kind == "travel" and trajectory is not None


def need(verb: Verb | None, trajectory: TrajectorySpec | None = None, repeat: int = 1,
         text: str = "", metres: float | None = None, sideways: bool = False,
         hold: bool = False) -> Need:
    """What one segment needs; `hold`: it keeps a pose (or posture) until it ends."""
    want = estimate(verb, trajectory, repeat, text, metres, sideways)
    if words("under_arm").search(text):
        want = max(want, PARTNER_SPIN_S + 0.5)
        return Need(want, PARTNER_SPIN_S, hold)
    if verb is None:
        return Need(want, min(want, 1.0), hold)
    bounded = verb.kind == "travel" and bool(trajectory is not None or metres or repeat > 1
                                             or g.DURATION_STEPS.search(text))
    if bounded:                  # a set distance or count: covered faster, at most twice as fast
        least = max(LEAST.get(verb.base, 0.0), 0.5 * want)
    else:
        per = LEAST.get(verb.base, 0.6 * verb.seconds)
        reps = 1 if _counted_by_path(verb, trajectory) else repeat
        least = min(want, per * reps)
    transition = verb.base == "stand" and any(w.text == "up" for w in tokens(text))      # "stands up" ends
    elastic = hold or (verb.kind == "travel" and not bounded) or (verb.base in lists()["elastic_verbs"]
                                                                  and not transition)
    return Need(want, max(MIN_SECONDS, min(least, want)), elastic)


def need_of_text(text: str, seconds: float, repeat: int = 1) -> Need:
    """An LLM step: its own `seconds` as the want, the least and elasticity of its first
    motion verb."""
    verb = next((h[0] for w in text.split() if (h := lookup(w)) and h[0].kind != "light"), None)
    base = need(verb, None, repeat, text)
    return Need(seconds, min(seconds, base.least), base.elastic)


def fit(needs: list[Need], total: int) -> list[int]:
    """Frames per segment (summing to `total`) as the module docstring says."""
    if not needs:
        raise ValueError(f"cannot share {total} frames among 0 segments")
    want = np.array([n.want for n in needs])
    least = np.array([n.least for n in needs])
    elastic = np.array([n.elastic for n in needs])
    seconds = total / FPS
    if seconds >= want.sum():
        grow = elastic if elastic.any() else np.ones(len(needs), bool)
        spare = seconds - want.sum()
        weights = want + np.where(grow, want / want[grow].sum() * spare, 0.0)
    elif seconds >= least.sum():
        room = want - least
        weights = least + (room / room.sum() * (seconds - least.sum()) if room.sum() > 0 else 0)
    else:
        weights = least
    return allocate(list(weights), total)


def allocate(seconds: list[float], total: int, minimum: int = round(MIN_SECONDS * FPS)) -> list[int]:
    """Frames per segment in proportion to `seconds`, each ≥ `minimum` when the total allows,
    summing exactly to `total` (largest remainders get the frames left after rounding down)."""
    n = len(seconds)
    if n == 0 or total < 1:
        raise ValueError(f"cannot share {total} frames among {n} segments")
    floor = min(minimum, total // n)
    w = np.asarray(seconds, dtype=np.float64)
    w = w if w.sum() > 0 else np.ones(n)
    exact = total * w / w.sum()
    frames = np.maximum(np.floor(exact).astype(int), floor)
    order = np.argsort(-(exact - np.floor(exact)), kind="stable")
    while frames.sum() < total:                    # hand out the rounding remainder
        frames[order[0]] += 1
        order = np.roll(order, -1)
    while frames.sum() > total:                    # the floor pushed some up: take from the longest
        frames[np.argmax(np.where(frames > floor, frames - exact, -np.inf))] -= 1
    return frames.tolist()


def fits(total: int, minimum: int = round(MIN_SECONDS * FPS)) -> int:
    """How many segments of at least `minimum` frames fit in `total` frames (≥ 1)."""
    return max(1, total // minimum)
