"""Request and response models of the HTTP API, with the validation rules of the contract."""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, Strict, field_validator, model_validator

from interplay.pipeline.requests import (
    MAX_PROMPT,
    MAX_SEED,
    MAX_SPEED,
    GenerationRequest,
    TrajectoryIn,
)


class JobCreate(GenerationRequest):
    model_config = ConfigDict(json_schema_extra={
        "description": "A generation (mode generate: `prompt` required, no `actor_motion_id`) "
                       "or a reaction (mode react: `actor_motion_id` required; `persons`, "
                       "`seconds` and `trajectory` unused). `trajectory.person` must be less "
                       "than `persons`; a drawn path may be at most "
                       f"{MAX_SPEED:g} m/s × `seconds` long.",
        "examples": [{"prompt": "two people dance salsa", "persons": 2, "seconds": 6, "seed": 7}]})

    mode: Literal["generate", "react"] = Field(default="generate", description="generate, or "
                                               "react: a reactor to a stored motion's person 0.")
    actor_motion_id: str | None = Field(default=None, description="react: the stored motion "
                                        "whose person 0 is the actor.")

    @model_validator(mode="after")
    def _modes(self):
        if self.mode == "react" and not self.actor_motion_id:
            raise ValueError("mode react needs actor_motion_id")
        if self.mode == "generate" and self.prompt is None:
            raise ValueError("prompt: give what the people do")
        if self.mode == "generate" and self.actor_motion_id:
            raise ValueError("actor_motion_id is for mode react")
        if self.trajectory is not None and self.trajectory.person >= self.persons:
            raise ValueError(f"trajectory person {self.trajectory.person} does not exist in a "
                             f"motion of {self.persons} person(s)")
        if self.mode == "generate" and self.trajectory is not None \
                and self.trajectory.length() > MAX_SPEED * self.seconds:
            raise ValueError(f"trajectory: the drawn path is {self.trajectory.length():.1f} m "
                             f"long; a {self.seconds:g} s motion covers at most "
                             f"{MAX_SPEED * self.seconds:g} m ({MAX_SPEED:g} m/s)")
        return self


class EditCreate(BaseModel):
    model_config = ConfigDict(json_schema_extra={
        "description": "A part edit (`prompt`, optionally `part`, `frames`, `seed`), a path "
                       "(`trajectory`), or both: at least one of `prompt` and `trajectory`; "
                       "`part` and `frames` need a `prompt`; `frames` [a, b] with 0 ≤ a < b ≤ "
                       "the motion's frames.",
        "examples": [{"part": "left_arm", "prompt": "raises the left arm above the head",
                      "frames": [20, 80], "seed": 3}]})

    part: str | None = Field(default=None, description="What to edit: left_arm, right_arm, "
                             "left_leg, right_leg, head, whole_body (default) or a model part "
                             "(left_upper, right_upper, left_lower, right_lower).")
    prompt: str | None = Field(default=None, description=f"What the edited part does, "
                               f"1–{MAX_PROMPT} characters (optional with a trajectory).")
    frames: list[Annotated[int, Strict()]] | None = Field(
        default=None, min_length=2, max_length=2,
        description="[a, b] (JSON integers, 0 ≤ a < b): edit frames a … b−1 only (default all).")
    seed: Annotated[int, Strict()] | None = Field(
        default=None, ge=0, le=MAX_SEED,
        description="Sampling seed, a JSON integer 0 … 2³¹−1; random (and stored) when omitted.")

    trajectory: TrajectoryIn | None = Field(default=None, description="A drawn path or preset "
                                            "for the motion to follow.")

    @field_validator("prompt")
    @classmethod
    def _prompt(cls, v: str | None) -> str | None:
        return None if v is None else JobCreate._prompt(v)     # the same rules as a job's prompt

    @model_validator(mode="after")
    def _something(self):
        if self.prompt is None and self.trajectory is None:
            raise ValueError("give a prompt, a trajectory or both")
        if self.prompt is None and (self.part is not None or self.frames is not None):
            raise ValueError("part and frames need a prompt")
        return self

    @field_validator("part")
    @classmethod
    def _part(cls, v: str | None) -> str | None:
        from interplay.generators.spam.generator import resolve_edit_part
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


JobState = Literal["queued", "running", "done", "failed", "cancelled"]


class JobStatus(BaseModel):
    job_id: str
    motion_id: str
    status: JobState
    events: int
    stream: str
    reason: str | None = Field(default=None, description="Why a failed or cancelled job ended.")
    attempts: int = Field(default=0, description="How many times a worker started the job.")


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
    edit: dict | None = Field(default=None, description="What made this version: {part, prompt,"
                              " frames, trajectory}; null for a generated motion.")
    review: dict | None = Field(default=None, description="The reviewer's rounds per segment.")
    created_at: str | None
    digest: str | None = Field(default=None, description="The frames' digest (`api.digest`), "
                               "as the job's `done` event has it; null in an edit's or "
                               "re-run's reply.")
    frame_digests: list[str] | None = Field(default=None, description="One digest per frame, "
                                            "as `done` has them; null where `digest` is.")


class Version(BaseModel):
    id: str
    parent_id: str | None
    created_at: str | None
    prompt: str
    edit: dict | None


class History(BaseModel):
    versions: list[Version] = Field(description="From the root to this motion.")


class JobCancelled(BaseModel):
    job_id: str
    status: str
    cancelled: bool


class SkeletonOut(BaseModel):
    joints: list[str]
    parents: list[int]
    parts: dict[str, list[int]]
    joint_part: list[str]
    colours: dict[str, str]
    rest: list[list[float]] = Field(description="Rest-pose joint positions (22×3), metres.")
    fps: int


class SegmentRerun(BaseModel):
    seed: int | None = Field(default=None, ge=0, le=MAX_SEED, strict=True,
                             description="Sampling seed for the segment, a JSON integer "
                                         "0 … 2³¹−1; random (and stored) when omitted.")


class MotionListItem(BaseModel):
    id: str
    prompt: str
    persons: int
    seconds: float
    frames: int
    created_at: str | None
    parent_id: str | None = Field(description="Set for a version made from another motion.")
    edit: dict | None = Field(description="What made this version (null: generated).")
    first_frame: list[list[list[float]]] = Field(description="The first frame per person: "
                                                 "[[x, y, z] × 22], metres, for a thumbnail.")


class MotionList(BaseModel):
    motions: list[MotionListItem] = Field(description="Newest first.")
    next: str | None = Field(default=None, description="The `after` of the next page (null: "
                             "this is the last).")
    total: int = Field(default=0, description="How many motions the client made in all.")


class ErrorOut(BaseModel):
    detail: str


# The type FastAPI's `responses=` takes.
ERRORS: dict[int | str, dict[str, Any]] = {code: {"model": ErrorOut} for code in (404, 422)}
