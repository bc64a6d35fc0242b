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

from interplay.catalogue import grammar as g
from interplay.catalogue.words import poses, words

ARMS = ("left_arm", "right_arm")
# (phrases, instruction, together): words.toml's held poses; `together` instructions are one
# action of both arms, the same words for each; the others are written per side ("{side}").
# First named wins.
POSES = poses()

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
    for said, instruction, together in POSES:
        if said.search(text):
            if together:
                return dict.fromkeys(ARMS, instruction)
            parts = ARMS if "t-pose" in text or words("t_pose").search(text) else _sides(text)
            return {p: instruction.format(side=p.split("_")[0]) for p in parts}
    return {}


def continues_hold(clause: str) -> bool:
    """Does a clause only keep what the step before it did ("waits", "keeps them up")?"""
    return words("hold_continue").whole(clause.strip(" ,.").lower())


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
