"""The CMU 8-action motion-prediction set (38-joint exponential-map text files) → the 22-joint
SMPL layout.

Format (`skeleton.json` beside the train/ and test/ folders): one frame per line, 117 values:
values[0:3] root position, then joint j's exp-map rotation at values[3+3j:6+3j] (joint 0 is the
root). Forward kinematics as the file states, in row-vector form:
    R_j = Rodrigues(expmap_j); xyz_0 = offset_0 + root_position, Rg_0 = R_0;
    xyz_j = offset_j · Rg_p + xyz_p, Rg_j = R_j · Rg_p.
The source then reorders axes to (x, z, y) only to plot Z up; we keep the native frame, which
is Acclaim's: Y up, rest pose facing +Z, left side at +X (like ours; the reorder would mirror).

What the convention text leaves open, decided from the data (train/walking/1 unless said;
the frame rate over all 6 walking and 6 running files):
  * Root position units: the offsets are source units × 70 but values[0:3] are plain source
    units (standing root height ≈ 16.7), so they are scaled by 70 too. With that, stance feet
    move 0.09 m/s (at 120 fps) and the walk covers 3.4 m; unscaled, the body would not travel
    (5 cm) and stance feet would slide at 1.1 m/s.
  * Root position order: x, y, z as written. The source repo's fkl() reads them reversed
    (z, y, x); that makes walking travel sideways (travel·facing cosine -0.01 against 0.99
    as written) and stance feet slide at 1.6 m/s.
  * The first line of every file is a rest pose (107 of 114 rotation values exactly zero, then
    a jump of > 1 rad to line 2); it is dropped.
  * Metres: source units are CMU ASF units (inches × 0.45), so one offset unit is
    0.0254 / 0.45 / 70 m (femur 0.43 m, tibia 0.41 m).
  * Frame rate: 120 fps. Walking clips step 1.6–1.9 times/s at 0.9–1.4 m/s at 120 fps (0.8–0.9
    steps/s at 0.4–0.7 m/s if it were 60); running clips step 2.5–2.8 times/s at 2.6–3.5 m/s.
  * The thorax has zero length: the 38 joints carry CMU's six spine/neck rotations (lowerback,
    upperback, thorax, lowerneck, upperneck, head at joints 13–18) but joint 16 (the thorax end,
    where CMU's clavicles and lower neck start) has a zero offset, so the torso comes out
    12 cm short: lowerback+upperback+thorax+lowerneck over femur+tibia is 0.38, against
    0.58–0.66 for HDM05's five actors. We restore it with the upperback's offset (CMU's
    thorax and upperback bones are near-equal) at joint 16 and the two clavicle starts
    (20, 29), which gives 0.52 and keeps every rotation where the source put it.
    `restore_thorax=False` gives the file's skeleton.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from interplay.motion.retarget import canonicalize, to_smpl22
from interplay.motion.retarget.hdm05 import JOINT_MAP as ACCLAIM_JOINT_MAP
from interplay.motion.rotations import axis_angle_to_matrix

FPS_8ACTION = 120.0
VALUES_PER_FRAME = 117
ROOT_POSITION_SCALE = 70.0           # values[0:3] are in source units, offsets in units × 70
METRES_PER_UNIT = 0.0254 / 0.45 / ROOT_POSITION_SCALE

# Each joint named for the Acclaim bone it ends ("…_start" joints carry no offset).
JOINT_NAMES: tuple[str, ...] = (
    "root", "lhipjoint_start", "lhipjoint", "lfemur", "ltibia", "lfoot", "ltoes",
    "rhipjoint_start", "rhipjoint", "rfemur", "rtibia", "rfoot", "rtoes",
    "lowerback_start", "lowerback", "upperback", "thorax", "lowerneck", "upperneck", "head",
    "lclavicle_start", "lclavicle", "lhumerus", "lradius", "lwrist_start", "lwrist", "lhand",
    "lthumb_start", "lthumb",
    "rclavicle_start", "rclavicle", "rhumerus", "rradius", "rwrist_start", "rwrist", "rhand",
    "rthumb_start", "rthumb",
)
_IDX = {n: i for i, n in enumerate(JOINT_NAMES)}
_THORAX_JOINTS = (_IDX["thorax"], _IDX["lclavicle_start"], _IDX["rclavicle_start"])

PROMPTS: dict[str, str] = {
    "basketball": "a person dribbles and shoots a basketball",
    "basketball_signal": "a person makes basketball referee signals with the arms",
    "directing_traffic": "a person directs traffic with arm signals",
    "jumping": "a person jumps",
    "running": "a person runs forward",
    "soccer": "a person dribbles and kicks a soccer ball",
    "walking": "a person walks forward",
    "washwindow": "a person washes a window",
}


@dataclass(frozen=True)
class ExpMapSkeleton:
    parents: tuple[int, ...]      # (38,), -1 for the root, parents-first
    offsets: np.ndarray           # (38, 3) source units × 70, in the parent's frame

    @classmethod
    def from_json(cls, path: str | Path) -> "ExpMapSkeleton":
        data = json.loads(Path(path).read_text())
        parents = tuple(int(p) for p in data["parent"])
        offsets = np.asarray(data["offset"], dtype=np.float64)
        if offsets.shape != (len(parents), 3) or len(parents) != len(JOINT_NAMES):
            raise ValueError(f"{path}: expected {len(JOINT_NAMES)} parents and (38, 3) offsets, "
                             f"got {len(parents)} and {offsets.shape}")
        if any(p >= j for j, p in enumerate(parents)):
            raise ValueError(f"{path}: joints are not ordered parents-first")
        return cls(parents, offsets)

    def with_thorax(self) -> "ExpMapSkeleton":
        """The skeleton with its zero-length thorax given the upperback's offset."""
        offsets = self.offsets.copy()
        offsets[list(_THORAX_JOINTS)] = offsets[_IDX["upperback"]]
        return ExpMapSkeleton(self.parents, offsets)


