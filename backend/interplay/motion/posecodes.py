"""Interpretable per-frame pose codes from joints, in the spirit of PoseScript / CoMo.

`frame_codes(joints)` turns a motion (T, 22, 3) (20 fps, metres, Y up) into named per-frame
arrays: booleans such as `left_hand_above_head`, `right_knee_bent`, `walking`, `jumping`, and a
few continuous signals (`speed`, `heading`, `pelvis_height`, …). Everything is measured in the
person's own body frame (`bodyframe.py`): forward from hips and shoulders, left = up × forward
(+X for a person facing +Z), heights above the local floor. Mirroring a motion (x → −x and
swapping left/right joints) swaps every left/right code; heading grows when the person turns
to their left (yaw from +Z towards +X).

`caption_clip` / `describe` aggregate the codes into short English captions per body part
(`captions.py`); `caption_accuracy` checks them against the labels of real clips.
Thresholds are named constants with the reason for their value.
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.bodyframe import DOWN, BodyFrame, angle, body_frame, frames
from interplay.motion.captions import captions_from_codes, score_clips, summarise
from interplay.motion.clip import Caption
from interplay.motion.signals import fill_gaps, runs, smooth, window_fraction, zigzag

J = sk.JOINT_INDEX
SIDES = ("left", "right")

# --- time scales (seconds) ---
SPEED_SMOOTH_S = 1.0     # root speed over one gait cycle (~2 steps) so it doesn't pulse with steps
TURN_SMOOTH_S = 0.5      # yaw rate over half a second: a deliberate turn, not a sway
CADENCE_WINDOW_S = 2.0   # steps counted over two seconds (3–6 steps when walking)
CIRCLE_WINDOW_S = 3.0    # a circle is a curve sustained for seconds, not a single corner
ARM_CIRCLE_WINDOW_S = 2.0  # one arm revolution takes ~1–2 s in HDM05's rotateArms clips

# --- hand and arm (metres, degrees) ---
ABOVE_HEAD_MARGIN = 0.10   # the head joint sits at jaw/ear level, ~15 cm below the crown: a wrist
                           # 10 cm over it puts the hand over the head
HEAD_BAND = 0.10           # wrist within 10 cm below the head joint or higher: raised to head
                           # height (HDM05's grabHighR reaches about there, fingers overhead)
SHOULDER_BAND = 0.12       # wrist within ±12 cm of the shoulder's height is "at shoulder height"
HAND_FLOOR_HEIGHT = 0.35   # a wrist this low is only reached by bending/squatting down to the floor
ARM_RAISED_DEG = 60.0      # upper arm this far from hanging straight down is "raised"
ELBOW_BENT_DEG = 120.0     # interior elbow angle below this is visibly bent (straight is ~170°)
NEAR_FACE = 0.22           # wrist to head joint: a hand on the mouth/cheek is ~0.12–0.2 m away
HANDS_TOGETHER = 0.15      # wrist to wrist: clasped hands keep the wrists ~0.08–0.12 m apart
NEAR_HIP = 0.20            # wrist to hip joint with a bent elbow: a hand on the hip (a hanging
                           # arm's wrist is as close, but its elbow is straight)
WAVE_AMPLITUDE = 0.06      # lateral hand swing (each way) that counts as a wave, not a tremor
WAVE_HALF_PERIOD_S = 0.8   # waves go back and forth at ≥ ~0.6 Hz
WAVE_MIN_REVERSALS = 3     # at least 1.5 back-and-forth swings
WAVE_HAND_HEIGHT = 0.0     # wrist above shoulder height (a running arm swings across the chest)
PUNCH_SPEED = 1.5          # m/s of both the forward hand speed and the arm's extension rate
                           # relative to the shoulder; walking/running arm swings stay < 1 m/s
PUNCH_ELBOW_DEG = 110.0    # the arm is (nearly) extended while the punch lands …
PUNCH_LOW = -0.30          # … the hand no lower than 30 cm under the shoulder, nor over the head
SWING_STD = 0.06           # forward/back hand travel (std, m) of a swinging arm when walking
ARM_CIRCLE_DEG = 240.0     # net rotation of the arm about the shoulder (sagittal) in the window

# --- legs and feet ---
CONTACT_HEIGHT = 0.05      # foot (ankle or toe) within 5 cm of its ground level …
CONTACT_SPEED = 0.8        # … and moving horizontally slower than 0.8 m/s (stance phase),
PLANTED_HEIGHT = 0.10      # or within 10 cm and nearly still: a planted foot rolling onto its
PLANTED_SPEED = 0.3        # heel or toes (the other joint of the foot lifts a few cm)
FOOT_LIFTED = 0.12         # both ankle and toe this far above ground: the foot is off the floor
KNEE_BENT_DEG = 140.0      # interior knee angle below this is clearly bent (standing ~175°)
KNEE_RAISED_DEG = 60.0     # thigh this far from vertical with the foot up: knee lifted
KICK_SPEED = 2.0           # m/s forward toe speed relative to the pelvis (walking swing ~1–1.5)
KICK_HEIGHT = 0.30         # toe height of a kick; a walking/jogging swing stays lower in front
KICK_REACH = 0.25          # toe ahead of the pelvis (m) when kicking forward
GROUND_KICK_SPEED = 6.0    # m/s: a kick along the ground (CMU soccer: 7–9) at any height or
                           # gait; running swings stay under ~4, HDM05 front kicks reach 4.5–7

# --- whole body ---
MOVE_SPEED = 0.35          # m/s root speed above which the person travels (slow walk ~0.6)
STILL_SPEED = 0.15         # m/s below which the person stands still (sway and shuffles)
MIN_CADENCE = 0.75         # steps/s: travelling without steps is a glide, not a walk
RUN_FLIGHT = 0.08          # fraction of a second with both feet off the ground: a running gait
                           # (walking always has a foot on the ground)
RUN_MIN_CADENCE = 1.6      # steps/s; jogging and running take ≥ 2 steps a second (a kick's
                           # one-legged hop does not make a run)
RUN_SPEED_ALONE = 2.6      # m/s that is a run even if the short flight phases are missed
JOG_MAX_SPEED = 2.5        # m/s; a running gait slower than this is a jog (~9 km/h)
SNEAK_MAX_SPEED = 1.0      # m/s; sneaking is slower than an ordinary walk (1.0–1.7 in CMU)
SNEAK_TILT_DEG = 12.0      # torso lean of a sneak (ordinary walks lean 2–9°)
SIDEWAYS_DEG = 50.0        # travel this far off the facing direction is sideways …
BACKWARDS_DEG = 130.0      # … and this far is backwards
TURN_RATE_DEG = 30.0       # deg/s of heading change that is a deliberate turn
CIRCLE_RATE_DEG = 30.0     # deg/s of travel-direction change sustained over CIRCLE_WINDOW_S
CIRCLE_SUSTAIN = 0.7       # … curving the same way (at ≥ 2/3 of that rate, 1 s smoothed) for
                           # 70% of that window
AIRBORNE_HEIGHT = 0.05     # both feet (ankle and toe) this far above ground: in the air
JUMP_RISE = 0.08           # pelvis this far above its straight-legged standing height while
                           # airborne: a jump (a running stride's flight, pushed off the toes,
                           # lifts it ~5 cm; CMU/HDM05 jumps and hops rise 0.2–0.4 m)
JUMP_MIN_FRAMES = 2        # airborne for ≥ 0.1 s …
JUMP_MAX_S = 1.0           # … and < 1 s (longer is standing on something raised, not flight)
SQUAT_HEIGHT = 0.75        # pelvis below 75% of standing height with bent knees: squatting
CROUCH_HEIGHT = 0.88       # below 88%: crouching (a walk dips ~3–5%)
SIT_HEIGHT = 0.30          # pelvis this close to the floor (fraction of standing): sitting down
LIE_TILT_DEG = 60.0        # torso this far from vertical with the pelvis low: lying
LIE_HEIGHT = 0.50
BEND_TILT_DEG = 45.0       # torso pitched forward this far with the pelvis high: bending over


def _check(joints: np.ndarray) -> np.ndarray:
    joints = np.asarray(joints, dtype=np.float64)
    if joints.ndim != 3 or joints.shape[1:] != (sk.NUM_JOINTS, 3):
        raise ValueError(f"joints must be (T, {sk.NUM_JOINTS}, 3), got {joints.shape}")
    if joints.shape[0] < 2:
        raise ValueError("pose codes need at least 2 frames")
    if not np.isfinite(joints).all():
        raise ValueError("joints contain NaN or inf")
    return joints


def frame_codes(joints: np.ndarray, fps: float = sk.FPS) -> dict[str, np.ndarray]:
    """Per-frame codes (each array (T,)) of one person's motion (T, 22, 3)."""
    b = body_frame(_check(joints), fps)
    codes: dict[str, np.ndarray] = {"pelvis_height": b.height[:, sk.PELVIS] / b.stand,
                                    "torso_tilt": b.tilt}
    _feet(b, codes)
    _travel(b, codes)
    _posture(b, codes)
    _legs(b, codes)
    _arms(b, codes)
    return codes


