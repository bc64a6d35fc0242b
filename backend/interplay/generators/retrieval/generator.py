"""Retrieval (motion matching) as a generator: every plan segment is filled with captured
motion found by text (`index.RetrievalIndex`) and stitched (`stitch.Stitcher`). For two
people it uses a two-person capture when the prompt matches one (salsa); otherwise it composes
two single-person captures, facing each other 1.5 m apart (side by side when they travel),
and marks the segment as synthetic.

    gen = RetrievalGenerator(RetrievalIndex(default_clips(), get_encoder()))
    plan = gen.plan(Request("a person walks forward then jumps", seconds=6, seed=3))
    for start, chunk in gen.stream(req, plan):  # chunk: one (n, 22, 3) array per person
        ...
    motion = gen.generate(req)                  # Motion with plan and metrics
"""

from __future__ import annotations

import secrets
from collections.abc import Iterator

import numpy as np

from interplay.generators.base import Request, generate_motion
from interplay.generators.retrieval.index import RetrievalIndex
from interplay.generators.retrieval.stitch import Stitcher
from interplay.motion.motion import Motion
from interplay.motion.skeleton import PELVIS
from interplay.planner.plan import plan_json

CHUNK = 40          # frames per streamed chunk at most (2 s)
SPACING = 1.5       # metres between two composed people
TRAVEL = 1.0        # metres of pelvis travel that make composed people stand side by side


def _rng(seed: int, segment: int) -> np.random.Generator:
    return np.random.default_rng([seed % 2**63, segment])


def _pair_end(after: list[dict]) -> dict | None:
    """The previous segment's end as one two-person piece, if it was one."""
    return after[0] if len(after) == 1 and len(after[0]["people"]) == 2 else None


class RetrievalGenerator:
    def __init__(self, index: RetrievalIndex):
        self.index = index

    # -- planning ----------------------------------------------------------------------------
    def _travel(self, track: list[dict]) -> float:
        """Ground distance the pelvis covers over a track's first piece."""
        p = track[0]
        pelvis = self.index.clip(p["clip"]).people[p["people"][0]][[p["start"], p["end"] - 1], PELVIS]
        return float(np.hypot(*(pelvis[1] - pelvis[0])[[0, 2]]))

    def retrieve(self, prompt: str, frames: int, persons: int, rng: np.random.Generator,
                 after: list[dict] | None = None) -> dict:
        """The captured pieces for one segment: {"mode", "tracks", "synthetic"[, "arrangement"]};
        `after` holds the previous segment's last piece per track, whose end pose the new
        pieces start from."""
        idx, after = self.index, after or []
        if persons == 2 and idx.use_pair(prompt):
            return {"mode": "pair", "synthetic": False,
                    "tracks": [idx.track(prompt, frames, rng, pair=True, after=_pair_end(after))]}
        first = idx.track(prompt, frames, rng, after=after[0] if after else None)
        if persons == 1:
            return {"mode": "single", "synthetic": False, "tracks": [first]}
        second = idx.track(prompt, frames, rng, exclude={first[0]["clip"]},
                           after=after[1] if len(after) > 1 else None)
        travel = max(self._travel(first), self._travel(second))
        return {"mode": "composed", "synthetic": True, "tracks": [first, second],
                "arrangement": "side_by_side" if travel > TRAVEL else "facing"}

    def plan(self, req: Request) -> dict:
        """The planner's plan plus, per segment, the captures chosen for it and the seed used."""
        plan = plan_json(req.prompt, req.persons, req.seconds)
        seed = req.seed if req.seed is not None else secrets.randbelow(2**31)
        after = None
        for seg in plan["segments"]:
            seg["retrieval"] = self.retrieve(seg["prompt"], seg["end"] - seg["start"], req.persons,
                                             _rng(seed, seg["index"]), after)
            after = [t[-1] for t in seg["retrieval"]["tracks"]]
        clips = {p["clip"] for s in plan["segments"] for t in s["retrieval"]["tracks"] for p in t}
        plan.update({"seed": seed, "generator": "retrieval",
                     "synthetic": any(s["retrieval"]["synthetic"] for s in plan["segments"]),
                     "sources": [{"clip": c, "licence": self.index.clip(c).licence,
                                  "label": self.index.clip(c).label} for c in sorted(clips)]})
        return plan

    # -- frames ------------------------------------------------------------------------------
    def _placement(self, arrangement: str) -> list[tuple[np.ndarray, float]]:
        """Start pelvis position and facing yaw of each composed person."""
        half = SPACING / 2
        if arrangement == "side_by_side":
            return [(np.array([half, 0.0, 0.0]), 0.0), (np.array([-half, 0.0, 0.0]), 0.0)]
        return [(np.array([-half, 0.0, 0.0]), np.pi / 2), (np.array([half, 0.0, 0.0]), -np.pi / 2)]

    def _render(self, stitcher: Stitcher, retrieval: dict, persons: int) -> list[np.ndarray]:
        """One segment's frames per person, continuing what the stitcher has output so far."""
        tracks = [self.index.pieces(t) for t in retrieval["tracks"]]
        if retrieval["mode"] == "pair":
            parts = [stitcher.add_pair(piece) for piece in tracks[0]]
            return [np.concatenate([p[i] for p in parts]) for i in range(2)]
        if len(tracks) != persons:
            raise ValueError(f"segment has {len(tracks)} tracks for {persons} people")
        place = self._placement(retrieval.get("arrangement", "facing")) if persons == 2 else [None]
        out = []
        for person, track in enumerate(tracks):
            frames = [stitcher.add_single(person, piece[0], place[person]) for piece in track]
            out.append(np.concatenate(frames))
        return out

    def stream(self, req: Request, plan: dict) -> Iterator[tuple[int, list[np.ndarray]]]:
        """(start frame, one (n, 22, 3) float32 chunk per person), in order, n ≤ 40, covering
        every frame of the plan (round(seconds × 20))."""
        persons, seed = plan.get("persons", req.persons), plan.get("seed", req.seed or 0)
        stitcher, expected, after = Stitcher(persons), 0, None
        for seg in plan["segments"]:
            start, end = int(seg["start"]), int(seg["end"])
            if start != expected or end <= start:
                raise ValueError(f"plan segments must tile the motion; segment {seg.get('index')} "
                                 f"spans {start}–{end}, expected to start at {expected}")
            retrieval = seg.get("retrieval") or self.retrieve(seg["prompt"], end - start, persons,
                                                              _rng(seed, seg.get("index", 0)), after)
            after = [t[-1] for t in retrieval["tracks"]]
            frames = self._render(stitcher, retrieval, persons)
            if any(len(f) != end - start for f in frames):
                raise ValueError(f"segment {seg.get('index')}: the plan's pieces do not last "
                                 f"{end - start} frames")
            for a in range(0, end - start, CHUNK):
                yield start + a, [f[a:a + CHUNK] for f in frames]
            expected = end

    def generate(self, req: Request) -> Motion:
        """Plan, all frames, clip metrics and per-frame highlights."""
        return generate_motion(self, req)
