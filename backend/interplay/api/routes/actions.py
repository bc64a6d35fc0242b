"""GET /api/actions: what the studio knows how to make (the catalogue), for the prompt box's
suggestions and for anyone asking; `kind` filters (whole, travel, part, gesture, pose, manner,
move, interaction)."""

from __future__ import annotations

from typing import Annotated, Literal

from fastapi import APIRouter, Query

from interplay.catalogue.listing import rows

router = APIRouter(prefix="/api", tags=["catalogue"])
KindName = Literal["whole", "travel", "part", "gesture", "pose", "manner", "move", "interaction"]


@router.get("/actions")
def actions(kind: Annotated[list[KindName] | None, Query(description="Only these kinds.")] = None
            ) -> dict:
    """Every action, gesture, pose and manner of the catalogue: its name, the words that ask
    for it, what it is made from, the checks that confirm it and examples."""
    out = rows(tuple(kind or ()))
    return {"count": len(out), "actions": out}
