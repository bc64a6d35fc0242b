"""Per-frame quantities and events of one or two people's motion that the named checks
(`named.py`) are built on. Joints (T, 22, 3), metres, Y up, 20 fps, the rest pose facing +Z
(a person's left is +X). Each person is measured in their own body frame
(`bodyframe.body_frame`: forward from hips and shoulders, heights above the local floor, the
standing pelvis height from the legs), so nothing depends on where or which way a motion
was made. Bounds are named constants with where their value comes from; "captured" means
the processed real captures in `models/data` (CMU, HDM05, salsa).
"""

from __future__ import annotations

import numpy as np
from numpy.lib.stride_tricks import sliding_window_view

from interplay.motion import skeleton as sk
from interplay.motion.bodyframe import BodyFrame, angle, body_frame
from interplay.motion.pair.body import HAND_SPHERES, SPHERE_JOINT, body_spheres, surface_gaps
from interplay.motion.signals import fill_gaps, runs, smooth, window_percentile, zigzag

FPS = sk.FPS
J = sk.JOINT_INDEX
SIDES = ("left", "right")
UP = np.array([0.0, 1.0, 0.0])

# --- time scales ---
SPEED_SMOOTH_S = 1.0       # root speed averaged over a gait cycle (two steps), so it does not
                           # pulse with each step; a start or a stop still shows within 0.5 s
TRAVEL_SMOOTH_S = 0.5      # pelvis path smoothed over half a second before its direction is read
                           # (the pelvis sways ±2–3 cm sideways with every step)

# --- feet and flight ---
AIRBORNE_M = 0.05          # both feet (the lower of ankle and toe, each above its own standing
                           # level) this far off the floor: in the air
JUMP_RISE_M = 0.08         # pelvis this far over its straight-legged standing height while in
                           # the air: a jump or hop (captured jumps and hops rise 0.2–0.5 m; a
                           # running stride's flight lifts the pelvis ~5 cm)
JUMP_FOOT_M = 0.10         # … with both feet ≥ 10 cm up at the top (captured hops clear 0.2–0.3 m;
                           # a body sinking into the floor lifts its feet off a floor that sinks
                           # with it by a few cm only)
FLIGHT_MIN_FRAMES = 2      # ≥ 0.1 s in the air …
FLIGHT_MAX_S = 1.0         # … and < 1 s (a 50 cm jump is in the air ~0.6 s)
NEAR_FLIGHT_S = 0.15       # take-off and landing frames next to a flight (the pelvis decelerates
                           # hard there) belong to it
BALLISTIC_CURVE = -1.5     # m/s²: the quadratic coefficient of the pelvis height over a flight
                           # (-g/2 = -4.9 for a body in free fall; captured jumps -3 … -6); a
                           # body lifted and held up has ~0 and is floating, not flying

# --- pelvis height (fraction of the standing pelvis height) ---
SQUAT_DOWN = 0.75          # a dip must go below this … (captured HDM05 squats reach 0.45–0.55;
                           # walking dips ~3–5 %, a crouched sneak ~10 %)
SQUAT_UP = 0.88            # … and come back over this to count (hysteresis: one squat, one count)
STAND_RATIO = 0.85         # standing: pelvis at ≥ 85 % of its standing height …
STAND_TILT_DEG = 30.0      # … the torso (pelvis → neck) within 30° of vertical …
FOOT_DOWN_M = 0.10         # … and a foot within 10 cm of the floor
LIE_TILT_DEG = 60.0        # lying: torso ≥ 60° from vertical …
LIE_RATIO = 0.45           # … with the pelvis below 45 % of standing (captured lie-downs end at
                           # ~0.1; a deep forward bend keeps the pelvis over 0.8)
LIE_HEAD_M = 0.50          # … and the head joint within 50 cm of the floor
SIT_RATIO = 0.50           # sitting: not lying, torso within 50° of vertical and the pelvis below
SIT_TILT_DEG = 50.0        # half its standing height (floor sitting puts it at ~0.15–0.3,
                           # sitting back on the heels at ~0.45)
KNEE_DOWN_M = 0.15         # kneeling: a knee joint within 15 cm of the floor (the joint sits
                           # ~6 cm above a kneeling knee's skin) with the torso upright-ish …
KNEEL_TILT_DEG = 45.0
KNEEL_RATIO = (0.30, 0.90)  # … and the pelvis between sitting on the floor and standing
ALL_FOURS_TILT_DEG = 50.0  # on all fours: torso ≥ 50° from vertical, pelvis over 30 % of
ALL_FOURS_RATIO = 0.30     # standing (lying is lower) and both hands within 20 cm of the floor
HAND_FLOOR_M = 0.20

# --- hands and arms ---
HAND_EXTENSION = 0.3       # the hand's centre lies 0.3 forearm lengths past the wrist (body.py's
                           # hand sphere)
HAND_RADIUS_M = 0.045      # body.py's hand sphere; hands "within d" = hand surfaces within d
OVERHEAD_M = 0.15          # a hand overhead: its centre 15 cm over the head joint (which sits at
                           # ear level, ~15 cm under the crown)
