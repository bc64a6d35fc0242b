"""The script of a two-person prompt, read as written and with its people named neutrally.

`kinds.read_script` reads the words, then the text encoder's nearest description. The
descriptions speak of "one person" and "the other"; a prompt that names its people by role ("a
waiter hands a menu to a guest") lands far from them (0.39 to the hand-over description), its
neutral form ("one person hands a menu to the other person", `catalogue.people.neutral`) near
(0.65). So a prompt the words do not settle is read both ways and the surer reading kept:

- words beat the encoder, and a nearer description beats a farther one;
- "together" (any motion of two people at once, the weakest of the kinds the words name) yields
  to a description of another kind at least OVER_TOGETHER near ("two friends clink their
  glasses together": the toast, not two people doing the same thing);
- a verb the catalogue lacks is read as the broader verb it knows (WordNet: "duel" → "fight",
  `planner.broader`) when the words as written leave the kind to the encoder, nearer than
  OVER_TOGETHER to none of its descriptions ("arm wrestle" stays the encoder's, at 0.87);
- nothing read: `kinds.fallback` (each does their own part, facing the other), read first so
  that a prompt left to another generator (a dance) stays with it.

    script = read(prompt, roles, encoder)      # kinds.Script, or None
"""

from __future__ import annotations

import dataclasses

from interplay.catalogue.people import neutral
from interplay.generators.interaction.kinds import Script, fallback, read_script
from interplay.planner.broader import broadened
from interplay.planner.verbs import third

# How near a description of another kind must be to take a prompt from "together" (the nearest
# paraphrases of the entries' descriptions sit at 0.7–0.8; unrelated prompts ≤ 0.6).
OVER_TOGETHER = 0.7


def _surer(a: Script | None, b: Script | None) -> Script | None:
    """The surer of two readings: one at all, then words over the encoder, then the nearer."""
    if a is None or b is None:
        return a or b
    if (a.guessed is None) != (b.guessed is None):
        return a if a.guessed is None else b
    if a.guessed is not None and b.guessed is not None and b.guessed > a.guessed:
        return b
    return a


def _encoder_only(prompt: str, roles: dict | None, encoder) -> Script | None:
    """The encoder's reading alone (the words' "together" set aside)."""
    script = read_script(prompt.replace("together", " "), roles, encoder)
    return script if script is not None and script.guessed is not None else None


def read(prompt: str, roles: dict | None, encoder) -> Script | None:
    """The prompt's script (see the module doc), or None when nothing reads it, or when the
    prompt is one this generator leaves to another (a dance, push-ups: read as written)."""
    script = read_script(prompt, roles, encoder) or fallback(prompt, encoder)
    if script is None or encoder is None:
        return script
    plain = neutral(prompt, encoder, third=third)
    if plain != prompt and (script.guessed is not None or script.kind == "together"):
        other = read_script(plain, roles, encoder)
        if other is not None and _surer(script, other) is other:
            script = dataclasses.replace(other, reasons=other.reasons + (
                f"read with the people named neutrally: '{plain}'",))
    if (script.guessed is not None and script.guessed < OVER_TOGETHER) or script.kind == "together":
        script = _broader(plain, roles, encoder, script)
    if script.kind == "together":
        alone = _encoder_only(plain, roles, encoder)
        if alone is not None and alone.kind != "together" and (alone.guessed or 0) >= OVER_TOGETHER:
            script = dataclasses.replace(alone, reasons=script.reasons + alone.reasons + (
                f"a {alone.kind} is nearer than two people doing the same thing together",))
    return script


def _broader(plain: str, roles: dict | None, encoder, script: Script) -> Script:
    """The prompt with its people named neutrally (`plain`) read with its verb the catalogue
    lacks as the broader verb it knows (`planner.broader`: "lob a beanbag to each other" →
    "throw …"), when that reading is the surer one; else `script`."""
    wide, found = broadened(plain)
    if not found:
        return script
    other = read_script(wide, roles, encoder)
    if other is None or _surer(script, other) is not other:
        return script
    return dataclasses.replace(other, reasons=other.reasons + tuple(b.reason() for b in found))
