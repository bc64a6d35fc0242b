"""The one module with regular expressions: numbers, counts, sides, sentence structure, and the
patterns compiled from the catalogue's own words (an action's word forms, a gesture's names).
No phrase table lives here: what an action is called comes from `actions.toml`, and the words
inside a sentence pattern ("the two friends", "how does a person …", the months) are words.toml
lists read by `listed`.

    words_rx(["sprint*", "as fast as"]).search("she dashes as fast as she can")
    names_source(["t pose"])        → matches "t pose", "t-pose", "tpose", "T-pose's"
    count_in("kicks three times")   → 3
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache

_WORD_CHARS = frozenset("abcdefghijklmnopqrstuvwxyz0123456789'é")


@lru_cache(maxsize=4096)
def rx(source: str, flags: int = 0) -> re.Pattern:
    """A compiled pattern, once per source (every dynamic pattern goes through here)."""
    return re.compile(source, flags)


def _word(w: str) -> str:
    """One word form: "sprint*" → any ending; "'s" may follow (a possessive name)."""
    if w.endswith("*"):
        return re.escape(w[:-1]) + r"\w*"
    return re.escape(w)


def words_source(words, not_before=()) -> str:
    """Any of the word forms (multi-word forms with any spaces), as whole words, not followed
    by a word of `not_before`."""
    alts = sorted({r"[\s-]+".join(_word(p) for p in w.split()) for w in words}, key=len, reverse=True)
    src = r"\b(?:" + "|".join(alts) + r")\b" if alts else r"(?!x)x"
    if not_before:
        src += r"(?!\s+(?:" + "|".join(_word(w) for w in not_before) + r")\b)"
    return src


def words_rx(words, not_before=()) -> re.Pattern:
    return rx(words_source(tuple(words), tuple(not_before)), re.IGNORECASE)


def any_words_rx(entries: tuple[tuple[tuple[str, ...], tuple[str, ...]], ...]) -> re.Pattern:
    """One pattern for several entries' word forms, each with the words it may not go on with."""
    return rx("|".join(f"(?:{words_source(forms, not_before)})" for forms, not_before in entries)
              or r"(?!x)x", re.IGNORECASE)


def names_source(names, followed_by=()) -> str:
    """Set phrases of a gesture or pose, longest first: words joined by a space, a hyphen, a
    comma or nothing ("t pose" is also "t-pose" and "tpose"), each may take a possessive 's."""
    def one(name: str) -> str:
        return r"(?:\s*[,-]?\s*)".join(_word(w) + r"(?:'s)?" for w in name.split())
    alts = sorted({one(n) for n in names}, key=len, reverse=True)
    src = "(?:" + "|".join(alts) + ")"
    if followed_by:
        ends = [r"\s*[,.;]" if w == "." else r"\s+" + _word(w) + r"\b" for w in followed_by]
        src += r"(?=" + "|".join(ends + [r"\s*$"]) + ")"
    return src


# --- numbers and counts ---
NUMBERS = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7,
           "eight": 8, "nine": 9, "ten": 10}
_NUMBER = r"(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)"
# Repetitions said without a number ("a few times"): a few and several are three, a couple two
# ("a few steps" asks no exact count).
VAGUE = {"a few": 3, "several": 3, "a couple": 2, "a couple of": 2}
_VAGUE = r"(?:a\s+few|several|a\s+couple(?:\s+of)?)"
# A count said in words: "once", "twice", "three times", "one time"; one of something.
ONE_SAID = re.compile(r"\b(?:one|a\s+single)\s+[a-z-]+", re.IGNORECASE)     # "one backflip"
# (groups: the word said alone, the number, "time" or "times")
COUNT_SAID = re.compile(rf"\b(?:(once|twice|thrice)|({_NUMBER})\s+(times?))\b", re.IGNORECASE)


DEGREES = re.compile(r"(\d+(?:\.\d+)?)\s*(?:°|deg\b|degrees?\b)")      # "look up 40 degrees"


