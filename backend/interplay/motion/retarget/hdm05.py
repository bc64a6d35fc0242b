"""HDM05 (Acclaim ASF/AMC, CMU-style 31-bone skeleton) → the 22-joint SMPL layout.

Units: HDM05's ASF says `length 0.45`, i.e. file units are inches × 0.45, so one unit is
0.0254 / 0.45 m (checked: actors come out 1.6–1.8 m tall). Axes: Acclaim's global frame is
already Y up with the rest pose facing +Z and the left side at +X, like ours.

Each SMPL joint is the end of one Acclaim bone (the root is the pelvis centre), except the
two that have no Acclaim counterpart: spine3 sits between the ends of upperback and thorax,
and a collar sits a third of the way along its clavicle (SMPL's collar joints lie a few cm
off the midline, Acclaim's clavicles start on it).

Class → prompt (the data card quotes this table; folder spellings such as
"kickLFront1Reps" or "sneak2StepsLStart" map by their class prefix):

| HDM05 class            | prompt                                                                 |
|------------------------|------------------------------------------------------------------------|
| depositFloorR          | a person bends down and deposits something on the floor with the right hand |
| elbowToKnee            | a person touches each elbow to the opposite knee, starting with the left elbow |
| grabHighR              | a person reaches up high and grabs something with the right hand       |
| hopBothLegs            | a person hops on both legs                                             |
| jogLeftCircle          | a person jogs in a circle to the left                                  |
| kickLFront             | a person kicks forward with the left foot                              |
| lieDownFloor           | a person lies down on the floor                                        |
| rotateArmsBothBackward | a person rotates both arms backward in circles                         |
| sneak                  | a person sneaks forward quietly                                        |
| squat                  | a person squats down and stands back up                                |
| throwBasketball        | a person throws a basketball                                           |
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from interplay.motion.formats.acclaim import load_acclaim
from interplay.motion.retarget import JointSource, canonicalize, to_smpl22

HDM05_FPS = 120

# SMPL joint → Acclaim joint (the end of that bone; "root" is the pelvis centre) or a blend.
JOINT_MAP: dict[str, JointSource] = {
    "pelvis": "root",
    "left_hip": "lhipjoint", "right_hip": "rhipjoint",
    "left_knee": "lfemur", "right_knee": "rfemur",
    "left_ankle": "ltibia", "right_ankle": "rtibia",
    "left_foot": "lfoot", "right_foot": "rfoot",          # ball of the foot (toes start)
    "spine1": "lowerback", "spine2": "upperback",
    "spine3": (("upperback", 0.5), ("thorax", 0.5)),
    "neck": "lowerneck", "head": "upperneck",             # base of the neck, base of the skull
    "left_collar": (("thorax", 2 / 3), ("lclavicle", 1 / 3)),
    "right_collar": (("thorax", 2 / 3), ("rclavicle", 1 / 3)),
    "left_shoulder": "lclavicle", "right_shoulder": "rclavicle",
    "left_elbow": "lhumerus", "right_elbow": "rhumerus",
    "left_wrist": "lradius", "right_wrist": "rradius",
}

# The docstring's table as data.
HDM05_PROMPTS: dict[str, str] = {
    "depositFloorR": "a person bends down and deposits something on the floor with the right hand",
    "elbowToKnee": "a person touches each elbow to the opposite knee, starting with the left elbow",
    "grabHighR": "a person reaches up high and grabs something with the right hand",
    "hopBothLegs": "a person hops on both legs",
    "jogLeftCircle": "a person jogs in a circle to the left",
    "kickLFront": "a person kicks forward with the left foot",
    "lieDownFloor": "a person lies down on the floor",
    "rotateArmsBothBackward": "a person rotates both arms backward in circles",
    "sneak": "a person sneaks forward quietly",
    "squat": "a person squats down and stands back up",
    "throwBasketball": "a person throws a basketball",
}


def hdm05_class(label: str) -> str:
    """A class name, folder name ("kickLFront1Reps") or clip stem
    ("HDM_bd_kickLFront1Reps_001_120") → its HDM05 class ("kickLFront")."""
    name = label.strip()
    if name.startswith("HDM_") and name.count("_") >= 2:
        name = name.split("_")[2]
    for cls in sorted(HDM05_PROMPTS, key=len, reverse=True):
        if name.lower().startswith(cls.lower()):
            return cls
    raise ValueError(f"unknown HDM05 class {label!r}; expected one of {sorted(HDM05_PROMPTS)}")


def hdm05_prompt(class_name: str) -> str:
    """Short prompt for an HDM05 class or folder name (see the module's table)."""
    return HDM05_PROMPTS[hdm05_class(class_name)]


def _class_or_none(stem: str) -> str | None:
    try:
        return hdm05_class(stem)
    except ValueError:
        return None


def clip_fps(amc_path: str | Path) -> float:
    """HDM05 names clips HDM_<actor>_<class>_<n>_<fps>.amc."""
    head, underscore, fps = Path(amc_path).stem.rpartition("_")
    return float(fps) if underscore and fps.isdecimal() else float(HDM05_FPS)


def load_hdm05(amc_path: str | Path, asf_path: str | Path) -> tuple[np.ndarray, np.ndarray, dict]:
    """One HDM05 clip → (joints (T, 22, 3) at 20 fps in metres, Y up, canonicalised: floor
    at y=0, pelvis at the XZ origin facing +Z on the first frame; offsets (22, 3); meta)."""
    named, asf, amc = load_acclaim(amc_path, asf_path)
    missing = sorted({s for src in JOINT_MAP.values()
                      for s in ([src] if isinstance(src, str) else [n for n, _ in src])} - set(named))
    if missing:
        raise ValueError(f"{Path(asf_path).name} lacks bones {missing} of the HDM05 joint map")
    fps = clip_fps(amc_path)
    fitted, offsets, raw = to_smpl22(named, JOINT_MAP, fps=fps, scale=asf.metres_per_unit)
    fit_error = float(np.linalg.norm(fitted - raw, axis=-1).mean())
    (joints,), transform = canonicalize([fitted])
    stem = Path(amc_path).stem
    meta = {
        "source_fps": fps,
        "source_frames": amc.n_frames,
        "metres_per_unit": asf.metres_per_unit,
        "skeleton": asf.name,
        "class": _class_or_none(stem),
        "fit_error_m": fit_error,
        "canonical": transform,
    }
    return joints, offsets, meta
