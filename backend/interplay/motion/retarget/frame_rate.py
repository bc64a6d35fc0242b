"""What frame rate a capture really has, from the motion itself, and the clean-up every CMU
BVH conversion needs before use (lead-in frames, broken root tracks).

Headers lie: the salsa files say 120 fps where CMU's index says 60, and 16_01/16_02 say 30
where the index says 120. All gait and physics measures below take joints (T, 22, 3) in
metres at the file's native frame spacing and a *hypothesised* rate, so the same clip can be
judged at each candidate rate.

Evidence (all 58 cmu-bvh trials and 14 salsa pairs, numbers from `gait_stats`; rerun with
`load_cmu_bvh`/`load_salsa_pair`, which store them in meta["fps_evidence"]):
- Gravity: in the 13 jumps the pelvis falls at 8.6–10.0 m/s² at 120 fps (2.1–2.5 at 60),
  including 16_01/16_02 (9.9, 10.0) whose header says 30 fps — their header is wrong and
  CMU's index (120) right. The 11 runs' short flights give 10.5–19.4 at 120, 2.6–4.9 at 60.
- cmu-bvh at 120 fps: 32 walks 0.6–1.8 m/s at 1.2–2.2 steps/s, 11 runs 2.5–3.5 m/s at
  2.1–2.9 steps/s (weight changes). At 60 the walks would crawl at 0.3–0.9 m/s, 0.6–1.1
  steps/s.
- Salsa (header 120, index 60), at 60 | 120 fps: pelvis 0.35–0.46 | 0.70–0.92 m/s (lead),
  0.51–0.63 | 1.01–1.26 m/s (follow); weight changes 1.2–1.7 | 2.4–3.4 /s (a 2 cm foot
  lift is needed to count one, so in-place salsa steps are missed: cadence alone does not
  decide); the follower's fastest full turn 0.55–1.03 | 0.28–0.52 s (a salsa turn takes two
  beats, ≈0.7 s at 170 BPM). Decisive: horizontal centre-of-mass acceleration (99th
  percentile, 0.2 s smoothing) 2.5–3.6 (lead) / 3.4–4.4 (follow) | 7.1–9.1 / 8.7–12.7 m/s²,
  against 0.8–2.3 for the walks, 1.2–1.8 for the runs and ≤ 4.7 for the jumps at their
  gravity-checked 120 fps: at 120 the dancers would push sideways with about a full g,
  beyond what floor friction gives. The frames are genuine samples, not 60→120
  interpolation (second differences are alike on odd and even frames), so the header is
  simply mislabelled: SALSA_FPS = 60.
- Two trials (07_12, 09_10) have broken root tracks: implausible at every rate (23 and 54
  m/s² at 120, 14 and 54 at 60); `motion_defects` reports them.
"""

from __future__ import annotations

from typing import TypedDict

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import facing_angle

SALSA_FPS = 60
CMU_RATES = (120, 60)  # the only rates in CMU's index (2109 and 326 trials)
GRAVITY = 9.81
# Free fall we accept as gravity (m/s²); candidates 2× apart give 4× apart values, so at
# most one candidate lands in this band.
GRAVITY_RANGE = (6.0, 16.0)
# Highest 99th-percentile horizontal centre-of-mass acceleration we accept (m/s², 0.2 s
# smoothing): CMU runners and walkers reach 2.1–2.3, jumpers ~3, the salsa follower 3.9.
MAX_COM_ACCELERATION = 6.0


def _smooth(x: np.ndarray, width: int) -> np.ndarray:
    """Moving average along axis 0 ('valid' part)."""
    if width <= 1 or x.shape[0] <= width:
        return x
    c = np.cumsum(np.concatenate([np.zeros((1,) + x.shape[1:]), x]), axis=0)
    return (c[width:] - c[:-width]) / width


def _foot_heights(joints: np.ndarray) -> np.ndarray:
    """(T, 2) height of each foot (lower of ankle and toe) above its own low level."""
    out = []
    for ankle, toe in ((sk.LEFT_ANKLE, sk.LEFT_FOOT), (sk.RIGHT_ANKLE, sk.RIGHT_FOOT)):
        h = [joints[:, j, 1] - np.percentile(joints[:, j, 1], 5) for j in (ankle, toe)]
        out.append(np.minimum(*h))
    return np.stack(out, axis=1)


def weight_changes(joints: np.ndarray, hysteresis: float = 0.02) -> int:
    """Number of times the support switches feet: which foot is lower flips by more than
    `hysteresis` metres. One per step in walking and running; independent of frame rate."""
    diff = np.diff(_foot_heights(joints), axis=1)[:, 0]
    side = np.where(diff > hysteresis, 1, np.where(diff < -hysteresis, -1, 0))
    side = side[side != 0]
    return int(np.count_nonzero(side[1:] != side[:-1]))


