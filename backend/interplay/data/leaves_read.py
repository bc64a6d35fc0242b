"""Reading the head and hand bones' world rotations out of each raw capture format, for
`data/leaves.py`, replayed through the positions' own pipeline (the converter's lead-in cut, the
capture rate's resampling to 20 fps by slerp at the very times the positions take, the clip's
canonical yaw), so that frame i is the library clip's frame i.

Each reader gives, per leaf it carries, (T, 2, 3, 3): the leaf bone's world rotation and its
parent bone's (column vectors, Y up), and "rest" (5, 3, 3) (LEAF_NAMES' order, NaN for a leaf
not carried) where the family rests as the rig does (a T-pose facing +Z, left at +X): the exact
correction per leaf (identity for the head; each hand the turn from the rig's rest hand, along
its rest forearm, onto the file's rest hand bone; each toe from the rig's, pointing +Z, onto
the file's toe bone, which `leaves.py` replaces by one measured on planted feet). Without
"rest" the correction is measured (`leaves.rest_corrections`).

Families and their leaf bones (bone, parent bone):
- Daz BVH (cmu-bvh, salsa): head on neck, l/rHand on l/rForeArm; no toe (the leg ends at the
  foot); exact rest.
- Acclaim-named BVH (cmu-bvh 16_01, 16_02; a joint sits at the start of its Acclaim bone):
  head on upperneck, l/rhand on l/rradius, l/rtoes on l/rfoot; exact rest (a T-pose, the hand
  bone along +X, each toe towards its End Site).
- Bandai Namco BVH: Head on Neck, Hand_L/_R on LowerArm_L/_R, Toes_L/_R on Foot_L/_R;
  measured (rests along +X; the toes on planted feet, `leaves.toe_correction`).
- CC_Base BVH (cmu-iclone): CC_Base_Head on NeckTwist02, L/R_Hand on L/R_Forearm, L/R_ToeBase
  on L/R_Foot; measured, as Bandai's.
- Acclaim ASF/AMC (HDM05, cmu-asfamc): head on upperneck, l/rhand on l/rradius, l/rtoes on
  l/rfoot; exact.
- The 8-action exp-maps (`retarget/cmu_8action`, Acclaim's bones, row vectors): a bone is
  turned by its start joint's global, the head by upperneck's, a hand by l/rwrist's (on
  l/rwrist_start's, the forearm with its twist), a toe by l/rfoot's (on l/rtibia's); exact
  rest (Acclaim's).
- DeepMimic's humanoid: the head is the neck joint's body (on the chest); its wrists are
  "fixed" joints (no rotation in any file: the hand is the forearm), so no hands are carried.
  Exact rest: the character faces +X with its right at +Z, the rig's rest turned by +90°
  about Y.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.captured_leaves import LEAF_NAMES
from interplay.motion.kinematics import forward_kinematics
from interplay.motion.rotations import matrix_to_quat, quat_to_matrix, rotation_between, yaw_matrix

J = sk.JOINT_INDEX
# Per BVH family, each leaf's bone and its parent bone's (the rig's parent joint's match).
BONES: dict[str, dict[str, tuple[str, str]]] = {
    "daz": {"head": ("head", "neck"), "left_wrist": ("lHand", "lForeArm"),
            "right_wrist": ("rHand", "rForeArm")},
    "acclaim": {"head": ("head", "upperneck"), "left_wrist": ("lhand", "lradius"),
                "right_wrist": ("rhand", "rradius")},
    "bandai-namco": {"head": ("Head", "Neck"), "left_wrist": ("Hand_L", "LowerArm_L"),
                     "right_wrist": ("Hand_R", "LowerArm_R")},
    "cc-base": {"head": ("CC_Base_Head", "CC_Base_NeckTwist02"),
                "left_wrist": ("CC_Base_L_Hand", "CC_Base_L_Forearm"),
                "right_wrist": ("CC_Base_R_Hand", "CC_Base_R_Forearm")},
}
# Per BVH family with toes, each toe's bone and its parent's (the foot).
TOE_BONES: dict[str, dict[str, tuple[str, str]]] = {
    "acclaim": {"left_foot": ("ltoes", "lfoot"), "right_foot": ("rtoes", "rfoot")},
    "bandai-namco": {"left_foot": ("Toes_L", "Foot_L"), "right_foot": ("Toes_R", "Foot_R")},
    "cc-base": {"left_foot": ("CC_Base_L_ToeBase", "CC_Base_L_Foot"),
                "right_foot": ("CC_Base_R_ToeBase", "CC_Base_R_Foot")},
}
# Per exactly resting BVH family, each hand or toe bone's rest direction: (from, to) positions.
REST_DIRECTIONS: dict[str, dict[str, tuple[str, str]]] = {
    "daz": {"left_wrist": ("lHand", "lMid1"), "right_wrist": ("rHand", "rMid1")},
    "acclaim": {"left_wrist": ("lhand", "lfingers"), "right_wrist": ("rhand", "rfingers"),
                "left_foot": ("ltoes", "ltoes_end"), "right_foot": ("rtoes", "rtoes_end")},
}
ACCLAIM_BONES: dict[str, tuple[str, str]] = {
    "head": ("head", "upperneck"), "left_wrist": ("lhand", "lradius"), "right_wrist": ("rhand", "rradius"),
    "left_foot": ("ltoes", "lfoot"), "right_foot": ("rtoes", "rfoot")}
EXPMAP_BONES: dict[str, tuple[str, str]] = {
    "head": ("upperneck", "lowerneck"), "left_wrist": ("lwrist", "lwrist_start"),
    "right_wrist": ("rwrist", "rwrist_start"), "left_foot": ("lfoot", "ltibia"),
    "right_foot": ("rfoot", "rtibia")}
TOE_TIP = np.array([0.0, 0.0, 1.0])      # the rig's rest toe points ahead (`rig.end_sites`)


def _rig_rest(leaf: str) -> np.ndarray:
    """The direction a leaf's bone points at the rig's rest: a hand along its forearm, a toe ahead."""
    return TOE_TIP if leaf.endswith("_foot") else sk.REST_OFFSETS[J[leaf]]


def _rests(directions: dict[str, np.ndarray]) -> np.ndarray:
    """Exact corrections (5, 3, 3) in LEAF_NAMES' order: the head none, each hand or toe given
    a direction the turn from the rig's rest onto it, NaN for a leaf not carried."""
    out = np.full((len(LEAF_NAMES), 3, 3), np.nan)
    out[0] = np.eye(3)
    for i, leaf in enumerate(LEAF_NAMES):
        if leaf in directions:
            out[i] = rotation_between(_rig_rest(leaf), directions[leaf])
    return out


