"""Temporal segmentation: one rewritten prompt → ordered clauses, one action each (CoMA's
temporal segment step).

    split("a person sits down, stands up and then does three jumps. finally they bow")
      → [Clause("a person sits down"), Clause("stands up"), Clause("jumps three times", repeat=3),
         Clause("they bow")]

Sequence markers: sentence ends, "then", "and then", "after that", "afterwards", "next",
"finally", "followed by", ordinals ("second, …"), "before"/"after" (reordered to the order
things happen), a comma or "and" in front of a new finite verb, "from a walk to a run", and
"… to <whole-body verb>" ("gets up to jump"). Simultaneous markers ("while", "as", "with",
", <verb>ing") stay inside a clause; the decomposer turns them into part edits. Counts ("three
times", "twice", "two squats") become `repeat`; "alternating between A and B four times"
becomes four clauses A, B, A, B.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import partial

from interplay.catalogue import grammar as g
from interplay.catalogue.grammar import COUNT_SAID
from interplay.catalogue.load import counted_once
from interplay.catalogue.phrases import Found, unquoted
from interplay.catalogue.words import lists
from interplay.catalogue.words import words as listed
from interplay.planner.verbs import doing_nouns, gerund, lookup, noun_verb, third

NUMBERS = {"once": 1, "one": 1, "twice": 2, "two": 2, "thrice": 3, "three": 3, "four": 4,
           "five": 5, "six": 6, "seven": 7, "eight": 8, "nine": 9, "ten": 10}


@dataclass
class Clause:
    text: str
    repeat: int = 1
    group: tuple[int, int] | None = None   # (k, n): k-th of n clauses split from one action
    hold: str = ""                         # words that keep its pose to the end ("waits")




def _verb_in(word: str, like: str) -> str | None:
    """`word` ("sitting", "ran") as the verb in the form of `like` ("starts" → "sits")."""
    noun = noun_verb(word)
    hit = lookup(word) or (lookup(noun) if noun else None)
    if hit is None or hit[0].kind == "light":
        return None
    like_hit = lookup(like)
    form = like_hit[1] if like_hit else "third"
    return gerund(hit[0].base) if form == "gerund" else third(hit[0].base)


# A user's imperative ("walk a few steps and wave") in the third person the rules read: the
# verbs that open the prompt and each of its clauses, and "you" as the person.
# (words.toml's list, what it becomes; "{2}": with the word after it), in this order
_YOU = (("you_yourself", "themselves"), ("you_your", "their"), ("you_can", "they {2}"), ("you", "them"))


def _imperative(t: str) -> str:
    """"squat down, stand up and walk away" → "squats down, stands up and walks away" (only
    when the prompt opens with a verb's base form: "a tired walk" is not an order)."""
    first = t.split(" ", 1)[0] if t else ""
    hit = lookup(first)
    if hit is None or hit[1] != "base":
        return t

    def verb(m: re.Match) -> str:
        h = lookup(m.group(2))
        return m.group(1) + (third(h[0].base) if h and h[1] == "base" else m.group(2))
    return g.CLAUSE_OPENS.sub(verb, t)


def _you(new: str, found: Found) -> str:
    return new.replace("{2}", found.text.split()[-1])          # "you can" → "they can"


def normalize(text: str) -> str:
    """Lower case, present tense chains: "is running" → "runs", "starts hopping" → "hops",
    "transitions to sitting" → "sits", "gets up" / "rises to standing" → "stands up";
    imperatives in the third person ("walk, then sit" → "walks, then sits", "your" → "their")."""
    t = text.lower().replace("’", "'").replace("‘", "'").replace("“", '"').replace("”", '"')
    t = unquoted(t)
    for said, new in _YOU:
        t = listed(said).sub(t, partial(_you, new))
    t = _imperative(t.strip())
    t = listed("progressive").sub(t, lambda found: _verb_in(found.text.split()[-1], "runs") or found.text)
    t = listed("gets_up").sub(t, lambda found: _stands(found.text) + " up")
    t = listed("rises_to_stand").sub(t, lambda found: _stands(found.text) + " up")
    t = listed("light_chain").sub(t, lambda found: _verb_in(found.text.split()[-1], found.text.split()[0]) or found.text)
    return " ".join(t.split())


def _stands(said: str) -> str:
    """"getting up" → "standing", "gets up" → "stands" (the form of its first word)."""
    return "standing" if said.split()[0].endswith("ing") else "stands"


def _noun_to_verb(text: str) -> tuple[str, int]:
    """"… does two squats …" / "a full turn" → ("… squats …", 2) / ("turns around", 1): a motion
    noun after a light verb (anywhere), or a clause that is only a motion noun phrase."""
    for m in g.NOUN_ACT.finditer(text):
        light, det, adj, noun = m.groups()
        if light is None and (m.start() > 0 or not (det or adj)
                              or any(lookup(w) for w in text[m.end():].split())):
            continue                        # a bare noun only counts alone ("a full turn")
        count = int(det) if (det or "").isdigit() else NUMBERS.get(det or "", 1)
        head, rest = text[:m.start()], text[m.end():]
        doing = doing_nouns()
        key = noun[:-1] if noun.endswith("s") and noun[:-1] in doing else noun
        if key in doing:
            return f"{head}does a {key}{rest}", count
        verb = noun_verb(noun)
        if verb is None:
            continue
        around = " around" if verb in ("turn", "spin") and "full" in (adj or "") else ""
        if det in ("a", "an", "one") and verb in counted_once() and not COUNT_SAID.search(rest):
            around += " once"               # "does one squat", "throws a punch": one, said
        return f"{head}{third(verb)}{around}{rest}", count
    return text, 1


def _clean(piece: str) -> tuple[str, int]:
    piece = piece.strip(" ,.;:!?")
    while True:
        lead = listed("leading_word").starts(piece)
        rest = piece[lead.end:] if lead else piece
        while lead and rest[:1] and (rest[0] == "," or rest[0].isspace()):
            rest = rest[1:]
        new = rest.strip(" ,")
        if new == piece:
            break
        piece = new
    piece = g.AGAIN_STILL.sub(" ", piece)
    piece = " ".join(piece.split()).strip(" ,")
    first = piece.split(" ", 1)[0] if piece else ""
    hit = lookup(first)
    if hit and hit[1] == "gerund" and hit[0].kind != "light":    # "before jumping" → "jumps"
        piece = third(hit[0].base) + piece[len(first):]
    piece, count = _noun_to_verb(piece)
    m = next((m for m in COUNT_SAID.finditer(piece) if (m.group(3) or "").lower() != "time"), None)
    if m:                                       # "once", "twice", "three times" (not "one time")
        word = (m.group(1) or m.group(2)).lower()
        count = int(word) if word.isdigit() else NUMBERS[word]
    elif count > 1:
        piece += " twice" if count == 2 else f" {count} times"
    return piece.strip(" ,"), count


def starts_action(text: str) -> bool:
    """Does this text begin with a (subject and a) finite verb, i.e. a new action?"""
    stripped = text.strip(" ,")
    head = next((w for w in ("and", "then", "also")
                 if stripped.startswith(w) and stripped[len(w):len(w) + 1].isspace()), "")
    words = stripped[len(head):].split()
    if not words:
        return False
    i, plural = 0, False
    if words[0] in lists()["clause_pronouns"]:
        i, plural = 1, words[0] in ("they", "both", "we", "you", "i")
    elif words[0] in lists()["clause_determiners"]:
        for j in range(1, min(4, len(words))):
            if words[j] in lists()["clause_not_subject"] or words[j] in ("to", "of", "with", "in", "on"):
                return False
            if lookup(words[j]):
                i, plural = j, words[0] == "two" or words[j - 1].endswith("s")
                break
        else:
            return False
    if i >= len(words):
        return False
    hit = lookup(words[i])
    if hit is None:
        return False
    return hit[1] in ("third", "past") or (hit[1] == "base" and plural)


def _split_and(fragment: str) -> list[str]:
    parts = fragment.split(" and ")             # a normalised text: words one space apart
    out: list[str] = []
    for p in parts:
        if out and starts_action(p):
            out.append(p)
        elif out:
            out[-1] += " and " + p
        else:
            out.append(p)
    return out


def _split_to(text: str) -> list[str]:
    """"stands up to jump" → ["stands up", "jump"] when a whole-body verb follows "to"."""
    at, word = text.find(" to "), ""            # a normalised text: words one space apart
    while at >= 0 and not word:
        end = at + 4
        while end < len(text) and (text[end].isalnum() or text[end] == "_"):
            end += 1                            # the word after "to" (letters, digits, _)
        word = text[at + 4:end]
        at = at if word else text.find(" to ", at + 1)
    if word:
        hit = lookup(word)
        head = text[:at].split()
        has_verb = any((h := lookup(w)) and h[0].kind != "light" for w in head)
        if hit and hit[0].kind in ("whole", "travel") and hit[1] != "gerund" and has_verb:
            return [text[:at], third(hit[0].base) + text[at + 4 + len(word):]]
    return [text]


def _reorder(sentence: str) -> list[str]:
    """Pieces of a sentence in the order they happen ("before"/"after")."""
    m = g.BEFORE_AFTER.match(sentence)
    if m is None or m.lastindex is None:
        return [sentence]
    parts = (m.group(m.lastindex - 1), m.group(m.lastindex))
    return [parts[k] for k in g.BEFORE_AFTER_ORDER[m.lastindex // 2 - 1]]


def _expand(text: str) -> list[tuple[str, tuple[int, int] | None]]:
    """"from a walk to a run, holding X" → two clauses; alternation → n clauses."""
    m = g.FROM_TO.search(text)
    if m:
        a, b = (noun_verb(w) or _base(w) for w in m.groups())
        if a and b:
            head, tail = text[:m.start()].strip(), text[m.end():]
            head = head + " " if head else ""
            return [(f"{head}{third(a)}{tail}", None), (f"{third(b)}{tail}", None)]
    m = g.ALTERNATE.search(text)
    if m:
        main = text[:m.start()].strip(" ,")
        acts = [_act(m.group(1)), _act(m.group(2))]
        word = m.group(3) or m.group(4) or ""
        n = int(word) if word.isdigit() else NUMBERS.get(word, 2)
        doing = []                                          # "taps the foot" → "tapping the foot"
        for act in acts:
            verb, _, rest = act.partition(" ")
            base = _base(verb)
            doing.append(f"{gerund(base)} {rest}".strip() if base is not None else act)
        return [(f"{main} while {doing[k % 2]}" if main else acts[k % 2], (k, n)) for k in range(n)]
    return [(text, None)]


def _base(word: str) -> str | None:
    """The base form of the verb `word` ("sat" → "sit"), None for other words."""
    hit = lookup(word)
    return hit[0].base if hit else None


def _act(phrase: str) -> str:
    """"foot taps" → "taps the right foot", "hand claps" → "claps the hands"."""
    words = phrase.split()
    verb = noun_verb(words[-1]) or _base(words[0]) or words[-1]
    obj = [w for w in words if w != words[-1]]
    thing = {"foot": "the right foot", "feet": "the feet", "hand": "the hands",
             "hands": "the hands", "toe": "the right foot", "knee": "the right knee"}
    return f"{third(verb)} {thing.get(obj[-1], ' '.join(obj)) if obj else ''}".strip()


def _comma_parts(piece: str) -> list[str]:
    """The piece split at its commas, without the spaces around them."""
    parts = piece.split(",")
    out = []
    for i, part in enumerate(parts):
        part = part.lstrip() if i > 0 else part
        out.append(part.rstrip() if i < len(parts) - 1 else part)
    return out


def split(text: str) -> list[Clause]:
    """Ordered clauses of a normalised prompt."""
    pieces: list[str] = []
    for sentence in g.SENTENCE_END.split(text):
        for part in _reorder(sentence.strip(" .!?;")):
            pieces.extend(p for p in g.CONNECTIVE.split(part) if p and p.strip(" ,"))
    clauses: list[Clause] = []
    for piece in pieces:
        fragments: list[str] = []
        for frag in _comma_parts(piece):
            for k, sub in enumerate(_split_and(frag)):
                if k == 0 and fragments and not starts_action(sub):
                    fragments[-1] += ", " + sub      # a modifier of the previous action
                else:
                    fragments.append(sub)
        for frag in fragments:
            for part in _split_to(frag):
                for text_k, group in _expand(part):
                    clean, count = _clean(text_k)
                    if clean:
                        clauses.append(Clause(clean, count, group))
    return clauses