def number(word: str) -> int | None:
    w = " ".join(word.lower().split())
    return int(w) if w.isdigit() else {"twice": 2, "thrice": 3, **NUMBERS, **VAGUE}.get(w)


def times_rx(nouns) -> re.Pattern:
    """"twice", "three times", "3 jumps", "four quick hops": a number and what it counts
    (`nouns`: the counted actions' plural forms)."""
    plural = "|".join(sorted({re.escape(n) for n in nouns}, key=len, reverse=True)) or "(?!x)x"
    return rx(rf"\b(twice|thrice)\b|\b({_NUMBER}|{_VAGUE}(?=\s+times\b))\s+(?:times\b|(?:\w+\s+)?(?:{plural})\b)")


def one_rx(nouns) -> re.Pattern:
    """"a jump", "one quick squat", "a single kick": one of a counted action."""
    singular = "|".join(sorted({re.escape(n) for n in nouns}, key=len, reverse=True)) or "(?!x)x"
    return rx(r"\b(?:a|an|one|single)\s+(?:(?!(?:few|couple|bit|little|lot|series|number|in|"
              r"on|at|with|your|his|her|their|the|of|to|for|and)\b)[a-z-]+\s+){0,2}?"
              rf"(?:{singular})\b")


def listed(name: str, space: str = r"\s+") -> str:
    """A words.toml list as a pattern's alternatives, in the list's order (a pattern tries them
    first to last): each phrase's words escaped and joined by `space` (any spaces unless said)."""
    from interplay.catalogue.words import lists
    return "|".join(space.join(re.escape(w) for w in phrase.split()) for phrase in lists()[name])


def words_of(text: str) -> list[str]:
    """Lower-case words of a text (letters a to z, digits, apostrophes, é)."""
    return "".join(c if c in _WORD_CHARS else " " for c in text.lower()).split()


# --- named gestures and poses: "<intro> <det> <adjectives> NAME <tail>" ---
_DET = (r"(?:(?P<det>the|a|an|his|her|their|one|two|three|four|five|six|seven|eight|nine|ten|"
        r"\d+)\s+)?")


def named_rx(names, followed_by, intro, sequential, adjectives, tails) -> re.Pattern:
    """A gesture's names as a prompt says them: "does the classic T-pose", "striking a dab
    move", "switching into a T-pose", "Rocky's victory pose" (groups: intro, det, name)."""
    lead = "|".join(sorted({r"\s+".join(_word(p) for p in w.split()) for w in intro}, key=len, reverse=True))
    seq = "|".join(sorted({_word(w) for w in sequential}, key=len, reverse=True))
    adj = "|".join(sorted({re.escape(a) for a in adjectives}, key=len, reverse=True))
    tail = "|".join(sorted({re.escape(t) for t in tails}, key=len, reverse=True))
    src = (rf"\b(?:(?P<intro>{lead}|(?:{seq})\s+(?:in)?to)\s+)?{_DET}"
           rf"(?:(?:{adj}|[\w.-]+(?:\s+[\w.-]+)?(?:'s|’s))\s+)*"
           rf"(?P<name>{names_source(names, followed_by)})(?:\s+(?:{tail}))?\b")
    return rx(src, re.IGNORECASE)


# --- directions, turns, postures: sentence structure around the catalogue's words ---
BACK_NOT = r"(?!\s+(?:up|to|home|and|into|in)\b)"      # "runs back to …", "steps back up" go somewhere


def back_rx(travel_forms) -> re.Pattern:
    """"<travel verb> back" ("steps back", "walks back") not followed by where to."""
    verbs = "|".join(sorted({re.escape(w) for w in travel_forms}, key=len, reverse=True))
    return rx(rf"\b(?:{verbs})\s+back\b{BACK_NOT}")


# Held poses: the side of a leg stood on or lifted (words.toml's `one_leg` says it is held), a squat held.
# the side stood on (group 1: "on the left leg") or lifted (group 2: "raises the right")
LEG_SIDE = re.compile(r"\bon (?:the |your |his |her |their )?(left|right) (?:leg|foot)\b"
                      r"|\b(?:lift|rais)\w* (?:the |your |his |her |their )?(left|right)")
