"""A clause the decomposer did not understand: the nearest phrase of the data's vocabulary
(MiniLM cosine ≥ SIMILARITY), else the words as written, or nothing when it has no motion; and
each step's first `coverage`: how well its words were understood (the generator refines it
with what it made the step from: captures, a primitive, a composition).

    coverage_of(decompose("jumps twice"))        → capture, similarity 1.0, entry "jump"
    coverage_of(<"juggles three balls", kept as written>) → nearest, similarity 0.0

Words the catalogue names (a verb, a gesture, a noun) are covered by what its entry is made
from; a clause taken from the nearest known phrase is covered by that phrase's captures at that
cosine; a clause kept as written is `nearest`: the studio shows the closest captures, and says so.

    resolve(decompose("does a flying kick"), …)   → the jump kick (cosine 0.81)
    resolve(decompose("does the griddy"), …)      → "does the griddy", kept as written
    resolve(decompose("gets tired"), …)           → None (dropped: no motion in it)
    resolve(decompose("hefts a bride …"), …)      → "lifts a bride …" (WordNet: heft is a kind of lift)
"""

from __future__ import annotations

from interplay.catalogue.grammar import COUNT_SAID, ONE_SAID
from interplay.catalogue.load import catalogue
from interplay.planner.broader import broader, primitive_near
from interplay.planner.decompose import SUBJECT_NOUNS, Action, decompose, split_subject
from interplay.planner.schema import Coverage
from interplay.planner.verbs import VERBS, doing_nouns, is_verb, lookup, noun_verb

SIMILARITY = 0.7      # cosine above which an unknown clause takes the nearest known phrase
# Its words are actions.toml's [words.lists]: `filler` (no motion in them), `not_a_verb` (open a
# clause without being its verb), `object_next` (after a subject noun: a verb with its object),
# `not_motion` (a state).


def _listed(name: str) -> list[str]:
    return catalogue().words.lists[name]


def _without_subject(words: list[str]) -> list[str]:
    """The words after a subject the decomposer left on ("a man drags …" → "drags …")."""
    i = 0
    filler, object_next = _listed("filler"), _listed("object_next")
    while i < len(words) and (words[i] in filler or words[i] in SUBJECT_NOUNS or
                              words[i] in ("two", "one", "he", "she", "they", "someone")):
        if words[i] in SUBJECT_NOUNS and (i == 0 or words[i - 1] not in filler) and \
                i + 1 < len(words) and words[i + 1] in object_next:
            break                    # a verb with its object ("fan yourself"), not a subject
        if words[i] == "one" and words[i + 1:i + 3] in (["of", "them"], ["of", "us"]):
            i += 2                   # "one of them storms off"
        i += 1
    return words[i:] if i < len(words) else words


def _unknown_verb(words: list[str]) -> bool:
    """Does the clause start with a verb the catalogue does not know ("levitates", "juggles")?
    Such a clause is kept and shown as the nearest captures, never dropped silently; a state
    ("is tired", "feels happy": the catalogue's `not_motion` words) is dropped."""
    words = _without_subject(words)
    if not words:
        return False
    head = words[0]
    states = set(catalogue().words.lists.get("not_motion", ()))
    if head in states or head in _listed("not_a_verb") or not head.isalpha():
        return False
    # "juggles", "juggling", and a bare form: a clause said as an instruction ("wave, then sip
    # a hot coffee") or after a plural subject ("they sip …"); the subject is gone by here
    return len(head) >= 3


_WORD_CHARS = frozenset("abcdefghijklmnopqrstuvwxyz-")


def _without_prefix(text: str, subjects: tuple[str, ...]) -> str:
    """The text without the first of `subjects` it starts with and the spaces after it."""
    for subject in subjects:
        if text.startswith(subject) and text[len(subject):len(subject) + 1].isspace():
            return text[len(subject):].lstrip()
    return text


