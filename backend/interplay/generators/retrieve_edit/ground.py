"""Put a stitched or generated body on the studio's floor (y = 0) where it carries weight.

Captures float or sink on a level floor for reasons of their own (CMU walks on tilted floors
rise 5–8 cm over a few metres, HDM05 kicks and lie-downs float 6–16 cm, pieces of different
performers meet at different heights), and a stitched motion inherits each piece's error for
seconds. This pass moves every frame vertically by one smooth offset:

- where the feet carry the body (standing, walking, squatting; not in a ballistic flight,
  `measures.feet_carry` and `measures.in_flight`), the offset puts the lower foot's surface
  on the floor (`measures.clearance` over the foot joints);
- where the body rests on the floor instead (lying, sitting), the lowest body surface;
- through flights and everything else, the offset is interpolated between its neighbours, so
  a jump keeps its height over its take-off and landing.

The offset is smoothed over SMOOTH_S and then kept within the bounds that matter: a carrying
foot within FLOAT_M of the floor and no joint's surface more than SINK_M under it.
Shapes: joints (T, 22, 3) metres, Y up, 20 fps.
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.checks import measures as m
from interplay.motion.signals import smooth

SMOOTH_S = 0.4      # the offset's moving average (a gait cycle's foot heights vary ±2 cm)
FLOAT_M = 0.03      # a carrying foot may stay this far up after the pass …
SINK_M = 0.02       # … and the body this far into the floor


def floor_offset(joints: np.ndarray) -> np.ndarray:
    """The vertical offset (T,) to subtract from every joint's height."""
    j = np.asarray(joints, dtype=np.float64)
    b = m.frame_of(j)
    feet = m.clearance(j, sk.FOOT_JOINTS)
    body = m.clearance(j)
    carry = m.feet_carry(b)
    flight = m.in_flight(b)
    ref = np.where(carry, feet, body)
    known = ~flight
    if not known.any():
        return np.zeros(len(j))
    t = np.arange(len(j))
    offset = np.interp(t, t[known], ref[known])
    offset = smooth(offset, max(1, int(round(SMOOTH_S * sk.FPS))))
    bound = carry & ~flight
    offset = np.where(bound, np.maximum(offset, feet - FLOAT_M), offset)
    return np.minimum(offset, body + SINK_M)


def on_floor(joints: np.ndarray) -> np.ndarray:
    """Joints (T ≥ 2, 22, 3) moved vertically onto the floor (a new array)."""
    j = np.asarray(joints, dtype=np.float64)
    if len(j) < 2:
        return j.copy()
    out = j.copy()
    out[..., 1] -= floor_offset(j)[:, None]
    return out
