"""Checks of everyday one-person actions the older checks cannot tell (registered in
`named.CHECKS` with them): the hands meeting, a hand at the face, a hand pumping or
scrubbing, the body lying face down or face up, the torso curling up from lying, an uneven
gait. Each is a function (BodyFrame, **params) → (passed, value, bound), measured on the
joints in the body's own frame (`measures.py`), with its bounds reasoned from body geometry.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.bodyframe import BodyFrame
from interplay.motion.checks import measures as m
from interplay.motion.signals import fill_gaps, runs, smooth, zigzag

FPS = sk.FPS
J = sk.JOINT_INDEX

HANDS_MEET_M = 0.10        # the two hands' surfaces within 10 cm: a clap, palms pressed, a
                           # ball or a glass held in both hands (a hand sphere is 4.5 cm across
                           # its radius, so the centres are then ≤ 19 cm apart) …
HANDS_APART_M = 0.20       # … and apart again by 20 cm before the next meeting counts
FACE_M = 0.15              # a hand at the face: its centre within 15 cm of the face point …
FACE_AHEAD_M = 0.08        # … which lies 8 cm ahead of the head joint (the joint sits between
                           # the ears; the face is a head's half-depth in front of it)
PUMP_AMPLITUDE_M = 0.15    # a hand pumping (hammering, scrubbing, juggling, sawing): each
                           # swing along the axis ≥ 15 cm, a forearm's half-length …
PUMP_HALF_PERIOD_S = 0.8   # … each reversal within 0.8 s of the last (≥ ~0.6 Hz) …
PUMP_MIN_TURNS = 4         # … ≥ 4 reversals: two strokes there and back …
PUMP_IN_PLACE = 0.5        # … with the pelvis under 0.5 m/s (an arm swung by walking or
                           # running pumps as much, so strokes are counted standing or seated)
FLAT_TILT_DEG = 60.0       # lying face down / up: torso ≥ 60° from vertical (lying's bound) …
FACING_COS = 0.5           # … the chest's normal within 60° of straight down / up …
FLAT_RATIO = 0.55          # … and the pelvis under 55 % of standing (a plank holds it at ~35 %;
                           # a forward bend to the floor keeps it over 80 %)
CURL_DOWN_DEG = 65.0       # a sit-up: the torso from ≥ 65° off vertical (lying back) …
CURL_UP_DEG = 35.0         # … up to ≤ 35° (sitting up) and back, the pelvis low throughout
GAIT_MIN_STEPS = 6         # uneven gait: ≥ 6 steps (three on each foot) to compare …
GAIT_UNEVEN = 0.30         # … and the mean time the body spends on each foot alone differs
                           # by ≥ 30 % of the longer (a limp hurries off the sore leg; captured
                           # Bandai "normal" walks and turns ≤ 13 %, but its old and swaggering
                           # styles reach 30–37 % and one CMU walk 36 %: an old person's uneven
                           # step passes as a limp)


def count_ok(n: int, count: int | None, at_least: int | None) -> tuple[bool, str]:
    """A count held to exactly `count`, else to at least `at_least` (1 when neither is given)."""
    if count is not None:
        return n == count, f"= {count}"
    lo = 1 if at_least is None else at_least
    return n >= lo, f">= {lo}"


def _longest(mask: np.ndarray) -> float:
    return max((e - s for s, e in runs(fill_gaps(mask))), default=0) / FPS


def _sides(hand: str) -> tuple[str, ...]:
    return m.SIDES if hand in ("either", "any", "both") else (hand,)


# ---- measures ----------------------------------------------------------------------------------

def own_hands_gap(b: BodyFrame) -> np.ndarray:
    """Gap (T,) between the surfaces of one person's two hands (metres)."""
    return m.hand_gap(b.joints, b.joints, "left", "right")


def meetings(gap: np.ndarray, near: float = HANDS_MEET_M, apart: float = HANDS_APART_M) -> list[int]:
    """Frames at which a gap (T,) closes under `near` after having been over `apart` (or at
    the start): separate meetings, not one long hold counted twice by its jitter."""
    out, ready = [], True
    for i, g in enumerate(gap):
        if ready and g <= near:
            out.append(i)
            ready = False
        elif g >= apart:
            ready = True
    return out


def hand_at_face(b: BodyFrame, side: str) -> np.ndarray:
    """(T,) bool: the hand's centre within FACE_M of the face point."""
    face = b.joints[:, sk.HEAD] + FACE_AHEAD_M * b.forward
    return np.linalg.norm(m.hand_point(b.joints, side) - face, axis=1) <= FACE_M


def hand_axis(b: BodyFrame, side: str, axis: str) -> np.ndarray:
    """The hand's centre (T,) relative to the neck along one of the body's axes: "up",
    "forward" or "side" (towards the body's left)."""
    lat, up, fwd = b.local(m.hand_point(b.joints, side) - b.joints[:, sk.NECK])
    return {"up": up, "forward": fwd, "side": lat}[axis]


def pumps(b: BodyFrame, side: str, axis: str) -> int:
    """The most quick reversals in one chain of a hand's to-and-fro along `axis` (each swing
    ≥ PUMP_AMPLITUDE_M, each reversal within PUMP_HALF_PERIOD_S of the last)."""
    turns = zigzag(smooth(hand_axis(b, side, axis), 3), PUMP_AMPLITUDE_M)
    turns = turns[m.speed(b)[turns] < PUMP_IN_PLACE]
    if len(turns) < 2:
        return len(turns)
    quick = np.diff(turns) <= PUMP_HALF_PERIOD_S * FPS
    return max((e - s + 1 for s, e in runs(quick)), default=1)


