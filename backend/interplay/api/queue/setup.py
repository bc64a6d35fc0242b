"""Building a process's job manager and generator from the settings (the app's lifespan and
`interplay worker`), and draining it on SIGTERM."""

from __future__ import annotations

import asyncio
import signal
import threading
from collections.abc import Callable
from types import FrameType
from typing import Any

from interplay.settings import Settings
from interplay.store import JobStore, MotionRepository


async def open_jobs(settings: Settings, repo: MotionRepository, generator):
    """The API process's JobManager (the app's lifespan): started off the event loop (orphans
    are checked first), drained on SIGTERM."""
    manager = await asyncio.to_thread(start_jobs, settings, repo, generator)
    manager.on_close.append(drain_on_signals(manager, settings.drain_s))
    return manager


def start_jobs(settings: Settings, repo: MotionRepository, generator):
    """The API process's JobManager, started: worker threads here (embedded), or procrastinate
    (PostgreSQL): `interplay worker` processes run the jobs."""
    from interplay.api.jobs import JobManager
    from interplay.api.queue.follow import Notifier
    store = JobStore(repo.engine)
    dsn = None
    if store.postgres:
        from interplay.api.queue.factory import conninfo
        dsn = conninfo(settings.db_url)
    role = "procrastinate" if settings.queue == "procrastinate" else "embedded"
    defer = None
    if role == "procrastinate":
        from interplay.api.queue.engine import Deferrer
        defer = Deferrer(settings.db_url)
    manager = JobManager(store, repo, role=role, workers=settings.job_workers,
                         max_pending=settings.max_pending_jobs,
                         retention_s=settings.job_retention_s, generator=generator, defer=defer,
                         notifier=Notifier(store, dsn), stale_s=settings.job_stale_s,
                         max_attempts=settings.job_max_attempts)
    manager.start()
    return manager


def drain_on_signals(manager, drain_s: float) -> Callable[[], None]:
    """On the first SIGTERM (or SIGINT) drain `manager` — no new jobs, up to `drain_s` seconds
    for the running ones, then an error event for the rest — and only then hand the signal to
    the handler that was there (uvicorn's, which closes the connections: by then every stream
    of a job here has sent its last event and closed normally). A second signal goes straight
    through. Only where signals can be caught (the main thread of `interplay serve`); returns
    the function that puts the old handlers back."""
    if threading.current_thread() is not threading.main_thread():
        return lambda: None
    loop = asyncio.get_running_loop()
    signals = (signal.SIGTERM, signal.SIGINT)
    previous: dict[int, Any] = {int(sig): signal.getsignal(sig) for sig in signals}
    draining = threading.Event()

    def handler(sig: int, frame: FrameType | None) -> None:
        prev = previous[sig]
        if draining.is_set():
            if callable(prev):
                prev(sig, frame)
            return
        draining.set()

        async def drain_then_pass_on() -> None:
            try:
                await manager.drain(drain_s)
            finally:
                if callable(prev):
                    prev(sig, None)
                else:
                    signal.signal(sig, prev)
                    signal.raise_signal(sig)
        loop.call_soon_threadsafe(lambda: loop.create_task(drain_then_pass_on()))

    for sig in signals:
        signal.signal(sig, handler)

    def restore() -> None:
        for sig, prev in previous.items():
            if signal.getsignal(sig) is handler:
                signal.signal(sig, prev)
    return restore
