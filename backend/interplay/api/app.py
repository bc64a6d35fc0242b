"""The FastAPI application: `create_app(settings=None, generator=None)`.

The lifespan opens the database (tables created if missing), loads the generator once (or takes
the one given, for tests) and starts the durable job queue (`api/jobs.py`). Every error is a 4xx JSON
`{"detail": "<readable message>"}`."""

from __future__ import annotations

import logging
from contextlib import asynccontextmanager

import anyio
from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse
from starlette.exceptions import HTTPException as StarletteHTTPException

from interplay import __version__
from interplay.api import security, stream
from interplay.api.queue.factory import retention_of
from interplay.api.queue.setup import open_jobs
from interplay.api.routes import actions, edits, jobs, library, motions, pages, rerun
from interplay.generators.base import Generator
from interplay.pipeline.requests import readable_errors
from interplay.settings import Settings, get_settings
from interplay.store import MotionRepository, make_engine

log = logging.getLogger(__name__)


def _load_generator(settings: Settings) -> Generator:
    from interplay.api.queue.factory import build_generator
    return build_generator(settings)


def create_app(settings: Settings | None = None, generator=None) -> FastAPI:
    settings = settings or get_settings()

    @asynccontextmanager
    async def lifespan(app: FastAPI):
        engine = make_engine(settings.db_url)
        app.state.repo = MotionRepository(engine, retention_of(settings))
        app.state.generator, app.state.generator_error = generator, None
        # With procrastinate (PostgreSQL) `interplay worker` processes load the generator.
        if generator is None and settings.queue == "embedded":
            try:  # ONNX sessions take a moment to build: off the event loop
                app.state.generator = await anyio.to_thread.run_sync(_load_generator, settings)
            except Exception as exc:  # serve stored motions anyway; POST /api/jobs answers 503
                log.exception("could not load the generator")
                app.state.generator_error = f"{type(exc).__name__}: {exc}"
        # Durable jobs: orphans of a dead process are ended (or taken over) before serving.
        app.state.jobs = await open_jobs(settings, app.state.repo, app.state.generator)
        try:
            yield
        finally:
            app.state.jobs.close()
            engine.dispose()

    app = FastAPI(title="Interplay", version=__version__, lifespan=lifespan,
                  description="Text to 3D human motion for one or two people. "
                              "See docs/api.md for the job event stream.")
    app.state.settings = settings

    @app.exception_handler(RequestValidationError)
    async def _validation(_req: Request, exc: RequestValidationError):
        return JSONResponse({"detail": readable_errors(exc.errors())}, status_code=422)

    @app.exception_handler(StarletteHTTPException)
    async def _http(req: Request, exc: StarletteHTTPException):
        if exc.status_code == 404 and pages.wants_page(req.url.path):
            return pages.not_found_page(req.url.path)     # a person's bad link: a page, not JSON
        detail = exc.detail if isinstance(exc.detail, str) else str(exc.detail)
        if exc.status_code == 404 and detail == "Not Found":
            detail = "not found"
        return JSONResponse({"detail": detail}, status_code=exc.status_code,
                            headers=getattr(exc, "headers", None))

    app.include_router(jobs.router)
    app.include_router(stream.router)
    app.include_router(motions.router)
    app.include_router(edits.router)
    app.include_router(rerun.router)
    app.include_router(library.router)
    app.include_router(actions.router)
    app.include_router(pages.router)  # last: it has a catch-all for top-level files
    security.install(app, settings)   # body limit, security headers, Retry-After on 429
    return app
