"""SPAM as a generator for one person: one piece per plan segment, blended, streamed as pieces
finish, and part/in-between edits of an existing motion. Which requests reach it, and the
fallback when its weights are missing or untrained, is the router's (`generators.router`).

    gen = SpamGenerator(SpamRuntime.load("models/weights/spam"))
    plan = gen.plan(Request("a person walks, then jumps", seconds=6, seed=1))   # generator "spam"
    edit, entry = gen.edit(joints, "left_arm", "raises the left arm", frames=(20, 80), seed=3)
"""

from __future__ import annotations

import logging
from collections.abc import Iterator, Mapping

import numpy as np

from interplay.generators.base import Request, random_seed
from interplay.generators.plan import GenerationPlan, ModelInfo
from interplay.generators.spam.runtime import Edit, SpamRuntime
from interplay.motion import skeleton as sk
from interplay.planner.plan import plan as make_plan
from interplay.planner.schema import Segment

log = logging.getLogger(__name__)
WHOLE_BODY = ("whole_body", "body", "all", "full_body")
EDIT_PARTS = tuple(sk.PART_ALIASES) + ("whole_body",) + sk.PART_NAMES + ("head",)


def resolve_edit_part(part: str | None) -> list[str]:
    """The model parts an edit names: "left_arm" → ["left_upper"], "whole_body" (or None) →
    all four; ValueError listing the valid names otherwise."""
    if part is None:
        return list(sk.PART_NAMES)
    key = part.strip().lower().replace(" ", "_").replace("-", "_")
    if key in WHOLE_BODY:
        return list(sk.PART_NAMES)
    if key == "head":          # no SPAM part: the router edits it by the head primitive
        return ["head"]
    try:
        return [sk.resolve_part(key)]
    except ValueError:
        raise ValueError(f"unknown body part {part!r}; expected one of {list(EDIT_PARTS)}") from None


def segment_texts(segment: Segment) -> str | dict[str, str]:
    """SPAM's text for a plan segment: its prompt, or — when the planner split it into a
    whole-body `base` and per-part `edits` (CoMA's P_base and P_edit) — the base for every
    part and each edit for its own part."""
    edits = {p: t for p, t in segment.edits.named().items() if p != "head"}   # no SPAM part:
    if not edits:                                 # the head primitive makes head edits
        return segment.prompt
    return {"global": segment.base or segment.prompt, **edits}


class SpamGenerator:
    """SPAM's plans and frames for one-person requests, and its edits."""

    reason = None      # always able to edit: the runtime is loaded

    def __init__(self, spam: SpamRuntime):
        self.spam = spam

    @property
    def can_edit(self) -> bool:
        return True

    def plan(self, req: Request) -> GenerationPlan:
        c = self.spam.config
        model = ModelInfo(name="spam", codes=c.K, layers=c.Q, cfg=c.cfg, steps=c.steps,
                          max_seconds_per_piece=c.max_frames / sk.FPS)
        seed = req.seed if req.seed is not None else random_seed()
        return GenerationPlan.from_plan(make_plan(req.prompt, req.persons, req.seconds), seed=seed,
                                        generator="spam", synthetic=False, sources=[], model=model)

    def stream(self, req: Request, plan: GenerationPlan) -> Iterator[tuple[int, list[np.ndarray]]]:
        segments: list[tuple[str | Mapping[str, str], int]] = [
            (segment_texts(s), s.end - s.start) for s in plan.segments]
        for start, joints in self.spam.stream(segments, plan.seed):
            yield start, [joints.astype(np.float32)]

    def edit(self, joints: np.ndarray, part: str | None, prompt: str,
             frames: tuple[int, int] | None = None, seed: int | None = None,
             context: str | None = None) -> tuple[Edit, dict]:
        """(Edit, plan entry) for one person's joints: `part` (a user part name, a model part
        or "whole_body") re-generated from `prompt` over `frames` [a, b) (default all)."""
        if not isinstance(prompt, str) or not prompt.strip():
            raise ValueError("the edit prompt is empty")
        parts = resolve_edit_part(part)
        if parts == ["head"]:
            raise ValueError("SPAM has no head part: head edits are the head primitive's "
                             "(generators/primitives)")
        seed = seed if seed is not None else random_seed()
        edit = self.spam.edit(joints, parts, prompt.strip(), seed, frames=frames, context=context)
        entry = {"generator": "spam", "part": part or "whole_body", "parts": list(edit.parts),
                 "prompt": prompt.strip(), "frames": list(edit.frames), "seed": seed,
                 "masked_tokens": edit.masked_tokens, "steps": edit.steps,
                 "untouched_change_cm": round(edit.untouched_change_cm, 3),
                 "untouched_pose_change_cm": round(edit.untouched_pose_change_cm, 3),
                 "model_untouched_change_cm": round(edit.model_untouched_change_cm, 3)}
        return edit, entry
