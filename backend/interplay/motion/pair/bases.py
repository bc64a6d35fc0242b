"""Real single-person motion to compose two-person clips from: quiet standing windows and
level walks found in the processed set, stretched to the length a composed clip needs.
numpy only.

Standing: frames where a person stands upright and still (pelvis and ankles slow over the
ground, trunk vertical, both wrists below the chest and slow relative to the pelvis), in runs
of at least `min_frames`. Captured standing is scarce (clips are pre-cut around actions: the
quiet starts of HDM05 clips, the pauses of CMU 8-action signals, the wait before a jump), so
a run shorter than the clip is played back and forth with a cosine time warp (speed falls to
zero at each turn, so there is no velocity jump), then re-posed on the person's fixed bones.

Walks: real level walks (prompt with "walk", not the uneven-terrain ones). A walk shorter than
needed is looped on its gait cycle: the pair of frames a cycle apart whose body poses (in the
heading frame) and velocities match best, each repetition moved rigidly onto the end of the
previous one and the small seam residual faded out over a few frames.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.clip import Clip
from interplay.motion.kinematics import facing_angle, fit_to_skeleton
from interplay.motion.pair.windows import mirror
from interplay.motion.rotations import yaw_matrix

SPINE3 = sk.JOINT_INDEX["spine3"]


@dataclass(frozen=True)
class StandConfig:
    pelvis_speed: float = 0.3     # m/s over the ground
    ankle_speed: float = 0.4      # m/s over the ground, each ankle
    wrist_speed: float = 0.8      # m/s relative to the pelvis, each wrist
    upright: float = 0.9          # cosine of the pelvis→neck line with the vertical
    min_height: float = 0.9       # pelvis above the lowest joint, × the person's leg length
    min_frames: int = 12


@dataclass(frozen=True)
class Base:
    """A stretch of one real clip: clip.people[0][start:end]."""
    clip: Clip
    start: int
    end: int

    @property
    def frames(self) -> int:
        return self.end - self.start


def _ground_speed(x: np.ndarray) -> np.ndarray:
    """Horizontal speed (T, ...) m/s of positions (T, ..., 3) at 20 fps (centred differences)."""
    if len(x) < 2:
        return np.zeros(x.shape[:-1])
    return np.linalg.norm(np.gradient(x[..., [0, 2]], axis=0), axis=-1) * sk.FPS


def _runs(mask: np.ndarray, min_len: int) -> list[tuple[int, int]]:
    edges = np.diff(np.concatenate([[0], mask.astype(int), [0]]))
    starts, ends = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)
    return [(int(s), int(e)) for s, e in zip(starts, ends) if e - s >= min_len]


def standing_mask(joints: np.ndarray, cfg: StandConfig = StandConfig()) -> np.ndarray:
    """(T,) bool: frames where the person stands upright and still (see the module doc)."""
    j = np.asarray(joints, dtype=np.float64)
    legs = np.median(np.linalg.norm(j[:, [sk.LEFT_HIP, sk.JOINT_INDEX["left_knee"]]]
                                    - j[:, [sk.JOINT_INDEX["left_knee"], sk.LEFT_ANKLE]], axis=-1).sum(1))
    height = j[:, sk.PELVIS, 1] - j[..., 1].min(axis=1)
    spine = j[:, sk.NECK] - j[:, sk.PELVIS]
    lean = spine[:, 1] / np.maximum(np.linalg.norm(spine, axis=-1), 1e-9)
    rel = j - j[:, [sk.PELVIS]]
    wrists = (sk.LEFT_HAND, sk.RIGHT_HAND)
    wrist_speed = (np.linalg.norm(np.gradient(rel[:, wrists], axis=0), axis=-1).max(axis=1) * sk.FPS
                   if len(j) > 1 else np.zeros(len(j)))
    return ((_ground_speed(j[:, sk.PELVIS]) < cfg.pelvis_speed)
            & (_ground_speed(j[:, [sk.LEFT_ANKLE, sk.RIGHT_ANKLE]]).max(axis=1) < cfg.ankle_speed)
            & (height > cfg.min_height * legs) & (lean > cfg.upright)
            & (wrist_speed < cfg.wrist_speed)
            & (j[:, wrists, 1].max(axis=1) < j[:, SPINE3, 1]))


def _real_singles(clips) -> list[Clip]:
    return [c for c in clips if not c.synthetic and len(c.people) == 1]


def standing_bases(clips, cfg: StandConfig = StandConfig()) -> list[Base]:
    """Every quiet standing run of the real single-person clips."""
    return [Base(c, s, e) for c in _real_singles(clips)
            for s, e in _runs(standing_mask(c.people[0], cfg), cfg.min_frames)]


# Walks that are not a straight walk ahead (backwards, sideways, turning …) are no bases.
NOT_AHEAD = ("uneven", "backward", "sideways", "diagonal", "turn", "circle", "to the left",
             "to the right")


def walk_bases(clips, min_frames: int = 40, min_speed: float = 0.5, ahead: float = 0.8) -> list[Base]:
    """Whole real level walks ahead (at least `min_frames`, pelvis faster than `min_speed`
    m/s, travelling within acos(`ahead`) of the way the person faces at the start)."""
    out = []
    for c in _real_singles(clips):
        if "walk" not in c.prompt or any(w in c.prompt for w in NOT_AHEAD) or c.frames < min_frames:
            continue
        j = c.people[0].astype(np.float64)
        travel = (j[-1, sk.PELVIS] - j[0, sk.PELVIS])[[0, 2]]
        dist = float(np.linalg.norm(travel))
        if dist / (c.frames - 1) * sk.FPS < min_speed:
            continue
        fwd = np.array([np.sin(facing_angle(j[0])), np.cos(facing_angle(j[0]))])
        if travel @ fwd >= ahead * dist:
            out.append(Base(c, 0, c.frames))
    return out


def base_joints(base: Base, flip: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """The base's joints (T, 22, 3) float64 and rest offsets (22, 3), mirrored if `flip`."""
    j = base.clip.people[0][base.start:base.end].astype(np.float64)
    off = np.asarray(base.clip.offsets[0], dtype=np.float64)
    return (mirror(j), mirror(off)) if flip else (j, off)


