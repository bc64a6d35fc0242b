"""Bandai Namco Research motion dataset (BVH, `bandai-namco/dataset-{1,2}/data/`) → the
22-joint SMPL layout, and its labels → prompts.

Skeleton: joint_Root (static) → Hips (position + rotation channels on every joint, the
positions equal to the OFFSETs except the Hips'), Spine, Chest, Neck, Head, Shoulder/UpperArm/
LowerArm/Hand _L/_R, UpperLeg/LowerLeg/Foot/Toes _L/_R; no fingers; End Sites with zero
offsets. Centimetres, Y up, the rest figure faces +Z with _L at +X (like ours). The dataset
aligned its three actors onto one figure ("proportion alignment"): all 594 files share it
(offsets equal to 0.01 cm), so the actors' own proportions are gone and the files carry no
actor label.

Joint map (measured on the rest figure): the hip joints sit 2 cm below Hips and Spine 16 cm
above it; SMPL's pelvis is ~8.5 cm above its hip joints, so pelvis = 60% Hips + 40% Spine.
spine1 = Spine, spine2 = Chest, spine3 = 20% of Chest → Neck, neck = Neck (3 cm above the
shoulders, as SMPL's), head = Head (6.5 cm above Neck: the skull base, as SMPL's head joint).
The collar sits a third of the way out from the Chest's midline to the shoulder: 75%
Shoulder_L + 25% UpperArm_L (Shoulder_L starts 5 cm off the midline). The foot joint is
Toes_L (the ball of the foot).

Proportions: the aligned figure is short in the trunk and narrow in the shoulders for its
legs: hip joints → shoulder line 40 cm over an 80 cm leg (0.50 of the leg, where the
skeletons measured on real people give 0.58–0.64 and SMPL 0.69) and 20 cm between the
shoulder joints (0.25 of the leg; measured skeletons 0.44–0.53, SMPL 0.48): in a contact
sheet the arms hang from a narrow neck. `load_bandai` keeps the legs, the pelvis and the
root track as captured (so feet and contacts are untouched) and re-poses the upper body by
IK → FK on a trunk and shoulder girdle scaled to measured proportions (`UPPER_BODY`); every
bone keeps its captured direction. `plausible_body=False` keeps the figure.

Frame rate: 30 fps (headers and README agree); the evidence (`checks.decide_rate` over 30
and 60, see the data card) is recorded per clip in meta["fps_evidence"].

Labels: the file name `dataset-N_{content}_{style}_{take}` and the JSON `{content, style}`
(indices into cfg/content_label.txt, cfg/style_label.txt) agree for every file; the build
checks that. Prompts keep the style: `bandai_prompt("walk", "old")` → "an old person walks",
("walk", "happy") → "a person walks happily", ("bow", "normal") → "a person bows",
("wave-right-hand", "normal") → "a person waves with the right hand". The tables below are
the whole mapping; the data card lists every (label, prompt) pair with its clip count.
What a content is was read from the motion (which wrist rises above the head and swings
sideways, where the pelvis goes; means over each content's clips, all styles):
  bye: the right hand raised to head height and waved (right wrist 0.16 m above the head at
  most, left 0.51 m below; sideways swing 0.63 m/s right, 0.06 left);
  byebye: both hands raised and waved (0.15 / 0.16 m above the head, 0.67 / 0.70 m/s);
  call: leaning forward with both hands at the mouth, calling out;
  guide: the right arm raised forward, showing the way (right wrist 0.15 m below the head,
  left 0.41 m); respond: the left hand raised high (0.25 m above the head);
  walk-left / walk-right: diagonally forward (3.7 m forward and 2.4 m to the left; 3.8 m
  and 2.6 m to the right), facing ahead; walk-turn-left / -right: a 90° turn (92° / -96°);
  walk-back: 5.7 m backwards; dash: 3.1 m/s against the runs' 2.2 m/s;
  wave-/raise-up-left-hand move our left wrist, -right-hand our right (0.25 m above the
  head against 0.54 below for the other hand), so the file's _L / _R are the person's own.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.formats.bvh import read_bvh
from interplay.motion.kinematics import fit_offsets, fit_to_skeleton, resample
from interplay.motion.retarget import JointSource, map_joints
from interplay.motion.retarget.checks import decide_rate, settle

BANDAI_FPS = 30.0
FPS_CANDIDATES = (30.0, 60.0)
CENTIMETRE = 0.01
_STYLE_CHARS = frozenset("abcdefghijklmnopqrstuvwxyz-")

JOINT_MAP: dict[str, JointSource] = {
    "pelvis": (("Hips", 0.6), ("Spine", 0.4)),
    "left_hip": "UpperLeg_L", "right_hip": "UpperLeg_R",
    "spine1": "Spine",
    "left_knee": "LowerLeg_L", "right_knee": "LowerLeg_R",
    "spine2": "Chest",
    "left_ankle": "Foot_L", "right_ankle": "Foot_R",
    "spine3": (("Chest", 0.8), ("Neck", 0.2)),
    "left_foot": "Toes_L", "right_foot": "Toes_R",
    "neck": "Neck",
    "left_collar": (("Shoulder_L", 0.75), ("UpperArm_L", 0.25)),
    "right_collar": (("Shoulder_R", 0.75), ("UpperArm_R", 0.25)),
    "head": "Head",
    "left_shoulder": "UpperArm_L", "right_shoulder": "UpperArm_R",
    "left_elbow": "LowerArm_L", "right_elbow": "LowerArm_R",
    "left_wrist": "Hand_L", "right_wrist": "Hand_R",
}

# Upper-body proportions the figure is re-posed on, as fractions of the leg (hip → knee →
# ankle): trunk = hip-joint centre → shoulder line height, shoulders = the distance between
# the shoulder joints. Measured on the processed offsets of the Acclaim skeletons fitted to
# real people: HDM05's five actors 0.64 / 0.53, CMU's subjects in cmu-asfamc 0.59 / 0.44 and
# cmu-8action 0.58 / 0.46 (SMPL's template 0.69 / 0.48); we take 0.62 / 0.48. Arms and head
# keep the figure's lengths (arm/leg 0.58, within those skeletons' 0.55–0.58).
UPPER_BODY = {"trunk": 0.62, "shoulders": 0.48}

# content → verb phrase (an adverb style follows a one-word verb and precedes a longer phrase).
CONTENTS: dict[str, str] = {
    "walk": "walks",
    "run": "runs",
    "dash": "sprints",
    "walk-back": "walks backwards",
    "walk-left": "walks diagonally forward to the left",
    "walk-right": "walks diagonally forward to the right",
    "walk-turn-left": "walks and turns 90 degrees to the left",
    "walk-turn-right": "walks and turns 90 degrees to the right",
    "bow": "bows",
    "bye": "waves goodbye with the right hand",
    "byebye": "waves goodbye with both hands",
    "guide": "points the way with the right arm",
    "respond": "raises the left hand high to answer",
    "call": "calls out with both hands at the mouth",
    "punch": "punches",
    "kick": "kicks",
    "slash": "slashes with a sword",
    "dance-long": "dances",
    "dance-short": "dances",
    "wave-both-hands": "waves with both hands",
    "wave-left-hand": "waves with the left hand",
    "wave-right-hand": "waves with the right hand",
    "raise-up-both-hands": "raises both hands",
    "raise-up-left-hand": "raises the left hand",
    "raise-up-right-hand": "raises the right hand",
}

# style → ("subject", words) for styles that describe the person, ("adverb", words) for how
# the motion is done, ("manner", words) for a phrase after the motion; normal adds nothing.
STYLES: dict[str, tuple[str, str]] = {
    "normal": ("none", ""),
    "old": ("subject", "an old person"),
    "elderly": ("subject", "an elderly person"),
    "tired": ("subject", "a tired person"),
    "exhausted": ("subject", "an exhausted person"),
    "youthful": ("subject", "a youthful person"),
    "childish": ("manner", "like a child"),
    "happy": ("adverb", "happily"),
    "sad": ("adverb", "sadly"),
    "angry": ("adverb", "angrily"),
    "proud": ("adverb", "proudly"),
    "active": ("adverb", "energetically"),
    "not-confident": ("manner", "without confidence"),
    "masculinity": ("manner", "in a masculine way"),
    "masculine": ("manner", "in a masculine way"),
    "feminine": ("manner", "in a feminine way"),
    "musical": ("manner", "like a musical performer"),
    "giant": ("manner", "like a giant"),
    "chimpira": ("manner", "like a swaggering thug"),
}


def bandai_prompt(content: str, style: str) -> str:
    """A Bandai Namco (content, style) → prompt with the style kept (module docstring)."""
    if content not in CONTENTS:
        raise ValueError(f"unknown Bandai Namco content {content!r}; expected one of {sorted(CONTENTS)}")
    if style not in STYLES:
        raise ValueError(f"unknown Bandai Namco style {style!r}; expected one of {sorted(STYLES)}")
    verb = CONTENTS[content]
    kind, words = STYLES[style]
    if kind == "subject":
        return f"{words} {verb}"
    if kind == "adverb":
        first, _, rest = verb.partition(" ")
        return f"a person {verb} {words}" if not rest else f"a person {words} {verb}"
    if kind == "manner":
        return f"a person {verb} {words}"
    return f"a person {verb}"


def parse_name(path: str | Path) -> dict:
    """dataset-N_{content}_{style}_{take}.bvh → {"dataset", "content", "style", "take"}."""
    # dataset-N_{content}_{style}_{take}: the last two underscores end the content (it may hold some)
    head, style, take = ([""] * 3 + Path(path).stem.rsplit("_", 2))[-3:]
    prefix, dataset, gap, content = head[:8], head[8:9], head[9:10], head[10:]
    if not (prefix == "dataset-" and dataset.isdecimal() and gap == "_" and content
            and style and set(style) <= _STYLE_CHARS and take.isdecimal()):
        raise ValueError(f"{path}: not a Bandai Namco file name (dataset-N_content_style_take)")
    return {"dataset": int(dataset), "content": content, "style": style, "take": int(take)}


def read_labels(path: str | Path) -> dict:
    """The clip's labels from its JSON and cfg/ tables; raises if they disagree with the name."""
    path = Path(path)
    name = parse_name(path)
    cfg = path.parent.parent / "cfg"
    contents = [s.strip() for s in (cfg / "content_label.txt").read_text().split() if s.strip()]
    styles = [s.strip() for s in (cfg / "style_label.txt").read_text().split() if s.strip()]
    label = json.loads(path.with_suffix(".json").read_text())
    prefix = f"dataset-{name['dataset']}_"
    content = contents[int(label["content"])].removeprefix(prefix)
    style = styles[int(label["style"])].removeprefix(prefix)
    if (content, style) != (name["content"], name["style"]):
        raise ValueError(f"{path.name}: JSON says ({content}, {style}), the name "
                         f"({name['content']}, {name['style']})")
    return name


