"""A job running in this process: its events in memory (a stream here replays and follows them
without touching the database) and, through the writer, in the database (for streams on other
processes and after a restart). The first `done` or `error` event ends it; its state follows
from that event, and later pushes are ignored."""

from __future__ import annotations

import asyncio
import logging
import threading
import time
from collections.abc import AsyncIterator
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from interplay.api.queue.writer import EventWriter

log = logging.getLogger(__name__)
TERMINAL_EVENTS = ("done", "error")


def state_of(event: dict) -> tuple[str, str | None]:
    """(state, reason) a job ends in with this terminal event."""
    if event["type"] == "done":
        return "done", None
    if event.get("cancelled"):
        return "cancelled", "cancelled"
    return "failed", str(event.get("message") or "failed")


class LiveJob:
    def __init__(self, job_id: str, motion_id: str, spec: Any, writer: EventWriter | None,
                 keep: bool = True, seq: int = 0):
        self.id, self.motion_id, self.spec = job_id, motion_id, spec
        self.status = "queued"            # queued → running → done | failed | cancelled
        self.reason: str | None = None
        self.result: dict | None = None   # stored with the end (an edit's HTTP status)
        self.attempts = 0
        self.created = time.monotonic()
        self.finished: float | None = None
        self._writer, self._keep, self._seq = writer, keep, seq
        self._events: list[dict] = []
        self._closed = False              # the last event is in: no more
        self._lock = threading.Lock()
        self._waiters: set[tuple[asyncio.AbstractEventLoop, asyncio.Event]] = set()
        self._cancel = threading.Event()
        self.cancel_reason: str | None = None

    # -- what a runner sees ---------------------------------------------------------------------

    def cancel(self, reason: str | None = None) -> None:
        """Ask the job to stop: it ends with an error event `cancelled: true` (a client's
        cancel), or with `reason` as the message (e.g. the server shutting down)."""
        if reason is not None and not self._cancel.is_set():
            self.cancel_reason = reason
        self._cancel.set()

    @property
    def cancelled(self) -> bool:
        return self._cancel.is_set()

    @property
    def ended(self) -> bool:
        """Whether the last event was pushed (it may still be on its way to the database)."""
        return self._closed

    @property
    def event_count(self) -> int:
        with self._lock:
            return self._seq

    def push(self, event: dict, store: bool = True) -> bool:
        """Append an event (from any thread), store it (unless `store` is False: the database
        has it already) and wake every listener; False (and nothing happens) once the job has
        ended. The last event (done / error) is visible here only once the job's end is in the
        database, so whatever a client asks next (the job's status, the motion) agrees."""
        end = event["type"] in TERMINAL_EVENTS
        with self._lock:
            if self._closed:
                return False
            seq = self._seq
            self._seq += 1
            writer = self._writer if store else None
            if end:
                self._closed = True
                state, reason = state_of(event)
            if writer is not None:
                writer.append(self.id, seq, event)
                if end:
                    writer.end(self.id, state, reason, self.result)
            if not end:
                self._remember(event)
                waiters = list(self._waiters)
        if end:
            if writer is not None and not writer.flush(10.0):
                log.warning("job %s: its end is not stored yet", self.id)
            with self._lock:
                self.status, self.reason = state, reason
                self.finished = time.monotonic()
                self._remember(event)
                waiters = list(self._waiters)
        for loop, flag in waiters:
            try:
                loop.call_soon_threadsafe(flag.set)
            except RuntimeError:  # that listener's loop has closed
                pass
        return True

    def _remember(self, event: dict) -> None:
        if self._keep:
            self._events.append(event)

    # -- what a stream sees ---------------------------------------------------------------------

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
                    if event["type"] in TERMINAL_EVENTS:
                        return
                sent += len(new)
                if not new:
                    await flag.wait()
        finally:
            with self._lock:
                self._waiters.discard(key)