def _slerp_at(q: np.ndarray, pos: np.ndarray) -> np.ndarray:
    """Unit quaternions (n, ..., 4) at fractional frame positions pos (m,), by slerp between
    neighbours (a position on a frame takes that frame)."""
    from interplay.motion.rig import slerp
    n = q.shape[0]
    lo = np.clip(np.floor(pos + 1e-9).astype(int), 0, n - 1)
    hi = np.clip(lo + 1, 0, n - 1)
    w = np.clip(pos - lo, 0.0, 1.0)
    w = np.broadcast_to(w.reshape((-1,) + (1,) * (q.ndim - 2)), q[lo].shape[:-1])
    return slerp(q[lo], q[hi], w)


def _slerp_resample(q: np.ndarray, src_fps: float, dst_fps: float = sk.FPS) -> np.ndarray:
    """Unit quaternions (n, ..., 4) at src_fps → dst_fps at the times `kinematics.resample`
    takes (so frame i lands on the positions' frame i)."""
    n = q.shape[0]
    if n < 2 or abs(src_fps - dst_fps) < 1e-9:
        return q.copy()
    duration = (n - 1) / src_fps
    return _slerp_at(q, np.arange(int(np.floor(duration * dst_fps + 1e-6)) + 1) / dst_fps * src_fps)


