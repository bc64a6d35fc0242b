"""What each capture does, measured with the benchmark's own measures
(`motion/checks/measures.py`), once per clip and kept: per frame its direction of travel
relative to where the body faces, its postures, and the spans of its countable actions per
side (jumps, squats, kicks, punches, steps). Retrieval reads them to choose views and
windows: a window that travels backwards, one with exactly two right kicks, the frame a
sit-down is complete.

A view's measures follow from its capture's (`views.py`): mirroring swaps left and right
(travel to the left becomes travel to the right, a left kick a right one); reversing time
reverses the frames and turns forward travel into backward travel and left into right
(a reversed jump or step is still one; a reversed kick or punch is not used: its wind-up
comes after it).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.generators.retrieval.views import View
from interplay.motion import skeleton as sk
from interplay.motion.checks import measures as m
from interplay.motion.signals import fill_gaps, runs

DIRECTIONS = ("forward", "backward", "left", "right")
SIDES = ("left", "right")
POSTURE_KEYS = ("standing", "sitting", "lying", "kneeling")
# Frames around an action's measured frame that belong to it (its wind-up and follow-through),
# so a window never cuts one in half: a kick's leg swings up ~0.4 s before its peak, a punch's
# drive starts ~0.2 s before it lands, a jump crouches ~0.3 s before take-off.
AROUND = {"kick": (8, 6), "punch": (4, 4), "jump": (6, 4), "squat": (2, 2), "step": (2, 2)}


@dataclass(frozen=True)
class Measures:
    frames: int
    travel: np.ndarray                      # (T-1, 4) metres of each pelvis step, by DIRECTIONS
    heading: np.ndarray                     # (T-1, 2) each step ahead of and to the left of facing
    postures: dict[str, np.ndarray]         # POSTURE_KEYS → (T,) bool
    actions: dict[str, dict[str, list[tuple[int, int]]]]   # action → side or "any" → [(s, e)]

    def travelled(self, s: int, e: int) -> dict[str, float]:
        """Metres travelled each way over frames [s, e)."""
        got = self.travel[max(0, s):max(0, e - 1)].sum(axis=0)
        return dict(zip(DIRECTIONS, (float(v) for v in got)))

    def angle(self, s: int, e: int) -> float:
        """Degrees between facing and the way frames [s, e) travel overall (0 ahead, 90 to
        the left, -90 to the right, ±180 back)."""
        ahead, side = self.heading[max(0, s):max(0, e - 1)].sum(axis=0)
        return float(np.degrees(np.arctan2(side, ahead)))

    def events(self, action: str, side: str | None) -> list[tuple[int, int]]:
        """Spans of an action: of that side, or of either side (side None)."""
        by = self.actions.get(action, {})
        if side is None:
            return sorted(e for k in by for e in by[k])
        return sorted(by.get(side, []) + by.get("any", []))

    def other(self, action: str, side: str | None) -> list[tuple[int, int]]:
        """Spans of the action with the other side (none when no side is asked)."""
        if side is None:
            return []
        return sorted(self.actions.get(action, {}).get("right" if side == "left" else "left", []))


def _travel_steps(b) -> tuple[np.ndarray, np.ndarray]:
    """Per pelvis step the metres forward / backward / left / right of facing (measures.travel
    per frame), and its (ahead, left) components."""
    p = m.path(b)
    step = np.diff(p, axis=0)
    fwd = (b.forward[1:] + b.forward[:-1])[:, [0, 2]]
    left = (b.left[1:] + b.left[:-1])[:, [0, 2]]
    ahead = (step * fwd).sum(1) / np.maximum(np.linalg.norm(fwd, axis=1), 1e-9)
    side = (step * left).sum(1) / np.maximum(np.linalg.norm(left, axis=1), 1e-9)
    ang = np.degrees(np.arctan2(side, ahead))
    dist = np.linalg.norm(step, axis=1)
    classes = [np.abs(ang) <= 45, np.abs(ang) >= 135, (ang > 45) & (ang < 135),
               (ang < -45) & (ang > -135)]
    return np.stack([np.where(c, dist, 0.0) for c in classes], axis=1), np.stack([ahead, side], axis=1)


def _steps(b, side: str) -> list[tuple[int, int]]:
    """Steps of one foot as (lift-off, landing) frames (measures.steps' rule)."""
    toe = b.joints[:, sk.JOINT_INDEX[f"{side}_foot"]][:, [0, 2]]
    stances = runs(fill_gaps(b.foot_height(side) < m.AIRBORNE_M))
    return [(e0, s1) for (_, e0), (s1, _) in zip(stances[:-1], stances[1:])
            if np.linalg.norm(toe[s1] - toe[e0 - 1]) >= 0.15]


def _around(action: str, spans: list[tuple[int, int]], total: int) -> list[tuple[int, int]]:
    before, after = AROUND[action]
    return [(max(0, s - before), min(total, e + after)) for s, e in spans]


def measure(joints: np.ndarray) -> Measures:
    """The measures of one person's capture (T, 22, 3); a capture under 4 frames does nothing
    measurable."""
    total = len(joints)
    if total < 4:
        return Measures(total, np.zeros((max(total - 1, 0), 4)), np.zeros((max(total - 1, 0), 2)),
                        {k: np.zeros(total, bool) for k in POSTURE_KEYS}, {})
    b = m.frame_of(np.asarray(joints, dtype=np.float64))
    postures = {k: fill_gaps(m.POSTURES[k](b)) for k in POSTURE_KEYS}
    raw: dict[str, dict[str, list[tuple[int, int]]]] = {
        "jump": {"any": m.jumps(b)},
        "squat": {"any": [(s, e) for s, _, e in m.squats(b)]},
        "kick": {s: [(f, f + 1) for f, _ in m.kicks(b, s)] for s in SIDES},
        "punch": {s: [(f, f + 1) for f in m.punches(b, s)] for s in SIDES},
        "step": {s: _steps(b, s) for s in SIDES},
    }
    actions = {a: {k: _around(a, v, total) for k, v in by.items()} for a, by in raw.items()}
    return Measures(total, *_travel_steps(b), postures, actions)


_SWAP = {"left": "right", "right": "left", "any": "any"}


def of_view(ms: Measures, view: View) -> Measures:
    """The measures of a view of the capture measured as `ms`."""
    travel, heading, postures, actions = ms.travel, ms.heading, ms.postures, ms.actions
    total = ms.frames
    if view.mirrored:
        travel, heading = travel[:, [0, 1, 3, 2]], heading * [1.0, -1.0]
        actions = {a: {_SWAP[k]: v for k, v in by.items()} for a, by in actions.items()}
    if view.reversed:
        travel, heading = travel[::-1][:, [1, 0, 3, 2]], -heading[::-1]
        postures = {k: v[::-1] for k, v in postures.items()}
        actions = {a: {k: sorted(view.span(s, e, total) for s, e in v) for k, v in by.items()}
                   for a, by in actions.items() if a not in ("kick", "punch")}
    return Measures(total, np.ascontiguousarray(travel), np.ascontiguousarray(heading),
                    postures, actions)


class Measurer:
    """Measures per capture (person 0, as a single-person request plays it), computed when
    first asked for and kept."""

    def __init__(self, people_of):
        self._people_of = people_of       # clip id → list of (T, 22, 3) arrays
        self._cache: dict[str, Measures] = {}

    def __call__(self, view: View) -> Measures:
        if view.clip not in self._cache:
            self._cache[view.clip] = measure(self._people_of(view.clip)[0])
        ms = self._cache[view.clip]
        return ms if view.plain else of_view(ms, view)