WAVE_AMPLITUDE_M = 0.05    # each lateral swing of a waving hand (a tremor or a held arm is less)
WAVE_HALF_PERIOD_S = 0.8   # back and forth at ≥ ~0.6 Hz
WAVE_MIN_TURNS = 3         # ≥ 1.5 swings: side, back, side again
T_ELEVATION_DEG = 25.0     # T-pose: shoulder → wrist within 25° of horizontal …
T_SIDEWAYS_DEG = 35.0      # … within 35° of straight out to that side …
T_STRAIGHT = 0.85          # … and the arm ≥ 85 % of its length (elbow nearly straight)

PUNCH_SPEED = 1.0          # m/s of both the hand's forward drive and the arm's straightening (captured
                           # punches 0.9–2.3; a walking arm swing never reaches 80 % of the arm ahead)
PUNCH_REACH = 0.80         # the punch lands with the wrist ≥ 80 % of the arm's length ahead

# --- legs ---
KICK_HEIGHT_M = 0.30       # a kick lifts the foot (its lower joint, above standing level) ≥ 30 cm
                           # (captured: CMU soccer kicks 0.33–0.51 m, HDM05 front kicks 1.1–1.2 m)
KICK_REACH_M = 0.40        # … ≥ 40 cm ahead of the pelvis (captured kicks 0.46–0.81 m) …
KICK_KNEE_DEG = 120.0      # … with the knee opened past 120° (captured kicks 131–155°; a knee
                           # raised to the elbow or a tuck jump's leg stays under 60°) …
KICK_SPEED = 4.0           # … the foot moving ≥ 4 m/s in the quarter second before (captured
                           # kicks 7–10 m/s, a knee raise ~2.5, a running swing < 4) …
KICK_SUPPORT_M = 0.10      # … while the other foot is on the floor (not a jump)

# --- ground contact (plausibility) ---
# Height of each joint's centre over the floor when that part rests on it (metres): the toe
# joint sits on the sole line, the ankle ~6 cm up, a lying pelvis or back ~9 cm up (captured
# HDM05 lie-downs: pelvis 8–9 cm), a kneeling knee ~6 cm, a hand on the floor ~3 cm.
SURFACE_DEPTH = np.array([
    0.09,        # pelvis
    0.08, 0.08,  # hips
    0.10,        # spine1
    0.05, 0.05,  # knees
    0.10,        # spine2
    0.055, 0.055,  # ankles
    0.10,        # spine3
    0.0, 0.0,    # toes
    0.07,        # neck
    0.07, 0.07,  # collars
    0.08,        # head
    0.06, 0.06,  # shoulders
    0.04, 0.04,  # elbows
    0.03, 0.03,  # wrists
])

# --- two people ---
TRUNK_JOINTS = (sk.PELVIS, J["spine1"], J["spine2"], J["spine3"], J["left_hip"], J["right_hip"])
TRUNK_SPHERES = np.flatnonzero(np.isin(SPHERE_JOINT, TRUNK_JOINTS))
ARM_JOINTS = tuple(J[f"{s}_{p}"] for s in SIDES for p in ("elbow", "wrist"))
# Spheres of the forearms and hands: where the body is meant to touch the other person, so
# their overlap is touching, not passing through.
REACH_SPHERES = np.flatnonzero(np.isin(SPHERE_JOINT, ARM_JOINTS))


def frame_of(joints: np.ndarray) -> BodyFrame:
    """The body frame of one person's motion (T ≥ 2, 22, 3)."""
    joints = np.asarray(joints, dtype=np.float64)
    if joints.ndim != 3 or joints.shape[1:] != (sk.NUM_JOINTS, 3) or joints.shape[0] < 2:
        raise ValueError(f"expected joints (T ≥ 2, 22, 3), got {joints.shape}")
    return body_frame(joints, FPS)


def frames(seconds: float) -> int:
    return max(1, int(round(seconds * FPS)))


# ---- heights and postures --------------------------------------------------------------

def pelvis_ratio(b: BodyFrame) -> np.ndarray:
    """Pelvis height (T,) as a fraction of the person's standing pelvis height."""
    return b.height[:, sk.PELVIS] / b.stand


def lowest_foot(b: BodyFrame) -> np.ndarray:
    """Height (T,) of the lower foot off the floor (each foot: its lower joint)."""
    return np.minimum(b.foot_height("left"), b.foot_height("right"))


def standing(b: BodyFrame) -> np.ndarray:
    """(T,) bool: upright, pelvis high, a foot on the floor."""
    return ((pelvis_ratio(b) >= STAND_RATIO) & (b.tilt <= STAND_TILT_DEG)
            & (lowest_foot(b) <= FOOT_DOWN_M))


def lying(b: BodyFrame) -> np.ndarray:
    return ((b.tilt >= LIE_TILT_DEG) & (pelvis_ratio(b) < LIE_RATIO)
            & (b.height[:, sk.HEAD] < LIE_HEAD_M))


def sitting(b: BodyFrame) -> np.ndarray:
    return ~lying(b) & (b.tilt <= SIT_TILT_DEG) & (pelvis_ratio(b) < SIT_RATIO)


def kneeling(b: BodyFrame) -> np.ndarray:
    knee = np.minimum(b.height[:, J["left_knee"]], b.height[:, J["right_knee"]])
    r = pelvis_ratio(b)
    return (knee < KNEE_DOWN_M) & (b.tilt <= KNEEL_TILT_DEG) & (r >= KNEEL_RATIO[0]) & (r <= KNEEL_RATIO[1])


