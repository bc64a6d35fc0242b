"""Which arm actions a planned segment asks for, read from its per-part edits (the planner's
P_edit) and, for whole-body poses the planner keeps in the base text ("hold a T-pose"), from
the segment's own text, by the catalogue's phrases of the entries with an `ik` pose. Only
actions `arm_poses` can hold are recognised; anything else is
left to the base motion (and named in the reasons, so a user sees it was not laid over).

    arm_actions(segment)  →  ([ArmAction(side, pose, start, end), …], [reason, …])
"""

from __future__ import annotations

from interplay.catalogue.grammar import template_rx
from interplay.catalogue.load import catalogue
from interplay.catalogue.phrases import tokens
from interplay.catalogue.words import words
from interplay.generators.retrieve_edit.arm_poses import ArmAction
from interplay.planner.schema import Segment

SIDES = ("left", "right")
# The poses `arm_poses` holds with both arms, most specific first; their words are the
# catalogue's (the entries with that `ik` and `phrases`).
BOTH = ("t_pose", "arm_crossed", "hand_on_hip", "arm_forward", "arm_up")


def _entries(ik: str, kinds: tuple[str, ...] = ("pose",)):
    return [a for a in catalogue().action if a.ik == ik and a.kind in kinds]


def _says(ik: str, text: str, kinds: tuple[str, ...] = ("pose",), part: bool = False) -> bool:
    """Do the words name the IK pose `ik` (the catalogue's phrases of its entries)?"""
    return any(template_rx(tuple(a.part_phrases if part else a.phrases)).search(text)
               for a in _entries(ik, kinds) if (a.part_phrases if part else a.phrases))


def both_pose(text: str) -> str | None:
    """The pose of both arms the words name, if any."""
    return next((pose for pose in BOTH if _says(pose, text)), None)


def side_of(text: str) -> str | None:
    sides = sorted({t.text for t in tokens(text.lower()) if t.text in ("left", "right")})
    return sides[0] if len(sides) == 1 else None


def pose_of(text: str, strict: bool = False) -> str | None:
    """The arm pose a part instruction (or, `strict`, a whole segment's text) names, if one
    `arm_poses` holds."""
    t = text.lower()
    both = both_pose(t)
    if both is not None:
        return both
    if _says("wave", t, ("part",)):
        return "wave"
    if _says("arm_up", t, ("part",), part=not strict):
        return "arm_up"
    return None


def arm_actions(seg: Segment, offset: int = 0) -> tuple[list[ArmAction], list[str]]:
    """The arm actions of one segment over its frames (shifted by `offset`), and the reasons:
    one line per arm saying what is laid over it, or that an edit was left to the base."""
    start, end = seg.start - offset, seg.end - offset
    actions: dict[str, str] = {}
    reasons: list[str] = []
    edits = seg.edits.named()
    for part, text in edits.items():
        if not part.endswith("_arm"):
            continue
        side = part.removesuffix("_arm")
        pose = pose_of(text)
        if pose is None:
            reasons.append(f"{part}: '{text}' is left to the captured motion (no held pose for it)")
            continue
        actions[side] = pose
    if not actions:
        # Poses the planner left in the segment's text: both arms for a whole-body pose; a
        # wave or a raise on the named hand (the right one when none is named).
        text = f"{seg.base} {seg.prompt}".lower()
        pose = pose_of(text, strict=True)
        both = both_pose(text)
        if both is not None:
            actions = {s: both for s in SIDES}
        elif pose in ("wave", "arm_up"):
            named = side_of(text)
            if pose == "arm_up" and named is None and words("both_sides").search(text):
                actions = {s: pose for s in SIDES}
            else:
                actions = {named or "right": pose}
    # Poses of both arms take both even where the plan named one.
    for pose in ("arm_crossed", "t_pose", "arm_forward"):
        if pose in actions.values():
            actions = {s: pose for s in SIDES}
            break
    for side, pose in actions.items():
        reasons.append(f"{side}_arm: {pose.replace('_', ' ')} held by IK over frames "
                       f"{seg.start}–{seg.end} (the captured arm there is replaced)")
    return [ArmAction(side, pose, start, end) for side, pose in sorted(actions.items())], reasons


def knee_lifts(seg: Segment) -> tuple[tuple[str, ...], list[str]]:
    """The legs whose knees the segment asks to lift high in every step ("march lifting your
    knees high", "jog with high knees"), and the reasons."""
    legs = tuple(p.removesuffix("_leg") for p, t in seg.edits.named().items()
                 if p.endswith("_leg") and _says("knees_high", t.lower(), ("manner",)))
    if not legs and _says("knees_high", f"{seg.base} {seg.prompt}".lower(), ("manner",)):
        legs = SIDES
    why = [f"{s}_leg: knee lifted high in every swing by IK over frames {seg.start}–{seg.end}"
           for s in legs]
    return legs, why
