"""Checks of the head and of part edits (registered in `named.CHECKS`).

The 22-joint skeleton has no joint past the head, so a head's own rotation leaves no trace in
the joints: the head is measured by the direction of the neck → head bone, which the neck's
rotation turns. A pitch (a nod, looking up or down) shows in that bone's lean against the
chest. A turn left or right shows only in the direction of the bone's horizontal part, and
only as far as the bone leans: SMPL's rest pose puts the head joint 5 cm ahead of the neck
(a 30° turn moves it 2.5 cm sideways), but captures re-posed on it often hold the bone nearly
upright (Bandai's: 1.3 cm of horizontal part at the median), and there a shake is all but
invisible. The shake check therefore reads the turn only where that part is ≥ 3 cm long
(at 2 cm a capture's jitter and a nod already swing its direction by 25°).

Pitch and yaw are taken in the upper torso's frame (shoulders and upper spine), so a turning,
leaning or swaying body does not read as a head movement. Edit checks
(`AGAINST_BASE`) compare an edited motion with the motion it was made from, frame by frame:
they take (edited BodyFrame, base BodyFrame, **params).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.bodyframe import BodyFrame
from interplay.motion.signals import fill_gaps, runs, smooth, zigzag

FPS = sk.FPS
J = sk.JOINT_INDEX

NOD_SWING_DEG = 10.0       # a nod: each dip or lift of the neck → head bone ≥ 10° (a nod is
                           # 15–30° of neck flexion; breathing and steps sway it ≤ 5°) …
SHAKE_SWING_DEG = 25.0     # a shake: each turn ≥ 25° (a "no" turns ±20–45°; the horizontal
                           # part's direction wobbles ≤ 10° with jitter) …
HEAD_HALF_PERIOD_S = 0.8   # … each reversal within 0.8 s of the last …
HEAD_MIN_TURNS = 4         # … ≥ 4 reversals: two nods or shakes, there and back …
CALM_SPEED = 0.3           # … with the pelvis under 0.3 m/s (a squat moves it ~0.5, a stride ~1)
PITCH_DEG = 25.0           # looking up / down: the bone pitched ≥ 25° from where the base had it
                           # (the neck alone extends ~50° and flexes ~60°)
HORIZONTAL_M = 0.03        # a turn needs the bone's horizontal part ≥ 3 cm long (else the
                           # head joint barely moves when the head turns)
STILL_CM = 2.0             # an edit of one part leaves every other joint within 2 cm of the base
                           # (mean over the frames; the IK and the retargeting round-trip keep
                           # untouched joints to < 1 mm)
# The joints an edit of each part may move (the rest must stay where the base had them).
PART_JOINTS: dict[str, tuple[str, ...]] = {
    "head": ("neck", "head"),
    "left_arm": ("left_collar", "left_shoulder", "left_elbow", "left_wrist"),
    "right_arm": ("right_collar", "right_shoulder", "right_elbow", "right_wrist"),
    "left_leg": ("left_hip", "left_knee", "left_ankle", "left_foot"),
    "right_leg": ("right_hip", "right_knee", "right_ankle", "right_foot"),
}


def head_bone(b: BodyFrame) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(left, up, forward) components (T,) of the neck → head bone in the upper torso's frame:
    left along the shoulders (right → left shoulder), up along the upper spine (spine3 →
    neck, made square to left), forward their cross product. Taken against the chest, not the
    floor, so that the torso's own sway in a stride or a bow is not read as the head's."""
    j = b.joints
    left = j[:, J["left_shoulder"]] - j[:, J["right_shoulder"]]
    left /= np.maximum(np.linalg.norm(left, axis=1, keepdims=True), 1e-9)
    up = j[:, sk.NECK] - j[:, J["spine3"]]
    up -= (up * left).sum(1, keepdims=True) * left
    up /= np.maximum(np.linalg.norm(up, axis=1, keepdims=True), 1e-9)
    fwd = np.cross(left, up)
    v = j[:, sk.HEAD] - j[:, sk.NECK]
    return (v * left).sum(1), (v * up).sum(1), (v * fwd).sum(1)


def head_pitch(b: BodyFrame) -> np.ndarray:
    """Degrees (T,) the neck → head bone leans forward of the upper spine in the body's
    front-to-back plane (+ chin down, − looking up)."""
    _, up, fwd = head_bone(b)
    return np.degrees(np.arctan2(fwd, up))


def head_yaw(b: BodyFrame) -> np.ndarray:
    """Degrees (T,) the head is turned to the body's left (− right) about the vertical: the
    neck → head bone's part along the shoulders (on the floor) over the length of its
    horizontal part, taken at its median over the clip, as an arcsine. A nod tips the bone
    about the shoulders' axis and leaves the part along it alone, so a nod does not read as a
    shake; NaN throughout when the horizontal part is under HORIZONTAL_M (a turn is not
    visible in the joints)."""
    j = b.joints
    left = (j[:, J["left_shoulder"]] - j[:, J["right_shoulder"]]) * np.array([1.0, 0.0, 1.0])
    left /= np.maximum(np.linalg.norm(left, axis=1, keepdims=True), 1e-9)
    v = j[:, sk.HEAD] - j[:, sk.NECK]
    reach = float(np.median(np.hypot(v[:, 0], v[:, 2])))
    if reach < HORIZONTAL_M:
        return np.full(len(v), np.nan)
    return np.degrees(np.arcsin(np.clip((v * left).sum(1) / reach, -1.0, 1.0)))


