"""`interplay data leaves`: the captures' own head and hand orientations, from the raw files in
../shared/data, into side files next to the processed library: models/data/leaves/<source>.npz.

The library's joint positions (models/data/<source>.npz) are not touched: every behaviour
fixture and evaluation number depends on them, so the orientations go into their own file per
source (the same licence as the source's positions), keyed by clip id and person, and frames
that match the library's clip frame for frame. The file holds

    quats  (M, 3, 4) float16   world orientations (w, x, y, z) of the head, left and right
                               hand, in the library's canonical frame (the clip's own yaw
                               applied, Y up), every person-frame of the source's carried
                               clips concatenated; the rest frame is the rig's (`motion/rig`):
                               identity = a T-pose facing +Z, the hand along the forearm
    index  JSON text           [{"id", "person", "start", "frames"}] into quats

Read by `interplay.motion.captured_leaves`. Carried today (962 people, 98,204 frames): the
BVH sources whose files name a head and hands, cmu-bvh (the 54 Daz-named of its 56 clips; the
other two are Acclaim-named), cmu-salsa (both dancers), bandai-namco (593 clips), and HDM05's
ASF/AMC (287; head, lhand, rhand). Not yet: cmu-asfamc (4), cmu-iclone (38), cmu-8action
(exp-map text) and DeepMimic. The positions' own pipeline is replayed on the rotations: the
converter's lead-in cut, the capture rate's resampling to 20 fps (slerp at the very times
`kinematics.resample` takes), the canonical yaw.

Rest correction C per leaf (the world orientation stored is the file's leaf frame times C):
- Daz and Acclaim (HDM05) rest as the rig does (a T-pose facing +Z, Y up, left at +X): the
  head needs none, each hand the turn from the rig's rest hand (along the template's rest
  forearm) onto the file's (Daz: wrist → middle finger; Acclaim: the hand bone), exact.
- Bandai Namco's rest figure lies along +X (every bone along its own X), so C is measured,
  as the SVD projection of a mean rotation: a hand's from the file's forearm frame to the
  rig's (`solve_rig` on the library's joints) over the first RESTS people, so a hand at rest
  on its forearm in the file is at rest on its forearm in the rig (3° and 174° for the left
  and right hands: the right arm's X points the other way); the head's from the file's head
  frame to the body's facing, upright, over RESTS plain walks ("a person walks": a walker
  looks ahead and level; the head's turn on the neck would not do, the figure's neck leans
  otherwise than the rig's and tilted every face 33° up).
The build reports how far the carried leaves are from the library's own joints (`agreement`:
medians 5–16° between the face and the body's facing, 9–25° between a hand and its forearm).

    interplay data leaves                      # every carried source (~25 s)
    interplay data leaves --only cmu-salsa
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.captured_leaves import LEAF_NAMES, leaves_file
from interplay.motion.clip import DATA_DIR, Clip, load_clips
from interplay.motion.kinematics import forward_kinematics
from interplay.motion.rotations import matrix_to_quat, quat_to_matrix, rotation_between, yaw_matrix

REPO = Path(__file__).resolve().parents[3]
DEFAULT_SOURCE = REPO.parent / "shared" / "data"
# Per BVH family, each leaf's bone and its parent bone's (the rig's parent joint's match).
BONES: dict[str, dict[str, tuple[str, str]]] = {
    "daz": {"head": ("head", "neck"), "left_wrist": ("lHand", "lForeArm"),
            "right_wrist": ("rHand", "rForeArm")},
    "bandai-namco": {"head": ("Head", "Neck"), "left_wrist": ("Hand_L", "LowerArm_L"),
                     "right_wrist": ("Hand_R", "LowerArm_R")},
}
ACCLAIM_BONES: dict[str, tuple[str, str]] = {
    "head": ("head", "upperneck"), "left_wrist": ("lhand", "lradius"), "right_wrist": ("rhand", "rradius")}
RESTS = 24                       # people per source the rest correction is measured on
J = sk.JOINT_INDEX


def _slerp_resample(q: np.ndarray, src_fps: float, dst_fps: float = sk.FPS) -> np.ndarray:
    """Unit quaternions (n, ..., 4) at src_fps → dst_fps at the times `kinematics.resample`
    takes (so frame i lands on the positions' frame i), by slerp between neighbours."""
    from interplay.motion.rig import slerp
    n = q.shape[0]
    if n < 2 or abs(src_fps - dst_fps) < 1e-9:
        return q.copy()
    duration = (n - 1) / src_fps
    pos = np.arange(int(np.floor(duration * dst_fps + 1e-6)) + 1) / dst_fps * src_fps
    lo = np.clip(np.floor(pos).astype(int), 0, n - 1)
    hi = np.clip(lo + 1, 0, n - 1)
    w = np.broadcast_to((pos - lo).reshape((-1,) + (1,) * (q.ndim - 2)), q[lo].shape[:-1])
    return slerp(q[lo], q[hi], w)


def bvh_globals(path: Path, cut: int, fps: float, yaw: float) -> dict[str, np.ndarray] | None:
    """Per leaf, the world rotations (T, 2, 3, 3) of its bone and its parent bone in a
    Daz-named CMU or a Bandai Namco BVH (both Y up), replayed through the positions'
    pipeline (lead-in `cut`, capture rate `fps` → 20, canonical `yaw`), and for Daz "rest":
    the exact rest corrections (3, 3, 3) of the head and hands; None for a file of another
    family."""
    from interplay.motion.formats.bvh import read_bvh
    from interplay.motion.retarget.cmu_daz import acclaim_names
    bvh = acclaim_names(read_bvh(path))
    family = next((f for f, bones in BONES.items()
                   if all(b in bvh.names for pair in bones.values() for b in pair)), None)
    if family is None:
        return None
    rot, _ = bvh.local_transforms()
    _, glob = forward_kinematics(rot[cut:], np.zeros((len(rot) - cut, 3)), bvh.offsets, list(bvh.parents))
    out = {}
    for leaf, pair in BONES[family].items():
        g = yaw_matrix(yaw) @ glob[:, [bvh.index(b) for b in pair]]
        out[leaf] = quat_to_matrix(_slerp_resample(matrix_to_quat(g), fps))
    if family == "daz":                          # rests as the rig: exact corrections (docstring)
        rest = replace(bvh, motion=np.zeros((1, bvh.motion.shape[1]))).named_positions()
        out["rest"] = np.stack([np.eye(3)] + [
            rotation_between(sk.REST_OFFSETS[J[leaf]], rest[finger][0] - rest[hand][0])
            for leaf, hand, finger in (("left_wrist", "lHand", "lMid1"), ("right_wrist", "rHand", "rMid1"))])
    return out


def acclaim_globals(amc_path: Path, asf_path: Path, fps: float, yaw: float) -> dict[str, np.ndarray]:
    """Per leaf, the world rotations (T, 2, 3, 3) of its Acclaim bone and its parent bone
    (head on upperneck, lhand / rhand on lradius / rradius; the bones' global rotations as
    `formats.acclaim.forward_kinematics` composes them, L = C · M · C⁻¹), resampled from
    `fps` to 20 and turned by the canonical `yaw`, and "rest": the exact rest corrections
    (Acclaim rests as the rig: a T-pose facing +Z, Y up, left at +X; each hand's rest
    direction is its hand bone's)."""
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
    out = {}
    for leaf, pair in ACCLAIM_BONES.items():
        g = yaw_matrix(yaw) @ np.stack([glob[b] for b in pair], axis=1)
        out[leaf] = quat_to_matrix(_slerp_resample(matrix_to_quat(g), fps))
    out["rest"] = np.stack([np.eye(3)] + [
        rotation_between(sk.REST_OFFSETS[J[leaf]], asf.bones[ACCLAIM_BONES[leaf][0]].direction)
        for leaf in ("left_wrist", "right_wrist")])
    return out


def rest_corrections(samples: list[tuple[dict[str, np.ndarray], np.ndarray]]) -> dict[str, np.ndarray]:
    """Per leaf, C (3, 3) over `samples` (a person's `bvh_globals`, their library joints), the
    SVD projection of a mean rotation: for a hand, from the file's parent bone frame (the
    forearm) to the rig's (`solve_rig`), so the hand keeps its bend on the forearm; for the
    head, from the file's head frame to the body's facing, upright (a figure's neck may lean
    otherwise than the rig's, so the head's turn on it would tilt the face: Bandai's by 33°),
    so the face looks level and ahead of the body on average."""
    from interplay.motion.kinematics import facing_angle
    from interplay.motion.rig import global_rotations, solve_rig
    sums = {leaf: np.zeros((3, 3)) for leaf in LEAF_NAMES}
    for globs, joints in samples:
        rig = global_rotations(solve_rig(joints))
        for leaf in LEAF_NAMES:
            if leaf == "head":
                sums[leaf] += np.einsum("tji,tjk->ik", globs[leaf][:, 0], yaw_matrix(facing_angle(joints)))
            else:
                sums[leaf] += np.einsum("tji,tjk->ik", globs[leaf][:, 1], rig[:, sk.PARENTS[J[leaf]]])
    out = {}
    for leaf, m in sums.items():
        u, _, vt = np.linalg.svd(m)
        out[leaf] = u @ np.diag([1.0, 1.0, np.linalg.det(u @ vt)]) @ vt
    return out


def _carry(clip: Clip, src: Path) -> list[dict[str, np.ndarray] | None]:
    """Per person of a library clip, its leaves' `bvh_globals` / `acclaim_globals`, or None."""
    meta = clip.meta
    yaw = float(meta.get("canonical", {}).get("yaw", 0.0))
    out: list[dict[str, np.ndarray] | None] = []
    if clip.source == "hdm05":
        out.append(acclaim_globals(src / meta["file"], src / "hdm05" / "asf" / f"HDM_{meta['actor']}.asf",
                                   float(meta["source_fps"]), yaw))
    elif clip.source in ("cmu-bvh", "bandai-namco", "cmu-salsa"):
        files = list(meta["files"]) if clip.source == "cmu-salsa" else [meta["file"]]
        for rel in files:
            out.append(bvh_globals(src / rel, int(meta.get("lead_in_frames", 0)),
                                   float(meta["native_fps"]), yaw))
    else:
        return [None] * len(clip.people)
    for k, g in enumerate(out):
        if g is not None and len(g["head"]) != clip.people[k].shape[0]:
            raise ValueError(f"{clip.id}: {len(g['head'])} carried frames for {clip.people[k].shape[0]} "
                             f"in the library")
    return out


def agreement(joints: np.ndarray, q: np.ndarray) -> dict[str, float]:
    """Median angles (deg) between carried leaves q (T, 3, 4) and the library's own joints
    (T, 22, 3): the head's face (its forward axis) against the body's facing, both on the
    floor (a head turns on its body, but a wrong yaw or axis shows at once); each hand's
    direction (its orientation applied to the rest forearm) against the forearm itself (they
    are different bones, a hand bends on its forearm: some degrees are normal)."""
    from interplay.motion.kinematics import facing_direction
    m = quat_to_matrix(q.astype(np.float64))
    face = m[:, 0, :, 2] * [1.0, 0.0, 1.0]
    body = facing_direction(joints) * [1.0, 0.0, 1.0]
    cos = np.sum(face * body, -1) / np.maximum(np.linalg.norm(face, axis=-1) * np.linalg.norm(body, axis=-1), 1e-9)
    out = {"head": float(np.median(np.degrees(np.arccos(np.clip(cos, -1, 1)))))}
    for i, leaf in enumerate(LEAF_NAMES[1:], start=1):
        along = sk.REST_OFFSETS[J[leaf]]
        d = m[:, i] @ (along / np.linalg.norm(along))
        bone = joints[:, J[leaf]] - joints[:, sk.PARENTS[J[leaf]]]
        bone = bone / np.linalg.norm(bone, axis=-1, keepdims=True)
        out[leaf] = float(np.median(np.degrees(np.arccos(np.clip(np.sum(d * bone, -1), -1, 1)))))
    return out


def build_leaves(source: str, src: Path, out: Path) -> dict:
    """Writes `<out>/leaves/<source>.npz` for the library's clips of a source; returns a
    summary (people and person-frames carried, median agreement per leaf)."""
    clips = [c for c in load_clips(out) if c.source == source]
    people = [(clip, k, g) for clip in clips for k, g in enumerate(_carry(clip, src)) if g is not None]
    if not people:
        raise ValueError(f"{source}: no clip carries its leaves")
    if "rest" in people[0][2]:
        fix = dict(zip(LEAF_NAMES, people[0][2]["rest"]))
    else:
        # The head's from plain walks (a person walking looks ahead, not down at a bow or
        # at a waving hand); the hands' from the first people.
        walks = [p for p in people if p[0].prompt == "a person walks"] or people
        fix = rest_corrections([(g, np.asarray(clip.people[k], np.float64)) for clip, k, g in people[:RESTS]])
        fix["head"] = rest_corrections([(g, np.asarray(clip.people[k], np.float64))
                                        for clip, k, g in walks[:RESTS]])["head"]
    quats, index, agree = [], [], []
    start = 0
    for clip, k, g in people:
        q = np.stack([matrix_to_quat(g[leaf][:, 0] @ fix[leaf]) for leaf in LEAF_NAMES], axis=1)
        index.append({"id": clip.id, "person": k, "start": start, "frames": len(q)})
        quats.append(q.astype(np.float16))
        agree.append(agreement(np.asarray(clip.people[k], np.float64), q))
        start += len(q)
    leaves_file(source, out).parent.mkdir(parents=True, exist_ok=True)
    np.savez_compressed(leaves_file(source, out), quats=np.concatenate(quats),
                        index=np.array(json.dumps(index)))
    turn = {leaf: round(float(np.degrees(np.arccos(np.clip((np.trace(c) - 1) / 2, -1, 1)))), 1)
            for leaf, c in fix.items()}
    return {"source": source, "people": len(index), "frames": start, "rest_correction_deg": turn,
            "agreement_deg": {leaf: round(float(np.median([a[leaf] for a in agree])), 1)
                              for leaf in LEAF_NAMES}}


CARRIED = ("cmu-bvh", "cmu-salsa", "bandai-namco", "hdm05")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="interplay data leaves", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--source", type=Path, default=DEFAULT_SOURCE, help="raw data folder (../shared/data)")
    ap.add_argument("--out", type=Path, default=DATA_DIR, help="the processed library (models/data)")
    ap.add_argument("--only", nargs="*", choices=CARRIED, help="only these sources")
    args = ap.parse_args(argv)
    if not args.source.is_dir():
        print(f"error: raw data folder {args.source} not found (pass --source)", file=sys.stderr)
        return 2
    for source in args.only or CARRIED:
        t0 = time.time()
        summary = build_leaves(source, args.source, args.out)
        print(f"{source:12s} {summary['people']:3d} people {summary['frames']:6d} frames "
              f"{time.time() - t0:5.1f} s; rest correction (deg) {summary['rest_correction_deg']}; "
              f"median angle to the library's bones (deg) {summary['agreement_deg']}", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