HELD_AROUND = r"\b(?:hold\w*|stay\w*|remain\w*|keep\w*)\b[^.]*"       # "… holds it", "stays in …"


def held_rx(words) -> re.Pattern:
    """A pose named by `words` held: "holds a squat", "squats and stays down", "in a deep squat"."""
    w = words_source(tuple(words))
    return rx(rf"{HELD_AROUND}{w}|{w}[^.]*\b(?:hold\w*|stay\w*|remain\w*)\b|\bin a (?:deep |low |full )?{w}")


# --- phrase templates: how the catalogue writes a phrase with optional and alternative words ---
# "arm* [held|stretched] out to (the|his|her) side*": words in order; `*` any ending; (a|b) one
# of; [a|b] one of or none; `...` any words between (within the text); `~3` up to three words;
# a trailing `!(a|b)` says the phrase may not go on with those words.


def _template_tokens(template: str) -> list[str]:
    """A template's parts: "(a|b)", "!(a|b)", "[a b]" (spaces inside), else runs of non-spaces."""
    out, i = [], 0
    while i < len(template):
        if template[i].isspace():
            i += 1
            continue
        opening = "(" if template.startswith("!(", i) or template[i] == "(" else "[" if template[i] == "[" else ""
        close = template.find(")" if opening == "(" else "]", i) if opening else -1
        if close < 0:
            close = next((j for j in range(i, len(template)) if template[j].isspace()), len(template)) - 1
        out.append(template[i:close + 1])
        i = close + 1
    return out


def _alts(body: str) -> str:
    return "|".join(sorted((r"\s+".join(_word(w) for w in alt.split()) for alt in body.split("|")),
                           key=len, reverse=True))


def template_source(template: str) -> str:
    """The regular expression of one template (see above)."""
    src, tail, glue = "", "", ""            # glue: what joins the next word to the source
    for tok in _template_tokens(template):
        if tok.startswith("!("):
            tail = rf"(?!\s+(?:{_alts(tok[2:-1])})\b)"
            continue
        if tok == "...":                     # any characters between
            src, glue = src + r".*?", ""
            continue
        if tok.startswith("~") and tok[1:].isdigit():   # up to n words between
            src, glue = src + rf"\s+(?:\w+\s+){{0,{int(tok[1:])}}}?", ""
            continue
        optional = tok.startswith("[")
        word = rf"(?:{_alts(tok[1:-1])})" if tok[0] in "([" else _word(tok)
        src += rf"(?:{glue}{word})?" if optional else glue + word
        glue = r"\s+"
    return r"\b" + src + r"\b" + tail


def template_rx(templates) -> re.Pattern:
    """One pattern for any of the templates."""
    return rx("|".join(f"(?:{template_source(t)})" for t in templates) or r"(?!x)x", re.IGNORECASE)


# --- context that names no motion (planner/context.py): proper names after a preposition
# (case matters: "at Wembley", "against the Lakers"), years and months, "in a … celebration" ---
CONTEXT_EVENT = re.compile(r"\s*\b(?:during|against|at|for|versus|vs\.?)\s+(?:the\s+)?(?:[A-Z][\w'’.-]*\s*)+"
                           r"(?:derby|game|match|final|cup|stadium|league|championship|tournament)?")
CONTEXT_YEAR = re.compile(r"\s*\bin\s+(?:[A-Z][a-z]+\s+)?(?:\d{4})\b")
_MONTHS = listed("months")
CONTEXT_MONTH = rx(rf"\s*\bin\s+(?:{_MONTHS})(?:\s+\d{{4}})?\b", re.IGNORECASE)
CONTEXT_CELEBRATION = re.compile(r"\s*\b(?:in|as|for)\s+(?:a|an|the|his|her|their)\s+[\w\s'’-]{0,40}?celebration\b",
                                 re.IGNORECASE)