def on_all_fours(b: BodyFrame) -> np.ndarray:
    hands = np.maximum(b.height[:, sk.LEFT_HAND], b.height[:, sk.RIGHT_HAND])
    return ((b.tilt >= ALL_FOURS_TILT_DEG) & (pelvis_ratio(b) >= ALL_FOURS_RATIO)
            & (hands < HAND_FLOOR_M))


def crawling_posture(b: BodyFrame) -> np.ndarray:
    """(T,) bool: low and prone enough to crawl (torso ≥ 50° from vertical, pelvis under 80 % of
    standing) with a hand on the floor within half a second (hands and knees, or a low belly
    crawl: captured DeepMimic's keeps the pelvis at 15–35 %)."""
    hands = np.minimum(b.height[:, sk.LEFT_HAND], b.height[:, sk.RIGHT_HAND])
    near = window_percentile(hands, 2 * frames(0.5) + 1, 0.0) < HAND_FLOOR_M
    return (b.tilt >= ALL_FOURS_TILT_DEG) & (pelvis_ratio(b) < 0.8) & near


POSTURES = {"standing": standing, "lying": lying, "sitting": sitting, "kneeling": kneeling,
            "all_fours": on_all_fours}


# ---- flight, jumps and dips ------------------------------------------------------------

def airborne(b: BodyFrame) -> np.ndarray:
    """(T,) bool: both feet off the floor."""
    return lowest_foot(b) > AIRBORNE_M


def flights(b: BodyFrame) -> list[tuple[int, int]]:
    """Runs [s, e) of airborne frames that last 0.1 s … 1 s (strides, hops and jumps)."""
    return [(s, e) for s, e in runs(airborne(b))
            if FLIGHT_MIN_FRAMES <= e - s <= FLIGHT_MAX_S * FPS]


def jumps(b: BodyFrame) -> list[tuple[int, int]]:
    """Ballistic flights that lift the pelvis over its standing height by JUMP_RISE_M: jumps
    and hops (a running stride's flight rises less; a body lifted off the floor and held there,
    a hover, does not fall like a thrown body and is no jump)."""
    pelvis, foot = b.height[:, sk.PELVIS], lowest_foot(b)
    return [(s, e) for s, e in flights(b)
            if pelvis[s:e].max() - b.stand >= JUMP_RISE_M and foot[s:e].max() >= JUMP_FOOT_M
            and ballistic(b, s, e)]


def ballistic(b: BodyFrame, s: int, e: int) -> bool:
    """The pelvis follows a falling arc over frames [s, e) (fitted quadratic coefficient under
    BALLISTIC_CURVE); spans under 4 frames are too short to tell and count as ballistic."""
    if e - s < 4:
        return True
    t = np.arange(e - s) / FPS
    return float(np.polyfit(t, b.joints[s:e, sk.PELVIS, 1], 2)[0]) < BALLISTIC_CURVE


def in_flight(b: BodyFrame) -> np.ndarray:
    """(T,) bool: frames of ballistic flights, with their take-off and landing frames."""
    out = np.zeros(b.joints.shape[0], bool)
    pad = frames(NEAR_FLIGHT_S)
    for s, e in flights(b):
        if ballistic(b, s, e):
            out[max(0, s - pad):e + pad] = True
    return out


def dips(ratio: np.ndarray, down: float = SQUAT_DOWN, up: float = SQUAT_UP) -> list[tuple[int, int, int]]:
    """Completed dips of a pelvis-height ratio (T,): (start, bottom, end) with the ratio over
    `up` at start and end and under `down` in between (a dip still down at the end, or one
    the clip starts in, is not completed and not returned)."""
    out, start, low = [], None, False
    for i, v in enumerate(ratio):
        if v >= up:
            if start is not None and low:
                s = start
                out.append((s, s + int(np.argmin(ratio[s:i + 1])), i))
            start, low = i, False
        elif v < down and start is not None:
            low = True
    return out


def squats(b: BodyFrame) -> list[tuple[int, int, int]]:
    """Pelvis dips with the feet on the floor at the bottom and the torso upright enough (not
    lying), not the crouch before a jump nor the landing after one."""
    ratio = smooth(pelvis_ratio(b), 3)
    jumped = np.zeros(len(ratio), bool)
    pad = frames(0.3)
    for s, e in jumps(b):
        jumped[max(0, s - pad):e + pad] = True
    foot = lowest_foot(b)
    return [(s, m, e) for s, m, e in dips(ratio)
            if not jumped[s:e + 1].any() and foot[m] <= FOOT_DOWN_M and b.tilt[m] < LIE_TILT_DEG]


# ---- travel ------------------------------------------------------------------------------

def speed(b: BodyFrame) -> np.ndarray:
    """Horizontal pelvis speed (T,) m/s, averaged over SPEED_SMOOTH_S."""
    step = np.linalg.norm(np.gradient(b.joints[:, sk.PELVIS, :][:, [0, 2]], axis=0), axis=1) * FPS
    return smooth(step, frames(SPEED_SMOOTH_S))


def path(b: BodyFrame) -> np.ndarray:
    """The pelvis on the floor (T, 2) as (x, z), smoothed over TRAVEL_SMOOTH_S."""
    return smooth(b.joints[:, sk.PELVIS][:, [0, 2]], frames(TRAVEL_SMOOTH_S))


