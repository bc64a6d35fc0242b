"""Pin planted feet after a motion has been turned onto a new path (the trajectory editor),
or where a generator let them slide (`lock_feet`, SPAM's output).

Turning each frame about the pelvis swings a planted foot round it (speed = turn rate × the
foot's distance from the pelvis). The fix keeps the pelvis on the curve and moves the legs:
during each stance of a foot (ankle or toe planted or in contact in the ORIGINAL motion) the
foot moves exactly as it did in the original, turned with the frame at the middle of the
stance, so it skates exactly as much as the original did. The correction this asks of each
foot (an XZ shift of the ankle and a yaw about it, the foot kept rigid) is carried smoothly
across the swing to the next stance (eased when the swing is short, faded out over `blend`
frames otherwise). Then a two-bone IK (hip fixed, knee in the plane of the mapped knee bend)
puts the ankle on its target and the toe on its own, every bone keeping its length; where a
stretched leg cannot reach, the whole body first shifts a few cm towards the foot.
"""

from __future__ import annotations

import numpy as np

from interplay.motion import features, metrics
from interplay.motion import skeleton as sk
from interplay.motion.signals import runs, smooth

REACH = 0.995     # share of a leg's length (thigh + shin) the IK may stretch to
MAX_SHIFT = 0.15  # m: the largest whole-body shift used to bring a foot within reach
# m per frame: how fast that shift may change (0.3 m/s at 20 fps). Unlimited, a foot held far
# behind a body that walked on pulled the body back within two frames: SPAM's walks jumped by
# up to 0.27 m in a frame (the pelvis moves ~0.04 m per frame). Where the shift cannot follow,
# the ankle stops on the line towards its goal (two_bone_ik) and the foot slides a little.
MAX_SHIFT_STEP = 0.015
# (hip, knee, ankle, toe) of each leg, left then right.
LEGS = tuple(tuple(sk.JOINT_INDEX[f"{side}_{j}"] for j in ("hip", "knee", "ankle", "foot"))
             for side in ("left", "right"))


def stance(joints: np.ndarray, fps: float = sk.FPS) -> np.ndarray:
    """(T, 2) bool per foot (left, right): ankle or toe planted (metrics.planted_feet) or in
    contact (features.foot_contacts) — the frames where the foot must stay put."""
    plant = metrics.planted_feet(joints, int(round(fps))) | features.foot_contacts(joints, fps)
    return plant.reshape(len(joints), 2, 2).any(axis=2)


def _rotate(xz: np.ndarray, angle) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([c * xz[..., 0] + s * xz[..., 1], -s * xz[..., 0] + c * xz[..., 1]], axis=-1)


def _fill(values: np.ndarray, known: np.ndarray, blend: int) -> np.ndarray:
    """values (T, D) defined where known (T,) bool; elsewhere: eased (smoothstep) from one
    known run to the next when they are at most 2 * blend frames apart, otherwise faded to
    zero over `blend` frames on each side."""
    out = np.where(known.reshape((-1,) + (1,) * (values.ndim - 1)), values, 0.0)
    t = len(known)
    for a, b in runs(~known):
        before = values[a - 1] if a > 0 else None
        after = values[b] if b < t else None
        if before is not None and after is not None and b - a <= 2 * blend:
            w = (np.arange(a, b) - (a - 1)) / (b - (a - 1))
            w = w * w * (3 - 2 * w)              # smoothstep: the foot lifts and lands gently
            out[a:b] = before * (1 - w)[:, None] + after * w[:, None]
            continue
        frames = np.arange(a, b)
        for edge, value in ((a - 1, before), (b, after)):
            if value is None:
                continue
            x = np.clip(1.0 - np.abs(frames - edge) / (blend + 1), 0.0, 1.0)
            out[a:b] += value * (x * x * (3 - 2 * x))[:, None]
    return out


def foot_targets(original: np.ndarray, mapped: np.ndarray, turn: np.ndarray,
                 fps: float = sk.FPS, blend: int = 4) -> np.ndarray:
    """Per frame and foot (left, right) a rigid ground correction of the mapped foot (T, 2, 3):
    the ankle's XZ shift and the foot's extra yaw (radians) about the ankle. During a stance
    the foot moves as in the original turned by the stance's middle frame's turn, so the yaw
    undoes the turning since then; across swings both are carried over (see _fill). Keeping
    the foot rigid keeps the ankle-to-toe vector's length, so the toe is never tipped."""
    t = len(original)
    plant = stance(original, fps)
    corr = np.zeros((t, 2, 3))
    for leg, (_, _, ankle, _) in enumerate(LEGS):
        for a, b in runs(plant[:, leg]):
            m = (a + b - 1) // 2
            moved = original[a:b, ankle][:, [0, 2]] - original[m, ankle][[0, 2]]
            target = mapped[m, ankle][[0, 2]] + _rotate(moved, turn[m])
            corr[a:b, leg, :2] = target - mapped[a:b, ankle][:, [0, 2]]
            corr[a:b, leg, 2] = turn[m] - turn[a:b]
        corr[:, leg] = _fill(corr[:, leg], plant[:, leg], blend)
    return corr