# --- the planner's sentence structure (planner/plan.py) ---
WHILE_THE_OTHER = re.compile(r",?\s+while\s+the\s+other(?:\s+(?:one|person))?\s+(.+)$")



def one_action_rx(countable) -> re.Pattern:
    """"a tuck jump", "one squat": one of the countable actions (not "jumping jacks" or "jump
    ropes", which count nothing)."""
    words = "(?:" + "|".join(sorted(countable)) + ")"
    return rx(rf"\b(?:a|an|one|single)\s+(?:[a-z-]+\s+){{0,3}}?{words}s?\b(?!\s+(?:jacks?|ropes?))",
              re.I)


# --- the decomposer's sentence structure (planner/decompose.py): limbs, modifiers, possessives ---
# a limb and its side, or the limb after "with" ("with the left hand"; groups: with, side, limb)
LIMB_PART = re.compile(r"\b(with\s+(?:(?:the|his|her|their|a)\s+)?)?"
                       r"(?:(left|right|both|each|either|other)\s+)?(arms?|hands?|fists?|elbows?|"
                   r"wrists?|fingers?|palms?|shoulders?|forearms?|thumbs?|legs?|foot|feet|knees?|"
                   r"toes?|heels?|ankles?|thighs?|shins?)\b")
_MODIFIER_MARKS = listed("modifier_marks")
MODIFIER_MARK = rx(rf"(?<!while)(?<!with)(?<!\bas)\s*,?\s+(?=(?:{_MODIFIER_MARKS})\b)|"
                   r"(?<!while)\s*,\s+(?=\w+ing\b)|\s+and\s+(?=\w+ing\b)")
# a modifier's own limb ("(the) left arm raised": side, limb, the rest)
MODIFIER_LIMB = re.compile(r"^(?:(?:the|a|an|his|her|their)\s+)?(?:(left|right|both|other)\s+)?"
                           r"(?:(arms?|hands?|fists?|legs?|foot|feet|knees?|elbows?|palms?)\b)?\s*(.*)$")
# Both limbs written for one side ("both clenched fists" → "the clenched left fist"): groups are
# the adjective (with its space) and the limb
_LIMB = r"(arm|hand|fist|leg|knee|elbow|palm|shoulder|wrist|forearm|thumb)"
_ADJS = r"((?:clenched|open|outstretched|bent|raised|straight|closed|extended)\s+)?"
# ... and limbs named without a side: "both (adj) arm(s)" (groups 1-3: adjective, limb, "feet")
# or "(the) (adj) arms" (groups 4-6), one side written for each
BOTH_OR_PLURAL = re.compile(rf"\bboth\s+{_ADJS}(?:{_LIMB}s?|(feet))\b"
                            rf"|\b(?:the\s+)?{_ADJS}(?<!left )(?<!right )(?:{_LIMB}s|(feet))\b")
AND_SIDE = re.compile(r"\s+and\s+(?=(?:the\s+|his\s+|her\s+|their\s+)?(?:left|right|both|other)\b)")


# --- temporal structure (planner/temporal.py): sentences, connectives, counts, noun phrases ---
SENTENCE_END = re.compile(r"(?<=[.!?;])\s+|;\s*|(?<=[a-z])\.\s*$")
_CONNECTIVES = listed("connectives")
CONNECTIVE = rx(rf"\s*,?\s*\b(?:{_CONNECTIVES}|next(?!\s+to)|(?:second|third|fourth|fifth)(?:ly)?(?=\s*,))\b\s*,?\s*")
AGAIN_STILL = re.compile(r"\s+again\b|,?\s*\bbut\s+(?:now|still|then)\b|\bstill\s+")     # said again: out
# "before X, Y" / "after X, Y" / "X before Y" / "X after Y": one pattern, its alternatives tried
# in this order; the k-th (from 1) fills groups 2k-1 and 2k (`m.lastindex` is 2k), the two parts
# as written, and BEFORE_AFTER_ORDER[k-1] says which happens first
BEFORE_AFTER = re.compile(r"^(?:(?:before|prior\s+to)\s+(.+?),\s*(.+)$|after\s+(?!that\b)(.+?),\s*(.+)$"
                          r"|(.+?)\s+(?:before|prior\s+to)\s+(.+)$|(.+?)\s+after\s+(?!that\b|wards?\b)(.+)$)")
