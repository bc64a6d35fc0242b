"""Held poses: a pose the body keeps over a whole segment, as one edit per part (the plan's
`edits`, each starting "holds …" so the generator and reviewer read it as kept, not as a
movement that comes and goes).

    held("with your arms crossed")
      → {"left_arm": "holds both arms crossed in front of the chest",
         "right_arm": "holds both arms crossed in front of the chest"}
    held("puts the hands on the hips")
      → {"left_arm": "holds the left hand on the hip", "right_arm": "holds the right …"}
    held("raises the left arm")  → {"left_arm": "holds the left arm raised above the head"}
    continues_hold("keeps them up") → True       # "raise both arms and keep them up"

The phrase table names each pose with its detail (crossed in front of the chest, at shoulder
height, above the head), so the detail survives the rewriting. `held` only reads the words;
whether a phrase is a hold (a "with …" state, "holds …", a step followed by "and waits") is the
caller's decision (`decompose`, `plan`).
"""

from __future__ import annotations

import re

from interplay.catalogue import grammar as g

ARMS = ("left_arm", "right_arm")
_ARM = r"(?:arms?|hands?|fists?|palms?)"
_DET = r"(?:(?:the|their|his|her|your|both|each|a|an|its)\s+)*"

# (pattern, instruction, together): `together` instructions are one action of both arms, the
# same words for each; the others are written per side ("{side}"). First match wins.
POSES: tuple[tuple[str, str, bool], ...] = (
    (rf"\b{_ARM}\s+(?:\w+\s+)?(?:crossed|folded)|\b(?:cross|crosse[sd]|crossing|fold|folds|"
     rf"folded|folding)\s+{_DET}(?:\w+\s+)?arms\b|\bcrossed\s+arms\b|\bwakanda\b",
     "holds both arms crossed in front of the chest", True),
    (rf"\b{_ARM}\s+on\s+{_DET}(?:hips?|waist)\b|\bakimbo\b",
     "holds the {side} hand on the hip", False),
    (rf"\b{_ARM}\s+(?:clasped\s+|held\s+|placed\s+|together\s+)*behind\s+{_DET}head\b",
     "holds the {side} hand behind the head", False),
    (rf"\b{_ARM}\s+(?:clasped\s+|held\s+|placed\s+|together\s+)*behind\s+{_DET}back\b",
     "holds the {side} hand behind the back", False),
    (rf"\bt[\s-]?pose\b|\b{_ARM}\s+(?:\w+\s+){{0,2}}out\s+(?:to|at)\s+{_DET}sides?\b|"
     rf"\b{_ARM}\s+(?:wide\s+)?(?:spread|outstretched)\b|\b(?:spread|spreads|spreading|"
     rf"outstretched)\s+{_DET}arms\b|\bstretch\w*\s+{_DET}(?:\w+\s+)?arms?\s+out\s+to\s+",
     "holds the {side} arm stretched out to the side at shoulder height", False),
    (rf"\b{_ARM}\s+(?:\w+\s+){{0,2}}(?:in\s+front|forwards?\b|ahead\b)|\b(?:extend|extends|"
     rf"extended|extending)\s+{_DET}(?:\w+\s+)?arms?\s+forward",
     "holds the {side} arm straight out in front at shoulder height", False),
    (rf"\b{_ARM}\s+(?:\w+\s+){{0,2}}(?:raised|up\b|above|over\s+{_DET}head|in\s+the\s+air|high"
     rf"\b|upwards?\b|lifted)|\b(?:raise|raises|raised|raising|lift|lifts|lifted|lifting|put|"
     rf"puts|putting|hold|holds|holding|keep|keeps|keeping)\s+{_DET}(?:\w+\s+)?{_ARM}\s*"
     rf"(?:up\b|above|over|in\s+the\s+air|high\b)|\b(?:raise|raises|raised|raising|lift|lifts|"
     rf"lifted|lifting)\s+{_DET}(?:\w+\s+)?{_ARM}\b",
     "holds the {side} arm raised above the head", False),
)

# What a step followed by these words does: keeps its pose ("… and waits", "… and keeps them
# up", "… and stays there", "holds it"). Said on its own it is a wait, not a hold.


def _sides(text: str) -> tuple[str, ...]:
    """Which arms a pose phrase names: both for "both"/plurals, else the side it says, else
    the right ("hand on hip")."""
    m = g.HOLD_SIDE.search(text)
    if m is None:
        return ("right_arm",)
    side = m.group(1)
    if side in ("left", "right"):
        return (f"{side}_arm",)
    return ARMS


def held(phrase: str) -> dict[str, str]:
    """{part: "holds …"} for the held pose a phrase names, {} when it names none."""
    text = phrase.lower()
    for pattern, words, together in POSES:
        if re.search(pattern, text):
            if together:
                return dict.fromkeys(ARMS, words)
            parts = ARMS if "t-pose" in text or re.search(r"\bt\s?pose", text) else _sides(text)
            return {p: words.format(side=p.split("_")[0]) for p in parts}
    return {}


def continues_hold(clause: str) -> bool:
    """Does a clause only keep what the step before it did ("waits", "keeps them up")?"""
    return bool(g.HOLD_CONTINUE.match(clause.strip(" ,.").lower()))


def as_held(edit: str) -> str:
    """A movement instruction kept until the segment ends: "raises the left arm" → "raises the
    left arm and holds it there" (for poses the table does not name)."""
    return edit if edit.startswith("holds ") or "holds it" in edit else f"{edit} and holds it there"


def keep(edits: dict[str, str], main: str, part_verb: bool) -> None:
    """`edits` with the main phrase's pose held to the end: its named pose with the table's
    detail ("puts the hands on the hips" → "holds the left hand on the hip" …), else each
    part verb's own instruction with "and holds it there"."""
    kept = held(main) if part_verb else {}
    if kept:
        edits.update(kept)
    elif part_verb:
        for part, words in list(edits.items()):
            edits[part] = as_held(words)
