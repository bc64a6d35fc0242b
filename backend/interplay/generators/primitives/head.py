"""The head as an editable part: look up / down / left / right by an angle, look at a point,
nod N times, shake N times, each a rotation of the head joint about the neck in the trunk's
own axes (`body.trunk_axes`: across the shoulders and hips, pelvis → neck, the chest's
normal), eased in and out over HEAD_EASE_S. Nothing but the head joint moves: every other
joint stays bit for bit, so "look up" on a walk keeps the walk.

Angles are measured as the rig reads them, on the neck → head bone in the trunk frame
(`pitch`: up is positive, `yaw`: towards the person's left is positive). The skeleton has no
head orientation beyond that bone, which leans ~30° forward of the neck in the rest pose: a
turn (yaw) shows as the head joint swinging sideways on a cone of at least TURN_CONE_DEG (for
performers whose head joint sits straight over the neck too), not as a twist.

Shapes: joints (T, 22, 3) metres; angles in degrees.
"""

from __future__ import annotations

import numpy as np

from interplay.generators.primitives.body import rotation, trunk_axes
from interplay.generators.primitives.timing import bumps, phase
from interplay.motion import skeleton as sk
from interplay.motion.ik import ease

ACTIONS = ("look_up", "look_down", "look_left", "look_right", "look_at", "nod", "shake")
DEFAULT_DEG = {"look_up": 35.0, "look_down": 35.0, "look_left": 50.0, "look_right": 50.0,
               "nod": 22.0, "shake": 35.0}
MAX_PITCH_DEG = 50.0
MAX_YAW_DEG = 75.0
HEAD_EASE_S = 0.3
TURN_CONE_DEG = 30.0   # a turn swings the head joint on a cone at least this wide (the rest
                       # pose's neck → head bone leans ~30° forward of the neck)


