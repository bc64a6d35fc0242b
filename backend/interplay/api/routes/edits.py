"""POST /api/motions/{id}/edit: re-generate a body part (or frames) of a stored one-person
motion with SPAM; the result is a new stored motion whose `parent_id` is the original."""

from __future__ import annotations

import logging

from fastapi import APIRouter, HTTPException, Request

from interplay.api.deps import ClientDep, RepoDep
from interplay.api.deps import generator as loaded_generator
from interplay.api.schemas import ERRORS, EditCreate, MotionOut
from interplay.generators.base import EditUnavailable
from interplay.pipeline.editing import edit_stored
from interplay.pipeline.motion_json import motion_payload

log = logging.getLogger(__name__)
router = APIRouter(prefix="/api", tags=["motions"])


@router.post("/motions/{motion_id}/edit", status_code=201, response_model=MotionOut,
             responses={**ERRORS, 503: ERRORS[404]})
def edit_motion(motion_id: str, body: EditCreate, repo: RepoDep, request: Request,
                client: ClientDep) -> dict:
    """Edit `part` (left_arm, right_arm, left_leg, right_leg, whole_body or a model part) over
    `frames` [a, b) from `prompt`; everything else stays as it was. With `trajectory` the
    (edited) motion's person then follows the drawn path or preset (prompt optional)."""
    parent = repo.get(motion_id)
    if parent is None:
        raise HTTPException(404, f"no motion {motion_id!r} (unknown or malformed id)")
    # Looked up here, not as a dependency, so bad input and ids get their 422/404 even while
    # the generator is unavailable (503), as for jobs.
    generator = loaded_generator(request) if body.prompt is not None else None
    try:
        edited = edit_stored(repo, generator, parent, body.part, body.prompt, body.frames,
                             body.seed, body.trajectory.plain() if body.trajectory else None,
                             client_id=client)
    except ValueError as exc:
        raise HTTPException(422, str(exc)) from None
    except EditUnavailable as exc:
        raise HTTPException(503, str(exc)) from None
    except Exception as exc:  # a model failure is reported, never a bare 500
        log.exception("edit of motion %s failed", motion_id)
        raise HTTPException(503, f"the edit failed: {type(exc).__name__}: {exc}") from None
    return motion_payload(edited)
