"""The trajectory editor (CoMA §3, appendix D.1–D.2): make a motion's root follow a ground curve.

Steps, all plain numpy over plain data:
1. `smooth_curve`: fit a smoothing cubic B-spline (bspline.py) to the curve's points and
   resample it evenly by arc length (CoMA: "resampled using B-spline interpolation, which
   adjusts point spacing and eliminates irregularities"). Knots every `knot_spacing` metres
   set the tightest turn kept, so square corners and zigzag tips become short turns a walker
   can make, and hand-drawn jitter goes.
2. Split the motion's pelvis path (XZ) into its travel (a spline with knots every
   `travel_knot_s` seconds, longer than a step, so the side-to-side sway of walking is left
   out) and the sway (the rest). The travel path gives the speed profile (metres per frame)
   and the travel direction.
3. Each frame is moved rigidly in XZ: the point the motion has travelled to, s(t) metres
   along its own path, goes to the point s(t) metres along the curve, and the frame turns by
   the angle between the curve's tangent there (smoothed over `turn_smooth_s`, so a corner is
   a step turn, not a snap) and the motion's own travel direction (CoMA D.2 replaces the
   root's rotational velocity so the facing direction rotates with the path). The offset
   between facing and travel direction is kept, so side steps and backwards walks keep
   theirs; limbs keep their local motion; the sway is turned with the frame. With a
   direction of travel (backward, left, right: travel.py) the facing is held at the tangent
   rotated by it instead: nobody is turned round to walk a path backwards.
4. The turning makes planted feet slide round the pelvis; footlock.py pins them with a short
   IK on the legs and, where a leg cannot reach, a small shift of the whole body (see there),
   so feet skate no more than in the original.

Placement (anchor_pose): in the person's start frame (origin at the pelvis, +Z where they
face, +X their left: the planner's convention), along their starting travel direction, or in
world coordinates (a path drawn on the studio floor). Length: by default the curve is scaled
to the distance the motion walks (it traces the whole shape at its own speed);
`scale_to_motion=False` keeps the curve's size and the speed (the motion stops where its walk
runs out, or carries on along the last tangent), and with `retime=True` (drawn paths) the
speed is scaled to cover the whole curve. Motions that barely travel (less than `min_travel`
metres) are left in place (moved to the curve's start only when anchored to the world):
spreading a curve over a standing person slides them over the floor; a trajectory needs a
motion that walks, which is the generator's job (docs/trajectory.md).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.footlock import pin_feet
from interplay.motion.kinematics import facing_angle, facing_direction, fit_to_skeleton
from interplay.motion.metrics import person_metrics
from interplay.planner.schema import TrajectorySpec
from interplay.trajectory import bspline
from interplay.trajectory.curves import drop_repeats, length, make_curve
from interplay.trajectory.travel import check, facing_fix, spec_travel


@dataclass(frozen=True)
class TrajectoryConfig:
    knot_spacing: float = 0.3      # m between curve spline knots (tightest turn kept, noise removed)
    penalty: float = 1e-2          # curve spline's second-difference penalty (bspline.fit)
    spacing: float = 0.01          # m between resampled curve points
    travel_knot_s: float = 0.6     # s between knots of the pelvis travel spline (> one step)
    min_speed: float = 0.15        # m/s: slower frames take their travel direction from neighbours
    turn_smooth_s: float = 0.15    # s: Gaussian smoothing of the heading in time (corners: a step turn)
    min_travel: float = 0.5        # m: motions travelling less are left in place
    scale_to_motion: bool = True   # fit the curve's length to the distance walked
    retime: bool = False           # keep the curve's size; scale the walking speed to cover it
    anchor: str = "facing"         # where the curve's frame sits: "facing", "travel" or "world"
    facing_window_s: float = 0.5   # s at the start over which the facing direction is averaged
    pin_feet: bool = True


DEFAULT = TrajectoryConfig()
# Most resampled points and spline segments a curve gets: 200 m (MAX_PATH_M, the longest path
# a request may ask for) at the default spacings; longer curves are sampled more coarsely.
MAX_SAMPLES = 20_000
MAX_KNOTS = 700


@dataclass(frozen=True)
class Curve:
    """A smoothed curve resampled by arc length: s (N,) metres from the start, points (N, 2)
    (x, z), heading (N,) radians of the tangent (0 along +Z, + towards +X), unwrapped."""
    s: np.ndarray
    points: np.ndarray
    heading: np.ndarray

    @property
    def length(self) -> float:
        return float(self.s[-1])

    def at(self, s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Points (T, 2) and headings (T,) at arc lengths s (T,); beyond the end the curve
        carries on straight along its last tangent."""
        s = np.asarray(s, dtype=np.float64)
        pts = np.stack([np.interp(s, self.s, self.points[:, i]) for i in range(2)], axis=1)
        head = np.interp(s, self.s, self.heading)
        over = np.maximum(s - self.s[-1], 0.0)
        last = self.heading[-1]
        pts += over[:, None] * np.array([np.sin(last), np.cos(last)])
        return pts, head


