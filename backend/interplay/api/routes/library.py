"""GET /api/motions?client=<id>[&limit=n&after=<id>]: the motions one browser made ("My motions"
in the studio), newest first, a page at a time. There is no listing without a client id: motion
ids stay unguessable, and a client id (random, kept by the browser, never sent back with a
motion) lists only its own."""

from __future__ import annotations

from typing import Annotated

from fastapi import APIRouter, HTTPException, Query

from interplay.api.deps import RepoDep
from interplay.api.schemas import ERRORS, MotionList
from interplay.pipeline.motion_json import joints_list
from interplay.store.models import ID_PATTERN

MAX_LIST = 50
router = APIRouter(prefix="/api", tags=["motions"])


@router.get("/motions", response_model=MotionList, responses=ERRORS)
def my_motions(repo: RepoDep,
               client: Annotated[str, Query(pattern=ID_PATTERN, description="The browser's "
                                            "client id (the X-Interplay-Client it sends).")],
               limit: Annotated[int, Query(ge=1, le=MAX_LIST, description="At most this many "
                                           f"(1–{MAX_LIST}).")] = 20,
               after: Annotated[str | None, Query(description="The next page: the `next` of the "
                                                  "page before (a motion id).")] = None) -> dict:
    """The motions made with this client id (generated, edited, re-run), newest first, each
    with its prompt, length, people and first frame; a page at a time: `next` is the cursor
    of the following page (null on the last) and `total` how many there are in all."""
    page = repo.for_client(client, limit + 1, after)
    if page is None:
        raise HTTPException(422, f"after: {after!r} is not one of this client's motions "
                                 "(deleted, or from another client); start from the first page")
    more = len(page) > limit
    page = page[:limit]
    return {"motions": [
        {"id": m.id, "prompt": m.prompt, "persons": m.persons, "seconds": m.seconds,
         "frames": m.frames, "created_at": m.created_at.isoformat() if m.created_at else None,
         "parent_id": m.parent_id, "edit": m.edit,
         "first_frame": [joints_list(f[None])[0] for f in (m.first_frame or [])]}
        for m in page],
        "next": page[-1].id if more else None,
        "total": repo.count_for_client(client)}