def path_length(b: BodyFrame) -> float:
    return float(np.linalg.norm(np.diff(path(b), axis=0), axis=1).sum())


def travel(b: BodyFrame) -> dict[str, float]:
    """Metres travelled forward, backward, left and right of where the body faces (each frame's
    pelvis step classified by its angle to the facing direction: within 45° of forward,
    within 45° of backward, else to that side)."""
    p = path(b)
    step = np.diff(p, axis=0)                                            # (T-1, 2)
    fwd = (b.forward[1:] + b.forward[:-1])[:, [0, 2]]
    left = (b.left[1:] + b.left[:-1])[:, [0, 2]]
    ahead = (step * fwd).sum(1) / np.maximum(np.linalg.norm(fwd, axis=1), 1e-9)
    side = (step * left).sum(1) / np.maximum(np.linalg.norm(left, axis=1), 1e-9)
    ang = np.degrees(np.arctan2(side, ahead))                            # 0 ahead, + to the left
    dist = np.linalg.norm(step, axis=1)
    return {"forward": float(dist[np.abs(ang) <= 45].sum()),
            "backward": float(dist[np.abs(ang) >= 135].sum()),
            "left": float(dist[(ang > 45) & (ang < 135)].sum()),
            "right": float(dist[(ang < -45) & (ang > -135)].sum())}


def heading(b: BodyFrame) -> np.ndarray:
    """Facing yaw (T,) in degrees, unwrapped; grows when the person turns to their left."""
    return np.degrees(np.unwrap(np.arctan2(b.forward[:, 0], b.forward[:, 2])))


def partner_turns(a: np.ndarray, b: np.ndarray, fa: BodyFrame, fb: BodyFrame, n: int,
                  max_m: float) -> np.ndarray:
    """(T − n,) degrees one of two people turns over frames s … s + n while the pelvises stay
    within `max_m` m and the other turns under half as much (0 where neither does): a
    couple's spin, the follower turned under the leader's arm."""
    dist = np.linalg.norm(a[:, sk.PELVIS][:, [0, 2]] - b[:, sk.PELVIS][:, [0, 2]], axis=1)
    near = sliding_window_view(dist, n + 1).max(axis=1) <= max_m
    ya, yb = heading(fa), heading(fb)
    ta, tb = np.abs(ya[n:] - ya[:-n]), np.abs(yb[n:] - yb[:-n])
    return np.maximum(np.where(near & (tb < ta / 2), ta, 0.0), np.where(near & (ta < tb / 2), tb, 0.0))


def steps(b: BodyFrame) -> int:
    """Steps taken: a foot lifted off the floor and put down ≥ 15 cm from where it left."""
    count = 0
    for side in SIDES:
        toe = b.joints[:, J[f"{side}_foot"]][:, [0, 2]]
        down = fill_gaps(b.foot_height(side) < AIRBORNE_M)
        stances = runs(down)
        for (_, e0), (s1, _) in zip(stances[:-1], stances[1:]):
            if np.linalg.norm(toe[s1] - toe[e0 - 1]) >= 0.15:
                count += 1
    return count


# ---- hands, arms, legs -------------------------------------------------------------------

def hand_point(joints: np.ndarray, side: str) -> np.ndarray:
    """Centre (T, 3) of a hand: HAND_EXTENSION forearm lengths past the wrist."""
    wr, el = joints[:, J[f"{side}_wrist"]], joints[:, J[f"{side}_elbow"]]
    return wr + HAND_EXTENSION * (wr - el)


def hand_over(b: BodyFrame, side: str, level: str) -> np.ndarray:
    """(T,) bool: the hand's centre over the head joint ("head": at least at ear level),
    OVERHEAD_M over it ("overhead": above the crown) or over its own shoulder ("shoulder")."""
    y = hand_point(b.joints, side)[:, 1]
    if level == "shoulder":
        return y > b.joints[:, J[f"{side}_shoulder"], 1]
    if level == "head":
        return y > b.joints[:, sk.HEAD, 1]
    if level == "overhead":
        return y > b.joints[:, sk.HEAD, 1] + OVERHEAD_M
    raise ValueError(f"unknown hand level {level!r}; expected shoulder, head or overhead")


def hand_lateral(b: BodyFrame, side: str) -> np.ndarray:
    """The hand's position (T,) along the body's left axis, from the neck."""
    return b.local(hand_point(b.joints, side) - b.joints[:, sk.NECK])[0]


def waves(b: BodyFrame, side: str, level: str = "head") -> list[tuple[int, int, int]]:
    """Waves of one hand: (start, end, reversals) of each chain of ≥ WAVE_MIN_TURNS quick
    lateral reversals (each swing ≥ WAVE_AMPLITUDE_M, each within WAVE_HALF_PERIOD_S of the
    last) inside one stretch of frames with the hand raised to `level`. A held arm, a reach
    or a throw makes no chain."""
    lateral = smooth(hand_lateral(b, side), 3)
    out = []
    for s, e in runs(fill_gaps(hand_over(b, side, level))):
        turns = zigzag(lateral[s:e], WAVE_AMPLITUDE_M)
        if len(turns) < WAVE_MIN_TURNS:
            continue
        quick = np.diff(turns) <= WAVE_HALF_PERIOD_S * FPS
        for q0, q1 in runs(quick):
            if q1 - q0 + 1 >= WAVE_MIN_TURNS:
                out.append((s + int(turns[q0]), s + int(turns[q1]) + 1, q1 - q0 + 1))
    return out


