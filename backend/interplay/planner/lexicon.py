"""Context-rich gestures and poses → the motion words a motion model knows (CoMA's recaption:
"wakanda forever salute → cross arms in front of the chest").

    rewrite("The man does the Tiger Woods fist pump")
      → ("The man raises the right fist to the chest, then pulls the right fist down sharply",
         ["lexicon: 'does the Tiger Woods fist pump' → 'raises …' (tiger woods fist pump)"])

An entry's text is a verb phrase in the third person ("crosses both arms …"); ", then" inside it
makes several temporal steps, "while …"/", <verb>ing …" simultaneous ones. The verb that
introduces a name ("does", "performs", "striking", "holding", …) is replaced with it: a gerund
introducer gives the text in -ing form, a holding verb gives the entry's `hold` phrase
("with both arms stretched out to the sides") when it has one.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from interplay.planner.verbs import gerund, lookup


@dataclass(frozen=True)
class Entry:
    name: str
    pattern: str          # regex of the name itself (case-insensitive)
    text: str             # what a person does, third person present
    hold: str | None = None   # the held pose as a "with …" phrase (poses only)


E = Entry
LEXICON: tuple[Entry, ...] = (
    E("wakanda forever salute", r"wakanda(?:\s+forever)?", "crosses both arms in front of the chest",
      "with both arms crossed in front of the chest"),
    E("t-pose", r"t[\s-]?pose", "raises both arms out to the sides",
      "with both arms stretched out to the sides"),
    E("superhero landing", r"superhero\s+landing", "drops down onto the right knee, pressing the "
      "right fist to the floor while stretching the left arm back"),
    E("victory pose", r"(?:rocky(?:'s)?\s+)?victory\s+pose|rocky(?:'s)?\s+(?:pose|celebration)",
      "raises both arms above the head with clenched fists", "with both arms raised above the head"),
    E("dab", r"dab(?:bing)?(?:\s+move|\s+dance)?", "tucks the head into the bent left elbow while "
      "stretching the right arm up and out to the side"),
    E("spider-man web shooting", r"spider[\s-]?man(?:'s)?\s+web[\s-]?shoot(?:ing|er)?(?:\s+move)?|"
      r"web[\s-]?shoot(?:ing)?", "thrusts the right arm forward with the wrist bent back"),
    E("karate kick", r"karate\s+kick|martial\s+arts?\s+kick", "kicks high forward with the right leg"),
    E("bruce lee kicks", r"bruce\s+lee(?:'s)?(?:\s+(?:classic|famous|iconic))?\s+kicks?",
      "kicks high with the right leg, then kicks high with the left leg"),
    E("moonwalk", r"moon[\s-]?walk(?:ing)?|michael\s+jackson(?:'s)?\s+moonwalk",
      "walks backwards, sliding the feet along the floor"),
    E("bow", r"(?:deep\s+)?bow(?=\s+to\b|\s*$|\s*[,.;])|takes?\s+a\s+(?:deep\s+)?bow",
      "bends forward at the waist"),
    E("shrug", r"shrugs?\s+(?:his|her|their|the)\s+shoulders|shoulder\s+shrug|(?<=a\s)shrug\b|"
      r"(?<=the\s)shrug\b",
      "raises both shoulders with the palms turned up"),
    E("applause", r"round\s+of\s+applause|applau(?:ds|d|se|ding)", "claps the hands"),
    E("facepalm", r"face[\s-]?palm", "brings the right hand up to cover the face"),
    E("superman flying pose", r"superman(?:'s)?(?:\s+(?:iconic|classic|famous))?(?:\s+flying)?",
      "stretches the right arm forward and up with a clenched fist",
      "with the right arm stretched forward and up"),
    E("double bicep pose", r"(?:front\s+)?double[\s-]bicep?s?|flex(?:es|ing)?\s+(?:his|her|their|"
      r"the)?\s*muscles", "raises both arms to the sides with the elbows bent, flexing the biceps",
      "with both arms bent up at the sides"),
    E("fist of solidarity", r"fist\s+of\s+solidarity|black\s+power\s+(?:salute|fist)|raised\s+fist",
      "raises the right fist straight up above the head", "with the right fist raised above the head"),
    E("military salute", r"military\s+salute|(?<!forever\s)salute(?!s)", "raises the right hand "
      "to the forehead", "with the right hand raised to the forehead"),
    E("tiger woods fist pump", r"(?:tiger\s+woods(?:'s)?\s+)?fist[\s-]pump",
      "raises the right fist to the chest, then pulls the right fist down sharply"),
    E("usain bolt celebration", r"(?:usain\s+)?bolt(?:'s)?\s+celebration|lightning\s+bolt|"
      r"usain\s+bolt", "leans back while pointing both arms up and to the left"),
    E("point to god", r"(?:messi(?:'s)?\s+)?(?:famous\s+)?point(?:ing)?\s+to\s+(?:god|the\s+sky|"
      r"the\s+heavens)", "points both arms up to the sky"),
    E("hulk smash", r"hulk(?:'s)?\s+smash(?:\s+stance)?|hulk(?:'s)?\s+stance",
      "bends the knees, raising both clenched fists above the head"),
    E("titanic flying pose", r"titanic(?:\s+(?:flying|king\s+of\s+the\s+world))?",
      "stretches both arms out to the sides while leaning forward",
      "with both arms stretched out to the sides"),
    E("home alone scream", r"home\s+alone(?:\s+macaulay\s+culkin)?(?:'s)?\s+scream|macaulay\s+"
      r"culkin(?:'s)?\s+scream|home\s+alone", "presses both hands against the cheeks",
      "with both hands pressed against the cheeks"),
    E("mbappe celebration", r"mbapp[eé](?:'s)?", "crosses both arms over the chest",
      "with both arms crossed over the chest"),
    E("siu celebration", r"(?:ronaldo(?:'s)?\s+)?siu+|ronaldo(?:'s)?(?=\s+celebration)",
      "jumps forward while spinning around in the air, then lands in a wide stance, pushing "
      "both arms down and out to the sides"),
    E("thierry henry celebration", r"thierry\s+henry(?:'s)?(?:\s+classic)?(?=\s+celebration)|"
      r"thierry\s+henry", "sprints forward with both arms extended, then slides on the knees in "
      "a straight line"),
    E("knee slide", r"knee[\s-]slide", "slides forward on the knees in a straight line"),
    E("ballet spin", r"ballet\s+spin|pirouette", "spins around on one foot with both arms "
      "rounded in front of the chest"),
    E("ballet curtsy", r"(?:ballet\s+)?curtsy", "bends both knees while crossing the right leg "
      "behind the left"),
    E("lasso spin", r"lasso(?:\s+spins?)?", "swings the right arm in circles"),
    E("slide tackle", r"slid(?:e|ing)[\s-]tackle", "slides along the floor on the left hip with "
      "the right leg extended forward"),
    E("mime box", r"pretend\w*\s+to\s+be\s+(?:inside|in|trapped\s+in)\s+(?:a|an|the)\s+"
      r"(?:invisible\s+)?box|mime(?:\s+in\s+a)?\s+box", "presses both palms against an invisible wall"),
    E("jump kick", r"(?:mid[\s-])?jump(?:ing)?[\s-]kick", "jumps while kicking the right leg "
      "forward in the air"),
    E("jump spin", r"jump[\s-]spin", "jumps while spinning around in the air"),
    E("bicycle kick", r"bicycle\s+kick|scissors?\s+kick|overhead\s+kick", "jumps backwards "
      "while kicking the right leg up over the head"),
    E("jumping jacks", r"jumping\s+jacks?|star\s+jumps?", "jumps while spreading the legs and "
      "raising both arms above the head"),
    E("push-ups", r"push[\s-]?ups?|press[\s-]?ups?", "lies face down, pushing the body up and "
      "down with both arms"),
    E("thumbs up", r"thumbs?[\s-]up", "raises the right hand with the thumb up"),
    E("peace sign", r"peace\s+sign|v[\s-]sign", "raises the right hand in a v sign"),
    E("surrender", r"hands\s+up\s+in\s+surrender|surrender(?:s|ing)?", "raises both hands "
      "above the head", "with both hands raised above the head"),
    E("prayer", r"prayer(?:\s+hands)?|praying\s+hands|namaste", "presses both palms together in "
      "front of the chest", "with both palms pressed together in front of the chest"),
    E("kamehameha", r"kamehameha|hadouken", "pushes both palms forward together"),
    E("gangnam style", r"gangnam\s+style(?:\s+dance)?", "hops from foot to foot with the "
      "wrists crossed in front of the chest"),
    E("floss dance", r"floss(?:ing)?\s+dance|the\s+floss", "swings both arms back and forth "
      "across the body while swaying the hips"),
    E("macarena", r"macarena", "swings both arms in turn to the front, the head and the hips"),
    E("robot dance", r"robot\s+dance", "swings both arms in stiff jerky motions"),
    E("tree pose", r"(?:yoga\s+)?tree\s+pose", "stands on the left leg with the right foot "
      "against the left knee, raising both hands above the head"),
    E("warrior pose", r"(?:yoga\s+)?warrior(?:\s+(?:one|two|i|ii|1|2))?\s+pose", "lunges "
      "forward with the right leg while stretching both arms out to the sides"),
    E("heisman pose", r"heisman(?:\s+trophy)?", "raises the right knee while stretching the "
      "left arm forward"),
    E("freeze", r"freez(?:e|es|ing)(?:\s+(?:and|,)\s+(?:do\s+not|don'?t)\s+move)?(?:\s+in\s+place)?|"
      r"(?:do\s+not|don'?t)\s+move(?:\s+at\s+all)?|(?:stands?|standing)\s+without\s+moving",
      "stands completely still"),
    E("karate chop", r"karate\s+chop", "chops down with the right hand"),
    E("golf swing", r"golf\s+swing", "swings both arms across the body like a golf club"),
    E("baseball swing", r"(?:baseball\s+)?bat\s+swing|baseball\s+swing", "swings both arms across the body "
      "like a bat"),
    E("boxing jab", r"(?:boxing\s+)?jab", "punches forward with the left fist"),
    E("uppercut", r"uppercut", "punches upwards with the right fist"),
    E("tennis serve", r"tennis\s+serve", "swings the right arm over the head"),
    E("volleyball spike", r"volleyball\s+spike", "jumps while swinging the right arm down "
      "hard over the head"),
    E("hula hoop", r"hula[\s-]?hoop(?:ing)?", "circles the hips with both arms raised"),
    E("zombie walk", r"zombie\s+walk", "walks slowly with both arms stretched forward"),
    E("proposal", r"(?:marriage\s+)?proposal(?:\s+pose)?", "kneels down on the right knee"),
    E("obstacle dodging", r"(?:try(?:ing|ies)?\s+to\s+)?(?:avoid|dodge)(?:s|ing)?\s+(?:the\s+)?"
      r"(?:[\w-]+\s+)?obstacles?|obstacle\s+dodging", "dodges from side to side in a zigzag"),
)

_INTRO = (r"do|does|did|doing|done|perform|performs|performed|performing|make|makes|made|making|"
          r"strike|strikes|struck|striking|imitate|imitates|imitated|imitating|copy|copies|copying|"
          r"hold|holds|held|holding|keep|keeps|kept|keeping|assume|assumes|assumed|assuming|"
          r"execute|executes|executed|executing|show|shows|showed|showing|pull(?:s|ed|ing)?\s+off|"
          r"(?:switch(?:es|ed|ing)?|transition(?:s|ed|ing)?|go(?:es|ing)?|went|get(?:s|ting)?|got)"
          r"\s+(?:in)?to")
_SEQUENTIAL = {"switch", "switches", "switched", "switching", "transition", "transitions",
               "transitioned", "transitioning", "go", "goes", "going", "went", "get", "gets",
               "getting", "got"}
_HOLDERS = {"hold", "keep", "holds", "holding", "held", "keeps", "keeping", "kept"}
_NUMBERS = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7,
            "eight": 8, "nine": 9, "ten": 10, "twice": 2, "thrice": 3}
_DET = (r"(?:(?P<det>the|a|an|his|her|their|one|two|three|four|five|six|seven|eight|nine|ten|"
        r"\d+)\s+)?")
_ADJ = (r"(?:(?:classic|iconic|famous|signature|trademark|legendary|well-known|typical|"
        r"traditional|full|perfect|quick|big|deep|little|small|funny|cool|so-called|front|"
        r"[\w.-]+(?:\s+[\w.-]+)?(?:'s|’s))\s+)*")
_TAIL = (r"(?:\s+(?:pose|poses|move|moves|celebration|gesture|salute|stance|dance|routine|"
         r"position|sign|signal|style|landing))?")


def _compile(entry: Entry) -> re.Pattern:
    return re.compile(rf"\b(?:(?P<intro>{_INTRO})\s+)?{_DET}{_ADJ}(?P<name>{entry.pattern}){_TAIL}\b",
                      re.IGNORECASE)


_PATTERNS = [(e, _compile(e)) for e in LEXICON]


def as_gerund(text: str) -> str:
    """"raises the arm, then lowers it" → "raising the arm, then lowering it"."""
    steps = []
    for step in text.split(", then "):
        first, _, rest = step.partition(" ")
        hit = lookup(first)
        steps.append(f"{gerund(hit[0].base)} {rest}".strip() if hit else step)
    return ", then ".join(steps)


def _form(entry: Entry, m: re.Match) -> str:
    """The entry's text in the form its introducer asks for."""
    intro = (m.group("intro") or "").split()
    first = (intro[0] if intro else m.group("name").split()[0]).lower()
    if first in _HOLDERS and entry.hold:
        return entry.hold
    if first in _SEQUENTIAL:      # "switching to a T-pose": a new step, not a simultaneous one
        return entry.text
    if first.endswith("ing") and not first.startswith("try"):
        return as_gerund(entry.text)
    return entry.text