def _rotate(xz: np.ndarray, angle: np.ndarray | float) -> np.ndarray:
    """Turn ground vectors (..., 2) by heading angles (broadcast over ...): +Z towards +X."""
    c, s = np.cos(angle), np.sin(angle)
    x, z = xz[..., 0], xz[..., 1]
    return np.stack([c * x + s * z, -s * x + c * z], axis=-1)


def _gaussian(x: np.ndarray, sigma: float) -> np.ndarray:
    """x (T,) smoothed by a Gaussian of `sigma` frames (ends padded with their values)."""
    if sigma <= 0 or len(x) < 2:
        return x.copy()
    half = int(np.ceil(3 * sigma))
    k = np.exp(-0.5 * (np.arange(-half, half + 1) / sigma) ** 2)
    return np.convolve(np.pad(x, half, mode="edge"), k / k.sum(), mode="valid")


def smooth_curve(points, cfg: TrajectoryConfig = DEFAULT) -> Curve:
    """Fit a smoothing cubic B-spline to ground points (N, 2) and resample it every
    `cfg.spacing` metres of arc length (knots every `cfg.knot_spacing`; on curves longer than
    MAX_SAMPLES × spacing or MAX_KNOTS × knot_spacing both grow so that neither count does:
    the work is linear in the points given and bounded whatever the length). The spline is fitted twice: first over the points'
    chord lengths, then over the first fit's arc lengths, so unevenly spaced points do not
    bunch the knots. The first and last points are held (weighted) so the curve starts and ends
    where it was asked to."""
    pts = np.asarray(points, dtype=np.float64)
    if pts.ndim != 2 or pts.shape[1] != 2 or not np.all(np.isfinite(pts)):
        raise ValueError(f"a curve must be finite points of shape (N, 2), got {pts.shape}")
    pts = drop_repeats(pts)
    total = length(pts)
    if len(pts) < 2 or total < 1e-3:
        raise ValueError("a curve needs at least two distinct points")
    # Knots every knot_spacing and samples every spacing metres, both coarser past the path
    # lengths requests may ask for (MAX_PATH_M), so the cost stays bounded whatever the curve.
    segments = max(4, int(np.ceil(total / max(cfg.knot_spacing, total / MAX_KNOTS))))
    spacing = max(cfg.spacing, total / MAX_SAMPLES)
    weights = np.ones(len(pts))
    weights[[0, -1]] = 1e3
    u = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(pts, axis=0), axis=1))]) / total
    dense_u = np.linspace(0.0, 1.0, max(2000, int(2 * total / spacing)))
    for fit_round in range(2):
        coef = bspline.fit(u, pts, segments, cfg.penalty, weights)
        dense = bspline.evaluate(coef, dense_u)
        arc = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(dense, axis=0), axis=1))])
        if fit_round == 0:
            u = np.interp(u, dense_u, arc / arc[-1])  # re-parametrise the points by arc length
    n = max(int(np.ceil(arc[-1] / spacing)), 2) + 1
    s = np.linspace(0.0, arc[-1], n)
    at_u = np.interp(s, arc, dense_u)
    tangent = bspline.evaluate(coef, at_u, derivative=1)
    heading = np.unwrap(np.arctan2(tangent[:, 0], tangent[:, 1]))
    out = bspline.evaluate(coef, at_u)
    # The weighted ends land within a fraction of a millimetre; a ramp makes them exact.
    ramp = (s / s[-1])[:, None]
    out += (pts[0] - out[0]) * (1 - ramp) + (pts[-1] - out[-1]) * ramp
    return Curve(s=s, points=out, heading=heading)