def arm_horizontal(b: BodyFrame, side: str) -> np.ndarray:
    """(T,) bool: the arm held straight out to its side at shoulder height."""
    sh, el, wr = (b.joints[:, J[f"{side}_{p}"]] for p in ("shoulder", "elbow", "wrist"))
    arm = wr - sh
    length = np.median(np.linalg.norm(el - sh, axis=1) + np.linalg.norm(wr - el, axis=1))
    lat, up, fwd = b.local(arm)
    out = lat if side == "left" else -lat
    horiz = np.hypot(lat, fwd)
    elevation = np.degrees(np.arctan2(up, horiz))
    sideways = np.degrees(np.arctan2(np.abs(fwd), out))
    return ((np.abs(elevation) <= T_ELEVATION_DEG) & (out > 0) & (sideways <= T_SIDEWAYS_DEG)
            & (np.linalg.norm(arm, axis=1) >= T_STRAIGHT * length))


def foot_lift(b: BodyFrame, side: str) -> np.ndarray:
    """Height (T,) of a foot off the floor (its lower joint)."""
    return b.foot_height(side)


def knee_angle(b: BodyFrame, side: str) -> np.ndarray:
    """Interior knee angle (T,) in degrees (~175 straight)."""
    hip, knee, ankle = (b.joints[:, J[f"{side}_{p}"]] for p in ("hip", "knee", "ankle"))
    return angle(hip - knee, ankle - knee)


def kicks(b: BodyFrame, side: str, height: float = KICK_HEIGHT_M) -> list[tuple[int, float]]:
    """Kicks of one leg: (peak frame, foot height at the peak) of each stretch with that foot
    ≥ `height` off the floor and ≥ KICK_REACH_M ahead of the pelvis while the other foot is
    on the floor, whose peak has the knee opened past KICK_KNEE_DEG and the foot swung in at
    ≥ KICK_SPEED."""
    other = "right" if side == "left" else "left"
    lift = foot_lift(b, side)
    toe = J[f"{side}_foot"]
    reach = b.local(b.joints[:, toe] - b.joints[:, sk.PELVIS])[2]
    fast = np.linalg.norm(b.velocity[:, toe], axis=1)
    knee = knee_angle(b, side)
    up = (lift >= height) & (reach >= KICK_REACH_M) & (foot_lift(b, other) <= KICK_SUPPORT_M)
    out = []
    back = frames(0.25)
    for s, e in runs(fill_gaps(up)):
        m = s + int(np.argmax(lift[s:e]))
        if knee[s:e].max() >= KICK_KNEE_DEG and fast[max(0, m - back):m + 1].max() >= KICK_SPEED:
            out.append((m, float(lift[m])))
    return out


def punches(b: BodyFrame, side: str) -> list[int]:
    """Frames where one hand punches: the hand driven forward and the arm straightening, both
    at ≥ PUNCH_SPEED, ending with the arm ≥ PUNCH_REACH of its length ahead of the shoulder,
    between 30 cm under the shoulder and the head (a walking arm swing stays under 1 m/s and
    bent; a throw or a reach ends over the head or slowly)."""
    sh, el, wr = (b.joints[:, J[f"{side}_{p}"]] for p in ("shoulder", "elbow", "wrist"))
    length = np.median(np.linalg.norm(el - sh, axis=1) + np.linalg.norm(wr - el, axis=1))
    _, up, fwd = b.local(wr - sh)
    extension = np.gradient(np.linalg.norm(wr - sh, axis=1)) * FPS
    drive = np.gradient(fwd) * FPS
    out = []
    for s, e in runs((drive > PUNCH_SPEED) & (extension > PUNCH_SPEED)):
        m = min(e + 1, len(fwd) - 1)                     # the frame the drive ends on
        m = s + int(np.argmax(fwd[s:m + 1]))
        if (fwd[m] >= PUNCH_REACH * length and up[m] >= -0.30
                and wr[m, 1] <= b.joints[m, sk.HEAD, 1] + 0.05):
            out.append(m)
    return out


def hands_on_hips(b: BodyFrame) -> np.ndarray:
    """(T,) bool: each wrist within 25 cm of its own hip joint and no lower than 5 cm under it,
    the elbow bent under 130° and out to the side of the shoulder (a hanging arm's wrist is as
    close to the hip, but its elbow is straight and under the shoulder)."""
    ok = np.ones(b.joints.shape[0], bool)
    for side in SIDES:
        sh, el, wr = (b.joints[:, J[f"{side}_{p}"]] for p in ("shoulder", "elbow", "wrist"))
        hip = b.joints[:, J[f"{side}_hip"]]
        out = b.local(el - sh)[0] * (1 if side == "left" else -1)
        ok &= ((np.linalg.norm(wr - hip, axis=1) < 0.25) & (wr[:, 1] > hip[:, 1] - 0.05)
               & (angle(sh - el, wr - el) < 130) & (out > 0.03))
    return ok


