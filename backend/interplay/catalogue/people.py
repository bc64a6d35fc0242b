"""The two people of a prompt, in neutral words: "a waiter hands a menu to a guest" → "one
person hands a menu to the other person". The interaction kinds' descriptions speak of "one
person" and "the other"; a prompt that names its people by role (waiter, grandson, boxer)
lands far from them in the text encoder's space (0.39 where the neutral form is 0.65), so
readers compare the neutral form as well. Which nouns are people is the encoder's call against
a few descriptions (people.toml), not a list of nouns.

    neutral("a father lifts his daughter onto his shoulders", encoder)
      → "one person lifts the other person onto his shoulders"
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


def neutral(prompt: str, encoder, keep: frozenset[str] = frozenset()) -> str:
    """The prompt with its people named "one person" / "the other person" ("two people" for a
    pair named at once: "two kids", "a couple"), in order; everything else as written. The
    prompt itself when it already says "the other". People named by a noun in `keep` count in the order but stay as written ("the man hands a menu to a guest" → "the
    man hands a menu to the other person")."""
    tokens = prompt.split()
    if "the other" in prompt.lower():
        return prompt
    t = table()
    found = _phrases(tokens)
    words = sorted({_bare(tokens[j]) for _, _, c, _ in found for j in c})
    margin = dict(zip(words, person_margin(words, encoder)))
    named = [(start, start + 1, False) for start, w in enumerate(tokens) if _bare(w) in t["alone"]]
    first = _bare(tokens[0]) if tokens else ""
    if first not in t["alone"] and (first and not found or (found and found[0][0] > 0 and first not in t["determiners"])):
        if person_margin([first], encoder)[0] > t["first_margin"]:     # a name first: "Mom tucks …"
            named.append((0, 1, False))
    for start, _, cands, pair in found:
        best = next((j for j in cands if margin[_bare(tokens[j])] > t["margin"]), None)
        if best is not None:    # the phrase ends at its first person word ("a waiter | hands")
            named.append((start, best + 1, pair or _bare(tokens[best]) in t["pair_nouns"]))
    swaps, seen = [], 0
    for start, end, pair in sorted(named):
        tail = tokens[end - 1][-1] if tokens[end - 1][-1:] in _PUNCT else ""
        noun = _bare(tokens[end - 1])
        if noun in keep:
            seen = 2 if pair else seen + 1
        elif pair:
            swaps.append((start, end, "two people" + tail))
            seen = 2
        elif seen < 2:
            swaps.append((start, end, ("one person", "the other person")[seen] + tail))
            seen += 1
    for start, end, text in reversed(swaps):
        tokens[start:end] = [text]
    return " ".join(tokens)


def _bare(word: str) -> str:
    return word.lower().strip(_PUNCT)
