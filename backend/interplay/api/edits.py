"""Editing a motion (one person, SPAM): the shared step of `POST /api/motions/{id}/edit` and
`interplay edit` — run the generator's edit and give back the new joints with their plan (the
parent's plan plus this edit appended to `plan["edits"]`), metrics and highlights.

Errors: ValueError for a bad request (the caller answers 422 / exit 2), EditUnavailable when
the generator cannot edit (503)."""

from __future__ import annotations

import numpy as np

from ..agents.spam_generator import EditUnavailable
from ..motion.metrics import clip_metrics
from ..store import MotionRepository, StoredMotion
from .jobs import _highlights_event
from .motion_json import plain


def edit_joints(generator, people: list[np.ndarray], plan: dict | None, prompt: str | None,
                part: str | None, edit_prompt: str, frames: list[int] | None,
                seed: int | None) -> tuple[np.ndarray, dict, dict, int]:
    """(joints (T, 22, 3) float32, plan, metrics, seed) of the edited motion."""
    if len(people) != 1:
        raise ValueError(f"edits work on one-person motions; this one has {len(people)} people")
    joints = np.asarray(people[0], dtype=np.float64)
    if frames is not None and not 0 <= frames[0] < frames[1] <= len(joints):
        raise ValueError(f"frames {frames} are outside the motion's 0 … {len(joints)} frames")
    if not hasattr(generator, "edit"):
        raise EditUnavailable("this generator cannot edit motions")
    edit, entry = generator.edit(joints, part, edit_prompt,
                                 tuple(frames) if frames is not None else None, seed,
                                 context=prompt or None)
    out = edit.joints.astype(np.float32)
    plan = dict(plan or {})
    plan["edits"] = list(plan.get("edits") or []) + [entry]
    metrics = plain(clip_metrics([out.astype(np.float64)]))
    return out, plan, metrics, entry["seed"]


def edit_stored(repo: MotionRepository, generator, parent: StoredMotion, part: str | None,
                prompt: str, frames: list[int] | None, seed: int | None) -> StoredMotion:
    """Edit a stored motion and store the result as a new motion whose parent is `parent`."""
    joints, plan, metrics, seed = edit_joints(generator, parent.people, parent.plan,
                                              parent.prompt, part, prompt, frames, seed)
    h = _highlights_event(0, [joints], 0, 1)
    highlights = {k: h[k] for k in ("contacts", "penetration", "min_distance")}
    return repo.create(prompt=parent.prompt, people=[joints], seconds=len(joints) / parent.fps,
                       seed=seed, plan=plain(plan), metrics=metrics, highlights=highlights,
                       parent_id=parent.id)