def calm(b: BodyFrame) -> np.ndarray:
    """(T,) bool: the body itself still enough to read the head against it: the pelvis under
    CALM_SPEED (3-D, over a quarter second) and the torso within 30° of vertical. A nod or a
    shake is made standing or sitting; a stride, a jump or a flip swings the head bone as much."""
    v = np.linalg.norm(b.velocity[:, sk.PELVIS], axis=1)
    return (smooth(v, max(1, round(0.25 * FPS))) < CALM_SPEED) & (b.tilt <= 30.0)


def quick_reversals(x: np.ndarray, swing: float, keep: np.ndarray | None = None) -> int:
    """The most reversals of x (T,) in one chain of swings ≥ `swing`, each reversal within
    HEAD_HALF_PERIOD_S of the last, counting only reversals on frames where `keep` (NaN frames
    are filled by interpolation)."""
    x = np.asarray(x, dtype=np.float64)
    ok = ~np.isnan(x)
    if ok.sum() < 2:
        return 0
    x = np.interp(np.arange(len(x)), np.flatnonzero(ok), x[ok])
    turns = zigzag(smooth(x, 3), swing)
    if keep is not None:
        turns = turns[keep[turns]]
    if len(turns) < 2:
        return len(turns)
    quick = np.diff(turns) <= HEAD_HALF_PERIOD_S * FPS
    return max((e - s + 1 for s, e in runs(quick)), default=1)


def _longest(mask: np.ndarray) -> float:
    return max((e - s for s, e in runs(fill_gaps(mask))), default=0) / FPS


# ---- one motion ----------------------------------------------------------------------------------

def head_nod(b: BodyFrame, min_turns: int = HEAD_MIN_TURNS, swing_deg: float = NOD_SWING_DEG):
    """A nod: the head dips and lifts against the upper spine in quick swings of ≥ 10°, ≥ 4 reversals, the body calm."""
    n = quick_reversals(head_pitch(b), swing_deg, calm(b))
    return n >= min_turns, n, f"≥ {min_turns} quick pitch reversals of ≥ {swing_deg}°"


def head_shake(b: BodyFrame, min_turns: int = HEAD_MIN_TURNS, swing_deg: float = SHAKE_SWING_DEG):
    """A head shake: the head turns left and right of the chest in quick swings of ≥ 25°, ≥ 4 reversals, the body calm."""
    n = quick_reversals(head_yaw(b), swing_deg, calm(b))
    return n >= min_turns, n, f"≥ {min_turns} quick yaw reversals of ≥ {swing_deg}°"


# ---- an edited motion against its base ----------------------------------------------------------

def _same_length(b: BodyFrame, base: BodyFrame) -> None:
    if b.joints.shape != base.joints.shape:
        raise ValueError(f"the edit changed the motion's shape {base.joints.shape} → {b.joints.shape}")


def head_pitch_over_base(b: BodyFrame, base: BodyFrame, direction: str = "up",
                         min_deg: float = PITCH_DEG, min_s: float = 1.0):
    """The edit tilts the head up (or down) ≥ 25° beyond the base motion's, for ≥ `min_s` s."""
    _same_length(b, base)
    d = head_pitch(base) - head_pitch(b)                    # + the edit looks higher
    if direction == "down":
        d = -d
    got = _longest(d >= min_deg)
    return got >= min_s, {"seconds": round(got, 2), "most_deg": round(float(d.max()), 1)}, (
        f"{direction} ≥ {min_deg}° over the base for ≥ {min_s} s")


def rest_unchanged(b: BodyFrame, base: BodyFrame, part: str = "head", max_cm: float = STILL_CM):
    """Every joint outside the edited part stays within 2 cm (mean over frames) of the base motion."""
    _same_length(b, base)
    moved = {J[n] for n in PART_JOINTS[part]}
    keep = [j for j in range(sk.NUM_JOINTS) if j not in moved]
    cm = np.linalg.norm(b.joints[:, keep] - base.joints[:, keep], axis=2).mean(axis=0) * 100
    worst = int(np.argmax(cm))
    return float(cm[worst]) <= max_cm, {"worst_cm": round(float(cm[worst]), 2),
                                        "joint": sk.JOINT_NAMES[keep[worst]]}, (
        f"joints outside {part} ≤ {max_cm} cm from the base")


SINGLE: list[Callable[..., tuple[bool, Any, str]]] = [head_nod, head_shake]
AGAINST_BASE: list[Callable[..., tuple[bool, Any, str]]] = [head_pitch_over_base, rest_unchanged]
