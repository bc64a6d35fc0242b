"""Two people's penetration resolution as the reviewer runs it (`motion.pair.resolve`), and
how its report is told."""

from __future__ import annotations

import numpy as np

from interplay.motion.pair.resolve import resolve_pair
from interplay.planner.schema import Segment
from interplay.review.checks import contact_mode


def resolve_people(seg: Segment, people: list[np.ndarray],
                   free_ends: tuple[bool, bool] = (True, True)) -> tuple[list[np.ndarray], dict]:
    """Two people with their penetration resolved under the contact `seg`'s text asks for
    (`motion.pair.resolve.resolve_pair`; unchanged within the bound), and the report."""
    a, b, report = resolve_pair(people[0], people[1], contact_mode(seg.prompt), *free_ends)
    return [a, b], report


def resolution_words(report: dict) -> str:
    """What a resolution did, for a correction's reason."""
    b, a = report["before"], report["after"]
    return (f"moved apart by up to {report['moved_m']:.2f} m, {report['arm_frames']} arm frames "
            f"re-solved, {report['frames']} frames changed: IF {b['if']:.2f} → {a['if']:.2f}, "
            f"any overlap {b['if_any']:.2f} → {a['if_any']:.2f}, depth {b['depth_cm']:.1f} → "
            f"{a['depth_cm']:.1f} cm" + ("" if a["ok"] else f" (still over the bound: {a['bound']})"))


def better(before: dict, after: dict) -> bool:
    """The penetration bound is met after, or none of its measures got worse and one fell."""
    keys = ("if", "if_any", "depth_cm")
    return after["ok"] or (all(after[k] <= before[k] for k in keys)
                           and any(after[k] < before[k] for k in keys))
