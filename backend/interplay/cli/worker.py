"""`interplay worker`: run jobs from the PostgreSQL queue (procrastinate), `--concurrency` at a
time, until SIGTERM/SIGINT (then no new jobs, `INTERPLAY_DRAIN_S` for the running ones, an
error event for the rest). Needs DATABASE_URL=postgresql://… and the [postgres] extra; start
as many as the machine has cores for (each loads the generator once)."""

from __future__ import annotations

import logging

from interplay.cli.args import CliError


def cmd_worker(args) -> int:
    from interplay.settings import get_settings
    settings = get_settings()
    if not settings.db_url.startswith("postgresql"):
        raise CliError("interplay worker needs DATABASE_URL=postgresql://…: with SQLite, "
                       "`interplay serve` runs the jobs itself")
    concurrency = args.concurrency if args.concurrency is not None else settings.job_workers
    if concurrency < 1:
        raise CliError("--concurrency must be at least 1")
    logging.basicConfig(level=logging.INFO, format="%(asctime)s %(levelname)s %(name)s: %(message)s")
    try:
        import procrastinate  # noqa: F401
    except ImportError:
        raise CliError("interplay worker needs procrastinate: pip install -e '.[postgres]'") from None
    from interplay.api.queue.engine import run_worker
    return run_worker(settings, concurrency)


def register(sub) -> None:
    p = sub.add_parser("worker", help="run jobs from the PostgreSQL queue (scale-out)")
    p.add_argument("--concurrency", type=int, help="jobs at once (default INTERPLAY_JOB_WORKERS, 1)")
    p.set_defaults(func=cmd_worker)
