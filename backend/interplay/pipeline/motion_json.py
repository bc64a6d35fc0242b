"""Motion JSON in and out: the wire/file form of a motion.

    {"fps": 20, "skeleton": "smpl22", "people": [{"joints": [[[x,y,z]×22]×T]}], "plan": …, "metrics": …}

Joints go out as float32 rounded to 0.1 mm, the same way for streamed frames and stored motions,
so a client can compare them exactly."""

from __future__ import annotations

import numpy as np

from interplay.motion.motion import Motion
from interplay.motion.skeleton import SKELETON_NAME
from interplay.store import StoredMotion

DECIMALS = 4


def plain(obj):
    """`obj` with numpy scalars/arrays turned into Python values and non-finite floats into
    None, so it is valid JSON (browsers reject NaN) and storable."""
    if isinstance(obj, dict):
        return {str(k): plain(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [plain(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return plain(obj.tolist())
    if isinstance(obj, (bool, np.bool_)):
        return bool(obj)
    if isinstance(obj, (int, np.integer)):
        return int(obj)
    if isinstance(obj, (float, np.floating)):
        return float(obj) if np.isfinite(obj) else None
    return obj


def joints_list(joints: np.ndarray) -> list:
    """(T, 22, 3) array → nested lists of floats (float32 precision, rounded to 0.1 mm)."""
    arr = np.asarray(joints, dtype=np.float32).astype(np.float64)
    return np.round(arr, DECIMALS).tolist()


def motion_file(m: StoredMotion) -> dict:
    """The Motion JSON of a stored motion as the JSON export downloads it: version 2, with the
    skeleton and each person's rig (`Motion.to_json(rig=True)`), whose head and wrists turn
    as the BVH and GLB exports' do (`pipeline.leaves.export_leaves`: the captures' own where
    the frames are a capture's, an edit's); reads back with `Motion.from_json`."""
    from interplay.pipeline.leaves import export_leaves
    motion = Motion(people=m.people, plan=m.plan or {}, metrics=m.metrics or {},
                    highlights=m.highlights, prompt=m.prompt, seed=m.seed)
    leaves = export_leaves(m.plan, len(motion.people), motion.frames)
    return {**motion.to_json(rig=True, rig_leaves=leaves), "id": m.id}


def motion_payload(m: StoredMotion) -> dict:
    """GET /api/motions/{id}: the Motion JSON plus the record's fields."""
    return {
        "id": m.id, "prompt": m.prompt, "persons": m.persons, "seconds": m.seconds,
        "seed": m.seed, "fps": m.fps, "skeleton": SKELETON_NAME,
        "people": [{"joints": joints_list(p)} for p in m.people],
        "plan": m.plan, "metrics": m.metrics, "highlights": m.highlights,
        "parent_id": m.parent_id, "edit": m.edit, "review": m.review,
        "created_at": m.created_at.isoformat() if m.created_at else None,
    }
