"""What running one job means, wherever it runs (an API process's worker thread or a
procrastinate worker): the runner for its mode pushes its events, and every way it can end
pushes the job's last event — `done`, or `error` with why (and `cancelled: true` for a client's
cancel). Nothing is raised to the caller."""

from __future__ import annotations

import logging
from collections.abc import Callable

from interplay.api.events import ErrorEvent
from interplay.api.queue.live import LiveJob
from interplay.api.runners.edit import edit_job, rerun_job
from interplay.api.runners.generate import GenerateRunner
from interplay.api.runners.react import react_job
from interplay.pipeline.orchestrator import StageError
from interplay.pipeline.segment_source import Cancelled  # raised by the orchestrator too

log = logging.getLogger(__name__)

SHUTDOWN = "the server is shutting down"


def run_job(job: LiveJob, generator, repo, closing: Callable[[], bool]) -> None:
    stop = lambda: closing() or job.cancelled   # noqa: E731
    try:
        if job.cancelled:
            raise Cancelled()
        if job.spec.mode == "react":
            react_job(job, repo)
        elif job.spec.mode == "edit":
            edit_job(job, generator, repo)
        elif job.spec.mode == "rerun":
            rerun_job(job, generator, repo)
        else:
            GenerateRunner(job, generator, repo, stop).run()
        if not job.ended:
            job.push(ErrorEvent(stage="store", message="the job ended without a result").dump())
    except Cancelled:
        if job.cancelled and not closing() and job.cancel_reason is None:
            job.push(ErrorEvent(message="cancelled", cancelled=True).dump())
        else:
            job.push(ErrorEvent(message=job.cancel_reason or SHUTDOWN).dump())
    except StageError as exc:
        job.push(ErrorEvent(stage=exc.stage,
                            message=f"generation failed at {exc.stage}: {exc.reason}").dump())
    except Exception as exc:  # reported to the client, never raised into the pool
        log.exception("job %s failed", job.id)
        job.push(ErrorEvent(stage="store", message=f"generation failed: {exc}").dump())