def _trunk_offsets(offsets: np.ndarray) -> np.ndarray:
    """The fitted offsets with the trunk raised and the shoulder girdle widened to
    UPPER_BODY's proportions of the leg: the heights of spine1 … spine3, the neck, the
    collars and the shoulders above the pelvis scale by one factor, the collars' and
    shoulders' spread by another; legs, hips, arms and head keep their lengths."""
    out = offsets.copy()
    j = sk.JOINT_INDEX
    rest = sk.rest_joints(offsets)
    leg = np.linalg.norm(offsets[j["left_knee"]]) + np.linalg.norm(offsets[j["left_ankle"]])
    hips = (rest[j["left_hip"]] + rest[j["right_hip"]]) / 2
    shoulders = (rest[j["left_shoulder"]] + rest[j["right_shoulder"]]) / 2
    below = rest[sk.PELVIS, 1] - hips[1]                   # pelvis above the hip centre (kept)
    rise = (UPPER_BODY["trunk"] * leg - below) / (shoulders[1] - hips[1] - below)
    for name in ("spine1", "spine2", "spine3", "neck", "left_collar", "right_collar",
                 "left_shoulder", "right_shoulder"):
        out[j[name], 1] *= rise
    width = np.linalg.norm(rest[j["left_shoulder"]] - rest[j["right_shoulder"]])
    spread = UPPER_BODY["shoulders"] * leg / width
    for name in ("left_collar", "right_collar", "left_shoulder", "right_shoulder"):
        out[j[name], 0] *= spread
    return out


