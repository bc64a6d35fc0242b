"""The PostgreSQL job queue: procrastinate (https://procrastinate.readthedocs.io), a task queue
kept by its maintainers on PostgreSQL alone — jobs are rows locked with SELECT … FOR UPDATE
SKIP LOCKED, workers wake on LISTEN/NOTIFY — so the database the motions live in is the
broker too. Why it and not Celery or Dramatiq: docs/api.md ("Scale-out").

Procrastinate carries only the job id (task `interplay.run_job`); the job itself, its state and
its events are Interplay's own rows (`store.jobs`), which the streams of every API process read.

    Deferrer(url)            an API process's handle: defer(job_id)
    run_worker(settings)     `interplay worker`: run jobs until SIGTERM/SIGINT
"""

from __future__ import annotations

import asyncio
import logging
import signal
from typing import Any

from interplay.api.queue.factory import conninfo
from interplay.settings import Settings

log = logging.getLogger(__name__)
TASK = "interplay.run_job"
QUEUE = "interplay"
SCHEMA_LOCK = 0x1A7E4E


def make_app(db_url: str, max_size: int = 4) -> Any:
    import procrastinate
    return procrastinate.App(connector=procrastinate.PsycopgConnector(
        conninfo=conninfo(db_url), min_size=1, max_size=max_size))


def ensure_schema(db_url: str) -> None:
    """Create procrastinate's tables once (the first process to start does it, under a lock)."""
    import procrastinate
    import psycopg
    with psycopg.connect(conninfo(db_url), autocommit=True) as conn:
        conn.execute("SELECT pg_advisory_lock(%s)", (SCHEMA_LOCK,))
        try:
            row = conn.execute("SELECT to_regclass('procrastinate_jobs')").fetchone()
            if row is None or row[0] is None:
                conn.execute(procrastinate.schema.SchemaManager.get_schema())
                log.info("created procrastinate's schema")
        finally:
            conn.execute("SELECT pg_advisory_unlock(%s)", (SCHEMA_LOCK,))


class Deferrer:
    """Defers `interplay.run_job(job_id)` (from a request's thread: procrastinate's sync API)."""

    def __init__(self, db_url: str):
        ensure_schema(db_url)
        self.app = make_app(db_url).open()
        self._task = self.app.configure_task(name=TASK, queue=QUEUE)

    def __call__(self, job_id: str) -> None:
        self._task.defer(job_id=job_id)

    def close(self) -> None:
        self.app.close()


def run_worker(settings: Settings, concurrency: int, generator=None) -> int:
    """`interplay worker`: load the generator once, then run jobs from the queue, `concurrency`
    at a time, until SIGTERM or SIGINT. Then it takes no new job, gives the running ones
    `settings.drain_s` seconds, and ends the rest with an error event ("the worker is shutting
    down"); queued jobs stay queued for the other workers."""
    from interplay.api.jobs import JobManager
    from interplay.api.queue.factory import build_generator, retention_of
    from interplay.api.queue.follow import Notifier
    from interplay.store import JobStore, MotionRepository, make_engine

    ensure_schema(settings.db_url)
    engine = make_engine(settings.db_url)
    repo = MotionRepository(engine, retention_of(settings))
    store = JobStore(engine)
    if generator is None:
        generator = build_generator(settings)
    manager = JobManager(store, repo, role="worker", workers=concurrency,
                         retention_s=settings.job_retention_s, generator=generator,
                         notifier=Notifier(store, None), stale_s=settings.job_stale_s,
                         max_attempts=settings.job_max_attempts)
    manager.start()
    app = make_app(settings.db_url, max_size=concurrency + 3)

    @app.task(name=TASK, queue=QUEUE)
    def run_job(job_id: str) -> None:
        manager.run_stored(job_id)

    async def main() -> None:
        loop = asyncio.get_running_loop()
        async with app.open_async():
            work = asyncio.create_task(app.run_worker_async(
                queues=[QUEUE], concurrency=concurrency, name=manager.name,
                install_signal_handlers=False, delete_jobs="successful",
                fetch_job_polling_interval=2.0, update_heartbeat_interval=2.0,
                stalled_worker_timeout=max(10.0, settings.job_stale_s),
                shutdown_graceful_timeout=settings.drain_s + 10.0))
            stopping = asyncio.Event()

            def stop() -> None:
                if not stopping.is_set():
                    log.info("stopping: no new jobs; %.0f s for the running ones",
                             settings.drain_s)
                    stopping.set()
                    manager.accepting = False
                    work.cancel()        # procrastinate stops fetching, waits for running jobs
                    loop.call_later(settings.drain_s, manager.stop_running,
                                    "the worker is shutting down")
            for sig in (signal.SIGTERM, signal.SIGINT):
                loop.add_signal_handler(sig, stop)
            cleaner = asyncio.create_task(_fail_stalled(app, settings.job_stale_s))
            try:
                await work
            except asyncio.CancelledError:
                pass
            finally:
                cleaner.cancel()

    try:
        asyncio.run(main())
    finally:
        manager.close()
        engine.dispose()
    return 0


async def _fail_stalled(app: Any, stale_s: float) -> None:
    """Procrastinate's own rows of jobs whose worker died (kill -9) stay `doing`: mark them
    failed (Interplay's job row is ended by the job reaper, with the reason)."""
    from procrastinate.jobs import Status
    while True:
        await asyncio.sleep(max(5.0, stale_s / 2))
        try:
            for job in await app.job_manager.get_stalled_jobs(
                    queue=QUEUE, seconds_since_heartbeat=max(10.0, stale_s)):
                await app.job_manager.finish_job(job, status=Status.FAILED, delete_job=False)
                log.warning("procrastinate job %s of a dead worker marked failed", job.id)
        except Exception:
            log.exception("could not check for stalled procrastinate jobs")
