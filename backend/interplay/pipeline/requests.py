"""What a generation request is, validated the same way wherever it comes from (the API's job
body, the CLI's flags): the prompt, people, length, seed and an optional path, with the limits
that bound its cost, and pydantic errors as one readable line.

Types are strict where a JSON client could send the wrong one: `true` is not a number of
seconds or persons, "7" is not a seed (an integer-valued float such as 6 for seconds is fine)."""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import (
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    Strict,
    ValidationError,
    field_validator,
    model_validator,
)

from interplay.pipeline.messages import readable_errors
from interplay.planner.schema import (
    MAX_COORD,
    MAX_PATH_M,
    MAX_POINTS,
    MAX_SPEED,
    Point,
    TrajectorySpec,
    polyline_length,
    readable,
)

MAX_PROMPT = 500
MIN_SECONDS, MAX_SECONDS = 1.0, 20.0
MAX_SEED = 2**31 - 1
__all__ = ["MAX_COORD", "MAX_PATH_M", "MAX_POINTS", "MAX_SPEED", "GenerationRequest", "TrajectoryIn",
           "readable_errors"]


def _whole_number(v: Any) -> Any:
    """A Literal of ints takes only JSON integers (pydantic would take true for 1 and 1.0)."""
    if isinstance(v, bool) or not isinstance(v, int):
        raise ValueError(f"must be an integer, got {v!r}")
    return v


Persons = Annotated[Literal[1, 2], BeforeValidator(_whole_number)]
PersonIndex = Annotated[Literal[0, 1], BeforeValidator(_whole_number)]


class TrajectoryIn(BaseModel):
    """A path for one person: drawn points on the floor ([x, z] metres, world) or a preset
    shape (the planner's TrajectorySpec fields: shape, clockwise, size_m, …)."""
    model_config = ConfigDict(extra="allow", json_schema_extra={
        "description": f"A path for one person: either `points` or `shape` (with the preset's "
                       f"fields: clockwise, size_m ≤ 50, distance_m, turns ≤ 20, direction, "
                       f"waypoints, turn_at), not both. Any path is at most {MAX_PATH_M:g} m long "
                       f"(a drawn one also at most {MAX_SPEED:g} m/s × seconds); points and "
                       f"waypoints are at most {MAX_POINTS} [x, z] pairs within ±{MAX_COORD:g} m.",
        "examples": [
            {"person": 0, "points": [[0, 0], [1, 1], [2, 0]]},
            {"person": 0, "shape": "circle", "clockwise": True, "size_m": 3}]})

    person: PersonIndex = Field(default=0, description="Who follows the path: 0 or 1 (less "
                                "than persons).")
    points: list[Point] | None = Field(
        default=None, min_length=2, max_length=MAX_POINTS,
        description=f"[[x, z], …] metres on the studio floor (world coordinates), 2–{MAX_POINTS} "
                    f"points within ±{MAX_COORD:g} m, at most {MAX_PATH_M:g} m along them.")
    shape: str | None = Field(default=None, description="A preset shape (line, arc, circle, "
                              "zigzag, s_curve, heart, figure_eight, square, spiral, polyline, "
                              "free).")

    @model_validator(mode="after")
    def _one_of(self):
        if (self.points is None) == (self.shape is None):
            raise ValueError("give either points or shape")
        if self.points is not None:
            if max(abs(a - c) + abs(b - d) for (a, b), (c, d)
                   in zip(self.points, self.points[1:])) == 0:
                raise ValueError("points must not all be the same")
            if self.model_extra:
                raise ValueError(f"unexpected fields with points: {sorted(self.model_extra)}")
            total = self.length()
            if total > MAX_PATH_M:
                raise ValueError(f"the drawn path is {total:.0f} m long; the limit is "
                                 f"{MAX_PATH_M:g} m")
        else:
            try:
                TrajectorySpec.model_validate(self.spec())
            except ValidationError as exc:
                raise ValueError(readable(exc)) from None
        return self

    def length(self) -> float:
        """Metres along the drawn points (0 for a preset)."""
        return polyline_length(self.points) if self.points is not None else 0.0

    def spec(self) -> dict:
        """The shape's TrajectorySpec fields (without person)."""
        return {"shape": self.shape, **(self.model_extra or {})}

    def plain(self) -> dict:
        if self.points is not None:
            return {"person": self.person, "points": [list(p) for p in self.points]}
        return {"person": self.person, **self.spec()}


class GenerationRequest(BaseModel):
    """The fields every generation takes."""

    # maxLength in the schema (not a pydantic constraint: the limit applies after spaces are
    # collapsed, below) lets the studio page read the limit instead of repeating it
    prompt: str | None = Field(default=None, json_schema_extra={"maxLength": MAX_PROMPT},
                               description=f"What the people do, 1–{MAX_PROMPT} "
                               "characters (required to generate; in react mode the optional "
                               "intent, e.g. \"shake hands\": without one the reactor "
                               "follows the actor unprompted).")
    persons: Persons = Field(default=1, description="How many people: 1 or 2 (a JSON integer).")
    seconds: Annotated[float, Strict()] = Field(
        default=6.0, ge=MIN_SECONDS, le=MAX_SECONDS, allow_inf_nan=False,
        description=f"Length in seconds, {MIN_SECONDS:g}–{MAX_SECONDS:g} (a JSON number).")
    seed: Annotated[int, Strict()] | None = Field(
        default=None, ge=0, le=MAX_SEED,
        description="Sampling seed, a JSON integer 0 … 2³¹−1; random (and returned) when omitted.")
    trajectory: TrajectoryIn | None = Field(default=None, description="A drawn path or preset "
                                            "the person follows.")

    @field_validator("prompt")
    @classmethod
    def _prompt(cls, v: str | None) -> str | None:
        if v is None:
            return None
        v = " ".join(v.split())
        if not v:
            raise ValueError("must not be empty")
        if len(v) > MAX_PROMPT:
            raise ValueError(f"is {len(v)} characters long; the limit is {MAX_PROMPT}")
        return v
