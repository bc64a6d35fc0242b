"""One person's motion in a scene, from real clips on the shared skeleton: quiet standing, and
walking that starts from standing and stops into standing. numpy only.

A walk (a real level walk, looped on its gait cycle, `pair.bases.loop_walk`) is played with a
time warp τ(t): still before it starts, its playback rate easing up from 0 to 1, walking, then
easing down to 0 so that it comes to rest exactly on a mid-stance frame (one foot planted, the
other passing it: the feet are side by side, so standing up from there needs no slide). Before
the start and after the stop the pose blends (smootherstep over `settle` frames) between that
frozen walk frame and a real standing clip, with the body placed so that the planted foot stays
where it is: the other foot is set down beside it as the body straightens up.

Shapes: joints (T, 22, 3) float64 metres, Y up, 20 fps; a walk faces +Z and starts at the origin.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from interplay.generators.interaction.bodies import lerp_frames, level, on_shared, refit, yaw_of
from interplay.motion import skeleton as sk
from interplay.motion.ik import ease, two_bone_ik
from interplay.motion.kinematics import facing_angle
from interplay.motion.pair import placement as pl
from interplay.motion.pair.bases import Base, base_joints, face_forward, loop_walk
from interplay.motion.rotations import yaw_matrix

ANKLES = (sk.LEFT_ANKLE, sk.RIGHT_ANKLE)
XZ = np.array([1.0, 0.0, 1.0])


@dataclass
class Clip1:
    """A real clip re-posed on the shared skeleton, with where it came from."""
    joints: np.ndarray
    source: dict = field(default_factory=dict)   # clip, start, end, mirrored, licence


def standing(rng, pool: pl.Pool, frames: int) -> Clip1:
    """Quiet standing (a real standing run played back and forth), facing +Z, pelvis centred."""
    p = pl.standing(rng, pool, frames)
    return Clip1(face_forward(on_shared(p.joints, p.offsets)), p.base)


def walk(rng, base: Base, frames: int, flip: bool | None = None, along: str = "travel") -> Clip1:
    """A real walk looped to `frames`, its travel (or, along="facing", its mean facing: a
    walk backwards) turned to +Z, the pelvis starting at the origin."""
    flip = bool(rng.random() < 0.5) if flip is None else flip
    j, off = base_joints(base, flip)
    j = straighten(on_shared(loop_walk(j, frames), off), along)
    j = level(j)
    j = j - j[0, sk.PELVIS] * XZ
    return Clip1(j, {"clip": base.clip.id, "start": base.start, "end": base.end,
                     "mirrored": flip, "licence": base.clip.licence})


def straighten(j: np.ndarray, along: str = "travel", window: int = 41) -> np.ndarray:
    """A walk whose path bends (a looped gait cycle drifts a few degrees a cycle) made
    straight along +Z: each frame's pose turned about its pelvis by the bend of the path
    there (its travel direction, or along="facing" its facing, averaged over `window`
    frames), and the pelvis path rebuilt from the turned steps."""
    if along == "travel":
        v = np.gradient(j[:, sk.PELVIS][:, [0, 2]], axis=0)
        yaw = np.unwrap(np.arctan2(v[:, 0], v[:, 1]))
    else:
        yaw = np.unwrap(facing_angle(j))
    k = np.ones(window) / window
    pad = np.pad(yaw, window // 2, mode="edge")
    yaw = np.convolve(pad, k, mode="valid")[:len(j)]
    rot = yaw_matrix(-yaw)                                             # (T, 3, 3)
    loc = np.einsum("tij,tkj->tki", rot, j - j[:, [sk.PELVIS]] * XZ)
    step = np.diff(j[:, sk.PELVIS] * XZ, axis=0)
    step = np.einsum("tij,tj->ti", rot[1:], step)
    path = np.concatenate([np.zeros((1, 3)), np.cumsum(step, axis=0)])
    return loc + path[:, None]


def speed(joints: np.ndarray) -> float:
    """Mean ground speed (m/s) of the pelvis over a clip."""
    d = (joints[-1, sk.PELVIS] - joints[0, sk.PELVIS])[[0, 2]]
    return float(np.linalg.norm(d) / max(len(joints) - 1, 1) * sk.FPS)


def mid_stances(joints: np.ndarray) -> list[tuple[int, int]]:
    """(frame, planted ankle) where one foot passes the other (their order along the facing
    direction changes), the planted one being the slower of the two there."""
    fwd = pl.axes(joints)[0]
    order = ((joints[:, sk.LEFT_ANKLE] - joints[:, sk.RIGHT_ANKLE]) * fwd).sum(axis=1)
    vel = np.linalg.norm(np.gradient(joints[:, ANKLES][..., [0, 2]], axis=0), axis=-1)
    out = []
    for f in np.flatnonzero(np.sign(order[1:]) != np.sign(order[:-1])):
        f = int(f) + (abs(order[f + 1]) < abs(order[f]))
        out.append((f, ANKLES[int(np.argmin(vel[f]))]))
    return out


def _local(j: np.ndarray) -> np.ndarray:
    return j - j[:, [sk.PELVIS]] * XZ


def _settle(stand: np.ndarray, pose: np.ndarray, ankle: int, toward_pose: np.ndarray,
            facing: float) -> np.ndarray:
    """Frames blending standing frames (n, 22, 3) and one walk pose (22, 3): weight
    `toward_pose` (n,) on the walk pose, the body placed so the walk pose's planted `ankle`
    stays put; the standing frames are turned to `facing` (yaw: the walk's own, over a gait
    cycle about that pose) first."""
    yaw = facing - yaw_of(stand)
    loc_s = _local(stand) @ yaw_matrix(yaw).T
    w = toward_pose[:, None, None]
    loc = (1.0 - w) * loc_s + w * _local(pose[None])
    anchor = pose[ankle] * XZ
    return loc + (anchor - loc[:, ankle] * XZ)[:, None]


def _cycle_yaw(w: np.ndarray, f: int, half: int = 12) -> float:
    """The walk's mean facing over about a gait cycle around frame f."""
    return yaw_of(w[max(0, f - half):f + half + 1])


