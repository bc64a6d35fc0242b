"""What a two-person prompt asks the two people to do together: one interaction kind, who
starts it, and whether they walk up to each other first. Read from the prompt's words (the
catalogue's `interaction` entries, `actions.toml`, in file order: the first whose words are
in the prompt), else from the MiniLM text encoder (the nearest of the entries' descriptions,
when it is near enough and not nearer a prompt this generator leaves to another, such as
dancing); the planner's per-person roles, when a segment carries them, say who does what.
Every decision comes with its reason, for the plan. The words it looks for besides the
entries' own are actions.toml's `[words.lists]` (`interaction_*`, `one_stops_subject`,
`first_named`, `first_responds_<kind>`, `touch_part_<part>`).

    script = read_script("one pushes the other, who stumbles backwards", roles, encoder)
    script.kind, script.actor, script.reasons     # "push", 0, ("'push' in the prompt: …", …)
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from interplay.catalogue.grammar import words_of, words_rx
from interplay.catalogue.load import catalogue, on_change

# The kinds, in a fixed order (a scene's random draws are seeded by the kind's place here).
KINDS = ("handshake", "high_five", "hug", "push", "wave", "wave_back", "bow", "mirror",
         "follow", "one_stops", "side_by_side", "approach", "together", "help_up", "spar",
         "hand_over", "touch", "chase", "carry", "lead", "face_to_face")
CONTACT = ("handshake", "high_five", "hug", "push", "help_up", "hand_over", "touch", "carry",
           "lead")  # they touch
APPROACHABLE = ("handshake", "high_five", "hug", "approach")

MIN_SIMILARITY = 0.6
# What the one who starts it does, as the reasons say it.
_VERB = {"push": "pushes", "wave_back": "waves first", "follow": "leads", "one_stops": "stops",
         "mirror": "leads (the other mirrors)", "help_up": "helps", "hand_over": "hands it over",
         "touch": "touches", "chase": "chases", "spar": "strikes first", "carry": "carries",
         "lead": "leads"}
# Kinds whose prompt may name the response first ("the man runs away while the woman chases
# him", "she takes a cup from him"): the first-named person is then the one who responds.
_RESPONSE_FIRST = ("help_up", "hand_over", "touch", "chase", "carry", "lead")


@dataclass(frozen=True)
class Script:
    """kind: one of KINDS; actor: the person who starts it (the pusher, the first to wave or
    bow, the leader who is followed or copied, the one who stops, the helper, the giver, the
    one who touches, the chaser), the other responds; approach: they walk up to each other
    first; held: hands held (side by side)."""
    kind: str
    actor: int = 0
    approach: bool = False
    held: bool = False
    reasons: tuple[str, ...] = field(default_factory=tuple)
    part: str | None = None     # touch: the partner's part the hand goes to
    guessed: float | None = None  # read by the text encoder, not the words: its cosine

    def to_json(self) -> dict:
        out = {"kind": self.kind, "actor": self.actor, "approach": self.approach,
               "held": self.held, "reasons": list(self.reasons)}
        if self.part is not None:
            out["part"] = self.part
        if self.guessed is not None:
            out["guessed"] = self.guessed
        return out


@dataclass(frozen=True)
class _Entry:
    kind: str
    words: tuple[str, ...]
    not_before: tuple[str, ...]
    descriptions: tuple[str, ...]
    parts: tuple[str, ...]


@lru_cache(maxsize=1)
def entries() -> tuple[_Entry, ...]:
    """The catalogue's two-person entries made by composition, in file order."""
    out = []
    for a in catalogue().of_kind("interaction"):
        kind = a.made_by.composition
        if kind in KINDS and 2 in a.persons:
            out.append(_Entry(kind, tuple(a.words), tuple(a.not_before), tuple(a.descriptions), tuple(a.parts)))
    return tuple(out)


on_change(entries.cache_clear)


@lru_cache(maxsize=1)
def _roles() -> tuple[dict[str, tuple[str, ...]], dict[str, tuple[str, ...]]]:
    """The kinds' role words from their catalogue entries: who starts it (the pusher) and who
    responds (the pushed), for the kinds that name them."""
    actor: dict[str, tuple[str, ...]] = {}
    responder: dict[str, tuple[str, ...]] = {}
    for a in catalogue().of_kind("interaction"):
        kind = a.made_by.composition
        if kind in KINDS and a.actor_words:
            actor[kind] = tuple(a.actor_words)
        if kind in KINDS and a.responder_words:
            responder[kind] = tuple(a.responder_words)
    return actor, responder


