"""Checking a drawn track against what its segment asks, before the plan keeps it: the track
is stitched on its own (as a first segment would be) and measured with the benchmark's named
checks (`motion/checks/named.py`) that the segment's intent implies: the direction of travel,
the side and number of kicks or punches, the number of jumps, squats or steps, the posture at
the start and the end. Stitching cross-fades pieces and refits them on one performer's bones,
which can blur a jump at a seam or add a step; a draw that fails is replaced by the next
seeded draw (`pick`).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from interplay.generators.retrieval.intent import LOW, Intent
from interplay.generators.retrieval.stitch import Stitcher
from interplay.motion.checks.measures import frame_of
from interplay.motion.checks.named import CHECKS, no_pops

COUNT_CHECKS = {"jump": "jump_count", "squat": "squat_count"}
STOP_M = 1.0       # a stop may take a step or two to come to rest
IN_PLACE_M = 0.6   # on the spot: the benchmark's stays_in_place bound
NO_POPS = {"check": "no_pops"}   # every checked draw must pass it too (see `passed`)


def render(index, track: list[dict], frames: int) -> np.ndarray:
    """One person's frames (frames, 22, 3) of a track stitched alone, its last pose held to
    `frames` when the pieces are shorter."""
    stitcher = Stitcher(1)
    out = [stitcher.add_single(0, piece[0]) for piece in index.pieces(track)]
    done = sum(len(x) for x in out)
    if done < frames:
        out.append(stitcher.hold(0, frames - done))
    return np.concatenate(out)[:frames]


def checks(intent: Intent, start: str | None = None, end: str | None = None,
           first: bool = False) -> list[dict]:
    """The named checks (specs for `run_check`) a segment with this intent should pass;
    `start` / `end` are the postures it must start and end in, where known; the first
    segment of a motion starts standing unless it is asked to start elsewhere."""
    out: list[dict] = []
    if intent.travel is not None:
        direction = "sideways" if intent.travel == "sideways" else intent.travel
        out.append({"check": "travel_direction", "direction": direction, "share": 0.7})
    a, n = intent.action, intent.count
    if a in ("kick", "punch") and (n is not None or intent.side is not None):
        key = "leg" if a == "kick" else "hand"
        out.append({"check": a, key: intent.side or "any",
                    **({"count": n} if n is not None else {"at_least": 1})})
    elif a in COUNT_CHECKS and n is not None:
        out.append({"check": COUNT_CHECKS[a], "count": n})
    elif a == "step" and n is not None:
        out.append({"check": "step_count", "count": n, "tolerance": 0})
    if intent.still or intent.in_place:
        out.append({"check": "stays_in_place", "max_m": STOP_M if intent.still else IN_PLACE_M})
    if intent.turn is not None:
        deg, way = intent.turn
        out.append({"check": "turn", "degrees": deg, "direction": way,
                    "tolerance": 45 if deg <= 180 else 60 if deg <= 360 else 90})
    # ("jog on the spot": the speed of a jog's steps, not of travel; stays_in_place holds it)
    if intent.speed is not None and intent.action is None and end not in LOW and not intent.in_place:
        out.append({"check": "speed_band", "band": intent.speed})
    if start is not None and (start in LOW or end in LOW):
        out.append({"check": "posture_at_start", "posture": start})
    elif first and start in (None, "standing"):
        out.append({"check": "posture_at_start", "posture": "standing"})
    if end is not None:
        out.append({"check": "posture_at_end", "posture": end})
    return out


def passed(joints: np.ndarray, specs: list[dict]) -> int:
    """How many of the checks the joints pass (`NO_POPS`: the plausibility check of a jump
    in the pelvis between frames)."""
    b = frame_of(joints)
    return sum(bool(no_pops(joints, b)[0] if s is NO_POPS else
                    CHECKS[s["check"]].fn(b, **{k: v for k, v in s.items() if k != "check"})[0])
               for s in specs)


def pick(index, draws: Callable[[], list[dict] | None], frames: int, specs: list[dict],
         tries: int = 6) -> list[dict] | None:
    """The first of up to `tries` draws whose stitched frames pass every check, else the
    draw that passed most (the earliest among equals); None when nothing could be drawn."""
    best, best_n = None, -1
    specs = [*specs, NO_POPS] if specs else specs     # a draw that passes pops nowhere
    for _ in range(tries):
        track = draws()
        if track is None:
            break
        if not specs:
            return track
        n = passed(render(index, track, frames), specs)
        if n == len(specs):
            return track
        if n > best_n:
            best, best_n = track, n
    return best