@dataclass
class Gait:
    """When a person walks in a scene: `go` the frame the walk starts from standing (None:
    walking from frame 0); stop after about `metres` of travel (None: as late as fits), by
    `stop_by` at the latest (both None: walking to the end); rate `scale` (1 = the capture's
    own speed); ramps and settles in frames."""
    go: int | None = None
    metres: float | None = None
    stop_by: int | None = None
    scale: float = 1.0
    ramp_in: int = 10
    ramp_out: int = 14
    settle: int = 10
    settle_in: int = 10


def locomote(w: np.ndarray, stand: np.ndarray, frames: int, g: Gait) -> tuple[np.ndarray, dict]:
    """`frames` frames of a person who stands, walks along the looped walk `w` and stands
    again, per the gait (see the module doc); `stand` (≥ frames, 22, 3) is the standing clip
    used before the start and after the stop. Returns (joints in the walk's frame, report:
    go, stop, travelled metres, planted ankle names)."""
    mids = mid_stances(w)
    t0 = 0 if g.go is None else int(g.go)
    if g.go is None:
        tau0, ankle0 = 0, None
    else:
        tau0, ankle0 = next(((f, a) for f, a in mids if f >= 2), mids[0])
    lead_in = 0 if g.go is None else g.ramp_in / 2
    stop = ankle1 = None
    tau1 = None
    if g.metres is not None or g.stop_by is not None:
        last = frames - 1 if g.stop_by is None else g.stop_by
        best = None
        for f, a in mids:
            if f <= tau0 + 8:
                continue
            t_stop = t0 + (f - tau0) / g.scale + lead_in + g.ramp_out / 2
            if t_stop > last:
                break
            travel = float(np.linalg.norm((w[f, sk.PELVIS] - w[tau0, sk.PELVIS])[[0, 2]]))
            err = -travel if g.metres is None else abs(travel - g.metres)
            if best is None or err < best[0]:
                best = (err, f, a, int(round(t_stop)))
        if best is None:
            raise ValueError(f"no stop of the walk fits in {frames} frames")
        _, tau1, ankle1, stop = best
    t = np.arange(frames, dtype=np.float64)
    rate = np.full(frames, float(g.scale))
    if g.go is not None:
        rate *= ease((t - t0) / max(g.ramp_in, 1)) * (t >= t0)
    if stop is not None:
        rate *= ease((stop - t) / max(g.ramp_out, 1)) * (t < stop)
    tau = tau0 + np.concatenate([[0.0], np.cumsum(rate[:-1])])
    if stop is not None and tau1 is not None:
        moved = tau[stop] - tau0
        tau = tau0 + (tau - tau0) * ((tau1 - tau0) / max(moved, 1e-9))
        tau[stop:] = tau1
    out = lerp_frames(w, tau)
    report: dict = {"go": g.go, "stop": stop, "walk_frames": [int(tau0), int(round(tau[-1]))]}
    if g.go is not None and ankle0 is not None and t0 > 0:
        k = np.arange(t0)
        out[:t0] = _settle(stand[:t0], w[tau0], ankle0, ease((k - (t0 - g.settle_in)) / g.settle_in),
                           _cycle_yaw(w, tau0))
    if stop is not None and ankle1 is not None and tau1 is not None:
        k = np.arange(stop, frames)
        out[stop:] = _settle(stand[stop:frames], w[tau1], ankle1, 1.0 - ease((k - stop) / g.settle),
                             _cycle_yaw(w, tau1))
        report["planted"] = sk.JOINT_NAMES[ankle1]
    report["travelled_m"] = round(float(np.linalg.norm((out[-1, sk.PELVIS] - out[0, sk.PELVIS])[[0, 2]])), 3)
    return refit(out), report


