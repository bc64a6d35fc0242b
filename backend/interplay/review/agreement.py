"""The reviewer's comparison of captions with the plan (CoMA appendix F.3, without an LLM):
does a part's automatic caption confirm the part's planned edit, does the body caption confirm
the segment's base motion, and a caption-agreement score when no evaluator is loaded.

A planned text is matched through a small table of action cues: each cue (regular expression
over the planned text) names the caption phrases that show it ("raises … above the head" →
"above the head" / "to head height"). A planned text with no cue is compared with the
captions by MiniLM cosine (`SIMILAR`)."""

from __future__ import annotations

import re

import numpy as np

# (cue in the planned part text, caption phrases that confirm it) — first matching cue wins.
PART_CUES: tuple[tuple[str, tuple[str, ...]], ...] = (
    (r"\bwav", ("waves",)),
    (r"\bpunch|\bjab|\bthrust", ("punches", "raised forward")),
    (r"\bcircl|\brotat|\bswing\w* .*circles", ("circles",)),
    (r"\bkick", ("kicks",)),
    (r"\bclap|hands together|\bclasp", ("holds the other hand", "near the face", "raised forward")),
    (r"\bcheek|\bface|\bmouth|\bears?\b|\bhead into", ("near the face", "head height",
                                                      "above the head")),
    (r"\bhip\b|\bwaist", ("on the hip",)),
    (r"\bfloor|\bground|\btoes\b", ("reaches down to the floor",)),
    (r"above the head|\bsky\b|straight up|\bupwards?\b|\bup in the air|\bhigh\b|\bup\b",
     ("above the head", "head height")),
    (r"\bto the side|out to the side|\bwide\b|\bspread|\bstretch\w* .*out", (
        "stretched out to the side", "raised", "above the head")),
    (r"\bforward|\bextend|\breach|\bpoint", ("raised forward", "punches", "stretched out",
                                              "raised", "above the head", "head height")),
    (r"\bknee\b.*\b(up|rais|lift)|\blift\w* .*\b(leg|foot|knee)|\bmarch",
     ("knee is raised", "foot is lifted", "kicks")),
    (r"\btap|\bstep|\bstomp", ("takes a step", "foot is lifted", "knee is raised", "walks",
                                "runs")),
    (r"\bcross", ("takes a step", "knee is bent", "bends deeply")),
    (r"\bbend|\bbent|\bflex|\bchest\b|\bfist\b.*\bdown|\bpull",
     ("elbow is bent", "knee is bent", "shoulder height", "bends deeply")),
    (r"\brest|\blower|\bhang|\bat the side|\bdown\b", ("rests at the side", "stands still",
                                                       "elbow is bent")),
    (r"\brais|\bhold\w* .*\bup|\blift", ("raised", "above the head", "head height", "waves",
                                         "shoulder height")),
)
# (cue in the base text, body caption phrases that confirm it).
BODY_CUES: tuple[tuple[str, tuple[str, ...]], ...] = (
    (r"\bcrawl|\blie|\blying|\bfall|\bfalls|\bdives?\b|\btopple", ("lies", "gets up", "crouches",
                                                                    "bends forward", "sits")),
    (r"\bsit|\bsits", ("sits", "crouches", "squats", "lies")),
    (r"\bsquat|\bkneel|\bdrops? down|\bcrouch|\bbends? (both )?(the )?knees", (
        "squats", "crouches", "sits", "bends forward")),
    (r"\bjump|\bhop|\bleap", ("jumps",)),
    (r"\bkick", ("kicks",)),
    (r"\brun|\bjog|\bsprint", ("runs", "jogs")),
    (r"\bwalk|\bstroll|\bmarch|\bstep", ("walks", "jogs", "sneaks")),
    (r"\bdodg", ("walks", "jogs", "runs", "sideways", "turns")),
    (r"\bspin|\bturn|\btwirl|\brotat", ("turns", "circle")),
    (r"\blean\w* forward|\bbow|\bbend\w* (over|forward|down)", ("bends forward", "crouches")),
    (r"\bstand", ("stands still", "stays in place", "turns", "gets up")),
)
SIMILAR = 0.5    # MiniLM cosine above which an uncued text counts as confirmed


def _cue(text: str, table) -> tuple[str, ...] | None:
    low = text.lower()
    for pattern, phrases in table:
        if re.search(pattern, low):
            return phrases
    return None


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
