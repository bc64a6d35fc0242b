"""The plan the planner hands to the generator, as validated pydantic models.

    Plan     {prompt, rewritten, persons, seconds, segments, reasons, planner, fallback_reason}
    Segment  {index, prompt, base, edits, trajectory, seconds, start, end, persons, roles, repeat,
              travel?, timing?, coverage?}

A segment is one temporal step of the motion (CoMA's P_i): `prompt` is its rewritten text,
`base` the whole-body motion (P_base), `edits` one instruction per body part or None (P_edit),
`trajectory` a path for the pelvis (P_traj). `start`/`end` are frames at 20 fps (end exclusive)
and the segments tile [0, round(seconds × 20)). `persons` lists the people who act in the
segment; with two people `roles` says what each one does ({"0": …, "1": …}) and `timing`,
when the segment is part of an exchange, who started it and when the other answers
("one pushes the other, who stumbles backwards": the push, then the stumble from the contact).
`travel` is the direction the moving people go relative to where they face ("walks backwards"
→ "backward"): a direction of the body's motion, never a path to turn round for. An edit that
starts with "holds" is a pose kept over the whole segment ("holds both arms crossed …").

Trajectory coordinates are metres on the floor as [x, z] in the first person's start frame:
+z is where they face, +x is their left (the skeleton's rest pose faces +Z, its left is +X).
The JSON keeps the keys the API streamed before (index/prompt/start/end/persons per segment).
"""

from __future__ import annotations

import math
from typing import Annotated, Literal, get_args

from pydantic import (
    AfterValidator,
    BaseModel,
    ConfigDict,
    Field,
    SerializerFunctionWrapHandler,
    Strict,
    ValidationError,
    field_validator,
    model_serializer,
    model_validator,
)

from interplay.motion.skeleton import FPS

Shape = Literal["line", "arc", "circle", "zigzag", "s_curve", "heart", "figure_eight", "square",
                "spiral", "polyline", "free"]
SHAPES: tuple[Shape, ...] = get_args(Shape)
PARTS = ("left_arm", "right_arm", "left_leg", "right_leg", "head")
MAX_SEGMENTS = 16
MAX_REPEAT = 20         # repetitions one segment holds ("claps 21 times" is planned as 20, said so)

# The cost bounds of a trajectory, whatever its form (drawn points, preset, waypoints, an LLM's
# plan): the trajectory editor's work grows with the path's length and point count.
MAX_PATH_M = 200.0      # metres along the path: 20 s (the longest motion) at 10 m/s, a sprint
MAX_COORD = 100.0       # metres from the origin, any coordinate of a drawn point or waypoint
MAX_POINTS = 2000       # drawn points or waypoints
MAX_SPEED = 10.0        # m/s: a drawn path may be at most MAX_SPEED × the motion's seconds long
MAX_SIZE_M = 50.0       # a preset's size_m
MAX_TURNS = 20.0        # a preset's turns

# make_curve's defaults (metres): each shape's size, forward length and turns when not given.
DEFAULT_SIZE = {"arc": 4.0, "circle": 2.0, "zigzag": 1.0, "s_curve": 1.5, "heart": 2.5,
                "figure_eight": 4.0, "square": 2.0, "spiral": 3.0}
DEFAULT_DISTANCE = {"line": 4.0, "zigzag": 4.0, "s_curve": 4.0}
DEFAULT_TURNS = {"arc": 0.25, "circle": 1.0, "spiral": 2.0}

# Numbers as JSON numbers only: strict, so `true` or "3" is not taken for a number.
Metres = Annotated[float, Strict(), Field(allow_inf_nan=False)]


def _within(v: float) -> float:
    if abs(v) > MAX_COORD:
        raise ValueError(f"must be within ±{MAX_COORD:g} m, got {v:g}")
    return v


Coord = Annotated[float, Strict(), Field(allow_inf_nan=False, json_schema_extra={
    "minimum": -MAX_COORD, "maximum": MAX_COORD}), AfterValidator(_within)]
