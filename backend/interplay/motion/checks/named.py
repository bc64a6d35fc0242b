"""Named checks of a motion, each a small function of the joints (one or two people) that
returns a `Result`: passed or not, the measured value and the bound it was held to. A prompt
suite names them (`{"check": "jump_count", "count": 3}`) and `run_check` looks them up in
`CHECKS`; `plausibility` runs the checks every output gets.

    people = [joints]                                    # one (T, 22, 3) array per person
    run_check(people, {"check": "travel_direction", "direction": "backward"})
    plausibility(people, start="standing", contact=False)   # [Result, …]

One-person checks take `person`: 0 or 1 (that person), "any" (someone does it, the default for
two people) or "both". Every bound is a named constant here or in `measures.py`, with where
its value comes from.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.bodyframe import BodyFrame
from interplay.motion.checks import contact, everyday, heads
from interplay.motion.checks import measures as m
from interplay.motion.checks.contact import riding as _riding
from interplay.motion.signals import fill_gaps, runs, zigzag

FPS = sk.FPS

# --- plausibility (every output) ---
POP_M = 0.10               # a pelvis step departing this far from its neighbours' is a jump cut
GROUND_M = 0.05            # the body's lowest point over / under the floor by more than this …
GROUND_S = 0.3             # … for longer than this is floating / sinking
# Two bodies passing through each other: share of frames in which a sphere of one body sinks
# more than OVERLAP_DEPTH_M into the other (measures.body_overlap: hands never count; for
# prompts that ask for contact — holding, hugging, pushing, dancing as a couple — forearms
# neither). Captured salsa (CMU, 14 pairs holding hands and turning close) does it in 0–6 % of
# its frames counted as contact, 0–32 % with its forearms counted; the bound of 10 % passes
# every captured pair at its real rate and fails any pair that stands or walks inside the other.
OVERLAP_DEPTH_M = 0.02
OVERLAP_SHARE = 0.10

# --- speeds (m/s, median over the frames between the first and the last that move) ---
SPEED_BANDS: dict[str, tuple[float, float]] = {
    "slow": (0.15, 0.90),   # captured sneaks 0.5–0.7, the slowest "slow walks" ~0.9
    "walk": (0.70, 1.90),   # captured walks 0.9–1.7 (strides included)
    "jog": (1.50, 3.20),    # captured jogs 1.7–2.6 (HDM05's in tight circles ~1.7)
    "run": (2.40, 99.0),    # captured runs 2.7–3.5
    "sprint": (3.00, 99.0),  # captured runs top out near 3.5–4 m/s
}
ZIGZAG_BEND = 0.10          # a zigzag's legs: RMS off straight ≤ 10 % of a leg (a real walk along
                            # a zigzag the trajectory stage rounds: ~0.08; a circle's arcs: ~0.2)
MOVING_SPEED = 0.3          # m/s: frames faster than this are travelling
MOVING_SHARE = 0.5          # a speed band needs travel over half the clip

HAND_TOUCH_M = 0.05         # hands "within 5 cm": hand surfaces (body.py's hand spheres) that close
PUMP_M = 0.02               # a handshake pumps: the joined hands go up and down ≥ 2 cm each way …
PUMP_TURNS = 2              # … turning at least twice (down-up-down)
HIGH_FIVE_APPROACH = 0.8   # m/s: hands swung together (composed high fives meet at 1.1–2.4 m/s;
                           # joined hands raised in a salsa turn drift up at < 0.5) …
HIGH_FIVE_MAX_S = 0.75     # … and part again (salsa partners keep raised hands joined for a turn)
PUSH_CONTACT_M = 0.05       # a pushing hand within 5 cm of the partner's trunk
PUSH_AWAY_M = 0.4           # the partner's pelvis then ≥ 40 cm from where it was …
PUSH_WITHIN_S = 1.0         # … within a second of the contact …
PUSH_MAX_TURN_DEG = 90.0    # … knocked back, not spun out (a salsa lead sends the follower
                            # away turning)
STILL_SPEED = 0.2           # m/s: stopped
WALK_SPEED = 0.8            # m/s: still walking


@dataclass(frozen=True)
class Result:
    check: str
    passed: bool
    value: Any              # what was measured (a number, a count or a short list)
    bound: str              # what it was held to
    person: int | str | None = None

    def to_json(self) -> dict:
        v = self.value
        if isinstance(v, (np.floating, float)):
            v = round(float(v), 4)
        elif isinstance(v, np.integer):
            v = int(v)
        return {"check": self.check, "passed": bool(self.passed), "value": v,
                "bound": self.bound, "person": self.person}


Single = Callable[..., tuple[bool, Any, str]]      # (BodyFrame, **params) → (passed, value, bound)
Pair = Callable[..., tuple[bool, Any, str]]        # (joints a, joints b, frames, **params)


@dataclass(frozen=True)
class Spec:
    fn: Callable[..., tuple[bool, Any, str]]
    persons: int                       # 1: a one-person check (per person), 2: needs both
    doc: str
    base: bool = False                 # compares an edited motion with its base (heads.AGAINST_BASE)


CHECKS: dict[str, Spec] = {}


def single(fn: Single) -> Single:
    CHECKS[fn.__name__] = Spec(fn, 1, (fn.__doc__ or "").strip().split("\n")[0])
    return fn


def pair(fn: Pair) -> Pair:
    CHECKS[fn.__name__] = Spec(fn, 2, (fn.__doc__ or "").strip().split("\n")[0])
    return fn


def _longest(mask: np.ndarray) -> float:
    """Seconds of the longest run of True (single-frame gaps filled)."""
    r = runs(fill_gaps(mask))
    return max((e - s for s, e in r), default=0) / FPS


def against_base(fn: Callable[..., tuple[bool, Any, str]]) -> Callable[..., tuple[bool, Any, str]]:
    CHECKS[fn.__name__] = Spec(fn, 1, (fn.__doc__ or "").strip().split("\n")[0], base=True)
    return fn


# The fresh split's checks of everyday actions, heads, touches and edits (their own modules).
for _fn in everyday.SINGLE + heads.SINGLE:
    single(_fn)
for _fn in contact.PAIR:
    pair(_fn)
for _fn in heads.AGAINST_BASE:
    against_base(_fn)


# ---- one person: counts ----------------------------------------------------------------------

@single
def jump_count(b: BodyFrame, count: int | None = None, at_least: int | None = None):
    """Jumps and hops: flights (both feet off the floor 0.1–1 s) that lift the pelvis over standing height."""
    n = len(m.jumps(b))
    ok, bound = everyday.count_ok(n, count, at_least)
    return ok, n, bound


@single
def squat_count(b: BodyFrame, count: int | None = None, at_least: int | None = None):
    """Squats: pelvis dips under 75 % of standing height and back over 88 %, feet down, not a jump's crouch."""
    n = len(m.squats(b))
    ok, bound = everyday.count_ok(n, count, at_least)
    return ok, n, bound


