"""The generator's frame stream cut at plan segments, for the orchestrator: pull frames until a
segment is complete, and — for retrieval, whose segments are chosen captures — restart the
stream from a plan whose segment i was re-drawn with a new seed (a `regenerate`).

The generator's stream is lazy, so nothing past the segment under review is made before the
review is done; chunks that straddle a segment end (SPAM pieces) are kept for the next one.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

import numpy as np

from interplay.generators.base import Generator, Redrawer, Request
from interplay.generators.plan import GenerationPlan
from interplay.motion.skeleton import NUM_JOINTS


class Cancelled(Exception):
    """The job was cancelled (or the server is shutting down)."""


class SegmentSource:
    def __init__(self, generator: Generator, req: Request, plan: GenerationPlan):
        self.generator, self.req, self.plan = generator, req, plan
        self.persons = plan.persons
        self.total = sum(s.end - s.start for s in plan.segments)
        self.people = np.zeros((self.persons, self.total, NUM_JOINTS, 3), dtype=np.float64)
        self.written = 0
        self._stream: Iterator = generator.stream(req, plan)

    def _check(self, chunk) -> list[np.ndarray]:
        chunk = [np.asarray(c, dtype=np.float64) for c in chunk]
        n = chunk[0].shape[0]
        if len(chunk) != self.persons or any(c.shape != (n, NUM_JOINTS, 3) for c in chunk):
            raise ValueError(f"generator sent chunk shapes {[c.shape for c in chunk]} "
                             f"for {self.persons} person(s)")
        return chunk

    def fill(self, end: int, on_chunk: Callable[[int, list[np.ndarray]], None],
             cancelled: Callable[[], bool] = lambda: False) -> None:
        """Pull chunks until frame `end` is written, calling on_chunk(start, chunk) for each."""
        while self.written < end:
            if cancelled():
                raise Cancelled()
            try:
                start, chunk = next(self._stream)
            except StopIteration:
                raise ValueError(f"the generator stopped at frame {self.written} of "
                                 f"{self.total}") from None
            chunk = self._check(chunk)
            start, stop = int(start), int(start) + chunk[0].shape[0]
            if stop > self.people.shape[1]:       # the generator ran longer than planned: grow
                grow = np.zeros((self.persons, stop - self.people.shape[1], NUM_JOINTS, 3))
                self.people = np.concatenate([self.people, grow], axis=1)
            self.people[:, start:stop] = np.stack(chunk)
            self.written = max(self.written, stop)
            on_chunk(start, chunk)

    def redraw(self, index: int, seed: int) -> tuple[SegmentSource, list[np.ndarray]]:
        """A new source whose plan re-draws retrieval segment `index` with `seed`, pulled up to
        that segment's end, and the segment's new frames per person. Earlier segments come out
        the same (the stitcher is deterministic)."""
        if not isinstance(self.generator, Redrawer):
            raise TypeError(f"{type(self.generator).__name__} cannot re-draw a segment")
        seg = self.plan.segments[index]
        other = SegmentSource(self.generator, self.req, self.generator.redraw(self.plan, index, seed))
        other.fill(seg.end, lambda *_: None)
        return other, [other.people[p, seg.start:seg.end].copy() for p in range(self.persons)]

    def adopt(self, other: "SegmentSource", upto: int) -> None:
        """Continue from `other`'s stream (a re-drawn plan), keeping our frames after `upto`
        only where other has none."""
        self.plan, self._stream = other.plan, other._stream
        self.people[:, :upto] = other.people[:, :upto]
        extra = other.written - upto
        if extra > 0:
            self.people[:, upto:other.written] = other.people[:, upto:other.written]
        self.written = other.written
