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

Read by `interplay.motion.captured_leaves`. Carried today: the Daz-named CMU BVH family
(cmu-bvh: 54 of its 56 clips, the other two are Acclaim-named; cmu-salsa: both dancers).
The same pipeline as the positions is replayed on the rotations: the converter's lead-in cut,
the capture rate's resampling to 20 fps (slerp at the very times `kinematics.resample` takes),
the canonical yaw. Each hand's rest correction maps the rig's rest hand (along the template's
rest forearm) onto the source's rest hand (wrist → middle finger); the head needs none (both
rests face +Z, Y up). The build reports, per source, how far the carried hands and heads are
from the library's own bones (a check that frames and axes line up).

    interplay data leaves                      # every carried source (~20 s)
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
# Daz bones whose global rotations are the leaves', and each hand's rest direction's child.
DAZ_BONES = {"head": "head", "left_wrist": "lHand", "right_wrist": "rHand"}
DAZ_FINGER = {"left_wrist": "lMid1", "right_wrist": "rMid1"}
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


def daz_world(path: Path, cut: int, fps: float, yaw: float) -> np.ndarray | None:
    """The head's and hands' world orientations (T, 3, 4) of a Daz-named CMU BVH, replayed
    through the positions' pipeline (lead-in `cut`, capture rate `fps` → 20, canonical
    `yaw`); None for a file of another family."""
    from interplay.motion.formats.bvh import read_bvh
    from interplay.motion.retarget.cmu_daz import acclaim_names, skeleton_family
    bvh = acclaim_names(read_bvh(path))
    if skeleton_family(bvh) != "daz":
        return None
    rot, _ = bvh.local_transforms()
    parents = list(bvh.parents)
    _, glob = forward_kinematics(rot[cut:], np.zeros((len(rot) - cut, 3)), bvh.offsets, parents)
    rest = replace(bvh, motion=np.zeros((1, bvh.motion.shape[1]))).named_positions()
    out = []
    for leaf in LEAF_NAMES:
        g = glob[:, bvh.index(DAZ_BONES[leaf])]
        if leaf in DAZ_FINGER:                                  # rest hand: rig's → source's
            src = rest[DAZ_FINGER[leaf]][0] - rest[DAZ_BONES[leaf]][0]
            g = g @ rotation_between(sk.REST_OFFSETS[J[leaf]], src)
        out.append(matrix_to_quat(yaw_matrix(yaw) @ g))
    q = np.stack(out, axis=1)
    return _slerp_resample(q, fps)


def _carry(clip: Clip, src: Path) -> list[np.ndarray | None]:
    """Per person of a library clip, its leaves' world orientations, or None."""
    meta = clip.meta
    if clip.source == "cmu-bvh":
        files = [meta["file"]]
    elif clip.source == "cmu-salsa":
        files = list(meta["files"])
    else:
        return [None] * len(clip.people)
    out: list[np.ndarray | None] = []
    for k, rel in enumerate(files):
        q = daz_world(src / rel, int(meta["lead_in_frames"]), float(meta["native_fps"]),
                      float(meta["canonical"]["yaw"]))
        if q is not None and len(q) != clip.people[k].shape[0]:
            raise ValueError(f"{clip.id}: {len(q)} carried frames for {clip.people[k].shape[0]} in the library")
        out.append(q)
    return out


def agreement(joints: np.ndarray, q: np.ndarray) -> dict[str, float]:
    """Median angles (deg) between a carried leaf and the library's own bone into it: the
    leaf's orientation applied to that bone's rest direction (neck → head, elbow → wrist)
    against the bone itself. They are different bones (a head nods on its neck, a hand bends
    on its forearm), so some degrees are normal; a wrong frame or axis shows as tens more."""
    m = quat_to_matrix(q.astype(np.float64))
    out = {}
    for i, leaf in enumerate(LEAF_NAMES):
        along = sk.REST_OFFSETS[J[leaf]]
        d = m[:, i] @ (along / np.linalg.norm(along))
        bone = joints[:, J[leaf]] - joints[:, sk.PARENTS[J[leaf]]]
        bone = bone / np.linalg.norm(bone, axis=-1, keepdims=True)
        out[leaf] = float(np.median(np.degrees(np.arccos(np.clip(np.sum(d * bone, -1), -1, 1)))))
    return out


def build_leaves(source: str, src: Path, out: Path) -> dict:
    """Writes `<out>/leaves/<source>.npz` for the library's clips of a source; returns a
    summary (clips and person-frames carried, median agreement per leaf)."""
    clips = [c for c in load_clips(out) if c.source == source]
    quats, index, agree = [], [], []
    start = 0
    for clip in clips:
        for k, q in enumerate(_carry(clip, src)):
            if q is None:
                continue
            index.append({"id": clip.id, "person": k, "start": start, "frames": len(q)})
            quats.append(q.astype(np.float16))
            agree.append(agreement(np.asarray(clip.people[k], np.float64), q))
            start += len(q)
    if not quats:
        raise ValueError(f"{source}: no clip carries its leaves")
    leaves_file(source, out).parent.mkdir(parents=True, exist_ok=True)
    np.savez_compressed(leaves_file(source, out), quats=np.concatenate(quats),
                        index=np.array(json.dumps(index)))
    return {"source": source, "people": len(index), "frames": start,
            "agreement_deg": {leaf: round(float(np.median([a[leaf] for a in agree])), 1)
                              for leaf in LEAF_NAMES}}


CARRIED = ("cmu-bvh", "cmu-salsa")


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
        print(f"{source:10s} {summary['people']:3d} people {summary['frames']:6d} frames "
              f"{time.time() - t0:5.1f} s; median angle to the library's bones (deg): "
              f"{summary['agreement_deg']}", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
