"""The head and hand turns every export gives the rig (BVH, GLB, the JSON export's rig; issue
27), per person, leaf by leaf:

1. an edit's own (plan["leaves"], `motion.leaves_in`: a head edit's nod or look), over
2. the captures' own where the motion's frames are a capture's (`captured`): a retrieval plan's
   pieces (`motion/captured_leaves.plan_leaves`), a retrieve-then-edit plan's where no arm
   action, primitive or held pose made the part (`generators/retrieve_edit/leaves.py`), less
   the frames a user's edit since then re-made (`_edited`: plan["edits"]), over
3. the rig's derived ones (`rig/leaves.py`) everywhere else: rows of NaN, which the rig turns
   into the captured ones over LEAF_BLEND frames next to them.

SPAM, CODA and composed (interaction) plans carry no captured leaves: their frames are a
model's or an IK composition's, not a capture's frame for frame, so theirs stay derived.

    leaves = export_leaves(motion.plan, motion.persons, motion.frames)   # [{leaf: (T, 4)}]
    write_bvh(people[k], leaves=leaves[k]); write_glb(people, leaves=leaves)
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.captured_leaves import LEAF_NAMES, plan_leaves
from interplay.motion.motion import leaves_in

Leaves = list[dict[str, np.ndarray]]


def captured(plan: dict | None, persons: int, frames: int) -> Leaves:
    """Per person, the captured leaves (frames, 4) of the motion a plan made, NaN rows where
    its generator changed the part; [{}…] for a plan whose frames are no capture's."""
    kind = plan.get("generator") if isinstance(plan, dict) else None
    if kind == "retrieve_edit":
        from interplay.generators.retrieve_edit.leaves import retrieve_edit_leaves
        return retrieve_edit_leaves(plan, persons, frames)
    return plan_leaves(plan, persons, frames)


def _touched(entry: dict) -> tuple[str, ...]:
    """The leaves an edit entry re-made: an IK arm pose its arms' wrists, a kick its leg's toe,
    a head edit the head, SPAM's parts the leaves inside them (`skeleton.PART_JOINTS`: an upper
    part holds the head and its hand, a lower one its toe), a path none (the whole body moved
    rigidly), anything else (a re-run segment, an unknown entry) every leaf."""
    if "trajectory" in entry:
        return ()
    kind = entry.get("generator")
    if kind == "ik_pose":
        return tuple(f"{a.split('_')[0]}_wrist" for a in entry.get("arms") or [])
    if kind == "captured_kick":                   # the kicking leg's toe
        return tuple(f"{leg.split('_')[0]}_foot" for leg in [entry.get("leg") or ""] if leg)
    if kind == "primitive" or entry.get("part") == "head":
        return ("head",)
    parts = [sk.PART_ALIASES.get(p, p) for p in entry.get("parts") or []]
    if kind == "spam" and parts and all(p in sk.PART_JOINTS for p in parts):
        return tuple(leaf for leaf in LEAF_NAMES
                     if any(sk.JOINT_INDEX[leaf] in sk.PART_JOINTS[p] for p in parts))
    return LEAF_NAMES


def _edited(leaves: Leaves, plan: dict) -> Leaves:
    """`leaves` with the frames each of plan["edits"] re-made (its "frames" [a, b), widened by
    its "fade"; all frames when it names none) left to the rig, on one-person motions (the
    only ones edited)."""
    edits = plan.get("edits") or []
    if len(leaves) != 1 or not leaves[0] or not isinstance(edits, list):
        return leaves
    out = {k: v.copy() for k, v in leaves[0].items()}
    frames = len(next(iter(out.values())))
    for entry in edits:
        if not isinstance(entry, dict):
            continue
        span = entry.get("frames") or [0, frames]
        fade = int(entry.get("fade") or 0)
        try:
            a, b = max(0, int(span[0]) - fade), min(frames, int(span[1]) + fade)
        except (TypeError, ValueError, IndexError):
            a, b = 0, frames
        for leaf in _touched(entry):
            if leaf in out:
                out[leaf][a:b] = np.nan
    return [{k: v for k, v in out.items() if np.isfinite(v).any()}]


def captured_since(plan: dict | None, persons: int, frames: int) -> Leaves:
    """`captured`, less what the user's edits since re-made (`_edited`)."""
    base = captured(plan, persons, frames)
    return _edited(base, plan) if isinstance(plan, dict) else base


def export_leaves(plan: dict | None, persons: int, frames: int) -> Leaves:
    """Per person, the leaves the exports give the rig (see the module): an edit's (the
    plan's, as stored) over the captures' own, {} where neither is known (the rig derives
    them). A `Motion` has lifted the plan's into its own: `captured_since` and `leaves_of`."""
    return [{**c, **e} for c, e in zip(captured_since(plan, persons, frames),
                                       leaves_in(plan, persons, frames))]
