"""The job stream's events, one pydantic model each: what a WebSocket client receives, in
order (docs/api.md):

    plan → (segment, (frames | replace, highlights)*, review, correction*, …, segment)*
        → metrics → done
    or, on failure or cancellation, … → error (with `stage`, or `cancelled: true`);
    a job whose process died and that runs again: … → restart → plan → … (from its start).

The TypeScript `StreamEvent` union (frontend/src/api/types.ts) mirrors these models; a test
checks that both sides name the same events and fields. The pipeline emits plain dicts
(`plan`, `segment`, `review`, `correction`); `from_pipeline` validates them here, at the API
edge, so a malformed event fails the job instead of reaching a client.
"""

from __future__ import annotations

from typing import Annotated, Any, ClassVar, Literal, Union

from pydantic import BaseModel, ConfigDict, Field, TypeAdapter

from interplay.pipeline.highlights import highlight_lists
from interplay.review.records import Verdict


class _Event(BaseModel):
    model_config = ConfigDict(extra="forbid")
    OMIT_NONE: ClassVar[tuple[str, ...]] = ()    # optional fields left out when None

    def dump(self) -> dict:
        out = self.model_dump()
        for key in self.OMIT_NONE:
            if out.get(key) is None:
                out.pop(key, None)
        return out


class PlanEvent(_Event):
    type: Literal["plan"] = "plan"
    plan: dict[str, Any]


class SegmentEvent(_Event):
    type: Literal["segment"] = "segment"
    index: int
    status: Literal["generating", "done"]
    generator: str


class FramesEvent(_Event):
    type: Literal["frames"] = "frames"
    start: int
    total: int
    people: list[list[list[list[float]]]]    # per person: [[[x, y, z] × 22] × n]


class ReplaceEvent(_Event):
    """Frames already streamed, changed: a correction (`segment` names it), the pair pass,
    the interaction review, a path (`trajectory`), or `sync` (any other change found at the
    end). Followed by their `highlights`. The client puts them in place of the old ones."""
    type: Literal["replace"] = "replace"
    start: int
    people: list[list[list[list[float]]]]    # per person: [[[x, y, z] × 22] × n]
    cause: str                               # correction | pair_pass | interaction | trajectory | sync
    segment: int | None


class HighlightsEvent(_Event):
    type: Literal["highlights"] = "highlights"
    start: int
    contacts: list[list[list[int]]]             # per frame: [[person, joint], …]
    penetration: list[list[list[int | str]]]    # per frame: [[person, part], …]
    min_distance: list[float | None] | None     # per frame, two people only


class ReviewEvent(_Event):
    model_config = ConfigDict(extra="forbid", protected_namespaces=())
    type: Literal["review"] = "review"
    segment: int
    round: int
    captions: dict[str, Any]
    summary: str
    score: float
    score_kind: str
    confirmed: dict[str, Any]
    checks: dict[str, Any]
    instructions: list[dict[str, Any]]
    verdict: Verdict       # ok | correct (corrections follow) | failed | not_covered


class CorrectionEvent(_Event):
    OMIT_NONE = ("reason",)
    type: Literal["correction"] = "correction"
    segment: int
    round: int
    instruction: dict[str, Any]
    accepted: bool
    score_before: float
    score_after: float | None
    reason: str | None = None


class MetricsEvent(_Event):
    type: Literal["metrics"] = "metrics"
    metrics: dict[str, Any]


class DoneEvent(_Event):
    """The motion is stored. `digest` / `frame_digests` (`api.digest`) are those of the stored
    frames: a client compares its copy and reloads the frames that differ. An edit's done
    (not streamed) has none."""
    OMIT_NONE = ("digest", "frame_digests")
    type: Literal["done"] = "done"
    motion_id: str
    frames: int
    digest: str | None = None
    frame_digests: list[str] | None = None


class RestartEvent(_Event):
    """The process running the job stopped (killed, crashed, restarted) and the job was queued
    again: what follows is attempt `attempt` from its start (plan, frames, …). A client drops
    what the earlier attempt streamed."""
    type: Literal["restart"] = "restart"
    attempt: int
    reason: str


class ErrorEvent(_Event):
    OMIT_NONE = ("stage", "cancelled")
    type: Literal["error"] = "error"
    message: str
    stage: str | None = None
    cancelled: bool | None = None


StreamEvent = Annotated[Union[PlanEvent, SegmentEvent, FramesEvent, ReplaceEvent, HighlightsEvent,
                              ReviewEvent, CorrectionEvent, MetricsEvent, DoneEvent, RestartEvent,
                              ErrorEvent],
                        Field(discriminator="type")]
EVENTS: tuple[type[_Event], ...] = (PlanEvent, SegmentEvent, FramesEvent, ReplaceEvent,
                                    HighlightsEvent, ReviewEvent, CorrectionEvent, MetricsEvent,
                                    DoneEvent, RestartEvent, ErrorEvent)
_ADAPTER: TypeAdapter = TypeAdapter(StreamEvent)


def from_pipeline(event: dict) -> dict:
    """A pipeline event (plain JSON) validated as its stream model, as the client gets it."""
    return _ADAPTER.validate_python(event).dump()


def frames_event(start: int, total: int, people: list) -> dict:
    """Frames of every person from `start` (joints already as nested lists). Built without
    re-validating thousands of floats per chunk: the runner made them from arrays."""
    return FramesEvent.model_construct(start=start, total=total, people=people).dump()


def replace_event(start: int, people: list, cause: str, segment: int | None) -> dict:
    """Frames already streamed, again (joints already as nested lists)."""
    return ReplaceEvent.model_construct(start=start, people=people, cause=cause,
                                        segment=segment).dump()


def highlights_event(start: int, window: list, skip: int, persons: int) -> dict:
    """Per-frame highlights of `window` (the chunk with `skip` frames of context before it)."""
    return HighlightsEvent.model_construct(
        start=start, **highlight_lists(window, skip, persons)).dump()