Point = tuple[Coord, Coord]


def polyline_length(points) -> float:
    """Metres along straight legs through points [[x, z], …]."""
    return float(sum(math.dist(a, b) for a, b in zip(points, points[1:])))


class TurnAt(BaseModel):
    """A turn towards a clock direction around the person (12 ahead, 3 to the right)."""
    model_config = ConfigDict(extra="forbid")
    clock: Annotated[int, Strict()] = Field(ge=1, le=12)
    side: Literal["left", "right"] | None = None
    after_m: Metres | None = Field(default=None, gt=0, le=MAX_PATH_M,
                                   description="Metres ahead before the turn (default half "
                                               "the distance).")


class TrajectorySpec(BaseModel):
    model_config = ConfigDict(extra="forbid", json_schema_extra={
        "description": f"A preset path. Its length (as drawn: size_m, distance_m, turns, "
                       f"waypoints, turn_at together) is at most {MAX_PATH_M:g} m; waypoints are "
                       f"at most {MAX_POINTS} [x, z] pairs within ±{MAX_COORD:g} m; a polyline "
                       f"needs two waypoints or a turn_at."})
    shape: Shape
    clockwise: Annotated[bool, Strict()] | None = None                 # seen from above
    size_m: Metres | None = Field(default=None, gt=0, le=MAX_SIZE_M)   # diameter / side / width
    distance_m: Metres | None = Field(default=None, gt=0, le=MAX_PATH_M)  # path or line length
    turns: Metres | None = Field(default=None, gt=0, le=MAX_TURNS)     # circles, arcs, spirals
    direction: Literal["forward", "backward", "left", "right"] | None = None
    waypoints: list[Point] | None = Field(default=None, max_length=MAX_POINTS)  # [[x, z], …] m
    turn_at: TurnAt | None = None
    text: str | None = Field(default=None, max_length=500)   # the phrase it was read from

    @model_validator(mode="after")
    def _polyline_has_points(self):
        if self.shape == "polyline" and (not self.waypoints or len(self.waypoints) < 2) \
                and self.turn_at is None:
            raise ValueError("a polyline trajectory needs at least two waypoints or a turn_at")
        total = spec_length(self)
        if total > MAX_PATH_M:
            raise ValueError(f"the {self.shape} path is {total:.0f} m long; the limit is "
                             f"{MAX_PATH_M:g} m")
        return self


_HEART = (2 + math.pi) / (1 + math.sqrt(2) / 2)   # heart path length / width (curves.heart)
_LEMNISCATE = 2.622057554292119                  # figure-eight path length / end-to-end size


def _sine_length(forward: float, amplitude: float) -> float:
    """Length of one sine period `forward` long with `amplitude` (curves.s_curve)."""
    k = 2 * math.pi * amplitude / forward
    n = 64                                         # periodic: the mean converges fast
    return forward * sum(math.sqrt(1 + (k * math.cos(2 * math.pi * i / n)) ** 2)
                         for i in range(n)) / n


def spec_length(spec: TrajectorySpec) -> float:
    """Metres along the path `curves.make_curve` draws for `spec` (before it is fitted to a
    motion), from the numbers alone: what MAX_PATH_M bounds."""
    shape, size, distance = spec.shape, spec.size_m, spec.distance_m
    turns = spec.turns or DEFAULT_TURNS.get(shape, 1.0)
    forward = distance or (size if shape == "line" and size else DEFAULT_DISTANCE.get(shape, 4.0))
    if shape in ("line", "polyline") and spec.turn_at is not None and spec.waypoints is None:
        first = spec.turn_at.after_m if spec.turn_at.after_m is not None else forward / 2
        return first + (forward - first if forward - first > 0.1 else forward / 2)
    if shape == "polyline":
        points = list(spec.waypoints or [])
        if points and math.hypot(*points[0]) > 1e-9:
            points.insert(0, (0.0, 0.0))
        return polyline_length(points)
    if shape == "free":
        return polyline_length(spec.waypoints or [])
    if shape == "line":
        return forward
    width = size or DEFAULT_SIZE[shape]
    if shape == "zigzag":
        legs = max(2, int(round(forward)))
        return legs * math.hypot(width, forward / legs)
    if shape == "s_curve":
        return _sine_length(forward, width / 2)
    if size is None and distance is not None:      # scaled so its path is distance_m long
        return distance
    if shape in ("arc", "circle"):
        return math.pi * width * turns
    if shape == "spiral":
        growth = width / 2 / (turns + 0.5)
        return math.hypot(math.pi * turns * (growth / 2 + width / 2), growth * turns)
    return {"heart": _HEART, "figure_eight": _LEMNISCATE, "square": 4.0}[shape] * width


