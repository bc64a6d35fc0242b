"""Small 1-D signal tools over frames (axis 0): moving averages, runs of True, turning points.
numpy only; used by the pose codes."""

from __future__ import annotations

import numpy as np


def smooth(x: np.ndarray, n: int) -> np.ndarray:
    """Centred moving average of x (T, ...) over n frames along axis 0. Near the ends the
    window shrinks to the frames that exist (so a constant stays constant and a rate is not
    diluted by frames outside the clip); n ≤ 1 returns a float copy."""
    x = np.asarray(x, dtype=np.float64)
    t = x.shape[0]
    if n <= 1 or t == 0:
        return x.copy()
    cs = np.concatenate([np.zeros((1,) + x.shape[1:]), np.cumsum(x, axis=0)])
    idx = np.arange(t)
    lo = np.maximum(idx - n // 2, 0)
    hi = np.minimum(idx + n - n // 2, t)
    count = (hi - lo).reshape((-1,) + (1,) * (x.ndim - 1))
    return (cs[hi] - cs[lo]) / count


def window_percentile(x: np.ndarray, n: int, q: float) -> np.ndarray:
    """q-th percentile (T,) of x (T,) over a centred window of n frames (shrinking at the
    ends, where the missing frames are ignored)."""
    x = np.asarray(x, dtype=np.float64)
    if n <= 1 or x.shape[0] == 0:
        return x.copy()
    before, after = n // 2, n - 1 - n // 2
    padded = np.concatenate([np.full(before, np.nan), x, np.full(after, np.nan)])
    return np.nanpercentile(np.lib.stride_tricks.sliding_window_view(padded, n), q, axis=1)


def fill_gaps(mask: np.ndarray) -> np.ndarray:
    """A boolean array (T,) with single-frame False gaps between two True frames set True."""
    m = np.asarray(mask, bool).copy()
    m[1:-1] |= m[:-2] & m[2:]
    return m


def window_fraction(mask: np.ndarray, n: int) -> np.ndarray:
    """Fraction (T,) of frames that are True in a centred window of n frames."""
    return smooth(np.asarray(mask, dtype=np.float64), n)


def runs(mask: np.ndarray) -> list[tuple[int, int]]:
    """Runs of True in a boolean array (T,) as (start, end) pairs, end exclusive."""
    m = np.concatenate([[False], np.asarray(mask, bool), [False]])
    edges = np.flatnonzero(m[1:] != m[:-1])
    return list(zip(edges[::2].tolist(), edges[1::2].tolist()))


def zigzag(x: np.ndarray, amplitude: float) -> np.ndarray:
    """Frames of the turning points of x (T,): extremes from which the signal then moves back by
    at least `amplitude` (hysteresis, so noise smaller than that never makes a turn). The first
    extreme counts once the first swing of that size is seen. A loop over frames: each step
    depends on the last confirmed extreme."""
    x = np.asarray(x, dtype=np.float64)
    turns: list[int] = []
    lo = hi = ext = 0
    direction = 0  # +1 rising, -1 falling, 0 not yet known
    for i in range(1, x.shape[0]):
        v = x[i]
        if direction == 0:
            hi = i if v > x[hi] else hi
            lo = i if v < x[lo] else lo
            if x[hi] - x[lo] >= amplitude:
                direction, ext = (1, hi) if hi > lo else (-1, lo)
                turns.append(lo if hi > lo else hi)
        elif direction * (v - x[ext]) > 0:
            ext = i
        elif direction * (x[ext] - v) >= amplitude:
            turns.append(ext)
            direction, ext = -direction, i
    return np.array(turns, dtype=int)
