"""Timing of counted primitives: N cycles laid evenly over a segment's frames, with still
borders, each cycle a smooth bump (0 at its ends, 1 at its middle, optionally held there), so
that counts are exact by construction and every primitive eases in and out.

Shapes: (T,) float arrays over a segment of T frames at 20 fps.
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.ik import ease

BORDER_S = 0.5        # eased time at each end of a segment before the first and after the last cycle


def border(t: int) -> int:
    """Frames kept still at each end of a T-frame segment (less on short ones)."""
    return min(int(round(BORDER_S * sk.FPS)), max(0, t // 10))


def phase(t: int, n: int) -> tuple[np.ndarray, np.ndarray]:
    """(cycle index (T,) int with −1 outside the cycles, phase in the cycle (T,) in [0, 1))."""
    if n < 1:
        raise ValueError(f"a count must be at least 1, got {n}")
    b = border(t)
    span = t - 2 * b
    if span < 2 * n:
        raise ValueError(f"{n} cycles do not fit in {t} frames")
    x = (np.arange(t) - b + 0.5) / span * n           # cycles elapsed at each frame's centre
    inside = (x >= 0) & (x < n)
    cycle = np.where(inside, np.floor(x), -1).astype(int)
    return cycle, np.where(inside, x - np.floor(x), 0.0)


def bumps(t: int, n: int, hold: float = 0.0) -> np.ndarray:
    """(T,) in [0, 1]: N smooth bumps, each rising over its cycle's first half and falling
    over its second, held at 1 over the middle `hold` fraction of the cycle."""
    cycle, ph = phase(t, n)
    rise = (1.0 - hold) / 2.0
    up = ease(ph / max(rise, 1e-9))
    down = ease((1.0 - ph) / max(rise, 1e-9))
    return np.where(cycle >= 0, np.minimum(up, down), 0.0)


def peaks(t: int, n: int) -> np.ndarray:
    """The middle frame of each of N cycles (N,) int."""
    b = border(t)
    span = t - 2 * b
    return (b + (np.arange(n) + 0.5) * span / n).astype(int)


def envelope(t: int) -> np.ndarray:
    """(T,) easing from 0 at the first frame to 1 where the cycles start, and back to 0 at
    the last frame from where they end: the weight that takes a part from the base into the
    primitive (and out) inside the borders, so every cycle runs at full weight."""
    b = max(1, border(t))
    idx = np.arange(t, dtype=np.float64)
    return np.minimum(ease(idx / b), ease((t - 1 - idx) / b))


def seconds_for(n: int, per_cycle_s: float) -> float:
    """A segment long enough for N cycles of `per_cycle_s` and its borders."""
    return n * per_cycle_s + 2 * BORDER_S
