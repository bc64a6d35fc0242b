"""What a two-person prompt asks the two people to do together: one interaction kind, who
starts it, and whether they walk up to each other first. Read from the prompt's words
(keywords, first match wins), else from the MiniLM text encoder (the nearest of a few
descriptions per kind, when it is near enough and not nearer a kind this generator leaves to
another, such as dancing); the planner's per-person roles, when a segment carries them, say
who does what. Every decision comes with its reason, for the plan.

    script = read_script("one pushes the other, who stumbles backwards", roles, encoder)
    script.kind, script.actor, script.reasons     # "push", 0, ("'push' in the prompt: …", …)
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

import numpy as np

KINDS = ("handshake", "high_five", "hug", "push", "wave", "wave_back", "bow", "mirror",
         "follow", "one_stops", "side_by_side", "approach", "together")
CONTACT = ("handshake", "high_five", "hug", "push")     # kinds where the two touch
APPROACHABLE = ("handshake", "high_five", "hug", "approach")

# Keywords, in order: the first kind whose pattern matches is the prompt's.
_PATTERNS: tuple[tuple[str, str], ...] = (
    ("push", r"\bpush(?![\s-]?ups?\b)\w*|\bshov\w*"),
    ("hug", r"\bhug\w*|\bembrac\w*|\bcuddl\w*|\barms? (a)?round each other"),
    ("high_five", r"\bhigh[\s-]?fiv\w*|\bhi[\s-]?fiv\w*"),
    ("handshake", r"\bshak\w* (each other'?s? )?hands?\b|\bhandshakes?\b"),
    ("wave_back", r"\bwav\w* back\b|\breturns? the wave\b|\bwav\w* in return\b"),
    ("wave", r"\bwav(e|es|ed|ing)\b"),
    ("bow", r"\bbow(s|ed|ing)?\b"),
    ("mirror", r"\bmirror\w*|\bcop(y|ies|ied|ying)\b|\bimitat\w*|\bmimic\w*"),
    ("follow", r"\bfollow(?!ers?\b)\w*|\bchas(e|es|ed|ing)\b|\bbehind\b"),
    ("one_stops", r"\b(one|the other|one of them|one person)\b[^.]*\bstops?\b"),
    ("side_by_side", r"\bside by side\b|\bnext to each other\b|\bbeside each other\b|"
                     r"\balongside\b|\bhand in hand\b|\bhold\w* hands\b|\bwalk\w* together\b"),
    ("approach", r"\b(towards?|up to) each other\b|\bapproach\w*|\bmeet\b"),
    # both do one person's action side by side ("two people jump together"); not a couple's
    # dance or a fight, which are one motion of two people
    ("together", r"\btogether\b|\bat the same time\b|\bin unison\b|\bin sync\w*|"
                 r"\bsimultaneous\w*|\bboth (of them )?\w+s?\b"),
)
_NOT_TOGETHER = r"\bdanc\w*|\bsalsa\b|\btango\b|\bwaltz\w*|\bfight\w*|\bbox(ing)?\b|\bspar\w*|\bwrestl\w*"
# Prompts this generator leaves to another (checked before the encoder's guess).
_NOT_MINE = r"\bpush[\s-]?ups?\b|\bdanc\w*|\bleader\b|\bfollower\b|\btwirl\w*|\bsalsa\b|\btango\b|\bwaltz\w*|\bjump\w*|\bfight\w*|\bbox(ing)?\b|\bspar\w*"
_HELD = r"\bhand in hand\b|\bhold\w* hands\b|\bholding each other'?s? hands?\b"
_APPROACH = r"\b(walk|come|run|step|move|head)\w* (up )?(to|towards?) each other\b|\bapproach\w*|" \
            r"\bwalk\w* up to\b"

# The encoder's descriptions: kinds, and (None) what is left to another generator.
_PROTOTYPES: tuple[tuple[str | None, str], ...] = (
    ("handshake", "two people shake hands"), ("handshake", "they greet each other with a handshake"),
    ("high_five", "two people give each other a high five"),
    ("hug", "two people hug each other"), ("hug", "two friends embrace"),
    ("push", "one person pushes the other away"),
    ("wave", "two people wave at each other"), ("wave_back", "one waves and the other waves back"),
    ("bow", "two people bow to each other"),
    ("mirror", "one person copies the other's movements like a mirror"),
    ("follow", "one person follows the other"),
    ("one_stops", "two people walk side by side, then one stops"),
    ("side_by_side", "two people walk side by side"), ("side_by_side", "two people stroll beside one another"),
    ("approach", "two people walk towards each other"),
    (None, "two people dance together"),
    (None, "two people fight"), (None, "two people play a game"), (None, "two people sit down"),
    (None, "two people salute each other"), (None, "two people exercise"), (None, "two people clap"),
)
MIN_SIMILARITY = 0.6
# Role words: who does the kind's first action (actor) and who responds.
_ACTOR = {"push": r"\bpush|\bshov", "wave_back": r"^(?!.*\bback\b).*\bwav", "follow": r"\blead|\bahead|\bin front",
          "one_stops": r"\bstop|\bhalt|\bstands? still"}
_RESPONDER = {"push": r"\bstumbl|\bpushed\b|\bfall|\bstagger|\bknock", "wave_back": r"\bwav\w* back|\breturn",
              "follow": r"\bfollow|\bbehind", "one_stops": r"\bkeeps? (on )?walking|\bcontinues",
              "mirror": r"\bcop|\bmirror|\bimitat|\bmimic"}


@dataclass(frozen=True)
class Script:
    """kind: one of KINDS; actor: the person who starts it (the pusher, the first to wave or
    bow, the leader who is followed or copied, the one who stops), the other responds;
    approach: they walk up to each other first; held: hands held (side by side)."""
    kind: str
    actor: int = 0
    approach: bool = False
    held: bool = False
    reasons: tuple[str, ...] = field(default_factory=tuple)

    def to_json(self) -> dict:
        return {"kind": self.kind, "actor": self.actor, "approach": self.approach,
                "held": self.held, "reasons": list(self.reasons)}


def _match(pattern: str, text: str) -> str | None:
    m = re.search(pattern, text, re.I)
    return m.group(0) if m else None


def keyword_kind(prompt: str) -> tuple[str | None, str]:
    """(kind, reason) by keywords, or (None, why not)."""
    for kind, pattern in _PATTERNS:
        word = _match(pattern, prompt)
        if word and not (kind == "together" and _match(_NOT_TOGETHER, prompt)):
            return kind, f"'{word}' in the prompt: {kind}"
    word = _match(_NOT_MINE, prompt)
    if word:
        return None, f"'{word}' in the prompt: not an interaction this generator composes"
    return None, "no interaction keyword in the prompt"


def encoder_kind(prompt: str, encoder) -> tuple[str | None, str]:
    """(kind, reason) by the nearest prototype description, or (None, why not)."""
    texts = [t for _, t in _PROTOTYPES]
    emb = np.asarray(encoder.encode(texts + [prompt]))
    sims = emb[:-1] @ emb[-1]
    best = int(np.argmax(sims))
    kind, text, sim = _PROTOTYPES[best][0], texts[best], float(sims[best])
    if kind is None:
        return None, f"nearest description '{text}' ({sim:.2f}) is not one this generator composes"
    if sim < MIN_SIMILARITY:
        return None, f"nearest description '{text}' is only {sim:.2f} similar (< {MIN_SIMILARITY})"
    return kind, f"the text encoder: nearest description '{text}' ({sim:.2f})"


_VERB = {"push": "pushes", "wave_back": "waves first", "follow": "leads", "one_stops": "stops",
         "mirror": "leads (the other mirrors)"}
# Prompts whose first-named person is the one who responds ("one person follows the other").
_SUBJECT = r"^\W*(one|a|the first)( person| of them)?\s+"
_FIRST_RESPONDS = {"follow": _SUBJECT + r"(follows?|chases?|trails?)\b",
                   "mirror": _SUBJECT + r"(cop(y|ies)|mirrors?|imitates?|mimics?)\b"}


def _actor(kind: str, prompt: str, roles: dict | None) -> tuple[int, str]:
    """Who starts: by the planner's roles when they tell the two apart (a role's words for
    starting count for it, its words for responding against it), else by the prompt (the
    'one' it names first starts, unless what that one does is the response)."""
    verb = _VERB.get(kind, "starts")
    if roles and kind in _RESPONDER:
        texts = [str(roles.get("0", "")), str(roles.get("1", ""))]
        responds = [bool(re.search(_RESPONDER[kind], t, re.I)) for t in texts]
        starts = [bool(re.search(_ACTOR[kind], t, re.I)) if kind in _ACTOR else False for t in texts]
        score = [int(s) - int(r) for s, r in zip(starts, responds)]
        if score[0] != score[1]:
            who = int(np.argmax(score))
            return who, f"roles: person {who} {verb} ('{texts[who]}'; the other: '{texts[1 - who]}')"
    if kind in _FIRST_RESPONDS and re.search(_FIRST_RESPONDS[kind], prompt, re.I):
        return 1, f"person 1 {verb} (the prompt's first-named one responds)"
    return 0, f"person 0 {verb} (the one the prompt names first)"


def read_script(prompt: str, roles: dict | None = None, encoder=None) -> Script | None:
    """The prompt's interaction (see the module doc), or None when it has none this
    generator composes (the reasons are then in `why_not`)."""
    kind, why = keyword_kind(prompt)
    reasons = [why]
    if kind is None and encoder is not None and not _match(_NOT_MINE, prompt):
        kind, why = encoder_kind(prompt, encoder)
        reasons.append(why)
    if kind is None:
        return None
    actor, who = _actor(kind, prompt, roles)
    approach = kind == "approach" or (kind in APPROACHABLE and bool(_match(_APPROACH, prompt)))
    held = kind == "side_by_side" and bool(_match(_HELD, prompt))
    if kind != "approach" and approach:
        reasons.append("they walk up to each other first")
    if held:
        reasons.append("hands held")
    if kind in _RESPONDER:
        reasons.append(who)
    return Script(kind, actor, approach, held, tuple(reasons))


def why_not(prompt: str, encoder=None) -> str:
    """Why `read_script` found no interaction in a prompt."""
    kind, why = keyword_kind(prompt)
    if kind is None and encoder is not None and not _match(_NOT_MINE, prompt):
        return f"{why}; {encoder_kind(prompt, encoder)[1]}"
    return why