@single
def kick(b: BodyFrame, leg: str = "any", count: int | None = None, at_least: int | None = None,
         height: float = m.KICK_HEIGHT_M):
    """Kicks with the named leg (and none with the other): foot ≥ `height` m up, ≥ 40 cm ahead, knee open, fast."""
    found = {s: m.kicks(b, s, height) for s in m.SIDES}
    if leg == "any":
        n, wrong = len(found["left"]) + len(found["right"]), 0
    else:
        n, wrong = len(found[leg]), len(found["right" if leg == "left" else "left"])
    ok, bound = everyday.count_ok(n, count, at_least)
    value = {s: [round(h, 2) for _, h in k] for s, k in found.items()}
    return ok and wrong == 0, value, f"{leg} kicks {bound} of ≥ {height:.2f} m" + (
        ", none with the other leg" if leg != "any" else "")


@single
def punch(b: BodyFrame, hand: str = "any", count: int | None = None, at_least: int | None = None):
    """Punches with the named hand: the hand driven forward fast onto a straight arm at chest-to-head height."""
    found = {s: m.punches(b, s) for s in m.SIDES}
    n = len(found["left"]) + len(found["right"]) if hand == "any" else len(found[hand])
    ok, bound = everyday.count_ok(n, count, at_least)
    return ok, {s: len(v) for s, v in found.items()}, f"{hand} punches {bound}"


@single
def step_count(b: BodyFrame, count: int = 1, tolerance: int = 1):
    """Steps: a foot lifted and put down ≥ 15 cm from where it left (± `tolerance`)."""
    n = m.steps(b)
    return abs(n - count) <= tolerance, n, f"{count} ± {tolerance}"


@single
def knee_raise(b: BodyFrame, at_least: int = 2):
    """Knees raised to about hip height (marching, high knees): thigh ≥ 60° up, that foot off the floor."""
    n = len(m.knee_raises(b))
    return n >= at_least, n, f">= {at_least}"


# ---- one person: travel ----------------------------------------------------------------------

@single
def travel_direction(b: BodyFrame, direction: str = "forward", share: float = 0.6,
                     min_m: float = 0.5):
    """Travel relative to where the body faces: ≥ `share` of the distance (and ≥ `min_m` m) that way."""
    t = m.travel(b)
    total = sum(t.values())
    got = t["left"] + t["right"] if direction == "sideways" else t[direction]
    frac = got / total if total > 0 else 0.0
    return (frac >= share and got >= min_m), {"share": round(frac, 2), "metres": round(got, 2)}, (
        f"{direction}: share >= {share}, >= {min_m} m")


@single
def speed_band(b: BodyFrame, band: str = "walk"):
    """Travelling speed (median over the moving stretch, which must fill half the clip) in a named band."""
    lo, hi = SPEED_BANDS[band]
    v = m.speed(b)
    go = np.flatnonzero(v > MOVING_SPEED)
    if len(go) < MOVING_SHARE * len(v):
        return False, round(float(np.median(v)), 2), f"{band} {lo}–{hi} m/s over ≥ half the clip"
    med = float(np.median(v[go[0]:go[-1] + 1]))
    return lo <= med <= hi, round(med, 2), f"{band} {lo}–{hi} m/s"


@single
def travels(b: BodyFrame, min_m: float = 1.0):
    """The pelvis ends ≥ `min_m` m (on the floor) from where it started."""
    d = float(np.linalg.norm(m.path(b)[-1] - m.path(b)[0]))
    return d >= min_m, round(d, 2), f">= {min_m} m"


@single
def stays_in_place(b: BodyFrame, max_m: float = 0.6):
    """The pelvis never goes more than `max_m` m (on the floor) from where it started."""
    p = m.path(b)
    d = float(np.linalg.norm(p - p[0], axis=1).max())
    return d <= max_m, round(d, 2), f"<= {max_m} m"


@single
def turn(b: BodyFrame, degrees: float = 180.0, direction: str = "any", tolerance: float = 45.0):
    """Net turn of the facing direction: ≥ `degrees` − `tolerance` (left = counterclockwise from above)."""
    h = m.heading(b)
    net = float(h[-1] - h[0])
    need = degrees - tolerance
    ok = {"left": net >= need, "right": -net >= need}.get(direction, abs(net) >= need)
    return ok, round(net), f"{direction} >= {need:.0f}°"


