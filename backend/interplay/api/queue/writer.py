"""The one thread per process that writes job events and job ends to the database, in batches:
a runner's push only appends to a list, so streaming frames never waits on the database.

A batch is whatever has queued up when the thread wakes, gathered for at most `interval`
seconds (a job's end is written at once); it is one transaction, in order, so a job's state
never runs ahead of its events. `flush()` waits until everything queued so far is written."""

from __future__ import annotations

import logging
import threading
import time

from interplay.store.jobs import JobStore, Write

log = logging.getLogger(__name__)


class EventWriter:
    def __init__(self, store: JobStore, interval: float = 0.05):
        self.store, self.interval = store, interval
        self._pending: list[Write] = []
        self._cond = threading.Condition()
        self._queued = 0      # writes ever queued
        self._written = 0     # of those, written (or given up)
        self._stop = False
        self._thread = threading.Thread(target=self._loop, name="interplay-job-writer",
                                        daemon=True)
        self._thread.start()

    def append(self, job_id: str, seq: int, event: dict) -> None:
        with self._cond:
            last = self._pending[-1] if self._pending else None
            if (last is not None and last.job_id == job_id and last.state is None
                    and last.events is not None and last.seq + len(last.events) == seq):
                last.events.append(event)
            else:
                self._pending.append(Write(job_id, seq, [event]))
                self._queued += 1
            self._cond.notify()

    def end(self, job_id: str, state: str, reason: str | None, result: dict | None = None) -> None:
        with self._cond:
            self._pending.append(Write(job_id, state=state, reason=reason, result=result))
            self._queued += 1
            self._cond.notify()

    def flush(self, timeout: float = 10.0) -> bool:
        """Wait until everything queued before this call is written; False on timeout."""
        deadline = time.monotonic() + timeout
        with self._cond:
            target = self._queued
            self._cond.notify()
            while self._written < target:
                left = deadline - time.monotonic()
                if left <= 0 or not self._thread.is_alive():
                    return False
                self._cond.wait(left)
        return True

    def close(self, timeout: float = 10.0) -> None:
        self.flush(timeout)
        with self._cond:
            self._stop = True
            self._cond.notify_all()
        self._thread.join(timeout)

    def _loop(self) -> None:
        while True:
            with self._cond:
                while not self._pending and not self._stop:
                    self._cond.wait()
                if not self._pending and self._stop:
                    return
                # Gather a little more unless a job is ending (its end goes out at once).
                deadline = time.monotonic() + self.interval
                while not self._stop and not any(w.state for w in self._pending):
                    left = deadline - time.monotonic()
                    if left <= 0:
                        break
                    self._cond.wait(left)
                batch, self._pending = self._pending, []
            try:
                self._write(batch)
            finally:
                with self._cond:
                    self._written += len(batch)
                    self._cond.notify_all()

    def _write(self, batch: list[Write]) -> None:
        for attempt in range(5):
            try:
                self.store.write(batch)
                return
            except Exception:   # the database is away for a moment: try again, then give up
                if attempt == 4:
                    log.exception("could not store %d job writes; dropped", len(batch))
                    return
                time.sleep(0.2 * 2 ** attempt)
