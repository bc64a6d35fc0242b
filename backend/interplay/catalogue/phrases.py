"""Phrases found in a text as sequences of words, without regular expressions: the text is split
into words once (a word is a run of letters, digits and underscores, what a regular expression's
`\\b…\\b` sees as one), a phrase is words in order.

    Phrases(["shak* [each other|each other's] (hand|hands)"]).search("shaking hands")
      → Found(start=0, end=13, text='shaking hands')

A phrase is written in the catalogue's template notation: words in order; `*` in a word any
letters there ("hug*": hug, hugs, hugging; "*greet*": greets, regreet), a leading `?` one; `*` alone any one word;
`(a|b c)` one of; `[a|b]` one of or none; `[a|b]*` any number of them; `~3` up to three words between; `...` any words and
marks between; and at the end `!(a|b)`: the phrase may not go on with these. Words are joined
by spaces in the text; a hyphen in a phrase's word ("high-five") takes spaces or hyphens there,
an apostrophe ("other's") the apostrophe alone. Letters compare as written unless the phrases
are read with `ignore_case`.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass


@dataclass(frozen=True)
class Token:
    text: str
    start: int
    end: int


@dataclass(frozen=True)
class Found:
    start: int
    end: int
    text: str


def tokens(text: str) -> list[Token]:
    """The words of `text` with their places."""
    out, start = [], -1
    for i, c in enumerate(text + " "):
        inside = c.isalnum() or c == "_"
        if inside and start < 0:
            start = i
        elif not inside and start >= 0:
            out.append(Token(text[start:i], start, i))
            start = -1
    return out


def unquoted(text: str) -> str:
    """Double quotes out, and single ones but an apostrophe between two letters ("don't")."""
    letters = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"

    def kept(i: int, c: str) -> bool:
        inside = 0 < i < len(text) - 1 and text[i - 1] in letters and text[i + 1] in letters
        return c != '"' and (c != "'" or inside)
    return "".join(c for i, c in enumerate(text) if kept(i, c))


def one_space(text: str) -> str:
    """Each run of spaces (tabs, line ends) as one space, the ends too ("  a  b " → " a b ")."""
    inner = " ".join(text.split())
    if not inner:
        return " " if text else ""
    return (" " if text[0].isspace() else "") + inner + (" " if text[-1].isspace() else "")


# A parsed phrase is a list of slots; a slot is words (one of its alternatives, or none when
# optional) or a gap of up to n words. An alternative is a tuple of (word, joint): the joint says
# what stands before the word in the text: " " spaces, "-" spaces or hyphens, "'" an apostrophe.
Word = tuple[str, str]


@dataclass(frozen=True)
class Slot:
    alternatives: tuple[tuple[Word, ...], ...] = ()
    optional: bool = False
    gap: int = 0
    negative: bool = False      # "!(a|b)" at the end: the phrase may not go on with these
    repeated: bool = False      # "[a|b]*": any number of them, or none


def _words(alternative: str) -> tuple[Word, ...]:
    out: list[Word] = []
    for word in alternative.split():
        parts, joints = [word], [" "]
        for sep in ("-", "'"):
            if sep in word.strip(sep):
                parts = word.split(sep)
                joints = [" "] + [sep] * (len(parts) - 1)
        out += zip(parts, joints)
    return tuple(out)


def parse(template: str) -> list[Slot]:
    """The slots of one phrase (see the module's notation)."""
    slots: list[Slot] = []
    rest = template.strip()
    while rest:
        negative = rest.startswith("!(")
        if rest[0] in "([" or negative:
            close = rest.find("]" if rest[0] == "[" else ")")
            if close < 0:
                raise ValueError(f"{template!r}: {rest[0]} not closed")
            body = rest[1 + negative:close]
            repeated = rest[0] == "[" and rest[close + 1:close + 2] == "*"
            slots.append(Slot(tuple(_words(a) for a in body.split("|")), optional=rest[0] == "[",
                              negative=negative, repeated=repeated))
            rest = rest[close + 1 + repeated:].lstrip()
            if negative and rest:
                raise ValueError(f"{template!r}: words after !(…)")
            continue
        word, _, rest = rest.partition(" ")
        rest = rest.lstrip()
        if word.startswith("~") and word[1:].isdigit():
            slots.append(Slot(gap=int(word[1:])))
        elif word == "...":
            slots.append(Slot(gap=-1))
        elif "(" in word or "[" in word:
            raise ValueError(f"{template!r}: a bracket inside a word ({word})")
        else:
            slots.append(Slot((_words(word),)))
    return slots


def _same(word: str, token: str) -> bool:
    """Whether a token is the word; a `*` in the word stands for any letters ("hug*", "*ing*"),
    a leading `?` for one ("?*ing": a word ending in "ing" after at least one letter)."""
    if word.startswith("?"):
        return bool(token) and _same(word[1:], token[1:])
    if "*" not in word:
        return token == word
    head, *middle, tail = word.split("*")
    if not (token.startswith(head) and token.endswith(tail) and len(token) >= len(head) + len(tail)):
        return False
    at, end = len(head), len(token) - len(tail)
    for part in middle:
        at = token.find(part, at, end)
        if at < 0:
            return False
        at += len(part)
    return True


def _joined(text: str, before: Token, after: Token, joint: str) -> bool:
    sep = text[before.end:after.start]
    if joint == "'":
        return sep == "'"
    return sep != "" and all(c.isspace() or (joint == "-" and c == "-") for c in sep)


def _fits(alt: tuple[Word, ...], text: str, toks: list[Token], words: list[str], k: int,
          began: int) -> int | None:
    """Where the words of `alt` end when they start at token k (None: they are not there)."""
    for word, joint in alt:
        if k >= len(toks) or not _same(word, words[k]) or (
                k > began and not _joined(text, toks[k - 1], toks[k], joint)):
            return None
        k += 1
    return k


class Phrases:
    """Phrases to find in texts: leftmost first, the longest there."""

    def __init__(self, templates: Iterable[str], ignore_case: bool = False):
        self.templates = tuple(templates)
        self.slots = [parse(t) for t in self.templates]
        self.ignore_case = ignore_case

    def _ends(self, slots: list[Slot], s: int, text: str, toks: list[Token], words: list[str],
              k: int, began: int) -> Iterator[int]:
        """Token indices where `slots[s:]` can end when it starts at token k."""
        if s == len(slots):
            yield k
            return
        slot = slots[s]
        if slot.gap < 0:                                 # any words, anything between them
            for e in range(k, len(toks) + 1):
                yield from self._ends(slots, s + 1, text, toks, words, e, e)
            return
        if slot.gap:
            yield from self._ends(slots, s + 1, text, toks, words, k, began)
            for _ in range(slot.gap):                    # up to n words ("partner's" is one)
                if k >= len(toks) or (k > began and not _joined(text, toks[k - 1], toks[k], " ")):
                    return
                k += 1
                while k < len(toks) and _joined(text, toks[k - 1], toks[k], "'"):
                    k += 1
                yield from self._ends(slots, s + 1, text, toks, words, k, began)
            return
        fits = (_fits(alt, text, toks, words, k, began) for alt in slot.alternatives)
        ends = [end for end in fits if end is not None]
        if slot.negative:
            if not ends:
                yield from self._ends(slots, s + 1, text, toks, words, k, began)
            return
        for end in ends:
            again = slot.repeated and end > k                 # "[the|his]*": the same slot once more
            yield from self._ends(slots, s if again else s + 1, text, toks, words, end, began)
        if slot.optional:
            yield from self._ends(slots, s + 1, text, toks, words, k, began)

    def _at(self, text: str, toks: list[Token], words: list[str], i: int) -> int:
        """The token index where the longest phrase starting at token i ends (i: none)."""
        return max((e for slots in self.slots for e in self._ends(slots, 0, text, toks, words, i, i)),
                   default=i)

    def _prepared(self, text: str) -> tuple[list[Token], list[str]]:
        toks = tokens(text)
        return toks, [t.text.lower() if self.ignore_case else t.text for t in toks]

    def finditer(self, text: str) -> Iterator[Found]:
        """The phrases in `text`, left to right, not overlapping."""
        toks, words = self._prepared(text)
        i = 0
        while i < len(toks):
            end = self._at(text, toks, words, i)
            if end > i:
                yield Found(toks[i].start, toks[end - 1].end, text[toks[i].start:toks[end - 1].end])
                i = end
            else:
                i += 1

    def search(self, text: str) -> Found | None:
        return next(self.finditer(text), None)

    def starts(self, text: str, pos: int = 0) -> Found | None:
        """The phrase that begins with the word beginning at `pos`, if any."""
        toks, words = self._prepared(text)
        i = next((n for n, t in enumerate(toks) if t.start == pos), None)
        end = self._at(text, toks, words, i) if i is not None else 0
        return Found(toks[i].start, toks[end - 1].end, text[pos:toks[end - 1].end]) \
            if i is not None and end > i else None

    def whole(self, text: str) -> bool:
        """Whether all of `text` is one phrase."""
        toks, words = self._prepared(text)
        if not toks or toks[0].start != 0 or toks[-1].end != len(text):
            return False
        return any(e == len(toks) for slots in self.slots for e in self._ends(slots, 0, text, toks, words, 0, 0))

    def sub(self, text: str, new: Callable[[Found], str], lead: str = "", trail: bool = False,
            clause: bool = False, count: int = 0) -> str:
        """`text` with each phrase (the first `count` of them; 0: all) and what leads up to it
        replaced by `new(found)`: lead "" nothing, " " any spaces, "+" one space or more (a phrase
        without is kept), "," spaces, one comma, spaces; `trail`: the spaces after it too;
        `clause`: the rest of its clause too (up to , . ; ! ? or the end)."""
        out, done, n = "", 0, 0
        for f in self.finditer(text):
            start, end = f.start, f.end
            if start < done:
                continue
            while lead and start > done and text[start - 1].isspace():
                start -= 1
            if lead == "+" and start == f.start:
                continue
            if lead == "," and start > done and text[start - 1] == ",":
                start -= 1
                while start > done and text[start - 1].isspace():
                    start -= 1
            while clause and end < len(text) and text[end] not in ",.;!?":
                end += 1
            while trail and end < len(text) and text[end].isspace():
                end += 1
            out, done, n = out + text[done:start] + new(Found(start, end, text[start:end])), end, n + 1
            if n == count:
                break
        return out + text[done:]

    def cut(self, text: str, lead: str = " ", count: int = 0) -> str:
        """`text` without the phrases and what leads up to each (see `sub`)."""
        return self.sub(text, lambda found: "", lead, count=count)
