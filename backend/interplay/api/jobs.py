"""Durable jobs: every job is a database row (`store.jobs`: spec, state, reason, owner, worker,
attempts) and every event it streams a row too, so a stream opened on any process, or after a
restart, replays it from the first event and follows it to its end.

Events, in order (see docs/api.md and docs/review.md):
    plan → (segment, (frames, highlights)*, review, correction*, …, segment)* → metrics
    → done
    or, on failure or cancellation, … → error (with `stage`, or `cancelled: true`).
What a job runs is a runner (`api/runners/`): generation (CoMA's Algorithm 1 in
`pipeline/orchestrator.py`), a reaction or an edit.

One `JobManager` per process, in one of three roles:
    embedded       (the default, SQLite or not) admits jobs and runs them on its worker threads;
                   a stream of a job run here reads the events from memory, the database has
                   them for everyone else (written in batches by `queue.writer`)
    procrastinate  (an API process with PostgreSQL) admits jobs and defers them to
                   procrastinate; `interplay worker` processes run them
    worker         (`interplay worker`) runs the jobs procrastinate hands it
Every role refreshes the heartbeat of the jobs it holds, passes on cancels asked for through
other processes, and handles orphans: a running job whose worker died is queued again with a
`restart` event and run from its start (`queue.requeue`; after `max_attempts` starts it is
failed with the reason and an error event); a queued embedded job whose process died is taken
over and run here.
"""

from __future__ import annotations

import asyncio
import logging
import math
import threading
import time
import weakref
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from dataclasses import asdict, dataclass, field
from typing import Any, Protocol

from fastapi import HTTPException

from interplay.api.events import ErrorEvent
from interplay.api.queue.execute import SHUTDOWN, run_job
from interplay.api.queue.follow import Notifier, StoredJob, ended_event
from interplay.api.queue.live import LiveJob
from interplay.api.queue.requeue import requeue_or_fail
from interplay.api.queue.writer import EventWriter
from interplay.motion.skeleton import FPS
from interplay.store import JobRecord, JobStore, MotionRepository, new_id
from interplay.store.jobs import process_name

log = logging.getLogger(__name__)
MAX_FINISHED = 64          # finished jobs kept in memory for replay at most (the rest: database)
TICK_S = 1.0               # heartbeats, cancels asked elsewhere, orphans
HOUSEKEEPING_S = 60.0      # events of old jobs, retention
ORPHAN_GRACE_S = 3.0       # a dead process's job is ended once its heartbeat is this old
_MANAGERS: weakref.WeakSet[JobManager] = weakref.WeakSet()


@dataclass(frozen=True)
class JobSpec:
    prompt: str | None                                          # None: a react job's no intent
    persons: int
    seconds: float
    seed: int | None                                            # None: an edit's random seed
    trajectory: dict | None = field(default=None, hash=False)   # {person, points | shape …}
    mode: str = "generate"                          # "generate" | "react" | "edit" | "rerun"
    actor_motion_id: str | None = None
    parent_id: str | None = None                                # edit: the motion edited
    part: str | None = None                                     # edit: the body part
    frames: list[int] | None = field(default=None, hash=False)  # edit: [a, b)
    segment: int | None = None                                  # rerun: the plan segment
    client_id: str | None = None    # the browser that asked (X-Interplay-Client), for its list

    @property
    def frame_count(self) -> int:
        return max(1, round(self.seconds * FPS))

    def plain(self) -> dict:
        return asdict(self)

    @classmethod
    def from_plain(cls, data: dict) -> JobSpec:
        known: dict[str, Any] = {k: data[k] for k in cls.__dataclass_fields__ if k in data}
        return cls(**known)


class QueueFull(Exception):
    def __init__(self, message: str, retry_after: int):
        super().__init__(message)
        self.retry_after = retry_after


class Unavailable(Exception):
    """The process cannot take jobs (shutting down, or the queue engine is unreachable)."""


