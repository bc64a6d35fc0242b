"""The two people of a prompt, in neutral words: "a waiter hands a menu to a guest" → "one
person hands a menu to the other person". The interaction kinds' descriptions speak of "one
person" and "the other"; a prompt that names its people by role (waiter, grandson, boxer)
lands far from them in the text encoder's space (0.39 where the neutral form is 0.65), so
readers compare the neutral form as well. Which nouns are people is the encoder's call against
a few descriptions (people.toml), not a list of nouns.

    neutral("a father lifts his daughter onto his shoulders", encoder)
      → "one person lifts the other person onto his shoulders"
    neutral("tickle a buddy", encoder, third=third) → "one person tickles the other person"
"""

from __future__ import annotations

import tomllib
from functools import lru_cache
from pathlib import Path

import numpy as np

TABLE = Path(__file__).with_name("people.toml")
_PUNCT = ",.;:!?"


@lru_cache(maxsize=1)
def table() -> dict:
    return tomllib.loads(TABLE.read_text())


def _prototypes(encoder) -> tuple[np.ndarray, np.ndarray]:
    t = table()
    return np.asarray(encoder.encode(t["person"])), np.asarray(encoder.encode(t["thing"]))


def person_margin(nouns: list[str], encoder) -> np.ndarray:
    """(N,) how much nearer "a <noun>" is to a person description than to a thing's (> 0: a
    person)."""
    if not nouns:
        return np.zeros(0)
    people, things = _prototypes(encoder)
    t = table()
    emb = np.asarray(encoder.encode([t["template"].format(n) for n in nouns]))
    return (emb @ people.T).max(axis=1) - (emb @ things.T).max(axis=1)


def _phrases(tokens: list[str]) -> list[tuple[int, int, list[int], bool]]:
    """(start, end, candidate noun indices, pair) of each determiner's phrase: the words after
    a determiner up to `max_words`, stopped by a stop word or punctuation."""
    t = table()
    dets, pairs, stops = set(t["determiners"]), t["pair_determiners"], set(t["stops"])
    low = [_bare(w) for w in tokens]
    out, i = [], 0
    while i < len(low):
        width = next((len(p.split()) for p in sorted(pairs, key=len, reverse=True)
                      if low[i:i + len(p.split())] == p.split()), 0)
        if width or low[i] in dets:
            start, j = i, i + max(width, 1)
            cands: list[int] = []
            while j < len(low) and len(cands) < t["max_words"] and low[j] not in stops \
                    and low[j] not in dets and low[j]:
                cands.append(j)
                if tokens[j][-1:] in _PUNCT:
                    break
                j += 1
            if cands:
                out.append((start, cands[-1] + 1, cands, bool(width)))
                i = cands[-1] + 1
                continue
        i += 1
    return out


def _instruction(tokens: list[str], named: list[tuple[int, int, bool]], margin: dict, third
                 ) -> str | None:
    """An instruction to do something to one person ("tickle a buddy", "flee from a bully",
    "deliver a parcel to a neighbour") in neutral words, its doer the one told: "one person
    tickles the other person". Only where that person is surely one (`sure_margin`: the nouns
    of an instruction's things sit near the plain margin: "iron a shirt" 0.009, "an armchair"
    0.056; "a neighbour" 0.066, "a buddy" 0.14) and is who the verb is done to: its object,
    after particles only ("from", "away") or after "to"; not in a likeness ("walk like a
    toddler"), nor after a gerund ("sitting at a desk" describes, it does not tell). None else."""
    t = table()
    first = _bare(tokens[0])
    if len(named) != 1 or named[0][2] or not first.isalpha() or first.endswith("ing") \
            or first in t["determiners"] or first in t["stops"] or first in t["alone"]:
        return None
    start, end, _ = named[0]
    between = [_bare(w) for w in tokens[1:start]]
    if margin.get(_bare(tokens[end - 1]), 0.0) < t["sure_margin"] or \
            not (all(w in t["stops"] for w in between) or between[-1:] == ["to"]) or \
            set(between) & set(t["likeness"]):
        return None
    last = tokens[end - 1].rstrip(_PUNCT)
    tail = ("'s" if last.lower().endswith("'s") else "") + tokens[end - 1][len(last):]
    out = tokens[:start] + ["the other person" + tail] + tokens[end:]
    return " ".join(["one person", third(first)] + out[1:])


