"""The motion verbs the planner knows: what moves (whole body, travel, one part), how long one
performance takes, which posture it ends in, and their word forms.

    lookup("walked")  → (VERBS["walk"], "past")
    third("sit") == "sits", gerund("sit") == "sitting"

Kinds: "travel" (moves the whole body along a path: walk, run, hop …), "whole" (whole body in
place: jump, sit, spin …), "part" (a limb does it: wave, raise, kick …; `part` says which by
default: "arm", "leg" or "arms" for both), "light" (carries no motion itself: do, perform,
start, keep …; the motion is in its object or the verb after it).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache


@dataclass(frozen=True)
class Verb:
    base: str
    kind: str                    # "travel" | "whole" | "part" | "light"
    seconds: float = 2.0         # one performance (travel: default length of the walk/run)
    part: str | None = None      # part verbs: "arm" | "leg" | "arms" | "legs"
    posture: str | None = None   # posture afterwards: standing, sitting, lying, squatting …
    speed: float | None = None   # travel: metres per second


def _v(base, kind, seconds=2.0, part=None, posture=None, speed=None):
    return Verb(base, kind, seconds, part, posture, speed)


# Durations are typical HumanML3D-style performances; travel speeds are ordinary gaits.
VERBS: dict[str, Verb] = {v.base: v for v in [
    _v("walk", "travel", 4.0, posture="standing", speed=1.3),
    _v("stroll", "travel", 4.0, posture="standing", speed=1.0),
    _v("march", "travel", 4.0, posture="standing", speed=1.3),
    _v("step", "travel", 1.5, posture="standing", speed=1.0),
    _v("sneak", "travel", 4.0, posture="standing", speed=0.8),
    _v("tiptoe", "travel", 4.0, posture="standing", speed=0.7),
    _v("run", "travel", 3.0, posture="standing", speed=3.0),
    _v("jog", "travel", 3.5, posture="standing", speed=2.2),
    _v("sprint", "travel", 3.0, posture="standing", speed=5.0),
    _v("hop", "travel", 2.5, posture="standing", speed=1.0),
    _v("skip", "travel", 3.0, posture="standing", speed=1.5),
    _v("crawl", "travel", 4.0, posture="crawling", speed=0.5),
    _v("move", "travel", 3.0, posture="standing", speed=1.3),
    _v("go", "travel", 3.0, posture="standing", speed=1.3),
    _v("slide", "whole", 2.0, posture="kneeling"),
    _v("moonwalk", "travel", 4.0, posture="standing", speed=0.6),
    _v("shuffle", "travel", 3.0, posture="standing", speed=0.8),
    _v("limp", "travel", 4.0, posture="standing", speed=0.8),
    _v("jump", "whole", 2.0, posture="standing"),
    _v("leap", "whole", 2.0, posture="standing"),
    _v("spin", "whole", 1.5, posture="standing"),
    _v("twirl", "whole", 1.5, posture="standing"),
    _v("pirouette", "whole", 1.5, posture="standing"),
    _v("turn", "whole", 1.5),
    _v("rotate", "whole", 1.5),
    _v("sit", "whole", 2.0, posture="sitting"),
    _v("stand", "whole", 2.0, posture="standing"),
    _v("rise", "whole", 2.0, posture="standing"),
    _v("squat", "whole", 2.0, posture="standing"),
    _v("crouch", "whole", 2.0, posture="squatting"),
    _v("kneel", "whole", 2.0, posture="kneeling"),
    _v("lie", "whole", 3.0, posture="lying"),
    _v("fall", "whole", 1.5, posture="lying"),
    _v("topple", "whole", 1.5, posture="lying"),
    _v("collapse", "whole", 1.5, posture="lying"),
    _v("trip", "whole", 1.5, posture="lying"),
    _v("stumble", "whole", 1.5, posture="standing"),
    _v("stagger", "whole", 1.5, posture="standing"),
    _v("stop", "whole", 2.5, posture="standing"),      # slows down, then is seen standing
    _v("follow", "travel", 4.0, posture="standing", speed=1.3),
    _v("chase", "travel", 3.0, posture="standing", speed=3.0),
    _v("lead", "travel", 4.0, posture="standing", speed=1.0),
    _v("dive", "whole", 1.5, posture="lying"),
    _v("roll", "whole", 2.0, posture="lying"),
    _v("cartwheel", "whole", 2.0, posture="standing"),
    _v("somersault", "whole", 2.0, posture="standing"),
    _v("flip", "whole", 2.0, posture="standing"),
    _v("bow", "whole", 2.0, posture="standing"),
    _v("curtsy", "whole", 2.0, posture="standing"),
    _v("bend", "whole", 2.0),
    _v("lean", "whole", 2.0),
    _v("dance", "whole", 4.0, posture="standing"),
    _v("stretch", "part", 2.0, "arms"),
    _v("hug", "whole", 2.5), _v("embrace", "whole", 2.5),
    _v("lunge", "whole", 2.0, posture="standing"),
    _v("land", "whole", 1.5),
    _v("dodge", "whole", 1.5, posture="standing"),
    _v("duck", "whole", 1.5, posture="standing"),
    _v("wait", "whole", 2.0), _v("stay", "whole", 2.0), _v("pose", "whole", 2.0),
    _v("look", "whole", 1.5), _v("nod", "whole", 1.0), _v("balance", "whole", 2.5),
    _v("kick", "part", 1.2, "leg"), _v("stomp", "part", 1.0, "leg"),
    _v("tap", "part", 1.0, "leg"), _v("lift", "part", 1.5, "arm"),
    _v("raise", "part", 1.5, "arm"), _v("lower", "part", 1.2, "arm"),
    _v("wave", "part", 2.0, "arm"), _v("point", "part", 1.5, "arm"),
    _v("reach", "part", 1.5, "arm"), _v("grab", "part", 1.5, "arm"),
    _v("punch", "part", 1.0, "arm"), _v("throw", "part", 1.5, "arm"),
    _v("swing", "part", 2.0, "arm"), _v("extend", "part", 1.5, "arm"),
    _v("clap", "part", 1.0, "arms"), _v("cross", "part", 1.5, "arms"),
    _v("cover", "part", 1.5, "arms"), _v("shrug", "part", 1.0, "arms"),
    _v("flex", "part", 2.0, "arms"), _v("salute", "part", 1.5, "arm"),
    _v("pump", "part", 1.0, "arm"), _v("shake", "part", 2.0, "arm"),
    _v("hold", "part", 2.0, "arm"), _v("keep", "light", 2.0),
    _v("rest", "part", 2.0, "arm"), _v("put", "part", 1.5, "arm"),
    _v("place", "part", 1.5, "arm"), _v("press", "part", 1.5, "arms"),
    _v("push", "part", 1.5, "arms"), _v("shove", "part", 1.5, "arms"),
    _v("hit", "part", 1.0, "arm"), _v("tackle", "whole", 1.5, posture="standing"), _v("pull", "part", 1.5, "arms"),
    _v("catch", "part", 1.5, "arms"), _v("shoot", "part", 1.5, "arm"),
    _v("dribble", "part", 2.0, "arm"), _v("chop", "part", 1.0, "arm"),
    _v("circle", "part", 2.0, "arm"), _v("rub", "part", 2.0, "arms"),
    _v("tuck", "part", 1.5, "arm"), _v("thrust", "part", 1.0, "arm"),
    _v("smash", "part", 1.2, "arms"), _v("open", "part", 1.5, "arms"),
    _v("touch", "part", 1.5, "arm"), _v("bring", "part", 1.5, "arm"),
    _v("drop", "whole", 1.5), _v("sway", "whole", 2.0), _v("glide", "travel", 3.0, speed=0.8),
    _v("spread", "part", 1.5, "legs"), _v("slap", "part", 1.0, "arm"), _v("clench", "part", 1.0, "arm"),
    _v("pat", "part", 1.5, "arm"), _v("scratch", "part", 1.5, "arm"), _v("stir", "part", 2.0, "arm"),
    _v("do", "light"), _v("perform", "light"), _v("make", "light"), _v("strike", "light"),
    _v("imitate", "light"), _v("execute", "light"), _v("start", "light"),
    _v("begin", "light"), _v("continue", "light"), _v("try", "light"), _v("attempt", "light"),
    _v("get", "light"), _v("switch", "light"), _v("transition", "light"), _v("pretend", "light"),
    _v("take", "light"), _v("give", "light"), _v("finish", "light"),
]}

_IRREGULAR = {  # base: (third, gerund, past, participle)
    "run": ("runs", "running", "ran", "run"), "sit": ("sits", "sitting", "sat", "sat"),
    "stand": ("stands", "standing", "stood", "stood"), "get": ("gets", "getting", "got", "got"),
    "swing": ("swings", "swinging", "swung", "swung"), "throw": ("throws", "throwing", "threw", "thrown"),
    "fall": ("falls", "falling", "fell", "fallen"), "lie": ("lies", "lying", "lay", "lain"),
    "spin": ("spins", "spinning", "spun", "spun"), "rise": ("rises", "rising", "rose", "risen"),
    "do": ("does", "doing", "did", "done"), "make": ("makes", "making", "made", "made"),
    "strike": ("strikes", "striking", "struck", "struck"), "begin": ("begins", "beginning", "began", "begun"),
    "go": ("goes", "going", "went", "gone"), "keep": ("keeps", "keeping", "kept", "kept"),
    "take": ("takes", "taking", "took", "taken"), "give": ("gives", "giving", "gave", "given"),
    "shake": ("shakes", "shaking", "shook", "shaken"), "hold": ("holds", "holding", "held", "held"),
    "put": ("puts", "putting", "put", "put"), "catch": ("catches", "catching", "caught", "caught"),
    "shoot": ("shoots", "shooting", "shot", "shot"), "slide": ("slides", "sliding", "slid", "slid"),
    "dive": ("dives", "diving", "dove", "dived"), "leap": ("leaps", "leaping", "leapt", "leapt"),
    "bend": ("bends", "bending", "bent", "bent"), "kneel": ("kneels", "kneeling", "knelt", "knelt"),
    "bring": ("brings", "bringing", "brought", "brought"), "try": ("tries", "trying", "tried", "tried"),
    "spread": ("spreads", "spreading", "spread", "spread"),
    "curtsy": ("curtsies", "curtsying", "curtsied", "curtsied"),
    "lean": ("leans", "leaning", "leaned", "leaned"),
    "lead": ("leads", "leading", "led", "led"), "hit": ("hits", "hitting", "hit", "hit"),
}
_DOUBLE = {"hop", "skip", "step", "jog", "tap", "trip", "flip", "grab", "chop", "drop", "stop",
           "nod", "clap", "shrug", "hug", "pat", "stir", "slap", "squat", "rub", "stab", "bob"}


def _regular(base: str) -> tuple[str, str, str, str]:
    if base.endswith(("s", "sh", "ch", "x", "z")):
        third = base + "es"
    elif base.endswith("y") and base[-2] not in "aeiou":
        third = base[:-1] + "ies"
    else:
        third = base + "s"
    if base in _DOUBLE:
        stem = base + base[-1]
    elif base.endswith("e") and not base.endswith(("ee", "ye", "oe")):
        stem = base[:-1]
    else:
        stem = base
    gerund = stem + "ing"
    if base.endswith("e"):
        past = base + "d"
    elif base.endswith("y") and base[-2] not in "aeiou":
        past = base[:-1] + "ied"
    else:
        past = stem + "ed"
    return third, gerund, past, past


def forms(base: str) -> dict[str, str]:
    """{"base", "third", "gerund", "past", "participle"} of a verb."""
    third, gerund, past, part = _IRREGULAR.get(base) or _regular(base)
    return {"base": base, "third": third, "gerund": gerund, "past": past, "participle": part}


def third(base: str) -> str:
    return forms(base)["third"]


def gerund(base: str) -> str:
    return forms(base)["gerund"]


@lru_cache(maxsize=1)
def _table() -> dict[str, tuple[Verb, str]]:
    out: dict[str, tuple[Verb, str]] = {}
    for verb in VERBS.values():
        for form, word in forms(verb.base).items():
            out.setdefault(word, (verb, form))
    return out


def lookup(word: str) -> tuple[Verb, str] | None:
    """The verb and form of a word ("sat" → (sit, "past")), None for other words."""
    return _table().get(word.lower().strip(".,;:!?\"'"))


def is_verb(word: str, kinds: tuple[str, ...] = ("travel", "whole", "part")) -> bool:
    hit = lookup(word)
    return hit is not None and hit[0].kind in kinds


# Nouns that name a motion ("a squat", "two kicks", "hand claps") → the verb they stand for.
NOUNS = {"squat": "squat", "kick": "kick", "punch": "punch", "jump": "jump", "spin": "spin",
         "turn": "turn", "clap": "clap", "tap": "tap", "bow": "bow", "curtsy": "curtsy",
         "lunge": "lunge", "leap": "leap", "hop": "hop", "step": "step", "wave": "wave",
         "somersault": "somersault", "cartwheel": "cartwheel", "flip": "flip", "roll": "roll",
         "run": "run", "walk": "walk", "sprint": "sprint", "dive": "dive", "stretch": "stretch",
         "dance": "dance", "salute": "salute", "shrug": "shrug", "stomp": "stomp", "twirl": "twirl",
         "pirouette": "pirouette", "swing": "swing", "throw": "throw", "chop": "chop", "fall": "fall",
         "handstand": "handstand", "crawl": "crawl", "nod": "nod", "hug": "hug"}
# Nouns done with "does a …" rather than turned into a verb ("does a handstand").
DOING_NOUNS = {"handstand": ("whole", 3.0, "standing"), "push-up": ("whole", 3.0, "lying"),
               "sit-up": ("whole", 3.0, "lying"), "jumping jack": ("whole", 1.0, "standing")}


def noun_verb(word: str) -> str | None:
    """The verb a motion noun stands for: "squats" → "squat", "claps" → "clap"."""
    w = word.lower().strip(".,;:!?\"'")
    if w in NOUNS:
        return NOUNS[w]
    if w.endswith("es") and w[:-2] in NOUNS:
        return NOUNS[w[:-2]]
    if w.endswith("s") and w[:-1] in NOUNS:
        return NOUNS[w[:-1]]
    return None