def find_skeleton(path: str | Path) -> Path:
    """skeleton.json in the data root above a <root>/<split>/<action>/<file>.txt path."""
    for folder in Path(path).resolve().parents:
        if (folder / "skeleton.json").is_file():
            return folder / "skeleton.json"
    raise ValueError(f"no skeleton.json found above {path}; pass skeleton=")


def read_frames(path: str | Path) -> np.ndarray:
    """(T, 117) values of a text file, one frame per line."""
    rows = [line for line in Path(path).read_text().splitlines() if line.strip()]
    values = np.array([[float(v) for v in line.split(",")] for line in rows]) if rows else np.zeros((0, 0))
    if values.ndim != 2 or values.shape[1] != VALUES_PER_FRAME:
        raise ValueError(f"{path}: expected {VALUES_PER_FRAME} comma-separated values per line, "
                         f"got shape {values.shape}")
    return values


def drop_rest_frames(values: np.ndarray) -> tuple[np.ndarray, int]:
    """Drop leading rest-pose lines (≥ 90% of rotation values exactly zero)."""
    zero = (values[:, 3:] == 0).mean(axis=1) >= 0.9
    n = int(np.argmin(zero)) if not zero.all() else len(values)
    return values[n:], n


def forward_kinematics(values: np.ndarray, skeleton: ExpMapSkeleton) -> np.ndarray:
    """Positions (T, 38, 3) in offset units (source × 70), native axes (Y up), from values
    (T, 117), following skeleton.json's row-vector convention."""
    t = values.shape[0]
    local = axis_angle_to_matrix(values[:, 3:].reshape(t, len(skeleton.parents), 3))
    root = values[:, :3] * ROOT_POSITION_SCALE
    pos = np.empty((t, len(skeleton.parents), 3))
    glob = np.empty_like(local)
    for j, p in enumerate(skeleton.parents):
        if p < 0:
            pos[:, j] = skeleton.offsets[j] + root
            glob[:, j] = local[:, j]
        else:
            pos[:, j] = skeleton.offsets[j] @ glob[:, p] + pos[:, p]   # row vector · matrix
            glob[:, j] = local[:, j] @ glob[:, p]
    return pos


def load_cmu_8action(path: str | Path, fps: float | None = None, skeleton: str | Path | None = None,
                     restore_thorax: bool = True) -> tuple[np.ndarray, np.ndarray, dict]:
    """One 8-action file → (joints (T, 22, 3) at 20 fps in metres, Y up, canonicalised: floor
    at y=0, pelvis at the XZ origin facing +Z on the first frame; offsets (22, 3); meta).
    fps defaults to the measured 120; skeleton to the skeleton.json above the file."""
    fps = FPS_8ACTION if fps is None else float(fps)
    if fps <= 0:
        raise ValueError(f"fps must be positive, got {fps}")
    skel_path = Path(skeleton) if skeleton is not None else find_skeleton(path)
    skel = ExpMapSkeleton.from_json(skel_path)
    if restore_thorax:
        skel = skel.with_thorax()
    values, dropped = drop_rest_frames(read_frames(path))
    if len(values) < 2:
        raise ValueError(f"{path}: fewer than two motion frames")
    pos = forward_kinematics(values, skel)
    named = {n: pos[:, i] for i, n in enumerate(JOINT_NAMES)}
    fitted, offsets, raw = to_smpl22(named, ACCLAIM_JOINT_MAP, fps=fps, scale=METRES_PER_UNIT)
    fit_error = float(np.linalg.norm(fitted - raw, axis=-1).mean())
    (joints,), transform = canonicalize([fitted])
    meta = {
        "source_fps": fps,
        "source_frames": int(len(values)),
        "dropped_rest_frames": dropped,
        "metres_per_unit": METRES_PER_UNIT,
        "thorax_restored": restore_thorax,
        "fit_error_m": fit_error,
        "canonical": transform,
    }
    return joints, offsets, meta


def cmu_8action_prompt(action: str) -> str:
    """Short prompt for an action folder name ("walking"), a file stem ("walking_3") or
    "walking_extra"."""
    key = action.strip().lower()
    if key not in PROMPTS:
        base = key.rsplit("_", 1)[0] if key.rsplit("_", 1)[-1].isdigit() or key.endswith("_extra") else key
        key = base
    if key not in PROMPTS:
        raise ValueError(f"unknown cmu-8action action {action!r}; expected one of {sorted(PROMPTS)}")
    return PROMPTS[key]