@single
def path_shape(b: BodyFrame, shape: str = "circle", max_distance: float = 0.07,
               min_size: float = 1.0):
    """The pelvis path's distance from a named shape (closed shapes: the nearest of the closed set)."""
    p = m.moving_path(b)
    size = float(np.linalg.norm(p.max(0) - p.min(0)))
    if size < min_size:
        return False, {"size_m": round(size, 2)}, f"{shape}: path ≥ {min_size} m across"
    if shape in m.CLOSED_SHAPES:
        d = {s: m.shape_distance(p, s) for s in m.CLOSED_SHAPES}
        nearest = min(d, key=lambda k: d[k])
        return (d[shape] <= max_distance and nearest == shape), {
            "distance": round(d[shape], 3), "nearest": nearest}, f"{shape} distance <= {max_distance}, nearest"
    if shape in ("line", "straight"):
        chord = p[-1] - p[0]
        length = float(np.linalg.norm(chord))
        normal = np.array([-chord[1], chord[0]]) / max(length, 1e-9)
        dev = float(np.abs((p - p[0]) @ normal).max())
        return (length >= 2 * min_size and dev <= 0.1 * length), {
            "length_m": round(length, 2), "deviation_m": round(dev, 2)}, "≥ 2 m, off the chord ≤ 10 %"
    if shape == "zigzag":
        turns, bend = m.zigzag_legs(p)
        return (turns >= 2 and bend <= ZIGZAG_BEND), {"turns": turns, "bend": round(bend, 3)}, (
            f"≥ 2 sideways turns of ≥ 25 cm, legs within {ZIGZAG_BEND:.0%} of straight")
    if shape in ("arc", "semicircle"):
        centre, r, res = m.fit_circle(p)
        swept = abs(m.swept_angle(p, centre))
        lo, hi = (60, 300) if shape == "arc" else (135, 240)
        return (res <= 0.1 and lo <= swept <= hi), {"swept_deg": round(swept), "residual": round(res, 3)}, (
            f"{lo}–{hi}° of a circle")
    raise ValueError(f"unknown shape {shape!r}")


@single
def curves(b: BodyFrame, direction: str = "left", min_deg: float = 45.0):
    """The travel direction bends ≥ `min_deg` to the named side (a curve or a circle walked that way)."""
    p = m.moving_path(b)
    step = np.diff(p, axis=0)
    keep = np.linalg.norm(step, axis=1) > 1e-4
    course = np.degrees(np.unwrap(np.arctan2(step[keep, 0], step[keep, 1]))) if keep.sum() > 2 else np.zeros(2)
    net = float(course[-1] - course[0])                     # + towards +X: the walker's left
    ok = net >= min_deg if direction == "left" else -net >= min_deg
    return ok, round(net), f"{direction} >= {min_deg}°"


# ---- one person: arms, poses, postures --------------------------------------------------------

def _hands(hand: str) -> tuple[str, ...]:
    return {"either": m.SIDES, "any": m.SIDES, "both": m.SIDES}.get(hand, (hand,))


@single
def hand_raised(b: BodyFrame, hand: str = "either", level: str = "overhead", min_s: float = 1.0):
    """A hand held over the head (`level` overhead / head / shoulder) for ≥ `min_s` s (both: together)."""
    masks = [m.hand_over(b, s, level) for s in _hands(hand)]
    if hand == "both":
        got = _longest(np.logical_and.reduce(masks))
    else:
        got = max(_longest(x) for x in masks)
    return got >= min_s, round(got, 2), f"{hand} hand {level} >= {min_s} s"


@single
def wave(b: BodyFrame, hand: str = "either", level: str = "shoulder", min_turns: int = m.WAVE_MIN_TURNS):
    """A wave: the raised hand (over its shoulder, or `level` head / overhead) swings side to side ≥ 1.5 times, quickly."""
    best = {s: max((k for _, _, k in m.waves(b, s, level)), default=0) for s in m.SIDES}
    sides = _hands(hand)
    ok = all(best[s] >= min_turns for s in sides) if hand == "both" else any(
        best[s] >= min_turns for s in sides)
    return ok, best, f"{hand} hand: ≥ {min_turns} quick reversals with the hand at {level} level"


POSES: dict[str, Callable[[BodyFrame], np.ndarray]] = {
    "t_pose": lambda b: m.arm_horizontal(b, "left") & m.arm_horizontal(b, "right"),
    "arms_up": lambda b: m.hand_over(b, "left", "overhead") & m.hand_over(b, "right", "overhead"),
    "hands_on_hips": m.hands_on_hips,
    "arms_crossed": m.arms_crossed,
    "arms_forward": m.arms_forward,
    "one_leg": m.one_leg,
    "squat": lambda b: (m.pelvis_ratio(b) < m.SQUAT_DOWN) & ~m.lying(b) & (m.lowest_foot(b) <= m.FOOT_DOWN_M),
    **m.POSTURES,
}


@single
def pose_held(b: BodyFrame, pose: str = "t_pose", min_s: float = 1.0):
    """A named pose (T-pose, arms up, hands on hips, arms crossed, one leg, squat, a posture) held ≥ `min_s` s."""
    got = _longest(POSES[pose](b))
    return got >= min_s, round(got, 2), f"{pose} >= {min_s} s"


def _posture_mask(b: BodyFrame, posture: str) -> np.ndarray:
    if posture == "low":                    # anything but standing: lying, sitting, kneeling …
        return ~m.standing(b) & (m.pelvis_ratio(b) < m.STAND_RATIO)
    return POSES[posture](b)


@single
def posture_at_end(b: BodyFrame, posture: str = "lying", seconds: float = 0.5):
    """The last `seconds` s in a posture (lying, sitting, kneeling, standing, all fours, low)."""
    n = m.frames(seconds)
    share = float(_posture_mask(b, posture)[-n:].mean())
    return share >= 0.8, round(share, 2), f"{posture} in ≥ 80 % of the last {seconds} s"


@single
def posture_at_start(b: BodyFrame, posture: str = "standing"):
    """The first frame in a posture (standing, lying, sitting, kneeling, all fours, low)."""
    first = bool(_posture_mask(b, posture)[0])
    return first, first, f"{posture} on the first frame"


