"""Base postures taken from real captured frames of the library (`motion.clip`), found by
their measures (`motion/checks/measures.py`: pelvis height over standing, torso tilt, the
chest's direction, hands and knees on the floor), canonicalised (floor at y = 0, pelvis over
the origin, facing +Z) and cached:

- standing: the stillest upright second of a captured stand, low-passed and played back and
  forth, so a held stand keeps a light captured sway;
- prone / supine: the flattest lying frame with the chest facing down / up;
- all_fours: a frame on hands and knees (or feet); kneeling: a knee on the floor, upright;
- seated: the standing frame sat onto a seat of a given height by two-bone IK (thighs level,
  shins down to the floor); the captures hold no chair;
- walk: a captured straight walk (the gait primitives' base).

    base = posture("prone", seconds=4.0)          # (80, 22, 3)
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from interplay.generators.primitives.body import axes, hold, trunk_axes
from interplay.motion import skeleton as sk
from interplay.motion.checks import measures as m
from interplay.motion.clip import Clip, default_clips
from interplay.motion.ik import two_bone_ik
from interplay.motion.kinematics import canonicalize
from interplay.motion.signals import smooth

J = sk.JOINT_INDEX
NAMES = ("standing", "seated", "floor", "kneeling", "prone", "supine", "all_fours", "walk")
SEAT_M = 0.45           # a chair's seat height
SWAY_SMOOTH_S = 0.6     # the stand's low pass
STAND_WINDOW_S = 1.5
WALK_LABELS = ("walk (normal)", "walk")


@dataclass(frozen=True)
class Found:
    """A posture's captured source: the clip and frame(s) it came from."""
    name: str
    clip: str
    frames: tuple[int, int]
    licence: str


def _single(clips) -> list[Clip]:
    return [c for c in clips if len(c.people) == 1 and not c.synthetic and c.frames >= 2]


def _canon(j: np.ndarray) -> np.ndarray:
    return canonicalize([np.asarray(j, dtype=np.float64)])[0][0]


def _chest_up(j: np.ndarray) -> np.ndarray:
    return trunk_axes(j)[2][:, 1]


def _best(clips, score) -> tuple[Clip, int, float]:
    """(clip, frame, score) maximising score(clip) → (T,) (−inf where not eligible)."""
    best: tuple[Clip | None, int, float] = (None, 0, -np.inf)
    for c in clips:
        s = score(c)
        k = int(np.argmax(s))
        if s[k] > best[2]:
            best = (c, k, float(s[k]))
    if best[0] is None or not np.isfinite(best[2]):
        raise LookupError("no captured frame fits this posture")
    return best[0], best[1], best[2]


def _lying(face: float):
    def score(c: Clip) -> np.ndarray:
        j = c.people[0].astype(np.float64)
        b = m.frame_of(j)
        ok = m.lying(b) & (face * _chest_up(j) > 0.8)
        flat = face * _chest_up(j) - 2.0 * b.height[:, sk.PELVIS]
        return np.where(ok, flat, -np.inf)
    return score


def _stand_score(c: Clip) -> np.ndarray:
    j = c.people[0].astype(np.float64)
    b = m.frame_of(j)
    w = int(STAND_WINDOW_S * sk.FPS)
    if len(j) < w + 1:
        return np.full(len(j), -np.inf)
    apart = j[:, sk.LEFT_ANKLE] - j[:, sk.RIGHT_ANKLE]
    across = (apart * b.left).sum(-1)
    side_by_side = (np.abs((apart * b.forward).sum(-1)) < 0.10) & (across > 0.10) & (across < 0.40)
    feet = (b.foot_height("left") < 0.03) & (b.foot_height("right") < 0.03)
    hands_down = np.maximum(j[:, sk.LEFT_HAND, 1], j[:, sk.RIGHT_HAND, 1]) < j[:, sk.PELVIS, 1]
    ok = (m.standing(b) & (b.tilt < 12) & side_by_side & feet
          & hands_down)
    speed = np.linalg.norm(b.velocity, axis=-1).mean(axis=1)
    good = np.convolve(ok.astype(float), np.ones(w), "valid") >= w
    still = -np.convolve(speed, np.ones(w) / w, "valid")
    s = np.where(good, still, -np.inf)
    return np.concatenate([s, np.full(len(j) - len(s), -np.inf)])


def _fours_score(c: Clip) -> np.ndarray:
    j = c.people[0].astype(np.float64)
    b = m.frame_of(j)
    knees = np.minimum(b.height[:, J["left_knee"]], b.height[:, J["right_knee"]])
    ok = m.on_all_fours(b) & (_chest_up(j) < -0.5) & (b.tilt < 110) & (knees < m.KNEE_DOWN_M)
    return np.where(ok, -np.abs(b.tilt - 90.0), -np.inf)


def _kneel_score(c: Clip) -> np.ndarray:
    j = c.people[0].astype(np.float64)
    b = m.frame_of(j)
    knees = np.minimum(b.height[:, J["left_knee"]], b.height[:, J["right_knee"]])
    ok = m.kneeling(b) & (knees < 0.10) & ~m.sitting(b)
    return np.where(ok, -b.tilt, -np.inf)


