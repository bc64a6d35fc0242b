"""The one rotation solver behind every export (BVH, GLB, JSON) and the studio's skinned
character: joints (T, 22, 3) → a `Rig` of rest offsets, root positions and local joint
rotations (unit quaternions w, x, y, z) that reproduce the joints by forward kinematics.
numpy only.

`kinematics.inverse_kinematics` (the IK behind the features) takes each bone's smallest
rotation from rest with zero twist, frame by frame. That is exact for positions but its
twist is arbitrary and unstable: near a 180° swing (a deep knee bend in the parent's frame,
an arm swung behind) the smallest rotation's axis spins, and every child inherits the spin,
so an ankle can turn 140° between two frames while its bone barely moves. Here each joint's
rotation is instead built from two directions in its parent's frame: the bone it moves (exact,
so positions do not change) and a secondary axis that fixes the twist:

- hips and shoulders with their knees and elbows, solved as hinges: the knee's (elbow's)
  rotation is a turn about a fixed side-to-side axis of the thigh (upper arm) by the angle
  that gives the shin (forearm) its observed angle to the thigh, and the hip's (shoulder's)
  twist is the one that puts the shin in that hinge's plane: knees and elbows stay hinges;
- ankles: the shin's side-to-side axis (the ankle flexes about it);
- spine1 / spine2: the pelvis's and the chest's side-to-side axes blended 2:1 and 1:2, so a
  torso twist spreads along the spine; neck: the chest's side-to-side axis; collars: the
  chest's forward axis;
- the pelvis and spine3: the frame of their children (hips / collars and the bone up), as IK.

Wherever that reference says little (a straight knee or elbow has no bend plane; a bone
pointing along its reference axis), the previous frame's axis, held in the parent's frame,
takes over smoothly: the twist is propagated along time, never re-solved from rest, so it does
not jump while the bone barely moves. Leaves carry no bone, so nothing in 22 joints says how
they turn; they get the rotations the moves imply (`LEAVES`): the head turns on the neck by
HEAD_SHARE of the neck's own turn (a nod, which tilts the neck→head bone, pitches the face
further; smooth wherever the neck is); each hand trails its forearm's swing with a lag of
HAND_LAG seconds, bent at most HAND_BEND (a wave turns the hand to and fro); explicit per-frame
rotations (`leaves=`, e.g. from an edit) replace either. Then no leaf's tip goes under the
floor: a toe whose tip (the end site) would dip pitches up just enough (a flat foot's toes lie
on the floor), and so does a hand whose mesh tip (HAND_REACH along it, HAND_THICK thick) would. Quaternions keep one sign
through time (q and -q are the same rotation; a reader interpolating them must not see a flip).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import (
    _FRAME_CHILDREN,
    _joint_frames,
    fit_offsets,
    floor_height,
    forward_kinematics,
)
from interplay.motion.rotations import (
    axis_angle_to_matrix,
    matrix_to_quat,
    quat_to_matrix,
    rotation_between,
)

J = sk.JOINT_INDEX
# Below this size (the sine of the angle between the reference and the bone; for a hinge the
# sine of the bend) the previous frame's axis is blended in, alone at zero.
_SURE = 0.5
# The secondary axis turns at most this much per frame (rad): where the reference swings
# faster (a hinge's bend plane turning while the limb is almost straight) the twist follows
# over a few frames instead of in one, and the hinge is briefly not a pure hinge.
_STEP = np.deg2rad(15.0)
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


@dataclass(frozen=True, eq=False)
class Rig:
    """A person's motion as a skeleton animation.

    offsets (22, 3): rest offsets (metres, parent → child in the parent's rest frame; the
    rest pose faces +Z, Y up; the root row is the rest pelvis height). root (T, 3): pelvis
    positions. rotations (T, 22, 4): local rotations, unit quaternions (w, x, y, z), each
    relative to its parent (the pelvis's is global), identity in the rest pose."""
    offsets: np.ndarray
    root: np.ndarray
    rotations: np.ndarray

    @property
    def frames(self) -> int:
        return int(self.root.shape[0])

    def matrices(self) -> np.ndarray:
        """Local rotation matrices (T, 22, 3, 3)."""
        return quat_to_matrix(self.rotations)


_X, _Z = np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0])
# Each solved joint: (kind, joint, child, reference joint, axis, weight), in an order where a
# joint's parent and reference are solved before it. Kinds: "spine" (reference: the pelvis's
# and spine3's side axes blended, `weight` on spine3), "frame" (reference: the reference
# joint's rotation applied to `axis`), "hinge" (a hip or shoulder and, with it, its knee or
# elbow; `axis`: the hinge's rest axis, before it is made perpendicular to the bone).
_PLAN: tuple[tuple[str, int, int, int, np.ndarray, float], ...] = (
    ("spine", J["spine1"], J["spine2"], -1, _X, 1.0 / 3.0),
    ("spine", J["spine2"], J["spine3"], -1, _X, 2.0 / 3.0),
    ("frame", J["neck"], J["head"], J["spine3"], _X, 0.0),
    ("frame", J["left_collar"], J["left_shoulder"], J["spine3"], _Z, 0.0),
    ("frame", J["right_collar"], J["right_shoulder"], J["spine3"], _Z, 0.0),
    # Knees fold the shin backwards (-Y towards -Z): positive turns about +X.
    ("hinge", J["left_hip"], J["left_knee"], -1, _X, 0.0),
    ("hinge", J["right_hip"], J["right_knee"], -1, _X, 0.0),
    ("frame", J["left_ankle"], J["left_foot"], J["left_knee"], _X, 0.0),
    ("frame", J["right_ankle"], J["right_foot"], J["right_knee"], _X, 0.0),
    # Elbows fold the forearm forwards (±X towards +Z): positive turns about -Y on the left.
    ("hinge", J["left_shoulder"], J["left_elbow"], -1, np.array([0.0, -1.0, 0.0]), 0.0),
    ("hinge", J["right_shoulder"], J["right_elbow"], -1, np.array([0.0, 1.0, 0.0]), 0.0),
)
_TOES = (J["left_foot"], J["right_foot"])


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


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.maximum(np.linalg.norm(v, axis=-1, keepdims=True), 1e-12)


