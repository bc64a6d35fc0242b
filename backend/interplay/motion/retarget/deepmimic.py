"""DeepMimic's humanoid motions (`deepmimic/motions/humanoid3d_*.txt`, JSON) → the 22-joint
SMPL layout.

Character (`characters/humanoid3d.txt`): 15 joints, parents first — root, chest, neck,
right_hip, right_knee, right_ankle, right_shoulder, right_elbow, right_wrist, left_hip …
left_wrist; each with an attachment offset in its parent's frame (metres; every AttachTheta
is zero). Y up; the character faces +X with its right side at +Z (right_hip at z = +0.085),
a proper rotation of our frame (facing +Z, left +X), so canonicalisation's yaw is all that
is needed. Knees and elbows are revolute about their z axis (knee angles ≤ 0 bend the shin
backwards, towards -X); wrists are fixed.

A frame: [duration (s), root position (3), root rotation (w, x, y, z), then in joint order
the local rotation of each moving joint: quaternions (w, x, y, z) for spherical joints,
one angle (rad) for revolute ones] — 44 numbers. A frame's duration is the time to the
next one (the last is 0).

Virtual joints (DeepMimic has no spine chain, collars, head joint or toes), each rigid on a
DeepMimic joint and placed from the character's own geometry: the pelvis is the root body's
centre (7 cm above the root; SMPL's pelvis is 8.5 cm above its hip joints, DeepMimic's hips
sit level with the root); spine1 15 cm above the root (SMPL's spine1 is a third of the way
from the hip joints to the neck: 0.33 × 0.46 m), spine2 = chest, spine3 6 cm above the
chest (SMPL: 65%), neck = neck (the base of the neck, 0.46 m above the root; the head sphere's
centre is 17.5 cm higher), head 8.75 cm above the neck (halfway to the head's centre, where
SMPL's skull-base head joint sits), a collar a third of the way out to its shoulder and
4 cm lower, the foot joint at the ball of the foot box (70% of its 17.7 cm from the heel,
2 cm above its sole).

Frame rate: the durations (1/120 … 1/16 s per clip) are the stated timing, and they are
kept: DeepMimic's simulated character tracks these clips under real gravity, and where a
clip leaves the floor its centre of mass falls at gravity's rate at the stated timing and
far from it at double or half (`checks.com_flight_gravity`, m/s² at half | stated | double:
backflip 2.0 | 8.2 | 32.7, jump 2.4 | 9.7 | 38.9, spinkick 2.4 | 9.6 | 38.6, jog 2.3 | 9.1 |
36.4, run 3.6 | 14.6 | 58.3). `frame_rate.estimate_true_fps` alone would retime four clips
(backflip and sideflip to 8 fps, spin to 48, dance_b to 120): its pelvis parabola breaks
in flips and spins, where the pelvis turns about the centre of mass, and its 6 m/s² cap on
horizontal acceleration is for walkers, not acrobats. Both are recorded per clip
(meta["fps_estimate"], meta["fps_evidence"]); the data card lists the disagreements.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import fit_to_skeleton
from interplay.motion.retarget import JointSource, map_joints
from interplay.motion.retarget.checks import decide_rate, record_fit, settle
from interplay.motion.rotations import axis_rotation, quat_to_matrix

VALUES_PER_FRAME = 44

# Clip name (humanoid3d_<name>.txt) → prompt; the data card quotes this table.
PROMPTS: dict[str, str] = {
    "backflip": "a person does a backflip",
    "cartwheel": "a person does a cartwheel",
    "crawl": "a person crawls forward low on the ground",
    "dance_a": "a person dances",
    "dance_b": "a person dances with small hops",
    "dance_spin": "a person dances and spins around",
    "getup_facedown": "a person gets up from lying face down",
    "getup_faceup": "a person gets up from lying on the back",
    "jog": "a person jogs forward",
    "jump": "a person jumps forward",
    "kick": "a person kicks with the right foot",
    "punch": "a person steps forward and punches",
    "roll": "a person rolls forward on the ground and stands up",
    "run": "a person runs forward",
    "sideflip": "a person does a sideflip",
    "spin": "a person leaps and spins in the air",
    "spinkick": "a person does a spinning kick",
    "stealthy_walk": "a person walks stealthily",
    "walk": "a person walks forward",
    "zombie_walk": "a person walks like a zombie",
}


def clip_name(path: str | Path) -> str:
    """humanoid3d_<name>.txt → name."""
    return Path(path).stem.removeprefix("humanoid3d_")


def deepmimic_prompt(name: str) -> str:
    """A clip name ("spinkick") or file name → its prompt (PROMPTS)."""
    key = clip_name(name) if name.endswith(".txt") else name
    if key not in PROMPTS:
        raise ValueError(f"unknown DeepMimic clip {name!r}; expected one of {sorted(PROMPTS)}")
    return PROMPTS[key]

# Virtual joints: name → (DeepMimic joint it is rigid on, offset in that joint's frame).
VIRTUAL: dict[str, tuple[str, tuple[float, float, float]]] = {
    "pelvis": ("root", (0.0, 0.07, 0.0)),
    "spine1": ("root", (0.0, 0.15, 0.0)),
    "spine3": ("chest", (0.0, 0.06, 0.0)),
    "head": ("neck", (0.0, 0.0875, 0.0)),
    "right_collar": ("chest", (-0.024, 0.2035, 0.061)),
    "left_collar": ("chest", (-0.024, 0.2035, -0.061)),
    "right_toe": ("right_ankle", (0.080, -0.030, 0.0)),
    "left_toe": ("left_ankle", (0.080, -0.030, 0.0)),
}

JOINT_MAP: dict[str, JointSource] = {
    "pelvis": "pelvis",
    "left_hip": "left_hip", "right_hip": "right_hip",
    "spine1": "spine1",
    "left_knee": "left_knee", "right_knee": "right_knee",
    "spine2": "chest",
    "left_ankle": "left_ankle", "right_ankle": "right_ankle",
    "spine3": "spine3",
    "left_foot": "left_toe", "right_foot": "right_toe",
    "neck": "neck",
    "left_collar": "left_collar", "right_collar": "right_collar",
    "head": "head",
    "left_shoulder": "left_shoulder", "right_shoulder": "right_shoulder",
    "left_elbow": "left_elbow", "right_elbow": "right_elbow",
    "left_wrist": "left_wrist", "right_wrist": "right_wrist",
}


@dataclass(frozen=True)
class Character:
    names: tuple[str, ...]
    parents: tuple[int, ...]
    kinds: tuple[str, ...]           # "none" (root), "spherical", "revolute", "fixed"
    offsets: np.ndarray              # (J, 3) attachment in the parent's frame, metres

    @classmethod
    def read(cls, path: str | Path) -> "Character":
        joints = json.loads(Path(path).read_text())["Skeleton"]["Joints"]
        joints = sorted(joints, key=lambda j: j["ID"])
        parents = tuple(int(j["Parent"]) for j in joints)
        if any(p >= i for i, p in enumerate(parents)):
            raise ValueError(f"{path}: joints are not ordered parents-first")
        if any(abs(j.get(f"AttachTheta{a}", 0.0)) > 1e-9 for j in joints for a in "XYZ"):
            raise ValueError(f"{path}: rotated attachments are not supported")
        return cls(tuple(j["Name"] for j in joints), parents, tuple(j["Type"] for j in joints),
                   np.array([[j["AttachX"], j["AttachY"], j["AttachZ"]] for j in joints], dtype=np.float64))

    @property
    def values_per_frame(self) -> int:
        per = {"none": 7, "spherical": 4, "revolute": 1, "fixed": 0}
        return 1 + sum(per[k] for k in self.kinds)


def find_character(motion_path: str | Path) -> Path:
    """characters/humanoid3d.txt in the data root above motions/<clip>.txt."""
    for folder in Path(motion_path).resolve().parents:
        if (folder / "characters" / "humanoid3d.txt").is_file():
            return folder / "characters" / "humanoid3d.txt"
    raise ValueError(f"no characters/humanoid3d.txt found above {motion_path}; pass character=")


def read_frames(path: str | Path) -> tuple[np.ndarray, str]:
    """(T, 44) values of a motion file and its "Loop" mode."""
    data = json.loads(Path(path).read_text())
    frames = np.asarray(data["Frames"], dtype=np.float64)
    if frames.ndim != 2 or frames.shape[1] != VALUES_PER_FRAME or len(frames) < 2:
        raise ValueError(f"{path}: expected ≥ 2 frames of {VALUES_PER_FRAME} values, got {frames.shape}")
    return frames, str(data.get("Loop", "none"))


def forward_kinematics(values: np.ndarray, character: Character) -> dict[str, np.ndarray]:
    """Global positions {joint or virtual joint: (T, 3)} (metres, the file's axes) from
    frames (T, 44)."""
    t = len(values)
    col = 1
    glob: list[np.ndarray] = []
    pos: list[np.ndarray] = []
    for j, (kind, parent) in enumerate(zip(character.kinds, character.parents)):
        if kind == "none":
            root = values[:, col:col + 3]
            local = quat_to_matrix(values[:, col + 3:col + 7])
            col += 7
        elif kind == "spherical":
            local = quat_to_matrix(values[:, col:col + 4])
            col += 4
        elif kind == "revolute":
            local = axis_rotation("Z", values[:, col])
            col += 1
        elif kind == "fixed":
            local = np.broadcast_to(np.eye(3), (t, 3, 3))
        else:
            raise ValueError(f"unknown joint type {kind!r}")
        if parent < 0:
            glob.append(local)
            pos.append(root)
        else:
            glob.append(glob[parent] @ local)
            pos.append(pos[parent] + np.einsum("tij,j->ti", glob[parent], character.offsets[j]))
    named = {n: pos[i] for i, n in enumerate(character.names)}
    for name, (on, offset) in VIRTUAL.items():
        i = character.names.index(on)
        named[name] = pos[i] + np.einsum("tij,j->ti", glob[i], np.asarray(offset))
    return named


def resample_times(x: np.ndarray, times: np.ndarray, fps: float = sk.FPS) -> np.ndarray:
    """Linear resampling along axis 0 from sample times (T,) (seconds, increasing) onto a
    uniform grid at fps starting at times[0]."""
    t_new = times[0] + np.arange(int(np.floor((times[-1] - times[0]) * fps + 1e-6)) + 1) / fps
    hi = np.clip(np.searchsorted(times, t_new, side="right"), 1, len(times) - 1)
    lo = hi - 1
    w = ((t_new - times[lo]) / np.maximum(times[hi] - times[lo], 1e-12)).clip(0.0, 1.0)
    w = w.reshape((-1,) + (1,) * (x.ndim - 1))
    return x[lo] * (1 - w) + x[hi] * w


def load_deepmimic(path: str | Path, character: str | Path | None = None) -> tuple[np.ndarray, np.ndarray, dict]:
    """One DeepMimic motion → (joints (T, 22, 3) at 20 fps, metres, Y up, canonical; offsets
    (22, 3); meta with the stated and decided rates, the evidence, the contact check and any
    defects)."""
    char_path = Path(character) if character is not None else find_character(path)
    char = Character.read(char_path)
    values, loop = read_frames(path)
    if values.shape[1] != char.values_per_frame:
        raise ValueError(f"{path}: {values.shape[1]} values per frame, the character needs {char.values_per_frame}")
    durations = values[:-1, 0]
    if np.any(durations <= 0):
        raise ValueError(f"{path}: frame durations must be positive (but the last)")
    named = forward_kinematics(values, char)
    native = map_joints(named, JOINT_MAP)
    stated = float(1.0 / np.median(durations))
    stated = float(round(stated)) if abs(stated - round(stated)) < 0.005 * stated else round(stated, 3)
    meta: dict = {"skeleton": "deepmimic-humanoid3d", "frames_native": len(values), "loop": loop,
                  "durations_s": sorted({round(float(d), 5) for d in durations}), "defects": []}
    # The stated timing stands (see the module docstring); the estimate is recorded.
    fps = decide_rate(native, stated, (stated, 2 * stated, stated / 2), meta, keep_stated=True)
    times = np.concatenate([[0.0], np.cumsum(durations)]) * (stated / fps)
    joints = resample_times(native, times)
    fitted, offsets = fit_to_skeleton(joints)
    record_fit(fitted, joints, meta)
    return settle(fitted, meta), offsets, meta


__all__ = ["Character", "JOINT_MAP", "PROMPTS", "VIRTUAL", "clip_name", "deepmimic_prompt", "find_character", "read_frames", "forward_kinematics",
           "resample_times", "load_deepmimic"]