def flight_gravity(joints: np.ndarray, fps: float, clearance: float = 0.06, min_frames: int = 6,
                   max_seconds: float = 1.2) -> float | None:
    """Downward acceleration (m/s²) of the pelvis over the longest stretch with both feet
    more than `clearance` above the floor, by a parabola fit; None without such a stretch
    (or when it lasts longer than any jump, which means the floor estimate is off)."""
    low = joints[:, list(sk.FOOT_JOINTS), 1].min(axis=1)
    air = np.r_[False, low > np.percentile(low, 2) + clearance, False]
    edges = np.flatnonzero(np.diff(air.astype(int)))
    if edges.size == 0:
        return None
    starts, ends = edges[::2], edges[1::2]
    k = int(np.argmax(ends - starts))
    if not min_frames <= ends[k] - starts[k] <= max_seconds * fps:
        return None
    t = np.arange(starts[k], ends[k])
    curvature = np.polyfit((t - t.mean()) / fps, joints[t, sk.PELVIS, 1], 2)[0]
    return float(-2.0 * curvature)


class GaitStats(TypedDict):
    cadence: float
    speed: float
    com_acceleration_p99: float
    fastest_turn_s: float | None
    flight_gravity: float | None


def gait_stats(joints: np.ndarray, fps: float) -> GaitStats:
    """Cadence (weight changes/s), mean pelvis ground speed (m/s), 99th-percentile horizontal
    centre-of-mass acceleration (m/s², 0.2 s smoothing), fastest full turn (s, None if the
    body never turns 360°) and flight-phase gravity (m/s², None without flight)."""
    t = joints.shape[0]
    duration = (t - 1) / fps
    path = np.linalg.norm(np.diff(joints[:, sk.PELVIS, [0, 2]], axis=0), axis=-1).sum()
    width = max(3, int(round(0.2 * fps)))
    com = _smooth(np.einsum("tjc,j->tc", joints, sk.SEGMENT_MASS), width)
    acc = _smooth(np.diff(com, 2, axis=0) * fps * fps, width)
    yaw = np.unwrap(facing_angle(joints))
    turn = None
    for k in range(1, t):
        if np.any(np.abs(yaw[k:] - yaw[:-k]) >= 2 * np.pi):
            turn = k / fps
            break
    return {
        "cadence": weight_changes(joints) / duration,
        "speed": float(path / duration),
        "com_acceleration_p99": float(np.percentile(np.linalg.norm(acc[:, [0, 2]], axis=1), 99)) if len(acc) else 0.0,
        "fastest_turn_s": turn,
        "flight_gravity": flight_gravity(joints, fps),
    }


def estimate_true_fps(joints: np.ndarray, candidates=CMU_RATES,
                      prior: float | None = None) -> tuple[float, dict[float, GaitStats]]:
    """The capture rate among `candidates` that makes the motion physical. A flight phase
    decides alone (the rate whose free fall lies in GRAVITY_RANGE); otherwise the `prior`
    (the header's rate) if the centre-of-mass acceleration stays under MAX_COM_ACCELERATION
    at it, else the highest candidate where it does (a slower rate only makes motion
    gentler, so the highest plausible one assumes least). If no candidate is plausible the
    prior (or the highest candidate) is returned and `motion_defects` reports it.
    Returns (fps, {candidate: gait_stats}) so callers can record the evidence."""
    joints = np.asarray(joints, dtype=np.float64)
    if joints.ndim != 3 or joints.shape[1:] != (sk.NUM_JOINTS, 3) or joints.shape[0] < 10:
        raise ValueError(f"joints must be (T ≥ 10, {sk.NUM_JOINTS}, 3), got {joints.shape}")
    table = {float(c): gait_stats(joints, c) for c in candidates}
    falls = [c for c, s in table.items()
             if s["flight_gravity"] and GRAVITY_RANGE[0] <= s["flight_gravity"] <= GRAVITY_RANGE[1]]
    if falls:
        return falls[0], table
    ok = [c for c, s in table.items() if s["com_acceleration_p99"] <= MAX_COM_ACCELERATION]
    if prior is not None and float(prior) in ok:
        return float(prior), table
    if ok:
        return max(ok), table
    return float(prior) if prior is not None else max(table), table


def motion_defects(evidence: dict[float, GaitStats]) -> list[str]:
    """Reasons a clip is unusable, from `estimate_true_fps`'s table; empty if none. A clip
    whose centre of mass accelerates implausibly at every CMU rate has a broken root track
    (07_12 and 09_10: the body is fine but hovers and slides; 23 and 54 m/s² at 120 fps,
    14 and 54 at 60, where every other clip stays under 5 at its true rate)."""
    acc = {c: s["com_acceleration_p99"] for c, s in evidence.items()}
    if all(a > MAX_COM_ACCELERATION for a in acc.values()):
        rates = ", ".join(f"{a:.0f} m/s² at {c:g} fps" for c, a in sorted(acc.items()))
        return [f"centre of mass accelerates implausibly at every capture rate ({rates}): "
                "broken root translation"]
    return []


def lead_in_frames(positions: np.ndarray, max_frames: int = 30, factor: float = 3.0) -> int:
    """Frames to drop at the start: cgspeed's conversions open with a T-pose that blends into
    the motion over ~5 frames (joints jump 15–30 cm per frame, 10× the usual). Returns the
    first frame from which two successive frame-to-frame jumps are ordinary (positions
    (T, J, 3) in any unit)."""
    jumps = np.abs(np.diff(positions, axis=0)).max(axis=(1, 2))
    if jumps.size < 3:
        return 0
    limit = factor * np.median(jumps)
    for i in range(min(max_frames, jumps.size - 1)):
        if jumps[i] <= limit and jumps[i + 1] <= limit:
            return i
    return 0
