"""The captures' own head and hand orientations, where the library carries them: side files
models/data/leaves/<source>.npz written by `interplay data leaves` (`data/leaves.py`, which
says what each holds), next to the positions they belong to, never inside them.

    world = captured_world("cmu:02_01", 0)       # {"head": (T, 4), ...} world, w x y z; {} if none
    local = captured_local(joints, world)        # → solve_rig(joints, leaves=local)

`captured_local` turns world orientations into the rig's leaf rotations: each relative to its
parent bone as `rig.solve_rig` solves it for these joints (the head on the neck, a hand on its
forearm), so the exported hand or head turns the way the capture's did, whatever twist the
solver gave the parent. numpy only; reads models/data only.
"""

from __future__ import annotations

import json
from functools import lru_cache
from pathlib import Path

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.clip import DATA_DIR

LEAF_NAMES: tuple[str, ...] = ("head", "left_wrist", "right_wrist")


def leaves_file(source: str, data_dir: Path | str = DATA_DIR) -> Path:
    """A source's side file (a folder of its own: the library's own files are data_dir/*.npz)."""
    return Path(data_dir) / "leaves" / f"{source}.npz"


@lru_cache(maxsize=8)
def _load(data_dir: str) -> dict[tuple[str, int], np.ndarray]:
    """{(clip id, person): (T, 3, 4) float32} over every side file in data_dir."""
    out: dict[tuple[str, int], np.ndarray] = {}
    for path in sorted((Path(data_dir) / "leaves").glob("*.npz")):
        with np.load(path) as f:
            quats = f["quats"].astype(np.float32)
            index = json.loads(str(f["index"]))
        for row in index:
            out[row["id"], int(row["person"])] = quats[row["start"]:row["start"] + row["frames"]]
    return out


def captured_world(clip_id: str, person: int = 0, frames: int | None = None,
                   data_dir: Path | str = DATA_DIR) -> dict[str, np.ndarray]:
    """The capture's world orientations {leaf: (T, 4)} (unit, w x y z, the library's canonical
    frame) of a library clip's person; {} where the library carries none, or where `frames`
    is given and differs (a side file from another build of the library)."""
    q = _load(str(data_dir)).get((clip_id, int(person)))
    if q is None or (frames is not None and len(q) != frames):
        return {}
    q = q.astype(np.float64)
    q /= np.linalg.norm(q, axis=-1, keepdims=True)
    return {leaf: q[:, i] for i, leaf in enumerate(LEAF_NAMES)}


def captured_local(joints: np.ndarray, world: dict[str, np.ndarray], *, fps: float = sk.FPS,
                   floor: float | None = None) -> dict[str, np.ndarray]:
    """World leaf orientations {leaf: (T, 4)} (frames of `joints` (T, 22, 3), the same world)
    → the rig's local leaf rotations {leaf: (T, 4)}, w x y z, one sign through time: each
    relative to its parent's global rotation in `solve_rig(joints)`."""
    from interplay.motion.rig import continuous, global_rotations, solve_rig
    from interplay.motion.rotations import matrix_to_quat, quat_to_matrix
    if not world:
        return {}
    glob = global_rotations(solve_rig(joints, fps=fps, floor=floor))
    out = {}
    for leaf, q in world.items():
        parent = glob[:, sk.PARENTS[sk.JOINT_INDEX[leaf]]]
        local = np.swapaxes(parent, -1, -2) @ quat_to_matrix(np.asarray(q, np.float64))
        out[leaf] = continuous(matrix_to_quat(local)[:, None])[:, 0]
    return out
