"""ReActIdle (Atxa Landa et al. 2025, MIT): idle standing captures, BVH (`acted/NNN_acted.bvh`,
`genuine/NNN_genuine.bvh`) → the 22-joint SMPL layout.

Skeleton (Blender's rigify-style names, metres, Y up, the figure faces +Z with `.L` at +X like
ours): pelvis (root) → spine → spine.001 → neck → face; shoulder/upper_arm/forearm .L/.R from
spine.001; pelvis.L/.R (zero length) and thigh/shin/foot .L/.R from the pelvis; End Sites
after face, the forearms (the wrists: there are no hand bones) and the feet (the toes). Most
joints carry position channels equal to their OFFSETs. The root's translation is captured (a
few centimetres of sway) but its height is 0: the feet hang 0.7 m below it, which the
canonical frame's floor takes care of.

Joint map (measured on the rest figure): `spine` sits at the pelvis and `spine.001` 21 cm above
it; `neck` is at shoulder height (0.42 m above the pelvis) and `face` 15 cm higher (mid-head).
SMPL's pelvis is ~8.5 cm above its hip joints: pelvis = 60% pelvis + 40% spine.001 (8 cm);
spine1 = halfway up to spine.001; spine2 = spine.001; spine3 = 20% spine.001 + 80% neck; SMPL's
neck sits ~5 cm above the shoulder line: neck = 65% neck + 35% face; head = face. The collar is
a quarter of the way from shoulder.L (at the neck) out to upper_arm.L; wrist = the forearm's
End Site; the foot joint = the foot's End Site (13 cm ahead of the ankle, the ball of the foot).

Frame rate: the headers say 24 fps (Frame Time 0.041667). Idle standing has no gait and no
flight to test it against, so the stated rate is kept (`checks.decide_rate(keep_stated=True)`
still records the estimate and rejects broken root tracks).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.formats.bvh import read_bvh
from interplay.motion.kinematics import fit_to_skeleton, resample
from interplay.motion.retarget import JointSource, map_joints
from interplay.motion.retarget.checks import decide_rate, record_fit, settle

REACTIDLE_FPS = 24.0
FPS_CANDIDATES = (24.0, 30.0, 48.0)

JOINT_MAP: dict[str, JointSource] = {
    "pelvis": (("pelvis", 0.6), ("spine.001", 0.4)),
    "left_hip": "thigh.L", "right_hip": "thigh.R",
    "spine1": (("spine", 0.5), ("spine.001", 0.5)),
    "left_knee": "shin.L", "right_knee": "shin.R",
    "spine2": "spine.001",
    "left_ankle": "foot.L", "right_ankle": "foot.R",
    "spine3": (("spine.001", 0.2), ("neck", 0.8)),
    "left_foot": "foot.L_end", "right_foot": "foot.R_end",
    "neck": (("neck", 0.65), ("face", 0.35)),
    "left_collar": (("shoulder.L", 0.75), ("upper_arm.L", 0.25)),
    "right_collar": (("shoulder.R", 0.75), ("upper_arm.R", 0.25)),
    "head": "face",
    "left_shoulder": "upper_arm.L", "right_shoulder": "upper_arm.R",
    "left_elbow": "forearm.L", "right_elbow": "forearm.R",
    "left_wrist": "forearm.L_end", "right_wrist": "forearm.R_end",
}

PROMPTS = {
    "acted": "a person stands idle, acting out waiting: shifting weight, looking around and fidgeting",
    "genuine": "a person stands idle naturally, shifting weight now and then",
}


def reactidle_prompt(kind: str) -> str:
    """`acted` or `genuine` (the folder) → the clip's prompt."""
    if kind not in PROMPTS:
        raise ValueError(f"unknown ReActIdle kind {kind!r}; expected one of {sorted(PROMPTS)}")
    return PROMPTS[kind]


def load_reactidle(path: str | Path) -> tuple[np.ndarray, np.ndarray, dict]:
    """One ReActIdle BVH → (joints (T, 22, 3) at 20 fps in metres, Y up, canonical; offsets
    (22, 3); meta with the stated and decided rates, the evidence, the fit error, the contact
    check and any defects)."""
    bvh = read_bvh(Path(path))
    named = bvh.named_positions(include_end_sites=True)
    needed = {s for src in JOINT_MAP.values() for s in ([src] if isinstance(src, str) else [n for n, _ in src])}
    missing = sorted(needed - set(named))
    if missing:
        raise ValueError(f"{path}: not a ReActIdle BVH (lacks {missing})")
    native = map_joints(named, JOINT_MAP)
    meta: dict = {"skeleton": "reactidle", "header_fps": round(bvh.fps, 3), "frames_native": bvh.num_frames,
                  "defects": []}
    fps = decide_rate(native, round(bvh.fps, 3), FPS_CANDIDATES, meta, keep_stated=True)
    joints = resample(native, fps, sk.FPS)
    fitted, offsets = fit_to_skeleton(joints)
    record_fit(fitted, joints, meta)
    return settle(fitted, meta), offsets, meta


__all__ = ["FPS_CANDIDATES", "JOINT_MAP", "PROMPTS", "REACTIDLE_FPS", "load_reactidle", "reactidle_prompt"]