def _floor_score(c: Clip) -> np.ndarray:
    """Sitting on the floor: the benchmark's sitting (pelvis under half its standing height,
    torso within 50° of upright), upright, hands low (not caught mid-fall)."""
    j = c.people[0].astype(np.float64)
    b = m.frame_of(j)
    hands = np.maximum(j[:, sk.LEFT_HAND, 1], j[:, sk.RIGHT_HAND, 1]) < j[:, J["spine3"], 1]
    ok = m.sitting(b) & (b.tilt < 25) & hands & (b.height[:, sk.PELVIS] < 0.35)
    return np.where(ok, -b.tilt, -np.inf)


@lru_cache(maxsize=8)
def found(name: str) -> tuple[np.ndarray, Found]:
    """(captured frames (K, 22, 3) canonicalised, where they came from) for one posture."""
    clips = _single(default_clips())
    if name == "standing":
        c, k, _ = _best(clips, _stand_score)
        w = int(STAND_WINDOW_S * sk.FPS)
        j = _canon(c.people[0][k:k + w])
        return j, Found(name, c.id, (k, k + w), c.licence)
    if name == "walk":
        walks = [c for c in clips if c.label in WALK_LABELS and c.split == "train"]
        c = max(walks, key=lambda c: c.frames)
        return _canon(c.people[0]), Found(name, c.id, (0, c.frames), c.licence)
    score = {"prone": _lying(-1.0), "supine": _lying(1.0), "all_fours": _fours_score,
             "kneeling": _kneel_score, "floor": _floor_score}.get(name)
    if score is None:
        raise ValueError(f"unknown posture {name!r}; expected one of {', '.join(NAMES)}")
    c, k, _ = _best(clips, score)
    return _canon(c.people[0][k:k + 1]), Found(name, c.id, (k, k + 1), c.licence)


def sway(frames: np.ndarray, t: int) -> np.ndarray:
    """T frames of a low-passed captured window played back and forth (a light sway)."""
    f = smooth(np.asarray(frames, dtype=np.float64), max(1, int(SWAY_SMOOTH_S * sk.FPS)))
    if len(f) < 2:
        return hold(f[0], t)
    loop = np.concatenate([f, f[-2:0:-1]])
    return loop[np.arange(t) % len(loop)]


def loop_walk(walk: np.ndarray, t: int) -> np.ndarray:
    """A captured walk made T frames long: cut where its pose (about the pelvis) comes back
    nearest its first frame's, and the cycles laid end to end, each moved on the ground to
    continue from where the last one stopped."""
    rel = walk - walk[:, sk.PELVIS:sk.PELVIS + 1] * np.array([1.0, 0.0, 1.0])
    half = len(walk) // 2
    k = half + int(np.argmin(np.linalg.norm(rel[half:] - rel[0], axis=-1).mean(axis=1)))
    cycle = walk[:k]
    step = (walk[k] - walk[0])[sk.PELVIS] * np.array([1.0, 0.0, 1.0])
    reps = -(-t // k)
    out = np.concatenate([cycle + i * step for i in range(reps)])
    return out[:t].copy()


def _fit_bones(j: np.ndarray, ref: np.ndarray) -> np.ndarray:
    """The low pass shortens bones slightly: re-pose on the reference frame's bone lengths."""
    from interplay.motion.kinematics import fit_offsets, forward_kinematics, inverse_kinematics
    off = fit_offsets(ref[:1].repeat(2, axis=0))
    local, root = inverse_kinematics(j, off)
    return forward_kinematics(local, root, off)[0]


def seated(stand: np.ndarray, seat_m: float = SEAT_M) -> np.ndarray:
    """A standing motion (T, 22, 3) sat onto a seat `seat_m` high: the body above the hips
    lowered and moved back over the seat, thighs level forward, shins down to the floor."""
    j = np.asarray(stand, dtype=np.float64).copy()
    left, up, fwd = axes(j)
    hips = 0.5 * (j[:, sk.LEFT_HIP] + j[:, sk.RIGHT_HIP])
    thigh = float(np.linalg.norm(j[0, J["left_knee"]] - j[0, sk.LEFT_HIP]))
    drop = hips[:, 1] - (seat_m + 0.08)
    shift = -drop[:, None] * up - 0.5 * thigh * fwd
    j += shift[:, None]
    for side in ("left", "right"):
        hip = j[:, J[f"{side}_hip"]]
        knee = hip + 0.95 * thigh * fwd
        ankle = knee.copy()
        ankle[:, 1] = np.minimum(stand[:, sk.LEFT_ANKLE, 1], stand[:, sk.RIGHT_ANKLE, 1])
        ankle += 0.05 * fwd
        j = two_bone_ik(j, f"{side}_leg", ankle, pole=knee + 0.3 * up, carry="keep")
    return j


def posture(name: str, seconds: float | None = None, frames: int | None = None,
            seat_m: float = SEAT_M) -> np.ndarray:
    """A base posture (T, 22, 3) held for `seconds` (or `frames`): the stand with its sway,
    the others as their captured frame held still (the walk: its first T frames)."""
    t = frames if frames is not None else max(2, int(round((seconds or 2.0) * sk.FPS)))
    if name == "walk":
        j, _ = found("walk")
        return j[:t].copy() if t <= len(j) else loop_walk(j, t)
    if name in ("standing", "seated"):
        j, _ = found("standing")
        base = _fit_bones(sway(j, t), j)
        return seated(base, seat_m) if name == "seated" else base
    j, _ = found(name)
    return hold(j[0], t)
