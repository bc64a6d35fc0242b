"""The generate job's runner: CoMA's Algorithm 1 (`pipeline.orchestrator.orchestrate`) in a
worker thread, its frames turned into `frames` and `highlights` events as they become final,
then metrics, the stored motion and `done`.

Frames changed after they were streamed (a correction, the pair pass, a path) go out again as
`replace` events with their cause; `done` carries the stored frames' digests (`api.digest`), so
the client can check its copy.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from interplay.api.digest import frame_digests, motion_digest
from interplay.api.events import (
    DoneEvent,
    MetricsEvent,
    frames_event,
    from_pipeline,
    highlights_event,
    replace_event,
)
from interplay.generators.base import Generator, Request
from interplay.motion.metrics import clip_metrics
from interplay.motion.skeleton import FPS, NUM_JOINTS
from interplay.pipeline.motion_json import joints_list, plain
from interplay.pipeline.orchestrator import StageError, default_evaluator, orchestrate
from interplay.pipeline.segment_source import Cancelled
from interplay.store import MotionRepository


class GenerateRunner:
    """One generate job: `run()` pushes its events and stores the motion."""

    def __init__(self, job, generator: Generator, repo: MotionRepository,
                 closing: Callable[[], bool]):
        self.job, self.generator, self.repo, self.closing = job, generator, repo, closing
        spec = job.spec
        self.persons, self.total = spec.persons, spec.frame_count
        self.people = np.zeros((spec.persons, self.total, NUM_JOINTS, 3), dtype=np.float32)
        self.written = 0
        self.contacts: list = [[] for _ in range(self.total)]
        self.penetration: list = [[] for _ in range(self.total)]
        self.min_dist: list | None = [None] * self.total if spec.persons > 1 else None

    def _grow(self, end: int) -> None:
        """The generator ran longer than asked: room for frames up to `end`."""
        grow = end - self.people.shape[1]
        if grow <= 0:
            return
        self.people = np.concatenate([self.people, np.zeros(
            (self.persons, grow, NUM_JOINTS, 3), dtype=np.float32)], axis=1)
        self.contacts += [[] for _ in range(grow)]
        self.penetration += [[] for _ in range(grow)]
        if self.min_dist is not None:
            self.min_dist += [None] * grow

    def on_frames(self, start: int, chunk: list[np.ndarray]) -> None:
        self._frames(start, chunk, None)

    def on_replace(self, start: int, chunk: list[np.ndarray], cause: str,
                   segment: int | None) -> None:
        self._frames(start, chunk, (cause, segment))

    def _frames(self, start: int, chunk: list[np.ndarray],
                replace: tuple[str, int | None] | None) -> None:
        if self.closing():
            raise Cancelled()
        chunk = [np.asarray(c, dtype=np.float32) for c in chunk]
        n = chunk[0].shape[0]
        if len(chunk) != self.persons or any(c.shape != (n, NUM_JOINTS, 3) for c in chunk):
            raise ValueError(f"generator sent chunk shapes {[c.shape for c in chunk]} "
                             f"for {self.persons} person(s)")
        start, end = int(start), int(start) + n
        self._grow(end)
        self.people[:, start:end] = np.stack(chunk)
        self.written = max(self.written, end)
        lists = [joints_list(c) for c in chunk]
        self.job.push(frames_event(start, max(self.total, self.written), lists)
                      if replace is None else replace_event(start, lists, *replace))
        # One frame of context before the chunk, so velocity-based contacts are defined.
        ctx = 1 if start > 0 else 0
        hl = highlights_event(start, [p[start - ctx:end] for p in self.people], ctx, self.persons)
        self.job.push(hl)
        self.contacts[start:end] = hl["contacts"]
        self.penetration[start:end] = hl["penetration"]
        if self.min_dist is not None:
            self.min_dist[start:end] = hl["min_distance"]

    def run(self) -> None:
        job, spec = self.job, self.job.spec
        req = Request(prompt=spec.prompt, persons=spec.persons, seconds=spec.seconds,
                      seed=spec.seed)
        out = orchestrate(self.generator, req, lambda e: job.push(from_pipeline(plain(e))),
                          self.on_frames, cancelled=lambda: job.cancelled or self.closing(),
                          trajectory=spec.trajectory, evaluator=default_evaluator(),
                          on_replace=self.on_replace)
        if self.written == 0:
            raise StageError("generate", "the generator produced no frames")
        final = [p[:self.written] for p in out.people]
        try:
            metrics = plain(clip_metrics([p.astype(np.float64) for p in final], fps=FPS))
        except Exception as exc:
            raise StageError("metrics", f"{type(exc).__name__}: {exc}") from exc
        job.push(MetricsEvent(metrics=metrics).dump())
        w = self.written
        highlights = {"contacts": self.contacts[:w], "penetration": self.penetration[:w],
                      "min_distance": self.min_dist[:w] if self.min_dist is not None else None}
        try:
            self.repo.create(id=job.motion_id, prompt=spec.prompt, people=final,
                             seconds=spec.seconds, seed=spec.seed, plan=plain(out.plan.to_json()),
                             metrics=metrics, highlights=highlights, review=plain(out.review),
                             client_id=spec.client_id)
        except Exception as exc:
            raise StageError("store", f"{type(exc).__name__}: {exc}") from exc
        digests = frame_digests(final)
        job.push(DoneEvent(motion_id=job.motion_id, frames=w, digest=motion_digest(digests),
                           frame_digests=digests).dump())
