"""The people of a two-person prompt named as the planner reads them: a noun the planner
knows ("the woman", "her partner") is read as written; a prompt that names one it does not
("a waiter", "two coworkers", "his grandson") has its people named "one person" / "the other
person" / "two people" (`catalogue.people`, the text encoder's person-or-thing call), so that
the pair grammar finds who does what:

    plain_people("a waiter hands a menu to a guest", encoder)
      → "one person hands a menu to the other person"
    plain_people("two coworkers argue loudly", encoder) → "two people argue loudly"
    plain_people("tickle a buddy", encoder) → "one person tickles the other person"
"""

from __future__ import annotations

from interplay.catalogue.people import neutral
from interplay.planner.pair.roles import NOUNS
from interplay.planner.verbs import third

KNOWN = frozenset(NOUNS)


def plain_people(text: str, encoder) -> tuple[str, list[str]]:
    """(text, reasons): the text with the people the planner does not know named neutrally."""
    if neutral(text, encoder, keep=KNOWN, third=third) == text:   # every person named is one it knows
        return text, []
    out = neutral(text, encoder, third=third)
    if out == text:
        return text, []
    return out, [f"people: '{text}' read as '{out}' (the people named by role)"]


def plain_person(text: str, encoder) -> tuple[str, list[str]]:
    """(text, reasons) for one person: a prompt that opens with someone the planner does not
    know ("a toddler wobbles across the rug", "a tired hiker climbs a steep hill") opens with
    "a person" instead, so that the words after them are read as their motion (they were kept
    with the noun: "a person toddler wobbles …"). Anyone named later is kept as written."""
    if text.split(" ", 1)[0].lower() not in ("a", "an", "the") or neutral(text, encoder, keep=KNOWN) == text:
        return text, []                 # a bare first word may be a verb ("pick apples …")
    out = neutral(text, encoder)
    if not out.startswith("one person ") or "the other person" in out or "two people" in out:
        return text, []
    out = "a person " + out[len("one person "):]
    return out, [f"person: '{text}' read as '{out}' (the person named by role)"]

