"""Editing a motion (one person, SPAM): the shared step of `POST /api/motions/{id}/edit` and
`interplay edit` — run the generator's edit and give back the new joints with their plan (the
parent's plan plus this edit appended to `plan["edits"]`), metrics and highlights.

A trajectory-only edit (a drawn path or preset for one person) needs no model.

An edit that gives the export explicit leaf rotations (a head edit's head turns, under its
entry's "leaves") stores them in the plan, plan["leaves"] (one object per person, read by
`motion.leaves_in`), over the parent's, which are kept only while the edit left the trunk,
neck and head where they were (the rotations are the head's on the neck).

Errors: ValueError for a bad request (the caller answers 422 / exit 2), EditUnavailable when
the generator cannot edit (503)."""

from __future__ import annotations

import numpy as np

from interplay.generators.base import Editor, EditUnavailable
from interplay.motion import skeleton as sk
from interplay.motion.metrics import clip_metrics
from interplay.motion.motion import leaves_in
from interplay.pipeline.highlights import highlight_lists
from interplay.pipeline.motion_json import plain
from interplay.store import MotionRepository, StoredMotion

# The joints whose rotations the leaves' rotations are relative to (the head's on the neck,
# its twist from the chest): a parent's leaves are kept while an edit leaves them in place.
_CARRIERS = [sk.JOINT_INDEX[n] for n in ("spine3", "neck", "head", "left_collar", "right_collar",
                                         "left_elbow", "right_elbow", "left_wrist", "right_wrist")]


def edit_joints(generator, people: list[np.ndarray], plan: dict | None, prompt: str | None,
                part: str | None, edit_prompt: str, frames: list[int] | None,
                seed: int | None) -> tuple[np.ndarray, dict, dict, int]:
    """(joints (T, 22, 3) float32, plan, metrics, seed) of the edited motion."""
    if len(people) != 1:
        raise ValueError(f"edits work on one-person motions; this one has {len(people)} people")
    joints = np.asarray(people[0], dtype=np.float64)
    if frames is not None and not 0 <= frames[0] < frames[1] <= len(joints):
        raise ValueError(f"frames {frames} are outside the motion's 0 … {len(joints)} frames")
    if not isinstance(generator, Editor):
        raise EditUnavailable("this generator cannot edit motions")
    edit, entry = generator.edit(joints, part, edit_prompt,
                                 (frames[0], frames[1]) if frames is not None else None, seed,
                                 context=prompt or None)
    out = edit.joints.astype(np.float32)
    given = entry.pop("leaves", None) or {}
    plan = dict(plan or {})
    plan["edits"] = list(plan.get("edits") or []) + [entry]
    parent = leaves_in(plan, 1, len(joints))[0]
    plan.pop("leaves", None)
    same = len(out) == len(joints) and np.abs(out[:, _CARRIERS] - joints[:, _CARRIERS]).max() < 1e-3
    leaves = {**(parent if same else {}), **{k: np.asarray(v) for k, v in given.items()}}
    if leaves:
        plan["leaves"] = [{k: np.round(v, 6).tolist() for k, v in leaves.items()}]
    metrics = plain(clip_metrics([out.astype(np.float64)]))
    return out, plan, metrics, entry["seed"]


def follow_path(people: list[np.ndarray], trajectory: dict) -> list[np.ndarray]:
    """`people` with person `trajectory["person"]` walking the drawn points (world, metres) or
    the preset shape (placed at the person's start, facing as they do)."""
    from interplay.pipeline.orchestrator import DRAWN_PATH
    from interplay.trajectory.apply import apply_trajectory
    person = int(trajectory.get("person", 0))
    if not 0 <= person < len(people):
        raise ValueError(f"trajectory person {person} does not exist: this motion has "
                         f"{len(people)} person(s)")
    joints = np.asarray(people[person], dtype=np.float64)
    if trajectory.get("points") is not None:
        moved = apply_trajectory(joints, np.asarray(trajectory["points"], dtype=np.float64),
                                 cfg=DRAWN_PATH)
    else:
        moved = apply_trajectory(joints, {k: v for k, v in trajectory.items() if k != "person"})
    out = [np.asarray(p, dtype=np.float32) for p in people]
    out[person] = moved.astype(np.float32)
    return out


def edit_stored(repo: MotionRepository, generator, parent: StoredMotion, part: str | None,
                prompt: str | None, frames: list[int] | None, seed: int | None,
                trajectory: dict | None = None, id: str | None = None,
                client_id: str | None = None) -> StoredMotion:
    """Edit a stored motion (a part/frames from `prompt`, then a path if `trajectory`) and
    store the result as a new motion (under `id` when given: an edit job hands it out) whose
    parent is `parent`, with `edit` saying what made it ({part, prompt, frames, trajectory}),
    listed as made by `client_id` (a browser's "My motions") when given."""
    if prompt is None and trajectory is None:
        raise ValueError("an edit needs a prompt, a trajectory or both")
    people = [np.asarray(p, np.float32) for p in parent.people]
    plan, seed_out = parent.plan, parent.seed
    if prompt is not None:
        joints, plan, _, seed_out = edit_joints(generator, parent.people, parent.plan,
                                                parent.prompt, part, prompt, frames, seed)
        people = [joints]
    if trajectory is not None:
        people = follow_path(people, trajectory)
        plan = dict(plan or {})
        plan["edits"] = list(plan.get("edits") or []) + [{"trajectory": trajectory}]
    metrics = plain(clip_metrics([p.astype(np.float64) for p in people]))
    highlights = highlight_lists(people, 0, len(people))
    edit = {"part": part if prompt is not None else None, "prompt": prompt,
            "frames": list(frames) if prompt is not None and frames is not None else None,
            "trajectory": trajectory}
    return repo.create(prompt=parent.prompt, people=people, seconds=len(people[0]) / parent.fps,
                       seed=seed_out, plan=plain(plan), metrics=metrics, highlights=highlights,
                       parent_id=parent.id, edit=plain(edit), id=id, client_id=client_id)
