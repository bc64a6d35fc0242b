"""Which arm actions a planned segment asks for, read from its per-part edits (the planner's
P_edit) and, for whole-body poses the planner keeps in the base text ("hold a T-pose"), from
the segment's own text. Only actions `arm_poses` can hold are recognised; anything else is
left to the base motion (and named in the reasons, so a user sees it was not laid over).

    arm_actions(segment)  →  ([ArmAction(side, pose, start, end), …], [reason, …])
"""

from __future__ import annotations

import re

from interplay.generators.retrieve_edit.arm_poses import ArmAction
from interplay.planner.schema import Segment

SIDES = ("left", "right")

# Whole-body arm poses (both arms) and the words that name them, most specific first.
BOTH: tuple[tuple[str, re.Pattern[str]], ...] = (
    ("t_pose", re.compile(r"\bt[- ]?pose\b|arms? (?:stretched |held |spread |straight )?"
                          r"(?:out )?(?:wide |out )?to (?:the|your|his|her|their) sides?"
                          r"|arms? outstretched|outstretched arms|like an? (?:aero|air)plane"
                          r"|arms? spread (?:wide|out)"
                          # "with the arms out": to the sides, unless it says in front
                          r"|arms? (?:held |stretched |spread |straight )?out\b(?! (?:in front|forward|ahead|to the front))")),
    ("arm_crossed", re.compile(r"\barms? (?:are |folded |)?crossed|cross(?:es|ing)? "
                               r"(?:your |his |her |their |the |both )*arms|folded arms"
                               r"|arms? folded|fold(?:s|ing)? (?:your |his |her |their )?arms")),
    ("hand_on_hip", re.compile(r"\bhands? on (?:your |his |her |their |the )?hips?")),
    ("arm_forward", re.compile(r"\barms? (?:held |stretched |straight )*(?:out )?"
                               r"(?:in front|forward|ahead)|like a (?:zombie|sleepwalker)")),
    ("arm_up", re.compile(r"\b(?:both|two) (?:arms|hands) (?:up|high|above|over|in the air)"
                          r"|raises? (?:both|your|his|her|their) arms|arms (?:up|raised|high)"
                          r"|(?:arms|hands) above (?:the|your|his|her|their) heads?")),
)
WAVE = re.compile(r"\bwav(?:e|es|ing)\b")
# A raised arm: the text names an arm or a hand and raising it (not a knee lifted high).
LIMB = re.compile(r"\b(?:arms?|hands?)\b")
RAISE = re.compile(r"\b(?:rais\w*|lift\w*|up|high|above|overhead|in the air|skyward)\b")
# … and in a whole segment's text ("picks up a box with both hands" is no raised arm): raising
# an arm or a hand, or an arm or a hand held up.
RAISE_STRICT = re.compile(r"\b(?:rais|lift|hold|put|stretch|reach)\w* (?:\w+ ){0,3}(?:arms?|hands?)"
                          r"\b(?! on)|\b(?:arms?|hands?) (?:is |are |held )?(?:up|raised|above|"
                          r"overhead|in the air)\b")


def side_of(text: str) -> str | None:
    t = text.lower()
    sides = [s for s in SIDES if re.search(rf"\b{s}\b", t)]
    return sides[0] if len(sides) == 1 else None


def pose_of(text: str, strict: bool = False) -> str | None:
    """The arm pose a part instruction (or, `strict`, a whole segment's text) names, if one
    `arm_poses` holds."""
    t = text.lower()
    for pose, pattern in BOTH:
        if pattern.search(t):
            return pose
    if WAVE.search(t):
        return "wave"
    if RAISE_STRICT.search(t) if strict else LIMB.search(t) and RAISE.search(t):
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
        both = next((p for p, pattern in BOTH if pattern.search(text)), None)
        if both is not None:
            actions = {s: both for s in SIDES}
        elif pose in ("wave", "arm_up"):
            named = side_of(text)
            if pose == "arm_up" and named is None and re.search(r"\b(?:both|arms|hands)\b", text):
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


KNEES = re.compile(r"\bknees?\b.*\b(?:high|up|lift|rais)|\b(?:lift|rais)\w* .*\bknees?\b|high knees")


def knee_lifts(seg: Segment) -> tuple[tuple[str, ...], list[str]]:
    """The legs whose knees the segment asks to lift high in every step ("march lifting your
    knees high", "jog with high knees"), and the reasons."""
    legs = tuple(p.removesuffix("_leg") for p, t in seg.edits.named().items()
                 if p.endswith("_leg") and KNEES.search(t.lower()))
    if not legs and KNEES.search(f"{seg.base} {seg.prompt}".lower()):
        legs = SIDES
    why = [f"{s}_leg: knee lifted high in every swing by IK over frames {seg.start}–{seg.end}"
           for s in legs]
    return legs, why
