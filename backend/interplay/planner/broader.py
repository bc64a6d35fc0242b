"""A verb the catalogue lacks, read as the nearest broader verb it knows, through WordNet's verb
hierarchy (catalogue/wordnet.py): "heft" is a kind of "lift", "lob" of "throw", "duel" of
"fight", "flee" of "run". The text encoder compares a whole clause with the data's captions,
and a clause with a rare verb is near none of them; WordNet says what the verb is a kind of.
Only the first two senses of a word are read, up
to two steps up, in the word kinds that say how a body moves (`broader_senses`), to a sense the
known verb means in the catalogue (catalogue/senses.toml), and never as a word too general to
mean a motion ("move", "go": `broader_too_general`) or as a particle ("off").

    broader("heft")   → Broader(said="heft", known="lift", word="lift", steps=1 …)
    broadened("two people duel")  → ("two people fight", (Broader(said="duel", …),))

The planner reads a clause's unknown head verb this way when no known phrase is near
(planner/resolve.py), and the two-person reader weighs the broadened prompt against the words
as written (the surer wins); every use says so in the plan's or the script's reasons.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from interplay.catalogue import wordnet
from interplay.catalogue.load import catalogue, on_change
from interplay.catalogue.phrases import Phrases, tokens
from interplay.catalogue.words import lists as word_lists
from interplay.planner.verbs import VERBS, forms, lookup, nouns

SENSES, DEPTH = 2, 2          # senses of a word read, and hypernym steps up from each
# A clause this near (MiniLM cosine) a phrasing of something a motion primitive makes ("bang on a
# drum": the drumming activity) is the primitive's to make (retrieve_edit.primitive_steps, whose
# PRIMITIVE_SIM this is): a broader verb ("hit") would take it from there.
PRIMITIVE_NEAR = 0.55
_BANKS: dict[int, np.ndarray] = {}
_NAMED = ("interaction",)   # gestures and poses are conventions: no synonym means them


@dataclass(frozen=True)
class Broader:
    said: str          # the word as written ("hefted")
    lemma: str         # its WordNet lemma ("heft")
    known: str         # the broader lemma the catalogue knows ("lift")
    word: str          # `known` in the said word's form ("lifted")
    steps: int         # 0: a synonym; 1: what it is a kind of; 2: what that is a kind of
    kind: str          # the sense's word kind (motion, contact …)

    def reason(self) -> str:
        how = "another word for" if self.steps == 0 else "a kind of"
        return f"'{self.said}' read as '{self.word}' (WordNet: to {self.lemma} is {how} to {self.known})"


@lru_cache(maxsize=1)
def _named() -> Phrases:
    """The catalogue's two-person kinds' word forms and set phrases."""
    return Phrases([w for a in catalogue().action if a.kind in _NAMED for w in a.words + a.names],
                   ignore_case=True)


def known(lemma: str) -> bool:
    """Does the catalogue name this verb (or phrase): a motion verb or the words of a two-person
    kind? (Not a gesture's or a pose's set phrase: a synonym seldom means the convention.)"""
    if lemma in VERBS and VERBS[lemma].kind != "light":
        return True
    return _named().whole(lemma)


@lru_cache(maxsize=1)
def _mentioned() -> Phrases:
    """Every plain word of every entry's word forms and set phrases ("hand*" of "hand* over")."""
    plain = {w for a in catalogue().action for phrase in a.words + a.names for w in phrase.split()
             if w.replace("*", "").replace("'", "").replace("-", "").isalpha()}
    return Phrases(sorted(plain), ignore_case=True)


def _said_known(word: str) -> bool:
    """A word the catalogue has: a verb form, a noun of an action, or any word of an entry's words
    ("hands", of the hand-over's "hand* over")."""
    w = word.lower()
    return lookup(w) is not None or w in nouns() or _mentioned().whole(w)