def neutral(prompt: str, encoder, keep: frozenset[str] = frozenset(), third=None) -> str:
    """The prompt with its people named "one person" / "the other person" ("two people" for a
    pair named at once: "two kids", "a couple"), in order; everything else as written. The
    A person named again is named as before ("… a client … and the client copies her" → "… the
    other person … and the other person copies her"; the first one: "the first person"). The
    prompt itself when it already says "the other", or when it does not open with a person
    ("tiptoe past the sleeping baby", "walk in a straight line": an instruction, whose nouns
    are read no further; MiniLM alone cannot tell "a hot | coffee" from "a waiter | hands").
    People named by a noun in `keep` count in the order but stay as written ("the man hands a
    menu to a guest" → "the man hands a menu to the other person"). With `third` (a verb's
    third person: "tickle" → "tickles"), an instruction to do something to one person is read
    with its doer ("tickle a buddy" → "one person tickles the other person")."""
    tokens = prompt.split()
    if "the other" in prompt.lower():
        return prompt
    t = table()
    found = _phrases(tokens)
    words = sorted({_bare(tokens[j]) for _, _, c, _ in found for j in c})
    margin = dict(zip(words, person_margin(words, encoder)))
    named = [(start, start + 1, False) for start, w in enumerate(tokens) if _bare(w) in t["alone"]]
    if _named_first(tokens, found, encoder):                   # a name first: "Mom tucks …"
        named.append((0, 1, False))
    for start, _, cands, pair in found:
        at = _noun(tokens, cands, margin, pair)
        if at is not None:
            named.append((start, at + 1, pair or _bare(tokens[at]) in t["pair_nouns"]))
    named.sort()
    if named and named[0][0] != 0 and third is not None:
        return _instruction(tokens, named, margin, third) or prompt
    if not named or named[0][0] != 0:       # a prompt that opens with its people, or none
        return prompt
    swaps, seen = [], 0
    who: dict[str, int] = {}                      # a named person's noun → 0 or 1
    for start, end, pair in named:
        last = tokens[end - 1].rstrip(_PUNCT)
        tail = ("'s" if last.lower().endswith("'s") else "") + tokens[end - 1][len(last):]
        noun = _bare(tokens[end - 1])
        if noun in keep:
            seen = 2 if pair else seen + 1
        elif pair:
            swaps.append((start, end, "two people" + tail))
            seen = 2
        elif noun in who:            # named again ("… and the client copies her"): the same one
            swaps.append((start, end, ("the first person", "the other person")[who[noun]] + tail))
        elif seen < 2:
            swaps.append((start, end, ("one person", "the other person")[seen] + tail))
            who[noun] = seen
            seen += 1
    for start, end, text in reversed(swaps):
        tokens[start:end] = [text]
    return " ".join(tokens)


def _verb_like(word: str) -> bool:
    """A third-person verb's ending ("hands", "carries"): what follows a singular subject."""
    w = _bare(word)
    return w.endswith("s") and not w.endswith("ss")


def _noun(tokens: list[str], cands: list[int], margin: dict, pair: bool) -> int | None:
    """The index of a phrase's person noun, or None: its first word read as a person, moved on
    to a later one read as a person more surely ("an angry | man"). A singular phrase's word
    read as a person only weakly (under `sure_margin`) and followed by another that is not a
    verb's form describes a thing ("a hot | coffee", "the warm | sun"); a pair's noun is
    followed by a bare verb ("two kids play"), and so is a person told to do something ("helps
    an old man | walk")."""
    bound = table()["margin"]
    score = [float(margin[_bare(tokens[j])]) for j in cands]
    k = next((n for n, m in enumerate(score) if m > bound), None)
    if k is None:
        return None
    while k + 1 < len(cands) and score[k + 1] > max(score[k], table()["sure_margin"]):
        k += 1
    if not pair and score[k] < table()["sure_margin"] and k + 1 < len(cands) \
            and not _verb_like(tokens[cands[k + 1]]):
        return None
    return cands[k]


def _named_first(tokens: list[str], found: list, encoder) -> bool:
    """The prompt opens with a person named with no determiner ("mom tucks her son …"): read
    as a person only more surely (`first_margin`) and before a verb's form."""
    t = table()
    first = _bare(tokens[0]) if tokens else ""
    if not first or first in t["alone"] or first in t["determiners"] or (found and found[0][0] == 0):
        return False
    return len(tokens) > 1 and _verb_like(tokens[1]) and \
        float(person_margin([first], encoder)[0]) > t["first_margin"]


def _bare(word: str) -> str:
    """The word as read: lower case, without punctuation or a possessive ("woman's": woman)."""
    return word.lower().strip(_PUNCT).removesuffix("'s")
