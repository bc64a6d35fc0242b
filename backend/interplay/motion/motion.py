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

Either version may give a person explicit rotations of the joints the 22 positions do not
turn (the leaves: "head", "left_wrist", "right_wrist"): per person "leaves": {"head": [[w, x,
y, z] × T], …} (local unit quaternions, as the rig's; e.g. a head edit's nod), which every
export (BVH, GLB, the rig of version 2) uses in place of the rotations it would derive
(`rig.solve_rig(..., leaves=…)`). Absent when unset; files without it read and export as
before. An edit stores them in its plan (plan["leaves"], one object per person), which
`Motion` lifts into the people's "leaves" (`leaves_in`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from interplay.motion.rig.leaves import LEAVES
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


def validate_leaves(leaves: object, persons: int, frames: int) -> list[dict[str, np.ndarray]]:
    """Per-person explicit leaf rotations as float64 arrays (T, 4), checked: one object (or
    None) per person, names among LEAVES, finite (T, 4) quaternions."""
    if not isinstance(leaves, (list, tuple)) or len(leaves) != persons:
        raise ValueError(f"'leaves' must give one object per person ({persons})")
    out = []
    for i, given in enumerate(leaves):
        if given is None:
            given = {}
        if not isinstance(given, dict):
            raise ValueError(f"person {i}: 'leaves' must be an object of joint → rotations")
        person = {}
        for name, q in given.items():
            if name not in LEAVES:
                raise ValueError(f"person {i}: leaves are {', '.join(LEAVES)}, got {name!r}")
            try:
                a = np.asarray(q, dtype=np.float64)
            except (ValueError, TypeError):
                raise ValueError(f"person {i}: leaves[{name!r}] is not a T×4 array") from None
            if a.shape != (frames, 4) or not np.isfinite(a).all() or (np.linalg.norm(a, axis=-1) < 1e-6).any():
                raise ValueError(f"person {i}: leaves[{name!r}] must be {frames}×4 finite "
                                 f"quaternions (w, x, y, z), got shape {a.shape}")
            person[name] = a
        out.append(person)
    return out


def leaves_in(plan: dict | None, persons: int, frames: int) -> list[dict[str, np.ndarray]]:
    """The per-person leaf rotations an edit stored in a plan (plan["leaves"]); empty objects
    where it gives none or ones that do not fit the motion (the plan is only their carrier)."""
    given = (plan or {}).get("leaves") if isinstance(plan, dict) else None
    try:
        return validate_leaves(given, persons, frames)
    except ValueError:
        return [{} for _ in range(persons)]


@dataclass
class Motion:
    people: list[np.ndarray]            # one (T, 22, 3) float32 array per person, metres, Y up
    fps: int = FPS
    plan: dict = field(default_factory=dict)
    metrics: dict = field(default_factory=dict)
    highlights: dict | None = None
    prompt: str = ""
    seed: int | None = None
    # Per person, explicit local rotations (T, 4) of head / wrists (see the module); None: none.
    leaves: list | None = None

    def __post_init__(self):
        self.people = validate_people(self.people)
        if self.fps != FPS:
            raise ValueError(f"motions are {FPS} fps, got {self.fps}")
        if isinstance(self.plan, dict) and "leaves" in self.plan:
            if self.leaves is None:
                self.leaves = leaves_in(self.plan, len(self.people), self.frames)
            self.plan = {k: v for k, v in self.plan.items() if k != "leaves"}
        if self.leaves is not None:
            self.leaves = validate_leaves(self.leaves, len(self.people), self.frames)
            if not any(self.leaves):
                self.leaves = None

    def leaves_of(self, person: int) -> dict[str, np.ndarray]:
        """Person `person`'s explicit leaf rotations (empty when none)."""
        return dict(self.leaves[person]) if self.leaves is not None else {}

    @property
    def frames(self) -> int:
        return int(self.people[0].shape[0])

    @property
    def seconds(self) -> float:
        return self.frames / self.fps

    def to_json(self, rig: bool = False, rig_leaves: list | None = None) -> dict:
        """The Motion JSON (plain lists, joints rounded to 0.1 mm): version 1, or with rig=True
        version 2, which adds the skeleton and each person's rig (see the module). rig_leaves:
        per person, the leaves the rig takes in place of the motion's own (the exports' own,
        `pipeline.leaves.export_leaves`: the captures' turns with NaN rows, which the JSON's
        "leaves" cannot hold; the rig's rotations carry them)."""
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
            for k, (person, joints) in enumerate(zip(d["people"], people)):
                given = rig_leaves[k] if rig_leaves is not None else self.leaves_of(k)
                r = solve_rig(joints, floor=floor, leaves=given)
                person["rig"] = {key: np.round(value, RIG_DECIMALS).tolist() for key, value in
                                 (("offsets", r.offsets), ("root", r.root), ("rotations", r.rotations))}
        for k, person in enumerate(d["people"]):
            if self.leaves_of(k):
                person["leaves"] = {name: np.round(q, RIG_DECIMALS).tolist()
                                    for name, q in self.leaves_of(k).items()}
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
        joints, leaves = [], []
        for i, p in enumerate(people):
            if not isinstance(p, dict) or "joints" not in p:
                raise ValueError(f"person {i}: expected an object with 'joints'")
            if schema == SCHEMA_V2 and not isinstance(p.get("rig"), dict):
                raise ValueError(f"person {i}: a {SCHEMA_V2} motion needs each person's 'rig'")
            joints.append(p["joints"])
            leaves.append(p.get("leaves"))
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
                   highlights=highlights, prompt=str(d.get("prompt") or ""), seed=seed,
                   leaves=leaves if any(x is not None for x in leaves) else None)
