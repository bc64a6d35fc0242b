"""What a segment asks for beyond its words' nearest captures: the direction of travel
relative to where the body faces, the side of a named limb, an exact count of an action, the
posture it starts in and the one it ends in (and holds).

    intent("a person kicks twice with the right leg", repeat=2)
        → Intent(side="right", action="kick", count=2)
    intent("a person runs backwards")            → Intent(travel="backward")
    intent("a person stands up from sitting on the floor") → Intent(start="sitting", end="standing")

Read from the segment's prompt, except what the plan says itself: `repeat` (the planner's
count) and `travel` (the planner's direction of travel, when its Segment carries one). These
are small word rules meant to be replaced by the plan's own fields as the planner grows them.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

TRAVELS = ("backward", "left", "right", "sideways")
ACTIONS = ("jump", "squat", "kick", "punch", "step")
POSTURES = ("standing", "sitting", "lying", "kneeling")
LOW = ("sitting", "lying", "kneeling")


@dataclass(frozen=True)
class Intent:
    travel: str | None = None   # backward / left / right / sideways (either side); None: forward or free
    side: str | None = None     # left / right: the side of a named limb
    action: str | None = None   # jump / squat / kick / punch / step (what a count counts)
    count: int | None = None    # exactly this many of the action (None: no number asked)
    start: str | None = None    # the posture it starts in (None: standing, or where it is)
    end: str | None = None      # the posture it ends in and holds (None: no posture asked)
    rises: bool = False         # it gets up (from wherever the previous segment left it)
    speed: str | None = None    # slow / jog / run / sprint: the speed band travel must land in
    turn: tuple[int, str] | None = None   # (degrees, left / right / any) the facing must turn
    still: bool = False         # it stops and stands still (the pelvis stays within a step)
    in_place: bool = False      # on the spot / in place: the pelvis stays within 0.6 m
    hold: str | None = None     # a held pose: "one_leg:left|right" (the lifted leg), "squat", "still"

    @property
    def plain(self) -> bool:
        return self == Intent()


_BACK = re.compile(r"\bbackwards?\b|\bin\s+reverse\b|\bbackpedal\w*|\bmoonwalk\w*|"
                   r"\b(?:step|steps|stepping|stepped|walk|walks|walking|move|moves|moving|"
                   r"run|runs|running|jog|jogs|jogging|shuffles?|shuffling)\s+back\b"
                   r"(?!\s+(?:up|to|home|and|into|in)\b)")
_SIDEWAYS = re.compile(r"\bsideways\b|\bside[\s-]?(?:steps?|stepping|shuffl\w*)\b|\bstrafe\w*|"
                       r"\bcrab[\s-]?walk\w*|\bsteps?\s+(?:to|towards)\s+(?:the|his|her|their)\s+"
                       r"(?:left|right)\b")
_LIMB = r"(?:leg|foot|feet|knee|arm|hand|fist|elbow|shoulder)s?"
_SIDE = re.compile(rf"\b(left|right)(?:[\s-]+(?:hand(?:ed)?|footed))?\s+{_LIMB}\b|"
                   rf"\b(left|right)[\s-]+(?:handed|footed)\b")
_LEFT_RIGHT = re.compile(r"\b(left|right)\b")
_ACTION = [(r"\b(?:jump|jumps|jumped|jumping|hop|hops|hopped|hopping)\b", "jump"),
           (r"\bsquat\w*\b", "squat"),
           (r"\bkick\w*\b", "kick"),
           (r"\b(?:punch\w*|jab\w*|uppercut\w*)\b", "punch"),
           (r"\bsteps?\b", "step")]
_NUMBERS = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7,
            "eight": 8, "nine": 9, "ten": 10}
_ONCE = re.compile(r"\bonce\b|\bone\s+time\b|\ba\s+single\b")
_TIMES = re.compile(r"\b(twice|thrice)\b|\b(\d+|one|two|three|four|five|six|seven|eight|nine|ten)"
                    r"\s+(?:times\b|(?:\w+\s+)?(?:jumps|hops|squats|kicks|punches|steps)\b)")
_ONE = re.compile(r"\b(?:a|an|one|single)\s+(?:(?!(?:few|couple|bit|little|lot|series|number|in|"
                  r"on|at|with|your|his|her|their|the|of|to|for|and)\b)[a-z-]+\s+){0,2}?"
                  r"(?:jump|hop|squat|kick|punch|jab|step)\b")
_FROM = re.compile(r"\bfrom\s+(?:a\s+|the\s+|his\s+|her\s+|their\s+)?(lying|lying\s+down|"
                   r"sitting|seated|sitting\s+down|kneeling|the\s+floor|the\s+ground|floor|ground)")
_RISE = re.compile(r"\b(?:gets?|getting|got)\s+(?:back\s+)?up\b|\bstands?\s+(?:back\s+)?up\b|"
                   r"\bstanding\s+(?:back\s+)?up\b|\brises?\b|\brising\b")
_ENDS = [(r"\bsits?\s+up\b|\bsitting\s+up\b", "sitting"),
         (r"\b(?:sits?|sitting|sat)\b(?!\s+up)|\btakes?\s+a\s+seat\b", "sitting"),
         (r"\b(?:lies|lie|lying|lays?|laying)\s+(?:down|on)\b|\blies\b", "lying"),
         (r"\bkneel\w*\b|\bon\s+(?:one|both|his|her|their)\s+knees?\b", "kneeling")]


_SPRINT = re.compile(r"\bsprint\w*|\bdash\w*|\bas\s+fast\s+as\b|\bfull\s+speed\b|\bflat\s+out\b")
_JOG = re.compile(r"\bjog\w*")
_RUN = re.compile(r"\b(?:run|runs|running|ran)\b(?!\s+(?:into|over|out|up|through)\b)")
_SLOW = re.compile(r"\bslow(?!s?\s+down|ing\s+down|ed\s+down)\w*|\bstroll\w*|\bshuffl\w*|\btired\w*|\bdrag\w*|\bsneak\w*|"
                   r"\btiptoe\w*|\bleisurely\b|\bexhausted\b")
_GOES = re.compile(r"\b(?:walk\w*|shuffl\w*|stroll\w*|mov\w*|amble\w*|sneak\w*|tiptoe\w*|"
                   r"plod\w*|trudg\w*|limp\w*)\b")
FASTEST_M_S = 4.0        # about the fastest captured runs (CMU, Bandai Namco dashes)


def speed_of(prompt: str) -> str | None:
    """The speed band travel is asked in: sprint (sprint, dash, as fast as …), jog, run ("run
    slowly" jogs), slow (a slow, tired or sneaking walk); None when no speed is said."""
    t = prompt.lower()
    if _SPRINT.search(t):
        return "sprint"
    if _JOG.search(t) or _RUN.search(t) and _SLOW.search(t):
        return "jog"
    if _RUN.search(t):
        return "run"
    if _SLOW.search(t) and _GOES.search(t):
        return "slow"
    return None


_SPIN = re.compile(r"\bspin\w*|\bpirouett\w*|\btwirl\w*")
_AROUND = re.compile(r"\bturn\w*\s+(?:all\s+the\s+way\s+)?a?round\b|\babout[- ]face\b|"
                     r"\bturn\w*\s+back\b")
_TURN_SIDE = re.compile(r"\bturn\w*\s+(?:to\s+(?:the|his|her|their)\s+)?(left|right)\b")


def turn_of(prompt: str, repeat: int = 1) -> tuple[int, str] | None:
    """(degrees, direction) the body is asked to turn: a spin 360° a time ("spins twice":
    720°), "turns around" 180°, "turns left" 90° to the left; None when no turn is said."""
    t = prompt.lower()
    if _SPIN.search(t):
        return 360 * (count_of(t, repeat) or 1), "any"
    if _AROUND.search(t):
        return 180, "any"
    m = _TURN_SIDE.search(t)
    return (90, m.group(1)) if m else None


_STILL = re.compile(r"\bstands?\s+still\b|\bstops?\b(?!\s+\w+ing\s+(?:the|a|his|her)\b)|"
                    r"\bhalts?\b|\bcomes?\s+to\s+a\s+(?:stop|halt)\b")


_IN_PLACE = re.compile(r"\bon\s+the\s+spot\b|\bin\s+place\b|\bwithout\s+(?:moving|travell?ing)\b|"
                       r"\bstationary\b")


def still_of(prompt: str) -> bool:
    """Does the segment stop and stand ("stops walking and stands still", "halts")?"""
    t = prompt.lower()
    return bool(_STILL.search(t)) and not re.search(r"\bthen\b|\bstarts?\b|\bagain\b", t)


def travel_of(prompt: str) -> str | None:
    """backward / left / right / sideways (either side) when the prompt asks to move that way
    relative to where the body faces ("walks backwards", "steps sideways to the left"); None
    for forward or free travel ("walks to the left" turns and walks: a path, not a direction
    of travel)."""
    t = prompt.lower()
    if _BACK.search(t):
        return "backward"
    if _SIDEWAYS.search(t):
        side = _LEFT_RIGHT.findall(t[_SIDEWAYS.search(t).start():])  # type: ignore[union-attr]
        return side[0] if side else "sideways"
    return None


def side_of(prompt: str) -> str | None:
    """The side of the limb a prompt names ("with the right leg", "your left fist"), if it
    names one side only."""
    sides = {a or b for a, b in _SIDE.findall(prompt.lower())}
    return sides.pop() if len(sides) == 1 else None


def action_of(prompt: str) -> str | None:
    t = prompt.lower()
    return next((a for rx, a in _ACTION if re.search(rx, t)), None)


def count_of(prompt: str, repeat: int = 1) -> int | None:
    """How many times the action is asked for: the plan's repeat when over 1, else a number
    in the words ("twice", "three jumps", "once", "a tuck jump"); None when none is said."""
    if repeat > 1:
        return repeat
    t = prompt.lower()
    m = _TIMES.search(t)
    if m:
        w = m.group(1) or m.group(2)
        return {"twice": 2, "thrice": 3}.get(w) or (int(w) if w.isdigit() else _NUMBERS[w])
    if _ONCE.search(t) or _ONE.search(t):
        return 1
    return None


def postures_of(prompt: str) -> tuple[str | None, str | None, bool]:
    """(start, end, rises): the posture a prompt starts from ("from lying on the floor"), the
    one it ends in ("sits down", "lies down", "kneels"; "standing" for a get-up) and whether it
    gets up."""
    t = prompt.lower()
    start = None
    m = _FROM.search(t)
    if m:
        w = m.group(1)
        start = ("sitting" if w.startswith(("sitting", "seated")) else
                 "kneeling" if w.startswith("kneeling") else "lying")
    rises = bool(_RISE.search(t))
    end = None
    if re.search(r"\bsits?\s+up\b|\bsitting\s+up\b", t):
        start, end = start or "lying", "sitting"
    elif rises:
        end = "standing"
    else:
        end = next((p for rx, p in _ENDS if re.search(rx, t)), None)
    if start is not None and end is None:
        end = "standing"
    return start, end, rises


# Held poses no capture holds for long (retrieve_edit.holds lays them over a stand or a squat)
_ONE_LEG = re.compile(r"\b(?:stand\w*|balanc\w*|stay\w*|remain\w*)\b[^.]*?\bon (?:one|a single|the (?:left|right)"
                      r"|(?:your|his|her|their) (?:left|right)) (?:leg|foot)\b"
                      r"|\b(?:lift|rais)\w* (?:one|a|the (?:left|right)|(?:your|his|her|their) (?:left|right)) "
                      r"(?:leg|foot)\b[^.]*\b(?:balanc|hold)\w*")
_SQUAT_HELD = re.compile(r"\b(?:hold\w*|stay\w*|remain\w*|keep\w*)\b[^.]*\bsquat\w*|\bsquat\w*\b[^.]*\b(?:hold\w*|"
                         r"stay\w*|remain\w*)\b|\bin a (?:deep |low |full )?squat\b")
_STILL_HELD = re.compile(r"\b(?:perfectly|completely|totally|absolutely|very) still\b|\bmotionless\b|"
                         r"\bwithout (?:moving|a movement|motion)\b|\bdo(?:es)?n'?t move\b|\bfreez\w*\b|"
                         r"\bnot mov\w*\b|\bstock[- ]still\b|\bstill as a statue\b")


def hold_of(prompt: str) -> str | None:
    """The held pose the words ask for: "one_leg:right" (standing on the left, the right leg
    lifted), "squat" (held down), "still" (no fidgeting), or None."""
    t = prompt.lower()
    if _ONE_LEG.search(t) and not re.search(r"\bhop\w*|\bjump\w*|\bkick\w*", t):
        stance = re.search(r"\bon (?:the |your |his |her |their )?(left|right) (?:leg|foot)\b", t)
        lifted = re.search(r"\b(?:lift|rais)\w* (?:the |your |his |her |their )?(left|right)", t)
        side = (lifted.group(1) if lifted else
                {"left": "right", "right": "left"}[stance.group(1)] if stance else "right")
        return f"one_leg:{side}"
    if _SQUAT_HELD.search(t):
        return "squat"
    if _STILL_HELD.search(t):
        return "still"
    return None


def intent(prompt: str, repeat: int = 1, travel: str | None = None) -> Intent:
    """What a segment asks for (see the module doc); `travel` is the plan's own direction of
    travel when it has one ("forward" counts as none)."""
    go = travel if travel in TRAVELS else None if travel is not None else travel_of(prompt)
    start, end, rises = postures_of(prompt)
    action = action_of(prompt)
    hold = hold_of(prompt)
    count = count_of(prompt, repeat) if action and hold != "squat" else None
    if action == "step" and count is None:
        action = None                      # "steps sideways": travel, not a count of steps
    return Intent(travel=go, side=side_of(prompt), action=action, count=count,
                  start=start, end=end, rises=rises, speed=speed_of(prompt),
                  turn=turn_of(prompt, repeat) if action is None else None,
                  still=still_of(prompt) and action is None and go is None,
                  # an action on the spot (hops, jumps, kicks): a wider text draw kept only
                  # for staying put plays clips of other actions that do
                  in_place=bool(_IN_PLACE.search(prompt.lower())) and go is None and action is not None,
                  hold=hold)