BEFORE_AFTER_ORDER = ((1, 0), (0, 1), (0, 1), (1, 0))
_LIGHT_VERBS, _NOUN_ADJECTIVES = listed("noun_light_verbs"), listed("noun_adjectives")
NOUN_ACT = rx(
    rf"\b(?:({_LIGHT_VERBS})\s+)?(?:(a|an|one|two|three|four|five|six|seven|eight|nine|ten|\d+|some|"
    rf"several|a\s+few)\s+)?((?:(?:{_NOUN_ADJECTIVES})\s+)*)([\w-]+)\b")
_CHANGE_VERBS = listed("change_verbs")
FROM_TO = rx(rf"(?:(?:{_CHANGE_VERBS})\s+)?from\s+(?:a\s+|an\s+)?(\w+?)\s+(?:in)?to\s+(?:a\s+|an\s+)?(\w+)\b")
ALTERNATE = re.compile(r"(?:,?\s*while\s+|,\s*)?alternat\w*\s+between\s+(.+?)\s+and\s+(.+?)"
                        r"(?:\s+(one|two|three|four|five|six|seven|eight|\d+)\s+times|\s+(twice))?"
                        r"\s*$")
CLAUSE_OPENS = re.compile(r"(^|[,;.]\s*(?:(?:and|then)\s+)*|\b(?:(?:and|then|or|before|after|while)\s+)+)"
                    r"([a-z-]+)")


# --- two people's sentence structure (planner/pair/roles.py, actors.py) ---
PAIR_NAMES = re.compile(r"^(?:a|an|the)?\s*(\w+) and (?:a|an|the)?\s*(\w+)$")       # "the man and the woman"
WHO_ANSWERS = re.compile(r"^(?P<head>.+?),?\s+who\s+(?P<answer>.+)$")
_COPY_VERBS, _COPIED = listed("copy_verbs"), listed("copied_things")
COPIES_THE_OTHER = rx(rf"^(?:{_COPY_VERBS})\s+the\s+other(?:\s+person)?'?s?"
                      rf"\s+((?:\w+\s+)?)(?:{_COPIED})(?P<rest>.*)$")


_OTHER_SUBJECT = r"the\s+other(?:\s+(?:one|person))?|the\s+second(?:\s+(?:one|person))?|the\s+follower"


@dataclass(frozen=True)
class TwoPeople:
    """Who does what to whom (planner/pair/roles.py), around the people's nouns."""
    partner: re.Pattern          # the partner as an object: "the other", "him", "the woman", "her partner"
    partner_owns: re.Pattern     # … followed by 's
    subject: re.Pattern          # a clause's one subject and the rest (groups subj, rest)
    coordinated: re.Pattern      # "waves, and the other waves back" (groups head, word, answer)
    named: re.Pattern            # "a woman" (group 1: the noun)
    done_to: re.Pattern          # "pushes (at) the other …" (groups verb, rest)
    plural_subject: re.Pattern   # "they ", "the two friends " at the start