def play_back_and_forth(joints: np.ndarray, frames: int, phase: float = 0.0) -> np.ndarray:
    """`frames` frames from a short clip (L, 22, 3) played forwards and backwards with a cosine
    time warp τ(t) = (L-1)(1 - cos(π(t/(L-1) + phase)))/2 (mean speed 1, zero at the turns),
    linearly interpolated. A clip at least `frames` long is cut from `phase` × its spare
    frames instead."""
    n = len(joints)
    if n >= frames:
        s = int(round(phase % 1.0 * (n - frames)))
        return joints[s:s + frames].copy()
    if n < 2:
        return np.repeat(joints[:1], frames, axis=0)
    t = np.arange(frames) / (n - 1)
    tau = (n - 1) * 0.5 * (1.0 - np.cos(np.pi * (t + phase)))
    lo = np.clip(np.floor(tau).astype(int), 0, n - 2)
    w = (tau - lo)[:, None, None]
    return joints[lo] * (1.0 - w) + joints[lo + 1] * w


def _pose_features(joints: np.ndarray) -> np.ndarray:
    """(T, 66): joints relative to the pelvis (XZ) in each frame's heading frame."""
    rel = joints - joints[:, [sk.PELVIS]] * [1.0, 0.0, 1.0]
    rot = yaw_matrix(-facing_angle(joints))
    return np.einsum("tij,tkj->tki", rot, rel).reshape(len(joints), -1)


def gait_cycle(joints: np.ndarray, shortest: int = 16, longest: int = 48) -> tuple[int, int]:
    """Frames (a, b), b - a in [shortest, longest], where the motion best repeats itself:
    smallest mean pose difference plus velocity difference (in the heading frame)."""
    f = _pose_features(joints)
    v = np.gradient(f, axis=0)
    n = len(f)
    best, pair = np.inf, (0, n - 1)
    for lag in range(shortest, min(longest, n - 2) + 1):
        cost = (np.abs(f[lag:] - f[:-lag]).mean(axis=1) + 2.0 * np.abs(v[lag:] - v[:-lag]).mean(axis=1))
        i = int(np.argmin(cost[1:])) + 1 if len(cost) > 1 else 0
        # A slight preference for long cycles: fewer seams in the loop.
        if cost[i] * (1.0 + 0.5 / lag) < best:
            best, pair = cost[i] * (1.0 + 0.5 / lag), (i, i + lag)
    return pair


def loop_walk(joints: np.ndarray, frames: int, fade: int = 6) -> np.ndarray:
    """A walk (T, 22, 3) extended to `frames` frames by repeating its gait cycle (see the
    module doc); a walk at least that long is cut to its first `frames`."""
    if len(joints) >= frames:
        return joints[:frames].copy()
    if len(joints) < 20:
        raise ValueError(f"a walk of {len(joints)} frames is too short to loop")
    a, b = gait_cycle(joints)
    out = [joints[:b]]
    total = b
    yaw = facing_angle(joints)
    prev_end = joints[b]          # where the next repetition's first frame should be
    prev_yaw = yaw[b]
    while total < frames:
        rot = yaw_matrix(prev_yaw - yaw[a])
        piece = (joints[a:b] - joints[a, sk.PELVIS] * [1.0, 0.0, 1.0]) @ rot.T
        piece += prev_end[sk.PELVIS] * [1.0, 0.0, 1.0]
        # Fade the pose residual at the seam (frame b's pose vs the cycle's frame a) out.
        resid = prev_end - piece[0]
        k = np.clip(1.0 - np.arange(len(piece)) / fade, 0.0, 1.0)[:, None, None]
        piece = piece + k * resid
        # Where this repetition's successor starts: frame b of the clip, moved the same way.
        nxt = (joints[b] - joints[a, sk.PELVIS] * [1.0, 0.0, 1.0]) @ rot.T + prev_end[sk.PELVIS] * [1.0, 0.0, 1.0]
        prev_end, prev_yaw = nxt, prev_yaw + (yaw[b] - yaw[a])
        out.append(piece)
        total += len(piece)
    return np.concatenate(out)[:frames]


def face_forward(joints: np.ndarray, heading: np.ndarray | None = None) -> np.ndarray:
    """Joints turned about the vertical so `heading` (a ground direction; default the mean
    facing direction) points to +Z, and moved so the mean pelvis XZ is at the origin."""
    if heading is None:
        yaw = facing_angle(joints)
        heading = np.array([np.sin(yaw).mean(), 0.0, np.cos(yaw).mean()])
    rot = yaw_matrix(-np.arctan2(heading[0], heading[2]))
    out = joints @ rot.T
    centre = out[:, sk.PELVIS].mean(axis=0)
    return out - centre * [1.0, 0.0, 1.0]


def refit(joints: np.ndarray, offsets: np.ndarray) -> np.ndarray:
    """Re-posed on the person's fixed bones (interpolated or faded frames shrink bones a bit)."""
    return fit_to_skeleton(joints, offsets)[0]
