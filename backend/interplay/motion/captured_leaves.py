"""The captures' own head, hand and toe orientations, where the library carries them (the
exports take the head and hands, EXPORTED): side files
models/data/leaves/<source>.npz written by `interplay data leaves` (`data/leaves.py`, which
says what each holds), next to the positions they belong to, never inside them.

    world = captured_world("cmu:02_01", 0)       # {"head": (T, 4), ...} world, w x y z; {} if none
    local = captured_local(joints, world)        # → solve_rig(joints, leaves=local)

`captured_local` turns world orientations into the rig's leaf rotations: each relative to its
parent bone as `rig.solve_rig` solves it for these joints (the head on the neck, a hand on its
forearm, a toe on its ankle), so the exported hand or head turns the way the capture's did, whatever twist the
solver gave the parent. numpy only; reads models/data only.
"""

from __future__ import annotations

import json
from functools import lru_cache
from pathlib import Path

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.clip import DATA_DIR

LEAF_NAMES: tuple[str, ...] = ("head", "left_wrist", "right_wrist", "left_foot", "right_foot")
HANDS: tuple[str, ...] = ("left_wrist", "right_wrist")
TOES: tuple[str, ...] = ("left_foot", "right_foot")       # the rig's toe joints (SMPL's "foot")
# The leaves the exports take from a capture: not the toes, which the side files hold but which
# look worse than the rig's own where the rig's foot is not the capture's: on planted feet a
# carried toe sits 21–28° (median) off the rig's ankle frame, which the mesh shows as a kink
# at the ball, and some captures flip a toe 176–178° (HDM05's bd kicks); the rig's toes bend
# off the floor themselves (`rig/leaves.py`).
EXPORTED: tuple[str, ...] = ("head", *HANDS)


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
            if quats.shape[1] < len(LEAF_NAMES):               # a file from before the toes
                pad = np.full((len(quats), len(LEAF_NAMES) - quats.shape[1], 4), np.nan, np.float32)
                quats = np.concatenate([quats, pad], axis=1)
            index = json.loads(str(f["index"]))
        for row in index:
            out[row["id"], int(row["person"])] = quats[row["start"]:row["start"] + row["frames"]]
    return out


def captured_world(clip_id: str, person: int = 0, frames: int | None = None,
                   data_dir: Path | str = DATA_DIR) -> dict[str, np.ndarray]:
    """The capture's world orientations {leaf: (T, 4)} (unit, w x y z, the library's canonical
    frame) of a library clip's person, the leaves its source carries; {} where the library
    carries none, or where `frames` is given and differs (a side file from another build)."""
    q = _load(str(data_dir)).get((clip_id, int(person)))
    if q is None or (frames is not None and len(q) != frames):
        return {}
    q = q.astype(np.float64)
    q /= np.linalg.norm(q, axis=-1, keepdims=True)
    # a leaf the source has no channel for is stored as NaN (DeepMimic's fixed wrists)
    return {leaf: q[:, i] for i, leaf in enumerate(LEAF_NAMES) if np.isfinite(q[:, i]).all()}


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


# Frames over which retrieval's stitcher cross-fades each piece from the last one's
# continuation (`generators/retrieval/stitch.FADE`; a test keeps the two equal): the leaves
# are cross-faded over the same frames with the same smoothstep weights, by slerp.
FADE = 10
_MIRROR_SWAP = {"head": "head", "left_wrist": "right_wrist", "right_wrist": "left_wrist",
                "left_foot": "right_foot", "right_foot": "left_foot"}


@lru_cache(maxsize=64)
def _source_local(clip_id: str, person: int, data_dir: str = str(DATA_DIR)) -> dict[str, np.ndarray]:
    """A library clip person's captured leaves as the rig's local rotations on its own joints."""
    from interplay.motion.clip import default_clips
    from interplay.motion.kinematics import floor_height
    clip = next((c for c in default_clips(data_dir) if c.id == clip_id), None)
    if clip is None or person >= len(clip.people):
        return {}
    people = [np.asarray(p, np.float64) for p in clip.people]
    world = {k: v for k, v in captured_world(clip_id, person, len(people[person]), data_dir).items()
             if k in EXPORTED}
    return captured_local(people[person], world, floor=floor_height(people)) if world else {}


def _view_local(view: str, person: int) -> dict[str, np.ndarray]:
    """The local leaves of a retrieval view of a clip ("<id>", "<id>#mirrored", "#reversed",
    both; `generators/retrieval/views.py`): mirrored left ↔ right (a reflection x → -x turns
    a rotation's quaternion (w, x, y, z) into (w, x, -y, -z)), reversed in time."""
    base, *marks = view.split("#")
    local = _source_local(base, person)
    if "mirrored" in marks:
        flip = np.array([1.0, 1.0, -1.0, -1.0])
        local = {_MIRROR_SWAP[k]: v * flip for k, v in local.items()}
    if "reversed" in marks:
        local = {k: v[::-1] for k, v in local.items()}
    return local


def _tracks(seg: dict) -> list[list[tuple[str, int, int, int]]]:
    """Per person, a segment's pieces as (view, source person, start, end)."""
    choice = seg["retrieval"]
    if choice["mode"] == "pair":
        return [[(p["clip"], int(p["people"][i]), int(p["start"]), int(p["end"])) for p in choice["tracks"][0]]
                for i in range(len(choice["tracks"][0][0]["people"]))]
    return [[(p["clip"], int(p["people"][0]), int(p["start"]), int(p["end"])) for p in track]
            for track in choice["tracks"]]


