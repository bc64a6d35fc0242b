"""Generation jobs: each runs in a worker thread (never on the event loop) and appends its
events to a buffer, so a WebSocket that connects late still replays everything from the start.

Events, in order (see docs/api.md and docs/review.md):
    plan → (segment, (frames, highlights)*, review, correction*, …, segment)* → metrics
    → done
    or, on failure or cancellation, … → error (with `stage`, or `cancelled: true`).
What a job runs is a runner (`api/runners/`): generation (CoMA's Algorithm 1 in
`pipeline/orchestrator.py`) or a reaction.
"""

from __future__ import annotations

import asyncio
import logging
import threading
import time
from collections.abc import AsyncIterator
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field

from interplay.api.events import ErrorEvent
from interplay.api.runners.generate import GenerateRunner
from interplay.api.runners.react import react_job
from interplay.api.schemas import JobState
from interplay.motion.skeleton import FPS
from interplay.pipeline.orchestrator import StageError
from interplay.pipeline.segment_source import Cancelled  # raised by the orchestrator too
from interplay.store import MotionRepository, new_id

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
    client_id: str | None = None    # the browser that asked (X-Interplay-Client), for its list

    @property
    def frames(self) -> int:
        return max(1, round(self.seconds * FPS))


class Job:
    def __init__(self, spec: JobSpec):
        self.id = new_id()
        self.motion_id = new_id()
        self.spec = spec
        self.status: JobState = "queued"  # queued → running → done | failed
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
            finished = sorted(((j.finished, j) for j in self._jobs.values() if j.finished is not None),
                              key=lambda pair: pair[0], reverse=True)
            for i, (at, j) in enumerate(finished):
                if i >= MAX_FINISHED or now - at > self.retention_s:
                    del self._jobs[j.id]

    def _run(self, job: Job, generator) -> None:
        job.status = "running"
        try:
            if job.cancelled:
                raise Cancelled()
            if job.spec.mode == "react":
                react_job(job, self.repo)
            else:
                GenerateRunner(job, generator, self.repo, self._closing.is_set).run()
            job.status = "done"
        except Cancelled:
            job.status = "failed"
            job.push(ErrorEvent(message="cancelled", cancelled=True).dump() if job.cancelled
                     else ErrorEvent(message="the server is shutting down").dump())
        except StageError as exc:
            job.status = "failed"
            job.push(ErrorEvent(stage=exc.stage,
                                message=f"generation failed at {exc.stage}: {exc.reason}").dump())
        except Exception as exc:  # reported to the client, never raised into the pool
            log.exception("job %s failed", job.id)
            job.status = "failed"
            job.push(ErrorEvent(stage="store", message=f"generation failed: {exc}").dump())
        finally:
            job.finished = time.monotonic()
