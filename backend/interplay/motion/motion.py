"""`Motion`: a generated motion for one or two people, and its JSON form.

Motion JSON, version 1 (what the stream, the store and motion files use):
{"fps": 20, "skeleton": "smpl22", "people": [{"joints": [[[x, y, z] × 22] × T]}],
"plan": {...}, "metrics": {...}} plus optional "highlights", "prompt", "seed". Joints are
rounded to 0.1 mm in JSON.

Version 2 (the exports: `to_json(rig=True)`) adds the skeleton, so that a rig can be driven
without solving rotations: "schema": "interplay.motion/2", "joint_names" and "parents" (22,
SMPL order, -1 for the root), "rig_convention" (a short description), and per person "rig":
{"offsets": [[x, y, z] × 22] (rest offsets, metres, parent → child in the parent's rest frame;
the rest pose faces +Z, Y up; the root row is the rest pelvis height), "root": [[x, y, z] × T]
(pelvis positions), "rotations": [[[w, x, y, z] × 22] × T] (local unit quaternions, each
relative to its parent, the pelvis's global, identity at rest; from `rig.solve_rig`)}. Offsets
and root are rounded to 1 µm and quaternions to 1e-6, so forward kinematics of the rig gives
the joints back well within 1 mm. `from_json` reads both versions (a version-1 file has no
"schema"); the joints stay the motion's truth, the rig is derived from them.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from interplay.motion.skeleton import FPS, JOINT_NAMES, NUM_JOINTS, PARENTS, SKELETON_NAME

DECIMALS = 4  # metres → 0.1 mm
SCHEMA_V2 = "interplay.motion/2"
SCHEMAS = (SCHEMA_V2,)          # "schema" values from_json reads (none: version 1)
RIG_DECIMALS = 6                # offsets and root: 1 µm; quaternions: 1e-6
RIG_CONVENTION = ("local rotations as unit quaternions (w, x, y, z), each relative to its "
                  "parent (the pelvis's global); identity is the rest pose given by the "
                  "offsets (metres, parent to child, facing +Z, Y up); root: pelvis positions")


def validate_people(people: list) -> list[np.ndarray]:
    """People as float32 arrays (T, 22, 3), checked: 1–2 people, same length, finite, ≥1 frame."""
    if not isinstance(people, (list, tuple)) or not 1 <= len(people) <= 2:
        n = len(people) if isinstance(people, (list, tuple)) else type(people).__name__
        raise ValueError(f"a motion has 1 or 2 people, got {n}")
    out = []
    for i, p in enumerate(people):
        try:
            a = np.asarray(p, dtype=np.float32)
        except (ValueError, TypeError) as exc:
            raise ValueError(f"person {i}: joints are not a regular T×22×3 array "
                             f"(ragged frames or non-numbers): {exc}") from None
        if a.ndim != 3 or a.shape[1:] != (NUM_JOINTS, 3):
            raise ValueError(f"person {i}: joints must have shape (T, {NUM_JOINTS}, 3), "
                             f"got {a.shape}")
        if a.shape[0] < 1:
            raise ValueError(f"person {i}: a motion needs at least one frame")
        if not np.isfinite(a).all():
            raise ValueError(f"person {i}: joints contain NaN or infinite values")
        out.append(a)
    lengths = [a.shape[0] for a in out]
    if len(set(lengths)) > 1:
        raise ValueError(f"people have different lengths {lengths}; they must share frames")
    return out


@dataclass
class Motion:
    people: list[np.ndarray]            # one (T, 22, 3) float32 array per person, metres, Y up
    fps: int = FPS
    plan: dict = field(default_factory=dict)
    metrics: dict = field(default_factory=dict)
    highlights: dict | None = None
    prompt: str = ""
    seed: int | None = None

    def __post_init__(self):
        self.people = validate_people(self.people)
        if self.fps != FPS:
            raise ValueError(f"motions are {FPS} fps, got {self.fps}")

    @property
    def frames(self) -> int:
        return int(self.people[0].shape[0])

    @property
    def seconds(self) -> float:
        return self.frames / self.fps

    def to_json(self, rig: bool = False) -> dict:
        """The Motion JSON (plain lists, joints rounded to 0.1 mm): version 1, or with rig=True
        version 2, which adds the skeleton and each person's rig (see the module)."""
        d: dict = {
            "fps": self.fps, "skeleton": SKELETON_NAME,
            "people": [{"joints": np.round(p.astype(np.float64), DECIMALS).tolist()}
                       for p in self.people],
            "plan": self.plan, "metrics": self.metrics,
        }
        if rig:
            from interplay.motion.kinematics import floor_height
            from interplay.motion.rig import solve_rig
            people = [p.astype(np.float64) for p in self.people]
            floor = floor_height(people)
            d = {"schema": SCHEMA_V2, **d, "joint_names": list(JOINT_NAMES),
                 "parents": list(PARENTS), "rig_convention": RIG_CONVENTION}
            for person, joints in zip(d["people"], people):
                r = solve_rig(joints, floor=floor)
                person["rig"] = {key: np.round(value, RIG_DECIMALS).tolist() for key, value in
                                 (("offsets", r.offsets), ("root", r.root), ("rotations", r.rotations))}
        if self.highlights is not None:
            d["highlights"] = self.highlights
        if self.prompt:
            d["prompt"] = self.prompt
        if self.seed is not None:
            d["seed"] = self.seed
        return d

    @classmethod
    def from_json(cls, d: dict) -> "Motion":
        """A Motion from its JSON; ValueError with a readable message when malformed."""
        if not isinstance(d, dict):
            raise ValueError("motion JSON must be an object")
        if d.get("fps", FPS) != FPS:
            raise ValueError(f"motion JSON must be {FPS} fps, got {d.get('fps')!r}")
        schema = d.get("schema")
        if schema is not None and schema not in SCHEMAS:
            raise ValueError(f"unknown motion JSON schema {schema!r}; this version reads "
                             f"{', '.join(SCHEMAS)} and version 1 (no 'schema')")
        if d.get("skeleton", SKELETON_NAME) != SKELETON_NAME:
            raise ValueError(f"unknown skeleton {d.get('skeleton')!r}, expected {SKELETON_NAME!r}")
        people = d.get("people")
        if not isinstance(people, list):
            raise ValueError("motion JSON needs 'people': a list of {'joints': [...]}")
        joints = []
        for i, p in enumerate(people):
            if not isinstance(p, dict) or "joints" not in p:
                raise ValueError(f"person {i}: expected an object with 'joints'")
            if schema == SCHEMA_V2 and not isinstance(p.get("rig"), dict):
                raise ValueError(f"person {i}: a {SCHEMA_V2} motion needs each person's 'rig'")
            joints.append(p["joints"])
        for key in ("plan", "metrics"):
            if not isinstance(d.get(key) or {}, dict):
                raise ValueError(f"'{key}' must be an object")
        highlights = d.get("highlights")
        if highlights is not None and not isinstance(highlights, dict):
            raise ValueError("'highlights' must be an object or null")
        seed = d.get("seed")
        if seed is not None and (not isinstance(seed, int) or isinstance(seed, bool)):
            raise ValueError(f"'seed' must be an integer, got {seed!r}")
        return cls(people=joints, plan=d.get("plan") or {}, metrics=d.get("metrics") or {},
                   highlights=highlights, prompt=str(d.get("prompt") or ""), seed=seed)
