"""What a segment asks for beyond its words' nearest captures: the direction of travel
relative to where the body faces, the side of a named limb, an exact count of an action, the
posture it starts in and the one it ends in (and holds).

    intent("a person kicks twice with the right leg", repeat=2)
        → Intent(side="right", action="kick", count=2)
    intent("a person runs backwards")            → Intent(travel="backward")
    intent("a person stands up from sitting on the floor") → Intent(start="sitting", end="standing")

Read from the segment's prompt, except what the plan says itself: `repeat` (the planner's
count) and `travel` (the planner's direction of travel, when its Segment carries one). The
words are the catalogue's (`catalogue/actions.toml`: counted actions, speed bands, manners);
the sentence structure around them is `catalogue/grammar.py`.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from interplay.catalogue import grammar as g
from interplay.catalogue.load import catalogue, on_change
from interplay.catalogue.words import tokens, words
from interplay.planner.verbs import forms

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


FASTEST_M_S = 4.0        # about the fastest captured runs (CMU, Bandai Namco dashes)
COUNTED = ACTIONS        # the counted events, in the order a prompt's words are tried


def _forms_of(a) -> tuple[str, ...]:
    """An entry's word forms: its `words`, else a verb's forms and nouns ("boing", "boings")."""
    if a.words:
        return tuple(a.words)
    if a.kind in ("travel", "whole", "part"):
        return tuple(dict.fromkeys([*forms(a.name).values(), *a.nouns, *(n + "s" for n in a.nouns)]))
    return ()


# patterns by the names of the entries they find, built once per catalogue in use
_PATTERNS: dict[tuple[str, ...], re.Pattern] = {}
on_change(_PATTERNS.clear)


def _words(entries) -> re.Pattern:
    """One pattern for the word forms of catalogue entries (each with its own exceptions)."""
    entries = list(entries)
    key = tuple(a.name for a in entries)
    if key not in _PATTERNS:
        _PATTERNS[key] = g.any_words_rx(tuple((_forms_of(a), tuple(a.not_before)) for a in entries if _forms_of(a)))
    return _PATTERNS[key]


def _entry(name: str) -> re.Pattern:
    a = catalogue().get(name)
    return _words([a] if a is not None else [])


def _band(*bands: str, kinds=("travel", "whole", "manner")) -> re.Pattern:
    return _words(a for a in catalogue().action if a.speed_band in bands and a.kind in kinds)


def speed_of(prompt: str) -> str | None:
    """The speed band travel is asked in: sprint (sprint, dash, as fast as …), jog, run ("run
    slowly" jogs), slow (a slow, tired or sneaking walk); None when no speed is said. The words
    of each band are the catalogue's (`speed_band`)."""
    t = prompt.lower()
    slow = _band("slow").search(t)
    if _band("sprint").search(t):
        return "sprint"
    if _band("jog").search(t) or _band("run").search(t) and slow:
        return "jog"
    if _band("run").search(t):
        return "run"
    if slow and _band("walk", "slow", kinds=("travel",)).search(t):
        return "slow"
    return None


def _spins() -> re.Pattern:
    """Words of the catalogue's actions checked as a whole turn (spin, twirl, pirouette)."""
    return _words(a for a in catalogue().action
                  if any(c.check == "turn" and getattr(c, "degrees", 0) == 360 for c in a.checks))


def turn_of(prompt: str, repeat: int = 1) -> tuple[int, str] | None:
    """(degrees, direction) the body is asked to turn: a spin 360° a time ("spins twice":
    720°), "turns around" 180°, "turns left" 90° to the left; None when no turn is said."""
    t = prompt.lower()
    if _spins().search(t):
        return 360 * (count_of(t, repeat) or 1), "any"
    if words("turns_around").search(t):
        return 180, "any"
    m = words("turn_side").search(t)
    return (90, m.text.split()[-1]) if m else None


def still_of(prompt: str) -> bool:
    """Does the segment stop and stand ("stops walking and stands still", "halts")?"""
    t = prompt.lower()
    return bool(words("stops").search(t)) and not words("goes_on").search(t)


def _travel_forms() -> list[str]:
    return [w for a in catalogue().action if a.kind == "travel" for w in forms(a.name).values()]


def travel_of(prompt: str) -> str | None:
    """backward / left / right / sideways (either side) when the prompt asks to move that way
    relative to where the body faces ("walks backwards", "steps sideways to the left"); None
    for forward or free travel ("walks to the left" turns and walks: a path, not a direction
    of travel)."""
    t = prompt.lower()
    if _entry("backwards").search(t) or g.back_rx(tuple(_travel_forms())).search(t):
        return "backward"
    sideways, step = _entry("sideways").search(t), words("step_to_side").search(t)
    start = sideways.start() if sideways else step.start if step else None
    if start is not None:
        sides = [w.text for w in tokens(t[start:]) if w.text in ("left", "right")]
        return sides[0] if sides else "sideways"
    return None


def side_of(prompt: str) -> str | None:
    """The side of the limb a prompt names ("with the right leg", "your left fist"), if it
    names one side only."""
    sides = {f.text.split()[0].split("-")[0] for f in words("limb_side").finditer(prompt.lower())}
    return sides.pop() if len(sides) == 1 else None


def _counted(action: str) -> list:
    return [a for a in catalogue().action if a.counts_as == action]


def action_of(prompt: str) -> str | None:
    """The counted event the words name first in COUNTED's order (a hop is a jump, a jab a punch)."""
    t = prompt.lower()
    return next((c for c in COUNTED if _words(_counted(c)).search(t)), None)


def _singular(a) -> str:
    return a.name if a.kind in ("travel", "whole", "part") else _forms_of(a)[0].rstrip("*")


def count_of(prompt: str, repeat: int = 1) -> int | None:
    """How many times the action is asked for: the plan's repeat when over 1, else a number
    in the words ("twice", "three jumps", "once", "a tuck jump"); None when none is said."""
    if repeat > 1:
        return repeat
    t = prompt.lower()
    counted = [a for c in COUNTED for a in _counted(c)]
    singular = [_singular(a) for a in counted]
    plural = [forms(s)["third"] if a.kind in ("travel", "whole", "part") else s + "s"
              for a, s in zip(counted, singular)]
    m = g.times_rx(tuple(plural)).search(t)
    if m:
        return g.number(m.group(1) or m.group(2))
    if words("once").search(t) or g.one_rx(tuple(singular)).search(t):
        return 1
    return None


def postures_of(prompt: str) -> tuple[str | None, str | None, bool]:
    """(start, end, rises): the posture a prompt starts from ("from lying on the floor"), the
    one it ends in ("sits down", "lies down", "kneels"; "standing" for a get-up) and whether it
    gets up."""
    t = prompt.lower()
    start = None
    said = words("starts_from").search(t)
    if said:
        w = said.text.split()[1:]                       # "from the floor": after "from"
        start = ("sitting" if any(x.startswith(("sitting", "seated")) for x in w) else
                 "kneeling" if any(x.startswith("kneeling") for x in w) else "lying")
    rises = bool(words("rises").search(t))
    end = None
    if words("sits_up").search(t):
        start, end = start or "lying", "sitting"
    elif rises:
        end = "standing"
    else:
        end = next((p for p, said in (("sitting", "ends_sitting"), ("lying", "ends_lying"),
                                      ("kneeling", "ends_kneeling")) if words(said).search(t)), None)
    if start is not None and end is None:
        end = "standing"
    return start, end, rises


def hold_of(prompt: str) -> str | None:
    """The held pose the words ask for: "one_leg:right" (standing on the left, the right leg
    lifted), "squat" (held down), "still" (no fidgeting), or None. Held poses no capture holds
    for long (retrieve_edit.holds lays them over a stand or a squat)."""
    t = prompt.lower()
    if any(words("one_leg").search(sentence) for sentence in t.split(".")) and not _words(_counted("jump") + _counted("kick")).search(t):
        said = list(g.LEG_SIDE.finditer(t))
        stance = next((m.group(1) for m in said if m.group(1)), None)
        lifted = next((m.group(2) for m in said if m.group(2)), None)
        side = lifted or ({"left": "right", "right": "left"}[stance] if stance else "right")
        return f"one_leg:{side}"
    if g.held_rx(tuple(w for a in _counted("squat") for w in a.words)).search(t):
        return "squat"
    if _entry("motionless").search(t):
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
                  # on the spot (hops, "march in place", "jog on the spot"): an action's draws
                  # that stay put are preferred (tracks.py), frames that still travel are kept
                  # on the spot (on_the_spot.py); a direction of travel in the same words wins
                  in_place=bool(_entry("on the spot").search(prompt)) and go is None,
                  hold=hold)