def _feet(b: BodyFrame, codes: dict) -> None:
    """Contact, lift and swing of each foot; step cadence (steps/s)."""
    hspeed = b.hspeed
    for side in SIDES:
        a, f = J[f"{side}_ankle"], J[f"{side}_foot"]
        h = b.foot_height(side)
        slow = np.minimum(hspeed[:, a], hspeed[:, f])
        raw = (((h < CONTACT_HEIGHT) & (slow < CONTACT_SPEED))
               | ((h < PLANTED_HEIGHT) & (slow < PLANTED_SPEED)))
        contact = fill_gaps(raw)                                 # one flickering frame is no step
        codes[f"{side}_foot_contact"] = contact
        codes[f"{side}_foot_lifted"] = h > FOOT_LIFTED
        codes[f"{side}_foot_stepping"] = ~contact & (hspeed[:, f] > 2 * MOVE_SPEED)
    contacts = np.stack([codes["left_foot_contact"], codes["right_foot_contact"]])
    onsets = np.concatenate([[0], (contacts[:, 1:] & ~contacts[:, :-1]).sum(0)]).astype(float)
    codes["cadence"] = smooth(onsets, frames(CADENCE_WINDOW_S, b.fps)) * b.fps
    codes["airborne"] = (b.foot_height("left") > AIRBORNE_HEIGHT) & (b.foot_height("right") > AIRBORNE_HEIGHT)