def _faded(cont: np.ndarray, new: np.ndarray) -> np.ndarray:
    """The first n = len(cont) rows of `new` (n', 4) cross-faded from `cont` (n, 4) as
    `stitch.crossfade` fades positions (smoothstep of i / (n + 1)), by slerp; NaN where
    either is."""
    from interplay.motion.rig import slerp
    out = new.copy()
    n = len(cont)
    x = np.arange(1, n + 1) / (n + 1)
    ok = np.isfinite(cont).all(-1) & np.isfinite(new[:n]).all(-1)
    out[:n][~ok] = np.nan
    out[:n][ok] = slerp(cont[ok], new[:n][ok], (x * x * (3 - 2 * x))[ok])
    return out


def piece_leaves(plan: dict | None, persons: int, frames: int) -> list[dict[str, np.ndarray]]:
    """Per person, the captured leaves (frames, 4) of the frames a plan's captured pieces give
    (`generators/plan.CapturePiece`: clip or view, people, frames [start, end), laid end to end
    over each segment), as retrieval's stitcher plays them: each piece after the first
    cross-faded over its first FADE frames from the last one's continuation (that capture's
    next frames, or its last leaf held where it has none, or a held pose's), a track shorter
    than its segment holding its last leaf; NaN rows where a capture carries none. [{}…] where
    none carries any or the plan does not fit. Any generator's plan: the caller knows whether
    its frames are the pieces' (`plan_leaves`: retrieval's; `generators/retrieve_edit/
    leaves.py` masks what its edits changed)."""
    empty: list[dict[str, np.ndarray]] = [{} for _ in range(persons)]
    if not isinstance(plan, dict):
        return empty
    out = [np.full((len(LEAF_NAMES), frames, 4), np.nan) for _ in range(persons)]
    # per person, the last piece's (view leaves (3, T, 4), its end) or None after a hold
    last: list[tuple[np.ndarray, int] | None] = [None] * persons
    started = [False] * persons
    try:
        for seg in plan.get("segments") or []:
            if not seg.get("retrieval"):
                return empty
            for person, track in enumerate(_tracks(seg)):
                if person >= persons:
                    return empty
                at, mine = int(seg["start"]), out[person]
                for ref, source, s, e in track:
                    local = _view_local(ref, source)
                    n = max((len(q) for q in local.values()), default=e)
                    if e > n or at + e - s > frames:
                        return empty
                    view = np.stack([local.get(leaf, np.full((n, 4), np.nan)) for leaf in LEAF_NAMES])
                    block = view[:, s:e].copy()
                    if started[person]:
                        k = min(FADE, e - s)
                        prev = last[person]
                        # the continuation: the last capture's next frames, then its last row held
                        tail = prev[0][:, prev[1]:prev[1] + k] if prev is not None else mine[:, :0]
                        held = tail[:, -1:] if tail.shape[1] else mine[:, at - 1:at]
                        cont = np.concatenate([tail, np.repeat(held, k - tail.shape[1], axis=1)], axis=1)
                        block = np.stack([_faded(cont[i], block[i]) for i in range(len(LEAF_NAMES))])
                    mine[:, at:at + e - s] = block
                    last[person], started[person], at = (view, e), True, at + e - s
                if at < int(seg["end"]):                   # the stitcher holds the last pose
                    mine[:, at:int(seg["end"])] = mine[:, at - 1:at]
                    last[person] = None
    except (KeyError, TypeError, ValueError, IndexError):
        return empty
    leaves = [{leaf: person[i] for i, leaf in enumerate(LEAF_NAMES) if np.isfinite(person[i]).any()}
              for person in out]
    return leaves if any(leaves) else empty


def plan_leaves(plan: dict | None, persons: int, frames: int) -> list[dict[str, np.ndarray]]:
    """`piece_leaves` for the retrieval generator's plans, whose frames are the pieces' (turned
    and placed, which leaves the local rotations as they are); [{}…] for any other plan."""
    if not isinstance(plan, dict) or plan.get("generator") != "retrieval":
        return [{} for _ in range(persons)]
    return piece_leaves(plan, persons, frames)


def resample_leaves(q: np.ndarray, rate: float, frames: int) -> np.ndarray:
    """Leaves (n, 4) (NaN rows: none) played at `rate` ≤ 1, as `kinematics.resample(x, 20·rate,
    20)` plays positions (output frame i at input time i·rate), by slerp between the two
    neighbours (NaN where either is), the last played row held to `frames` rows."""
    from interplay.motion.rig import slerp
    q = np.asarray(q, np.float64)
    n = len(q)
    if n < 2 or abs(rate - 1.0) < 1e-9:
        played = q.copy()
    else:
        pos = np.arange(int(np.floor((n - 1) / rate + 1e-6)) + 1) * rate
        lo = np.clip(np.floor(pos).astype(int), 0, n - 1)
        hi = np.where(pos - lo < 1e-9, lo, np.clip(lo + 1, 0, n - 1))    # on a frame: that frame
        ok = np.isfinite(q[lo]).all(-1) & np.isfinite(q[hi]).all(-1)
        played = np.full((len(pos), 4), np.nan)
        played[ok] = slerp(q[lo][ok], q[hi][ok], (pos - lo)[ok])
    pad = np.repeat(played[-1:], max(0, frames - len(played)), axis=0)
    return np.concatenate([played, pad])[:frames]
