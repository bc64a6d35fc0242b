"""Who acts in a clause, for two people: indices 0 and 1.

    actors("two people", 2, None, {}, "two people shake hands")   → [0, 1]
    actors("one", 2, None, {}, "one walks away")                  → [1]  (0 anchors the frame)
    actors("the other", 2, [1], {}, "the other sits")             → [0]
    actors("the man", 2, None, names, …) → the man's index, kept in `names` for later clauses

"one" acting alone is the second person: the first anchors the shared frame (their start
pelvis is the origin) and stays. In an exchange with "the other" (`roles.py`) the one who
starts is person 0.
"""

from __future__ import annotations

from interplay.catalogue import grammar as g
from interplay.catalogue.words import words

# the subjects (each read as the whole subject) and, anywhere in a clause, what both do
BOTH, FIRST, SECOND = words("pair_both"), words("pair_first"), words("pair_second")
OTHER, ONE, MUTUAL = words("pair_other"), words("pair_one"), words("pair_mutual")


def actors(subject: str | None, persons: int, prev: list[int] | None, names: dict,
           text: str) -> list[int]:
    """Who acts in a clause: indices into the people (0-based). `names` maps the nouns seen
    so far ("man", "woman") to people; `prev` is who acted in the clause before."""
    if persons == 1:
        return [0]
    s = " ".join((subject or "").split())
    if MUTUAL.search(text) or BOTH.whole(s):
        return [0, 1]
    if not s:
        return prev or [0, 1]
    pair = g.PAIR_NAMES.match(s)
    if pair:
        names.update({pair.group(1): 0, pair.group(2): 1})
        return [0, 1]
    if FIRST.whole(s):
        return [0]
    if SECOND.whole(s):
        return [1]
    if OTHER.whole(s):
        return [1 - prev[0]] if prev and len(prev) == 1 else [0]
    if ONE.whole(s):
        return [1]
    return [person(s, names)]


def person(noun_phrase: str, names: dict) -> int:
    """The index of a named person ("the man"), given the next free one when new."""
    noun = noun_phrase.split()[-1]
    if noun not in names:
        names[noun] = 0 if 0 not in names.values() else 1
    return names[noun]