class PartEdits(BaseModel):
    """One instruction per body part, None where the part follows the base motion."""
    model_config = ConfigDict(extra="forbid")
    left_arm: str | None = None
    right_arm: str | None = None
    left_leg: str | None = None
    right_leg: str | None = None
    head: str | None = None               # left out of the JSON when unset (plans before it)

    @field_validator("*")
    @classmethod
    def _blank_is_none(cls, v):
        if isinstance(v, str) and (not v.strip() or v.strip().lower() == "none"):
            return None
        return v

    @model_serializer(mode="wrap")
    def _drop_unset_head(self, handler: SerializerFunctionWrapHandler) -> dict:
        out = handler(self)
        if out.get("head") is None:
            out.pop("head", None)
        return out

    def named(self) -> dict[str, str]:
        return {p: getattr(self, p) for p in PARTS if getattr(self, p)}


Travel = Literal["forward", "backward", "left", "right"]
TRAVELS: tuple[Travel, ...] = get_args(Travel)


class RoleTiming(BaseModel):
    """Who starts a two-person exchange and when the other one answers.

    phase "lead": the segment is `lead`'s action while the other waits; the answer is the next
    segment. phase "response": the other's answer, starting where the lead's action ended
    (`response` "after": "… who waves back") or at its contact ("contact": "… who stumbles
    backwards", the segment boundary is the moment of contact). phase "both": one segment in
    which the other acts during the lead's action (`response` "with": "the leader spins the
    follower")."""
    model_config = ConfigDict(extra="forbid")
    lead: Literal[0, 1]
    response: Literal["with", "after", "contact"]
    phase: Literal["lead", "response", "both"]

    @model_validator(mode="after")
    def _consistent(self):
        if (self.phase == "both") != (self.response == "with"):
            raise ValueError(f"a '{self.response}' answer does not fit phase '{self.phase}' "
                             "('with' goes with 'both' only)")
        return self


CoverageHow = Literal["capture", "primitive", "composed", "nearest"]


class Coverage(BaseModel):
    """How a segment was made and how sure the studio is that it shows what was asked.

    how: "capture" (real clips the words name), "primitive" (built per body part from the
    catalogue's primitives), "composed" (two people timed from real clips), "nearest" (nothing
    in the catalogue fits: the nearest clip is shown and the segment is reported not covered).
    similarity: the text-encoder cosine that chose it (catalogue entry or caption), in [-1, 1].
    confidence: calibrated probability that the segment shows its words, in [0, 1].
    shown: what was shown, in words (the entry or caption it was made from).
    entry: always a catalogue entry's name (what the words were read as, whose checks the
    reviewer adds); primitive: the primitive's name (a push-up entry is built by "push_up")."""
    model_config = ConfigDict(extra="forbid")
    how: CoverageHow
    similarity: float = Field(ge=-1.0, le=1.0)
    confidence: float | None = Field(default=None, ge=0.0, le=1.0)   # set once the judge has scored it
    shown: str = Field(default="", max_length=300)
    entry: str | None = None          # the catalogue entry it was matched to
    primitive: str | None = None      # how = primitive: the primitive that built it


# Optional segment fields added after plans were first stored: left out of the JSON when unset,
# so a plan without them reads and writes exactly as before.
_OPTIONAL = ("travel", "timing", "coverage")