@single
def crawl(b: BodyFrame, min_s: float = 1.0, min_m: float = 0.5):
    """Crawling: low and prone with a hand on the floor, for ≥ `min_s` s, travelling ≥ `min_m` m."""
    mask = fill_gaps(m.crawling_posture(b))
    p = m.path(b)
    best_s, best_m = 0.0, 0.0
    for s, e in runs(mask):
        best_s = max(best_s, (e - s) / FPS)
        best_m = max(best_m, float(np.linalg.norm(p[e - 1] - p[s])))
    return best_s >= min_s and best_m >= min_m, {"seconds": round(best_s, 2), "metres": round(best_m, 2)}, (
        f"crawling posture >= {min_s} s and >= {min_m} m")


def _bows(b: BodyFrame, min_deg: float) -> list[tuple[int, int, float]]:
    """(start, end, deepest lean) of each bow: the torso leans forward ≥ `min_deg` and comes
    back within 15° of upright, in place (pelvis slower than 0.4 m/s), feet on the floor and
    the pelvis high (≥ 75 % of standing: not a squat, a kick, a dash or a dancer's arabesque)."""
    lean_, ratio, v = m.torso_lean(b), m.pelvis_ratio(b), m.speed(b)
    feet = np.maximum(b.foot_height("left"), b.foot_height("right")) <= m.FOOT_DOWN_M
    out = []
    for s, e in runs(lean_ >= min_deg):
        if (e < len(lean_) and (lean_[e:] <= 15).any() and ratio[s:e].min() >= 0.75
                and v[s:e].max() < 0.4 and feet[s:e].mean() >= 0.8):
            out.append((s, e, float(lean_[s:e].max())))
    return out


@single
def bow(b: BodyFrame, min_deg: float = 30.0):
    """A bow: the torso leans ≥ `min_deg` forward and back up, in place, feet down, pelvis high."""
    best = max((d for _, _, d in _bows(b, min_deg)), default=0.0)
    return best >= min_deg, round(best), f"lean >= {min_deg}° and back, in place, feet down"


@single
def lean(b: BodyFrame, min_deg: float = -90.0, max_deg: float = 90.0):
    """Median forward lean of the torso within [min_deg, max_deg] (a hunched walk, an upright march)."""
    v = float(np.median(m.torso_lean(b)))
    return min_deg <= v <= max_deg, round(v, 1), f"{min_deg}° … {max_deg}°"


@single
def active(b: BodyFrame, min_speed: float = 0.4):
    """The limbs keep moving (dancing, fighting, exercising): wrists and ankles ≥ `min_speed` m/s on average."""
    v = float(m.limb_speed(b).mean())
    return v >= min_speed, round(v, 2), f">= {min_speed} m/s"


@single
def still(b: BodyFrame, max_speed: float = 0.15, max_m: float = 0.3):
    """Standing still: wrists and ankles under `max_speed` m/s on average, the pelvis within `max_m` m."""
    v = float(m.limb_speed(b).mean())
    p = m.path(b)
    d = float(np.linalg.norm(p - p[0], axis=1).max())
    return v <= max_speed and d <= max_m, {"limb_speed": round(v, 2), "drift_m": round(d, 2)}, (
        f"limbs ≤ {max_speed} m/s, pelvis within {max_m} m")


# ---- one person: order of events -------------------------------------------------------------

def _onsets(mask: np.ndarray, min_s: float) -> list[int]:
    return [s for s, e in runs(fill_gaps(mask)) if e - s >= m.frames(min_s)]


