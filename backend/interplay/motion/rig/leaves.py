"""The leaves of `solve_rig`: the head, the wrists and the toes. Leaves carry no bone, so
nothing in 22 joints says how they turn; they get the rotations the moves imply (`LEAVES`):
the head turns on the neck by HEAD_SHARE of the neck's own turn (a nod, which tilts the
neck→head bone, pitches the face further; smooth wherever the neck is); each hand trails its
forearm's swing with a lag of HAND_LAG seconds, bent at most HAND_BEND (a wave turns the hand
to and fro); explicit per-frame rotations (`leaves=`, e.g. from an edit) replace either. Then
no leaf's tip goes under the floor: a toe whose tip (the end site) would dip pitches up just
enough (a flat foot's toes lie on the floor), and so does a hand whose mesh tip (HAND_REACH
along it, HAND_THICK thick) would.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.rig.base import _perp, _unit, slerp
from interplay.motion.rotations import matrix_to_quat, quat_to_matrix, rotation_between

J = sk.JOINT_INDEX
# The leaves (joints with no child): their rotations are not in the joints (see above).
LEAVES: tuple[str, ...] = ("head", "left_wrist", "right_wrist")
HEAD_SHARE = 0.5                 # the head's turn on the neck, as a share of the neck's
HAND_LAG = 0.08                  # s: the hand follows its forearm's direction with this lag
HAND_BEND = np.deg2rad(40.0)     # the lag bends the wrist at most this much
# The studio's mesh hand (`formats/humanoid.py`) on the template: its length from the wrist
# and its half thickness (m); scaled to the person.
HAND_REACH, HAND_THICK = 0.175, 0.024
# A leaf tip pushed up off the floor turns its heading slowly: each frame the last heading
# weighs this much against the tip's own horizontal direction (length ≤ 1; where the tip
# is nearly level, hardly any push is needed and the heading hardly matters).
# (Toes keep none: their tips point forward, well away from straight down; the library's
# toe steps grow with it.)
_HAND_HEADING_MEMORY = 2.0
_TOES = (J["left_foot"], J["right_foot"])
_Z = np.array([0.0, 0.0, 1.0])


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


def _headings(flat: np.ndarray, ref: np.ndarray, memory: float) -> np.ndarray:
    """Unit horizontal headings (T, 3) that follow the horizontal directions `flat` (T, 3)
    where they are long and keep the previous frame's where they vanish (a leaf pointing
    straight down has no heading of its own), `ref` (T, 3) breaking ties."""
    out = np.empty_like(flat)
    prev = np.zeros(3)
    for i in range(len(flat)):
        h = flat[i] + memory * prev + 1e-3 * ref[i]
        n = float(np.linalg.norm(h))
        prev = h / n if n > 1e-12 else np.array([0.0, 0.0, 1.0])
        out[i] = prev
    return out


def _tip_above_floor(height: np.ndarray, glob_leaf: np.ndarray, rest_dir: np.ndarray,
                     length: float, ref: np.ndarray, memory: float = 0.0) -> np.ndarray:
    """World pitches (T, 3, 3) for a leaf joint: identity unless its tip (`length` along
    `rest_dir`, in its rest frame) would be under the floor, the joint being `height` (T,)
    above it; then the least turn up that puts the tip on the floor, or level with the joint
    when the joint itself is under it. The tip keeps its horizontal direction and is pushed
    out along a heading that follows it over time (`_headings`; `ref` (T, 3): a direction
    for ties, the parent bone's; `memory`: how much the last heading weighs, 0: none, the
    tip turns up in its own vertical plane), so a tip pointing straight down does not spin:
    continuous in the pose and in time."""
    tip = glob_leaf @ rest_dir                                   # tip direction, world (T, 3)
    want = np.clip(-height / length, -1.0, 0.0)                  # lowest allowed tip direction y
    low = tip[:, 1] < want
    flat = tip * np.array([1.0, 0.0, 1.0])
    heading = _headings(flat, ref * np.array([1.0, 0.0, 1.0]), memory)
    # The horizontal part grown along the heading to the length sqrt(1 - want²) (the least
    # push: none where the tip is just at `want`).
    r2 = 1.0 - want ** 2
    fh = np.sum(flat * heading, axis=-1)
    push = -fh + np.sqrt(np.maximum(fh ** 2 - np.sum(flat * flat, axis=-1) + r2, 0.0))
    target = flat + push[:, None] * heading
    target[:, 1] = want
    target = _unit(target)
    return np.where(low[:, None, None], rotation_between(tip, np.where(low[:, None], target, tip)),
                    np.eye(3))


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
        if name not in LEAVES:
            raise ValueError(f"explicit rotations are for {', '.join(LEAVES)}, got {name!r}")
        q = np.asarray(q, dtype=np.float64)
        if q.shape != (len(joints), 4) or not np.all(np.isfinite(q)):
            raise ValueError(f"{name}: rotations must be finite (T={len(joints)}, 4), got {q.shape}")
        local[:, J[name]] = quat_to_matrix(q / np.maximum(np.linalg.norm(q, axis=-1, keepdims=True), 1e-12))
    tips = end_sites(offsets)
    scale = _body_scale(offsets)
    for wrist in (sk.LEFT_HAND, sk.RIGHT_HAND):
        g_el = glob[:, sk.PARENTS[wrist]]
        g = g_el @ local[:, wrist]
        height = joints[:, wrist, 1] - floor - HAND_THICK * scale
        forearm = joints[:, wrist] - joints[:, sk.PARENTS[wrist]]
        pitch = _tip_above_floor(height, g, _unit(offsets[wrist]), HAND_REACH * scale, forearm,
                                 _HAND_HEADING_MEMORY)
        local[:, wrist] = np.swapaxes(g_el, -1, -2) @ pitch @ g
    for toe in _TOES:
        g_an = glob[:, sk.PARENTS[toe]]
        foot = joints[:, toe] - joints[:, sk.PARENTS[toe]]
        pitch = _tip_above_floor(joints[:, toe, 1] - floor, g_an, _Z, float(np.linalg.norm(tips[toe])), foot)
        # World pitch applied after the ankle's rotation → local: ankle^T · pitch · ankle.
        local[:, toe] = np.swapaxes(g_an, -1, -2) @ pitch @ g_an