class Segment(BaseModel):
    model_config = ConfigDict(extra="forbid")
    index: int = Field(ge=0)
    prompt: str = Field(min_length=1, max_length=500)
    base: str = Field(min_length=1, max_length=300)
    edits: PartEdits = Field(default_factory=PartEdits)
    trajectory: TrajectorySpec | None = None
    seconds: float = Field(gt=0)
    start: int = Field(ge=0)
    end: int = Field(gt=0)
    persons: list[int] = Field(min_length=1, max_length=2)
    roles: dict[Literal["0", "1"], str] | None = None
    repeat: int = Field(default=1, ge=1, le=MAX_REPEAT)
    travel: Travel | None = None           # direction of travel relative to facing
    timing: RoleTiming | None = None       # two people: who starts, who answers and when
    coverage: Coverage | None = None       # how it was made; set by the generator

    @model_serializer(mode="wrap")
    def _drop_unset(self, handler: SerializerFunctionWrapHandler) -> dict:
        out = handler(self)
        for key in _OPTIONAL:
            if out.get(key) is None:
                out.pop(key, None)
        return out

    @model_validator(mode="after")
    def _frames(self):
        if self.end <= self.start:
            raise ValueError(f"end ({self.end}) must be after start ({self.start})")
        if abs(self.seconds - (self.end - self.start) / FPS) > 0.5 / FPS:
            raise ValueError(f"seconds ({self.seconds}) must equal (end - start) / {FPS}")
        if sorted(set(self.persons)) != self.persons or min(self.persons) < 0:
            raise ValueError(f"persons must be distinct person indices in order, got {self.persons}")
        return self


class Plan(BaseModel):
    model_config = ConfigDict(extra="forbid")
    prompt: str
    rewritten: str
    persons: Literal[1, 2]
    seconds: float = Field(gt=0, le=120)
    segments: list[Segment] = Field(min_length=1, max_length=MAX_SEGMENTS)
    reasons: list[str] = Field(default_factory=list)
    planner: Literal["embedded", "llm"]
    fallback_reason: str | None = None

    @model_validator(mode="after")
    def _tiles(self):
        total, expected = round(self.seconds * FPS), 0
        for i, s in enumerate(self.segments):
            where = f"segment {i}"
            if s.index != i:
                raise ValueError(f"{where}: index is {s.index}, expected {i}")
            if s.start != expected:
                raise ValueError(f"{where}: starts at frame {s.start}, expected {expected} "
                                 "(segments must follow each other without gaps)")
            if max(s.persons) >= self.persons:
                raise ValueError(f"{where}: person {max(s.persons)} does not exist in a plan "
                                 f"for {self.persons} person(s)")
            if s.roles is not None and self.persons != 2:
                raise ValueError(f"{where}: roles are for two people only")
            if s.timing is not None and self.persons != 2:
                raise ValueError(f"{where}: timing is for two people only")
            expected = s.end
        if expected != total:
            raise ValueError(f"segments end at frame {expected}, but {self.seconds:g} s is "
                             f"{total} frames")
        return self

    def to_json(self) -> dict:
        """Plain JSON (what the API streams as the plan)."""
        return self.model_dump(mode="json")


def readable(exc: ValidationError) -> str:
    """A pydantic error as one line: 'segments.1.end: end (3) must be after start (9); …'."""
    parts = []
    for err in exc.errors():
        loc = ".".join(str(x) for x in err.get("loc", ()))
        msg = str(err.get("msg", "invalid value")).removeprefix("Value error, ")
        parts.append(f"{loc}: {msg}" if loc else msg)
    return "; ".join(parts)


def validate_plan(data: dict) -> Plan:
    """A Plan from JSON data; ValueError with a readable message when it is not one."""
    if not isinstance(data, dict):
        raise ValueError(f"a plan must be a JSON object, got {type(data).__name__}")
    try:
        return Plan.model_validate(data)
    except ValidationError as exc:
        raise ValueError(f"invalid plan: {readable(exc)}") from None
