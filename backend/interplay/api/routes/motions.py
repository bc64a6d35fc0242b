"""Stored motions: GET /api/motions/{id} (with its frames' digests), its export (BVH per
person, GLB or Motion JSON), and the skeleton description the viewer draws with."""

from __future__ import annotations

import json
from enum import IntEnum
from typing import Annotated, Literal

from fastapi import APIRouter, HTTPException, Query, Response

from interplay.api.deps import RepoDep
from interplay.api.digest import frame_digests, motion_digest
from interplay.api.filenames import content_disposition, export_name
from interplay.api.jobs import motion_missing
from interplay.api.schemas import ERRORS, History, MotionOut, SkeletonOut
from interplay.motion import skeleton as sk
from interplay.pipeline.motion_json import motion_file, motion_payload
from interplay.store import StoredMotion

router = APIRouter(prefix="/api", tags=["motions"])


class BvhFps(IntEnum):
    """The BVH and GLB exports' frame rates (`bvh.FPS_CHOICES`); an enum, as a query string "24"
    validates into it (a Literal of ints takes no strings)."""
    FPS_20 = 20
    FPS_24 = 24
    FPS_30 = 30
    FPS_60 = 60


def _load(repo, motion_id: str) -> StoredMotion:
    motion = repo.get(motion_id)
    if motion is None:   # unknown, not made yet, its job failed (409), or deleted
        raise motion_missing(repo, motion_id)
    return motion


@router.get("/motions/{motion_id}", response_model=MotionOut, responses={**ERRORS, 409: ERRORS[404]})
def get_motion(motion_id: str, repo: RepoDep) -> dict:
    """The stored motion, with the digests its job's `done` event carried (computed again from
    the stored frames, which are the ones `done` hashed)."""
    motion = _load(repo, motion_id)
    digests = frame_digests(motion.people)
    return {**motion_payload(motion), "digest": motion_digest(digests), "frame_digests": digests}


@router.get("/motions/{motion_id}/history", response_model=History, responses=ERRORS)
def motion_history(motion_id: str, repo: RepoDep) -> dict:
    """The versions from the root (a generated motion) to this one, following parent_id:
    each with what made it (`edit`), for undo/redo and the share page."""
    chain = repo.lineage(motion_id)
    if not chain:
        raise motion_missing(repo, motion_id)
    return {"versions": [{"id": v.id, "parent_id": v.parent_id, "prompt": v.prompt,
                          "created_at": v.created_at.isoformat() if v.created_at else None,
                          "edit": v.edit} for v in chain]}


@router.get("/motions/{motion_id}/export", responses={
    **ERRORS, 200: {"content": {"text/plain": {}, "application/json": {}, "model/gltf-binary": {}},
                    "description": "A BVH file (one person), a GLB (everyone) or the Motion JSON, "
                                   "as a download."}})
def export_motion(motion_id: str, repo: RepoDep,
                  format: Annotated[Literal["bvh", "glb", "json"],
                                    Query(description="bvh, glb or json")] = "json",
                  person: Annotated[int, Query(ge=0, le=1, description="BVH: which person")] = 0,
                  mesh: Annotated[bool, Query(description="GLB: with the skinned mesh (false: "
                                                          "skeletons and animation only)")] = True,
                  fps: Annotated[BvhFps, Query(
                      description="BVH and GLB: frames per second (resampled keeping the last "
                                  "pose; the motion is 20)")] = BvhFps.FPS_20,
                  units: Annotated[Literal["m", "cm"], Query(description="BVH and GLB: m or cm")] = "m",
                  up: Annotated[Literal["y", "z"], Query(
                      description="BVH: up axis, y or z (z: facing -Y, as in Blender)")] = "y",
                  names: Annotated[Literal["smpl", "mixamo"], Query(
                      description="BVH and GLB: joint names, smpl or mixamo (mixamorig:Hips, "
                                  "mixamorig:LeftUpLeg, …; in the GLB with Mixamo's bone axes "
                                  "and end bones)")] = "smpl",
                  ) -> Response:
    motion = _load(repo, motion_id)
    if format == "glb":
        from interplay.motion.formats.gltf import MEDIA_TYPE, write_glb
        from interplay.pipeline.leaves import export_leaves
        data = write_glb([p.astype("float64") for p in motion.people], fps=motion.fps, mesh=mesh,
                         name=motion.prompt or "motion", out_fps=int(fps), units=units, names=names,
                         leaves=export_leaves(motion.plan, motion.persons, motion.frames))
        name = export_name(motion.id, motion.prompt, "glb", "" if mesh else "-skeleton")
        return Response(data, media_type=MEDIA_TYPE,
                        headers={"Content-Disposition": content_disposition(name)})
    if format == "json":
        body = json.dumps(motion_file(motion), separators=(",", ":"))
        name = export_name(motion.id, motion.prompt, "json")
        return Response(body, media_type="application/json",
                        headers={"Content-Disposition": content_disposition(name)})
    if person >= motion.persons:
        raise HTTPException(422, f"person {person} does not exist: this motion has "
                                 f"{motion.persons} person(s), numbered from 0")
    from interplay.motion.formats.bvh import write_bvh
    from interplay.motion.kinematics import floor_height
    people = [p.astype("float64") for p in motion.people]
    from interplay.pipeline.leaves import export_leaves
    text = write_bvh(people[person], fps=motion.fps, out_fps=int(fps), units=units, up=up, names=names,
                     floor=floor_height(people),
                     leaves=export_leaves(motion.plan, motion.persons, motion.frames)[person])
    # the file names people as the studio does: person=0 is Person 1, "…-person1.bvh"
    name = export_name(motion.id, motion.prompt, "bvh", f"-person{person + 1}")
    return Response(text, media_type="text/plain; charset=utf-8",
                    headers={"Content-Disposition": content_disposition(name)})


@router.get("/skeleton", response_model=SkeletonOut)
def skeleton() -> SkeletonOut:
    """Joint names and parents, the four CoMA body parts (joint indices), each joint's colour
    part, the part colours, and the rest pose."""
    return SkeletonOut(
        joints=list(sk.JOINT_NAMES), parents=list(sk.PARENTS),
        parts={p: [int(j) for j in idx] for p, idx in sk.PART_JOINTS.items()},
        joint_part=list(sk.JOINT_PART), colours=dict(sk.PART_COLOURS),
        rest=sk.rest_joints().round(4).tolist(), fps=sk.FPS)