def load_bandai(path: str | Path, plausible_body: bool = True) -> tuple[np.ndarray, np.ndarray, dict]:
    """One Bandai Namco BVH → (joints (T, 22, 3) at 20 fps in metres, Y up, canonical: floor
    at y = 0, pelvis at the XZ origin facing +Z on frame 0; offsets (22, 3); meta). meta
    records the rate evidence, the contact check and any defects (`checks`)."""
    bvh = read_bvh(Path(path))
    missing = sorted({s for src in JOINT_MAP.values()
                      for s in ([src] if isinstance(src, str) else [n for n, _ in src])} - set(bvh.names))
    if missing:
        raise ValueError(f"{path}: not a Bandai Namco BVH (lacks {missing})")
    named = bvh.named_positions(include_end_sites=False)
    native = map_joints(named, JOINT_MAP) * CENTIMETRE
    meta: dict = {"skeleton": "bandai-namco", "header_fps": round(bvh.fps, 3),
                  "frames_native": bvh.num_frames, "unit_m": CENTIMETRE, "defects": []}
    fps = decide_rate(native, BANDAI_FPS, FPS_CANDIDATES, meta)
    joints = resample(native, fps, sk.FPS)
    offsets = fit_offsets(joints)
    if plausible_body:
        offsets = _trunk_offsets(offsets)
    fitted, offsets = fit_to_skeleton(joints, offsets)
    err = np.linalg.norm(fitted - joints, axis=-1)
    legs = [sk.JOINT_INDEX[n] for n in ("left_knee", "right_knee", "left_ankle", "right_ankle",
                                        "left_foot", "right_foot")]
    meta["fit_error_mean_mm"] = round(float(err.mean()) * 1000, 2)
    meta["fit_error_legs_max_mm"] = round(float(err[:, legs].max()) * 1000, 2)
    meta["plausible_body"] = plausible_body
    return settle(fitted, meta), offsets, meta


__all__ = ["BANDAI_FPS", "CONTENTS", "STYLES", "JOINT_MAP", "UPPER_BODY", "bandai_prompt",
           "parse_name", "read_labels", "load_bandai"]
