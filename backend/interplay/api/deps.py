"""FastAPI dependencies as `Annotated` aliases; everything lives on `app.state` (set in the
lifespan), so tests can override any of them with `app.dependency_overrides`."""

from __future__ import annotations

from typing import Annotated

from fastapi import Depends, HTTPException, Request

from interplay.api.jobs import JobManager
from interplay.generators.base import Generator
from interplay.settings import Settings
from interplay.store import MotionRepository


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


SettingsDep = Annotated[Settings, Depends(app_settings)]
RepoDep = Annotated[MotionRepository, Depends(repository)]
JobsDep = Annotated[JobManager, Depends(job_manager)]
GeneratorDep = Annotated[Generator, Depends(generator)]
