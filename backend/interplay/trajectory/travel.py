"""The direction of travel relative to where the body faces, as the trajectory editor keeps it:
"walks backwards" along a path means facing the other way from where the path goes, "steps
sideways to the left" facing 90° to the right of it. With a direction of travel the editor
never turns a person round to follow the path: each frame's facing goes to the path's tangent
rotated by that direction (`facing_fix`), and the motion has to travel that way itself (the
generator's job; one that does not ends up sliding: a forward walk on a backward path
moonwalks, and `map_trajectory` reports how far the facing had to be corrected).

Where the direction comes from: the caller (the plan's segment `travel`, when it has one),
else the path's own spec: a line the planner drew `direction` backward / left / right for a
phrase that says so ("runs backwards", "steps sideways to the left"). A forward walk told to
go "to the left" is a path that turns, not sideways travel, and keeps turning.
"""

from __future__ import annotations

import numpy as np

from interplay.catalogue.grammar import words_rx
from interplay.catalogue.load import catalogue
from interplay.catalogue.words import words
from interplay.motion.kinematics import facing_angle

TRAVELS = ("forward", "backward", "left", "right")
# Facing minus the direction of travel (radians, + towards the person's left): a backward walk
# faces away from where it goes, a step to the left faces 90° to the right of it.
OFFSET = {"forward": 0.0, "backward": np.pi, "left": -np.pi / 2, "right": np.pi / 2}



def _says(manner: str, text: str) -> bool:
    """Do the words name the catalogue's manner ("backwards", "sideways")?"""
    entry = catalogue().get(manner)
    return entry is not None and words_rx(entry.words, entry.not_before).search(text) is not None


def check(travel: str | None) -> str | None:
    if travel is not None and travel not in TRAVELS:
        raise ValueError(f"travel must be one of {list(TRAVELS)} or None, got {travel!r}")
    return travel


def spec_travel(spec) -> str | None:
    """The direction of travel a path spec (dict or TrajectorySpec) implies: its `travel`
    when it has one, else its `direction` when its text asks to move that way relative to the
    body (backwards; sideways, side steps), else None (follow the path facing along it)."""
    d = spec.model_dump() if hasattr(spec, "model_dump") else dict(spec)
    if d.get("travel") is not None:
        return check(d["travel"])
    direction, text = d.get("direction"), str(d.get("text") or "").lower()
    if direction == "backward" and _says("backwards", text):
        return "backward"
    if direction in ("left", "right") and (_says("sideways", text) or words("step_to_side").search(text) is not None):
        return direction
    return None


def own_offset(joints: np.ndarray, heading: np.ndarray, moving: np.ndarray) -> float:
    """The motion's own facing minus its travel direction (radians in (-π, π]), the circular
    mean over the frames that move (all frames when none does)."""
    d = facing_angle(joints) - heading
    keep = moving if moving.any() else np.ones(len(d), bool)
    return float(np.angle(np.exp(1j * d[keep]).mean()))


def facing_fix(joints: np.ndarray, heading: np.ndarray, moving: np.ndarray,
               travel: str | None) -> float:
    """The constant turn (radians) that puts a motion's facing at its travel direction rotated
    by `travel`'s offset (0 without a direction of travel, and ~0 for a motion that already
    travels that way)."""
    if travel is None:
        return 0.0
    return float(np.angle(np.exp(1j * (OFFSET[travel] - own_offset(joints, heading, moving)))))