@dataclass(frozen=True)
class JobInfo:
    id: str
    motion_id: str
    status: str
    events: int
    reason: str | None
    attempts: int
    cancel_requested: bool = False
    result: dict | None = None


class Streamable(Protocol):
    id: str
    motion_id: str

    def events(self) -> Any: ...


def _info_live(job: LiveJob) -> JobInfo:
    return JobInfo(id=job.id, motion_id=job.motion_id, status=job.status,
                   events=job.event_count, reason=job.reason, attempts=job.attempts,
                   cancel_requested=job.cancelled, result=job.result)


def _info_stored(rec: JobRecord) -> JobInfo:
    return JobInfo(id=rec.id, motion_id=rec.motion_id, status=rec.state, events=rec.events,
                   reason=rec.reason, attempts=rec.attempts,
                   cancel_requested=rec.cancel_requested or rec.state == "cancelled",
                   result=rec.result)


class JobManager:
    def __init__(self, store: JobStore, repo: MotionRepository, *, role: str = "embedded",
                 workers: int = 1, max_pending: int = 16, retention_s: float = 900.0,
                 generator=None, defer=None, notifier: Notifier | None = None,
                 stale_s: float = 30.0, poll_s: float | None = None, tick_s: float = TICK_S,
                 max_attempts: int = 3):
        assert role in ("embedded", "procrastinate", "worker")
        self.store, self.repo, self.role = store, repo, role
        self.workers, self.max_pending, self.retention_s = workers, max_pending, retention_s
        self.generator, self.defer = generator, defer
        self.stale_s, self.tick_s = stale_s, tick_s
        self.max_attempts = max_attempts        # starts of a job whose process keeps dying
        self.poll_s = poll_s if poll_s is not None else (1.0 if store.postgres else 0.2)
        self.name = process_name()
        self.notifier = notifier or Notifier(store, None)
        self.writer = EventWriter(store) if role != "procrastinate" else None
        self._pool = (ThreadPoolExecutor(max_workers=workers, thread_name_prefix="interplay-gen")
                      if role == "embedded" else None)
        self._live: dict[str, LiveJob] = {}
        self._lock = threading.Lock()
        self._closing = threading.Event()     # running jobs stop at their next step
        self.accepting = True
        self._stop = threading.Event()
        self._streams = 0
        self._thread: threading.Thread | None = None
        self.on_close: list[Callable[[], None]] = []
        _MANAGERS.add(self)

    # -- life -----------------------------------------------------------------------------------

    def start(self) -> None:
        """End or take over the jobs a dead process left (before serving), then keep doing so
        along with heartbeats in a background thread."""
        self.notifier.start()
        try:
            self._reap()
        except Exception:
            log.exception("could not check for orphaned jobs")
        self._thread = threading.Thread(target=self._maintain, name="interplay-job-keeper",
                                        daemon=True)
        self._thread.start()

    def close(self) -> None:
        """Stop at once (the lifespan's end): running jobs stop at their next step with an error
        event, queued ones here end the same way; what was pushed is written."""
        self.accepting = False
        self._closing.set()
        self._stop_jobs(self._unfinished(), queued_only=True)
        if self._pool is not None:
            self._pool.shutdown(wait=False, cancel_futures=True)
        self._stop.set()
        self.notifier.stop()
        if self.writer is not None:
            self.writer.close(5.0)
        close = getattr(self.defer, "close", None)
        for hook in ([close] if close is not None else []) + self.on_close:
            try:
                hook()
            except Exception:
                log.exception("closing the job manager")

    async def drain(self, timeout: float, settle: float = 3.0) -> None:
        """SIGTERM: take no new jobs, give the ones here up to `timeout` seconds to finish,
        then end the rest with an error event ("the server is shutting down"), and wait (up
        to `settle` s) for those events to be written and sent to open streams."""
        self.accepting = False
        deadline = time.monotonic() + timeout
        while self._unfinished() and time.monotonic() < deadline:
            await asyncio.sleep(0.05)
        left = self._unfinished()
        if left:
            log.warning("shutting down: failing %d unfinished job(s)", len(left))
        self._closing.set()
        await asyncio.to_thread(self._stop_jobs, left, queued_only=True)
        end = time.monotonic() + settle
        while self._unfinished() and time.monotonic() < end:
            await asyncio.sleep(0.05)
        # A runner stuck inside a step: end it from here.
        await asyncio.to_thread(self._stop_jobs, self._unfinished(), queued_only=False)
        if self.writer is not None:
            await asyncio.to_thread(self.writer.flush, max(0.5, end - time.monotonic()))
        # Open streams here may follow jobs another process runs (and drains): give them as
        # long as that process gives its jobs, then they are closed (1012) by the server.
        end = max(end, deadline + settle)
        while self._streams and time.monotonic() < end:
            await asyncio.sleep(0.02)

    @staticmethod
    def _stop_jobs(jobs: list[LiveJob], queued_only: bool) -> None:
        """Cancel `jobs` for the shutdown; end the queued ones (or all) with its error event."""
        for job in jobs:
            job.cancel(SHUTDOWN)
            if job.status == "queued" or not queued_only:
                job.push(ErrorEvent(message=SHUTDOWN).dump())

    def _local(self) -> list[LiveJob]:
        with self._lock:
            return list(self._live.values())

    def _unfinished(self) -> list[LiveJob]:
        return [j for j in self._local() if not j.ended]

    # -- admission ------------------------------------------------------------------------------

    def submit(self, spec: JobSpec, generator=None) -> JobInfo:
        """Queue a job: QueueFull when `max_pending` jobs are already queued or running (in every
        process), Unavailable while shutting down."""
        if not self.accepting or self.role == "worker":
            raise Unavailable(SHUTDOWN)
        job_id, motion_id = new_id(), new_id()
        if not self.store.admit(id=job_id, motion_id=motion_id, kind=spec.mode,
                                spec=spec.plain(), queue=self.role, owner=self.name,
                                max_active=self.max_pending):
            raise QueueFull(f"{self.max_pending} jobs are already waiting; try again shortly",
                            self.retry_after())
        if self.role == "procrastinate":
            try:
                self.defer(job_id)
            except Exception as exc:
                log.exception("could not queue job %s", job_id)
                rec = self.store.get(job_id)
                if rec is not None:
                    self.store.end_with_event(rec, from_states=("queued",), state="failed",
                                              reason=f"could not queue the job: {exc}",
                                              event=ErrorEvent(message="could not queue the "
                                                               f"job: {exc}").dump())
                raise Unavailable(f"the job queue is unavailable: {exc}") from None
            return JobInfo(id=job_id, motion_id=motion_id, status="queued", events=0,
                           reason=None, attempts=0)
        job = self._add_live(job_id, motion_id, spec)
        self._schedule(job, generator if generator is not None else self.generator)
        return _info_live(job)

    def _add_live(self, job_id: str, motion_id: str, spec: JobSpec, seq: int = 0) -> LiveJob:
        self._prune_memory()
        job = LiveJob(job_id, motion_id, spec, self.writer, seq=seq)
        with self._lock:
            self._live[job_id] = job
        return job

    def _schedule(self, job: LiveJob, generator) -> None:
        assert self._pool is not None
        try:
            self._pool.submit(self._run, job, generator)
        except RuntimeError:     # the pool has shut down
            job.push(ErrorEvent(message=SHUTDOWN).dump())

    def retry_after(self) -> int:
        """Seconds until a slot is likely free: the queue ahead, at the recent run time."""
        try:
            recent = self.store.recent_run_seconds()
            active = self.store.active_count()
        except Exception:
            return 5
        per_job = sum(recent) / len(recent) if recent else 5.0
        ahead = max(1, active - self.max_pending + 1)
        return int(min(300, max(1, math.ceil(per_job * ahead / max(1, self.workers)))))

    # -- running --------------------------------------------------------------------------------

    def _run(self, job: LiveJob, generator) -> None:
        if job.ended:                     # cancelled while queued
            return
        try:
            rec = self.store.claim(job.id, self.name)
            if rec is None:               # ended by another process meanwhile (cancel, reaper)
                done = self.store.get(job.id)
                job.cancel()
                job.push(ended_event(done), store=False)
                return
        except Exception as exc:
            # Raised here it would only reach the pool's future, which nobody reads: the job
            # would stay queued with no event and its streams would wait for ever. It fails,
            # with the reason (e.g. SQLite's "database is locked"), and the thread goes on.
            log.exception("job %s could not start", job.id)
            job.push(ErrorEvent(stage="store", message=f"the job could not start: {exc}").dump())
            return
        job.status, job.attempts = "running", rec.attempts
        run_job(job, generator, self.repo, self._closing.is_set)

    def run_stored(self, job_id: str) -> None:
        """The worker role: run the stored job `job_id` (procrastinate's task), its events
        written (not kept in memory), and return once its end is stored."""
        rec = self.store.claim(job_id, self.name)
        if rec is None:
            log.info("job %s is not queued any more; skipped", job_id)
            return
        job = LiveJob(rec.id, rec.motion_id, JobSpec.from_plain(rec.spec), self.writer,
                      keep=False, seq=rec.events)
        job.status, job.attempts = "running", rec.attempts
        with self._lock:
            self._live[job.id] = job
        try:
            if self._closing.is_set():
                job.cancel(SHUTDOWN)
            run_job(job, self.generator, self.repo, self._closing.is_set)
        finally:
            assert self.writer is not None
            self.writer.flush(30.0)
            with self._lock:
                self._live.pop(job.id, None)

    def stop_running(self, reason: str) -> None:
        """Ask every job running here to stop (their streams end with `reason`)."""
        self._closing.set()
        for job in self._unfinished():
            job.cancel(reason)

    # -- lookups --------------------------------------------------------------------------------

    def get(self, job_id: str) -> Streamable | None:
        """A streamable job (from memory, or the database); None when unknown, malformed, or
        its events have expired."""
        with self._lock:
            live = self._live.get(job_id)
        if live is not None and self.role == "embedded":
            return _Counted(live, self)
        rec = self.store.get(job_id)
        if rec is None or rec.events_pruned:
            return None
        return _Counted(StoredJob(rec, self.store, self.notifier, self.poll_s), self)

    def status(self, job_id: str) -> JobInfo | None:
        with self._lock:
            live = self._live.get(job_id)
        if live is not None and self.role == "embedded":
            return _info_live(live)
        rec = self.store.get(job_id)
        return _info_stored(rec) if rec is not None else None

    def pending(self) -> int:
        return self.store.active_count()

    def cancel(self, job_id: str) -> JobInfo | None:
        """Cancel a job wherever it runs (a finished one is left as it is); None for unknown
        ids."""
        with self._lock:
            live = self._live.get(job_id)
        if live is not None and self.role == "embedded":
            if not live.ended:
                live.cancel()
                if live.status == "queued":
                    live.push(ErrorEvent(message="cancelled", cancelled=True).dump())
            return _info_live(live)
        rec = self.store.request_cancel(job_id, ErrorEvent(message="cancelled",
                                                           cancelled=True).dump())
        return _info_stored(rec) if rec is not None else None

    async def wait(self, job_id: str) -> JobInfo | None:
        """Follow a job to its end; its final status."""
        job = self.get(job_id)
        if job is not None:
            async for _ in job.events():
                pass
        return await asyncio.to_thread(self.status, job_id)

    # -- upkeep ---------------------------------------------------------------------------------

    def _maintain(self) -> None:
        last_housekeeping = 0.0
        while not self._stop.wait(self.tick_s):
            try:
                mine = [j.id for j in self._unfinished()]
                self.store.heartbeat(mine)
                running = [j for j in self._unfinished() if j.status == "running"]
                if running:
                    asked = self.store.cancel_requested([j.id for j in running])
                    for job in running:
                        if job.id in asked:
                            job.cancel()
                self._reap()
                if time.monotonic() - last_housekeeping > HOUSEKEEPING_S:
                    last_housekeeping = time.monotonic()
                    self.housekeeping()
            except Exception:
                log.exception("job upkeep failed; trying again")

    def housekeeping(self) -> None:
        """Drop old jobs' events (their rows stay) and apply the retention policy."""
        self.store.prune_events(self.retention_s)
        self.repo.enforce_retention()
        self._prune_memory()

    def _reap(self) -> None:
        for rec in self.store.orphans(self.stale_s, ORPHAN_GRACE_S):
            with self._lock:
                if rec.id in self._live:
                    continue                          # alive, here
            if rec.state == "queued":
                if self.role == "embedded" and self.accepting and self.store.adopt(rec, self.name):
                    log.info("took over queued job %s from %s", rec.id, rec.owner)
                    job = self._add_live(rec.id, rec.motion_id, JobSpec.from_plain(rec.spec),
                                         seq=rec.events)
                    self._schedule(job, self.generator)
                continue
            requeue_or_fail(self, rec)

    def run_again(self, rec: JobRecord) -> None:
        """The embedded queue: run a job queued again here (`queue.requeue`); its events go on
        after the `restart` event."""
        job = self._add_live(rec.id, rec.motion_id, JobSpec.from_plain(rec.spec),
                             seq=rec.events + 1)
        self._schedule(job, self.generator)

    def _prune_memory(self) -> None:
        """Forget finished jobs older than the retention time, and all but the newest
        MAX_FINISHED (their buffered frames hold memory; the database keeps them)."""
        now = time.monotonic()
        with self._lock:
            finished = sorted(((j.finished, j) for j in self._live.values()
                               if j.finished is not None), key=lambda p: p[0], reverse=True)
            for i, (at, j) in enumerate(finished):
                if i >= MAX_FINISHED or now - at > self.retention_s:
                    del self._live[j.id]


