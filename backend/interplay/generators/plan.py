"""The plan a generator makes from the planner's Plan and the pipeline carries to the end of a
job: what the planner decided (segments, part edits, trajectories, timing) plus what the
generator chose (seed, which generator and why, the captures retrieval picked, the model's
settings, the contact refinement's report per segment). It becomes JSON once, at the API
edge (`to_json`), where the studio and the store read it.

    plan = GenerationPlan.from_plan(planner_plan, seed=3, generator="spam", model=ModelInfo(…))
    plan.segments[0].retrieval        # RetrievalChoice for retrieval segments, else None
    plan.to_json()                    # the plan JSON the stream's plan event carries

Optional fields a generator did not set stay out of the JSON (a SPAM plan has no `retrieval`
per segment, a retrieval plan no `model`), so each generator's plan keeps its own shape.
"""

from __future__ import annotations

from typing import Any, ClassVar, Literal

from pydantic import BaseModel, ConfigDict, Field

from interplay.planner.schema import Plan, Segment

# retrieve_edit: captured clips with arm actions laid over them (generators/retrieve_edit);
# compose: two people's interactions composed from single-person captures (generators/interaction).
GeneratorName = Literal["retrieval", "spam", "coda", "retrieve_edit", "compose"]


class _Json(BaseModel):
    model_config = ConfigDict(extra="forbid", protected_namespaces=())
    OMIT_UNSET: ClassVar[tuple[str, ...]] = ()     # optional fields left out of the JSON if unset

    def _omit(self, out: dict) -> dict:
        for key in self.OMIT_UNSET:
            if key not in self.model_fields_set:
                out.pop(key, None)
        return out


class CapturePiece(_Json):
    """A cut of one capture: frames [start, end) of the clip's `people` (one, or both of a pair)."""
    clip: str
    people: list[int]
    start: int
    end: int
    score: float


class RetrievalChoice(_Json):
    """The captures retrieval chose for one segment: one track of pieces per person ("single",
    "composed") or one track of two-person pieces ("pair")."""
    OMIT_UNSET = ("arrangement",)
    mode: Literal["single", "pair", "composed"]
    synthetic: bool
    tracks: list[list[CapturePiece]]
    arrangement: Literal["side_by_side", "facing"] | None = None

    def to_json(self) -> dict:
        return self._omit(self.model_dump(mode="json"))


class Source(_Json):
    clip: str
    licence: str
    label: str


class ModelInfo(_Json):
    """The model that made the frames and its sampling settings."""
    OMIT_UNSET = ("layers", "interaction_codes", "max_seconds_per_piece", "max_seconds_per_window")
    name: Literal["spam", "coda"]
    codes: int
    cfg: float
    steps: int
    layers: int | None = None
    interaction_codes: int | None = None
    max_seconds_per_piece: float | None = None
    max_seconds_per_window: float | None = None


class GenerationSegment(Segment):
    """A planned segment plus the generator's choices for it."""
    OMIT_UNSET: ClassVar[tuple[str, ...]] = ("retrieval", "contact")
    model_config = ConfigDict(extra="forbid", protected_namespaces=())
    retrieval: RetrievalChoice | None = None
    contact: dict[str, Any] | None = None      # contact refinement's report (coda.finish)


class GenerationPlan(Plan):
    OMIT_UNSET: ClassVar[tuple[str, ...]] = ("generator_reason", "model", "trajectory",
                                             "composition")
    model_config = ConfigDict(extra="forbid", protected_namespaces=())
    # pydantic narrows the planner's segments to generation segments; mypy sees list as invariant
    segments: list[GenerationSegment] = Field(min_length=1)  # type: ignore[assignment]
    seed: int
    generator: GeneratorName
    generator_reason: str | None = None         # why not the model this request would prefer
    synthetic: bool = False                     # any segment composed from separate captures
    sources: list[Source] = Field(default_factory=list)
    model: ModelInfo | None = None
    trajectory: dict[str, Any] | None = None    # the request's drawn path or preset, if any
    composition: dict[str, Any] | None = None   # compose: the interaction, its clips, timing, reasons

    @classmethod
    def from_plan(cls, plan: Plan, **fields: Any) -> GenerationPlan:
        return cls.model_validate({**plan.model_dump(), **fields})

    def to_json(self) -> dict:
        out = self.model_dump(mode="json")
        for key in self.OMIT_UNSET:
            if key not in self.model_fields_set:
                out.pop(key, None)
        if self.model is not None:
            out["model"] = self.model._omit(out["model"])
        for seg, js in zip(self.segments, out["segments"]):
            for key in GenerationSegment.OMIT_UNSET:
                if key not in seg.model_fields_set:
                    js.pop(key, None)
            if seg.retrieval is not None:
                js["retrieval"] = seg.retrieval._omit(js["retrieval"])
        return out