def step(j: np.ndarray, profile: np.ndarray, shift: np.ndarray, foot: str,
         lift: float = 0.07) -> np.ndarray:
    """A step: the body moves by `shift` (a ground vector, metres) × `profile` (T,) in [0, 1];
    the `foot` leg steps twice as far (lifted by up to `lift` m while it moves), so the
    pelvis ends between the feet, and the other foot stays planted. Both legs follow by
    two-bone IK (the pelvis lowered where a leg would not reach), bones kept."""
    d = profile[:, None] * np.asarray(shift, dtype=np.float64)[None]           # (T, 3)
    before = j
    out = j + d[:, None]
    moving = np.abs(np.gradient(profile)) * max(len(profile), 1)
    up = lift * np.clip(moving / max(float(moving.max()), 1e-9), 0.0, 1.0)
    other = "left" if foot == "right" else "right"
    goals = {foot: before[:, sk.JOINT_INDEX[f"{foot}_ankle"]] + 2.0 * d + up[:, None] * np.array([0.0, 1.0, 0.0]),
             other: before[:, sk.JOINT_INDEX[f"{other}_ankle"]]}
    drop = np.zeros(len(j))
    for side, goal in goals.items():
        hip = out[:, sk.JOINT_INDEX[f"{side}_hip"]]
        reach = 0.995 * (np.linalg.norm(before[:, sk.JOINT_INDEX[f"{side}_knee"]] - before[:, sk.JOINT_INDEX[f"{side}_hip"]], axis=1)
                         + np.linalg.norm(before[:, sk.JOINT_INDEX[f"{side}_ankle"]] - before[:, sk.JOINT_INDEX[f"{side}_knee"]], axis=1))
        rel = hip - goal
        room = np.square(reach) - np.square(rel[:, [0, 2]]).sum(axis=1)
        drop = np.maximum(drop, rel[:, 1] - np.sqrt(np.maximum(room, 0.0)))
    out[..., 1] -= drop[:, None]
    fwd = pl.axes(before)[0]
    for side, goal in goals.items():
        knee = out[:, sk.JOINT_INDEX[f"{side}_knee"]] + 0.3 * fwd
        out = two_bone_ik(out, f"{side}_leg", goal, pole=knee, carry="keep")
    return out
