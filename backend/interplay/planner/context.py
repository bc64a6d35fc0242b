"""Motion-irrelevant context out, vague places and manners into motion words (CoMA's
recaption step: "tatami → ground"; Table 8 marks "hopeless", "an away fan" as context).

    strip_context("An angry man sits on the court floor to protest a verdict")
      → ("An man sits on the floor", ["context: dropped 'angry'", …])

Runs on the original text (before lower-casing) so capitalised names after "at/against/during"
can be recognised as places and events. Every change is returned as a reason.
"""

from __future__ import annotations

import re

_I = re.IGNORECASE
_MONTHS = ("january|february|march|april|may|june|july|august|september|october|november|"
           "december")
_EMOTIONS = ("angry|angrily|hopeless|hopelessly|happy|happily|sad|sadly|excited|excitedly|tired|"
             "worried|nervous|nervously|proud|proudly|joyful|joyfully|furious|furiously|bored|"
             "scared|frightened|desperate|desperately|exhausted|elated|confident|confidently|shy|"
             "annoyed|frustrated|triumphant|triumphantly|cheerful|cheerfully|grumpy|upset|"
             "relieved|surprised|delighted|ecstatic|enthusiastic|enthusiastically|jubilant|"
             "disappointed|anxious|anxiously|lonely|bravely|brave")
_STATES = ("excitement|ecstasy|joy|anger|frustration|despair|triumph|celebration|rhythm|"
           "disbelief|pain|fear|delight|victory|relief|surprise|unison|time to the music|"
           "protest|happiness|sadness|jubilation|glee|panic|shock|agony")
_PURPOSES = ("taunt|celebrate|protest|impress|tease|mock|annoy|entertain|greet|show off|express|"
             "honou?r|mark|thank|cheer|please|scare|warn|signal|find|win|intimidate|distract|"
             "comfort|encourage|amuse|attract|pretend to be (?!inside|in |trapped)|look for|"
             "search for|escape from|hide from|catch (?:a|the) (?:bus|train)")
_AUDIENCE = ("friends|crowd|audience|fans|family|camera|mirror|class|team|people|everyone|"
             "others|spectators|supporters|teammates|opponents?|home team|away team|referee|"
             "judges?|coach|kids|children|parents|house|building|goal")
_PLACES = "court|field|pitch|tatami|mat|stage|grass|ground|carpet|beach|sand|dance floor|track"

# (pattern, replacement, flags, what it is). Applied in order; the first two are case-sensitive
# on purpose (capitalised names after a preposition are places, teams, events).
RULES: list[tuple[str, str, int, str]] = [
    (r"\s*\b(?:during|against|at|for|versus|vs\.?)\s+(?:the\s+)?(?:[A-Z][\w'’.-]*\s*)+"
     r"(?:derby|game|match|final|cup|stadium|league|championship|tournament)?", " ", 0, "event/place"),
    (r"\s*\bin\s+(?:[A-Z][a-z]+\s+)?(?:\d{4})\b", " ", 0, "date"),
    (rf"\s*\bin\s+(?:{_MONTHS})(?:\s+\d{{4}})?\b", " ", _I, "date"),
    (r"\s*\b(?:before|after|during)\s+the\s+(?:game|match|show|race|fight|concert|party|class|"
     r"meeting|final|wedding)(?:\s+(?:started|starts|begins|began|ended|ends|was\s+over))?\b", " ", _I,
     "occasion"),
    (rf"\s*\bin\s+front\s+of\s+(?:his|her|their|the|a|an|my|our)\s+(?:{_AUDIENCE})\b", " ", _I, "audience"),
    (rf"\s*,?\s*\b(?:in\s+order\s+)?to\s+(?:{_PURPOSES})\b[^,.;!?]*", " ", _I, "purpose"),
    (r"\s*\b(?:in|as|for)\s+(?:a|an|the|his|her|their)\s+[\w\s'’-]{0,40}?celebration\b", " ", _I,
     "occasion"),
    (rf"\s*\b(?:in|with|out\s+of)\s+(?:pure\s+|great\s+|sheer\s+)?(?:{_STATES})\b", " ", _I, "mood"),
    (rf"\b(?:{_EMOTIONS})\b\s*", "", _I, "mood"),
    (r"\s*\bon\s+(?:another|an?|the|his|her|their)\s+(?:other\s+)?(?:player|opponent|defender|"
     r"attacker|striker|goalkeeper|man|person)\b", " ", _I, "target"),
    (rf"\bon\s+(?:the\s+|a\s+)?(?:{_PLACES})(?:\s+floor)?\b", "on the floor", _I, "place"),
    (r"\b(?:to|towards|onto|into)\s+(?:the\s+)?(?:cent(?:er|re)\s+(?:of\s+the\s+)?stage|field|"
     r"pitch|court|stage|goal|door|crowd|corner\s+flag|finish\s+line|podium|net)\b", "forward", _I,
     "place"),
    (r"\s*\b(?:on|in)\s+(?:a|the)\s+(?:sunny|rainy|cold|hot|windy|snowy|beautiful)\s+"
     r"(?:day|night|morning|afternoon|evening)\b", " ", _I, "weather"),
    (r"\s*\b(?:in|at)\s+the\s+(?:park|office|gym|beach|street|morning|evening|party|club|rain|"
     r"snow|kitchen|garden|living\s+room)\b", " ", _I, "place"),
    (r"\blos(?:es|e|t|ing)\s+control\b(?:\s+and)?\s*", "", _I, "state"),
    (r"\s*\bin\s+(?:his|her|their|the)\s+way\b", " ", _I, "place"),
    (r"\s*\b(?:shortly|soon|right|immediately|just)\s+after(?:wards)?\b(?!\s+(?:that|the|a|\w+ing))",
     " ", _I, "timing"),
    (r"\bcalmly\b", "slowly", _I, "manner"),
    (r"\bin\s+a\s+(?:hurry|rush)\b", "quickly", _I, "manner"),
    (r"\b(wav(?:e|es|ed|ing))\s+(?:hello|goodbye|hi|bye)\b(?:\s+to\s+\w+)?", r"\1 the right hand", _I,
     "greeting"),
    (r"\s*\bthe\s+(?:home|away|rival|other)\s+(?:team|crowd|side)\b", " ", _I, "audience"),
]
_COMPILED = [(re.compile(p, f), r, what) for p, r, f, what in RULES]


def strip_context(text: str) -> tuple[str, list[str]]:
    """The text without motion-irrelevant context, and one reason per change."""
    reasons = []
    for rx, repl, what in _COMPILED:
        def sub(m, repl=repl, what=what):
            new = m.expand(repl) if "\\" in repl else repl
            old = m.group(0).strip(" ,")
            if new.strip():
                reasons.append(f"context ({what}): '{old}' → '{new.strip()}'")
            else:
                reasons.append(f"context ({what}): dropped '{old}'")
            return new
        text = rx.sub(sub, text)
    text = re.sub(r"\s+([,.;!?])", r"\1", re.sub(r"\s{2,}", " ", text)).strip()
    return re.sub(r"^[,;\s]+", "", text), reasons
