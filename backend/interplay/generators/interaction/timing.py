"""When things happen in a composed scene: each touch is a beat, approach → reach → hold →
release, laid out in the frames the request has. numpy only.

Durations (seconds, drawn per seed from these ranges) are the composer's (`pair.compose`:
handshake hold 1.2–1.8 s, ramps 0.6–0.8 s …), lengthened where the benchmark's bounds need
room (a handshake holds ≥ 1 s, a hug ≥ 1 s) and squeezed in proportion when the request is
too short for them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.motion.ik import window_weights
from interplay.motion.skeleton import FPS

# kind: (lead before the reach, ramp in, hold, ramp out), each (low, high) seconds.
BEATS: dict[str, tuple[tuple[float, float], ...]] = {
    "handshake": ((0.4, 0.9), (0.6, 0.8), (1.6, 2.4), (0.6, 0.8)),
    "high_five": ((0.4, 1.0), (0.45, 0.6), (0.1, 0.2), (0.5, 0.7)),
    "hug": ((0.3, 0.7), (0.8, 1.0), (1.8, 2.6), (0.8, 1.0)),
    "push": ((0.5, 1.0), (0.35, 0.5), (0.2, 0.3), (0.4, 0.5)),
}
PUMP_HZ = (1.6, 2.2)         # a handshake's up-and-down …
PUMP_M = (0.025, 0.04)
PUMP_S = (1.1, 1.6)          # … for the first second or so of the grip


@dataclass(frozen=True)
class Beat:
    """A touch: full weight on [start, end), easing in over `ramp_in` frames before and out
    over `ramp_out` after."""
    start: int
    end: int
    ramp_in: int
    ramp_out: int

    def weights(self, frames: int) -> np.ndarray:
        return window_weights(frames, self.start, self.end, self.ramp_in, self.ramp_out)

    @property
    def reach_start(self) -> int:
        return self.start - self.ramp_in

    @property
    def release_end(self) -> int:
        return self.end + self.ramp_out

    def to_json(self) -> dict:
        return {"reach": self.reach_start, "contact": [self.start, self.end],
                "release_end": self.release_end, "seconds": round((self.end - self.start) / FPS, 2)}


def _draw(rng, lo_hi: tuple[float, float]) -> float:
    return float(rng.uniform(*lo_hi))


def beat(rng, kind: str, begin: int, frames: int, tail: float = 0.3) -> Beat:
    """The kind's beat starting after frame `begin` (the end of an approach, or 0), fitted
    in [begin, frames − tail s): its phases are squeezed in proportion when they do not fit."""
    lead, ramp_in, hold, ramp_out = (_draw(rng, r) * FPS for r in BEATS[kind])
    room = frames - int(round(tail * FPS)) - begin
    total = lead + ramp_in + hold + ramp_out
    if total > room:
        s = max(room, 8) / total
        lead, ramp_in, hold, ramp_out = lead * s, ramp_in * s, hold * s, ramp_out * s
    r_in, r_out = max(2, int(round(ramp_in))), max(2, int(round(ramp_out)))
    start = begin + int(round(lead)) + r_in
    end = min(start + max(1, int(round(hold))), frames - r_out - 1)
    if end <= start:
        raise ValueError(f"{frames} frames are too few for a {kind}")
    return Beat(start, end, r_in, r_out)


def pump(rng, frames: int, start: int) -> np.ndarray:
    """A handshake's vertical motion (T,) metres: a sine from the grip on, fading out after
    a second or so (the hands stay joined, still)."""
    t = (np.arange(frames) - start) / FPS
    fade = window_weights(frames, start, min(frames, start + int(_draw(rng, PUMP_S) * FPS)), 0, 6)
    return _draw(rng, PUMP_M) * np.sin(2 * np.pi * _draw(rng, PUMP_HZ) * t) * fade


def frames_of(seconds: float) -> int:
    return int(round(seconds * FPS))