on_change(_roles.cache_clear)


def _listed(name: str) -> tuple[str, ...]:
    return tuple(catalogue().words.lists.get(name, ()))


def _touch_parts() -> tuple[str, ...]:
    """The parts with words of their own (`touch_part_<part>`), in file order."""
    return tuple(n.removeprefix("touch_part_") for n in catalogue().words.lists if n.startswith("touch_part_"))


def _approach() -> tuple[str, ...]:
    """"walks towards each other", "approaches": they walk up to each other first."""
    return tuple(f"{v} {to}" for v in _listed("approach_moves") for to in _listed("approach_to")) \
        + _listed("approach")


def _match(words, text: str, not_before=()) -> str | None:
    m = words_rx(tuple(words), tuple(not_before)).search(text)
    return m.group(0) if m else None


def _one_stops(text: str, e: _Entry) -> str | None:
    """The stop word after "one" / "the other" … in the same sentence."""
    for sentence in text.split("."):
        one = words_rx(_listed("one_stops_subject")).search(sentence)
        if one:
            stop = words_rx(e.words, e.not_before).search(sentence, one.end())
            if stop:
                return sentence[one.start():stop.end()].strip()
    return None


def keyword_kind(prompt: str) -> tuple[str | None, str]:
    """(kind, reason) by keywords, or (None, why not)."""
    text = words_rx(_listed("interaction_look_alike")).sub(" ", prompt)
    for e in entries():
        word = _one_stops(text, e) if e.kind == "one_stops" else _match(e.words, text, e.not_before)
        if word and not (e.kind == "together" and _match(_listed("interaction_not_together"), prompt)):
            return e.kind, f"'{word}' in the prompt: {e.kind}"
    word = _match(_listed("interaction_not_mine"), prompt)
    if word:
        return None, f"'{word}' in the prompt: not an interaction this generator composes"
    return None, "no interaction keyword in the prompt"


def _prototypes() -> list[tuple[str | None, str]]:
    return [(e.kind, d) for e in entries() for d in e.descriptions] + [(None, d) for d in _listed("interaction_others")]


def encoder_kind(prompt: str, encoder) -> tuple[str | None, str]:
    """(kind, reason) by the nearest prototype description, or (None, why not)."""
    kind, why, _ = _encoder_read(prompt, encoder)
    return kind, why


def _left_to_other(prompt: str, encoder) -> bool:
    """The nearest description is one this generator leaves to another, near enough to count."""
    protos = _prototypes()
    emb = np.asarray(encoder.encode([t for _, t in protos] + [prompt]))
    sims = emb[:-1] @ emb[-1]
    best = int(np.argmax(sims))
    return protos[best][0] is None and float(sims[best]) >= MIN_SIMILARITY


def _encoder_read(prompt: str, encoder) -> tuple[str | None, str, float]:
    """(kind or None, reason, cosine to the nearest prototype description)."""
    protos = _prototypes()
    texts = [t for _, t in protos]
    emb = np.asarray(encoder.encode(texts + [prompt]))
    sims = emb[:-1] @ emb[-1]
    best = int(np.argmax(sims))
    kind, text, sim = protos[best][0], texts[best], float(sims[best])
    if kind is None:
        return None, f"nearest description '{text}' ({sim:.2f}) is not one this generator composes", sim
    if sim < MIN_SIMILARITY:
        return None, f"nearest description '{text}' is only {sim:.2f} similar (< {MIN_SIMILARITY})", sim
    return kind, f"the text encoder: nearest description '{text}' ({sim:.2f})", sim


def _starts(kind: str, text: str) -> bool:
    actor = _roles()[0]
    if kind == "wave_back":       # waves, and not back
        return bool(_match(actor[kind], text)) and not _match(("back",), text)
    return bool(_match(actor.get(kind, ()), text))


def _first_responds(kind: str, prompt: str) -> bool:
    """"One person follows the other": the subject the prompt names first does the response."""
    w = words_of(prompt)
    if w[:2] == ["the", "first"]:
        w = w[2:]
    elif w[:1] and w[0] in _listed("first_named"):
        w = w[1:]
    else:
        return False
    if w[:1] == ["person"]:
        w = w[1:]
    elif w[:2] == ["of", "them"]:
        w = w[2:]
    return bool(w) and w[0] in _listed(f"first_responds_{kind}")