def _perp(v: np.ndarray, axis: np.ndarray) -> np.ndarray:
    """v without its component along the unit axis."""
    return v - np.sum(v * axis, axis=-1, keepdims=True) * axis


def _frame(primary: np.ndarray, secondary: np.ndarray) -> np.ndarray:
    """Orthonormal frames (..., 3, 3), columns: the unit primary, the secondary made
    perpendicular to it, their cross product."""
    a = _unit(primary)
    b = _unit(_perp(secondary, a))
    return np.stack([a, b, np.cross(a, b)], axis=-1)


def _any_perp(v: np.ndarray) -> np.ndarray:
    trial = np.array([1.0, 0.0, 0.0]) if abs(v[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    return _unit(_perp(trial, v))


def _hinge(bone: np.ndarray, child: np.ndarray, u: np.ndarray, v: np.ndarray, a: np.ndarray
           ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A two-bone chain (a hip and knee, a shoulder and elbow) as a hinge, in the upper
    joint's parent's frame: bone, child (T, 3) unit directions of the upper and lower bone;
    u, v their rest directions, a the hinge's rest axis (unit, perpendicular to u).

    The hinge angle theta (T,) is the turn about a that gives the lower bone the observed
    angle to the upper one, on the bending side (theta grows as the limb folds; the rest pose
    is theta = 0 for the template's directions, which rest slightly folded). Returns the
    upper joint's secondary axis that makes the lower joint exactly that hinge (where the
    angle is reachable), as long as the sine of the bend (how sure it is: a straight limb has
    no bend plane), theta, and the rest lower bone turned by theta, R(a, theta) v."""
    cos = np.sum(bone * child, axis=-1)
    av = a @ v
    v_perp = v - av * a
    big_a, big_b, big_c = av * (a @ u), u @ v_perp, u @ np.cross(a, v_perp)
    size, phi = np.hypot(big_b, big_c), np.arctan2(big_c, big_b)
    theta = phi + np.arccos(np.clip((cos - big_a) / max(size, 1e-12), -1.0, 1.0))
    turned = axis_angle_to_matrix(a[None] * theta[:, None]) @ v
    across = _perp(child, bone)                                  # its length: sin(bend)
    observed = _frame(bone, across)
    rest = _frame(np.broadcast_to(u, turned.shape), _perp(turned, u))
    axis = np.einsum("tij,tkj,k->ti", observed, rest, a)
    return axis * np.linalg.norm(across, axis=-1, keepdims=True), theta, turned


def _turn_at_most(a: np.ndarray, b: np.ndarray, axis: np.ndarray, limit: float) -> np.ndarray:
    """b, or a turned towards b about the unit axis by limit (rad) when they are further
    apart (a and b unit and perpendicular to the axis)."""
    cos = float(np.clip(a @ b, -1.0, 1.0))
    if cos >= np.cos(limit):
        return b
    side = np.cross(axis, a)
    sign = 1.0 if side @ b >= 0 else -1.0
    return np.cos(limit) * a + sign * np.sin(limit) * side


def _propagate(bone: np.ndarray, ref: np.ndarray, start: np.ndarray) -> np.ndarray:
    """Secondary axes (T, 3), unit and perpendicular to the unit bones (T, 3), all in the
    parent's frame: each frame's reference made perpendicular to the bone, with the previous
    frame's axis blended in where the reference is short (alone when it vanishes; below _SURE
    the reference weighs size² / _SURE against 1 - size / _SURE), turning at most _STEP per
    frame. The reference's size is the sine of the angle between it and the
    bone (a hinge's: the sine of the bend).

    The walk starts at the first frame whose reference is sure and goes forward from there
    and back to frame 0, so a motion that starts with a straight arm takes its axis from the
    first bend; with no sure frame it starts from the rest axis `start`."""
    t = bone.shape[0]
    ref_p = _perp(ref, bone)
    size = np.linalg.norm(ref_p, axis=-1)
    keep = np.clip(1.0 - size / _SURE, 0.0, 1.0)
    # A short reference counts for less still (its direction is noise when it nearly vanishes).
    ref_p = ref_p * np.clip(size / _SURE, 0.0, 1.0)[:, None]
    out = np.empty((t, 3))
    sure = np.flatnonzero(size >= _SURE)
    first = int(sure[0]) if len(sure) else 0
    prev = start
    if len(sure):
        prev = ref_p[first] / np.linalg.norm(ref_p[first])
    for order in (range(first, t), range(first - 1, -1, -1)):
        if order.start < first:
            prev = out[first]
        for i in order:
            b = bone[i]
            r = ref_p[i]
            p = prev - (prev @ b) * b
            s = r + keep[i] * p
            n = np.sqrt(s @ s)
            n_p = np.sqrt(p @ p)
            if n < 1e-9:
                s, n = (p, n_p) if n_p > 1e-9 else (_any_perp(b), 1.0)
            s = s / n
            if n_p > 1e-9:
                s = _turn_at_most(p / n_p, s, b, _STEP)
            prev = s
            out[i] = prev
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


def _leaves(joints: np.ndarray, offsets: np.ndarray, local: np.ndarray, glob: np.ndarray,
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


def continuous(q: np.ndarray) -> np.ndarray:
    """Quaternions (T, J, 4) with each one's sign flipped to agree with the frame before."""
    q = q.copy()
    for i in range(1, q.shape[0]):
        flip = np.sum(q[i] * q[i - 1], axis=-1) < 0
        q[i, flip] *= -1.0
    return q


def solve_rig(joints: np.ndarray, offsets: np.ndarray | None = None, *, fps: float = sk.FPS,
              floor: float | None = None, leaves: Mapping[str, np.ndarray] | None = None) -> Rig:
    """A Rig (offsets, root, continuous local rotations) reproducing joints (T, 22, 3) by FK:
    exactly (to float precision) when the joints lie on the offsets' bone lengths, as every
    motion in Interplay does. offsets (22, 3) default to the motion's own (`fit_offsets`).
    floor: the ground's height (y, m) the toe tips keep above; the person's own
    (`kinematics.floor_height`) when None; pass the shared one for two people. fps: the
    motion's rate (the hands' lag is in seconds). leaves: explicit local rotations (T, 4),
    w x y z, of "head", "left_wrist" or "right_wrist" (an edit's), in place of the derived."""
    joints = np.asarray(joints, dtype=np.float64)
    if joints.ndim != 3 or joints.shape[1:] != (sk.NUM_JOINTS, 3) or joints.shape[0] < 1:
        raise ValueError(f"joints must be (T >= 1, {sk.NUM_JOINTS}, 3), got {joints.shape}")
    if not np.all(np.isfinite(joints)):
        raise ValueError("joints contain NaN or infinite values")
    offsets = fit_offsets(joints) if offsets is None else np.asarray(offsets, dtype=np.float64)
    if offsets.shape != (sk.NUM_JOINTS, 3):
        raise ValueError(f"offsets must be ({sk.NUM_JOINTS}, 3), got {offsets.shape}")
    t = joints.shape[0]
    rest = sk.rest_joints(offsets)
    glob = np.tile(np.eye(3), (t, sk.NUM_JOINTS, 1, 1))
    local = glob.copy()
    # Frame joints: the rotation taking the rest frame of their children onto the observed.
    for j in _FRAME_CHILDREN:
        glob[:, j] = _joint_frames(joints, j) @ _joint_frames(rest, j).T
    local[:, sk.PELVIS] = glob[:, sk.PELVIS]

    for kind, j, c, ref_joint, vec, weight in _PLAN:
        p = sk.PARENTS[j]
        gp = glob[:, p]                                          # parent's global (T, 3, 3)
        to_parent = np.swapaxes(gp, -1, -2)
        bone_rest = _unit(offsets[c])
        bone = _unit(np.einsum("tij,tj->ti", to_parent, joints[:, c] - joints[:, j]))
        if kind == "hinge":
            (grand,) = sk.children(c)
            lower = _unit(np.einsum("tij,tj->ti", to_parent, joints[:, grand] - joints[:, c]))
            sec_rest = _unit(_perp(vec, bone_rest))
            ref_local, theta, turned = _hinge(bone, lower, bone_rest, _unit(offsets[grand]), sec_rest)
        elif kind == "frame":
            ref_local = np.einsum("tij,tjk,k->ti", to_parent, glob[:, ref_joint], vec)
            sec_rest = _unit(_perp(vec, bone_rest))
        else:                                                    # spine
            side = (1 - weight) * glob[:, sk.PELVIS, :, 0] + weight * glob[:, J["spine3"], :, 0]
            ref_local = np.einsum("tij,tj->ti", to_parent, side)
            sec_rest = _unit(_perp(vec, bone_rest))
        sec = _propagate(bone, ref_local, sec_rest)
        local[:, j] = _frame(bone, sec) @ _frame(bone_rest, sec_rest).T
        glob[:, j] = gp @ local[:, j]
        if kind == "hinge":
            # The lower joint: the hinge turn, then the (small; none where the upper joint
            # took the hinge's axis) swing onto the observed lower bone.
            hinge = axis_angle_to_matrix(sec_rest[None] * theta[:, None])
            lower_here = np.einsum("tji,tj->ti", local[:, j], lower)
            local[:, c] = rotation_between(turned, lower_here) @ hinge
            glob[:, c] = glob[:, j] @ local[:, c]
    # spine3's global is its children's frame; its local follows from spine2's.
    s3 = J["spine3"]
    local[:, s3] = np.swapaxes(glob[:, sk.PARENTS[s3]], -1, -2) @ glob[:, s3]
    ground = floor_height([joints]) if floor is None else float(floor)
    _leaves(joints, offsets, local, glob, fps, ground, leaves or {})
    quats = continuous(matrix_to_quat(local))
    return Rig(offsets=offsets.copy(), root=joints[:, sk.PELVIS].copy(), rotations=quats)


def rig_from_json(person: dict) -> Rig:
    """The Rig of one person of a version-2 Motion JSON ({"rig": {"offsets", "root",
    "rotations"}}); ValueError when it is missing or malformed."""
    block = person.get("rig") if isinstance(person, dict) else None
    if not isinstance(block, dict):
        raise ValueError("the person has no 'rig' (a version-1 motion: solve_rig its joints)")
    try:
        offsets, root, rotations = (np.asarray(block[k], dtype=np.float64)
                                    for k in ("offsets", "root", "rotations"))
    except (KeyError, TypeError, ValueError) as exc:
        raise ValueError(f"'rig' needs numeric 'offsets', 'root' and 'rotations': {exc}") from None
    t = root.shape[0] if root.ndim == 2 else -1
    if offsets.shape != (sk.NUM_JOINTS, 3) or root.shape != (t, 3) or rotations.shape != (t, sk.NUM_JOINTS, 4):
        raise ValueError(f"'rig' shapes must be offsets (22, 3), root (T, 3), rotations (T, 22, 4); "
                         f"got {offsets.shape}, {root.shape}, {rotations.shape}")
    return Rig(offsets=offsets, root=root, rotations=rotations / np.linalg.norm(rotations, axis=-1, keepdims=True))


def global_rotations(rig: Rig) -> np.ndarray:
    """Global rotation matrices (T, 22, 3, 3) of every joint."""
    return forward_kinematics(rig.matrices(), rig.root, rig.offsets)[1]


def rig_positions(rig: Rig) -> np.ndarray:
    """Joint positions (T, 22, 3) by forward kinematics of the rig."""
    return forward_kinematics(rig.matrices(), rig.root, rig.offsets)[0]


def slerp(q0: np.ndarray, q1: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Spherical interpolation of unit quaternions (..., 4) by weights w (...) in [0, 1],
    along the shorter arc."""
    q0, q1 = np.asarray(q0, dtype=np.float64), np.asarray(q1, dtype=np.float64)
    w = np.asarray(w, dtype=np.float64)[..., None]
    dot = np.sum(q0 * q1, axis=-1, keepdims=True)
    q1 = np.where(dot < 0, -q1, q1)
    dot = np.abs(dot)
    theta = np.arccos(np.clip(dot, -1.0, 1.0))
    sin = np.sin(theta)
    near = sin < 1e-6
    a = np.where(near, 1 - w, np.sin((1 - w) * theta) / np.where(near, 1.0, sin))
    b = np.where(near, w, np.sin(w * theta) / np.where(near, 1.0, sin))
    out = a * q0 + b * q1
    return out / np.linalg.norm(out, axis=-1, keepdims=True)
