"""Analytic two-bone inverse kinematics for the limbs of the 22-joint skeleton, and eased
weights that blend IK in and out over a time window. numpy only.

A limb is a chain root → mid → end (shoulder → elbow → wrist, hip → knee → ankle). Given a
target for the end joint, the solver keeps the root where it is, puts the end on the line
root → target at the target's distance (clamped to what the two bones can span, so an
unreachable target is approached along that line with the limb straight), and places the mid
joint by the law of cosines in the plane that holds the root, the target and a pole (bend)
hint. Both bone lengths are kept exactly (to float64 rounding); joints below the end (the
foot under the ankle) move rigidly with it.

Blending: with weight w in [0, 1] per frame the solved target is lerp(end, target, w) and the
bend side is the normalised blend of the current bend side and the pole's, so w = 0 gives back
the input pose exactly and an eased w reaches and releases contact without jumps.

Shapes: joints (T, 22, 3) or (22, 3) metres; target and pole (T, 3) or (3,); weight (T,) or
a scalar.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.rotations import rotation_between

_EPS = 1e-9


@dataclass(frozen=True)
class Limb:
    name: str
    root: int   # shoulder / hip
    mid: int    # elbow / knee
    end: int    # wrist / ankle


LIMBS: dict[str, Limb] = {
    f"{side}_{kind}": Limb(f"{side}_{kind}", *(sk.JOINT_INDEX[f"{side}_{j}"] for j in joints))
    for side in ("left", "right")
    for kind, joints in (("arm", ("shoulder", "elbow", "wrist")), ("leg", ("hip", "knee", "ankle")))
}


def limb(name: str | Limb) -> Limb:
    """A limb by name ("left_arm", "right_leg", …)."""
    if isinstance(name, Limb):
        return name
    if name not in LIMBS:
        raise ValueError(f"unknown limb {name!r}; expected one of {sorted(LIMBS)}")
    return LIMBS[name]


def descendants(joint: int) -> list[int]:
    """Every joint below `joint` in the tree (parents-first order)."""
    out, frontier = [], {joint}
    for j, p in enumerate(sk.PARENTS):
        if p in frontier:
            out.append(j)
            frontier.add(j)
    return out


def ease(x: np.ndarray) -> np.ndarray:
    """Smootherstep 6x⁵ - 15x⁴ + 10x³ of x clipped to [0, 1]: zero velocity and acceleration
    at both ends, so a contact starts and ends without a jerk."""
    x = np.clip(np.asarray(x, dtype=np.float64), 0.0, 1.0)
    return x * x * x * (x * (6.0 * x - 15.0) + 10.0)


def window_weights(frames: int, start: int, end: int, ramp_in: int, ramp_out: int | None = None) -> np.ndarray:
    """IK weights (frames,): 1 on the contact window [start, end), easing up from 0 over the
    `ramp_in` frames before `start` and back down to 0 over the `ramp_out` frames after it."""
    ramp_out = ramp_in if ramp_out is None else ramp_out
    if not 0 <= start <= end <= frames or ramp_in < 0 or ramp_out < 0:
        raise ValueError(f"bad window [{start}, {end}) with ramps {ramp_in}/{ramp_out} "
                         f"for {frames} frames")
    t = np.arange(frames, dtype=np.float64)
    up = ease((t - (start - ramp_in)) / ramp_in) if ramp_in else (t >= start).astype(float)
    down = ease(((end - 1 + ramp_out) - t) / ramp_out) if ramp_out else (t < end).astype(float)
    return np.minimum(up, down)


def _unit(v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return v / np.maximum(n, _EPS), n[..., 0]


def _perp(v: np.ndarray, axis: np.ndarray) -> np.ndarray:
    """Component of v (..., 3) perpendicular to the unit axis (..., 3)."""
    return v - np.sum(v * axis, axis=-1, keepdims=True) * axis


def _any_perp(axis: np.ndarray) -> np.ndarray:
    """Some unit vector perpendicular to each unit axis (fallback bend side)."""
    guess = np.where(np.abs(axis[..., 1:2]) < 0.9, [0.0, 1.0, 0.0], [1.0, 0.0, 0.0])
    return _unit(_perp(-guess, axis))[0]


def two_bone_ik(joints: np.ndarray, which: str | Limb, target: np.ndarray,
                pole: np.ndarray | None = None, weight: np.ndarray | float = 1.0,
                carry: str = "rotate") -> np.ndarray:
    """Joints with one limb re-posed so its end joint reaches `target` (blended by `weight`).

    pole: points the mid joint should bend towards (e.g. an elbow hint behind and below the
    shoulder); None keeps each frame's current bend plane. carry: how joints below the end
    follow it: "rotate" turns them with the lower bone (as forward kinematics would), "keep"
    only translates them (a planted foot keeps its orientation on the floor).
    Returns a new float64 array of the input's shape; the input is not modified."""
    lb = limb(which)
    if carry not in ("rotate", "keep"):
        raise ValueError(f"carry must be 'rotate' or 'keep', got {carry!r}")
    j = np.asarray(joints, dtype=np.float64)
    single = j.ndim == 2
    if single:
        j = j[None]
    if j.ndim != 3 or j.shape[1:] != (sk.NUM_JOINTS, 3):
        raise ValueError(f"expected joints of shape (T, 22, 3) or (22, 3), got {np.shape(joints)}")
    t = j.shape[0]
    target = np.broadcast_to(np.asarray(target, dtype=np.float64), (t, 3))
    w = np.broadcast_to(np.asarray(weight, dtype=np.float64), (t,))
    if np.any(w < 0) or np.any(w > 1) or not np.all(np.isfinite(w)):
        raise ValueError("IK weights must lie in [0, 1]")
    if not np.all(np.isfinite(target)):
        raise ValueError("IK targets contain NaN or infinite values")

    a, b, c = j[:, lb.root], j[:, lb.mid], j[:, lb.end]
    l1 = np.linalg.norm(b - a, axis=-1)
    l2 = np.linalg.norm(c - b, axis=-1)
    goal = c + w[:, None] * (target - c)
    u, dist = _unit(goal - a)
    degenerate = dist < _EPS
    u = np.where(degenerate[:, None], _unit(c - a)[0], u)
    d = np.clip(dist, np.abs(l1 - l2) + 1e-9, l1 + l2)

    # Bend side: the current plane (mid joint off the root→goal line), blended with the pole's.
    side, n_side = _unit(_perp(b - a, u))
    side = np.where((n_side < 1e-6)[:, None], _any_perp(u), side)
    if pole is not None:
        pole = np.broadcast_to(np.asarray(pole, dtype=np.float64), (t, 3))
        want, n_want = _unit(_perp(pole - a, u))
        want = np.where((n_want < 1e-6)[:, None], side, want)
        mixed, n_mixed = _unit((1.0 - w)[:, None] * side + w[:, None] * want)
        side = np.where((n_mixed < 1e-6)[:, None], want, mixed)

    cos_a = np.clip((l1 ** 2 + d ** 2 - l2 ** 2) / (2.0 * l1 * d), -1.0, 1.0)
    sin_a = np.sqrt(1.0 - cos_a ** 2)
    new_b = a + l1[:, None] * (cos_a[:, None] * u + sin_a[:, None] * side)
    new_c = a + d[:, None] * u

    out = j.copy()
    out[:, lb.mid], out[:, lb.end] = new_b, new_c
    below = descendants(lb.end)
    if below:
        rel = j[:, below] - c[:, None]                                   # (T, K, 3)
        if carry == "rotate":
            rot = rotation_between(c - b, new_c - new_b)                 # (T, 3, 3)
            rel = np.einsum("tij,tkj->tki", rot, rel)
        out[:, below] = new_c[:, None] + rel
    return out[0] if single else out


def reach(joints: np.ndarray, which: str | Limb) -> np.ndarray:
    """Longest distance (...) from the limb's root its end can reach (sum of its two bones)."""
    lb = limb(which)
    j = np.asarray(joints, dtype=np.float64)
    return (np.linalg.norm(j[..., lb.mid, :] - j[..., lb.root, :], axis=-1)
            + np.linalg.norm(j[..., lb.end, :] - j[..., lb.mid, :], axis=-1))
