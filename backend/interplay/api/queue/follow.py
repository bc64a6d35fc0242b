"""A stream of a job this process does not run (another API process or worker runs it, or it
ran before a restart): its events read from the database, from the first, then followed until
`done` or `error`.

On PostgreSQL one thread per process LISTENs on the jobs channel and wakes the streams of the
job named in each notification; the streams also poll (`poll_s`) in case one was missed. On
SQLite, which has no notifications, they poll every `poll_s`."""

from __future__ import annotations

import asyncio
import logging
import threading
from collections.abc import AsyncIterator

import anyio

from interplay.api.events import ErrorEvent
from interplay.api.queue.live import TERMINAL_EVENTS
from interplay.store.jobs import CHANNEL, JobRecord, JobStore

log = logging.getLogger(__name__)


class Notifier:
    """Wakes waiters when a job's events change: LISTEN on PostgreSQL, nothing elsewhere."""

    def __init__(self, store: JobStore, dsn: str | None):
        self.store, self.dsn = store, dsn
        self._waiters: dict[str, set[tuple[asyncio.AbstractEventLoop, asyncio.Event]]] = {}
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self.listening = threading.Event()

    def start(self) -> None:
        if self.dsn and self._thread is None:
            self._thread = threading.Thread(target=self._listen, name="interplay-job-listen",
                                            daemon=True)
            self._thread.start()

    def stop(self) -> None:
        self._stop.set()

    def add(self, job_id: str, loop: asyncio.AbstractEventLoop, flag: asyncio.Event) -> None:
        with self._lock:
            self._waiters.setdefault(job_id, set()).add((loop, flag))

    def discard(self, job_id: str, loop: asyncio.AbstractEventLoop, flag: asyncio.Event) -> None:
        with self._lock:
            group = self._waiters.get(job_id)
            if group is not None:
                group.discard((loop, flag))
                if not group:
                    del self._waiters[job_id]

    def wake(self, job_id: str) -> None:
        with self._lock:
            group = list(self._waiters.get(job_id, ()))
        for loop, flag in group:
            try:
                loop.call_soon_threadsafe(flag.set)
            except RuntimeError:
                pass

    def _listen(self) -> None:
        import psycopg
        assert self.dsn is not None
        backoff = 0.5
        while not self._stop.is_set():
            try:
                with psycopg.connect(self.dsn, autocommit=True) as conn:
                    conn.execute(f"LISTEN {CHANNEL}")
                    self.listening.set()
                    backoff = 0.5
                    while not self._stop.is_set():
                        for note in conn.notifies(timeout=1.0):
                            self.wake(note.payload)
            except Exception as exc:   # the database went away: streams poll meanwhile
                self.listening.clear()
                log.warning("job notifications lost (%s); retrying in %.1f s", exc, backoff)
                self._stop.wait(backoff)
                backoff = min(10.0, backoff * 2)


class StoredJob:
    """A job read from the database, streamable from any process."""

    def __init__(self, rec: JobRecord, store: JobStore, notifier: Notifier, poll_s: float):
        self.rec, self.store, self.notifier, self.poll_s = rec, store, notifier, poll_s
        self.id, self.motion_id = rec.id, rec.motion_id

    async def events(self) -> AsyncIterator[dict]:
        flag = asyncio.Event()
        loop = asyncio.get_running_loop()
        self.notifier.add(self.id, loop, flag)
        try:
            sent = 0
            while True:
                flag.clear()
                new = await anyio.to_thread.run_sync(self.store.events_after, self.id, sent)
                for event in new:
                    yield event
                    if event["type"] in TERMINAL_EVENTS:
                        return
                sent += len(new)
                if new:
                    continue
                rec = await anyio.to_thread.run_sync(self.store.get, self.id)
                if rec is None or rec.finished:
                    # Ended without a last event here (its events were dropped): say how.
                    more = await anyio.to_thread.run_sync(self.store.events_after, self.id, sent)
                    if more:
                        continue
                    yield ended_event(rec)
                    return
                try:
                    await asyncio.wait_for(flag.wait(), self.poll_s)
                except asyncio.TimeoutError:
                    pass
        finally:
            self.notifier.discard(self.id, loop, flag)


def ended_event(rec: JobRecord | None) -> dict:
    """The last event of a job whose own last event is not stored (any more)."""
    if rec is None:
        return ErrorEvent(message="the job is gone (its records were deleted)").dump()
    if rec.state == "done":
        return ErrorEvent(message=f"the job's events have expired; its motion is "
                                  f"/api/motions/{rec.motion_id}").dump()
    if rec.state == "cancelled":
        return ErrorEvent(message="cancelled", cancelled=True).dump()
    return ErrorEvent(message=rec.reason or "the job failed").dump()