def resample_curve(points, cfg: TrajectoryConfig = DEFAULT) -> np.ndarray:
    """Smoothed points (M, 2) evenly spaced by `cfg.spacing` metres along the curve."""
    return smooth_curve(points, cfg).points


@dataclass(frozen=True)
class Travel:
    """A motion's travel: path (T, 2) pelvis XZ without the sway, s (T,) metres travelled,
    heading (T,) radians of the travel direction (unwrapped), moving (bool: travels at all)."""
    path: np.ndarray
    s: np.ndarray
    heading: np.ndarray
    moving: bool


def travel(joints: np.ndarray, fps: float = sk.FPS, cfg: TrajectoryConfig = DEFAULT) -> Travel:
    """Split the pelvis path of joints (T, 22, 3) into travel and sway (see the module doc)."""
    pelvis = joints[:, sk.PELVIS][:, [0, 2]].astype(np.float64)
    t = len(pelvis)
    if t < 4:
        return Travel(pelvis, np.zeros(t), np.zeros(t), False)
    segments = max(1, int(round((t - 1) / fps / cfg.travel_knot_s)))
    path = bspline.smooth(pelvis, segments, 1e-3)
    # Start and end exactly where the pelvis does (a straight ramp of the end residuals).
    ramp = np.linspace(0.0, 1.0, t)[:, None]
    path += (pelvis[0] - path[0]) * (1 - ramp) + (pelvis[-1] - path[-1]) * ramp
    step = np.linalg.norm(np.diff(path, axis=0), axis=1)
    s = np.concatenate([[0.0], np.cumsum(step)])
    velocity = np.gradient(path, axis=0) * fps
    speed = np.linalg.norm(velocity, axis=1)
    fast = speed >= cfg.min_speed
    if s[-1] < cfg.min_travel or fast.sum() < 2:
        return Travel(path, s, np.full(t, facing_angle(joints[:1])[0]), False)
    known = np.unwrap(np.arctan2(velocity[fast, 0], velocity[fast, 1]))
    heading = np.interp(np.arange(t), np.flatnonzero(fast), known)
    return Travel(path, s, heading, True)


_split = travel          # map_trajectory's `travel` argument is the direction of travel
ANCHORS = ("facing", "travel", "world")


def anchor_pose(joints: np.ndarray, tr: Travel, fps: float = sk.FPS,
                cfg: TrajectoryConfig = DEFAULT) -> tuple[np.ndarray, float]:
    """Where a curve's origin (2,) and its +Z heading (radians) go in the world. "facing": the
    start of the travel path and the person's facing direction over the first
    `facing_window_s` (the planner's convention: curves are drawn in the person's start frame,
    +Z where they face, so "walks backwards" is a line towards -Z). "travel": the starting
    travel direction instead, so frame 0 is never turned. "world": the curve as given."""
    if cfg.anchor not in ANCHORS:
        raise ValueError(f"anchor must be one of {list(ANCHORS)}, got {cfg.anchor!r}")
    if cfg.anchor == "world":
        return np.zeros(2), 0.0
    if cfg.anchor == "travel":
        return tr.path[0], float(tr.heading[0])
    n = max(1, int(round(cfg.facing_window_s * fps)))
    fwd = facing_direction(joints[:n]).sum(axis=0)
    return tr.path[0], float(np.arctan2(fwd[0], fwd[2]))


