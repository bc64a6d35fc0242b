"""The captures' own head and hand turns in a retrieve-then-edit motion (issue 27), read back
from its plan at export time (the plan is all an export has; `RetrieveEditGenerator.frames`
is replayed on the leaves, not on the joints):

- frames a captured piece gives keep the capture's leaves (`captured_leaves.piece_leaves`:
  the same pieces retrieval's stream lays, cross-faded at each join as its joints are);
- a segment a primitive makes (`primitive_steps.lay`, and its EASE frames after it): every
  leaf derived, the primitive's own (a nod turns the head with the neck, `rig/leaves.py`);
- a held pose (`holds`: the stand low-passed, a squat frozen, a leg lifted over a calm
  stand): every leaf derived over the segment (the captured hands would still fidget);
- the slowed last segment (`pace`): its leaves played at the same rate (slerp), the rate
  measured as `pace.rate_of` measures it, on the segment's pieces as the stitcher plays them;
- an arm action (`arm_poses`: a pose held, a wave): that arm's wrist derived wherever the IK
  weighs in (a wave's hand trails its forearm); the head and the other hand stay captured;
- high knees: the lifted legs' toes derived (should captured toes be exported: today the
  exports leave every toe to the rig, `captured_leaves.EXPORTED`), every other leaf kept.

Derived frames are rows of NaN; the rig turns its derived leaves into the captured ones over
LEAF_BLEND frames at each end (`rig.leaves._given`), so an edit's ends blend. Shapes: leaves
(T, 4) local unit quaternions w x y z per person, as `rig.solve_rig(leaves=…)` takes them.

    leaves = retrieve_edit_leaves(plan_json, persons, frames)   # [{leaf: (T, 4)}] per person
"""

from __future__ import annotations

import numpy as np

from interplay.generators.plan import GenerationPlan
from interplay.generators.retrieve_edit.actions import knee_lifts
from interplay.generators.retrieve_edit.arm_poses import weights
from interplay.generators.retrieve_edit.generator import NAME, _actions, _slowed
from interplay.generators.retrieve_edit.holds import hold_of
from interplay.generators.retrieve_edit.pace import rate_of
from interplay.generators.retrieve_edit.primitive_steps import EASE
from interplay.motion.captured_leaves import LEAF_NAMES, piece_leaves, resample_leaves


def _plan(plan: dict) -> GenerationPlan | None:
    """The stored plan as the generator saw it (the keys stored beside it, edits, review, an
    edit's leaves, dropped); None when it does not read."""
    try:
        return GenerationPlan.model_validate({k: v for k, v in plan.items()
                                              if k in GenerationPlan.model_fields})
    except ValueError:
        return None


def _piece(ref: str, person: int, start: int, end: int):
    """A plan's piece as `RetrievalIndex.pieces` makes it (core, FADE tail, offsets) from the
    library clip's view ("<id>#mirrored", "#reversed"); None for a clip the library lacks."""
    from interplay.generators.retrieval.stitch import FADE, Piece
    from interplay.generators.retrieval.views import View
    from interplay.generators.retrieval.views import clip as view_clip
    from interplay.motion.clip import default_clips
    view = View.parse(ref)
    clip = next((c for c in default_clips() if c.id == view.clip), None)
    if clip is None or person >= len(clip.people) or not 0 <= start < end <= clip.frames:
        return None
    clip = clip if view.plain else view_clip(clip, view)
    j = clip.people[person]
    return Piece(j[start:end], j[end:end + FADE], clip.offsets[person])


def _played(plan: dict, index: int) -> np.ndarray | None:
    """One person's frames (T, 22, 3) of segment `index` as retrieval's stitcher plays them
    (every piece from the first on: each is refit to the first piece's bones and its root
    scaled, which changes its speed), for `pace.rate_of`; None where a piece is missing."""
    from interplay.generators.retrieval.stitch import Stitcher
    stitcher = Stitcher(1)
    out: list[np.ndarray] = []
    for seg in plan["segments"][:index + 1]:
        out = []
        for p in seg["retrieval"]["tracks"][0]:
            piece = _piece(p["clip"], int(p["people"][0]), int(p["start"]), int(p["end"]))
            if piece is None:
                return None
            out.append(stitcher.add_single(0, piece))
        short = int(seg["end"]) - int(seg["start"]) - sum(len(f) for f in out)
        if short > 0:
            out.append(stitcher.hold(0, short))
    return np.concatenate(out).astype(np.float64) if out else None


def _derive(leaves: dict[str, np.ndarray], names, lo: int, hi: int) -> None:
    """Frames [lo, hi) of the named leaves left to the rig (NaN), in place."""
    for name in names:
        if name in leaves:
            leaves[name][max(lo, 0):max(hi, 0)] = np.nan


def retrieve_edit_leaves(plan: dict | None, persons: int, frames: int) -> list[dict[str, np.ndarray]]:
    """Per person, the captured leaves (frames, 4) of a retrieve-then-edit motion, NaN where an
    edit made the part (see the module); [{}…] for another generator's plan or one that does
    not read or fit."""
    empty: list[dict[str, np.ndarray]] = [{} for _ in range(persons)]
    if not isinstance(plan, dict) or plan.get("generator") != NAME:
        return empty
    out = piece_leaves(plan, persons, frames)
    gp = _plan(plan)
    if not any(out) or gp is None or gp.persons != persons:
        return empty
    first = out[0]
    for seg in gp.segments:              # as `frames()`: primitives for one person, holds
        if persons == 1 and seg.coverage is not None and seg.coverage.how == "primitive":
            _derive(first, LEAF_NAMES, seg.start, min(seg.end + EASE, frames))
        elif hold_of(seg) is not None:
            _derive(first, LEAF_NAMES, seg.start, seg.end)
    slow = _slowed(gp)                   # one person's last segment, asked to go slowly
    if slow is not None:
        try:
            joints = _played(plan, slow.index)
        except (KeyError, TypeError, ValueError, IndexError):
            joints = None
        rate = rate_of(joints) if joints is not None else 1.0
        for q in first.values():
            q[slow.start:slow.end] = resample_leaves(q[slow.start:slow.end], rate, slow.end - slow.start)
    for seg in gp.segments:              # high knees: the lifted legs' toes (`leg_lifts`)
        legs, _ = knee_lifts(seg)
        if legs and not (seg.retrieval is not None and seg.retrieval.mode == "pair"):
            _derive(first, [f"{side}_foot" for side in legs], seg.start, seg.end)
    for act in _actions(gp)[0]:
        w = weights(frames, max(0, act.start), min(frames, act.end))
        on = np.flatnonzero(w > 0)
        if len(on):
            _derive(first, [f"{act.side}_wrist"], int(on[0]), int(on[-1]) + 1)
    return [{k: v for k, v in person.items() if np.isfinite(v).any()} for person in out]
