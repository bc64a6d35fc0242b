"""A small rule-based planner: split a prompt into ordered segments and give each a duration.

"a person walks forward, then jumps. Finally they sit" → three segments ("a person walks
forward", "a person jumps", "they sit") with durations proportional to their word counts,
each ≥ 1 s, summing to the requested length. Frames are at 20 fps; segment `end` is exclusive.
(The full planner comes later; this one keeps the same plan JSON.)
"""

from __future__ import annotations

import re

import numpy as np

from ..motion.skeleton import FPS

MAX_PROMPT = 500
# Connectives that start a new segment, and sentence ends; longest alternatives first.
_SPLIT = re.compile(r"\b(?:and\s+then|after\s+that|afterwards|then|finally)\b|;|(?<=[.!?])(?:\s+|$)",
                    re.IGNORECASE)
_STRIP = " \t\n,.;:!?"
_TRAILING_AND = re.compile(r"(?:\s*,)?\s+and$", re.IGNORECASE)
# Words that show a segment already names who moves ("the person jumps", "they sit").
_SUBJECTS = {"a", "an", "the", "he", "she", "they", "someone", "somebody", "person", "people",
             "man", "woman", "men", "women", "both", "two", "one", "it", "we", "i", "you", "his",
             "her", "their", "each", "everyone", "both", "dancers", "couple", "partners"}


def split_prompt(prompt: str) -> list[str]:
    """Ordered segment texts of a prompt (connectives and punctuation removed)."""
    parts = []
    for piece in _SPLIT.split(prompt):
        piece = _TRAILING_AND.sub("", piece.strip(_STRIP)).strip(_STRIP)
        piece = re.sub(r"^(?:and|,)\s+", "", piece, flags=re.IGNORECASE).strip(_STRIP)
        piece = re.sub(r"\s+", " ", piece)
        if piece:
            parts.append(piece)
    return parts


def _with_subject(text: str, persons: int) -> str:
    """Give a segment without a subject ("jumps") the default one ("a person jumps")."""
    first = text.split(" ", 1)[0].lower()
    if first in _SUBJECTS:
        return text
    return ("two people " if persons == 2 else "a person ") + text


def allocate_frames(weights: list[float], total: int, minimum: int = FPS) -> list[int]:
    """Frames per segment: each ≥ minimum (when total allows), the rest proportional to the
    weights with largest-remainder rounding, summing exactly to total."""
    n = len(weights)
    base = min(minimum, total // n)
    spare = total - base * n
    w = np.asarray(weights, dtype=np.float64)
    share = spare * w / w.sum() if w.sum() > 0 else np.full(n, spare / n)
    frames = base + np.floor(share).astype(int)
    left = total - int(frames.sum())
    order = np.argsort(-(share - np.floor(share)), kind="stable")
    frames[order[:left]] += 1
    return frames.tolist()


def basic_plan(prompt: str, persons: int = 1, seconds: float = 6.0) -> dict:
    """The plan JSON: {"prompt", "rewritten", "persons", "seconds", "segments": [{"index",
    "prompt", "start", "end", "persons"}], "planner": "basic"} (start/end in frames)."""
    if not isinstance(prompt, str) or not prompt.strip():
        raise ValueError("the prompt is empty")
    if len(prompt) > MAX_PROMPT:
        raise ValueError(f"the prompt is longer than {MAX_PROMPT} characters")
    if persons not in (1, 2):
        raise ValueError(f"persons must be 1 or 2, got {persons!r}")
    if not seconds > 0 or not np.isfinite(seconds):
        raise ValueError(f"seconds must be positive, got {seconds!r}")
    total = max(1, int(round(seconds * FPS)))
    texts = split_prompt(prompt) or [prompt.strip()]
    # Too many segments for ≥ 1 s each: fold the extra ones into the last.
    fit = max(1, total // FPS)
    if len(texts) > fit:
        texts = texts[:fit - 1] + [", then ".join(texts[fit - 1:])]
    texts = [_with_subject(t, persons) for t in texts]
    frames = allocate_frames([len(t.split()) for t in texts], total)
    segments, start = [], 0
    for i, (t, n) in enumerate(zip(texts, frames)):
        segments.append({"index": i, "prompt": t, "start": start, "end": start + n,
                         "persons": list(range(persons))})
        start += n
    return {"prompt": prompt, "rewritten": ", then ".join(texts), "persons": persons,
            "seconds": total / FPS, "segments": segments, "planner": "basic"}
