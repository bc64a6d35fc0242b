"""CMU trials retargeted onto Reallusion's CC_Base rig (`cmu-iclone/subjects/NNN/NNN_TT.bvh`,
a third party's iClone conversion) → the 22-joint SMPL layout.

Skeleton: root CC_Base_Hip (or RL_BoneRoot above it, whose rotation turns the file's Z-up
hip offset into Y up) → CC_Base_Pelvis → Thigh/Calf/Foot/ToeBase, Waist → Spine01 → Spine02 →
NeckTwist01 → NeckTwist02 → Head, Clavicle/Upperarm/Forearm/Hand, plus twist, "ShareBone",
finger, toe, breast, ribs and face bones, which the joint map never reads (their rotations
move nothing we keep). Centimetres, Y up after FK, facing +Z with L at +X (like ours).
The motion is scaled to the CC figure (the pelvis of 02_01 travels 3.84 m where cmu-bvh's
Daz conversion of the same trial travels 3.35 m), so the proportions are the figure's:
hip joints at 1.03 m, head joint at 1.67 m.

Joint map (heights on 02_01's first frame): the thighs sit 2–3 cm below CC_Base_Hip and
Waist 8 cm above it; SMPL's pelvis is ~8.5 cm above its hip joints, so pelvis = 25% Hip +
75% Waist. Along hip joints (1.03 m) → NeckTwist01 (1.59 m, 5 cm above the shoulders, as
SMPL's neck) SMPL puts spine1/spine2/spine3 at 33/56/65%: spine1 = 70% Spine01 + 30%
Spine02, spine2 = Spine02, spine3 = 75% Spine02 + 25% NeckTwist01; neck = NeckTwist01,
head = CC_Base_Head (the skull base, 8 cm above the neck). Clavicle starts 3 cm off the
midline, so the collar is 75% Clavicle + 25% Upperarm (as for Daz). Foot = ToeBase (ball).

Frame rate: 60 fps as the headers say, for every file (Frame Time 0.016667, set by the
converter from CMU's 120 fps: the frame counts are the CSV's "Frames 60fps", half of CMU's;
02_01 lasts 2.85 s here and 2.87 s in cmu-bvh's 120 fps file). At 60 the centre of mass
falls at 6.1–10.8 m/s² in the trials with a clear flight (05_13, 05_16, 05_18, 05_19, 06_15;
24–45 at 120). `frame_rate.estimate_true_fps` alone would retime 05_07 and 05_10 (small
jetés) to 120 on their pelvis parabolas; one converter and one session give one rate, so
they stay at 60 and the card lists the disagreement. Evidence per clip
(`checks.decide_rate` over 60 and 120) in meta["fps_evidence"].

The T-pose: the converter says it prepends one T-pose frame to every trial. These exports
do not start with one: no file's first frame is a T-pose (arms hang 40–50 cm below the
shoulders in 41 of 47; the others start mid-motion) and the first frame-to-frame jumps are
ordinary (≤ 8 cm at 60 fps, the clips' own speed). `load_cmu_iclone` still drops leading
frames that are a T-pose followed by a jump (`tpose_lead_in`) and records how many.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.formats.bvh import read_bvh
from interplay.motion.retarget import JointSource, map_joints, to_smpl22
from interplay.motion.retarget.checks import decide_rate, record_fit, settle
from interplay.motion.retarget.cmu_index import read_cmu_index
from interplay.motion.retarget.frame_rate import lead_in_frames

ICLONE_FPS = 60.0
FPS_CANDIDATES = (60.0, 120.0)
CENTIMETRE = 0.01

JOINT_MAP: dict[str, JointSource] = {
    "pelvis": (("CC_Base_Hip", 0.25), ("CC_Base_Waist", 0.75)),
    "left_hip": "CC_Base_L_Thigh", "right_hip": "CC_Base_R_Thigh",
    "spine1": (("CC_Base_Spine01", 0.7), ("CC_Base_Spine02", 0.3)),
    "left_knee": "CC_Base_L_Calf", "right_knee": "CC_Base_R_Calf",
    "spine2": "CC_Base_Spine02",
    "left_ankle": "CC_Base_L_Foot", "right_ankle": "CC_Base_R_Foot",
    "spine3": (("CC_Base_Spine02", 0.75), ("CC_Base_NeckTwist01", 0.25)),
    "left_foot": "CC_Base_L_ToeBase", "right_foot": "CC_Base_R_ToeBase",
    "neck": "CC_Base_NeckTwist01",
    "left_collar": (("CC_Base_L_Clavicle", 0.75), ("CC_Base_L_Upperarm", 0.25)),
    "right_collar": (("CC_Base_R_Clavicle", 0.75), ("CC_Base_R_Upperarm", 0.25)),
    "head": "CC_Base_Head",
    "left_shoulder": "CC_Base_L_Upperarm", "right_shoulder": "CC_Base_R_Upperarm",
    "left_elbow": "CC_Base_L_Forearm", "right_elbow": "CC_Base_R_Forearm",
    "left_wrist": "CC_Base_L_Hand", "right_wrist": "CC_Base_R_Hand",
}


def is_tpose(frame: np.ndarray, tolerance: float = 0.15) -> bool:
    """Whether one frame of mapped joints (22, 3), metres, is a T-pose: both wrists level
    with their shoulders (within `tolerance` m) and out to the side (at least 80% of the
    arm's length away from the shoulder, sideways)."""
    for s, w in ((sk.LEFT_SHOULDER, sk.LEFT_HAND), (sk.RIGHT_SHOULDER, sk.RIGHT_HAND)):
        arm = frame[w] - frame[s]
        across = frame[sk.LEFT_SHOULDER] - frame[sk.RIGHT_SHOULDER]
        across[1] = 0.0
        side = abs(arm @ across) / max(float(np.linalg.norm(across)), 1e-9)
        if abs(arm[1]) > tolerance or side < 0.8 * np.linalg.norm(arm):
            return False
    return True


def tpose_lead_in(native: np.ndarray) -> int:
    """Leading frames to drop: a T-pose at frame 0 that the motion jumps away from
    (frame_rate.lead_in_frames' test for an unusual jump); 0 when frame 0 is no T-pose."""
    if len(native) < 4 or not is_tpose(native[0]):
        return 0
    return max(1, lead_in_frames(native, max_frames=5))


def trial_of(path: str | Path) -> tuple[int, int]:
    """NNN_TT.bvh → (subject, trial)."""
    subject, trial = Path(path).stem.split("_")[:2]
    return int(subject), int(trial)


def load_cmu_iclone(path: str | Path) -> tuple[np.ndarray, np.ndarray, dict]:
    """One CC_Base BVH → (joints (T, 22, 3) at 20 fps, metres, Y up, canonical; offsets
    (22, 3); meta with the rate evidence, the dropped T-pose frames, the contact check and
    any defects)."""
    bvh = read_bvh(Path(path))
    named = bvh.named_positions(include_end_sites=False)
    missing = sorted({s for src in JOINT_MAP.values()
                      for s in ([src] if isinstance(src, str) else [n for n, _ in src])} - set(named))
    if missing:
        raise ValueError(f"{path}: not a CC_Base BVH (lacks {missing})")
    native = map_joints(named, JOINT_MAP) * CENTIMETRE
    cut = tpose_lead_in(native)
    named = {k: v[cut:] for k, v in named.items()}
    meta: dict = {"skeleton": "cc-base", "header_fps": round(bvh.fps, 3), "frames_native": bvh.num_frames,
                  "unit_m": CENTIMETRE, "tpose_frames_dropped": cut, "root": bvh.names[0], "defects": []}
    fps = decide_rate(native[cut:], ICLONE_FPS, FPS_CANDIDATES, meta, keep_stated=True)
    fitted, offsets, raw = to_smpl22(named, JOINT_MAP, fps, scale=CENTIMETRE)
    record_fit(fitted, raw, meta)
    return settle(fitted, meta), offsets, meta


__all__ = ["ICLONE_FPS", "JOINT_MAP", "is_tpose", "tpose_lead_in", "trial_of", "load_cmu_iclone",
           "read_cmu_index"]
