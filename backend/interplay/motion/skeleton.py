"""The 22-joint SMPL layout every motion in Interplay lives in.

Conventions: Y up, metres, 20 fps; the canonical rest pose faces +Z, so a person's
left side is +X. Joint order is SMPL's (the first 22 joints, no hands).
"""

from __future__ import annotations

import numpy as np

FPS = 20
NUM_JOINTS = 22
SKELETON_NAME = "smpl22"

JOINT_NAMES: tuple[str, ...] = (
    "pelvis", "left_hip", "right_hip", "spine1", "left_knee", "right_knee",
    "spine2", "left_ankle", "right_ankle", "spine3", "left_foot", "right_foot",
    "neck", "left_collar", "right_collar", "head", "left_shoulder",
    "right_shoulder", "left_elbow", "right_elbow", "left_wrist", "right_wrist",
)
JOINT_INDEX: dict[str, int] = {n: i for i, n in enumerate(JOINT_NAMES)}

PARENTS: tuple[int, ...] = (
    -1, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 9, 9, 12, 13, 14, 16, 17, 18, 19,
)

# Rest offsets of each joint from its parent (metres), the SMPL neutral template.
# The pelvis row is the pelvis height above the soles in the rest pose.
REST_OFFSETS = np.array([
    [0.0000, 0.9500, 0.0000],    # pelvis
    [0.0586, -0.0823, -0.0177],  # left_hip
    [-0.0603, -0.0905, -0.0135],  # right_hip
    [0.0044, 0.1244, -0.0384],   # spine1
    [0.0435, -0.3865, 0.0080],   # left_knee
    [-0.0433, -0.3837, -0.0048],  # right_knee
    [0.0045, 0.1380, 0.0268],    # spine2
    [-0.0148, -0.4269, -0.0374],  # left_ankle
    [0.0191, -0.4200, -0.0345],  # right_ankle
    [-0.0023, 0.0560, 0.0029],   # spine3
    [0.0411, -0.0603, 0.1221],   # left_foot
    [-0.0348, -0.0621, 0.1303],  # right_foot
    [-0.0134, 0.2116, -0.0335],  # neck
    [0.0717, 0.1140, -0.0189],   # left_collar
    [-0.0830, 0.1125, -0.0237],  # right_collar
    [0.0101, 0.0889, 0.0504],    # head
    [0.1229, 0.0452, -0.0190],   # left_shoulder
    [-0.1132, 0.0469, -0.0085],  # right_shoulder
    [0.2553, -0.0156, -0.0229],  # left_elbow
    [-0.2601, -0.0144, -0.0313],  # right_elbow
    [0.2657, 0.0127, -0.0073],   # left_wrist
    [-0.2691, 0.0068, -0.0060],  # right_wrist
], dtype=np.float64)

# CoMA appendix E.2: four overlapping parts (the torso belongs to both upper parts,
# the pelvis to both lower parts).
BODY_PARTS: dict[str, tuple[str, ...]] = {
    "left_upper": ("left_collar", "left_shoulder", "left_elbow", "left_wrist",
                   "spine3", "spine2", "spine1", "head", "neck"),
    "right_upper": ("right_collar", "right_shoulder", "right_elbow", "right_wrist",
                    "spine3", "spine2", "spine1", "head", "neck"),
    "left_lower": ("left_ankle", "left_foot", "left_hip", "pelvis", "left_knee"),
    "right_lower": ("right_ankle", "right_foot", "right_hip", "pelvis", "right_knee"),
}
PART_NAMES: tuple[str, ...] = tuple(BODY_PARTS)
PART_JOINTS: dict[str, np.ndarray] = {
    p: np.array(sorted(JOINT_INDEX[j] for j in js)) for p, js in BODY_PARTS.items()
}
# What a user calls a part ("left arm") mapped to the model's part.
PART_ALIASES: dict[str, str] = {
    "left_arm": "left_upper", "right_arm": "right_upper",
    "left_leg": "left_lower", "right_leg": "right_lower",
}

# Colour of each part in the studio's legend (hex), shared with the front end.
PART_COLOURS: dict[str, str] = {
    "left_upper": "#4f9dde", "right_upper": "#e0875a",
    "left_lower": "#5fbf8f", "right_lower": "#c46fc4",
}

