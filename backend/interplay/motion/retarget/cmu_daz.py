"""CMU captures as BVH (`cmu-bvh/`, `cmu-salsa/`) → the 22-joint SMPL layout.

Three skeleton families occur:
- Daz-friendly (cgspeed's conversion; 56 of the 58 cmu-bvh trials and all salsa files): hip,
  abdomen, chest, neck, head, eyes, l/rCollar, l/rShldr, l/rForeArm, l/rHand (+ fingers),
  l/rButtock, l/rThigh, l/rShin, l/rFoot with an End Site at the ball of the foot. Every file
  carries the very same figure (offsets identical to 1e-4 cm across all 84 files, salsa
  after × 128), so the subjects' own proportions are gone; only the motion is theirs.
- MotionBuilder names (una-dinosauria/cmu-mocap's conversion of every trial: Hips, LHipJoint,
  LeftUpLeg, LeftLeg, LeftFoot, LeftToeBase, LowerBack, Spine, Spine1, Neck, Neck1, Head,
  LeftShoulder, LeftArm, LeftForeArm, LeftHand …): the Acclaim bones renamed (`MB_NAMES`), read
  as the Acclaim-named family below.
- Acclaim names (16_01, 16_02): hip, l/rhipjoint, l/rfemur, l/rtibia, l/rfoot, l/rtoes,
  lowerback … head, l/rclavicle, l/rhumerus, l/rradius, l/rwrist …; a joint sits at the start
  of its Acclaim bone. The converter dropped the thorax bone (lowerneck and both clavicles
  have a zero OFFSET, so the shoulders sit on the thorax joint); we restore it as a copy of
  the upperback bone (in the five HDM05 ASF skeletons the two agree within 3 mm in length
  and 7° in direction).

Units (measured on the rest skeleton, toe tip to eye):
- cmu-bvh Daz files are centimetres: eye height 153 cm, leg 82 cm, walks at 0.6–1.8 m/s.
- salsa `_scaled` files are NOT metres: their offsets equal the cmu-bvh figure's × 1/128
  (to all 6 printed decimals), eye height 1.19 "m", i.e. 1.3 m tall dancers if read as
  metres. We undo it (× 1.28 → metres) so both datasets share one body size.
- Acclaim-named files use Acclaim's `length 0.45` unit: inches / 0.45 = 0.05644 m.

Joint map (Daz): proportions along the Daz torso (hip 0, abdomen 20.7, chest 32.4, neck
54.6 cm above the hip joint) match SMPL's (scaled to the same hip-to-neck length) when
spine1 = abdomen, spine2 = chest, spine3 = 20% of the way from chest to neck and the pelvis
halfway between hip and abdomen (SMPL's pelvis is ~9 cm above its hip joints; Daz's hip root
is 3 cm below its thighs). SMPL's collar sits a third of the way out to the shoulder; Daz's
lCollar starts 2.7 cm off the midline, so we take 25% of the way from lCollar to lShldr.
SMPL's head joint is between the skull base and the eyes: 70% Daz head + 30% eye midpoint.
The SMPL foot joint is the ball of the foot: lFoot's End Site.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np

from interplay.motion.formats.bvh import Bvh, read_bvh
from interplay.motion.retarget import JointSource, canonicalize, map_joints, to_smpl22
from interplay.motion.retarget.checks import record_fit
from interplay.motion.retarget.cmu_index import read_cmu_index
from interplay.motion.retarget.frame_rate import (
    SALSA_FPS,
    estimate_true_fps,
    lead_in_frames,
    motion_defects,
)

DAZ_MAP: dict[str, JointSource] = {
    "pelvis": (("hip", 0.5), ("abdomen", 0.5)),
    "left_hip": "lThigh", "right_hip": "rThigh",
    "spine1": "abdomen",
    "left_knee": "lShin", "right_knee": "rShin",
    "spine2": "chest",
    "left_ankle": "lFoot", "right_ankle": "rFoot",
    "spine3": (("chest", 0.8), ("neck", 0.2)),
    "left_foot": "lFoot_end", "right_foot": "rFoot_end",
    "neck": "neck",
    "left_collar": (("lCollar", 0.75), ("lShldr", 0.25)),
    "right_collar": (("rCollar", 0.75), ("rShldr", 0.25)),
    "head": (("head", 0.7), ("leftEye", 0.15), ("rightEye", 0.15)),
    "left_shoulder": "lShldr", "right_shoulder": "rShldr",
    "left_elbow": "lForeArm", "right_elbow": "rForeArm",
    "left_wrist": "lHand", "right_wrist": "rHand",
}

# Same choices as retarget/hdm05.py (there joints are bone ends, here bone starts).
ACCLAIM_MAP: dict[str, JointSource] = {
    "pelvis": "hip",
    "left_hip": "lfemur", "right_hip": "rfemur",
    "spine1": "upperback",
    "left_knee": "ltibia", "right_knee": "rtibia",
    "spine2": "thorax",
    "left_ankle": "lfoot", "right_ankle": "rfoot",
    "spine3": (("thorax", 0.5), ("lowerneck", 0.5)),
    "left_foot": "ltoes", "right_foot": "rtoes",
    "neck": "upperneck",
    "left_collar": (("lclavicle", 2 / 3), ("lhumerus", 1 / 3)),
    "right_collar": (("rclavicle", 2 / 3), ("rhumerus", 1 / 3)),
    "head": "head",
    "left_shoulder": "lhumerus", "right_shoulder": "rhumerus",
    "left_elbow": "lradius", "right_elbow": "rradius",
    "left_wrist": "lwrist", "right_wrist": "rwrist",
}

# The ASF → BVH conversion of the whole CMU database (una-dinosauria/cmu-mocap) names the
# Acclaim bones MotionBuilder-style; a joint still sits at the start of its Acclaim bone and the
# thorax is dropped the same way, so the files are read as Acclaim-named ones after renaming.
MB_NAMES: dict[str, str] = {
    "Hips": "hip", "LowerBack": "lowerback", "Spine": "upperback", "Spine1": "thorax",
    "Neck": "lowerneck", "Neck1": "upperneck", "Head": "head",
    **{f"{side}{mb}": f"{s}{acclaim}" for side, s in (("Left", "l"), ("Right", "r")) for mb, acclaim in (
        ("UpLeg", "femur"), ("Leg", "tibia"), ("Foot", "foot"), ("ToeBase", "toes"), ("Shoulder", "clavicle"),
        ("Arm", "humerus"), ("ForeArm", "radius"), ("Hand", "wrist"), ("FingerBase", "hand"),
        ("HandIndex1", "fingers"))},
    "LHipJoint": "lhipjoint", "RHipJoint": "rhipjoint", "LThumb": "lthumb", "RThumb": "rthumb",
}

CENTIMETRE = 0.01
SALSA_SCALED_UNIT = 1.28          # the salsa files are centimetres / 128
ACCLAIM_UNIT = 0.0254 / 0.45      # Acclaim `length 0.45`: inches / 0.45
BODY_HEIGHT_RANGE = (1.2, 2.2)    # plausible rest height (metres), to catch a wrong unit


def acclaim_names(bvh: Bvh) -> Bvh:
    """A MotionBuilder-named CMU conversion (`MB_NAMES`) renamed to Acclaim's bone names;
    any other file unchanged."""
    if not {"Hips", "LowerBack", "Spine1", "LeftUpLeg", "LeftLeg", "LeftToeBase"} <= set(bvh.names):
        return bvh
    return replace(bvh, names=tuple(MB_NAMES.get(n, n) for n in bvh.names))


def skeleton_family(bvh: Bvh) -> str:
    names = set(bvh.names)
    if {"hip", "abdomen", "chest", "lThigh", "lShin", "lFoot"} <= names:
        return "daz"
    if {"hip", "lowerback", "thorax", "lfemur", "ltibia", "ltoes"} <= names:
        return "acclaim"
    raise ValueError(f"not a CMU Daz-style or Acclaim-named BVH (joints: {', '.join(bvh.names[:8])} …)")


def rest_height(bvh: Bvh) -> float:
    """Top minus bottom of the rest skeleton (identity rotations), End Sites included, in file
    units: toe tip to eyes (Daz) or to the crown (Acclaim)."""
    rest = replace(bvh, motion=np.zeros((1, bvh.motion.shape[1])))
    y = rest.positions(include_end_sites=True)[0, :, 1]
    return float(y.max() - y.min())


def _repair_acclaim_thorax(bvh: Bvh) -> Bvh:
    offsets = bvh.offsets.copy()
    thorax = bvh.index("thorax")
    for j, p in enumerate(bvh.parents):
        if p == thorax and np.allclose(offsets[j], 0):
            offsets[j] = offsets[thorax]
    return replace(bvh, offsets=offsets)


def file_unit(bvh: Bvh, family: str) -> float:
    """Metres per file unit (see the module docstring for the evidence)."""
    if family == "acclaim":
        return ACCLAIM_UNIT
    return CENTIMETRE if rest_height(bvh) > 20 else SALSA_SCALED_UNIT


def _read(path: str | Path, scale: float | None) -> tuple[dict[str, np.ndarray], dict[str, JointSource], dict]:
    """A CMU BVH → named joint positions at its native frames (metres), its joint map, meta."""
    bvh = acclaim_names(read_bvh(Path(path)))
    family = skeleton_family(bvh)
    if family == "acclaim":
        bvh = _repair_acclaim_thorax(bvh)
    unit = file_unit(bvh, family) if scale is None else float(scale)
    height = rest_height(bvh) * unit
    if not BODY_HEIGHT_RANGE[0] <= height <= BODY_HEIGHT_RANGE[1]:
        raise ValueError(f"{path}: rest skeleton is {height:.2f} m tall at {unit} m per unit; "
                         f"pass scale= (metres per file unit)")
    named = {k: v * unit for k, v in bvh.named_positions(include_end_sites=True).items()}
    meta = {"skeleton": f"cmu-{family}", "header_fps": round(bvh.fps, 3), "frames_native": bvh.num_frames,
            "unit_m": unit, "rest_height_m": round(height, 3)}
    return named, (DAZ_MAP if family == "daz" else ACCLAIM_MAP), meta


def _retarget(named: dict[str, np.ndarray], joint_map: dict[str, JointSource], fps: float,
              meta: dict) -> tuple[np.ndarray, np.ndarray]:
    """Named native positions (lead-in already cut) → (fitted joints at 20 fps, offsets);
    records the fit error (raw mapped vs fitted joints) in meta."""
    fitted, offsets, raw = to_smpl22(named, joint_map, fps)
    record_fit(fitted, raw, meta)
    return fitted, offsets


def _rate(native: np.ndarray, fps: float | None, meta: dict) -> float:
    """Decide the capture rate (explicit, else estimated with the header as prior) and note
    the evidence and any defect in meta."""
    estimate, table = estimate_true_fps(native, prior=meta["header_fps"])
    meta["fps_estimate"] = estimate
    meta["fps_evidence"] = {f"{c:g}": {k: (round(v, 3) if isinstance(v, float) else v) for k, v in s.items()}
                            for c, s in table.items()}
    meta["defects"] = motion_defects(table)
    meta["native_fps"] = float(fps) if fps is not None else estimate
    return meta["native_fps"]


def load_cmu_bvh(path: str | Path, fps: float | None = None,
                 scale: float | None = None) -> tuple[np.ndarray, np.ndarray, dict]:
    """A cmu-bvh trial → (joints (T, 22, 3) at 20 fps, canonical: floor y=0, pelvis at the XZ
    origin facing +Z on frame 0; offsets (22, 3); meta). The converter's T-pose lead-in frames
    are cut. fps: the capture rate (default: estimate_true_fps with the header as prior, which
    turns 16_01/16_02's "30" into 120); scale: metres per file unit (default by family).
    meta["defects"] lists reasons the clip should not be used (broken root tracks)."""
    named, joint_map, meta = _read(path, scale)
    cut = lead_in_frames(map_joints(named, joint_map))
    named = {k: v[cut:] for k, v in named.items()}
    rate = _rate(map_joints(named, joint_map), fps, meta)
    meta["lead_in_frames"] = cut
    fitted, offsets = _retarget(named, joint_map, rate, meta)
    (joints,), transform = canonicalize([fitted])
    meta["canonical"] = transform
    return joints, offsets, meta


def load_salsa_pair(lead_path: str | Path, follow_path: str | Path, fps: float | None = None,
                    scale: float | None = None) -> tuple[list[np.ndarray], list[np.ndarray], dict]:
    """A synchronised salsa pair (subject 60 leads, 61 follows; same frames, one world) →
    ([lead, follow] joints (T, 22, 3) at 20 fps, [offsets, offsets], meta), canonicalised by
    ONE transform (the lead's frame 0) so their relation is kept. fps defaults to SALSA_FPS
    (60: the headers' 120 is wrong, see frame_rate.py)."""
    reads = [_read(p, scale) for p in (lead_path, follow_path)]
    if reads[0][2]["frames_native"] != reads[1][2]["frames_native"]:
        raise ValueError(f"salsa pair is not synchronised: {reads[0][2]['frames_native']} vs "
                         f"{reads[1][2]['frames_native']} frames")
    # One cut for both, so the pair stays in step.
    cut = max(lead_in_frames(map_joints(named, jm)) for named, jm, _ in reads)
    people, offsets, metas = [], [], []
    for named, joint_map, meta in reads:
        named = {k: v[cut:] for k, v in named.items()}
        _rate(map_joints(named, joint_map), SALSA_FPS if fps is None else fps, meta)
        fitted, off = _retarget(named, joint_map, meta["native_fps"], meta)
        people.append(fitted)
        offsets.append(off)
        metas.append(meta)
    people, transform = canonicalize(people)
    meta = {k: metas[0][k] for k in ("skeleton", "header_fps", "native_fps", "frames_native", "unit_m")}
    for key in ("rest_height_m", "fit_error_mean_mm", "fit_error_max_mm", "fps_estimate", "fps_evidence"):
        meta[key] = [m[key] for m in metas]
    meta.update({"lead_in_frames": cut, "defects": metas[0]["defects"] + metas[1]["defects"],
                 "canonical": transform})
    return people, offsets, meta


__all__ = ["DAZ_MAP", "ACCLAIM_MAP", "MB_NAMES", "acclaim_names", "load_cmu_bvh", "load_salsa_pair", "read_cmu_index",
           "skeleton_family", "rest_height", "file_unit"]
