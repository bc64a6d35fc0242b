"""The evaluation samples: every person of every clip of a split, cut into windows of at most
10 s (as the evaluator was trained), each with its text (the clip prompt, made single-person).

A two-person capture (salsa) is evaluated as two single people; its prompt is rewritten for one
person ("two people dance salsa" → "a person dances salsa"), which is also the text the
evaluator was trained with for those people.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.motion.clip import Clip
from interplay.review.evaluator import chunks

MAX_FRAMES = 200            # 10 s at 20 fps: the evaluator's longest training window
# Two-person prompts said of one of the two people.
SINGLE_PROMPTS = {"two people dance salsa": "a person dances salsa"}


@dataclass(frozen=True, eq=False)
class Sample:
    clip: str              # clip id
    person: int            # which person of the clip
    start: int             # frame range [start, end) within that person's motion
    end: int
    text: str              # the prompt, for one person
    joints: np.ndarray     # (end - start, 22, 3) float64, metres

    @property
    def frames(self) -> int:
        return self.end - self.start


def person_prompt(clip: Clip) -> str:
    """The clip's prompt as said of one of its people."""
    if len(clip.people) == 1:
        return clip.prompt
    if clip.prompt in SINGLE_PROMPTS:
        return SINGLE_PROMPTS[clip.prompt]
    two = "two people "
    return "a person " + clip.prompt[len(two):] if clip.prompt.startswith(two) else clip.prompt


def split_samples(clips, split: str = "test", max_frames: int = MAX_FRAMES,
                  include_synthetic: bool = False, sources=None) -> list[Sample]:
    """Every person-window of the clips in `split` (synthetic composed pairs left out unless
    asked: they are not real reference motion), of the given processed `sources` only (None:
    all)."""
    if split not in ("train", "val", "test"):
        raise ValueError(f"split must be train, val or test, got {split!r}")
    out = []
    for c in clips:
        if c.split != split or (c.synthetic and not include_synthetic) \
                or (sources is not None and c.source not in sources):
            continue
        text = person_prompt(c)
        for i, person in enumerate(c.people):
            for a, b in chunks(len(person), max_frames):
                out.append(Sample(c.id, i, a, b, text, np.asarray(person[a:b], dtype=np.float64)))
    return out