# Non-overlapping part of each joint, for colouring bones (torso goes to the uppers
# by side of the body, centre line to left_upper, pelvis to left_lower).
JOINT_PART: tuple[str, ...] = tuple(
    "left_lower" if n in ("pelvis", "left_hip", "left_knee", "left_ankle", "left_foot")
    else "right_lower" if n in ("right_hip", "right_knee", "right_ankle", "right_foot")
    else "right_upper" if n.startswith("right_")
    else "left_upper"
    for n in JOINT_NAMES
)

PELVIS = JOINT_INDEX["pelvis"]
HEAD = JOINT_INDEX["head"]
NECK = JOINT_INDEX["neck"]
LEFT_HAND, RIGHT_HAND = JOINT_INDEX["left_wrist"], JOINT_INDEX["right_wrist"]
LEFT_ANKLE, RIGHT_ANKLE = JOINT_INDEX["left_ankle"], JOINT_INDEX["right_ankle"]
LEFT_FOOT, RIGHT_FOOT = JOINT_INDEX["left_foot"], JOINT_INDEX["right_foot"]
LEFT_HIP, RIGHT_HIP = JOINT_INDEX["left_hip"], JOINT_INDEX["right_hip"]
LEFT_SHOULDER, RIGHT_SHOULDER = JOINT_INDEX["left_shoulder"], JOINT_INDEX["right_shoulder"]
# Joints that touch the ground in HumanML3D-style foot contact (ankles, toes).
FOOT_JOINTS = (LEFT_ANKLE, LEFT_FOOT, RIGHT_ANKLE, RIGHT_FOOT)
# Key joints of CODA's key-joint trajectory loss: hands, feet, pelvis.
KEY_JOINTS = (PELVIS, LEFT_HAND, RIGHT_HAND, LEFT_FOOT, RIGHT_FOOT)

# Bones as (child, parent) pairs, one per non-root joint.
BONES: tuple[tuple[int, int], ...] = tuple((j, p) for j, p in enumerate(PARENTS) if p >= 0)

# Segment mass fractions (de Leva 1996, male), one per joint: the segment that runs from
# the joint towards its child(ren) (its centre is taken midway). Toes and collars carry none.
SEGMENT_MASS: np.ndarray = np.array([
    0.1117,  # pelvis: lower trunk
    0.1416, 0.1416,  # hips: thighs
    0.0816,  # spine1: lower half of the middle trunk
    0.0433, 0.0433,  # knees: shanks
    0.0817,  # spine2: upper half of the middle trunk
    0.0137, 0.0137,  # ankles: feet
    0.1596,  # spine3: upper trunk
    0.0, 0.0,  # toes
    0.0200,  # neck
    0.0, 0.0,  # collars
    0.0494,  # head
    0.0271, 0.0271,  # shoulders: upper arms
    0.0162, 0.0162,  # elbows: forearms
    0.0061, 0.0061,  # wrists: hands
])
SEGMENT_MASS = SEGMENT_MASS / SEGMENT_MASS.sum()


def rest_joints(offsets: np.ndarray = REST_OFFSETS) -> np.ndarray:
    """Rest-pose joint positions (22, 3) from per-joint offsets."""
    out = np.zeros((NUM_JOINTS, 3))
    for j, p in enumerate(PARENTS):
        out[j] = offsets[j] if p < 0 else out[p] + offsets[j]
    return out


def bone_lengths(joints: np.ndarray) -> np.ndarray:
    """Bone lengths (..., 21) of joints (..., 22, 3), in BONES order."""
    child = np.array([c for c, _ in BONES])
    parent = np.array([p for _, p in BONES])
    return np.linalg.norm(joints[..., child, :] - joints[..., parent, :], axis=-1)


def children(joint: int) -> list[int]:
    return [j for j, p in enumerate(PARENTS) if p == joint]


def resolve_part(name: str) -> str:
    """A part name as a user may type it ("left arm", "left_upper") → the model's part."""
    key = name.strip().lower().replace(" ", "_").replace("-", "_")
    key = PART_ALIASES.get(key, key)
    if key not in BODY_PARTS:
        raise ValueError(f"unknown body part {name!r}; expected one of "
                         f"{sorted(PART_ALIASES) + list(PART_NAMES)}")
    return key
