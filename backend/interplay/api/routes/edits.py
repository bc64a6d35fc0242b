"""POST /api/motions/{id}/edit: re-generate a body part (or frames) of a stored one-person
motion with SPAM; the result is a new stored motion whose `parent_id` is the original.

An edit is a job (`mode: "edit"`, `api/runners/edit.py`): admitted through the same queue and
limit as generation (429 with Retry-After when full) and run by the same worker threads or
worker processes, so at most that many heavy edits run at once. The request waits for it and
answers with the new motion."""

from __future__ import annotations

import anyio
from fastapi import APIRouter, HTTPException, Request

from interplay.api.deps import ClientDep, JobsDep, RepoDep
from interplay.api.deps import generator as loaded_generator
from interplay.api.jobs import JobManager, JobSpec, QueueFull, Unavailable, motion_missing
from interplay.api.schemas import ERRORS, EditCreate, MotionOut
from interplay.pipeline.motion_json import motion_payload
from interplay.store import MotionRepository, StoredMotion

router = APIRouter(prefix="/api", tags=["motions"])


@router.post("/motions/{motion_id}/edit", status_code=201, response_model=MotionOut,
             responses={**ERRORS, 409: ERRORS[404], 429: ERRORS[404], 503: ERRORS[404]})
async def edit_motion(motion_id: str, body: EditCreate, repo: RepoDep, jobs: JobsDep,
                      request: Request, client: ClientDep) -> dict:
    """Edit `part` (left_arm, right_arm, left_leg, right_leg, whole_body or a model part) over
    `frames` [a, b) from `prompt`; everything else stays as it was. With `trajectory` the
    (edited) motion's person then follows the drawn path or preset (prompt optional)."""
    if not await anyio.to_thread.run_sync(repo.exists, motion_id):
        raise await anyio.to_thread.run_sync(motion_missing, jobs.store, motion_id)
    # Looked up here, not as a dependency, so bad input and ids get their 422/404 even while
    # the generator is unavailable (503), as for jobs. Worker processes hold their own.
    generator = None
    if body.prompt is not None and jobs.role == "embedded":
        generator = loaded_generator(request)
    spec = JobSpec(mode="edit", prompt=body.prompt, persons=1, seconds=0.0, seed=body.seed,
                   trajectory=body.trajectory.plain() if body.trajectory else None,
                   parent_id=motion_id, part=body.part, frames=body.frames, client_id=client)
    return motion_payload(await run_to_motion(jobs, repo, spec, generator, "the edit"))


async def run_to_motion(jobs: JobManager, repo: MotionRepository, spec: JobSpec, generator,
                        what: str) -> StoredMotion:
    """Queue a job that makes one stored motion (an edit, a re-run), wait for it, and give the
    motion; the job's failure as an HTTPException with its status (429 + Retry-After when the
    queue is full)."""
    try:
        job = await anyio.to_thread.run_sync(jobs.submit, spec, generator)
    except QueueFull as exc:
        raise HTTPException(429, str(exc), headers={"Retry-After": str(exc.retry_after)}) from None
    except Unavailable as exc:
        raise HTTPException(503, str(exc)) from None
    end = await jobs.wait(job.id)
    if end is None or end.status != "done":
        status = int((end.result or {}).get("http_status", 503)) if end else 503
        raise HTTPException(status, (end.reason if end else None) or f"{what} failed")
    made = await anyio.to_thread.run_sync(repo.get, job.motion_id)
    if made is None:
        raise HTTPException(503, f"the motion of {what} was not stored")
    return made
