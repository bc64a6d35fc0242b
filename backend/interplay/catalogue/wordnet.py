"""The verb half of the Open English WordNet (CC BY 4.0, based on Princeton WordNet 3.0), as
`wordnet_verbs.json.gz` beside this file holds it (built from a fetched snapshot by
scripts/build_wordnet_verbs.py, which names the repository and commit): each verb lemma's
senses in WordNet's order, and each sense's word kind (its lexicographer file: motion, contact,
body …), member lemmas, hypernyms (the more general senses it is a kind of) and definition.

    senses("heft")                       → ("01976263-v", …)
    above("heft", senses=2, depth=2)     → [(1, 0, "lift", "contact", "01976263-v"), …]
                                           (steps, rank, lemma, word kind, the sense it names)
    lemmas("hefted")                     → ["heft"]
    meant("lift")                        → ("01978076-v", "01582002-v")  (senses.toml)

Loaded once, on first use. numpy-free, no network.
"""

from __future__ import annotations

import gzip
import json
import tomllib
from functools import lru_cache
from pathlib import Path

DATA = Path(__file__).with_name("wordnet_verbs.json.gz")
SENSES = Path(__file__).with_name("senses.toml")        # the senses each catalogue verb means
# regular inflections undone: (ending, what replaces it)
_ENDINGS = (("ies", "y"), ("ied", "y"), ("es", ""), ("s", ""), ("ed", ""), ("ed", "e"), ("ing", ""), ("ing", "e"))


@lru_cache(maxsize=1)
def _data() -> dict:
    with gzip.open(DATA, "rt", encoding="utf-8") as f:
        return json.load(f)


@lru_cache(maxsize=1)
def _meant() -> dict[str, tuple[str, ...]]:
    with open(SENSES, "rb") as f:
        return {verb: tuple(ids) for verb, ids in tomllib.load(f)["senses"].items()}


def meant(verb: str) -> tuple[str, ...] | None:
    """The WordNet senses a catalogue verb means (senses.toml), None for a verb not listed."""
    return _meant().get(verb)


def source() -> dict:
    """Where the data came from: repository, commit, path, licence, attribution."""
    return dict(_data()["source"])


def senses(lemma: str) -> tuple[str, ...]:
    """The verb senses (synset ids) of a lemma in WordNet's order, () for a word it has no verb for."""
    return tuple(_data()["lemmas"].get(lemma.lower(), ()))


def definition(sense: str) -> str:
    """A verb sense's first definition ("" when it has none)."""
    entry = _data()["synsets"].get(sense)
    return entry[3] if entry is not None and len(entry) > 3 else ""


def lemmas(word: str) -> list[str]:
    """The verb lemmas a word form may be ("hefted" → ["heft"]; "lobbed" → ["lob"]): the word
    itself, then regular inflections undone (a doubled last consonant too), those WordNet has."""
    w = word.lower()
    out = [w]
    for end, new in _ENDINGS:
        if w.endswith(end) and len(w) > len(end) + 1:
            base = w[:-len(end)] + new
            out.append(base)
            if len(base) > 2 and base[-1] == base[-2] and base[-1] not in "aeiouls":
                out.append(base[:-1])
    seen: list[str] = []
    for c in out:
        if c not in seen and senses(c):
            seen.append(c)
    return seen


def above(lemma: str, senses_read: int = 2, depth: int = 2,
          kinds: tuple[str, ...] | None = None) -> list[tuple[int, int, str, str, str]]:
    """(steps, rank, lemma, word kind, sense) of every lemma in the first `senses_read` senses of
    `lemma` (steps 0: a synonym) and in their hypernyms up to `depth` steps up, nearest first
    (then the more common sense first); senses of other word kinds than `kinds` left out."""
    data = _data()
    synsets = data["synsets"]
    found: list[tuple[int, int, str, str, str]] = []
    for rank, sid in enumerate(senses(lemma)[:senses_read]):
        kind = synsets[sid][0]
        if kinds is not None and kind not in kinds:
            continue
        frontier, seen = [sid], {sid}
        for step in range(depth + 1):
            for s in frontier:
                found += [(step, rank, m.lower(), kind, s) for m in synsets[s][1] if m.lower() != lemma]
            frontier = [h for s in frontier for h in synsets[s][2] if h in synsets and h not in seen]
            seen.update(frontier)
    return sorted(found, key=lambda f: (f[0], f[1]))