def _out(glob: dict[str, np.ndarray], bones: dict[str, tuple[str, str]], yaw: float,
         resample) -> dict[str, np.ndarray]:
    """Per leaf, its (bone, parent bone) world rotations (T, 2, 3, 3) turned by the canonical
    yaw and resampled by `resample` (quaternions (n, 2, 4) → (T, 2, 4))."""
    out = {}
    for leaf, pair in bones.items():
        g = yaw_matrix(yaw) @ np.stack([glob[b] for b in pair], axis=1)
        out[leaf] = quat_to_matrix(resample(matrix_to_quat(g)))
    return out


def bvh_globals(path: Path, cut: int, fps: float, yaw: float) -> dict[str, np.ndarray] | None:
    """A BVH of one of the BONES families (Y up after FK), replayed through the positions'
    pipeline (lead-in `cut`, capture rate `fps` → 20, canonical `yaw`); None for another."""
    from interplay.motion.formats.bvh import read_bvh
    from interplay.motion.retarget.cmu_daz import acclaim_names
    bvh = acclaim_names(read_bvh(path))
    family = next((f for f, bones in BONES.items()
                   if all(b in bvh.names for pair in bones.values() for b in pair)), None)
    if family is None:
        return None
    bones = {**BONES[family], **{leaf: pair for leaf, pair in TOE_BONES.get(family, {}).items()
                                 if all(b in bvh.names for b in pair)}}
    rot, _ = bvh.local_transforms()
    _, g = forward_kinematics(rot[cut:], np.zeros((len(rot) - cut, 3)), bvh.offsets, list(bvh.parents))
    glob = {b: g[:, bvh.index(b)] for pair in bones.values() for b in pair}
    out = _out(glob, bones, yaw, lambda q: _slerp_resample(q, fps))
    if family in REST_DIRECTIONS:               # rests as the rig: exact corrections
        rest = replace(bvh, motion=np.zeros((1, bvh.motion.shape[1]))).named_positions(include_end_sites=True)
        out["rest"] = _rests({leaf: rest[b][0] - rest[a][0] for leaf, (a, b) in REST_DIRECTIONS[family].items()
                              if leaf in bones and a in rest and b in rest})
    return out


def acclaim_globals(amc_path: Path, asf_path: Path, fps: float, yaw: float) -> dict[str, np.ndarray]:
    """An ASF/AMC pair (HDM05, cmu-asfamc): the bones' global rotations as
    `formats.acclaim.forward_kinematics` composes them (L = C · M · C⁻¹), resampled from `fps`
    to 20, turned by the canonical `yaw`; "rest": exact, each hand along its hand bone."""
    from interplay.motion.formats.acclaim import _bone_motion, ordered_rotation, read_amc, read_asf
    asf, amc = read_asf(asf_path), read_amc(amc_path)
    t = amc.n_frames
    degrees = amc.degrees if amc.degrees is not None else asf.angle_unit == "deg"
    to_rad = np.pi / 180 if degrees else 1.0
    root = amc.values["root"]
    cols = [i for i, ch in enumerate(asf.root_order) if ch.lower().startswith("r")]
    c_root = ordered_rotation(asf.root_orientation, asf.root_axis)
    axes = "".join(asf.root_order[i][1].upper() for i in cols)
    glob = {"root": c_root @ ordered_rotation(root[:, cols] * to_rad, axes) @ c_root.T}
    for name, bone in asf.bones.items():
        c = ordered_rotation(bone.axis, bone.axis_order)
        glob[name] = glob[asf.parents[name]] @ (c @ _bone_motion(bone, amc.values.get(name), t, to_rad) @ c.T)
    out = _out(glob, ACCLAIM_BONES, yaw, lambda q: _slerp_resample(q, fps))
    out["rest"] = _rests({leaf: asf.bones[bone].direction for leaf, (bone, _) in ACCLAIM_BONES.items()
                          if leaf != "head"})
    return out