def two_bone_ik(hip: np.ndarray, knee: np.ndarray, target: np.ndarray, thigh: np.ndarray,
                shin: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Knee and ankle (T, 3) reaching for target (T, 3) from hip (T, 3) with bones of these
    lengths (T,); the knee stays in the plane through hip, target and the given knee. Out of
    reach the ankle stops on the line towards the target."""
    d = target - hip
    dist = np.linalg.norm(d, axis=1)
    dhat = d / np.maximum(dist, 1e-9)[:, None]
    reach = np.clip(dist, np.abs(thigh - shin) + 1e-6, (thigh + shin) * (1 - 1e-9))
    cos_a = np.clip((thigh ** 2 + reach ** 2 - shin ** 2) / (2 * thigh * reach), -1.0, 1.0)
    pole = knee - hip
    side = pole - np.sum(pole * dhat, axis=1, keepdims=True) * dhat
    side /= np.maximum(np.linalg.norm(side, axis=1, keepdims=True), 1e-9)
    new_knee = hip + thigh[:, None] * (cos_a[:, None] * dhat + np.sqrt(1 - cos_a ** 2)[:, None] * side)
    return new_knee, hip + reach[:, None] * dhat


def rate_limited(x: np.ndarray, step: float) -> np.ndarray:
    """x (T, D) with every frame-to-frame change at most `step` long, staying as close to x as
    a forward then a backward sweep allow (each sweep only shortens changes; the backward one
    keeps the forward one's bound)."""
    out = np.array(x, dtype=np.float64)
    for order in (range(1, len(out)), range(len(out) - 2, -1, -1)):
        for i in order:
            prev = out[i - 1] if order.step == 1 else out[i + 1]
            d = out[i] - prev
            n = np.linalg.norm(d)
            if n > step:
                out[i] = prev + d * (step / n)
    return out


def _root_shift(hips: np.ndarray, goals: np.ndarray, reach: np.ndarray) -> np.ndarray:
    """XZ shift (T, 2) of the whole body bringing ankle goals (T, 2 legs, 3) within reach
    (T, 2) of the hips (T, 2, 3): a few rounds of stepping towards the goals that are too far,
    averaged over 3 frames, capped at MAX_SHIFT, and changing by at most MAX_SHIFT_STEP a frame
    so the body never jerks; none on the first and last frame (stretches treated one by one
    still meet), growing from there at that rate at most."""
    shift = np.zeros((len(hips), 2))
    for _ in range(10):
        d = goals - hips
        d[..., [0, 2]] -= shift[:, None]
        excess = np.maximum(np.linalg.norm(d, axis=-1) - reach, 0.0)           # (T, 2)
        flat = d[..., [0, 2]]
        flat /= np.maximum(np.linalg.norm(flat, axis=-1, keepdims=True), 1e-9)
        shift += smooth((excess[..., None] * flat).sum(axis=1), 3)
        norm = np.linalg.norm(shift, axis=1, keepdims=True)
        shift *= np.minimum(1.0, MAX_SHIFT / np.maximum(norm, 1e-9))
    t = len(shift)
    room = MAX_SHIFT_STEP * np.minimum(np.arange(t), np.arange(t)[::-1])[:, None]   # (T, 1)
    shift *= np.minimum(1.0, room / np.maximum(np.linalg.norm(shift, axis=1, keepdims=True), 1e-9))
    return rate_limited(shift, MAX_SHIFT_STEP)


def pin_feet(original: np.ndarray, mapped: np.ndarray, turn: np.ndarray, fps: float = sk.FPS,
             blend: int = 4) -> np.ndarray:
    """Mapped joints (T, 22, 3) with the legs re-posed so planted feet stay put (module doc).
    `turn` (T,) is the heading change each frame got; bone lengths are the mapped frame's own.
    Where a leg cannot reach (stretched at heel strike or push-off) the whole body first shifts
    a little towards the foot (at most MAX_SHIFT), so feet are not lifted off the ground."""
    return apply_foot_corrections(mapped, foot_targets(original, mapped, turn, fps, blend))


def lock_feet(joints: np.ndarray, fps: float = sk.FPS, blend: int = 4, edge: int = 4
              ) -> np.ndarray:
    """Joints (T, 22, 3) whose feet stay where they are at the middle of each stance (a
    generated motion's sliding planted feet); the correction fades to nothing over `edge`
    frames at both ends, so consecutive stretches treated one by one still meet exactly."""
    t = len(joints)
    plant = stance(joints, fps)
    corr = np.zeros((t, 2, 3))
    for leg, (_, _, ankle, _) in enumerate(LEGS):
        for a, b in runs(plant[:, leg]):
            m = (a + b - 1) // 2
            corr[a:b, leg, :2] = joints[m, ankle][[0, 2]] - joints[a:b, ankle][:, [0, 2]]
        corr[:, leg] = _fill(corr[:, leg], plant[:, leg], blend)
    ramp = np.minimum(1.0, np.minimum(np.arange(t), np.arange(t)[::-1]) / max(1, edge))
    return apply_foot_corrections(joints, corr * ramp[:, None, None])


def apply_foot_corrections(mapped: np.ndarray, corr: np.ndarray,
                           lift: np.ndarray | None = None) -> np.ndarray:
    """Mapped joints with each foot moved rigidly by corr (T, 2, 3: ankle XZ shift, yaw about
    the ankle) and raised by `lift` (T, 2) metres where given, by two-bone IK of the legs (hips
    fixed after a whole-body shift of at most MAX_SHIFT where a leg cannot reach)."""
    hip, knee, ankle, toe = (list(j) for j in zip(*LEGS))                       # (2,) each
    bone = lambda a, b: np.linalg.norm(mapped[:, a] - mapped[:, b], axis=-1)    # (T, 2)
    thigh, shin, foot = bone(knee, hip), bone(ankle, knee), bone(toe, ankle)
    goal_ankle = mapped[:, ankle].copy()                                         # (T, 2, 3)
    goal_ankle[..., [0, 2]] += corr[..., :2]
    if lift is not None:
        goal_ankle[..., 1] += lift
    goal_toe = goal_ankle + mapped[:, toe] - mapped[:, ankle]
    goal_toe[..., [0, 2]] = goal_ankle[..., [0, 2]] + _rotate(
        (mapped[:, toe] - mapped[:, ankle])[..., [0, 2]], corr[..., 2])
    out = mapped.copy()
    out[..., [0, 2]] += _root_shift(mapped[:, hip], goal_ankle, REACH * (thigh + shin))[:, None]
    for leg in range(2):
        out[:, knee[leg]], out[:, ankle[leg]] = two_bone_ik(
            out[:, hip[leg]], out[:, knee[leg]], goal_ankle[:, leg], thigh[:, leg], shin[:, leg])
        along = goal_toe[:, leg] - out[:, ankle[leg]]
        out[:, toe[leg]] = out[:, ankle[leg]] + foot[:, leg, None] * along / np.maximum(
            np.linalg.norm(along, axis=1, keepdims=True), 1e-9)
    return out


def ground(joints: np.ndarray, window: int = 25, edge: int = 4, fade_start: bool = True
           ) -> np.ndarray:
    """Joints (T, 22, 3) moved vertically so that, within every `window` frames (1.25 s), the
    lowest joint touches y = 0: a generated body that hovers or sinks is put on the floor while
    a jump's flight (shorter than half the window) keeps its height above the take-off and
    landing. The shift is smoothed over 9 frames and fades out over `edge` frames at both ends,
    so stretches treated one by one still meet."""
    t = len(joints)
    lowest = joints[..., 1].min(axis=1)
    half = window // 2                     # rolling minimum (window_percentile at 0 is ~50x slower)
    padded = np.pad(lowest, (half, window - 1 - half), mode="edge")
    floor = np.lib.stride_tricks.sliding_window_view(padded, window).min(axis=1)
    start = np.arange(t) if fade_start else np.full(t, edge)   # a motion's first frame: no fade
    ramp = np.minimum(1.0, np.minimum(start, np.arange(t)[::-1]) / max(1, edge))
    out = joints.copy()
    shift = np.minimum(smooth(floor, 9), lowest)     # smoothing never sinks a frame
    out[..., 1] -= (shift * ramp)[:, None]
    return out
