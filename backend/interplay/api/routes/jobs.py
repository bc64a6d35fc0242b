"""POST /api/jobs (start a generation), GET /api/jobs/{id} (its status), DELETE /api/jobs/{id}
(cancel it), GET /api/jobs?client=<id> (a browser's generations that made no motion yet). Jobs are durable (`api/jobs.py`): admitted by the database (429 with Retry-After
when full), run by this process's worker threads or by `interplay worker` processes."""

from __future__ import annotations

from typing import Annotated

from fastapi import APIRouter, HTTPException, Query, Request
from pydantic import BaseModel, Field

from interplay.api.deps import ClientDep, JobsDep, RepoDep
from interplay.api.deps import generator as loaded_generator
from interplay.api.jobs import JobSpec, QueueFull, Unavailable
from interplay.api.schemas import ERRORS, JobCancelled, JobCreate, JobCreated, JobStatus
from interplay.generators.base import random_seed
from interplay.store.models import ID_PATTERN

router = APIRouter(prefix="/api/jobs", tags=["jobs"])


def stream_path(job_id: str) -> str:
    return f"/api/jobs/{job_id}/stream"


@router.post("", status_code=201, response_model=JobCreated,
             responses={**ERRORS, 429: ERRORS[404], 503: ERRORS[404]})
def create_job(body: JobCreate, jobs: JobsDep, repo: RepoDep, request: Request,
               client: ClientDep) -> JobCreated:
    """Start generating; follow the WebSocket at `stream` for plan, segment, frames,
    highlights, review, correction, metrics and done events. The motion is stored under
    `motion_id` when done. `trajectory` makes a person follow a drawn path or preset shape;
    `mode: react` generates a reactor to the stored motion `actor_motion_id`. With the
    `X-Interplay-Client` header the motion is listed in that browser's GET /api/motions."""
    if body.mode == "react":
        assert body.actor_motion_id is not None     # JobCreate: mode react needs one
        if not repo.exists(body.actor_motion_id):
            raise HTTPException(404, f"no motion {body.actor_motion_id!r} to react to")
    # Looked up here, not as a dependency: dependencies run before the body is validated, and
    # bad input must get its 422 even while the generator is unavailable (503).
    # With procrastinate the worker processes hold the generator, not this one.
    generator = loaded_generator(request) if jobs.role == "embedded" else None
    seed = body.seed if body.seed is not None else random_seed()
    spec = JobSpec(prompt=body.prompt, persons=body.persons, seconds=body.seconds, seed=seed,
                   trajectory=body.trajectory.plain() if body.trajectory else None,
                   mode=body.mode, actor_motion_id=body.actor_motion_id, client_id=client)
    try:
        job = jobs.submit(spec, generator)
    except QueueFull as exc:
        raise HTTPException(429, str(exc), headers={"Retry-After": str(exc.retry_after)}) from None
    except Unavailable as exc:
        raise HTTPException(503, str(exc)) from None
    return JobCreated(job_id=job.id, motion_id=job.motion_id, stream=stream_path(job.id), seed=seed)


class ClientJob(BaseModel):
    job_id: str
    motion_id: str
    status: str
    reason: str | None
    attempts: int
    mode: str
    prompt: str | None
    persons: int
    seconds: float
    created_at: str | None
    stream: str
    request: dict = Field(description="The body to POST /api/jobs again (Retry).")


class ClientJobs(BaseModel):
    jobs: list[ClientJob]


def _retry_body(spec: dict) -> dict:
    if spec.get("mode") == "react":
        return {k: v for k, v in {"mode": "react", "actor_motion_id": spec.get("actor_motion_id"),
                                  "prompt": spec.get("prompt"), "seed": spec.get("seed")}.items()
                if v is not None}
    body = {k: spec.get(k) for k in ("prompt", "persons", "seconds", "seed", "trajectory")}
    return {k: v for k, v in body.items() if v is not None}


@router.get("", response_model=ClientJobs, responses=ERRORS)
def my_jobs(jobs: JobsDep,
            client: Annotated[str, Query(pattern=ID_PATTERN, description="The browser's client "
                                         "id (the X-Interplay-Client it sends).")],
            limit: Annotated[int, Query(ge=1, le=50)] = 20) -> ClientJobs:
    """This browser's generations that made no motion (yet): queued, running, failed or
    cancelled, newest first, each with the request to send again (My motions' Retry)."""
    return ClientJobs(jobs=[ClientJob(
        job_id=r.id, motion_id=r.motion_id, status=r.state, reason=r.reason, attempts=r.attempts,
        mode=r.spec.get("mode") or r.kind, prompt=r.spec.get("prompt"),
        persons=int(r.spec.get("persons") or 1), seconds=float(r.spec.get("seconds") or 0),
        created_at=r.created_at.isoformat() if r.created_at else None,
        stream=stream_path(r.id), request=_retry_body(r.spec))
        for r in jobs.store.for_client(client, limit)])


@router.get("/{job_id}", response_model=JobStatus, responses=ERRORS)
def job_status(job_id: str, jobs: JobsDep) -> JobStatus:
    """queued → running → done | failed | cancelled, with the reason a failed or cancelled
    job ended (e.g. its worker process stopped) and how many times a worker started it."""
    job = jobs.status(job_id)
    if job is None:
        raise HTTPException(404, f"no job {job_id!r} (unknown, malformed or expired)")
    return JobStatus(job_id=job.id, motion_id=job.motion_id, status=job.status,  # type: ignore[arg-type]
                     events=job.events, stream=stream_path(job.id), reason=job.reason,
                     attempts=job.attempts)


@router.delete("/{job_id}", response_model=JobCancelled, responses=ERRORS)
def cancel_job(job_id: str, jobs: JobsDep) -> JobCancelled:
    """Cancel a queued or running job: its stream ends with
    {"type": "error", "message": "cancelled", "cancelled": true}. A finished job is left as
    it is (cancelled: false)."""
    job = jobs.cancel(job_id)
    if job is None:
        raise HTTPException(404, f"no job {job_id!r} (unknown, malformed or expired)")
    return JobCancelled(job_id=job.id, status=job.status, cancelled=job.cancel_requested)