def expmap_globals(path: Path, yaw: float) -> dict[str, np.ndarray]:
    """A cmu-8action file: its skeleton's global rotations (row vectors: a bone from joint p
    to j is turned by p's global, column form its transpose), the positions' pipeline replayed
    (rest lines dropped, 120 → 20 fps, canonical yaw); "rest": exact (Acclaim's T-pose)."""
    from interplay.motion.retarget import cmu_8action as ea
    from interplay.motion.rotations import axis_angle_to_matrix
    skel = ea.ExpMapSkeleton.from_json(ea.find_skeleton(path)).with_thorax()
    values, _ = ea.drop_rest_frames(ea.read_frames(path))
    t, n = len(values), len(skel.parents)
    local = axis_angle_to_matrix(values[:, 3:].reshape(t, n, 3))
    g = np.empty_like(local)
    for j, p in enumerate(skel.parents):
        g[:, j] = local[:, j] if p < 0 else local[:, j] @ g[:, p]
    names = {name: i for i, name in enumerate(ea.JOINT_NAMES)}
    glob = {b: np.swapaxes(g[:, names[b]], -1, -2) for pair in EXPMAP_BONES.values() for b in pair}
    out = _out(glob, EXPMAP_BONES, yaw, lambda q: _slerp_resample(q, ea.FPS_8ACTION))
    # each bone's rest direction: the offset of the joint it ends at
    out["rest"] = _rests({leaf: skel.offsets[names[end]] for leaf, end in
                          (("left_wrist", "lhand"), ("right_wrist", "rhand"), ("left_foot", "ltoes"),
                           ("right_foot", "rtoes"))})
    return out


def deepmimic_globals(path: Path, fps: float, yaw: float) -> dict[str, np.ndarray]:
    """A DeepMimic motion: the head only (its wrists are fixed joints, see the module), the neck
    joint's global rotation on the chest's, resampled as `retarget.deepmimic` resamples the
    positions (the stated durations scaled to the decided `fps`, onto a 20 fps grid); "rest":
    exact (+90° about Y: the character faces +X)."""
    from interplay.motion.retarget import deepmimic as dm
    char = dm.Character.read(dm.find_character(path))
    values, _ = dm.read_frames(path)
    t, col = len(values), 1
    glob: list[np.ndarray] = []
    for kind, parent in zip(char.kinds, char.parents):
        if kind == "none":
            local, col = quat_to_matrix(values[:, col + 3:col + 7]), col + 7
        elif kind == "spherical":
            local, col = quat_to_matrix(values[:, col:col + 4]), col + 4
        elif kind == "revolute":
            local, col = np.broadcast_to(np.eye(3), (t, 3, 3)), col + 1    # knees, elbows: not read
        else:
            local = np.broadcast_to(np.eye(3), (t, 3, 3))
        glob.append(local if parent < 0 else glob[parent] @ local)
    durations = values[:-1, 0]
    stated = float(1.0 / np.median(durations))
    stated = float(round(stated)) if abs(stated - round(stated)) < 0.005 * stated else round(stated, 3)
    times = np.concatenate([[0.0], np.cumsum(durations)]) * (stated / fps)
    grid = times[0] + np.arange(int(np.floor((times[-1] - times[0]) * sk.FPS + 1e-6)) + 1) / sk.FPS
    hi = np.clip(np.searchsorted(times, grid, side="right"), 1, len(times) - 1)
    pos = hi - 1 + ((grid - times[hi - 1]) / np.maximum(times[hi] - times[hi - 1], 1e-12)).clip(0.0, 1.0)
    names = {n: i for i, n in enumerate(char.names)}
    out = _out({b: glob[names[b]] for b in ("neck", "chest")}, {"head": ("neck", "chest")}, yaw,
               lambda q: _slerp_at(q, pos))
    out["rest"] = np.full((len(LEAF_NAMES), 3, 3), np.nan)
    out["rest"][0] = yaw_matrix(np.pi / 2)
    return out
