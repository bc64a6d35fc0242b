"""Views of a capture: the clip as captured, mirrored left ↔ right, played backwards in time,
or both. Retrieval uses them where the captures exist only the other way round: a right kick
for "kick with the right leg" when the set holds left ones (mirrored), a backward walk or run
from a forward one, a get-up from a lie-down (reversed).

A view is named by its clip id with suffixes, and that name is what a plan's piece records as
its `clip`:

    hdm05:HDM_bd_kickLFront1Reps_001_120             the capture as it is
    hdm05:HDM_bd_kickLFront1Reps_001_120#mirrored    left and right swapped (x → -x)
    cmu:09_04#reversed                               played backwards
    cmu:09_04#mirrored#reversed                      both

A piece's `start`/`end` count frames of its view: in a reversed view frame i is the capture's
frame T-1-i. Mirroring is `motion.pair.windows.mirror` (every left_* joint swapped with its
right_* partner and x negated; the stitcher turns and places every piece anyway, so the plane
of the reflection does not matter); a mirrored view's texts (label, captions) say left where
the capture's say right and the other way round. A reversed view keeps its texts: what it
shows is chosen by measurement (`measured.py`), not by its words.

Why reversing time is a fair backward walk: the feet stay planted exactly as long and where
they were, the body's sway and lean are the capture's, only the order of the frames changes;
what gives it away is the push-off (the toe rolls the wrong way) and, in a reversed run, the
flight phases that start with a landing.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from interplay.catalogue.words import Found, words
from interplay.motion.clip import Caption, Clip
from interplay.motion.pair.windows import mirror

MIRRORED = "mirrored"
REVERSED = "reversed"
SEP = "#"


@dataclass(frozen=True)
class View:
    clip: str                 # the capture's id
    mirrored: bool = False
    reversed: bool = False

    @property
    def ref(self) -> str:
        """The view's name: the clip id with its suffixes (what a plan records)."""
        flags = [n for n, on in ((MIRRORED, self.mirrored), (REVERSED, self.reversed)) if on]
        return SEP.join([self.clip, *flags])

    @property
    def plain(self) -> bool:
        return not (self.mirrored or self.reversed)

    @classmethod
    def parse(cls, ref: str) -> View:
        """The view a name stands for; ValueError for suffixes that are not views."""
        base, *flags = ref.split(SEP)
        if set(flags) - {MIRRORED, REVERSED} or len(set(flags)) != len(flags):
            raise ValueError(f"unknown clip view {ref!r} (suffixes: #{MIRRORED}, #{REVERSED})")
        return cls(base, MIRRORED in flags, REVERSED in flags)

    def span(self, start: int, end: int, total: int) -> tuple[int, int]:
        """Frames [start, end) of the capture as frames of this view (and back: it is its
        own inverse)."""
        return (total - end, total - start) if self.reversed else (start, end)

    def frame(self, f: int, total: int) -> int:
        """A frame of the capture as a frame of this view (and back)."""
        return total - 1 - f if self.reversed else f


def joints(x: np.ndarray, view: View) -> np.ndarray:
    """A person's joints (T, 22, 3) as the view shows them (a new array)."""
    out = x[::-1] if view.reversed else x
    return mirror(out) if view.mirrored else np.array(out)


def offsets(off: np.ndarray, view: View) -> np.ndarray:
    """Rest offsets (22, 3) of the performer as the view shows them."""
    return mirror(off) if view.mirrored else off


def mirror_text(text: str) -> str:
    """The words left and right swapped (case kept)."""
    def swap(found: Found) -> str:
        w = found.text
        other = "right" if w.lower() == "left" else "left"
        return other.capitalize() if w[0].isupper() else other
    return words("sides", ignore_case=True).sub(text, swap)


def text(words: str, view: View) -> str:
    """A capture's label or caption as said of the view."""
    return mirror_text(words) if view.mirrored else words


def clip(c: Clip, view: View) -> Clip:
    """The view of a capture as a clip of its own: id the view's name, frames and rest
    offsets as the view shows them, label, prompt and captions said of the view (a reversed
    view's captions are dropped: they describe the capture's order of events)."""
    total = c.frames
    captions = [] if view.reversed else [
        Caption(cap.start, cap.end, _mirror_part(cap.part) if view.mirrored else cap.part,
                text(cap.text, view)) for cap in c.captions]
    return replace(c, id=view.ref, people=[joints(p, view) for p in c.people],
                   offsets=[offsets(o, view) for o in c.offsets], label=text(c.label, view),
                   prompt=text(c.prompt, view), captions=captions,
                   meta={**c.meta, "view": {"of": c.id, "mirrored": view.mirrored,
                                            "reversed": view.reversed, "frames": total}})


def _mirror_part(part: str) -> str:
    return part.replace("left", "#").replace("right", "left").replace("#", "right")
