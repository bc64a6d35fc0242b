"""The reviewer's comparison of captions with the plan (CoMA appendix F.3, without an LLM):
does a part's automatic caption confirm the part's planned edit, does the body caption confirm
the segment's base motion, and a caption-agreement score when no evaluator is loaded.

A planned text is matched through a small table of action cues: each cue (phrases of the
planned text, catalogue/words.toml) names the caption phrases that show it ("raises … above the head" →
"above the head" / "to head height"). A planned text with no cue is compared with the
captions by MiniLM cosine (`SIMILAR`)."""

from __future__ import annotations

import numpy as np

from interplay.catalogue.words import cues

# (the planned part's words, caption phrases that confirm them), first cue a text has wins;
# and the same for a segment's base words and the body caption (catalogue/words.toml's cues).
PART_CUES = cues("part")
BODY_CUES = cues("body")
SIMILAR = 0.5    # MiniLM cosine above which an uncued text counts as confirmed


def _cue(text: str, table) -> tuple[str, ...] | None:
    low = text.lower()
    for said, phrases in table:
        if said.search(low):
            return phrases
    return None


def cued(text: str, table=BODY_CUES) -> bool:
    """Whether a text has a cue in `table`."""
    return _cue(text, table) is not None


def confirms(planned: str, captions: list[str], table=PART_CUES, encoder=None) -> tuple[bool, str]:
    """(confirmed, how): whether any of `captions` shows the planned action."""
    phrases = _cue(planned, table)
    if phrases is not None:
        ok = any(p in c.lower() for c in captions for p in phrases)
        return ok, "cue"
    if encoder is None or not captions:
        return False, "no cue"
    e = encoder.encode([planned, *captions])
    return bool((e[1:] @ e[0]).max() >= SIMILAR), "similarity"


def caption_agreement(summary: str, text: str, encoder) -> float:
    """MiniLM cosine between the caption summary and the planned text, in [-1, 1]."""
    e = encoder.encode([summary, text])
    return float(np.clip(e[0] @ e[1], -1.0, 1.0))
