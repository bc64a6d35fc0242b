"""Each version keeps its review rounds (issue 26.3): the review stored with a version made by
an edit (a part edit, "Redo in place", a path) or a segment re-run is the parent's, segment by
segment, except where the edit changed frames: those segments get the edit's own review — the
reviewer run once on the new frames (round 0), the user's part edit counted as one of the
segment's part edits — marked with what made it (`edit`), so the agent timeline of the version
on screen shows the rounds that belong to its frames.

    repo = Reviewing(repo, parent, what)     # what: {"kind", "part", "prompt", "frames"|"segment"}
    edit_stored(repo, …)                     # its repo.create(…) stores the version's review
"""

from __future__ import annotations

import logging
from copy import deepcopy
from typing import Any

import numpy as np

from interplay.generators.plan import GenerationSegment
from interplay.pipeline.motion_json import plain

log = logging.getLogger(__name__)
PARTS = ("left_arm", "right_arm", "left_leg", "right_leg", "head")


def touched(plan: dict | None, what: dict, frames: int) -> list[int]:
    """Indices of the plan segments whose frames the edit changed."""
    segments = (plan or {}).get("segments") or []
    if what.get("segment") is not None:
        return [int(what["segment"])]
    if what.get("prompt") is None:          # a path only: the poses are the parent's
        return []
    a, b = what.get("frames") or (0, frames)
    return [i for i, s in enumerate(segments) if int(s["start"]) < b and int(s["end"]) > a]


def _segment(seg_json: dict, what: dict) -> GenerationSegment:
    seg = GenerationSegment.model_validate(seg_json)
    part, prompt = what.get("part"), what.get("prompt")
    if what.get("kind") == "edit" and part in PARTS and prompt:
        seg = seg.model_copy(update={"edits": seg.edits.model_copy(update={part: prompt})})
    return seg


def review_of(people: list[np.ndarray], plan: dict | None, parent_review: dict | None,
              what: dict, evaluator=None) -> dict | None:
    """The new version's review: the parent's, with the touched segments reviewed again."""
    from interplay.pipeline.orchestrator import asked_of
    from interplay.review.reviewer import review
    out: dict[str, Any] = deepcopy(parent_review) if parent_review else {"segments": []}
    out.pop("interaction", None)        # about the parent's whole pair of frames
    out["segments"] = [s for s in out.get("segments") or [] if isinstance(s, dict)]
    segments = (plan or {}).get("segments") or []
    frames = len(people[0])
    for i in touched(plan, what, frames):
        if not 0 <= i < len(segments):
            continue
        a, b = int(segments[i]["start"]), min(int(segments[i]["end"]), frames)
        entry: dict[str, Any] = {"segment": i, "reviews": [], "corrections": [], "edit": plain(what)}
        if b - a >= 3:
            try:
                seg = _segment(segments[i], what)
                r = review(seg, [np.asarray(p[a:b], dtype=np.float64) for p in people],
                           evaluator=evaluator, asked=asked_of(seg) if len(people) == 1 else None)
                entry["reviews"] = [plain(r.to_json())]
            except Exception as exc:   # the version is stored anyway; its timeline says why
                log.exception("reviewing segment %d of an edit failed", i)
                entry["error"] = f"{type(exc).__name__}: {exc}"
        out["segments"] = [s for s in out["segments"] if s.get("segment") != i] + [entry]
    out["segments"].sort(key=lambda s: s.get("segment", 0))
    return out


class Reviewing:
    """The motion repository, whose `create` stores the version's review (`review_of`)."""

    def __init__(self, repo, parent, what: dict, evaluator=None):
        self._repo, self._parent, self._what, self._evaluator = repo, parent, what, evaluator

    def create(self, **kw):
        kw["review"] = review_of(kw["people"], kw.get("plan"), self._parent.review, self._what,
                                 self._evaluator)
        return self._repo.create(**kw)

    def __getattr__(self, name: str):
        return getattr(self._repo, name)