def events(b: BodyFrame) -> dict[str, list[int]]:
    """Frames at which things happen, by kind: squat, jump, kick, kick_left/right, punch, wave,
    raise_hand, walk / jog / run (a stretch of ≥ 1 s in that speed band), move, stop, sit,
    lie, kneel, stand (a posture taken for ≥ 0.5 s), turn (≥ 90° within 2 s), bow."""
    out: dict[str, list[int]] = {"squat": [mid for _, mid, _ in m.squats(b)],
                                 "jump": [(s + e) // 2 for s, e in m.jumps(b)]}
    for side in m.SIDES:
        out[f"kick_{side}"] = [f for f, _ in m.kicks(b, side)]
        out[f"punch_{side}"] = m.punches(b, side)
    out["kick"] = sorted(out["kick_left"] + out["kick_right"])
    out["punch"] = sorted(out["punch_left"] + out["punch_right"])
    out["wave"] = sorted(s for side in m.SIDES for s, _, _ in m.waves(b, side, "shoulder"))
    out["raise_hand"] = sorted(s for side in m.SIDES
                               for s in _onsets(m.hand_over(b, side, "overhead"), 0.5))
    v = m.speed(b)
    for band in ("walk", "jog", "run"):
        lo, hi = SPEED_BANDS[band]
        out[band] = _onsets((v >= lo) & (v <= hi), 1.0)
    out["move"] = _onsets(v > MOVING_SPEED + 0.1, 1.0)
    moved = np.maximum.accumulate(v > MOVING_SPEED + 0.1)
    out["stop"] = _onsets((v < STILL_SPEED) & moved, 0.75)
    for name, posture in (("sit", "sitting"), ("lie", "lying"), ("kneel", "kneeling"),
                          ("stand", "standing")):
        out[name] = _onsets(m.POSTURES[posture](b), 0.5)
    h = m.heading(b)
    n = m.frames(2.0)
    turning = np.abs(h[np.minimum(np.arange(len(h)) + n, len(h) - 1)] - h) >= 90
    out["turn"] = _onsets(turning, 0.1)
    out["bow"] = [s for s, _, _ in _bows(b, 30.0)]
    return out


@single
def sequence(b: BodyFrame, steps: list | None = None):
    """Events in order: each step (an event kind, or {"event": kind, "count": n}) after the one before."""
    ev = events(b)
    t, found = -1, []  # type: tuple[int, list[str]]
    for step in steps or []:
        kind, n = (step, 1) if isinstance(step, str) else (step["event"], int(step.get("count", 1)))
        later = [f for f in ev[kind] if f > t]
        if len(later) < n:
            return False, found + [f"no {kind}" + (f" ×{n}" if n > 1 else "")], " then ".join(
                s if isinstance(s, str) else f"{s['event']}×{s.get('count', 1)}" for s in steps or [])
        t = later[n - 1]
        found.append(f"{kind}@{t / FPS:.1f}s")
    return True, found, "in order"


# ---- two people -------------------------------------------------------------------------------

def _run_seconds(mask: np.ndarray) -> tuple[float, tuple[int, int] | None]:
    r = runs(fill_gaps(mask))
    if not r:
        return 0.0, None
    s, e = max(r, key=lambda x: x[1] - x[0])
    return (e - s) / FPS, (s, e)


@pair
def handshake(a, b, fa, fb, min_s: float = 1.0):
    """Right hands within 5 cm for ≥ `min_s` s, pumping up and down (≥ 2 turns of ≥ 2 cm)."""
    gap = m.hand_gap(a, b, "right", "right")
    secs, span = _run_seconds(gap <= HAND_TOUCH_M)
    turns = 0
    if span is not None:
        s, e = span
        y = 0.5 * (m.hand_point(a, "right")[s:e, 1] + m.hand_point(b, "right")[s:e, 1])
        turns = len(zigzag(y, PUMP_M))
    return secs >= min_s and turns >= PUMP_TURNS, {"seconds": round(secs, 2), "pumps": turns,
                                                    "closest_m": round(float(gap.min()), 3)}, (
        f"right hands ≤ {HAND_TOUCH_M} m for ≥ {min_s} s, ≥ {PUMP_TURNS} vertical turns")


@pair
def high_five(a, b, fa, fb, approach: float = HIGH_FIVE_APPROACH):
    """Facing each other, one hand of each meets the other's (within 5 cm) above both shoulders, swung in fast, briefly."""
    best = 0.0
    top = np.maximum(a[:, [sk.LEFT_SHOULDER, sk.RIGHT_SHOULDER], 1].max(1),
                     b[:, [sk.LEFT_SHOULDER, sk.RIGHT_SHOULDER], 1].max(1))
    back = m.frames(0.25)
    facing = _facing_each_other(a, b, fa, fb, 60.0)
    gaps = {(sa, sb): m.hand_gap(a, b, sa, sb) for sa in m.SIDES for sb in m.SIDES}
    for (sa, sb), gap in gaps.items():
        others = np.min([g for (oa, ob), g in gaps.items() if oa != sa and ob != sb], axis=0)
        ha, hb = m.hand_point(a, sa), m.hand_point(b, sb)
        meet = ((gap <= HAND_TOUCH_M) & (0.5 * (ha[:, 1] + hb[:, 1]) > top) & facing
                & (others > HAND_TOUCH_M))
        rel = np.linalg.norm(np.gradient(ha - hb, axis=0), axis=1) * FPS
        for s, e in runs(meet):
            if e - s <= HIGH_FIVE_MAX_S * FPS:
                best = max(best, float(rel[max(0, s - back):s + 1].max()))
    return best >= approach, round(best, 2), (
        f"hands ≤ {HAND_TOUCH_M} m above both shoulders for ≤ {HIGH_FIVE_MAX_S} s, met at ≥ {approach} m/s")


@pair
def hands_held(a, b, fa, fb, min_s: float = 2.0):
    """A hand of each within 5 cm of a hand of the other for ≥ `min_s` s (holding hands)."""
    gap = np.min([m.hand_gap(a, b, sa, sb) for sa in m.SIDES for sb in m.SIDES], axis=0)
    secs, _ = _run_seconds(gap <= HAND_TOUCH_M)
    return secs >= min_s, round(secs, 2), f"hands ≤ {HAND_TOUCH_M} m for ≥ {min_s} s"


@pair
def hug(a, b, fa, fb, min_s: float = 1.0, who: str = "both"):
    """Arms round the partner: a wrist behind the partner's torso plane (near their back) for ≥ `min_s` s, both at once."""
    ha = m.behind_torso(a, fb, "left") | m.behind_torso(a, fb, "right")
    hb = m.behind_torso(b, fa, "left") | m.behind_torso(b, fa, "right")
    if who == "both":
        secs, _ = _run_seconds(ha & hb)
    else:
        secs = max(_run_seconds(ha)[0], _run_seconds(hb)[0])
    return secs >= min_s, round(secs, 2), f"{who}: a wrist behind the partner's back ≥ {min_s} s"


@pair
def push(a, b, fa, fb, min_m: float = PUSH_AWAY_M, within_s: float = PUSH_WITHIN_S):
    """A hand on the partner's trunk (≤ 5 cm), then the partner's pelvis ≥ 0.4 m further away within 1 s."""
    best = 0.0
    n = m.frames(within_s)
    for pusher, pushed in ((a, b), (b, a)):
        touch = np.min([m.hand_to_trunk(pusher, pushed, s) for s in m.SIDES], axis=0) <= PUSH_CONTACT_M
        pel = pushed[:, sk.PELVIS][:, [0, 2]]
        src = pusher[:, sk.PELVIS][:, [0, 2]]
        turned = m.heading(fb if pushed is b else fa)
        for s, _ in runs(touch):
            away = pel[s] - src[s]
            away = away / max(float(np.linalg.norm(away)), 1e-9)
            moved = ((pel[s:s + n + 1] - pel[s]) @ away).max()       # displacement away from the pusher
            spin = np.abs(turned[s:s + n + 1] - turned[s]).max()
            if spin <= PUSH_MAX_TURN_DEG:
                best = max(best, float(moved))
    return best >= min_m, round(best, 2), (
        f"trunk touched, then ≥ {min_m} m away within {within_s} s, not turning > {PUSH_MAX_TURN_DEG:.0f}°")


@pair
def wave_back(a, b, fa, fb, delay_s: float = 0.3):
    """One waves (hand over the shoulder, side to side, not holding the other's), the other starts ≥ `delay_s` s later."""
    def onset(f, me, other):
        free = np.min([m.hand_gap(me, other, s, t) for s in m.SIDES for t in m.SIDES], axis=0) > 0.15
        starts = [s for side in m.SIDES for s, e, _ in m.waves(f, side, "shoulder") if free[s:e].all()]
        return min(starts) if starts else None
    ta, tb = onset(fa, a, b), onset(fb, b, a)
    if ta is None or tb is None:
        return False, {"onsets_s": [None if t is None else round(t / FPS, 2) for t in (ta, tb)]}, (
            "both wave, one after the other")
    gap = abs(ta - tb) / FPS
    return gap >= delay_s, {"onsets_s": [round(ta / FPS, 2), round(tb / FPS, 2)]}, (
        f"the second wave starts ≥ {delay_s} s after the first")


@pair
def one_stops(a, b, fa, fb, last_s: float = 2.0):
    """Over the last `last_s` s one is under 0.2 m/s while the other is over 0.8 m/s."""
    n = m.frames(last_s)
    va, vb = float(m.speed(fa)[-n:].mean()), float(m.speed(fb)[-n:].mean())
    lo, hi = min(va, vb), max(va, vb)
    return lo < STILL_SPEED and hi > WALK_SPEED, {"speeds": [round(va, 2), round(vb, 2)]}, (
        f"one < {STILL_SPEED}, the other > {WALK_SPEED} m/s in the last {last_s} s")


@pair
def side_by_side(a, b, fa, fb, seconds: float = 2.0):
    """Both walking (> 0.5 m/s) the same way, 0.3–1.5 m apart mostly side to side, for ≥ `seconds` s."""
    va, vb = m.speed(fa), m.speed(fb)
    d = b[:, sk.PELVIS][:, [0, 2]] - a[:, sk.PELVIS][:, [0, 2]]
    dist = np.linalg.norm(d, axis=1)
    fwd = fa.forward[:, [0, 2]]
    ahead = np.abs((d * fwd).sum(1))
    same = (fa.forward * fb.forward).sum(1) > np.cos(np.radians(45))
    ok = (va > 0.5) & (vb > 0.5) & (dist >= 0.3) & (dist <= 1.5) & (ahead < 0.7 * dist) & same
    secs, _ = _run_seconds(ok)
    return secs >= seconds, round(secs, 2), f"side by side, walking, ≥ {seconds} s"


@pair
def follows(a, b, fa, fb, min_m: float = 1.5, share: float = 0.6):
    """Both travel ≥ `min_m` m the same way, one behind the other (0.5–4 m) most of the way."""
    best = 0.0
    for lead, foll, fl in ((a, b, fa), (b, a, fb)):
        d = foll[:, sk.PELVIS][:, [0, 2]] - lead[:, sk.PELVIS][:, [0, 2]]
        dist = np.linalg.norm(d, axis=1)
        move = np.gradient(m.path(fl), axis=0)
        dirn = move / np.maximum(np.linalg.norm(move, axis=1, keepdims=True), 1e-9)
        behind = ((d * dirn).sum(1) < -0.5 * dist) & (dist >= 0.5) & (dist <= 4.0)
        best = max(best, float(behind[m.speed(fl) > MOVING_SPEED].mean()) if (m.speed(fl) > MOVING_SPEED).any() else 0.0)
    travelled = min(m.path_length(fa), m.path_length(fb))
    return best >= share and travelled >= min_m, {"behind_share": round(best, 2), "metres": round(travelled, 2)}, (
        f"one behind the other ≥ {share} of the way, both ≥ {min_m} m")


def _facing_each_other(a, b, fa, fb, within_deg: float) -> np.ndarray:
    """(T,) bool: each faces the other's pelvis within `within_deg`."""
    d = b[:, sk.PELVIS][:, [0, 2]] - a[:, sk.PELVIS][:, [0, 2]]
    d = d / np.maximum(np.linalg.norm(d, axis=1, keepdims=True), 1e-9)
    cos = np.cos(np.radians(within_deg))
    return ((fa.forward[:, [0, 2]] * d).sum(1) >= cos) & ((fb.forward[:, [0, 2]] * -d).sum(1) >= cos)


@pair
def face_each_other(a, b, fa, fb, share: float = 0.6, within_deg: float = 45.0):
    """Each faces the other (within `within_deg`) in ≥ `share` of the frames."""
    got = float(_facing_each_other(a, b, fa, fb, within_deg).mean())
    return got >= share, round(got, 2), f"≥ {share} of frames"


@pair
def mirrors(a, b, fa, fb, min_corr: float = 0.5):
    """One moves as the other's mirror image: limb velocities correlate ≥ `min_corr` with left and right swapped."""
    c = m.mirror_correlation(fa, fb)
    moving = min(float(m.limb_speed(fa).mean()), float(m.limb_speed(fb).mean()))
    return c >= min_corr and moving >= 0.2, {"correlation": round(c, 2), "limb_speed": round(moving, 2)}, (
        f"correlation ≥ {min_corr}, both moving")


@pair
def close_together(a, b, fa, fb, max_m: float = 1.2, share: float = 0.8):
    """The pelvises stay within `max_m` m of each other in ≥ `share` of the frames (dancing as a couple)."""
    dist = np.linalg.norm(a[:, sk.PELVIS][:, [0, 2]] - b[:, sk.PELVIS][:, [0, 2]], axis=1)
    got = float((dist <= max_m).mean())
    return got >= share, round(got, 2), f"≤ {max_m} m in ≥ {share} of frames"


@pair
def partner_spin(a, b, fa, fb, min_deg: float = 300.0, within_s: float = 2.5, max_m: float = 1.2):
    """One spins (the facing turns ≥ `min_deg` within `within_s` s) close to the other (pelvises ≤ `max_m` m), who turns under half that."""
    n = min(m.frames(within_s), len(a) - 1)
    best = float(m.partner_turns(a, b, fa, fb, n, max_m).max()) if n >= 1 else 0.0
    return best >= min_deg, round(best), (
        f"one turns ≥ {min_deg:.0f}° in {within_s} s within {max_m} m of the other, who turns under half that")


@pair
def approach(a, b, fa, fb, min_m: float = 1.0):
    """The two come ≥ `min_m` m closer (pelvis distance, first frame to closest)."""
    dist = np.linalg.norm(a[:, sk.PELVIS][:, [0, 2]] - b[:, sk.PELVIS][:, [0, 2]], axis=1)
    got = float(dist[0] - dist.min())
    return got >= min_m, round(got, 2), f"≥ {min_m} m closer"


# ---- two people: composed kinds of issue 24 (help up, spar, hand over, touch, chase) ---------

@pair
def helped_up(a, b, fa, fb, min_s: float = 0.3):
    """One goes from the floor (pelvis under 60 % of standing height) to standing, a hand of each joined (≤ 5 cm) ≥ `min_s` s while they rise, the other standing."""
    best = 0.0
    gap = np.min([m.hand_gap(a, b, sa, sb) for sa in m.SIDES for sb in m.SIDES], axis=0)
    for fr, fh in ((fa, fb), (fb, fa)):
        ratio = m.pelvis_ratio(fr)
        if not (ratio[0] < 0.6 and bool(m.standing(fr)[-1])) or float(m.standing(fh).mean()) < 0.8:
            continue
        rising = (ratio >= 0.3) & (ratio <= 0.9) & (np.gradient(ratio) > 0)
        best = max(best, _run_seconds(fill_gaps(rising) & (gap <= HAND_TOUCH_M))[0])
    return best >= min_s, round(best, 2), f"hands joined ≤ {HAND_TOUCH_M} m ≥ {min_s} s while one rises from the floor"


@pair
def spar(a, b, fa, fb, min_m: float = 0.9, max_m: float = 2.0, within_deg: float = 60.0):
    """Facing each other (within 60°) most of the time, `min_m`–`max_m` m apart, each throwing a punch or kick, not both at once."""
    dist = np.median(np.linalg.norm(a[:, sk.PELVIS][:, [0, 2]] - b[:, sk.PELVIS][:, [0, 2]], axis=1))
    facing = float(_facing_each_other(a, b, fa, fb, within_deg).mean())
    blows = [sorted(e["punch"] + e["kick"]) for e in (events(fa), events(fb))]
    apart = all(blows) and abs(blows[0][0] - blows[1][0]) >= 2
    ok = min_m <= dist <= max_m and facing >= 0.5 and bool(apart)
    return bool(ok), {"distance_m": round(float(dist), 2), "facing": round(facing, 2),
                      "blows": [len(x) for x in blows]}, (
        f"{min_m}–{max_m} m apart, facing ≥ half the time, both strike, at different times")


@pair
def hand_over(a, b, fa, fb, max_m: float = contact.HANDS_MEET_M, hold_s: float = 0.5):
    """A hand of each meets the other's (≤ 10 cm), then they part and the receiving hand stays up in front of its owner (≥ 10 cm over the pelvis, ≥ 15 cm ahead) for ≥ `hold_s` s."""
    best = 0.0
    for sa in m.SIDES:
        for sb in m.SIDES:
            gap = m.hand_gap(a, b, sa, sb)
            met = np.flatnonzero(gap <= max_m)
            if not len(met):
                continue
            after = slice(int(met[-1]) + 1, None)
            for j, f, side in ((a, fa, sa), (b, fb, sb)):
                rel = f.local(m.hand_point(j, side) - j[:, sk.PELVIS])
                up = (rel[1] >= 0.10) & (rel[2] >= 0.15) & (gap > max_m + 0.1)
                best = max(best, _run_seconds(up[after])[0])
    return best >= hold_s, round(best, 2), f"hands ≤ {max_m} m, then one kept up in front ≥ {hold_s} s"


@pair
def touch_part(a, b, fa, fb, part: str = "any", min_s: float = 0.5):
    """A hand of one on the other's named part (shoulder, back, arm, head, hand; "any") for ≥ `min_s` s."""
    parts = ("shoulder", "back", "arm", "head", "hand") if part == "any" else (part,)
    best = 0.0
    for doer, partner, fp in ((a, b, fb), (b, a, fa)):
        for p in parts:
            if p == "hand":
                gap = np.min([m.hand_gap(doer, partner, s, t) for s in m.SIDES for t in m.SIDES], axis=0)
            else:
                gap = contact.hand_on(doer, partner, fp, p)
            best = max(best, _run_seconds(gap <= contact.TOUCH_M)[0])
    return best >= min_s, round(best, 2), f"a hand on the partner's {part} ≤ {contact.TOUCH_M} m for ≥ {min_s} s"


@pair
def chase(a, b, fa, fb, min_m: float = 2.0, closes_m: float = 0.8):
    """Both travel ≥ `min_m` m the same way, one behind the other, and the one behind closes the gap by ≥ `closes_m` m."""
    dist = np.linalg.norm(a[:, sk.PELVIS][:, [0, 2]] - b[:, sk.PELVIS][:, [0, 2]], axis=1)
    both = (m.speed(fa) > MOVING_SPEED) & (m.speed(fb) > MOVING_SPEED)
    closed = 0.0
    if both.any():
        d = dist[int(np.argmax(both)):]
        closed = float(np.max(np.maximum.accumulate(d) - d))
    fol = follows(a, b, fa, fb, min_m=min_m)
    return bool(fol[0]) and closed >= closes_m, {"closed_m": round(closed, 2), **fol[1]}, (
        f"one behind the other, both ≥ {min_m} m, the gap closed by ≥ {closes_m} m")


# ---- plausibility -----------------------------------------------------------------------------

def no_pops(joints: np.ndarray, frame: BodyFrame) -> tuple[bool, Any, str]:
    """No frame whose pelvis step departs > 10 cm from the steps around it (outside flights)."""
    pops = m.pelvis_pops(joints)
    pops[m.in_flight(frame)] = 0.0
    worst = float(pops.max()) if len(pops) else 0.0
    return worst <= POP_M, {"worst_m": round(worst, 3), "frame": int(np.argmax(pops))}, f"≤ {POP_M} m"


def grounded(joints: np.ndarray, frame: BodyFrame) -> tuple[bool, Any, str]:
    """Feet that carry the body within 5 cm of the floor, and no part of it 5 cm under it, for all but ≤ 0.3 s at a time."""
    feet = m.clearance(joints, sk.FOOT_JOINTS)
    body = m.clearance(joints)
    weight = m.feet_carry(frame) & ~m.in_flight(frame)
    floating = (feet > GROUND_M) & weight
    worst_float = _longest(floating)
    worst_sink = _longest(body < -GROUND_M)
    return (worst_float <= GROUND_S and worst_sink <= GROUND_S), {
        "float_s": round(worst_float, 2), "sink_s": round(worst_sink, 2),
        "max_float_m": round(float(np.where(weight, feet, 0.0).max()), 3),
        "max_sink_m": round(float(max(0.0, -body.min())), 3)}, f"≤ {GROUND_S} s beyond ±{GROUND_M} m"


def no_interpenetration(a: np.ndarray, b: np.ndarray, contact: bool = False) -> tuple[bool, Any, str]:
    """The bodies overlap > 2 cm in ≤ 10 % of the frames (hands aside; forearms too where contact is asked)."""
    share = float(m.body_overlap(a, b, OVERLAP_DEPTH_M, touching=contact).mean())
    parts = "hands and forearms" if contact else "hands"
    return share <= OVERLAP_SHARE, round(share, 3), (
        f"≤ {OVERLAP_SHARE} of frames > {OVERLAP_DEPTH_M} m deep ({parts} aside)")


PLAUSIBILITY = ("no_pops", "grounded", "starts_standing", "no_interpenetration")


def plausibility(people: list[np.ndarray], start: str = "standing", contact: bool = False) -> list[Result]:
    """The checks every output gets: no pelvis pops, grounded, the first frame standing (when
    `start` is "standing"; otherwise in that posture, "any" skips it) and, for two people, no
    interpenetration (with the arms that are asked to touch left out when `contact`). A
    person carried on the other's back (`contact.riding`) is held up by them: their feet
    off the floor there are not floating, so `grounded` judges only their other frames."""
    people = [np.asarray(p, dtype=np.float64) for p in people]
    frames_ = [m.frame_of(p) for p in people]
    out = []
    for i, (p, f) in enumerate(zip(people, frames_)):
        for name, fn in (("no_pops", no_pops), ("grounded", grounded)):
            if name == "grounded" and len(people) == 2:
                up = _riding(p, people[1 - i])
                if up.any():
                    rest = p[~up]
                    ok, v, bound = fn(rest, m.frame_of(rest)) if len(rest) >= 3 else (True, {}, "carried")
                    out.append(Result(name, ok, v, bound, i))
                    continue
            ok, v, bound = fn(p, f)
            out.append(Result(name, ok, v, bound, i))
        if start != "any":
            posture = "standing" if start == "standing" else start
            first = bool(_posture_mask(f, posture)[0])
            out.append(Result("starts_standing" if start == "standing" else f"starts_{start}",
                              first, first, f"{posture} on the first frame", i))
    if len(people) == 2:
        ok, v, bound = no_interpenetration(people[0], people[1], contact)
        out.append(Result("no_interpenetration", ok, v, bound, None))
    return out


# ---- running a check by name --------------------------------------------------------------------

def run_check(people: list[np.ndarray], spec: dict, base: list[np.ndarray] | None = None) -> Result:
    """The check `spec["check"]` with the rest of `spec` as its parameters, on these people.
    One-person checks: `person` 0/1, "any" (default with two people) or "both". Checks of an
    edit (`Spec.base`) compare each person with the same person of `base`, the motion the edit
    was made from."""
    params = dict(spec)
    name = params.pop("check")
    if name not in CHECKS:
        raise ValueError(f"unknown check {name!r}; expected one of {', '.join(sorted(CHECKS))}")
    check = CHECKS[name]
    people = [np.asarray(p, dtype=np.float64) for p in people]
    frames_ = [m.frame_of(p) for p in people]
    if check.persons == 2:
        if len(people) != 2:
            raise ValueError(f"{name} needs two people, got {len(people)}")
        ok, v, bound = check.fn(people[0], people[1], frames_[0], frames_[1], **params)
        return Result(name, bool(ok), v, bound, None)
    args: list[tuple] = [(f,) for f in frames_]
    if check.base:
        if base is None or len(base) != len(people):
            raise ValueError(f"{name} compares an edit with its base motion: pass base=")
        args = [(f, m.frame_of(np.asarray(p, dtype=np.float64))) for f, p in zip(frames_, base)]
    who = params.pop("person", "any" if len(people) == 2 else 0)
    if who in ("any", "both"):
        results = [check.fn(*x, **params) for x in args]
        oks = [r[0] for r in results]
        ok = all(oks) if who == "both" else any(oks)
        return Result(name, bool(ok), [r[1] for r in results], results[0][2], who)
    ok, v, bound = check.fn(*args[int(who)], **params)
    return Result(name, bool(ok), v, bound, int(who))
