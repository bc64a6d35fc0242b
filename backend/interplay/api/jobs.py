"""Generation jobs: each runs in a worker thread (never on the event loop) and appends its
events to a buffer, so a WebSocket that connects late still replays everything from the start.

Events, in order (see docs/api.md and docs/review.md):
    plan → (segment, (frames, highlights)*, review, correction*, …, segment)* → metrics
    → done
    or, on failure or cancellation, … → error (with `stage`, or `cancelled: true`).
The work itself is CoMA's Algorithm 1 in agents/orchestrator.py; this module runs it in a
thread, turns its frames into events and stores the result.
"""

from __future__ import annotations

import asyncio
import logging
import secrets
import threading
import time
from collections.abc import AsyncIterator
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field

import numpy as np

from ..agents.segment_source import Cancelled  # raised by the orchestrator too
from ..motion.skeleton import FPS, NUM_JOINTS
from ..store import MotionRepository, new_id
from .motion_json import joints_list, plain

log = logging.getLogger(__name__)
TERMINAL = ("done", "error")
MAX_FINISHED = 64   # finished jobs kept for replay at most


@dataclass(frozen=True)
class JobSpec:
    prompt: str | None                                          # None: a react job's no intent
    persons: int
    seconds: float
    seed: int
    trajectory: dict | None = field(default=None, hash=False)   # {person, points | shape …}
    mode: str = "generate"                                      # "generate" | "react"
    actor_motion_id: str | None = None

    @property
    def frames(self) -> int:
        return max(1, round(self.seconds * FPS))


class Job:
    def __init__(self, spec: JobSpec):
        self.id = new_id()
        self.motion_id = new_id()
        self.spec = spec
        self.status = "queued"            # queued → running → done | failed
        self.created = time.monotonic()
        self.finished: float | None = None
        self._events: list[dict] = []
        self._lock = threading.Lock()
        self._waiters: set[tuple[asyncio.AbstractEventLoop, asyncio.Event]] = set()
        self._cancel = threading.Event()

    def cancel(self) -> None:
        """Ask the job to stop; it ends with an error event `cancelled: true`."""
        self._cancel.set()

    @property
    def cancelled(self) -> bool:
        return self._cancel.is_set()

    @property
    def event_count(self) -> int:
        with self._lock:
            return len(self._events)

    def push(self, event: dict) -> None:
        """Append an event (from any thread) and wake every listener."""
        with self._lock:
            self._events.append(event)
            waiters = list(self._waiters)
        for loop, flag in waiters:
            try:
                loop.call_soon_threadsafe(flag.set)
            except RuntimeError:  # that listener's loop has closed
                pass

    async def events(self) -> AsyncIterator[dict]:
        """Every event from the first, then new ones as they come, up to done/error."""
        flag = asyncio.Event()
        key = (asyncio.get_running_loop(), flag)
        with self._lock:
            self._waiters.add(key)
        try:
            sent = 0
            while True:
                flag.clear()   # before reading, so a push after the read still wakes us
                with self._lock:
                    new = self._events[sent:]
                for event in new:
                    yield event
                    if event["type"] in TERMINAL:
                        return
                sent += len(new)
                if not new:
                    await flag.wait()
        finally:
            with self._lock:
                self._waiters.discard(key)


def make_request(prompt: str, persons: int, seconds: float, seed: int):
    """The generator's `Request` for a job (the CLI builds the same)."""
    from ..agents.generator import Request
    return Request(prompt=prompt, persons=persons, seconds=seconds, seed=seed)


def _highlights_event(start: int, window: list[np.ndarray], skip: int, persons: int) -> dict:
    """Per-frame highlights of `window` (the chunk with `skip` frames of context before it)."""
    from ..motion.metrics import frame_highlights
    h = plain(frame_highlights(window))
    dist = h.get("min_distance")
    return {
        "type": "highlights", "start": start,
        "contacts": [[[int(p), int(j)] for p, j in f] for f in h["contacts"][skip:]],
        "penetration": [[[int(p), str(part)] for p, part in f] for f in h["penetration"][skip:]],
        "min_distance": ([None if d is None else round(float(d), 4) for d in dist[skip:]]
                         if persons > 1 and dist is not None else None),
    }


