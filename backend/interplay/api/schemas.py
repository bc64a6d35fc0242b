"""Request and response models of the HTTP API, with the validation rules of the contract."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, field_validator

MAX_PROMPT = 500
MIN_SECONDS, MAX_SECONDS = 1.0, 20.0
MAX_SEED = 2**31 - 1


class JobCreate(BaseModel):
    model_config = ConfigDict(json_schema_extra={
        "examples": [{"prompt": "two people dance salsa", "persons": 2, "seconds": 6, "seed": 7}]})

    prompt: str = Field(description=f"What the people do, 1–{MAX_PROMPT} characters.")
    persons: Literal[1, 2] = Field(default=1, description="How many people: 1 or 2.")
    seconds: float = Field(default=6.0, ge=MIN_SECONDS, le=MAX_SECONDS, allow_inf_nan=False,
                           description=f"Length in seconds, {MIN_SECONDS:g}–{MAX_SECONDS:g}.")
    seed: int | None = Field(default=None, ge=0, le=MAX_SEED,
                             description="Sampling seed; random (and returned) when omitted.")

    @field_validator("prompt")
    @classmethod
    def _prompt(cls, v: str) -> str:
        v = " ".join(v.split())
        if not v:
            raise ValueError("must not be empty")
        if len(v) > MAX_PROMPT:
            raise ValueError(f"is {len(v)} characters long; the limit is {MAX_PROMPT}")
        return v


class EditCreate(BaseModel):
    model_config = ConfigDict(json_schema_extra={
        "examples": [{"part": "left_arm", "prompt": "raises the left arm above the head",
                      "frames": [20, 80], "seed": 3}]})

    part: str | None = Field(default=None, description="What to edit: left_arm, right_arm, "
                             "left_leg, right_leg, whole_body (default) or a model part "
                             "(left_upper, right_upper, left_lower, right_lower).")
    prompt: str = Field(description=f"What the edited part does, 1–{MAX_PROMPT} characters.")
    frames: list[int] | None = Field(default=None, min_length=2, max_length=2,
                                     description="[a, b]: edit frames a … b−1 only (default all).")
    seed: int | None = Field(default=None, ge=0, le=MAX_SEED,
                             description="Sampling seed; random (and stored) when omitted.")

    _prompt = field_validator("prompt")(JobCreate._prompt.__func__)

    @field_validator("part")
    @classmethod
    def _part(cls, v: str | None) -> str | None:
        from ..agents.spam_generator import resolve_edit_part
        if v is not None:
            resolve_edit_part(v)   # ValueError with the valid names → 422
        return v

    @field_validator("frames")
    @classmethod
    def _frames(cls, v: list[int] | None) -> list[int] | None:
        if v is not None and not 0 <= v[0] < v[1]:
            raise ValueError(f"must be [a, b] with 0 ≤ a < b, got {v}")
        return v


class JobCreated(BaseModel):
    job_id: str
    motion_id: str = Field(description="Id the motion will have once done (share link /m/{id}).")
    stream: str = Field(description="WebSocket path streaming the job's events.")
    seed: int


class JobStatus(BaseModel):
    job_id: str
    motion_id: str
    status: Literal["queued", "running", "done", "failed"]
    events: int
    stream: str


class Person(BaseModel):
    joints: list[list[list[float]]] = Field(description="[[[x,y,z]×22]×T], metres, Y up.")


class MotionOut(BaseModel):
    id: str
    prompt: str
    persons: int
    seconds: float
    seed: int | None
    fps: int = 20
    skeleton: str = "smpl22"
    people: list[Person]
    plan: dict | None
    metrics: dict | None
    highlights: dict | None
    parent_id: str | None = None
    created_at: str | None


class SkeletonOut(BaseModel):
    joints: list[str]
    parents: list[int]
    parts: dict[str, list[int]]
    joint_part: list[str]
    colours: dict[str, str]
    rest: list[list[float]] = Field(description="Rest-pose joint positions (22×3), metres.")
    fps: int


class ErrorOut(BaseModel):
    detail: str


ERRORS = {code: {"model": ErrorOut} for code in (404, 422)}