def chest_up(b: BodyFrame) -> np.ndarray:
    """(T,) the vertical component of the chest's normal (the body's forward from hips and
    shoulders, taken in 3-D here rather than on the ground): +1 lying on the back, −1 face down."""
    hips = b.joints[:, J["left_hip"]] - b.joints[:, J["right_hip"]]
    spine = b.joints[:, sk.NECK] - b.joints[:, sk.PELVIS]
    n = np.cross(hips, spine)                    # left × up = forward for an upright body
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-9)
    return n[:, 1]


def lying_on(b: BodyFrame, side: str) -> np.ndarray:
    """(T,) bool: the torso flat (≥ FLAT_TILT_DEG from vertical) and low (pelvis under
    FLAT_RATIO of standing) with the chest facing the floor (side "front") or the sky
    ("back")."""
    c = chest_up(b)
    facing = c <= -FACING_COS if side == "front" else c >= FACING_COS
    return (b.tilt >= FLAT_TILT_DEG) & facing & (m.pelvis_ratio(b) < FLAT_RATIO)


def curls(b: BodyFrame) -> list[int]:
    """Frames of completed sit-ups: the torso from flat on the back (≥ CURL_DOWN_DEG off
    vertical, chest up) to ≤ CURL_UP_DEG and back down, the pelvis under 45 % of standing
    (sitting on the floor, not getting up)."""
    tilt = smooth(b.tilt, 3)
    low = m.pelvis_ratio(b) < m.LIE_RATIO
    back = chest_up(b) > 0
    out, state, top = [], "none", 0
    for i in range(len(tilt)):
        if not low[i]:
            state = "none"
        elif tilt[i] >= CURL_DOWN_DEG and back[i]:
            if state == "up":
                out.append(top)
            state = "down"
        elif tilt[i] <= CURL_UP_DEG and state == "down":
            state, top = "up", i
    return out


def single_support(b: BodyFrame, side: str) -> list[float]:
    """Seconds of each whole stretch with only this foot on the floor (the body carried on one
    leg; the stretches cut by the clip's ends are left out). A limp shortens them on the sore
    leg: the body hurries off it."""
    down = {s: fill_gaps(b.foot_height(s) < m.AIRBORNE_M) for s in m.SIDES}
    other = "right" if side == "left" else "left"
    alone = down[side] & ~down[other]
    return [(e - s) / FPS for s, e in runs(alone) if s > 0 and e < len(alone)]


# ---- checks ------------------------------------------------------------------------------------

def hands_meet(b: BodyFrame, count: int | None = None, at_least: int | None = None,
               max_m: float = HANDS_MEET_M):
    """The two hands come together (surfaces within 10 cm) — a clap, a toast, a ball in both hands — counted per meeting."""
    n = len(meetings(own_hands_gap(b), max_m))
    ok, bound = count_ok(n, count, at_least)
    return ok, n, f"hands within {max_m} m, {bound} times"


def hand_to_face(b: BodyFrame, hand: str = "either", min_s: float = 1.0):
    """A hand at the face (its centre within 15 cm of the face's middle) for ≥ `min_s` s: eating, drinking, a phone, teeth."""
    got = max(_longest(hand_at_face(b, s)) for s in _sides(hand))
    return got >= min_s, round(got, 2), f"{hand} hand at the face >= {min_s} s"


def hand_pumps(b: BodyFrame, hand: str = "either", axis: str = "up",
               min_turns: int = PUMP_MIN_TURNS):
    """A hand goes to and fro along a body axis (up, forward, side) in quick strokes of ≥ 15 cm, in place: hammering, scrubbing, sawing."""
    got = {s: pumps(b, s, axis) for s in m.SIDES}
    sides = _sides(hand)
    ok = (all if hand == "both" else any)(got[s] >= min_turns for s in sides)
    return ok, got, f"{hand} hand: ≥ {min_turns} quick reversals of ≥ {PUMP_AMPLITUDE_M} m along {axis}"


def lies_on(b: BodyFrame, side: str = "front", min_s: float = 1.0):
    """Lying face down (`side` front: plank, press-ups, swimming strokes) or on the back for ≥ `min_s` s: torso flat, chest to the floor or the sky."""
    got = _longest(lying_on(b, side))
    return got >= min_s, round(got, 2), f"torso flat, chest {'down' if side == 'front' else 'up'}, >= {min_s} s"


def sit_ups(b: BodyFrame, count: int | None = None, at_least: int | None = None):
    """Sit-ups: from lying on the back the torso curls up to within 35° of vertical and lies back, the pelvis staying low."""
    n = len(curls(b))
    ok, bound = count_ok(n, count, at_least)
    return ok, n, bound


def uneven_gait(b: BodyFrame, min_diff: float = GAIT_UNEVEN):
    """A limp: the time on one foot alone differs by ≥ 30 % between the feet, over ≥ three steps on each."""
    st = {s: single_support(b, s) for s in m.SIDES}
    if min(len(v) for v in st.values()) < GAIT_MIN_STEPS // 2:
        return False, {s: len(v) for s, v in st.items()}, f"≥ {GAIT_MIN_STEPS // 2} steps on each foot"
    mean = {s: float(np.mean(v)) for s, v in st.items()}
    diff = abs(mean["left"] - mean["right"]) / max(mean.values())
    return diff >= min_diff, round(diff, 2), f"time on one foot differs by ≥ {min_diff:.0%} between the feet"


SINGLE: list[Callable[..., tuple[bool, Any, str]]] = [hands_meet, hand_to_face, hand_pumps, lies_on, sit_ups, uneven_gait]
