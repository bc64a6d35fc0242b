"""Contact windows measured on real two-person captures, for the data card and the pair
evaluator's data: when a hand of one person touches the other person's body (sphere body of
`interplay.motion.pair.body`, gap within `TOUCH_GAP`), for at least `MIN_FRAMES` frames.

Measured, not annotated: a window is a run of frames where the gap is within the bound (short
gaps inside a touch, up to `BRIDGE` frames, are bridged), named by whose hand touches and
which of the other's body parts is nearest."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.clip import Clip
from interplay.motion.pair.body import HAND_SPHERES, SPHERE_CHILD, body_spheres, surface_gaps
from interplay.motion.skeleton import FPS

TOUCH_GAP = 0.03     # metres between sphere surfaces: a touch
MIN_FRAMES = 3       # 0.15 s at 20 fps
BRIDGE = 2           # frames of lost contact inside a touch that are bridged


@dataclass(frozen=True)
class ContactWindow:
    start: int        # first frame (20 fps)
    end: int          # one past the last frame
    person: int       # whose hand (0 or 1)
    hand: str         # "left" | "right"
    part: str         # the other person's nearest body part (sk.PART_NAMES)
    min_gap: float    # smallest gap in the window, metres (negative: the hand sinks in)

    @property
    def seconds(self) -> float:
        return (self.end - self.start) / FPS


def _runs(mask: np.ndarray, bridge: int, min_frames: int) -> list[tuple[int, int]]:
    runs: list[list[int]] = []
    for t in np.flatnonzero(mask):
        if runs and t - runs[-1][1] <= bridge:
            runs[-1][1] = int(t) + 1
        else:
            runs.append([int(t), int(t) + 1])
    return [(a, b) for a, b in runs if b - a >= min_frames]


def contact_windows(a: np.ndarray, b: np.ndarray, touch_gap: float = TOUCH_GAP,
                    min_frames: int = MIN_FRAMES, bridge: int = BRIDGE) -> list[ContactWindow]:
    """Hand-to-body contact windows of two people's joints (T, 22, 3), both directions."""
    out = []
    for person, (me, other) in enumerate(((a, b), (b, a))):
        mine, theirs = body_spheres(me), body_spheres(other)
        for hand, joint in (("left", sk.LEFT_HAND), ("right", sk.RIGHT_HAND)):
            s = HAND_SPHERES[SPHERE_CHILD[HAND_SPHERES] == joint]
            gaps = surface_gaps(mine._replace(centres=mine.centres[:, s], radii=mine.radii[s],
                                              part=mine.part[s], joint=mine.joint[s]), theirs).min(axis=1)
            best = gaps.min(axis=1)
            for start, end in _runs(best <= touch_gap, bridge, min_frames):
                window = gaps[start:end]
                t, k = np.unravel_index(np.argmin(window), window.shape)
                out.append(ContactWindow(start, end, person, hand, sk.PART_NAMES[int(theirs.part[k])],
                                         round(float(window[t, k]), 3)))
    return sorted(out, key=lambda w: (w.start, w.person, w.hand))


def pair_contact_lines(clips: list[Clip]) -> list[str]:
    """Data-card lines: per real (not synthetic) two-person clip, its measured contact windows."""
    pairs = [c for c in clips if len(c.people) == 2 and not c.synthetic]
    if not pairs:
        return []
    lines = ["## Real two-person captures: measured contact windows", "",
             f"Hand-to-body touches (gap ≤ {TOUCH_GAP * 100:.0f} cm between the sphere bodies of "
             f"`interplay.motion.pair.body`, ≥ {MIN_FRAMES} frames, gaps of ≤ {BRIDGE} frames bridged), "
             "measured by `interplay.data.pairs.contact_windows`; times in seconds.", "",
             "| clip | kind | split | seconds | touching | windows (person's hand → other's part, start–end s) |",
             "|---|---|---|---|---|---|"]
    for c in pairs:
        ws = contact_windows(c.people[0], c.people[1])
        touching = np.zeros(c.frames, bool)
        for w in ws:
            touching[w.start:w.end] = True
        shown = "; ".join(f"{w.person + 1} {w.hand} → {w.part} {w.start / FPS:.1f}–{w.end / FPS:.1f}"
                          for w in ws[:6]) + (f"; … ({len(ws)} in all)" if len(ws) > 6 else "")
        lines.append(f"| {c.id} | {c.label} | {c.split} | {c.seconds:.1f} | "
                     f"{touching.mean() * 100:.0f}% | {shown or 'none'} |")
    return lines + [""]


__all__ = ["BRIDGE", "MIN_FRAMES", "TOUCH_GAP", "ContactWindow", "contact_windows", "pair_contact_lines"]
