"""Plain data types for motions: a `Clip` (one labelled capture, one or two people) and the
processed data set stored in the repo (`models/data/`), loaded once and shared.

Storage (written by `interplay data build`, read here):
  models/data/<source>.npz  per source (so each licence's derived data stays in its own file:
                            HDM05 is CC BY-SA, CMU has its own terms): joints (N, 22, 3) float16,
                            every person-frame of that source's clips concatenated; offsets
                            (P, 22, 3) float32, one row per person.
  models/data/index.json    {"fps": 20, "clips": [ClipMeta...]} with, per clip, its file and its
                            people as (start, frames, offsets_row) into that file's arrays.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

import numpy as np

from interplay.motion.skeleton import FPS

DATA_DIR = Path(__file__).resolve().parents[3] / "models" / "data"


@dataclass
class Caption:
    """An automatic part caption over frames [start, end) (end exclusive)."""
    start: int
    end: int
    part: str  # "body", "left_upper", "right_upper", "left_lower", "right_lower"
    text: str


@dataclass
class Clip:
    id: str                      # e.g. "cmu:02_01", "salsa:05", "hdm05:HDM_bd_squat1Reps_001_120"
    source: str                  # "cmu-bvh", "cmu-salsa", "hdm05", "cmu-8action"
    people: list[np.ndarray]     # one (T, 22, 3) float array per person, metres, 20 fps
    offsets: list[np.ndarray]    # one (22, 3) rest-offset array per person
    label: str                   # raw label from the source ("run/jog", "kickLFront1Reps")
    prompt: str                  # cleaned short prompt ("a person jogs")
    split: str = "train"         # "train" | "val" | "test", by trial
    captions: list[Caption] = field(default_factory=list)
    synthetic: bool = False
    licence: str = "CMU"
    meta: dict = field(default_factory=dict)  # provenance: file, native fps, transform …

    @property
    def frames(self) -> int:
        return int(self.people[0].shape[0])

    @property
    def seconds(self) -> float:
        return self.frames / FPS


def save_clips(clips: list[Clip], out_dir: Path) -> None:
    out_dir.mkdir(parents=True, exist_ok=True)
    metas = []
    for source in sorted({c.source for c in clips}):
        joints: list[np.ndarray] = []
        offsets: list[np.ndarray] = []
        start = 0
        for c in (c for c in clips if c.source == source):
            people = []
            for p, off in zip(c.people, c.offsets):
                people.append({"start": start, "frames": int(p.shape[0]), "offsets_row": len(offsets)})
                joints.append(p.astype(np.float16))
                offsets.append(off.astype(np.float32))
                start += p.shape[0]
            metas.append({
                "id": c.id, "source": c.source, "file": f"{source}.npz", "label": c.label,
                "prompt": c.prompt, "split": c.split, "synthetic": c.synthetic,
                "licence": c.licence, "people": people,
                "captions": [vars(cap) for cap in c.captions], "meta": c.meta,
            })
        np.savez_compressed(out_dir / f"{source}.npz", joints=np.concatenate(joints),
                            offsets=np.stack(offsets))
    (out_dir / "index.json").write_text(json.dumps({"fps": FPS, "clips": metas}, indent=1))


def load_clips(data_dir: Path = DATA_DIR) -> list[Clip]:
    data_dir = Path(data_dir)
    index = json.loads((data_dir / "index.json").read_text())
    arrays: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    clips = []
    for m in index["clips"]:
        if m["file"] not in arrays:
            with np.load(data_dir / m["file"]) as f:
                arrays[m["file"]] = (f["joints"].astype(np.float32), f["offsets"])
        joints, offsets = arrays[m["file"]]
        people = [joints[p["start"]:p["start"] + p["frames"]] for p in m["people"]]
        offs = [offsets[p["offsets_row"]] for p in m["people"]]
        clips.append(Clip(id=m["id"], source=m["source"], people=people, offsets=offs,
                          label=m["label"], prompt=m["prompt"], split=m["split"],
                          captions=[Caption(**c) for c in m["captions"]],
                          synthetic=m["synthetic"], licence=m["licence"], meta=m["meta"]))
    return clips


@lru_cache(maxsize=2)
def default_clips(data_dir: str = str(DATA_DIR)) -> tuple[Clip, ...]:
    """The processed data set, loaded once per process."""
    return tuple(load_clips(Path(data_dir)))