def _actor(kind: str, prompt: str, roles: dict | None) -> tuple[int, str]:
    """Who starts: by the planner's roles when they tell the two apart (a role's words for
    starting count for it, its words for responding against it), else by the prompt (the
    'one' it names first starts, unless what that one does is the response)."""
    verb = _VERB.get(kind, "starts")
    actor, responder = _roles()
    if roles and kind in responder:
        texts = [str(roles.get("0", "")), str(roles.get("1", ""))]
        responds = [bool(_match(responder[kind], t)) for t in texts]
        starts = [_starts(kind, t) if kind in actor else False for t in texts]
        score = [int(s) - int(r) for s, r in zip(starts, responds)]
        if score[0] != score[1]:
            who = int(np.argmax(score))
            return who, f"roles: person {who} {verb} ('{texts[who]}'; the other: '{texts[1 - who]}')"
    if _first_responds(kind, prompt):
        return 1, f"person 1 {verb} (the prompt's first-named one responds)"
    if kind in _RESPONSE_FIRST:
        said = [words_rx(responder[kind]).search(prompt), words_rx(actor[kind]).search(prompt)]
        if said[0] and (said[1] is None or said[0].start() < said[1].start()):
            return 1, f"person 1 {verb} (the prompt names the response first: '{said[0].group(0)}')"
    return 0, f"person 0 {verb} (the one the prompt names first)"


def touched_part(prompt: str) -> tuple[str, str]:
    """(part, reason): the partner's part a touch goes to, the first the prompt names of the
    touch entry's parts (shoulder by default)."""
    parts = next((e.parts for e in entries() if e.kind == "touch"), ()) or _touch_parts()
    found = []
    for p in parts:
        m = words_rx(_listed(f"touch_part_{p}") or (p,)).search(prompt)
        if m:
            found.append((m.start(), p, m.group(0)))
    if not found:
        return "shoulder", "no body part named: the shoulder"
    if len(found) > 1:        # "puts a hand on her shoulder": the hand is the toucher's own
        found = [f for f in found if f[1] != "hand"]
    _, part, word = min(found)
    return part, f"'{word}' in the prompt: the hand goes to the other's {part}"


def read_script(prompt: str, roles: dict | None = None, encoder=None) -> Script | None:
    """The prompt's interaction (see the module doc), or None when it has none this
    generator composes (the reasons are then in `why_not`)."""
    kind, why = keyword_kind(prompt)
    reasons = [why]
    guessed = None
    if kind is None and encoder is not None and not _match(_listed("interaction_not_mine"), prompt):
        kind, why, guessed = _encoder_read(prompt, encoder)
        reasons.append(why)
    if kind is None:
        return None
    actor, who = _actor(kind, prompt, roles)
    approach = kind == "approach" or (kind in APPROACHABLE and bool(_match(_approach(), prompt)))
    held = kind == "side_by_side" and bool(_match(_listed("hands_held"), prompt))
    part = None
    if kind == "touch":
        part, where = touched_part(prompt)
        reasons.append(where)
    if kind != "approach" and approach:
        reasons.append("they walk up to each other first")
    if held:
        reasons.append("hands held")
    if kind in _roles()[1]:
        reasons.append(who)
    return Script(kind, actor, approach, held, tuple(reasons), part,
                  None if guessed is None else round(guessed, 4))


def fallback(prompt: str, encoder) -> Script | None:
    """Two people whose words name no kind near enough, and that no other generator takes (a
    dance, a jump, push-ups: the entries' `not mine` words; the nearest description one left
    to another): each does their own part of the words, facing the other (`face_to_face`),
    read as the weakest guess (its cosine to the nearest description)."""
    if _match(_listed("interaction_not_mine"), prompt):
        return None
    kind, why, sim = _encoder_read(prompt, encoder)
    if kind is not None or _left_to_other(prompt, encoder):
        return None
    return Script("face_to_face", 0, False, False,
                  (why, "no interaction named or near enough: each does their own part of the "
                        "words, facing the other"), None, round(min(sim, MIN_SIMILARITY), 4))


def kind_checks(kind: str) -> list[dict]:
    """The pair checks the catalogue names for a kind (its entry's `checks`, as run_check specs)."""
    from interplay.catalogue.schema import specs
    entry = next((a for a in catalogue().of_kind("interaction") if a.made_by.composition == kind), None)
    return specs(entry) if entry is not None else []


def why_not(prompt: str, encoder=None) -> str:
    """Why `read_script` found no interaction in a prompt."""
    kind, why = keyword_kind(prompt)
    if kind is None and encoder is not None and not _match(_listed("interaction_not_mine"), prompt):
        return f"{why}; {encoder_kind(prompt, encoder)[1]}"
    return why
