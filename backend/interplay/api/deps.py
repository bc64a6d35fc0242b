"""FastAPI dependencies as `Annotated` aliases; everything lives on `app.state` (set in the
lifespan), so tests can override any of them with `app.dependency_overrides`."""

from __future__ import annotations

from typing import Annotated

from fastapi import Depends, Header, HTTPException, Request

from interplay.api.jobs import JobManager
from interplay.generators.base import Generator
from interplay.settings import Settings
from interplay.store import MotionRepository, valid_id

CLIENT_HEADER = "X-Interplay-Client"


def app_settings(request: Request) -> Settings:
    return request.app.state.settings


def repository(request: Request) -> MotionRepository:
    return request.app.state.repo


def job_manager(request: Request) -> JobManager:
    return request.app.state.jobs


def generator(request: Request) -> Generator:
    gen = getattr(request.app.state, "generator", None)
    if gen is None:
        reason = getattr(request.app.state, "generator_error", None) or "not loaded"
        raise HTTPException(503, f"the motion generator is unavailable: {reason}")
    return gen


def client_id(x_interplay_client: Annotated[str | None, Header(
        description="This browser's random id (22–64 URL-safe characters): what it makes is "
                    "listed by GET /api/motions?client=<id>.")] = None) -> str | None:
    """The studio's per-browser id sent with jobs and edits, or None; malformed → 422."""
    if x_interplay_client is None or x_interplay_client == "":
        return None
    if not valid_id(x_interplay_client):
        raise HTTPException(422, f"{CLIENT_HEADER}: must be 22–64 characters of A–Z, a–z, "
                                 "0–9, '_' or '-'")
    return x_interplay_client


SettingsDep = Annotated[Settings, Depends(app_settings)]
RepoDep = Annotated[MotionRepository, Depends(repository)]
JobsDep = Annotated[JobManager, Depends(job_manager)]
GeneratorDep = Annotated[Generator, Depends(generator)]
ClientDep = Annotated[str | None, Depends(client_id)]