def arms_crossed(b: BodyFrame) -> np.ndarray:
    """(T,) bool: each wrist across the body's midline, in front of the chest, between the
    pelvis and the neck, within 25 cm of the other arm's elbow."""
    neck, pelvis = b.joints[:, sk.NECK], b.joints[:, sk.PELVIS]
    ok = np.ones(b.joints.shape[0], bool)
    for side, other in (("left", "right"), ("right", "left")):
        wr = b.joints[:, J[f"{side}_wrist"]]
        lat, _, ahead = b.local(wr - neck)
        across = lat < 0 if side == "left" else lat > 0
        y = wr[:, 1]
        ok &= (across & (ahead > 0) & (y > pelvis[:, 1] + 0.1) & (y < neck[:, 1])
               & (np.linalg.norm(wr - b.joints[:, J[f"{other}_elbow"]], axis=1) < 0.25))
    return ok


def arms_forward(b: BodyFrame) -> np.ndarray:
    """(T,) bool: both arms held straight ahead at about shoulder height (a zombie's or a
    sleepwalker's arms): wrist ≥ 75 % of the arm's length ahead of the shoulder, within 25 cm of
    its height."""
    ok = np.ones(b.joints.shape[0], bool)
    for side in SIDES:
        sh, el, wr = (b.joints[:, J[f"{side}_{p}"]] for p in ("shoulder", "elbow", "wrist"))
        length = np.median(np.linalg.norm(el - sh, axis=1) + np.linalg.norm(wr - el, axis=1))
        _, up, fwd = b.local(wr - sh)
        ok &= (fwd >= 0.75 * length) & (np.abs(up) <= 0.25)
    return ok


def one_leg(b: BodyFrame) -> np.ndarray:
    """(T,) bool: standing on one leg: one foot ≥ 15 cm off the floor, the other on it, the
    pelvis at standing height."""
    lf, rf = b.foot_height("left"), b.foot_height("right")
    return (((lf >= 0.15) & (rf <= FOOT_DOWN_M)) | ((rf >= 0.15) & (lf <= FOOT_DOWN_M))) & (
        pelvis_ratio(b) >= STAND_RATIO)


def knee_raises(b: BodyFrame) -> list[int]:
    """Frames where a knee is raised: thigh ≥ 60° from hanging (about horizontal) with that
    foot off the floor and the other on it."""
    down = np.array([0.0, -1.0, 0.0])
    out = []
    for side, other in (("left", "right"), ("right", "left")):
        thigh = angle(b.joints[:, J[f"{side}_knee"]] - b.joints[:, J[f"{side}_hip"]], down)
        up = (thigh >= 60) & (b.foot_height(side) > 0.12) & (b.foot_height(other) <= FOOT_DOWN_M)
        out += [s + int(np.argmax(thigh[s:e])) for s, e in runs(fill_gaps(up))]
    return sorted(out)


def torso_lean(b: BodyFrame) -> np.ndarray:
    """Forward lean (T,) of the torso in degrees (pelvis → neck against vertical, + forward)."""
    v = b.joints[:, sk.NECK] - b.joints[:, sk.PELVIS]
    _, up, fwd = b.local(v)
    return np.degrees(np.arctan2(fwd, up))


def limb_speed(b: BodyFrame) -> np.ndarray:
    """Mean speed (T,) of the wrists and ankles relative to the pelvis, m/s: how much the body
    moves apart from travelling."""
    idx = [sk.LEFT_HAND, sk.RIGHT_HAND, sk.LEFT_ANKLE, sk.RIGHT_ANKLE]
    rel = b.velocity[:, idx] - b.velocity[:, [sk.PELVIS]]
    return np.linalg.norm(rel, axis=2).mean(axis=1)


# ---- path shapes ---------------------------------------------------------------------------

def resample_path(points: np.ndarray, n: int = 120) -> np.ndarray:
    """A polyline (N, 2) resampled to n points evenly spaced along its length."""
    seg = np.linalg.norm(np.diff(points, axis=0), axis=1)
    s = np.concatenate([[0.0], np.cumsum(seg)])
    if s[-1] <= 1e-9:
        return np.repeat(points[:1], n, axis=0)
    u = np.linspace(0.0, s[-1], n)
    return np.stack([np.interp(u, s, points[:, k]) for k in range(2)], axis=1)


def moving_path(b: BodyFrame, still: float = 0.2) -> np.ndarray:
    """The smoothed pelvis path (N, 2) between the first and the last frame faster than
    `still` m/s (standing before or after adds nothing to a shape)."""
    p, v = path(b), speed(b)
    go = np.flatnonzero(v > still)
    return p[go[0]:go[-1] + 1] if len(go) >= 2 else p


def _template(shape: str, n: int) -> np.ndarray:
    u = np.linspace(0.0, 1.0, n, endpoint=False)
    if shape == "circle":
        a = 2 * np.pi * u
        return np.stack([np.cos(a), np.sin(a)], axis=1)
    if shape == "figure_eight":                               # two loops crossing at the centre
        a = 2 * np.pi * u
        return resample_path(np.stack([np.sin(a), np.sin(a) * np.cos(a)], axis=1), n)
    corners: dict[str, list[tuple[float, float]]] = {
        "square": [(0, 0), (1, 0), (1, 1), (0, 1)],
        "triangle": [(0, 0), (1, 0), (0.5, float(np.sqrt(3) / 2))]}
    if shape not in corners:
        raise ValueError(f"no closed template for {shape!r}")
    c = np.array(corners[shape] + corners[shape][:1], dtype=np.float64)
    return resample_path(c, n + 1)[:-1]


