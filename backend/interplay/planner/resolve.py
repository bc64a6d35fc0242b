"""A clause the decomposer did not understand: the nearest phrase of the data's vocabulary
(MiniLM cosine ≥ SIMILARITY), else the words as written, or nothing when it has no motion.

    resolve(decompose("does a flying kick"), …)   → the jump kick (cosine 0.81)
    resolve(decompose("does the griddy"), …)      → "does the griddy", kept as written
    resolve(decompose("gets tired"), …)           → None (dropped: no motion in it)
"""

from __future__ import annotations

import re

from interplay.planner.decompose import Action, decompose, split_subject
from interplay.planner.verbs import VERBS, is_verb, lookup, noun_verb

SIMILARITY = 0.7      # cosine above which an unknown clause takes the nearest known phrase
_FILLER = {"a", "an", "the", "it", "up", "down", "some", "something", "again", "too", "also"}


def resolve(action: Action, clause: str, posture: str, last_parts, vocab, reasons):
    """A clause the decomposer did not understand: the nearest vocabulary phrase when close
    enough; None when the clause has no motion at all (it is dropped)."""
    words = re.findall(r"[a-z-]+", action.text)
    if all(is_verb(w, ("light",)) or w in _FILLER for w in words):
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
                        re.sub(r"^(?:two people|a person)\s+", "", target)
                    new.base, new.verb = f"a person {new.text}", VERBS["pose"]
                new.subject = action.subject
                return new
    if not any(lookup(w) or noun_verb(w) for w in words):
        reasons.append(f"dropped '{clause}': no motion in it")
        return None
    action.text = re.sub(r"^(?:two people|a person|the person|they|both)\s+", "", action.text)
    reasons.append(f"unknown motion '{action.text}': kept as written")
    action.base, action.verb = f"a person {action.text}", VERBS["pose"]
    return action
