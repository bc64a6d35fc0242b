"""A slow walk from a capture that walks faster: the captured slow, tired or sneaking walks of
the processed data go 0.9–1.3 m/s, over the benchmark's slow band (≤ 0.9 m/s), so a segment
asked to go slowly whose frames travel faster is played slower — the capture's own frames in
order, resampled in time (positions interpolated, then put back on the performer's bones), the
cadence slowing with the speed. Only a motion's last segment is slowed (the frames it plays
are the segment's first ones, so its end pose changes and nothing follows it to meet).

    joints, rate = slow_down(joints)      # rate 1.0: already slow enough
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.checks import measures as ms
from interplay.motion.kinematics import fit_offsets, fit_to_skeleton, resample

SLOW_MAX_M_S = 0.9        # the benchmark's slow band tops out here …
SLOW_TARGET_M_S = 0.7     # … a slowed walk is aimed here
MIN_RATE = 0.5            # never slower than half speed (slow motion, not a slow walk)
MOVING_M_S = 0.2


def travel_speed(joints: np.ndarray) -> float:
    """Median horizontal pelvis speed (m/s) over the frames that move."""
    v = ms.speed(ms.frame_of(joints))
    moving = v[v > MOVING_M_S]
    return float(np.median(moving)) if len(moving) >= len(v) // 2 else 0.0


def rate_of(joints: np.ndarray) -> float:
    """The rate ≤ 1 `slow_down` plays joints (T, 22, 3) at: 1.0 when already slow enough (also
    read by the exports' leaves, `leaves.py`, which play the captured leaves alike)."""
    j = np.asarray(joints, dtype=np.float64)
    if len(j) < 4:
        return 1.0
    v = travel_speed(j)
    return 1.0 if v <= SLOW_MAX_M_S else max(SLOW_TARGET_M_S / v, MIN_RATE)


def slow_down(joints: np.ndarray) -> tuple[np.ndarray, float]:
    """(joints of the same length played at `rate` ≤ 1, rate): slowed to about
    SLOW_TARGET_M_S when the motion travels faster than SLOW_MAX_M_S."""
    j = np.asarray(joints, dtype=np.float64)
    rate = rate_of(j)
    if rate >= 1.0:
        return j, 1.0
    played = resample(j, sk.FPS * rate, sk.FPS)          # each frame shown 1/rate as long
    out = np.concatenate([played, np.repeat(played[-1:], max(0, len(j) - len(played)), 0)])[:len(j)]
    return fit_to_skeleton(out, fit_offsets(j))[0], round(rate, 3)
