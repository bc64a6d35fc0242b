"""The motion verbs the planner knows (the catalogue's entries of kinds travel, whole, part and
light, `catalogue/actions.toml`): what moves (whole body, travel, one part), how long one
performance takes, which posture it ends in, and their word forms.

    lookup("walked")  → (VERBS["walk"], "past")
    third("sit") == "sits", gerund("sit") == "sitting"

Kinds: "travel" (moves the whole body along a path: walk, run, hop …), "whole" (whole body in
place: jump, sit, spin …), "part" (a limb does it: wave, raise, kick …; `part` says which by
default: "arm", "leg" or "arms" for both), "light" (carries no motion itself: do, perform,
start, keep …; the motion is in its object or the verb after it).
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from functools import lru_cache

from interplay.catalogue.load import catalogue, on_change


@dataclass(frozen=True)
class Verb:
    base: str
    kind: str                    # "travel" | "whole" | "part" | "light"
    seconds: float = 2.0         # one performance (travel: default length of the walk/run)
    part: str | None = None      # part verbs: "arm" | "leg" | "arms" | "legs"
    posture: str | None = None   # posture afterwards: standing, sitting, lying, squatting …
    speed: float | None = None   # travel: metres per second


class _Table(Mapping[str, Verb]):
    """{base: Verb} of the catalogue's motion verbs (kinds travel / whole / part / light), read
    through to the catalogue in use so that a test's catalogue is seen everywhere."""

    def _verbs(self) -> dict[str, Verb]:
        return _verbs()

    def __getitem__(self, key: str) -> Verb:
        return self._verbs()[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._verbs())

    def __len__(self) -> int:
        return len(self._verbs())


@lru_cache(maxsize=1)
def _verbs() -> dict[str, Verb]:
    return {a.name: Verb(a.name, a.kind, a.seconds, a.part, a.ends_in, a.speed)
            for a in catalogue().action if a.kind in _KINDS and not a.noun_only}


@lru_cache(maxsize=1)
def _irregular() -> dict[str, tuple[str, ...]]:
    return {a.name: tuple(a.forms) for a in catalogue().action if a.forms}


@lru_cache(maxsize=1)
def _doubles() -> frozenset[str]:
    return frozenset(a.name for a in catalogue().action if a.doubles)


_KINDS = ("travel", "whole", "part", "light")
VERBS: Mapping[str, Verb] = _Table()


def _regular(base: str) -> tuple[str, str, str, str]:
    if base.endswith(("s", "sh", "ch", "x", "z")):
        third = base + "es"
    elif base.endswith("y") and base[-2] not in "aeiou":
        third = base[:-1] + "ies"
    else:
        third = base + "s"
    if base in _doubles():
        stem = base + base[-1]
    elif base.endswith("e") and not base.endswith(("ee", "ye", "oe")):
        stem = base[:-1]
    else:
        stem = base
    gerund = stem + "ing"
    if base.endswith("e"):
        past = base + "d"
    elif base.endswith("y") and base[-2] not in "aeiou":
        past = base[:-1] + "ied"
    else:
        past = stem + "ed"
    return third, gerund, past, past


def forms(base: str) -> dict[str, str]:
    """{"base", "third", "gerund", "past", "participle"} of a verb."""
    third, gerund, past, part = _irregular().get(base) or _regular(base)
    return {"base": base, "third": third, "gerund": gerund, "past": past, "participle": part}


def third(base: str) -> str:
    return forms(base)["third"]


def gerund(base: str) -> str:
    return forms(base)["gerund"]


@lru_cache(maxsize=1)
def _table() -> dict[str, tuple[Verb, str]]:
    out: dict[str, tuple[Verb, str]] = {}
    for verb in VERBS.values():
        for form, word in forms(verb.base).items():
            out.setdefault(word, (verb, form))
    return out


def lookup(word: str) -> tuple[Verb, str] | None:
    """The verb and form of a word ("sat" → (sit, "past")), None for other words."""
    return _table().get(word.lower().strip(".,;:!?\"'"))


def is_verb(word: str, kinds: tuple[str, ...] = ("travel", "whole", "part")) -> bool:
    hit = lookup(word)
    return hit is not None and hit[0].kind in kinds


@lru_cache(maxsize=1)
def nouns() -> dict[str, str]:
    """Nouns that name a motion ("a squat", "two kicks", "hand claps") → the verb they stand for."""
    return {n: a.name for a in catalogue().action for n in a.nouns}


@lru_cache(maxsize=1)
def doing_nouns() -> dict[str, tuple[str, float, str | None]]:
    """Nouns done with "does a …" rather than turned into a verb ("does a handstand"):
    {noun: (kind, seconds, posture after)}."""
    return {a.name: (a.kind, a.seconds, a.ends_in) for a in catalogue().action if a.noun_only}


def _clear() -> None:
    for f in (_verbs, _irregular, _doubles, _table, nouns, doing_nouns):
        f.cache_clear()


on_change(_clear)


def noun_verb(word: str) -> str | None:
    """The verb a motion noun stands for: "squats" → "squat", "claps" → "clap"."""
    w, table = word.lower().strip(".,;:!?\"'"), nouns()
    if w in table:
        return table[w]
    if w.endswith("es") and w[:-2] in table:
        return table[w[:-2]]
    if w.endswith("s") and w[:-1] in table:
        return table[w[:-1]]
    return None