def _travel(b: BodyFrame, codes: dict) -> None:
    """Root speed, gait, direction of travel relative to facing, turns and circles."""
    fps = b.fps
    root_v = smooth(b.velocity[:, sk.PELVIS], frames(SPEED_SMOOTH_S, fps))
    root_v[:, 1] = 0.0
    speed = np.linalg.norm(root_v, axis=-1)
    codes["speed"] = speed
    lat, _, ahead = b.local(root_v)
    travel = np.degrees(np.arctan2(lat, ahead))                  # 0 forward, + to the left
    going = speed > MOVE_SPEED
    codes["moving_forward"] = going & (np.abs(travel) <= SIDEWAYS_DEG)
    codes["moving_backwards"] = going & (np.abs(travel) >= BACKWARDS_DEG)
    codes["moving_left"] = going & (travel > SIDEWAYS_DEG) & (travel < BACKWARDS_DEG)
    codes["moving_right"] = going & (travel < -SIDEWAYS_DEG) & (travel > -BACKWARDS_DEG)
    cadence = codes["cadence"]
    moving = going & (cadence >= MIN_CADENCE)
    flight = ~(codes["left_foot_contact"] | codes["right_foot_contact"])
    running_gait = moving & (cadence >= RUN_MIN_CADENCE) & (
        (window_fraction(flight, frames(1.0, fps)) >= RUN_FLIGHT) | (speed >= RUN_SPEED_ALONE))
    codes["running_gait"] = running_gait
    codes["walking"] = moving & ~running_gait
    # Sneaking: a slow walk leaning forward or crouched (HDM05's sneak leans 14–38°, walks ~3°).
    codes["sneaking"] = codes["walking"] & (speed < SNEAK_MAX_SPEED) & (
        (smooth(b.tilt, frames(1.0, fps)) > SNEAK_TILT_DEG) | (codes["pelvis_height"] < CROUCH_HEIGHT))
    codes["jogging"] = running_gait & (speed < JOG_MAX_SPEED)
    codes["running"] = running_gait & (speed >= JOG_MAX_SPEED)

    heading = np.unwrap(np.arctan2(b.forward[:, 0], b.forward[:, 2]))  # + when turning left
    codes["heading"] = heading
    yaw_rate = np.degrees(smooth(np.gradient(heading) * fps, frames(TURN_SMOOTH_S, fps)))
    codes["yaw_rate"] = yaw_rate
    codes["turning_left"] = yaw_rate > TURN_RATE_DEG
    codes["turning_right"] = yaw_rate < -TURN_RATE_DEG
    course = np.unwrap(np.arctan2(root_v[:, 0], root_v[:, 2]))   # direction of travel
    curve = np.degrees(smooth(np.gradient(course) * fps, frames(1.0, fps))) * going
    n = frames(CIRCLE_WINDOW_S, fps)
    for name, sign in (("circling_left", 1.0), ("circling_right", -1.0)):
        codes[name] = (moving & (sign * smooth(curve, n) > CIRCLE_RATE_DEG)
                       & (window_fraction(sign * curve > CIRCLE_RATE_DEG * 2 / 3, n) >= CIRCLE_SUSTAIN))