def rewrite(text: str) -> tuple[str, list[str]]:
    """The text with every known gesture or pose replaced by its motion words."""
    reasons = []
    for entry, rx in _PATTERNS:
        def sub(m, entry=entry):
            out = _form(entry, m)
            intro = (m.group("intro") or "").lower()
            if out == entry.hold and not intro.endswith("ing") and not _verb_before(m):
                out = f"stands {out}"                        # "hold a T-pose": the body stands
            det = (m.group("det") or "").lower()
            count = int(det) if det.isdigit() else _NUMBERS.get(det, 1)
            if count > 1:
                out += " twice" if count == 2 else f" {det} times"
            reasons.append(f"lexicon: '{m.group(0)}' → '{out}' ({entry.name})")
            return out
        text = rx.sub(sub, text)
    return text, reasons


def _verb_before(m: re.Match) -> bool:
    """Is there a motion verb in the clause before the match ("walks holding a T-pose")?"""
    clause = re.split(r"[,.;]|\bthen\b", m.string[:m.start()])[-1]
    return any((h := lookup(w)) and h[0].kind != "light" for w in clause.split())


def find(text: str) -> Entry | None:
    """The first entry whose name occurs in the text."""
    for entry, rx in _PATTERNS:
        if rx.search(text):
            return entry
    return None


def phrases() -> list[tuple[str, str]]:
    """(name, text) of every entry: lexicon part of the similarity vocabulary."""
    return [(e.name, e.text) for e in LEXICON]
