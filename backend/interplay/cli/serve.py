"""`interplay serve`: the studio (API + front end). The one command that builds the web app.

`--workers N` runs N API processes on one port (uvicorn's process supervisor; each builds the
app from the environment). Jobs are durable (docs/api.md), so a stream opened on any of them
follows a job run anywhere: by the worker threads of the process that took it (embedded queue),
or by `interplay worker` processes (procrastinate, with PostgreSQL)."""

from __future__ import annotations

import os

from interplay.cli.args import CliError


def cmd_serve(args) -> int:
    import uvicorn

    from interplay.api.app import create_app
    from interplay.settings import get_settings
    settings = get_settings()
    host, port = args.host or settings.host, args.port if args.port is not None else settings.port
    workers = args.workers
    if workers < 1:
        raise CliError("--workers must be at least 1")
    if workers == 1:
        uvicorn.run(create_app(settings.model_copy(update={"host": host, "port": port})),
                    host=host, port=port, log_level="info")
        return 0
    # Every process reads the same settings from the environment.
    os.environ["INTERPLAY_HOST"], os.environ["INTERPLAY_PORT"] = host, str(port)
    get_settings.cache_clear()
    uvicorn.run("interplay.api.app:create_app", factory=True, host=host, port=port,
                workers=workers, log_level="info")
    return 0


def register(sub) -> None:
    p = sub.add_parser("serve", help="run the studio (API + front end)")
    p.add_argument("--host", help="listen address (default INTERPLAY_HOST or 127.0.0.1)")
    p.add_argument("--port", type=int, help="port (default INTERPLAY_PORT or 8000)")
    p.add_argument("--workers", type=int, default=1, help="API processes (default 1); with "
                   "PostgreSQL run `interplay worker` processes for the jobs")
    p.set_defaults(func=cmd_serve)
