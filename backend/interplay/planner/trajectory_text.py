"""Trajectory phrases → a TrajectorySpec (what CoMA's planner forwards to the trajectory editor).

    parse("walks in a circle counterclockwise")      → circle, clockwise=False
    parse("runs 5 metres forward")                   → line, distance_m=5, waypoints [[0,0],[0,5]]
    parse("walks 4 m and turns right at 3 o'clock")  → line, turn_at={"clock": 3, "side": "right"}
    parse("walks backwards")                         → polyline [[0, 0], [0, -4]]

Coordinates: metres on the floor, [x, z] in the person's start frame, +z ahead, +x to their
left (as `curves.make_curve` draws them: a line runs along +z, `turn_at` turns it half-way).
Clockwise is seen from above; walking "in a circle to the right" is clockwise. Plain
"forward" (a free walk or run) is no trajectory: Table 8 marks only shapes, paths and
distances as explicit trajectories.
"""

from __future__ import annotations

import math
from typing import Literal, cast

from interplay.catalogue import grammar as g
from interplay.catalogue.words import words
from interplay.planner.schema import (
    MAX_COORD,
    MAX_PATH_M,
    MAX_SIZE_M,
    MAX_TURNS,
    TrajectorySpec,
    TurnAt,
    spec_length,
)

_NUM = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
        "nine": 9, "ten": 10, "twenty": 20, "a": 1, "half a": 0.5, "a half": 0.5}
_UNIT = {"m": 1.0, "metre": 1.0, "meter": 1.0, "metres": 1.0, "meters": 1.0, "step": 0.7,
         "steps": 0.7, "foot": 0.3048, "feet": 0.3048, "ft": 0.3048, "yard": 0.9144,
         "yards": 0.9144, "pace": 0.7, "paces": 0.7}
_CLOCK_WORDS = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7,
                "eight": 8, "nine": 9, "ten": 10, "eleven": 11, "twelve": 12}
# (shape, the words.toml list that says it); first said wins
_SHAPES = [("figure_eight", "path_figure_eight"), ("zigzag", "path_zigzag"), ("s_curve", "path_s_curve"),
           ("heart", "path_heart"), ("spiral", "path_spiral"), ("square", "path_square"), ("arc", "path_arc"),
           ("circle", "path_circle"), ("line", "path_line"), ("free", "path_free")]
_DIRECTION = [("backward", "path_backward"), ("left", "path_left"), ("right", "path_right")]
DEFAULT_LINE = 4.0    # metres of a sideways/backwards walk with no distance given
_HEADING = {"forward": (0.0, 1.0), "backward": (0.0, -1.0), "left": (1.0, 0.0), "right": (-1.0, 0.0)}


def _number(word: str) -> float:
    word = " ".join(word.split())                  # "half  a": a number's words, no spaces around
    return float(word) if word[:1].isdecimal() else float(_NUM[word])


def _direction(text: str) -> str | None:
    return next((name for name, said in _DIRECTION if words(said).search(text)), None)


def parse(text: str) -> TrajectorySpec | None:
    """The trajectory a clause asks for, or None for free or in-place motion."""
    t = text.lower()
    clock = g.PATH_CLOCK.search(t)
    if clock:
        word = clock.group(2)
        hour = int(word) if word.isdigit() else _CLOCK_WORDS[word]
        if 1 <= hour <= 12:
            said = cast(Literal["left", "right"] | None, clock.group(1))   # the pattern's (left|right)?
            side = said or ("right" if hour < 6 else "left" if hour > 6 else None)
            dist = g.PATH_DISTANCE.search(t)
            distance_m = round(_number(dist.group(1)) * _UNIT[dist.group(2)], 3) if dist else None
            return _bounded({"shape": "line", "turn_at": TurnAt(clock=hour, side=side),
                             "direction": "forward", "text": text.strip(),
                             "distance_m": distance_m})
    travel = words("travel_words").search(t) is not None or words("path_words").search(t)
    # Shapes only count for travel: "swings the arm in circles" is not a path.
    shape = next((s for s, said in _SHAPES if words(said).search(t)), None) if travel else None
    dist = g.PATH_DISTANCE.search(words("path_on_foot").cut(t, "")) if travel else None
    distance = _number(dist.group(1)) * _UNIT[dist.group(2)] if dist else None
    direction = _direction(dist.group(3) or "") if dist and dist.group(3) else None
    if shape is None and direction is None and travel:
        direction = _direction(t)
    if shape is None and (distance is not None or direction is not None):
        shape = "line"
    if shape is None:
        return None
    spec: dict = {"shape": shape, "text": text.strip()}
    if shape in ("circle", "arc", "spiral", "figure_eight", "square", "heart"):
        turning = next((c for c, w in ((False, "path_counterclockwise"), (True, "path_clockwise"),
                                       (True, "path_turning_right"), (False, "path_turning_left"))
                        if words(w).search(t)), None)
        if turning is not None:
            spec["clockwise"] = turning
        size = g.PATH_SIZE.search(t)
        sized = size.group(0) if size else ""
        if size and (not dist or any(w in sized for w in ("wide", "across", "diameter", "radius", "side", "big", "large"))
                     or t[size.end():].lstrip().startswith(("circle", "square", "heart", "spiral", "figure", "arc",
                                                             "semi"))):
            spec["size_m"] = _number(size.group(1)) * (2.0 if "radius" in size.group(0) else 1.0)
            distance = None                      # "a 3 m circle": its size, not the path length
        turns = g.PATH_TURNS.search(t)
        if turns and shape in ("circle", "spiral"):
            spec["turns"] = _number(turns.group(1))
        elif shape == "arc":
            spec["turns"] = 0.5
    if shape == "line":
        spec["direction"] = direction or "forward"
        if distance is not None:
            spec["distance_m"] = round(distance, 3)
        if spec["direction"] != "forward":      # a line along +z is the forward one: others as points
            d, (hx, hz) = distance or DEFAULT_LINE, _HEADING[spec["direction"]]
            spec["shape"] = "polyline"
            spec["waypoints"] = [(0.0, 0.0), (round(hx * d, 3), round(hz * d, 3))]
    elif distance is not None:
        spec["distance_m"] = round(distance, 3)
    return _bounded(spec)


