"""`interplay serve`: the studio (API + front end). The one command that builds the web app."""

from __future__ import annotations

from interplay.cli.args import CliError  # noqa: F401  (the commands' shared error)


def cmd_serve(args) -> int:
    import uvicorn

    from interplay.api.app import create_app
    from interplay.settings import get_settings
    settings = get_settings()
    host, port = args.host or settings.host, args.port if args.port is not None else settings.port
    uvicorn.run(create_app(settings.model_copy(update={"host": host, "port": port})),
                host=host, port=port, log_level="info")
    return 0


def register(sub) -> None:
    p = sub.add_parser("serve", help="run the studio (API + front end)")
    p.add_argument("--host", help="listen address (default INTERPLAY_HOST or 127.0.0.1)")
    p.add_argument("--port", type=int, help="port (default INTERPLAY_PORT or 8000)")
    p.set_defaults(func=cmd_serve)
