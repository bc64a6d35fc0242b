"""Motion-irrelevant context out, vague places and manners into motion words (CoMA's
recaption step: "tatami → ground"; Table 8 marks "hopeless", "an away fan" as context).

    strip_context("An angry man sits on the court floor to protest a verdict")
      → ("An man sits on the floor", ["context: dropped 'angry'", …])

Runs on the original text (before lower-casing) so capitalised names after "at/against/during"
can be recognised as places and events. Every change is returned as a reason.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass

from interplay.catalogue import grammar as g
from interplay.catalogue.words import Found, Phrases, words


@dataclass(frozen=True)
class Said:
    """A list of words.toml found in the text: what leads up to each phrase and what follows
    it go too (`Phrases.sub`)."""
    phrases: Phrases
    lead: str = " "
    trail: bool = False
    clause: bool = False


def _said(name: str, lead: str = " ", trail: bool = False, clause: bool = False) -> Said:
    return Said(words(name, ignore_case=True), lead, trail, clause)


# (how it is found, what replaces it, what it is), applied in order. Proper names, years and
# "in a … celebration" are sentence structure (grammar.py; case matters: capitalised names after
# a preposition are places, teams, events); the rest are words.toml's context lists. "{1}": the
# phrase's first word ("waves hello" → "waves the right hand").
RULES: list[tuple[re.Pattern | Said, str, str]] = [
    (g.CONTEXT_EVENT, " ", "event/place"),
    (g.CONTEXT_YEAR, " ", "date"),
    (g.CONTEXT_MONTH, " ", "date"),
    (_said("context_occasion"), " ", "occasion"),
    (_said("context_audience"), " ", "audience"),
    (_said("context_purpose", lead=",", clause=True), " ", "purpose"),
    (g.CONTEXT_CELEBRATION, " ", "occasion"),
    (_said("context_mood"), " ", "mood"),
    (_said("context_emotion", lead="", trail=True), "", "mood"),
    (_said("context_target"), " ", "target"),
    (_said("context_floor", lead=""), "on the floor", "place"),
    (_said("context_forward", lead=""), "forward", "place"),
    (_said("context_weather"), " ", "weather"),
    (_said("context_place"), " ", "place"),
    (_said("context_control", lead="", trail=True), "", "state"),
    (_said("context_way"), " ", "place"),
    (_said("context_timing"), " ", "timing"),
    (_said("context_calmly", lead=""), "slowly", "manner"),
    (_said("context_hurry", lead=""), "quickly", "manner"),
    (_said("context_greeting", lead=""), "{1} the right hand", "greeting"),
    (_said("context_team"), " ", "audience"),
]


def _reason(old: str, new: str, what: str) -> str:
    old = old.strip(" ,")
    if new.strip():
        return f"context ({what}): '{old}' → '{new.strip()}'"
    return f"context ({what}): dropped '{old}'"


def _apply(text: str, how: re.Pattern | Said, repl: str, what: str, reasons: list[str]) -> str:
    def new(old: str) -> str:
        out = repl.replace("{1}", old.split()[0]) if "{1}" in repl else repl
        reasons.append(_reason(old, out, what))
        return out
    if isinstance(how, Said):
        sub: Callable[[Found], str] = lambda found: new(found.text)        # noqa: E731
        return how.phrases.sub(text, sub, how.lead, how.trail, how.clause)
    return how.sub(lambda m: new(m.group(0)), text)


def strip_context(text: str) -> tuple[str, list[str]]:
    """The text without motion-irrelevant context, and one reason per change."""
    reasons: list[str] = []
    for how, repl, what in RULES:
        text = _apply(text, how, repl, what, reasons)
    return _tidy(text), reasons


def _tidy(text: str) -> str:
    """Runs of spaces as one, none before a punctuation mark, none (nor a comma) to start."""
    out: list[str] = []
    run = ""
    for c in text + "\0":
        if c.isspace():
            run += c
            continue
        if run and c not in ",.;!?":
            out.append(run if len(run) == 1 else " ")
        run = ""
        out.append(c)
    text = "".join(out[:-1]).strip()
    while text and (text[0] in ",;" or text[0].isspace()):
        text = text[1:]
    return text
