"""Two-person exchanges in one clause: who starts, what the other one does, and when.

    exchange("one pushes the other, who stumbles backwards", {})
      → Exchange(lead=0, texts={0: "pushes the other person", 1: "stumbles backwards"},
                 response="contact")         # 1 waits until the push lands, then stumbles
    exchange("one waves at the other, who waves back", {})
      → lead 0 "waves at the other person", then 1 "waves"               (response "after")
    exchange("the leader spins the follower", {})
      → lead 0 "raises the right arm over the other person's head to spin them",
        1 "spins around under the other person's raised arm"            (response "with")
    exchange("one person follows the other around the room", {})
      → lead 1 "walks around the room", 0 "walks … behind the other person" (response "with")
    exchange("they bow in turn", {}) → lead 0 "bows", then 1 "bows"       (response "after")

Forms read: "A does X (to) the other, who Y" (relative clause: the other answers), "A X, and /
while / as the other Y" ("… Y back", "in return", "too": an answer after X; else at the same
time), "the leader X the follower", a verb done to the partner with a known answer ("spins",
"pushes", "pulls", "follows", "chases", "leads", "copies the other's …"), and "in turn" / "take
turns" / "one after the other". Anything else is None: `people.actors` decides who acts.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from interplay.catalogue import grammar as g
from interplay.catalogue.phrases import one_space
from interplay.catalogue.words import lists, words
from interplay.planner.decompose import SUBJECT_NOUNS, Action, decompose
from interplay.planner.manner.travel import direction
from interplay.planner.pair.actors import FIRST, ONE, SECOND, person
from interplay.planner.segments import Step
from interplay.planner.verbs import VERBS, lookup, third

Response = Literal["with", "after", "contact"]
# The people's nouns ("the woman", "her partner"); the sentence structure around them (the
# partner as an object, a clause's subject, "…, and the other …") is grammar.py's.
NOUNS = tuple(sorted(SUBJECT_NOUNS | {"partner", "friend", "follower", "leader"}))
_ROLES = g.two_people(NOUNS)
# verbs the partner answers on contact: words.toml's `contact_verbs`

# Verbs done to the partner whose answer is known: (lead's words, partner's words, response).
# "{rest}" is what followed the partner ("around the room"); lead 1 means the partner leads.
CAUSED: dict[str, tuple[str, str, Response, int]] = {
    "spin": ("raises the right arm over the other person's head to spin them{rest}",
             "spins around under the other person's raised arm{rest}", "with", 0),
    "twirl": ("raises the right arm over the other person's head to spin them{rest}",
              "spins around under the other person's raised arm{rest}", "with", 0),
    "push": ("pushes the other person with both hands{rest}", "stumbles backwards", "contact", 0),
    "shove": ("pushes the other person with both hands{rest}", "stumbles backwards", "contact", 0),
    "pull": ("pulls the other person by the hand{rest}", "stumbles forward", "contact", 0),
    "punch": ("punches the other person{rest}", "staggers backwards", "contact", 0),
    "hit": ("hits the other person{rest}", "staggers backwards", "contact", 0),
    "tackle": ("tackles the other person{rest}", "falls down", "contact", 0),
    "follow": ("walks{rest}", "walks{rest}, following behind the other person", "with", 1),
    "chase": ("runs after the other person{rest}", "runs away{rest}", "with", 0),
    "lead": ("walks forward{rest}, leading the other person by the hand",
             "walks along{rest}, following the other person", "with", 0),
}


@dataclass
class Exchange:
    lead: int                     # who starts
    texts: dict[int, str]         # what each one does (no subject; the partner: "the other person")
    response: Response            # when the other one acts: with the lead, after, at the contact
    why: str

    @property
    def sequential(self) -> bool:
        """Two steps (the lead's action, then the answer), not one."""
        return self.response != "with" and len(self.texts) == 2


def _partner_words(text: str) -> str:
    """"pushes the other" / "pushes him" → "pushes the other person"."""
    text = _ROLES.partner_owns.sub("the other person", text)
    text = _ROLES.partner.sub("the other person", text)
    return " ".join(text.split()).strip(" ,")


def _answer(text: str) -> tuple[str, bool]:
    """(the answer's words, whether it is said to answer: "waves back" → ("waves", True))."""
    t = words("in_return").cut(text, "+")
    return t.strip(" ,"), t != text


def _verb(text: str) -> str | None:
    hit = lookup(text.split(" ", 1)[0]) if text else None
    return hit[0].base if hit else None


def _who(subject: str, names: dict) -> int:
    s = one_space(subject)
    if SECOND.whole(s) or (s[:3] == "the" and s[3:4].isspace() and s[3:].lstrip().startswith("follower")):
        return 1
    if FIRST.whole(s) or ONE.whole(s) or s in ("he", "she"):
        return 0
    return person(s, names)


def _copied(rest: str) -> bool:
    """Does the clause go on with the other copying ("… demonstrates a kick and the other person
    copies it": the mirror's answer, whatever the first one's verb)?"""
    coord = _ROLES.coordinated.match(rest)
    if coord is None or coord.group("answer").split(" ", 1)[0] not in lists()["copy_verbs"]:
        return False
    joint = rest[coord.end("head"):coord.start("answer")].replace(",", " ").split()
    return bool(set(joint) & set(lists()["coordinating"]))      # not "helps the other stand up"


def exchange(text: str, names: dict) -> Exchange | None:
    """The exchange a clause describes (see the module docstring), or None."""
    t = words("take_turns").sub(text, lambda found: f"{found.text.split()[-1]} in turn")
    if words("in_turn").search(t) and words("plural_subject").starts(t):
        rest = _ROLES.plural_subject.sub("", words("in_turn").cut(t, ","))
        hit = lookup(rest.split(" ", 1)[0])
        if hit is None:
            return None
        rest = third(hit[0].base) + rest[len(rest.split(" ", 1)[0]):]      # "bow" → "bows"
        return Exchange(0, {0: rest, 1: rest}, "after", f"roles: '{text}' → one after the other")
    m = _ROLES.subject.match(t)
    if m is None or words("each_other").search(t) or not (lookup(m.group("rest").split(" ", 1)[0])
                                                or g.COPIES_THE_OTHER.match(m.group("rest"))
                                                or _copied(m.group("rest"))):
        return None                  # both do it ("… wave at each other"), or no verb follows
    subject, rest = m.group("subj"), m.group("rest")
    first = _who(subject, names)
    named = _ROLES.named.search(rest)
    if named and named.group(1) not in names:                # "… pushes a woman": the other one
        names[named.group(1)] = 1 - first
    who = g.WHO_ANSWERS.match(rest)
    if who and _ROLES.partner.search(who.group("head")):
        head, (answer, _) = who.group("head"), _answer(who.group("answer"))
        verb = _verb(head)
        response: Response = "contact" if verb in lists()["contact_verbs"] else "after"
        return Exchange(first, {first: _partner_words(head), 1 - first: answer}, response,
                        f"roles: '{text}' → {first} {head}, then {1 - first} {answer} "
                        f"({'from the contact' if response == 'contact' else 'after it'})")
    coord = _ROLES.coordinated.match(rest)
    if coord and (lookup(coord.group("answer").split(" ", 1)[0]) or _copied(rest)):
        head = coord.group("head")
        answer, answers = _answer(coord.group("answer"))
        simultaneous = (coord.group("word") or "").strip() in ("while", "as", "whereas")
        response = "with" if simultaneous or not answers else "after"
        return Exchange(first, {first: _partner_words(head), 1 - first: answer}, response,
                        f"roles: '{text}' → {first} {head}; {1 - first} {answer} "
                        f"({'at the same time' if response == 'with' else 'after it'})")
    copy = g.COPIES_THE_OTHER.match(rest)
    if copy:
        what = (copy.group(1) or "arm").strip().rstrip("s")
        lead_text = f"raises and lowers both {'legs' if what == 'leg' else 'arms'} slowly"
        return Exchange(1 - first, {1 - first: lead_text, first: _partner_words(rest)}, "with",
                        f"roles: '{text}' → {1 - first} leads, {first} copies")
    obj = _ROLES.done_to.match(rest)
    if obj is None:
        return None
    verb = _verb(obj.group("verb"))
    tail = obj.group("rest").rstrip(" ,")
    if verb in CAUSED:
        lead_words, answer_words, response, swap = CAUSED[verb]
        lead = first if swap == 0 else 1 - first
        follower = 1 - lead
        texts = {lead: lead_words.format(rest=tail), follower: answer_words.format(rest=tail)}
        return Exchange(lead, texts, response, f"roles: '{text}' → {lead} {texts[lead]}; "
                                               f"{follower} {texts[follower]}")
    return Exchange(first, {first: _partner_words(rest)}, "after",
                    f"roles: '{text}' → {first} starts, {1 - first} is its partner")


def exchange_steps(ex: Exchange, clause, postures: list[str], idle_of, reasons: list[str]
                   ) -> list[Step]:
    """The plan's steps for an exchange: one step when the other acts with the lead (or only
    watches), two when they answer it (the lead's action, then the answer from its end or its
    contact). `idle_of(person)` is what a person who waits does in their posture ("a person
    stands still"); `postures` is updated."""
    reasons.append(ex.why)
    lead, other = ex.lead, 1 - ex.lead
    first = _action(ex.texts[lead], postures[lead], bool(clause.hold))
    postures[lead] = first.posture
    if other not in ex.texts:                                 # "one waves at the other"
        return [Step(first, clause.repeat, [lead], None, None, {other: idle_of(other)}, [lead],
                     travel=direction(first.text, first.verb), prompt=f"one person {first.text}")]
    if not ex.sequential:
        answer = ex.texts[other]
        ways = {direction(first.text, first.verb), direction(answer, decompose(answer).verb)}
        timing = {"lead": lead, "response": "with", "phase": "both"}
        return [Step(first, clause.repeat, [lead], None, None, {other: f"a person {answer}"}, [0, 1],
                     travel=ways.pop() if len(ways) == 1 else None, timing=timing,
                     prompt=f"one person {first.text} while the other {answer}")]
    second = _action(ex.texts[other], postures[other], False)
    postures[other] = second.posture
    lead_step = Step(first, clause.repeat, [lead], None, None, {other: idle_of(other)}, [lead],
                     travel=direction(first.text, first.verb),
                     timing={"lead": lead, "response": ex.response, "phase": "lead"},
                     prompt=f"one person {first.text}")
    answer_step = Step(second, 1, [other], None, None, {lead: idle_of(lead)}, [other],
                       travel=direction(second.text, second.verb),
                       timing={"lead": lead, "response": ex.response, "phase": "response"},
                       prompt=f"the other person {second.text}")
    return [lead_step, answer_step]


def _action(text: str, posture: str, hold: bool) -> Action:
    """A role's action; words with no known verb are kept as written (a pose of the body)."""
    action = decompose(text, posture, None, hold)
    if not action.known:
        action.base, action.verb = f"a person {action.text}", VERBS["pose"]
    return action