def _posture(b: BodyFrame, codes: dict) -> None:
    """Jumping, lying, sitting, squatting, crouching, bending over, standing still."""
    pelvis_h = b.height[:, sk.PELVIS]
    jumping = np.zeros(len(pelvis_h), bool)
    for s, e in runs(codes["airborne"]):
        if JUMP_MIN_FRAMES <= e - s <= JUMP_MAX_S * b.fps and (pelvis_h[s:e] - b.stand).max() >= JUMP_RISE:
            jumping[max(s - 2, 0):e + 2] = True                  # include take-off and landing
    codes["jumping"] = jumping
    rel, tilt = codes["pelvis_height"], b.tilt
    knee = {s: angle(b.joints[:, J[f"{s}_hip"]] - b.joints[:, J[f"{s}_knee"]],
                     b.joints[:, J[f"{s}_ankle"]] - b.joints[:, J[f"{s}_knee"]]) for s in SIDES}
    for side in SIDES:
        codes[f"{side}_knee_bent"] = knee[side] < KNEE_BENT_DEG
    lying = (tilt > LIE_TILT_DEG) & (rel < LIE_HEIGHT)
    sitting = ~lying & (rel < SIT_HEIGHT)
    low = ~lying & ~sitting
    codes["lying"], codes["sitting"] = lying, sitting
    codes["squatting"] = low & (rel < SQUAT_HEIGHT) & codes["left_knee_bent"] & codes["right_knee_bent"]
    codes["crouching"] = low & ~codes["squatting"] & (rel < CROUCH_HEIGHT)
    leaning = b.local(b.joints[:, sk.NECK] - b.joints[:, sk.PELVIS])[2] > 0
    codes["bending_forward"] = low & (tilt > BEND_TILT_DEG) & leaning & (rel >= SQUAT_HEIGHT)
    codes["standing_still"] = (codes["left_foot_contact"] & codes["right_foot_contact"]
                               & (codes["speed"] < STILL_SPEED) & low & (rel >= CROUCH_HEIGHT))


def _legs(b: BodyFrame, codes: dict) -> None:
    """Knee raised and forward kicks per leg (knee bend is set with the posture)."""
    pelvis = b.joints[:, sk.PELVIS]
    for side in SIDES:
        hip, kn, toe = J[f"{side}_hip"], J[f"{side}_knee"], J[f"{side}_foot"]
        thigh = angle(b.joints[:, kn] - b.joints[:, hip], DOWN)
        codes[f"{side}_knee_raised"] = ((thigh > KNEE_RAISED_DEG) & (b.foot_height(side) > FOOT_LIFTED)
                                        & (codes["pelvis_height"] > CROUCH_HEIGHT))
        toe_fwd_v = b.local(b.velocity[:, toe] - b.velocity[:, sk.PELVIS])[2]
        reach = b.local(b.joints[:, toe] - pelvis)[2]
        toe_up = b.height[:, toe] - b.toe_ground
        high_kick = ((toe_fwd_v > KICK_SPEED) & (toe_up > KICK_HEIGHT) & (reach > KICK_REACH)
                     & ~codes["running_gait"])
        codes[f"{side}_foot_kicking"] = high_kick | (toe_fwd_v > GROUND_KICK_SPEED)