def _world_curve(curve_points, joints: np.ndarray, tr: Travel, fps: float,
                 cfg: TrajectoryConfig) -> np.ndarray:
    """The curve's points (N, 2) placed in the world (see anchor_pose)."""
    try:
        pts = np.asarray(curve_points, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError("a curve must be ground points [[x, z], …]") from None
    if pts.ndim != 2 or pts.shape[1] != 2 or len(pts) < 2 or not np.all(np.isfinite(pts)):
        raise ValueError(f"a curve must be at least two finite [x, z] points, got shape {pts.shape}")
    origin, angle = anchor_pose(joints, tr, fps, cfg)
    if cfg.anchor == "world":
        return pts
    return _rotate(pts - pts[0], angle) + origin


def map_trajectory(joints: np.ndarray, curve_points, offsets: np.ndarray | None = None,
                   fps: float = sk.FPS, cfg: TrajectoryConfig = DEFAULT,
                   travel: str | None = None) -> dict:
    """Map one person's motion (T, 22, 3) onto a ground curve (N, 2). Returns
    {"joints": (T, 22, 3), "curve": the smoothed world curve (M, 2) as used, "scale": factor
    applied to the curve, "moving": whether the motion travels, "turn": (T,) radians each frame
    was turned, "facing_fix": the constant turn (radians) a direction of travel added}. With
    offsets (22, 3) the result is refitted on those bone lengths. `travel` (forward / backward
    / left / right) holds the facing at the path's tangent rotated by that direction of travel
    (travel.py): a person walking backwards along any path is never turned round."""
    check(travel)
    joints = np.asarray(joints, dtype=np.float64)
    if joints.ndim != 3 or joints.shape[1:] != (sk.NUM_JOINTS, 3) or len(joints) < 1:
        raise ValueError(f"expected joints of shape (T, 22, 3), got {joints.shape}")
    if not np.all(np.isfinite(joints)):
        raise ValueError("joints contain NaN or infinite values")
    tr = _split(joints, fps, cfg)
    world = _world_curve(curve_points, joints, tr, fps, cfg)
    scale = 1.0
    if tr.moving and cfg.scale_to_motion:
        scale = tr.s[-1] / max(length(world), 1e-9)
        world = world[0] + (world - world[0]) * scale
    curve = smooth_curve(world, cfg)
    if tr.moving and cfg.scale_to_motion:
        # Smoothing cuts corners: stretch the smoothed curve back to the distance walked.
        k = tr.s[-1] / curve.length
        curve = Curve(curve.s * k, curve.points[0] + (curve.points - curve.points[0]) * k, curve.heading)
        scale *= k
    speed = 1.0
    progress = tr.s
    if tr.moving and cfg.retime and not cfg.scale_to_motion:
        # A drawn path is where the person must go: keep its size and the motion's own speed
        # profile, scaled so the walk covers the whole curve in the motion's duration (planted
        # feet are pinned below, so a faster walk strides, not skates).
        speed = curve.length / max(tr.s[-1], 1e-9)
        progress = tr.s * speed
    fix = 0.0
    if tr.moving:
        target, head = curve.at(progress)
        moving = np.linalg.norm(np.gradient(tr.path, axis=0), axis=1) * fps >= cfg.min_speed
        fix = facing_fix(joints, tr.heading, moving, travel)
        turn = _gaussian(head, cfg.turn_smooth_s * fps) - tr.heading + fix
        centre = tr.path
    else:
        # One rigid move of the whole clip (none unless the curve is anchored to the world).
        turn = np.full(len(joints), curve.heading[0] - tr.heading[0] if cfg.anchor == "world" else 0.0)
        target, _ = curve.at(np.zeros(len(joints)))
        centre = np.broadcast_to(tr.path[0], tr.path.shape)
    out = joints.copy()
    rel = joints[..., [0, 2]] - centre[:, None, :]
    out[..., [0, 2]] = target[:, None, :] + _rotate(rel, turn[:, None])
    if cfg.pin_feet and tr.moving:
        out = pin_feet(joints, out, turn, fps=fps)
    if offsets is not None:
        out, _ = fit_to_skeleton(out, np.asarray(offsets, dtype=np.float64))
    return {"joints": out, "curve": curve.points, "scale": float(scale), "speed": float(speed),
            "moving": tr.moving, "turn": turn, "facing_fix": fix}


def apply_trajectory(joints: np.ndarray, curve, offsets: np.ndarray | None = None,
                     fps: float = sk.FPS, cfg: TrajectoryConfig = DEFAULT,
                     travel: str | None = None) -> np.ndarray:
    """Joints (T, 22, 3) of the motion walking along `curve`: ground points (N, 2) or a
    TrajectorySpec-like dict (see curves.make_curve). See the module doc for what is kept.
    `travel` is the direction of travel relative to facing (map_trajectory); for a spec
    without one it is the spec's own (travel.spec_travel: "walks backwards" → backward)."""
    spec = isinstance(curve, (dict, TrajectorySpec))
    if travel is None and spec:
        travel = spec_travel(curve)
    points = make_curve(curve) if spec else curve
    return map_trajectory(joints, points, offsets, fps, cfg, travel)["joints"]


def skating(joints: np.ndarray, fps: float = sk.FPS) -> float:
    """Mean horizontal speed (m/s) of planted foot joints (metrics.foot_skating)."""
    return person_metrics(np.asarray(joints, dtype=np.float64), int(fps))["foot_skating"]


