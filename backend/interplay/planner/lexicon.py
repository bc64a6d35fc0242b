"""Context-rich gestures and poses (the catalogue's entries with `names`) → the motion words a motion model knows (CoMA's recaption:
"wakanda forever salute → cross arms in front of the chest").

    rewrite("The man does the Tiger Woods fist pump")
      → ("The man raises the right fist to the chest, then pulls the right fist down sharply",
         ["lexicon: 'does the Tiger Woods fist pump' → 'raises …' (tiger woods fist pump)"])

An entry's text is a verb phrase in the third person ("crosses both arms …"); ", then" inside it
makes several temporal steps, "while …"/", <verb>ing …" simultaneous ones. The verb that
introduces a name ("does", "performs", "striking", "holding", …) is replaced with it: a gerund
introducer gives the text in -ing form, a holding verb gives the entry's `hold` phrase
("with both arms stretched out to the sides") when it has one.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache

from interplay.catalogue.grammar import named_rx, number
from interplay.catalogue.load import catalogue, on_change
from interplay.catalogue.phrases import tokens
from interplay.planner.verbs import gerund, lookup


@dataclass(frozen=True)
class Entry:
    name: str
    text: str             # what a person does, third person present
    hold: str | None = None   # the held pose as a "with …" phrase (poses only)


@lru_cache(maxsize=1)
def _patterns() -> list[tuple[Entry, re.Pattern]]:
    """Every catalogue entry with set phrases (gestures, poses, named verbs), in file order,
    with the pattern that finds it in a prompt."""
    cat = catalogue()
    lists = cat.words.lists
    out = []
    for a in cat.action:
        if a.names and a.text:
            rx = named_rx(a.names, a.followed_by, lists.get("name_intro", ()),
                          lists.get("sequential_intro", ()), cat.words.name_adjectives,
                          cat.words.name_tails)
            out.append((Entry(a.name, a.text, a.hold), rx))
    return out


on_change(_patterns.cache_clear)


def entries() -> list[Entry]:
    """Every named gesture, pose and verb with set phrases, in catalogue order."""
    return [e for e, _ in _patterns()]


def _lists(name: str) -> set[str]:
    return set(catalogue().words.lists.get(name, ()))


def as_gerund(text: str) -> str:
    """"raises the arm, then lowers it" → "raising the arm, then lowering it"."""
    steps = []
    for step in text.split(", then "):
        first, _, rest = step.partition(" ")
        hit = lookup(first)
        steps.append(f"{gerund(hit[0].base)} {rest}".strip() if hit else step)
    return ", then ".join(steps)


def _form(entry: Entry, m: re.Match) -> str:
    """The entry's text in the form its introducer asks for."""
    intro = (m.group("intro") or "").split()
    first = (intro[0] if intro else m.group("name").split()[0]).lower()
    if first in _lists("holding_intro") and entry.hold:
        return entry.hold
    if first in _lists("sequential_intro"):      # "switching to a T-pose": a new step, not a simultaneous one
        return entry.text
    if first.endswith("ing") and not first.startswith("try"):
        return as_gerund(entry.text)
    return entry.text


def rewrite(text: str) -> tuple[str, list[str]]:
    """The text with every known gesture or pose replaced by its motion words."""
    text, reasons, _ = rewrite_named(text)
    return text, reasons


def rewrite_named(text: str) -> tuple[str, list[str], list[tuple[str, str]]]:
    """`rewrite`, and (motion words, entry name) for each replacement: which catalogue entry a
    later step's words came from ("does a T-pose" → "raises both arms …", "t-pose")."""
    reasons: list[str] = []
    named: list[tuple[str, str]] = []
    for entry, rx in _patterns():
        def sub(m, entry=entry):
            out = _form(entry, m)
            intro = (m.group("intro") or "").lower()
            if out == entry.hold and not intro.endswith("ing") and not _verb_before(m):
                out = f"stands {out}"                        # "hold a T-pose": the body stands
            det = (m.group("det") or "").lower()
            count = number(det) or 1
            if count > 1:
                out += " twice" if count == 2 else f" {det} times"
            reasons.append(f"lexicon: '{m.group(0)}' → '{out}' ({entry.name})")
            named.append((out, entry.name))
            return out
        text = rx.sub(sub, text)
    return text, reasons, named


def _verb_before(m: re.Match) -> bool:
    """Is there a motion verb in the clause before the match ("walks holding a T-pose")?"""
    before = m.string[:m.start()]
    cut = max([before.rfind(c) + 1 for c in ",.;"] + [t.end for t in tokens(before) if t.text == "then"])
    clause = before[cut:]                                   # after the last , . ; or "then"
    return any((h := lookup(w)) and h[0].kind != "light" for w in clause.split())


def find(text: str) -> Entry | None:
    """The first entry whose name occurs in the text."""
    for entry, rx in _patterns():
        if rx.search(text):
            return entry
    return None


def phrases() -> list[tuple[str, str]]:
    """(name, text) of every entry: lexicon part of the similarity vocabulary."""
    return [(e.name, e.text) for e, _ in _patterns()]