def pitch_yaw(joints: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(pitch, yaw) (T,) in degrees of the neck → head bone in the trunk frame."""
    j = np.asarray(joints, dtype=np.float64)
    left, up, chest = trunk_axes(j)
    v = j[:, sk.HEAD] - j[:, sk.NECK]
    a, u, c = (v * left).sum(-1), (v * up).sum(-1), (v * chest).sum(-1)
    return np.degrees(np.arctan2(-c, u)), np.degrees(np.arctan2(a, c))


def head_turns(joints: np.ndarray, pitch_deg: np.ndarray, yaw_deg: np.ndarray) -> np.ndarray:
    """The world rotations (T, 3, 3) `turn_head` turns the neck → head bone by: a pitch up by
    `pitch_deg` (about the trunk's left axis), then a turn left by `yaw_deg`; (T,) each. An
    export's head leaf turns by the same (`primitives.edit.head_leaf`)."""
    out = np.asarray(joints, dtype=np.float64)
    left, up, chest = trunk_axes(out)
    v = out[:, sk.HEAD] - out[:, sk.NECK]
    # A turn is about an axis leant back from the bone by at least TURN_CONE_DEG, so that the
    # head joint swings sideways as a turning head's centre does even where a performer's head
    # joint sits straight over the neck (a turn about the bone itself would not move it).
    lean = np.degrees(np.arctan2((v * chest).sum(-1), (v * up).sum(-1)))
    back = np.radians(np.clip(TURN_CONE_DEG - lean, 0.0, TURN_CONE_DEG))[:, None]
    axis = np.cos(back) * up - np.sin(back) * chest
    rp = rotation(left, -np.radians(pitch_deg))       # + about left tips the head forward
    ry = rotation(axis, np.radians(yaw_deg))
    return ry @ rp


def turn_head(joints: np.ndarray, pitch_deg: np.ndarray, yaw_deg: np.ndarray) -> np.ndarray:
    """Joints with the head joint turned about the neck: pitched up by `pitch_deg` (about the
    trunk's left axis), then turned left by `yaw_deg` (about pelvis → neck); (T,) each."""
    out = np.asarray(joints, dtype=np.float64).copy()
    v = np.einsum("tij,tj->ti", head_turns(out, pitch_deg, yaw_deg), out[:, sk.HEAD] - out[:, sk.NECK])
    out[:, sk.HEAD] = out[:, sk.NECK] + v
    return out


def _ramp(t: int) -> np.ndarray:
    r = max(1, int(round(HEAD_EASE_S * sk.FPS)))
    r = min(r, max(1, t // 3))
    idx = np.arange(t, dtype=np.float64)
    return np.minimum(ease((idx + 1) / r), ease((t - idx) / r))


def _look_at_angles(j: np.ndarray, point: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(pitch, yaw) (T,) that turn a head looking along the chest to look at `point` (T, 3)
    (performers' head joints sit differently, so the base's own head angle is not read)."""
    left, up, chest = trunk_axes(j)
    d = np.asarray(point, dtype=np.float64) - j[:, sk.NECK]
    a, u, c = (d * left).sum(-1), (d * up).sum(-1), (d * chest).sum(-1)
    yaw = np.clip(np.degrees(np.arctan2(a, c)), -MAX_YAW_DEG, MAX_YAW_DEG)
    pitch = np.clip(np.degrees(np.arctan2(u - 0.1, np.hypot(a, c))), -MAX_PITCH_DEG, MAX_PITCH_DEG)
    return pitch, yaw


def head(base: np.ndarray, action: str, count: int = 1, degrees: float | None = None,
         point: np.ndarray | None = None, start: int = 0, end: int | None = None) -> np.ndarray:
    """The base (T, 22, 3) with the head doing `action` over frames [start, end): a look held
    (eased in and out), `count` nods (down and back up) or `count` shakes (left, right, back),
    or a look at `point` (3,) or (T, 3) world."""
    j = np.asarray(base, dtype=np.float64)
    pitch, yaw = head_angles(j, action, count, degrees, point, start, end)
    out = j.copy()
    out[start:len(pitch) + start] = turn_head(j[start:len(pitch) + start], pitch, yaw)
    return out


def head_angles(base: np.ndarray, action: str, count: int = 1, degrees: float | None = None,
                point: np.ndarray | None = None, start: int = 0, end: int | None = None
                ) -> tuple[np.ndarray, np.ndarray]:
    """(pitch, yaw) (end - start,) in degrees: the turns `head` gives the frames [start, end)."""
    if action not in ACTIONS:
        raise ValueError(f"unknown head action {action!r}; expected one of {ACTIONS}")
    j = np.asarray(base, dtype=np.float64)
    end = len(j) if end is None else end
    if not 0 <= start < end <= len(j):
        raise ValueError(f"bad frames [{start}, {end}) for {len(j)} frames")
    sub = j[start:end]
    t = len(sub)
    deg = float(degrees if degrees is not None else DEFAULT_DEG.get(action, 0.0))
    zero = np.zeros(t)
    if action in ("look_up", "look_down", "look_left", "look_right"):
        w = _ramp(t)
        a = min(deg, MAX_PITCH_DEG if action in ("look_up", "look_down") else MAX_YAW_DEG)
        sign = 1.0 if action in ("look_up", "look_left") else -1.0
        pitch, yaw = (sign * a * w, zero) if action in ("look_up", "look_down") else (zero, sign * a * w)
    elif action == "look_at":
        if point is None:
            raise ValueError("look_at needs a point")
        p, y = _look_at_angles(sub, np.broadcast_to(point, (t, 3)))
        w = _ramp(t)
        pitch, yaw = w * p, w * y
    elif action == "nod":
        pitch, yaw = -deg * bumps(t, count, hold=0.0), zero
    else:
        cycle, ph = phase(t, count)
        yaw = np.where(cycle >= 0, deg * np.sin(2 * np.pi * ph), 0.0)
        pitch = zero
    return pitch, yaw