@lru_cache(maxsize=4)
def two_people(nouns: tuple[str, ...]) -> TwoPeople:
    """The two-person patterns for these nouns (compiled once per noun list)."""
    n = "|".join(nouns)
    joins = listed("coordinating")
    partner = (rf"(?:the\s+other(?:\s+(?:one|person))?|him|her(?!\s+(?:{n})\b)|them|"
               rf"(?:a|an|the|his|her|their)\s+(?:{n}))")
    return TwoPeople(
        partner=rx(rf"\b{partner}\b"), partner_owns=rx(rf"\b{partner}(?='s)"),
        subject=rx(rf"^(?P<subj>one(?:\s+(?:of\s+them|person))?|someone|a\s+person|he|she|"
                   rf"the\s+(?:first|second|leader|follower)(?:\s+(?:one|person))?|"
                   rf"(?:a|an|the)\s+(?:{n}))\s+(?P<rest>.+)$"),
        coordinated=rx(rf"^(?P<head>.+?)(?:\s*,\s*|\s+)(?:(?:{joins})\s+)?"
                       rf"(?P<word>(?:{joins})\s+|)?(?:{_OTHER_SUBJECT})\s+"
                       rf"(?P<answer>\w+.*)$"),
        named=rx(rf"\b(?:a|an|the|his|her|their)\s+({n})\b"),
        done_to=rx(rf"^(?P<verb>\w+)\s+(?:(?:at|to|towards|with|on|into)\s+)?(?:{partner})\b(?P<rest>.*)$"),
        plural_subject=rx(r"^(?:they|both(?:\s+of\s+them)?|two\s+\w+|the\s+(?:two|pair|couple)(?:\s+\w+)?)\s+"))


# --- paths said in words (planner/trajectory_text.py) ---
_PATH_NUMBER = r"(\d+(?:\.\d+)?|one|two|three|four|five|six|seven|eight|nine|ten|twenty|half\s+a|a)"
PATH_DISTANCE = re.compile(rf"\b{_PATH_NUMBER}\s*-?\s*(m|metres?|meters?|steps?|feet|foot|ft|yards?|paces?)\b"
                       r"(?:\s+(forward|forwards|ahead|backward|backwards|back|to\s+the\s+left|"
                       r"to\s+the\s+right|left|right|sideways))?")
PATH_SIZE = re.compile(rf"\b(?:(?:radius|diameter)\s+(?:of\s+)?)?{_PATH_NUMBER}\s*-?\s*(?:m|metres?|meters?)\b"
                   r"(?:\s*(?:wide|across|diameter|radius|sides?|sided|big|large)\b)?")
PATH_TURNS = re.compile(r"\b(\d+(?:\.\d+)?|one|two|three|four|five)\s+(?:times|turns|loops|laps|circles)\b")
PATH_CLOCK = re.compile(r"\b(?:turns?|turning|turned|heads?|goes|walks|runs)?\s*(left|right)?\s*"
                    r"(?:at|to|towards?|toward)\s+(\d{1,2}|one|two|three|four|five|six|seven|eight|"
                    r"nine|ten|eleven|twelve)\s*o'?\s*clock\b")


# --- held poses (planner/manner/holds.py) ---
HOLD_SIDE = re.compile(r"\b(left|right|both|each)\s+(?:\w+\s+)?(?:arms?|hands?|fists?|palms?)|\b(?:arms|hands|fists|palms)\b")


# --- questions (planner/questions.py) ---
_Q_WORDS, _Q_VERBS, _Q_SUBJECTS = listed("question_words"), listed("question_verbs"), listed("question_subjects")
_Q_MOTIONS, _Q_LINKS = listed("question_motions"), listed("question_links")
QUESTION_STEM = rx(rf"^\s*(?:{_Q_WORDS})\s+(?:{_Q_VERBS})\s+"
                   rf"(?:a|the|an|one)?\s*(?:{_Q_SUBJECTS})?'?s?\s*"
                   rf"(?:{_Q_MOTIONS})?\s*(?:{_Q_LINKS})?\s*", re.IGNORECASE)


# --- durations (planner/durations.py) ---
_STEP_UNITS = listed("step_units")
DURATION_STEPS = rx(r"\b(a\s+few|a\s+couple\s+of|few|several|\d+|one|two|three|four|five|six|"
                    rf"seven|eight|nine|ten)\s+(?:{_STEP_UNITS})\b")


# --- two people's gestures (generators/interaction/scenes/gestures.py) ---

_GROUP_OF_TWO, _GROUP_NOUNS = listed("group_of_two", " "), listed("group_nouns")
GESTURE_WHO = rx(rf"\b(?:{_GROUP_OF_TWO})\s+(?:of\s+them\s+)?(?:{_GROUP_NOUNS})?\b|"
                 r"\bboth\s+of\s+them\b|\bthey\b|\bboth\b", re.I)
