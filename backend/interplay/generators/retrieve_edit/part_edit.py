"""A user's part edit that names an arm pose `arm_poses` can hold ("raise the left arm above
the head", "hold a T-pose", "cross your arms", "wave") made by IK over the edited frames,
instead of by re-generating the part with SPAM: the pose holds for the whole span (eased in
and out over its first and last BLEND_S), and every joint outside the edited arm(s) stays
exactly where it was. Anything else (a kick, "swing the arm") is left to SPAM's edit.

    pose_edit(joints, "left_arm", "raise the left arm above the head", (10, 60))
        → (joints, entry) | None
"""

from __future__ import annotations

import numpy as np

from interplay.generators.retrieve_edit.actions import SIDES, pose_of, side_of
from interplay.generators.retrieve_edit.arm_poses import ArmAction, apply
from interplay.motion import skeleton as sk

TWO_ARMS = ("t_pose", "arm_crossed", "arm_forward")
WHOLE = ("whole_body", "whole body", "body", "all")


def _arms(part: str | None, prompt: str, pose: str) -> list[str] | None:
    """The sides an edit of `part` moves, or None when the part is not an arm."""
    key = (part or "whole_body").strip().lower().replace("-", "_")
    if key in WHOLE:
        named = side_of(prompt)
        if pose in TWO_ARMS or named is None and pose != "wave":
            return list(SIDES)
        return [named or "right"]
    for side in SIDES:
        if key in (f"{side}_arm", f"{side}_upper", f"{side}_hand"):
            return [side]
    return None


def pose_edit(joints: np.ndarray, part: str | None, prompt: str,
              frames: tuple[int, int] | None = None) -> tuple[np.ndarray, dict] | None:
    """(edited joints (T, 22, 3), plan entry), or None when the edit is not an arm pose."""
    pose = pose_of(prompt)
    if pose is None:
        return None
    sides = _arms(part, prompt, pose)
    if not sides:
        return None
    j = np.asarray(joints, dtype=np.float64)
    a, b = frames or (0, len(j))
    out = apply(j, [ArmAction(s, pose, a, b) for s in sides])
    moved = np.linalg.norm(out - j, axis=-1)                                  # (T, 22)
    arm = np.zeros(sk.NUM_JOINTS, bool)
    for s in sides:
        arm[[sk.JOINT_INDEX[f"{s}_{p}"] for p in ("elbow", "wrist")]] = True
    entry = {"generator": "ik_pose", "part": part or "whole_body", "pose": pose,
             "arms": [f"{s}_arm" for s in sides], "prompt": prompt.strip(), "frames": [a, b],
             "untouched_change_cm": round(float(moved[:, ~arm].mean() * 100), 3),
             "edited_change_cm": round(float(moved[a:b][:, arm].mean() * 100), 3)}
    return out, entry
