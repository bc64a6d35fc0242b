"""The leaves of `solve_rig`: the head, the wrists and the toes. Leaves carry no bone, so
nothing in 22 joints says how they turn; they get the rotations the moves imply (`LEAVES`):
the head turns on the neck by HEAD_SHARE of the neck's own turn (a nod, which tilts the
neck→head bone, pitches the face further; smooth wherever the neck is); each hand trails its
forearm's swing with a lag of HAND_LAG seconds, bent at most HAND_BEND (a wave turns the hand
to and fro); explicit per-frame rotations (`leaves=`, e.g. from an edit or a capture's own;
rows of NaN: derive that frame) replace either. Then
no leaf's tip goes under the floor: a toe whose tip (the end site) would dip bends up about
its own side-to-side axis just enough (a flat foot's toes lie on the floor), and so does a
hand whose mesh tip (HAND_REACH along it, HAND_THICK thick) would, towards its back; both
bends start before the leaf reaches the floor and change at most LIFT_RATE (`_floor_bend`).

Each leaf's channel so turns at most max(30°, its parent bone's turn) a frame on every clip
of the library (`rig/steps.py`, `interplay export-leaves`; issue 27: before the bends were
hinges spread over frames, 43 wrist and 265 toe steps did not, by up to 26° and 40°).
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.rig.base import _perp, _unit, slerp
from interplay.motion.rotations import (
    axis_angle_to_matrix,
    matrix_to_quat,
    quat_to_matrix,
    rotation_between,
)

J = sk.JOINT_INDEX
# The leaves (joints with no child): their rotations are not in the joints (see above).
LEAVES: tuple[str, ...] = ("head", "left_wrist", "right_wrist")
# Toes may be given too (a capture's own, `motion/captured_leaves.py`), then kept off the floor
# as derived ones are; the Motion JSON's "leaves" holds LEAVES only.
GIVEN: tuple[str, ...] = LEAVES + ("left_foot", "right_foot")
HEAD_SHARE = 0.5                 # the head's turn on the neck, as a share of the neck's
HAND_LAG = 0.08                  # s: the hand follows its forearm's direction with this lag
# The lag bends the wrist at most this much. 30°, not more: a forearm reversing its swing
# flips the lag's bend to the other side in a frame, (1 - a)·swing + a·HAND_BEND with a
# the lag's share a frame (0.46 at 20 fps), over 30° for swings of 22–40° when it was 40°.
HAND_BEND = np.deg2rad(30.0)
# The studio's mesh hand (`formats/humanoid.py`) on the template: its length from the wrist
# and its half thickness (m); scaled to the person.
HAND_REACH, HAND_THICK = 0.175, 0.024
# rad/s: how fast a leaf's bend off the floor may change (`_floor_bend`): 15° a frame at
# 20 fps, half the 30° a frame the leaves' turns keep within.
LIFT_RATE = np.deg2rad(300.0)
LEAF_BLEND = 4                   # frames over which derived leaves turn into explicit ones
LIFT_MOST = np.pi / 2            # a toe or wrist bends up at most this much off the floor (a
                                 # leaf upside down: the rest is the exports' floor pass's)
_TOES = (J["left_foot"], J["right_foot"])
_Y, _Z = np.array([0.0, 1.0, 0.0]), np.array([0.0, 0.0, 1.0])


def end_sites(offsets: np.ndarray) -> dict[int, np.ndarray]:
    """End-site offsets (metres, in the leaf joint's rest frame) scaled to the person: the
    crown above the head, the hand along the forearm, the toe tip ahead of the ball of the
    foot. Shared by the exports so that every file ends its leaves the same way."""
    offsets = np.asarray(offsets, dtype=np.float64)
    scale = _body_scale(offsets)
    out = {sk.HEAD: np.array([0.0, 0.10, 0.0]) * scale}
    for hand in (sk.LEFT_HAND, sk.RIGHT_HAND):
        out[hand] = offsets[hand] / np.linalg.norm(offsets[hand]) * 0.08 * scale
    for toe in (sk.LEFT_FOOT, sk.RIGHT_FOOT):
        out[toe] = np.array([0.0, 0.0, 0.05]) * scale
    return out


def _body_scale(offsets: np.ndarray) -> float:
    return float(np.linalg.norm(offsets[1:], axis=1).sum()
                 / np.linalg.norm(sk.REST_OFFSETS[1:], axis=1).sum())


def _floor_bend(height: np.ndarray, frame: np.ndarray, tip: np.ndarray, length: float,
                rate: float) -> np.ndarray:
    """Bends (T,) (rad) of a leaf off the floor: the leaf turns as a hinge in its own frame,
    its tip (`length` along the unit `tip`, rest frame) towards its own up (rest +Y: a foot's
    top, the back of a hand; a toe flexes up, a wrist extends), by the least angle that keeps
    the tip off the floor, the leaf joint being `height` (T,) above it; `frame` (T, 3, 3): the
    leaf's world rotation before the bend. Then the bend is spread over time, changing at
    most `rate` a frame: it starts before the leaf reaches the floor and eases off after it
    leaves (a hand coming down 9 cm a frame needs no bend, then 49°: now it bends 15° a frame
    as it comes down), as r[t] grown to max over frames s of r[s] - rate·|t - s| (a forward
    and a backward pass; so a tip leaving the floor fast may point above level for a frame
    or two), at most LIFT_MOST. The bend alone is the leaf's turn
    off the floor, about one axis of its own frame, so it cannot spin where the tip points
    straight down (a tip pushed out along its own horizontal direction did: those few
    centimetres flip side frame to frame, 40–70° turns of a toe or hand in a frame)."""
    up = _unit(_perp(_Y, tip))
    t_y, w_y = (frame @ tip)[:, 1], (frame @ up)[:, 1]           # world heights of tip and up
    # The tip's direction height along the hinge: t_y cos b + w_y sin b = r cos(b - top).
    r, top = np.hypot(t_y, w_y), np.arctan2(w_y, t_y)
    top = np.where(top < 0, top + 2 * np.pi, top)                # the highest, turning up
    want = np.clip(-height / length, -1.0, 0.0)                  # the lowest it may point
    reach = np.arccos(np.clip(want / np.maximum(r, 1e-12), -1.0, 1.0))
    need = np.clip(top - reach, 0.0, None)
    # Out of reach within LIFT_MOST (the leaf's up faces down: bending lowers the tip first):
    # LIFT_MOST where that is still as good as the floor asks, less as it helps less, none
    # where it does not help at all (continuous in the pose).
    most = r * np.cos(LIFT_MOST - top)                           # the tip's height at LIFT_MOST
    helps = np.clip((most - t_y) / np.maximum(want - t_y, 1e-12), 0.0, 1.0)
    need = np.where(need > LIFT_MOST, LIFT_MOST * helps, need)
    bend = np.where(t_y >= want, 0.0, need)
    for order in (range(1, len(bend)), range(len(bend) - 2, -1, -1)):
        step = -1 if order.step > 0 else 1
        for i in order:
            bend[i] = max(bend[i], bend[i + step] - rate)
    return bend


def _hand_lag(joints: np.ndarray, wrist: int, fps: float) -> np.ndarray:
    """World swings (T, 3, 3) that bend a hand from its forearm's direction towards where the
    forearm pointed a moment ago: the direction followed with time constant HAND_LAG, at
    most HAND_BEND away (so the wrist turns with any swing of the forearm: a wave, an arm
    swing, a throw's follow-through)."""
    d = _unit(joints[:, wrist] - joints[:, sk.PARENTS[wrist]])
    alpha = 1.0 - np.exp(-1.0 / (max(float(fps), 1e-6) * HAND_LAG))
    h = np.empty_like(d)
    h[0] = d[0]
    limit = np.cos(HAND_BEND)
    for i in range(1, len(d)):
        g = h[i - 1] + alpha * (d[i] - h[i - 1])
        g = g / max(float(np.linalg.norm(g)), 1e-12)
        c = float(g @ d[i])
        if c < limit:                                            # clamp to HAND_BEND from d
            side = _unit(_perp(g, d[i]))
            g = limit * d[i] + np.sin(HAND_BEND) * side
        h[i] = g
    return rotation_between(d, h)


def _given(q: np.ndarray, known: np.ndarray, derived: np.ndarray) -> np.ndarray:
    """Local rotations (T, 3, 3) from explicit quaternions q (T, 4) on the `known` frames
    (T,) (e.g. a capture's own, `motion/captured_leaves.py`), the `derived` ones (T, 3, 3)
    elsewhere, turned towards the nearest explicit one over LEAF_BLEND frames next to it (so
    the hand or head does not jump where the explicit ones start or stop)."""
    t = len(q)
    q = np.where(known[:, None], q, 0.0)
    q = q / np.maximum(np.linalg.norm(q, axis=-1, keepdims=True), 1e-12)
    if known.all() or not known.any():
        return quat_to_matrix(q) if known.all() else derived
    idx = np.flatnonzero(known)
    pos = np.searchsorted(idx, np.arange(t))
    left, right = idx[np.clip(pos - 1, 0, len(idx) - 1)], idx[np.clip(pos, 0, len(idx) - 1)]
    near = np.where(np.abs(np.arange(t) - left) <= np.abs(right - np.arange(t)), left, right)
    w = np.clip(1.0 - np.abs(np.arange(t) - near) / (LEAF_BLEND + 1), 0.0, 1.0)
    return quat_to_matrix(slerp(matrix_to_quat(derived), q[near], w))


def fill_leaves(joints: np.ndarray, offsets: np.ndarray, local: np.ndarray, glob: np.ndarray,
            fps: float, floor: float, given: Mapping[str, np.ndarray]) -> None:
    """Fills the local rotations of the head, wrists and toes in place (see the module's
    docstring): derived, or `given` (local quaternions (T, 4) by joint name), then kept off
    the floor."""
    head, neck = J["head"], J["neck"]
    local[:, head] = quat_to_matrix(slerp(np.array([1.0, 0.0, 0.0, 0.0]),
                                          matrix_to_quat(local[:, neck]), np.asarray(HEAD_SHARE)))
    for wrist in (sk.LEFT_HAND, sk.RIGHT_HAND):
        g_el = glob[:, sk.PARENTS[wrist]]
        local[:, wrist] = np.swapaxes(g_el, -1, -2) @ _hand_lag(joints, wrist, fps) @ g_el
    for name, q in given.items():
        if name not in GIVEN:
            raise ValueError(f"explicit rotations are for {', '.join(GIVEN)}, got {name!r}")
        q = np.asarray(q, dtype=np.float64)
        known = np.all(np.isfinite(q), axis=-1) if q.ndim == 2 else np.zeros(0, bool)
        if q.shape != (len(joints), 4) or not np.all(known | np.all(np.isnan(q), axis=-1)):
            raise ValueError(f"{name}: rotations must be finite (T={len(joints)}, 4) or rows of NaN, "
                             f"got {q.shape}")
        local[:, J[name]] = _given(q, known, local[:, J[name]])
    tips = end_sites(offsets)
    scale = _body_scale(offsets)
    rate = LIFT_RATE / max(float(fps), 1e-6)
    for leaf in (sk.LEFT_HAND, sk.RIGHT_HAND, *_TOES):
        hand = leaf in (sk.LEFT_HAND, sk.RIGHT_HAND)
        tip = _unit(offsets[leaf]) if hand else _Z
        frame = glob[:, sk.PARENTS[leaf]] @ local[:, leaf]
        height = joints[:, leaf, 1] - floor - (HAND_THICK * scale if hand else 0.0)
        length = HAND_REACH * scale if hand else float(np.linalg.norm(tips[leaf]))
        bend = _floor_bend(height, frame, tip, length, rate)
        axis = _unit(np.cross(tip, _perp(_Y, tip)))
        local[:, leaf] = local[:, leaf] @ axis_angle_to_matrix(bend[:, None] * axis)
