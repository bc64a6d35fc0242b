"""`interplay data leaves`: the captures' own head and hand orientations, from the raw files in
../shared/data, into side files next to the processed library: models/data/leaves/<source>.npz.

The library's joint positions (models/data/<source>.npz) are not touched: every behaviour
fixture and evaluation number depends on them, so the orientations go into their own file per
source (the same licence as the source's positions), keyed by clip id and person, and frames
that match the library's clip frame for frame. The file holds

    quats  (M, 5, 4) float16   world orientations (w, x, y, z) of the head, left and right
                               hand, left and right toe (LEAF_NAMES; NaN: not carried),
                               in the library's canonical frame (the clip's own yaw
                               applied, Y up), every person-frame of the source's carried
                               clips concatenated; the rest frame is the rig's (`motion/rig`):
                               identity = a T-pose facing +Z, the hand along the forearm
    index  JSON text           [{"id", "person", "start", "frames"}] into quats

Read by `interplay.motion.captured_leaves`. Carried: every person of every captured source
(1064 people, 113,521 frames; the composed pairs are no captures): cmu-bvh (54 Daz- and 2
Acclaim-named files), cmu-salsa (both dancers), bandai-namco (593), hdm05 (287), cmu-asfamc
(4), cmu-iclone (38), cmu-8action (38) and deepmimic (20, the head only: its humanoid's wrists
are fixed joints, so no file turns a hand; a leaf not carried is stored as NaN). Each
format's bones are read by `leaves_read.py`, which replays the positions' own pipeline on
the rotations (the converter's lead-in or T-pose cut, the capture rate's resampling to 20 fps
by slerp at the very times the positions take, the canonical yaw). Toes (the rig's "left_foot" / "right_foot", the ball of the foot; `rig/leaves.py` keeps them off
the floor on top) are carried where the file has a toe bone: Acclaim's ltoes / rtoes (HDM05,
cmu-asfamc, cmu-bvh 16_01/02; in the 8-action files the toe bone's turn sits at the "lfoot"
joint), Bandai's Toes_L/_R and iClone's ToeBase: 962 people. Not carried: the Daz files
(cmu-bvh, salsa) end the leg at the foot and DeepMimic's humanoid at the ankle. A toe's
correction is measured on planted feet for every source (`toe_correction`). The exports do not
use them yet (`captured_leaves.EXPORTED`): a carried toe sits 21–28° (median, planted feet) off
the rig's own ankle frame, a kink at the ball, and some captures flip a toe 176° (HDM05's bd
kicks); a toe's flex about the rig's foot would be the part worth carrying.

Rest correction C per leaf (the world orientation stored is the file's leaf frame times C):
- Daz, Acclaim (HDM05, cmu-asfamc, cmu-bvh's Acclaim-named files, the 8-action exp-maps) and
  DeepMimic rest as the rig does, or as it does turned (DeepMimic faces +X: C is +90° about
  Y): the head needs none, each hand the turn from the rig's rest hand (along the template's
  rest forearm) onto the file's, exact, per person.
- Bandai Namco's rest figure lies along +X and iClone's CC_Base bones have axes of their own,
  so C is measured per source,
  as the SVD projection of a mean rotation: a hand's from the file's forearm frame to the
  rig's (`solve_rig` on the library's joints) over the first RESTS people, so a hand at rest
  on its forearm in the file is at rest on its forearm in the rig (Bandai: 3° and 174° for
  the left and right hands: the right arm's X points the other way); the head's from the
  file's head frame to the body's facing, upright, over RESTS plain walks ("a person walks": a
  walker looks ahead and level; the head's turn on the neck would not do, the figure's neck
  leans otherwise than the rig's and tilted every face 33° up).
The build reports how far the carried leaves are from the library's own joints (`agreement`:
medians 5–16° between the face and the body's facing, 9–32° between a hand and its forearm:
CMU's Acclaim-based hands and iClone's left bend the most).

    interplay data leaves                      # every carried source (~45 s)
    interplay data leaves --only cmu-salsa
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

from interplay.data.leaves_read import acclaim_globals, bvh_globals, deepmimic_globals, expmap_globals
from interplay.motion import skeleton as sk
from interplay.motion.captured_leaves import LEAF_NAMES, TOES, leaves_file
from interplay.motion.clip import DATA_DIR, Clip, load_clips
from interplay.motion.rotations import matrix_to_quat, quat_to_matrix, yaw_matrix

REPO = Path(__file__).resolve().parents[3]
DEFAULT_SOURCE = REPO.parent / "shared" / "data"
RESTS = 24                       # people per source the rest correction is measured on
J = sk.JOINT_INDEX


def rest_corrections(samples: list[tuple[dict[str, np.ndarray], np.ndarray]]) -> dict[str, np.ndarray]:
    """Per leaf, C (3, 3) over `samples` (a person's `bvh_globals`, their library joints), the
    SVD projection of a mean rotation: for a hand, from the file's parent bone frame (the
    forearm) to the rig's (`solve_rig`), so the hand keeps its bend on the forearm; for the
    head, from the file's head frame to the body's facing, upright (a figure's neck may lean
    otherwise than the rig's, so the head's turn on it would tilt the face: Bandai's by 33°),
    so the face looks level and ahead of the body on average."""
    from interplay.motion.kinematics import facing_angle
    from interplay.motion.rig import global_rotations, solve_rig
    sums = {leaf: np.zeros((3, 3)) for leaf in LEAF_NAMES if leaf in samples[0][0]}
    for globs, joints in samples:
        rig = global_rotations(solve_rig(joints))
        for leaf in sums:
            if leaf == "head":
                sums[leaf] += np.einsum("tji,tjk->ik", globs[leaf][:, 0], yaw_matrix(facing_angle(joints)))
            else:
                sums[leaf] += np.einsum("tji,tjk->ik", globs[leaf][:, 1], rig[:, sk.PARENTS[J[leaf]]])
    out = {}
    for leaf, m in sums.items():
        u, _, vt = np.linalg.svd(m)
        out[leaf] = u @ np.diag([1.0, 1.0, np.linalg.det(u @ vt)]) @ vt
    return out


def toe_correction(toe: str, samples: list[tuple[dict[str, np.ndarray], np.ndarray]]) -> np.ndarray:
    """A toe's correction C (3, 3), for every source with toes: measured on its foot's frame
    (`rest_corrections`) a toe bone need not continue its foot at rest (Bandai's has no length,
    iClone's bends up), which left planted toes 21–25° off the foot's heading, and the exact
    rest corrections left Acclaim's rolled 11–22°; so it is measured where the foot is planted
    (the ball within 4 cm of the floor), where a toe lies flat along the foot's heading: the
    SVD projection of the mean rotation from the file's toe frame onto that flat frame (the
    rig's rest toe: ahead +Z, up +Y), as the head's onto the facing."""
    from interplay.motion.kinematics import floor_height
    ankle = J[toe.replace("foot", "ankle")]
    total = np.zeros((3, 3))
    for globs, joints in samples:
        planted = joints[:, J[toe], 1] - floor_height([joints]) < 0.04
        ahead = (joints[planted, J[toe]] - joints[planted, ankle]) * [1.0, 0.0, 1.0]
        ahead /= np.maximum(np.linalg.norm(ahead, axis=-1, keepdims=True), 1e-9)
        up = np.broadcast_to([0.0, 1.0, 0.0], ahead.shape)
        flat = np.stack([np.cross(up, ahead), up, ahead], axis=-1)         # columns x, y, z
        total += np.einsum("tji,tjk->ik", globs[toe][planted, 0], flat)
    u, _, vt = np.linalg.svd(total)
    return u @ np.diag([1.0, 1.0, np.linalg.det(u @ vt)]) @ vt


def _carry(clip: Clip, src: Path) -> list[dict[str, np.ndarray] | None]:
    """Per person of a library clip, its leaves' world rotations (`leaves_read`), or None."""
    meta = clip.meta
    yaw = float(meta.get("canonical", {}).get("yaw", 0.0))
    out: list[dict[str, np.ndarray] | None] = []
    if clip.source == "hdm05":
        out.append(acclaim_globals(src / meta["file"], src / "hdm05" / "asf" / f"HDM_{meta['actor']}.asf",
                                   float(meta["source_fps"]), yaw))
    elif clip.source == "cmu-asfamc":
        from interplay.motion.retarget.cmu_acclaim import find_asf
        out.append(acclaim_globals(src / meta["file"], find_asf(src / meta["file"]),
                                   float(meta["source_fps"]), yaw))
    elif clip.source in ("cmu-bvh", "bandai-namco", "cmu-salsa", "cmu-iclone"):
        files = list(meta["files"]) if clip.source == "cmu-salsa" else [meta["file"]]
        cut = int(meta.get("tpose_frames_dropped", meta.get("lead_in_frames", 0)))
        for rel in files:
            out.append(bvh_globals(src / rel, cut, float(meta["native_fps"]), yaw))
    elif clip.source == "cmu-8action":
        out.append(expmap_globals(src / meta["file"], yaw))
    elif clip.source == "deepmimic":
        out.append(deepmimic_globals(src / meta["file"], float(meta["source_fps"]), yaw))
    else:
        return [None] * len(clip.people)
    for k, g in enumerate(out):
        if g is not None and len(g["head"]) != clip.people[k].shape[0]:
            raise ValueError(f"{clip.id}: {len(g['head'])} carried frames for {clip.people[k].shape[0]} "
                             f"in the library")
    return out


def agreement(joints: np.ndarray, q: np.ndarray) -> dict[str, float]:
    """Median angles (deg) between carried leaves q (T, 5, 4) and the library's own joints
    (T, 22, 3): the head's face (its forward axis) against the body's facing, both on the
    floor (a head turns on its body, but a wrong yaw or axis shows at once); each hand's
    direction (its orientation applied to the rest forearm) against the forearm itself (they
    are different bones, a hand bends on its forearm: some degrees are normal)."""
    from interplay.motion.kinematics import facing_direction
    m = quat_to_matrix(np.nan_to_num(q.astype(np.float64), nan=1.0))
    face = m[:, 0, :, 2] * [1.0, 0.0, 1.0]
    body = facing_direction(joints) * [1.0, 0.0, 1.0]
    cos = np.sum(face * body, -1) / np.maximum(np.linalg.norm(face, axis=-1) * np.linalg.norm(body, axis=-1), 1e-9)
    out = {"head": float(np.median(np.degrees(np.arccos(np.clip(cos, -1, 1)))))}
    for i, leaf in enumerate(LEAF_NAMES[1:3], start=1):           # the hands (not the toes)
        if not np.isfinite(q[:, i].astype(np.float64)).all():    # not carried (DeepMimic's)
            continue
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
    exact = all("rest" in g for _, _, g in people)
    if not exact:
        # The head's from plain walks (a person walking looks ahead, not down at a bow or
        # at a waving hand); the hands' from the first people.
        walks = [p for p in people if p[0].prompt == "a person walks"] or people
        fix = rest_corrections([(g, np.asarray(clip.people[k], np.float64)) for clip, k, g in people[:RESTS]])
        fix["head"] = rest_corrections([(g, np.asarray(clip.people[k], np.float64))
                                        for clip, k, g in walks[:RESTS]])["head"]
    # Toes measured on planted feet for every source (`toe_correction`): the exact corrections
    # left Acclaim's planted toes rolled 11–22° on their feet, the foot's frame Bandai's and
    # iClone's 21–25° off their heading.
    with_toes = [(g, np.asarray(clip.people[k], np.float64)) for clip, k, g in people if TOES[0] in g]
    toes = {toe: toe_correction(toe, with_toes[:RESTS]) for toe in TOES} if with_toes else {}
    quats, index, agree = [], [], []
    start = 0
    for clip, k, g in people:
        rest = {**(dict(zip(LEAF_NAMES, g["rest"])) if exact else fix), **toes}   # exact: per file
        q = np.full((len(g["head"]), len(LEAF_NAMES), 4), np.nan)      # NaN: a leaf not carried
        for i, leaf in enumerate(LEAF_NAMES):
            if leaf in g and leaf in rest:
                q[:, i] = matrix_to_quat(g[leaf][:, 0] @ rest[leaf])
        index.append({"id": clip.id, "person": k, "start": start, "frames": len(q)})
        quats.append(q.astype(np.float16))
        agree.append(agreement(np.asarray(clip.people[k], np.float64), q))
        start += len(q)
    if exact:
        fix = dict(zip(LEAF_NAMES, people[0][2]["rest"]))
    leaves_file(source, out).parent.mkdir(parents=True, exist_ok=True)
    np.savez_compressed(leaves_file(source, out), quats=np.concatenate(quats),
                        index=np.array(json.dumps(index)))
    turn = {leaf: round(float(np.degrees(np.arccos(np.clip((np.trace(c) - 1) / 2, -1, 1)))), 1)
            for leaf, c in fix.items() if np.isfinite(c).all()}
    fix = {**fix, **toes}
    carried_toes = sum(int(np.isfinite(q[:, 3:].astype(np.float64)).all(axis=(1, 2)).any()) for q in quats)
    return {"source": source, "people": len(index), "toes": carried_toes, "clips": len({row["id"] for row in index}),
            "frames": start, "rest_correction_deg": turn,
            "agreement_deg": {leaf: round(float(np.median([a[leaf] for a in agree if leaf in a])), 1)
                              for leaf in LEAF_NAMES if any(leaf in a for a in agree)}}


CARRIED = ("cmu-bvh", "cmu-salsa", "bandai-namco", "hdm05", "cmu-asfamc", "cmu-iclone", "cmu-8action",
           "deepmimic")


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
        print(f"{source:12s} {summary['people']:3d} people ({summary['toes']} with toes) {summary['frames']:6d} frames "
              f"{time.time() - t0:5.1f} s; rest correction (deg) {summary['rest_correction_deg']}; "
              f"median angle to the library's bones (deg) {summary['agreement_deg']}", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
