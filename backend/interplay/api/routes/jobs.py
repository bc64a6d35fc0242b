"""POST /api/jobs (start a generation), GET /api/jobs/{id} (its status)."""

from __future__ import annotations

from fastapi import APIRouter, HTTPException, Request

from ..deps import JobsDep, generator as loaded_generator
from ..jobs import JobSpec, random_seed
from ..schemas import ERRORS, JobCreate, JobCreated, JobStatus

router = APIRouter(prefix="/api/jobs", tags=["jobs"])


def stream_path(job_id: str) -> str:
    return f"/api/jobs/{job_id}/stream"


@router.post("", status_code=201, response_model=JobCreated,
             responses={**ERRORS, 429: ERRORS[404], 503: ERRORS[404]})
def create_job(body: JobCreate, jobs: JobsDep, request: Request) -> JobCreated:
    """Start generating; follow the WebSocket at `stream` for plan, frames, highlights,
    metrics and done events. The motion is stored under `motion_id` when done."""
    # Looked up here, not as a dependency: dependencies run before the body is validated, and
    # bad input must get its 422 even while the generator is unavailable (503).
    generator = loaded_generator(request)
    seed = body.seed if body.seed is not None else random_seed()
    spec = JobSpec(prompt=body.prompt, persons=body.persons, seconds=body.seconds, seed=seed)
    try:
        job = jobs.submit(spec, generator)
    except OverflowError as exc:
        raise HTTPException(429, str(exc)) from None
    return JobCreated(job_id=job.id, motion_id=job.motion_id, stream=stream_path(job.id), seed=seed)


@router.get("/{job_id}", response_model=JobStatus, responses=ERRORS)
def job_status(job_id: str, jobs: JobsDep) -> JobStatus:
    job = jobs.get(job_id)
    if job is None:
        raise HTTPException(404, f"no job {job_id!r} (unknown, malformed or expired)")
    return JobStatus(job_id=job.id, motion_id=job.motion_id, status=job.status,
                     events=job.event_count, stream=stream_path(job.id))