CLOSED_SHAPES = ("circle", "square", "triangle", "figure_eight")


def _similarity_rms(x: np.ndarray, y: np.ndarray) -> float:
    """RMS distance (normalised by y's spread) between y and the best similarity transform
    (rotation, reflection, scale, shift) of x onto y; both (n, 2)."""
    xc, yc = x - x.mean(0), y - y.mean(0)
    u, sv, vt = np.linalg.svd(xc.T @ yc)
    rot = u @ vt                                              # reflection allowed
    nx = (xc ** 2).sum()
    scale = sv.sum() / max(nx, 1e-12)
    res = yc - scale * xc @ rot
    spread = np.sqrt((yc ** 2).sum(1).mean())
    return float(np.sqrt((res ** 2).sum(1).mean()) / max(spread, 1e-9))


def shape_distance(points: np.ndarray, shape: str, n: int = 120) -> float:
    """Distance of a closed path (N, 2) from a closed shape: the RMS gap, as a fraction of the
    path's spread, after the best rotation, reflection, scale and shift of the shape and the
    best starting point along it (walked either way). 0 for the exact shape; a walked circle
    is ~0.03 from a circle, ~0.08 from a square."""
    y = resample_path(points, n)
    t = _template(shape, n)
    best = np.inf
    for k in range(0, n, max(1, n // 60)):
        for tt in (np.roll(t, -k, axis=0), np.roll(t[::-1], -k, axis=0)):
            best = min(best, _similarity_rms(tt, y))
    return float(best)


def fit_circle(points: np.ndarray) -> tuple[np.ndarray, float, float]:
    """Least-squares circle (centre (2,), radius, RMS radial residual / radius) of (N, 2) points."""
    x, z = points[:, 0], points[:, 1]
    a = np.stack([x, z, np.ones_like(x)], axis=1)
    c, *_ = np.linalg.lstsq(a, x ** 2 + z ** 2, rcond=None)
    centre = c[:2] / 2
    r = float(np.sqrt(max(c[2] + (centre ** 2).sum(), 1e-12)))
    resid = np.linalg.norm(points - centre, axis=1) - r
    return centre, r, float(np.sqrt((resid ** 2).mean()) / r)


def swept_angle(points: np.ndarray, centre: np.ndarray) -> float:
    """Degrees swept around `centre` along the path (signed, + counterclockwise seen from above
    with x right and z up)."""
    d = points - centre
    return float(np.degrees(np.unwrap(np.arctan2(d[:, 1], d[:, 0]))[-1]
                            - np.arctan2(d[0, 1], d[0, 0])))


def zigzag_legs(points: np.ndarray, amplitude: float = 0.25) -> tuple[int, float]:
    """(turns, bend) of a path read as a zigzag: the turning points of its sideways offset from
    its main axis (each swing ≥ `amplitude` m) and the RMS distance of the path from the
    polyline through its ends and those turns, as a fraction of that polyline's mean leg (0
    for straight legs; a walk rounds its corners to ~0.05–0.08; a circle's arcs ~0.2)."""
    c = points - points.mean(0)
    _, _, vt = np.linalg.svd(c, full_matrices=False)
    side = c @ vt[1]
    turns = zigzag(side, amplitude)
    knots = np.unique(np.concatenate([[0], turns, [len(points) - 1]]).astype(int))
    poly = resample_path(points[knots], 400)
    d = np.linalg.norm(points[:, None] - poly[None], axis=2).min(axis=1)
    leg = float(np.linalg.norm(np.diff(points[knots], axis=0), axis=1).mean())
    return len(turns), float(np.sqrt((d ** 2).mean()) / max(leg, 1e-9))


# ---- two people: mirroring -------------------------------------------------------------------

MIRROR_JOINTS = np.array([sk.JOINT_INDEX[n.replace("left_", "#").replace("right_", "left_")
                                         .replace("#", "right_")] for n in sk.JOINT_NAMES])


def body_local(b: BodyFrame) -> np.ndarray:
    """Joints (T, 22, 3) relative to the pelvis in the body's own (left, up, forward) axes."""
    rel = b.joints - b.joints[:, [sk.PELVIS]]
    return np.stack([(rel * b.left[:, None]).sum(-1), rel[..., 1],
                     (rel * b.forward[:, None]).sum(-1)], axis=-1)


def mirror_correlation(a: BodyFrame, b: BodyFrame) -> float:
    """How closely b's body moves as a's mirror image (0 … 1): the correlation of a's limb
    velocities in a's own frame with b's, left and right swapped and the lateral axis negated,
    over the limb joints (what someone facing you does when they mirror you)."""
    la, lb = body_local(a), body_local(b)
    lb = lb[:, MIRROR_JOINTS] * np.array([-1.0, 1.0, 1.0])
    limbs = [sk.LEFT_HAND, sk.RIGHT_HAND, sk.JOINT_INDEX["left_elbow"], sk.JOINT_INDEX["right_elbow"],
             sk.LEFT_ANKLE, sk.RIGHT_ANKLE, sk.JOINT_INDEX["left_knee"], sk.JOINT_INDEX["right_knee"]]
    va, vb = np.diff(la[:, limbs], axis=0).ravel(), np.diff(lb[:, limbs], axis=0).ravel()
    if va.std() < 1e-6 or vb.std() < 1e-6:
        return 0.0
    return float(np.corrcoef(va, vb)[0, 1])


# ---- ground contact (plausibility) ---------------------------------------------------------

def clearance(joints: np.ndarray, joints_of: tuple[int, ...] | None = None) -> np.ndarray:
    """Gap (T,) between the body and the studio's floor y = 0: the lowest joint's height (of
    `joints_of`, default all) less the depth its centre sits above a floor it rests on
    (SURFACE_DEPTH, the SMPL template's); ~0 standing, walking, lying or kneeling on the floor,
    > 0 floating, < 0 sunk. Captures on other skeletons place their foot joints up to ~4 cm
    differently, and captures on tilted floors (several CMU walks rise 5–8 cm over a few
    metres) float on a level one."""
    j = np.asarray(joints, dtype=np.float64)
    idx = list(range(sk.NUM_JOINTS)) if joints_of is None else list(joints_of)
    return (j[:, idx, 1] - SURFACE_DEPTH[idx]).min(axis=1)


def feet_carry(b: BodyFrame) -> np.ndarray:
    """(T,) bool: the feet carry the body (torso within 45° of vertical, pelvis over 35 % of
    standing: standing, walking, squatting, kneeling up): where feet off the floor are
    floating, unlike lying, sitting on the floor or crawling."""
    return (b.tilt <= 45.0) & (pelvis_ratio(b) >= 0.35)


def pelvis_pops(joints: np.ndarray) -> np.ndarray:
    """Per frame (T,), how far the pelvis's step into that frame departs from the steps around
    it (metres): |Δp_t - (Δp_t-1 + Δp_t+1)/2|, one-sided at the ends. A steady walk or run
    gives ~0 however fast it is; a body that jumps 41 cm in one frame gives 0.41 there."""
    p = np.asarray(joints)[:, sk.PELVIS]
    t = p.shape[0]
    out = np.zeros(t)
    if t < 3:
        return out
    d = np.diff(p, axis=0)                                               # d[i] = p[i+1] - p[i]
    out[1] = np.linalg.norm(d[0] - d[1])                                 # step into frame 1
    out[t - 1] = np.linalg.norm(d[-1] - d[-2])
    if t > 3:
        mid = d[1:-1] - 0.5 * (d[:-2] + d[2:])                           # steps into 2 … t-2
        out[2:t - 1] = np.linalg.norm(mid, axis=1)
    return out


# ---- two people ----------------------------------------------------------------------------

def hand_gap(a: np.ndarray, b: np.ndarray, side_a: str, side_b: str) -> np.ndarray:
    """Gap (T,) between the surfaces of a's `side_a` hand and b's `side_b` hand (metres)."""
    d = np.linalg.norm(hand_point(a, side_a) - hand_point(b, side_b), axis=1)
    return d - 2 * HAND_RADIUS_M


def hand_to_trunk(a: np.ndarray, b: np.ndarray, side: str) -> np.ndarray:
    """Gap (T,) from the surface of a's `side` hand to the nearest trunk sphere of b."""
    sb = body_spheres(b)
    centres, radii = sb.centres[:, TRUNK_SPHERES], sb.radii[TRUNK_SPHERES]
    d = np.linalg.norm(centres - hand_point(a, side)[:, None], axis=2) - radii[None]
    return d.min(axis=1) - HAND_RADIUS_M


def behind_torso(hugger: np.ndarray, partner: BodyFrame, side: str) -> np.ndarray:
    """(T,) bool: the hugger's `side` hand (its centre, `hand_point`: an arm round someone puts
    the wrist at their side and the hand on their back) lies behind the partner's torso plane
    (the vertical plane through the partner's spine3 across their facing direction), within
    35 cm of the partner's spine line and between the partner's pelvis and head height: an arm
    round the back, not a hand behind someone standing in front."""
    hand = hand_point(hugger, side)
    rel = hand - partner.joints[:, J["spine3"]]
    lat, _, ahead = partner.local(rel)
    y = hand[:, 1]
    return ((ahead < 0) & (np.hypot(lat, ahead) <= 0.35)
            & (y >= partner.joints[:, sk.PELVIS, 1]) & (y <= partner.joints[:, sk.HEAD, 1] + 0.10))


def body_overlap(a: np.ndarray, b: np.ndarray, depth: float, touching: bool = False) -> np.ndarray:
    """(T,) bool: a sphere of one body sinks deeper than `depth` metres into a sphere of the
    other. The hands never count (a hand brushing the other is a touch); when the two are
    `touching` (asked to hold, hug, push, dance as a couple) the forearms do not count either:
    they are what holds and pushes, so only the rest of the body passing through counts."""
    sa, sb = body_spheres(a), body_spheres(b)
    gaps = surface_gaps(sa, sb)                                          # (T, S, S)
    keep = np.ones(gaps.shape[1], bool)
    keep[REACH_SPHERES if touching else HAND_SPHERES] = False
    return np.asarray((gaps[:, keep][:, :, keep] < -depth).any(axis=(1, 2)))


def deepest_overlap(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Depth (T,) in metres of the deepest overlap of any two spheres of the two bodies (0 apart)."""
    return np.maximum(0.0, -surface_gaps(body_spheres(a), body_spheres(b)).min(axis=(1, 2)))
