"""A running job whose process died (killed, crashed, restarted): run again from its start, up to
`max_attempts` starts in all, then `failed` with the reason.

Queued again, its stream carries a `restart` event (`attempt`, `reason`) after what the dead
attempt streamed, and then the new attempt's events from its plan on; a client drops what it
had at `restart`. The embedded queue runs it on this process's worker threads; with
procrastinate the API process defers it again for the workers (an `interplay worker` leaves it
to the API processes, which can defer; it still fails one that has used its attempts). A job
carries its seed, so the new attempt makes the same motion."""

from __future__ import annotations

import logging
from typing import Any

from interplay.api.events import ErrorEvent, RestartEvent
from interplay.store import JobRecord

log = logging.getLogger(__name__)


def died(rec: JobRecord) -> str:
    who = rec.worker or rec.owner
    return f"the process running the job ({who}) stopped before it finished (killed, crashed or restarted)"


def requeue_or_fail(manager: Any, rec: JobRecord) -> None:
    """Handle one running orphan `rec` (its process is gone) for `manager` (an
    `api.jobs.JobManager`, which imports this module)."""
    reason = died(rec)
    if rec.attempts < manager.max_attempts:
        if manager.role == "worker" or not manager.accepting:
            return            # an API process queues it again (it can defer; this one cannot)
        event = RestartEvent(attempt=rec.attempts + 1, reason=reason).dump()
        if not manager.store.requeue(rec, owner=manager.name, event=event):
            return            # someone else got to it first
        log.warning("job %s queued again (attempt %d of %d): %s", rec.id, rec.attempts + 1,
                    manager.max_attempts, reason)
        manager.notifier.wake(rec.id)
        if manager.role == "embedded":
            manager.run_again(rec)
            return
        try:
            manager.defer(rec.id)
        except Exception as exc:
            log.exception("could not queue job %s again", rec.id)
            again = manager.store.get(rec.id)
            if again is not None:
                manager.store.end_with_event(again, from_states=("queued",), state="failed",
                                             reason=f"{reason}; could not queue it again: {exc}",
                                             event=ErrorEvent(stage="worker", message=(
                                                 f"generation failed: {reason}; could not "
                                                 f"queue it again: {exc}")).dump())
        return
    if rec.attempts > 1:
        reason = f"{reason}, on each of its {rec.attempts} attempts"
    event = ErrorEvent(stage="worker", message=f"generation failed: {reason}").dump()
    if manager.store.end_with_event(rec, from_states=("running",), state="failed",
                                    reason=reason, event=event):
        log.warning("job %s failed: %s", rec.id, reason)
        manager.notifier.wake(rec.id)