def _form(said: str, lemma: str) -> str:
    if said == lemma:
        return "base"
    if said.endswith("ing"):
        return "gerund"
    if said.endswith("ed"):
        return "past"
    return "third" if said.endswith("s") else "base"


def meant(name: str) -> tuple[str, ...]:
    """The WordNet senses a known word means: a catalogue verb's from catalogue/senses.toml
    (none when it is not listed: the catalogue's "flip" is a somersault, not WordNet's toss), a
    two-person kind's word's its first SENSES."""
    if name in VERBS:
        return wordnet.meant(name) or ()
    return wordnet.senses(name)[:SENSES]


def broader(word: str, then: str | None = "") -> Broader | None:
    """The nearest broader verb the catalogue knows for a word it does not (module doc), or None.
    The sense reached must be one the catalogue's verb means (`meant`): "toss" is another word
    for "flip" only in throwing, not in the somersault the catalogue's flip is. `then`: the word
    after it (None: nothing follows); a verb of one limb or thing (raise, lift, throw) is read
    only where an object follows: "a person levitates and spins" is not "raises and spins"."""
    said = word.lower()
    if not said.isalpha() or _said_known(said):
        return None
    bare = then is None or then.lower() in word_lists()["coordinating"] or then.lower() in word_lists()["connectives"]
    general = set(word_lists()["broader_too_general"])
    kinds = tuple(word_lists()["broader_senses"])
    for lemma in wordnet.lemmas(said):
        for steps, _rank, other, kind, sense in wordnet.above(lemma, SENSES, DEPTH, kinds):
            if other in general or not known(other) or sense not in meant(other):
                continue
            if bare and other in VERBS and VERBS[other].kind == "part":
                continue
            head, _, rest = other.partition(" ")
            word_out = forms(head)[_form(said, lemma)] + (f" {rest}" if rest else "")
            return Broader(said, lemma, other, word_out, steps, kind)
    return None


def primitive_near(text: str, encode) -> bool:
    """Is `text` (a clause without its subject) as near a phrasing of a primitive-made entry
    (`made_by.primitive`: an activity, push-ups, a head turn) as the generator takes it
    (PRIMITIVE_NEAR), as written or with a bare verb in the third person? `encode`: texts →
    unit rows (the planner's vocabulary's)."""
    key = id(encode)
    if key not in _BANKS:
        phrasings = [d for a in catalogue().action if a.made_by.primitive for d in a.descriptions]
        _BANKS[key] = np.asarray(encode(phrasings), dtype=np.float64)
    first, _, rest = text.partition(" ")
    said = [text] + ([f"{forms(first)['third']} {rest}".strip()] if first.isalpha() and not first.endswith("s") else [])
    return bool((np.asarray(encode(said), dtype=np.float64) @ _BANKS[key].T).max() >= PRIMITIVE_NEAR)


def broadened(text: str) -> tuple[str, tuple[Broader, ...]]:
    """The text with its verb read as the broader verb the catalogue knows (module doc) — the
    first word after a leading subject ("two people", "one person", "they": `broader_subjects`),
    or the first word of an instruction — and what was replaced; the text itself and () when
    nothing was. Only that word: without parts of speech, a later word that WordNet also has as
    a verb is as likely a noun ("a zigzag pattern", "one foot")."""
    lowered = text.lower()
    for subject in sorted(word_lists()["broader_subjects"], key=len, reverse=True):
        if lowered.startswith(subject + " "):
            lowered = lowered[len(subject) + 1:]
            break
    toks = tokens(text[len(text) - len(lowered):])
    if not toks or toks[0].text.lower() in word_lists()["broader_never"]:
        return text, ()
    hit = broader(toks[0].text, toks[1].text if len(toks) > 1 else None)
    if hit is None:
        return text, ()
    at = len(text) - len(lowered)
    return text[:at + toks[0].start] + hit.word + text[at + toks[0].end:], (hit,)


on_change(_named.cache_clear)
on_change(_BANKS.clear)
on_change(_mentioned.cache_clear)