def resolve(action: Action, clause: str, posture: str, last_parts, vocab, reasons):
    """A clause the decomposer did not understand: the nearest vocabulary phrase when close
    enough; None when the clause has no motion at all (it is dropped)."""
    words = "".join(c if c in _WORD_CHARS else " " for c in action.text).split()     # runs of a-z and -
    if all(is_verb(w, ("light",)) or w in _listed("filler") for w in words):
        reasons.append(f"dropped '{clause}': no motion in it")       # "gets (tired)"
        return None
    if vocab is not None:
        try:
            match = vocab().nearest(f"a person {action.text}")
        except Exception as exc:                     # no encoder installed: say so, go on
            reasons.append(f"similarity unavailable ({type(exc).__name__}: {exc})")
            vocab = None
        else:
            if match.score >= SIMILARITY:
                target = match.target.removeprefix("a person ")
                reasons.append(f"similarity: '{action.text}' → '{target}' (nearest {match.source} "
                               f"phrase '{match.phrase}', cosine {match.score:.2f})")
                new = decompose(target, posture, last_parts)
                if not new.known:                # a data phrase with a verb we lack ("high-five")
                    new.text = split_subject(target)[1] if split_subject(target)[0] else \
                        _without_prefix(target, ("two people", "a person"))
                    new.base, new.verb = f"a person {new.text}", VERBS["pose"]
                new.subject = action.subject
                new.matched = (match.phrase, match.score)
                said = COUNT_SAID.search(action.text)
                count = said.group(0) if said else "once" if ONE_SAID.search(action.text) else None
                if count and not COUNT_SAID.search(new.text):     # "a backflip once": keep the count
                    new.text, new.base = f"{new.text} {count}", f"{new.base} {count}"
                    reasons.append(f"count: '{count}' kept after the nearest phrase")
                return new
    wider = _broader(action, posture, last_parts, reasons, vocab)
    if wider is not None:
        return wider
    if not any(lookup(w) or noun_verb(w) for w in words) and not _unknown_verb(words):
        reasons.append(f"dropped '{clause}': no motion in it")
        return None
    action.text = _without_prefix(action.text, ("two people", "a person", "the person", "they", "both"))
    action.text = " ".join(_without_subject(action.text.split()))
    reasons.append(f"unknown motion '{action.text}': kept as written")
    action.base, action.verb = f"a person {action.text}", VERBS["pose"]
    return action


def _broader(action: Action, posture: str, last_parts, reasons, vocab) -> Action | None:
    """The clause with its unknown head verb read as the broader verb the catalogue knows
    (planner/broader.py: "heft a bride …" → "lift a bride …"), when the decomposer then knows
    it, unless a motion primitive makes the words as they are ("bang on a drum": drumming, not
    a hit; `broader.primitive_near`, with the vocabulary's encoder when there is one)."""
    rest = _without_subject(action.text.split())
    hit = broader(rest[0], rest[1] if len(rest) > 1 else None) if rest and _unknown_verb(rest) else None
    if hit is None or (vocab is not None and primitive_near(" ".join(rest), vocab().encode)):
        return None
    new = decompose(" ".join([hit.word, *rest[1:]]), posture, last_parts)
    if not new.known:
        return None
    new.subject = action.subject
    reasons.append(f"vocabulary: {hit.reason()}")
    return new


def coverage_of(action: Action, named: list[tuple[str, str]] | None = None) -> Coverage:
    """`named`: (motion words, entry) of the gestures the lexicon rewrote (`lexicon.rewrite_named`):
    a step made of such words is covered by that entry."""
    if action.matched is not None:
        phrase, score = action.matched
        return Coverage(how="capture", similarity=round(max(-1.0, min(1.0, score)), 4),
                        shown=phrase[:300])
    if not action.known:
        return Coverage(how="nearest", similarity=0.0, shown="")
    cat = catalogue()
    gesture = next((name for out, name in named or ()
                    if any(step.split(" while ")[0] in action.text for step in out.split(", then "))), None)
    noun = next((n for n in doing_nouns() if action.text.startswith(f"does a {n}")), None)
    name = gesture or noun or (action.verb.base if action.verb is not None else None)
    entry = cat.get(name) if name else None
    how = entry.made_by.how if entry is not None else "capture"
    return Coverage(how=how, similarity=1.0, shown=action.text[:300],  # type: ignore[arg-type]
                    entry=entry.name if entry is not None else None)


def not_understood() -> Coverage:
    """A prompt with no motion the planner recognises: shown as the nearest captures."""
    return Coverage(how="nearest", similarity=0.0, shown="")
