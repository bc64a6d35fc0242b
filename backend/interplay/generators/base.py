"""What every generator shares: the `Request` it is asked, the `Generator` protocol the
pipeline calls (`plan`, then `stream` the planned frames), the `Editor` protocol of a
generator that can re-generate a part of an existing motion, and `generate_motion`, the
plan-then-all-frames form the CLI and tests use.

    req = Request("a person walks forward then jumps", persons=1, seconds=6, seed=3)
    plan = gen.plan(req)                        # JSON: segments, generator, seed, …
    for start, chunk in gen.stream(req, plan):  # chunk: one (n, 22, 3) array per person
        ...
"""

from __future__ import annotations

import secrets
from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any, Protocol, runtime_checkable

import numpy as np

from interplay.generators.plan import GenerationPlan
from interplay.motion.metrics import clip_metrics, frame_highlights
from interplay.motion.motion import Motion
from interplay.motion.skeleton import FPS


@dataclass(frozen=True)
class Request:
    prompt: str
    persons: int = 1
    seconds: float = 6.0
    seed: int | None = None

    def __post_init__(self):
        if self.persons not in (1, 2):
            raise ValueError(f"persons must be 1 or 2, got {self.persons!r}")
        if not isinstance(self.seconds, (int, float)) or not 0 < self.seconds <= 60:
            raise ValueError(f"seconds must be in (0, 60], got {self.seconds!r}")
        if self.seed is not None and (not isinstance(self.seed, int) or isinstance(self.seed, bool)):
            raise ValueError(f"seed must be an integer, got {self.seed!r}")


def random_seed() -> int:
    """A seed for a request that gave none (returned to the caller, so it can repeat it)."""
    return secrets.randbelow(2**31)


@runtime_checkable
class Generator(Protocol):
    """Plans a request, then streams (start frame, one (n, 22, 3) chunk per person) in order,
    covering every frame of the plan."""

    def plan(self, req: Request) -> GenerationPlan: ...

    def stream(self, req: Request, plan: GenerationPlan
               ) -> Iterator[tuple[int, list[np.ndarray]]]: ...


class EditUnavailable(RuntimeError):
    """Edits need the SPAM model, which is not loaded (the message says why)."""


@runtime_checkable
class Editor(Protocol):
    """A generator that can re-generate a body part (or frames) of one person's motion, when
    `can_edit` (its model is loaded; else `reason` says why not)."""

    reason: str | None

    @property
    def can_edit(self) -> bool: ...

    def edit(self, joints: np.ndarray, part: str | None, prompt: str,
             frames: tuple[int, int] | None = None, seed: int | None = None,
             context: str | None = None) -> tuple[Any, dict]: ...


@runtime_checkable
class Redrawer(Protocol):
    """A generator whose retrieval segments can be drawn again with another seed."""

    def redraw(self, plan: GenerationPlan, index: int, seed: int) -> GenerationPlan: ...


def generate_motion(gen: Generator, req: Request) -> Motion:
    """Plan, all frames, clip metrics and per-frame highlights."""
    plan = gen.plan(req)
    chunks = [people for _, people in gen.stream(req, plan)]
    people = [np.concatenate([c[i] for c in chunks]) for i in range(req.persons)]
    return Motion(people=people, fps=FPS, plan=plan.to_json(), metrics=clip_metrics(people, fps=FPS),
                  highlights=frame_highlights(people), prompt=req.prompt, seed=plan.seed)