def _arms(b: BodyFrame, codes: dict) -> None:
    """Hand height and placement, arm direction, elbow bend, waves, punches, swings, circles."""
    fps, t = b.fps, b.joints.shape[0]
    head = b.joints[:, sk.HEAD]
    wrists = {s: b.joints[:, J[f"{s}_wrist"]] for s in SIDES}
    codes["hands_together"] = np.linalg.norm(wrists["left"] - wrists["right"], axis=-1) < HANDS_TOGETHER
    for side, out in (("left", 1.0), ("right", -1.0)):
        sh, el = b.joints[:, J[f"{side}_shoulder"]], b.joints[:, J[f"{side}_elbow"]]
        wr = wrists[side]
        arm = wr - sh
        a_lat, a_up, a_fwd = b.local(arm)
        a_out = out * a_lat                                      # away from the body's midline
        elbow = angle(sh - el, wr - el)
        raised = angle(el - sh, DOWN) > ARM_RAISED_DEG
        p = f"{side}_"
        codes[p + "hand_above_head"] = wr[:, 1] > head[:, 1] + ABOVE_HEAD_MARGIN
        codes[p + "hand_at_head"] = wr[:, 1] > head[:, 1] - HEAD_BAND
        codes[p + "hand_at_shoulder"] = np.abs(a_up) < SHOULDER_BAND
        codes[p + "hand_low"] = wr[:, 1] < b.joints[:, sk.PELVIS, 1]
        codes[p + "hand_floor"] = b.height[:, J[f"{side}_wrist"]] < HAND_FLOOR_HEIGHT
        codes[p + "arm_forward"] = raised & (a_fwd > 0) & (a_fwd >= a_out)
        codes[p + "arm_sideways"] = raised & (a_out > 0) & (a_out > a_fwd)
        codes[p + "elbow_bent"] = elbow < ELBOW_BENT_DEG
        codes[p + "hand_near_face"] = np.linalg.norm(wr - head, axis=-1) < NEAR_FACE
        codes[p + "hand_near_hip"] = ((np.linalg.norm(wr - b.joints[:, J[f"{side}_hip"]], axis=-1) < NEAR_HIP)
                                      & (elbow < ELBOW_BENT_DEG))
        codes[p + "hand_waving"] = _waving(a_out, a_up, fps)
        extension = np.gradient(np.linalg.norm(arm, axis=-1)) * fps
        codes[p + "hand_punching"] = ((np.gradient(a_fwd) * fps > PUNCH_SPEED) & (extension > PUNCH_SPEED)
                                      & (elbow > PUNCH_ELBOW_DEG) & (a_up > PUNCH_LOW)
                                      & (wr[:, 1] < head[:, 1]))
        n = frames(1.0, fps)
        spread = np.sqrt(np.maximum(smooth(a_fwd ** 2, n) - smooth(a_fwd, n) ** 2, 0.0))
        codes[p + "arm_swinging"] = spread > SWING_STD
        # Sagittal angle about the shoulder: 0 down, 90 forward, 180 up, 270 behind; it grows
        # through a backward circle (forward, up, back, down).
        theta = np.degrees(np.unwrap(np.arctan2(a_fwd, -a_up)))
        half, idx = frames(ARM_CIRCLE_WINDOW_S, fps) // 2, np.arange(t)
        sweep = theta[np.minimum(idx + half, t - 1)] - theta[np.maximum(idx - half, 0)]
        codes[p + "arm_circling_backward"] = sweep > ARM_CIRCLE_DEG
        codes[p + "arm_circling_forward"] = sweep < -ARM_CIRCLE_DEG


def _waving(lateral: np.ndarray, up: np.ndarray, fps: float) -> np.ndarray:
    """Frames inside a chain of ≥ WAVE_MIN_REVERSALS quick lateral reversals of the hand, with
    the hand above the shoulder and moving more sideways than up and down."""
    out = np.zeros(lateral.shape[0], bool)
    turns = zigzag(smooth(lateral, 3), WAVE_AMPLITUDE)
    if len(turns) < WAVE_MIN_REVERSALS:
        return out
    quick = np.diff(turns) <= WAVE_HALF_PERIOD_S * fps
    for a, b in runs(quick):                                     # chains of quick reversals
        if b - a + 1 >= WAVE_MIN_REVERSALS:
            s, e = turns[a], turns[b] + 1
            if np.ptp(up[s:e]) < np.ptp(lateral[s:e]) and np.median(up[s:e]) > WAVE_HAND_HEIGHT:
                out[s:e] = True
    return out


def caption_clip(joints: np.ndarray, fps: float = sk.FPS, window: int = 40) -> list[Caption]:
    """Captions per part ("body", "left_upper", "right_upper", "left_lower", "right_lower")
    over windows of `window` frames (2 s at 20 fps), equal neighbours merged; each Caption
    covers frames [start, end) and the captions of a part tile the whole clip."""
    if window < 2:
        raise ValueError(f"window must be at least 2 frames, got {window}")
    return captions_from_codes(frame_codes(joints, fps), window)


def describe(joints: np.ndarray, fps: float = sk.FPS) -> str:
    """One sentence summarising a motion (T, 22, 3), for the reviewer and the UI."""
    return summarise(caption_clip(joints, fps))


def caption_accuracy(clips) -> dict:
    """How often the automatic captions agree with each clip's label family (walk, run, jump,
    squat, kick, …) over `Clip`s (every person of each): see `captions.score_clips`."""
    return score_clips([(c.label, c.prompt, caption_clip(p)) for c in clips for p in c.people])
