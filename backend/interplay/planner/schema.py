"""The plan the planner hands to the generator, as validated pydantic models.

    Plan     {prompt, rewritten, persons, seconds, segments, reasons, planner, fallback_reason}
    Segment  {index, prompt, base, edits, trajectory, seconds, start, end, persons, roles, repeat}

A segment is one temporal step of the motion (CoMA's P_i): `prompt` is its rewritten text,
`base` the whole-body motion (P_base), `edits` one instruction per body part or None (P_edit),
`trajectory` a path for the pelvis (P_traj). `start`/`end` are frames at 20 fps (end exclusive)
and the segments tile [0, round(seconds × 20)). `persons` lists the people who act in the
segment; with two people `roles` says what each one does ({"0": …, "1": …}).

Trajectory coordinates are metres on the floor as [x, z] in the first person's start frame:
+z is where they face, +x is their left (the skeleton's rest pose faces +Z, its left is +X).
The JSON keeps the keys the API streamed before (index/prompt/start/end/persons per segment).
"""

from __future__ import annotations

from typing import Literal, get_args

from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator

from interplay.motion.skeleton import FPS

Shape = Literal["line", "arc", "circle", "zigzag", "s_curve", "heart", "figure_eight", "square",
                "spiral", "polyline", "free"]
SHAPES: tuple[Shape, ...] = get_args(Shape)
PARTS = ("left_arm", "right_arm", "left_leg", "right_leg")
MAX_SEGMENTS = 16


class TurnAt(BaseModel):
    """A turn towards a clock direction around the person (12 ahead, 3 to the right)."""
    model_config = ConfigDict(extra="forbid")
    clock: int = Field(ge=1, le=12)
    side: Literal["left", "right"] | None = None
    after_m: float | None = Field(default=None, ge=0)


class TrajectorySpec(BaseModel):
    model_config = ConfigDict(extra="forbid")
    shape: Shape
    clockwise: bool | None = None                 # seen from above
    size_m: float | None = Field(default=None, gt=0, le=50)        # diameter / side / width
    distance_m: float | None = Field(default=None, gt=0, le=200)   # path length or line length
    turns: float | None = Field(default=None, gt=0, le=20)         # circles, arcs, spirals
    direction: Literal["forward", "backward", "left", "right"] | None = None
    waypoints: list[tuple[float, float]] | None = None             # [[x, z], …] metres
    turn_at: TurnAt | None = None
    text: str | None = None                       # the phrase it was read from

    @model_validator(mode="after")
    def _polyline_has_points(self):
        if self.shape == "polyline" and (not self.waypoints or len(self.waypoints) < 2) \
                and self.turn_at is None:
            raise ValueError("a polyline trajectory needs at least two waypoints or a turn_at")
        return self


class PartEdits(BaseModel):
    """One instruction per body part, None where the part follows the base motion."""
    model_config = ConfigDict(extra="forbid")
    left_arm: str | None = None
    right_arm: str | None = None
    left_leg: str | None = None
    right_leg: str | None = None

    @field_validator("*")
    @classmethod
    def _blank_is_none(cls, v):
        if isinstance(v, str) and (not v.strip() or v.strip().lower() == "none"):
            return None
        return v

    def named(self) -> dict[str, str]:
        return {p: getattr(self, p) for p in PARTS if getattr(self, p)}


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
    repeat: int = Field(default=1, ge=1, le=20)

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