def _bounded(spec: dict) -> TrajectorySpec:
    """The spec with its numbers brought within the schema's limits: none that is not positive,
    waypoints (and the distance with them) scaled to within MAX_COORD, size_m, turns and
    distance_m at most their maxima, and the whole path scaled down to MAX_PATH_M ("walks 300
    metres" walks 200, "walks 500 m backwards" 100; a preset is fitted to the motion's walk
    anyway)."""
    spec = {k: v for k, v in spec.items() if v is not None}
    for key in ("distance_m", "size_m", "turns"):
        if key in spec and not spec[key] > 0:
            del spec[key]

    def scale(k: float) -> None:
        for key in ("distance_m", "size_m"):
            if key in spec:
                spec[key] *= k
        if spec.get("waypoints"):
            spec["waypoints"] = [(x * k, z * k) for x, z in spec["waypoints"]]

    far = max((abs(c) for p in spec.get("waypoints") or [] for c in p), default=0.0)
    if far > MAX_COORD:
        scale(MAX_COORD / far)
    for key, top in (("distance_m", MAX_PATH_M), ("size_m", MAX_SIZE_M), ("turns", MAX_TURNS)):
        if key in spec:
            spec[key] = min(float(spec[key]), top)
    total = spec_length(TrajectorySpec.model_construct(**{**dict.fromkeys(
        TrajectorySpec.model_fields), **spec}))
    if total > MAX_PATH_M:
        scale(MAX_PATH_M / total * (1 - 1e-6))
    return TrajectorySpec(**spec)


def path_length(spec: TrajectorySpec) -> float | None:
    """Metres walked along a trajectory (None when it is not known: free paths, turns)."""
    if spec.distance_m:
        return spec.distance_m
    if spec.waypoints and len(spec.waypoints) > 1:
        return float(sum(math.dist(a, b) for a, b in zip(spec.waypoints, spec.waypoints[1:])))
    size = spec.size_m or 2.0
    circle = math.pi * size * (spec.turns or 1.0)
    return {"circle": circle, "arc": circle, "spiral": circle * 0.6, "figure_eight": 2 * circle,
            "square": 4 * size, "heart": 3.5 * size, "zigzag": 3.0 * size, "s_curve": 2.5 * size,
            "line": None, "polyline": None, "free": None}[spec.shape]


def _word_char(c: str) -> bool:
    return c.isalnum() or c == "_"


def turns_at_clock(clause: str) -> bool:
    """Does the clause only turn at a clock hour ("turns right at 3 o'clock", "he turns at two
    oclock")? It opens with "turn(s)" (after "he", "she", "they" or "it") and says "o'clock",
    "oclock" or "o clock" later on its line."""
    at = 0
    subject = next((p for p in ("he", "she", "they", "it")
                    if clause.startswith(p) and clause[len(p):len(p) + 1].isspace()), None)
    if subject is not None:
        at = len(subject)
        while at < len(clause) and clause[at].isspace():
            at += 1
    word = next((w for w in ("turns", "turn") if clause.startswith(w, at)
                 and not _word_char(clause[at + len(w):at + len(w) + 1] or " ")), None)
    if word is None:
        return False
    line_end = clause.find("\n", at)
    for i in range(at + len(word), line_end if line_end >= 0 else len(clause)):
        if clause[i] != "o" or _word_char(clause[i - 1]):
            continue                      # an "o" that opens a word, on the turn's line
        j = i + 1 + (clause[i + 1:i + 2] == "'")
        while j < len(clause) and clause[j].isspace():
            j += 1
        if clause.startswith("clock", j) and not _word_char(clause[j + 5:j + 6] or " "):
            return True
    return False

