"""POST /api/motions/{id}/segments/{index}/rerun: generate one planned segment of a stored
motion again with a new seed, in place (`pipeline/rerun.py`): the other segments' frames stay
exactly, the new one is blended in at its borders, and the result is a new stored version
whose `parent_id` is the original."""

from __future__ import annotations

import logging
from typing import Annotated

from fastapi import APIRouter, Body, HTTPException, Path, Request

from interplay.api.deps import ClientDep, RepoDep
from interplay.api.deps import generator as loaded_generator
from interplay.api.schemas import ERRORS, MotionOut, SegmentRerun
from interplay.generators.base import random_seed
from interplay.pipeline.motion_json import motion_payload
from interplay.pipeline.rerun import rerun_stored, segment_span

log = logging.getLogger(__name__)
router = APIRouter(prefix="/api", tags=["motions"])


@router.post("/motions/{motion_id}/segments/{index}/rerun", status_code=201,
             response_model=MotionOut, responses={**ERRORS, 503: ERRORS[404]})
def rerun_segment(motion_id: str, index: Annotated[int, Path(ge=0, le=99)], repo: RepoDep,
                  request: Request, client: ClientDep,
                  body: Annotated[SegmentRerun | None, Body()] = None) -> dict:
    """Re-generate plan segment `index` (from 0) with `seed` (random when omitted): frames
    outside it are kept exactly, the motion keeps its length, the new version is answered."""
    parent = repo.get(motion_id)
    if parent is None:
        raise HTTPException(404, f"no motion {motion_id!r} (unknown or malformed id)")
    try:
        segment_span(parent.plan, index, parent.frames)
    except ValueError as exc:
        raise HTTPException(422, str(exc)) from None
    # Looked up after the checks, so bad ids and indices get their 404/422 even while the
    # generator is unavailable (503), as for jobs and edits.
    generator = loaded_generator(request)
    seed = body.seed if body is not None and body.seed is not None else random_seed()
    try:
        made = rerun_stored(repo, generator, parent, index, seed, client_id=client)
    except Exception as exc:  # a model failure is reported, never a bare 500
        log.exception("re-run of segment %s of motion %s failed", index, motion_id)
        raise HTTPException(503, f"the re-run failed: {type(exc).__name__}: {exc}") from None
    return motion_payload(made)