class JobManager:
    """Runs jobs on a small thread pool and keeps them (with their events) for a while."""

    def __init__(self, repo: MotionRepository, workers: int = 1, max_pending: int = 16,
                 retention_s: float = 900.0):
        self.repo = repo
        self.max_pending = max_pending
        self.retention_s = retention_s
        self._pool = ThreadPoolExecutor(max_workers=workers, thread_name_prefix="interplay-gen")
        self._jobs: dict[str, Job] = {}
        self._lock = threading.Lock()
        self._closing = threading.Event()

    def get(self, job_id: str) -> Job | None:
        with self._lock:
            return self._jobs.get(job_id)

    def pending(self) -> int:
        with self._lock:
            return sum(j.status in ("queued", "running") for j in self._jobs.values())

    def submit(self, spec: JobSpec, generator) -> Job:
        """Queue a job; raises OverflowError when too many are waiting."""
        self._prune()
        if self.pending() >= self.max_pending:
            raise OverflowError(f"{self.max_pending} jobs are already waiting; try again shortly")
        job = Job(spec)
        with self._lock:
            self._jobs[job.id] = job
        self._pool.submit(self._run, job, generator)
        return job

    def cancel(self, job_id: str) -> Job | None:
        """Cancel a job (a finished one is left as it is); None for unknown ids."""
        job = self.get(job_id)
        if job is not None and job.finished is None:
            job.cancel()
        return job

    def shutdown(self) -> None:
        self._closing.set()
        self._pool.shutdown(wait=False, cancel_futures=True)

    def _prune(self) -> None:
        """Forget finished jobs older than the retention time, and all but the newest
        MAX_FINISHED (their buffered frames hold memory; the motions stay in the store)."""
        now = time.monotonic()
        with self._lock:
            finished = sorted((j for j in self._jobs.values() if j.finished is not None),
                              key=lambda j: j.finished, reverse=True)
            for i, j in enumerate(finished):
                if i >= MAX_FINISHED or now - j.finished > self.retention_s:
                    del self._jobs[j.id]

    def _run(self, job: Job, generator) -> None:
        from ..agents.orchestrator import StageError
        job.status = "running"
        try:
            if job.cancelled:
                raise Cancelled()
            if job.spec.mode == "react":
                from ..agents import reaction   # the reaction engineer's module
                reaction.react_job(job, generator, self.repo)
            else:
                self._generate(job, generator)
            job.status = "done"
        except Cancelled:
            job.status = "failed"
            job.push({"type": "error", "message": "cancelled", "cancelled": True} if job.cancelled
                     else {"type": "error", "message": "the server is shutting down"})
        except StageError as exc:
            job.status = "failed"
            job.push({"type": "error", "stage": exc.stage,
                      "message": f"generation failed at {exc.stage}: {exc.reason}"})
        except Exception as exc:  # reported to the client, never raised into the pool
            log.exception("job %s failed", job.id)
            job.status = "failed"
            job.push({"type": "error", "stage": "store",
                      "message": f"generation failed: {exc}"})
        finally:
            job.finished = time.monotonic()

    def _generate(self, job: Job, generator) -> None:
        from ..agents.orchestrator import StageError, default_evaluator, orchestrate
        from ..motion.metrics import clip_metrics
        spec = job.spec
        req = make_request(spec.prompt, spec.persons, spec.seconds, spec.seed)
        total = spec.frames
        people = np.zeros((spec.persons, total, NUM_JOINTS, 3), dtype=np.float32)
        written = 0
        contacts: list = [[] for _ in range(total)]
        penetration: list = [[] for _ in range(total)]
        min_dist: list | None = [None] * total if spec.persons > 1 else None

        def on_frames(start: int, chunk: list[np.ndarray]) -> None:
            nonlocal people, written, contacts, penetration, min_dist
            if self._closing.is_set():
                raise Cancelled()
            chunk = [np.asarray(c, dtype=np.float32) for c in chunk]
            n = chunk[0].shape[0]
            if len(chunk) != spec.persons or any(c.shape != (n, NUM_JOINTS, 3) for c in chunk):
                raise ValueError(f"generator sent chunk shapes {[c.shape for c in chunk]} "
                                 f"for {spec.persons} person(s)")
            start, end = int(start), int(start) + n
            if end > people.shape[1]:   # the generator ran longer than asked: grow
                grow = end - people.shape[1]
                people = np.concatenate([people, np.zeros((spec.persons, grow, NUM_JOINTS, 3),
                                                          dtype=np.float32)], axis=1)
                contacts += [[] for _ in range(grow)]
                penetration += [[] for _ in range(grow)]
                if min_dist is not None:
                    min_dist += [None] * grow
            people[:, start:end] = np.stack(chunk)
            written = max(written, end)
            # A repeated start (a corrected segment, a moved path) replaces those frames.
            job.push({"type": "frames", "start": start, "total": max(total, written),
                      "people": [joints_list(c) for c in chunk]})
            # One frame of context before the chunk, so velocity-based contacts are defined.
            ctx = 1 if start > 0 else 0
            hl = _highlights_event(start, [p[start - ctx:end] for p in people], ctx, spec.persons)
            job.push(hl)
            contacts[start:end] = hl["contacts"]
            penetration[start:end] = hl["penetration"]
            if min_dist is not None:
                min_dist[start:end] = hl["min_distance"]

        out = orchestrate(generator, req, lambda e: job.push(plain(e)), on_frames,
                          cancelled=lambda: job.cancelled or self._closing.is_set(),
                          trajectory=spec.trajectory, evaluator=default_evaluator())
        if written == 0:
            raise StageError("generate", "the generator produced no frames")
        final = [p[:written] for p in out.people]
        try:
            metrics = plain(clip_metrics([p.astype(np.float64) for p in final], fps=FPS))
        except Exception as exc:
            raise StageError("metrics", f"{type(exc).__name__}: {exc}") from exc
        job.push({"type": "metrics", "metrics": metrics})
        highlights = {"contacts": contacts[:written], "penetration": penetration[:written],
                      "min_distance": min_dist[:written] if min_dist is not None else None}
        try:
            self.repo.create(id=job.motion_id, prompt=spec.prompt, people=final,
                             seconds=spec.seconds, seed=spec.seed, plan=plain(out.plan),
                             metrics=metrics, highlights=highlights, review=plain(out.review))
        except Exception as exc:
            raise StageError("store", f"{type(exc).__name__}: {exc}") from exc
        job.push({"type": "done", "motion_id": job.motion_id, "frames": written})


def random_seed() -> int:
    return secrets.randbelow(2**31)
