"""The job pipeline's two-person pass: penetration resolution (`motion.pair.resolve`, issue 15)
on every two-person output, whichever generator made it.

- `resolve_segment`: each two-person segment as soon as its frames are in, before its review
  (so the reviewer judges, and the studio shows, the resolved pair), under the contact the
  segment's text asks for (`review.checks.contact_mode`). A segment's edges stay as generated
  where it meets another segment (`free_start` / `free_end` False: the change eases to zero
  there), so segments still join without a jump.
- `resolve_motion`: once more after the trajectories (which move each person on their own path)
  on every segment that is then over the bound.

A pair within the bound is left exactly as it is. What a pass did goes into the plan's
`reasons` ("pair resolution, segment i: …") and, in full, into the job's review under
`pair_resolution` (`report_entry`): per segment the stage, the contact, the bounds before and
after, how far the bodies were moved apart (m), how many frames changed and how many arm
frames were re-solved, and the time it took.
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from interplay.generators.plan import GenerationPlan, GenerationSegment
from interplay.motion.pair.resolve import resolve_pair
from interplay.review.checks import contact_mode
from interplay.review.reviewer import resolution_words

OnFrames = Callable[[int, list[np.ndarray]], None]
CHUNK = 40


def _resolve(people: np.ndarray, plan: GenerationPlan, seg: GenerationSegment) -> dict:
    """Resolve `seg`'s frames of people (2, T, 22, 3) in place; the resolution's report."""
    a, b = seg.start, seg.end
    last = seg.index == len(plan.segments) - 1
    ra, rb, report = resolve_pair(people[0, a:b], people[1, a:b], contact_mode(seg.prompt),
                                  free_start=seg.index == 0, free_end=last)
    if report["applied"]:
        people[0, a:b], people[1, a:b] = ra, rb
    return report


def report_entry(seg: GenerationSegment, stage: str, report: dict) -> dict:
    return {"segment": seg.index, "stage": stage, **report}


def _note(plan: GenerationPlan, entry: dict) -> None:
    plan.reasons.append(f"pair resolution, segment {entry['segment']} ({entry['stage']}): "
                        + resolution_words(entry))


def _send(people: np.ndarray, a: int, b: int, on_frames: OnFrames) -> None:
    for s in range(a, b, CHUNK):
        on_frames(s, [p[s:min(b, s + CHUNK)] for p in people])


def resolve_segment(people: np.ndarray, plan: GenerationPlan, seg: GenerationSegment,
                    on_frames: OnFrames) -> dict | None:
    """The pass on one finished segment of people (2, T, 22, 3), in place; changed frames are
    sent again. The entry for the job's `pair_resolution` when it acted, else None."""
    if people.shape[0] != 2 or seg.end - seg.start < 2:
        return None
    report = _resolve(people, plan, seg)
    if not report["applied"]:
        return None
    _send(people, seg.start, seg.end, on_frames)
    entry = report_entry(seg, "segment", report)
    _note(plan, entry)
    return entry


def resolve_motion(people: np.ndarray, plan: GenerationPlan, on_frames: OnFrames) -> list[dict]:
    """The pass on every segment of the finished motion (after the trajectories) that is over
    the bound, in place; its entries."""
    out: list[dict] = []
    if people.shape[0] != 2:
        return out
    for seg in plan.segments:
        if seg.end - seg.start < 2 or seg.end > people.shape[1]:
            continue
        report = _resolve(people, plan, seg)
        if report["applied"]:
            _send(people, seg.start, seg.end, on_frames)
            entry = report_entry(seg, "motion", report)
            _note(plan, entry)
            out.append(entry)
    return out
