"""POST /api/motions/{id}/segments/{index}/rerun: generate one planned segment of a stored
motion again with a new seed, in place (`pipeline/rerun.py`): the other segments' frames stay
exactly, the new one is blended in at its borders, and the result is a new stored version
whose `parent_id` is the original.

A re-run is a job (`mode: "rerun"`, `api/runners/edit.py`), admitted through the same queue
and limit as generation and edits (429 with Retry-After when full); the request waits for it
and answers with the new motion."""

from __future__ import annotations

from typing import Annotated

import anyio
from fastapi import APIRouter, Body, HTTPException, Path, Request

from interplay.api.deps import ClientDep, JobsDep, RepoDep
from interplay.api.deps import generator as loaded_generator
from interplay.api.jobs import JobSpec, motion_missing
from interplay.api.routes.edits import run_to_motion
from interplay.api.schemas import ERRORS, MotionOut, SegmentRerun
from interplay.generators.base import random_seed
from interplay.pipeline.motion_json import motion_payload
from interplay.pipeline.rerun import segment_span

router = APIRouter(prefix="/api", tags=["motions"])


@router.post("/motions/{motion_id}/segments/{index}/rerun", status_code=201,
             response_model=MotionOut,
             responses={**ERRORS, 409: ERRORS[404], 429: ERRORS[404], 503: ERRORS[404]})
async def rerun_segment(motion_id: str, index: Annotated[int, Path(ge=0, le=99)], repo: RepoDep,
                        jobs: JobsDep, request: Request, client: ClientDep,
                        body: Annotated[SegmentRerun | None, Body()] = None) -> dict:
    """Re-generate plan segment `index` (from 0) with `seed` (random when omitted): frames
    outside it are kept exactly, the motion keeps its length, the new version is answered."""
    parent = await anyio.to_thread.run_sync(repo.get, motion_id)
    if parent is None:
        raise await anyio.to_thread.run_sync(motion_missing, jobs.store, motion_id)
    try:
        segment_span(parent.plan, index, parent.frames)
    except ValueError as exc:
        raise HTTPException(422, str(exc)) from None
    # Looked up after the checks, so bad ids and indices get their 404/422 even while the
    # generator is unavailable (503), as for jobs and edits. Worker processes hold their own.
    generator = loaded_generator(request) if jobs.role == "embedded" else None
    seed = body.seed if body is not None and body.seed is not None else random_seed()
    spec = JobSpec(mode="rerun", prompt=None, persons=parent.persons, seconds=0.0, seed=seed,
                   parent_id=motion_id, segment=index, client_id=client)
    return motion_payload(await run_to_motion(jobs, repo, spec, generator, "the re-run"))