class _Counted:
    """A streamable job that counts its open streams on the manager (drain waits for them)."""

    def __init__(self, job: Any, manager: JobManager):
        self.job, self.manager = job, manager
        self.id, self.motion_id = job.id, job.motion_id

    async def events(self):
        self.manager._streams += 1
        try:
            async for event in self.job.events():
                yield event
        finally:
            self.manager._streams -= 1


async def drain_all(timeout: float) -> None:
    """Drain every job manager of this process (cli/serve calls it on SIGTERM, before the
    server closes its connections)."""
    managers = list(_MANAGERS)
    if managers:
        await asyncio.gather(*(m.drain(timeout) for m in managers))


def motion_missing(store: JobStore | MotionRepository, motion_id: str) -> HTTPException:
    """Why `motion_id` is not a stored motion, as the HTTP error to answer:
    404 unknown, 404 not made yet (its job is queued or running), 409 its job failed or was
    cancelled (with the reason), 404 deleted by the retention policy."""
    jobs = store if isinstance(store, JobStore) else JobStore(store.engine)
    rec = jobs.by_motion(motion_id)
    unknown = f"no motion {motion_id!r} (unknown or malformed id)"
    if rec is None:
        return HTTPException(404, unknown)
    if rec.state in ("queued", "running"):
        return HTTPException(404, f"motion {motion_id!r} is not ready yet: its job is "
                                  f"{rec.state}", headers={"X-Interplay-Job-State": rec.state})
    if rec.state == "done":
        return HTTPException(404, f"motion {motion_id!r} was deleted (retention policy)",
                             headers={"X-Interplay-Job-State": "deleted"})
    why = rec.reason or rec.state
    what = "was cancelled" if rec.state == "cancelled" else f"failed: {why}"
    return HTTPException(409, f"motion {motion_id!r} was not made: its job {what}",
                         headers={"X-Interplay-Job-State": rec.state})
