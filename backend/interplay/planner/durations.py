"""How long each segment lasts: an estimate from its verb (and path), scaled to the requested
total, then whole frames at 20 fps that sum exactly to it.

    estimate(VERBS["jump"])                          → 1.5 s
    estimate(VERBS["walk"], line of 5 m)             → 3.85 s (5 m at 1.3 m/s)
    allocate([1.5, 3.85], total=120)                 → [34, 86] frames
"""

from __future__ import annotations

import re

import numpy as np

from interplay.motion.skeleton import FPS
from interplay.planner.schema import TrajectorySpec
from interplay.planner.trajectory_text import path_length
from interplay.planner.verbs import Verb

MIN_SECONDS, MAX_SEGMENT = 0.5, 15.0      # one segment: ≥ half a second, ≤ 15 s
_MANNER = [(r"\b(?:slowly|slow|calmly|gently|carefully|leisurely)\b", 1.4),
           (r"\b(?:quickly|fast|rapidly|briskly|hurriedly|swiftly)\b", 0.75)]


def estimate(verb: Verb | None, trajectory: TrajectorySpec | None = None, repeat: int = 1,
             text: str = "") -> float:
    """Seconds one segment takes: the verb's typical duration, a travel's path length over its
    speed, times the repeat count, slower or faster by its adverbs."""
    if verb is None:
        seconds = 2.0
    elif verb.kind == "travel":
        length = path_length(trajectory) if trajectory is not None else None
        seconds = length / verb.speed if length and verb.speed else verb.seconds
    else:
        seconds = verb.seconds
    for rx, factor in _MANNER:
        if re.search(rx, text):
            seconds *= factor
    # Travel repeats ("walks in a circle twice") are already in the path length via turns.
    if repeat > 1 and not (verb is not None and verb.kind == "travel" and trajectory is not None):
        seconds *= repeat
    return float(np.clip(seconds, MIN_SECONDS, MAX_SEGMENT))


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
