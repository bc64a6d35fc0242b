"""Retrieval (motion matching) as a generator: every plan segment is filled with captured
motion found by text (`index.RetrievalIndex`) and stitched (`stitch.Stitcher`). For two
people it uses a two-person capture when the prompt matches one (salsa); otherwise it composes
two single-person captures, facing each other 1.5 m apart (side by side when they travel),
and marks the segment as synthetic; a couple's dance is drawn close together, a spin cut where a
captured salsa follower spins (`couple.py`). One person's segment is drawn for what its words ask
beyond the nearest captures (`tracks.py`: direction of travel, side, counts, postures, with
mirrored and time-reversed views of the captures); a track shorter than its segment holds its
last pose to the segment's end. A segment whose words ask to stay on the spot ("hop on the
spot", "march in place") and whose frames still travel has its drift taken out; the segments
after it continue from where it now ends (`on_the_spot.py`).

    gen = RetrievalGenerator(RetrievalIndex(default_clips(), get_encoder()))
    plan = gen.plan(Request("a person walks forward then jumps", seconds=6, seed=3))
    for start, chunk in gen.stream(req, plan):  # chunk: one (n, 22, 3) array per person
        ...
    motion = gen.generate(req)                  # Motion with plan and metrics
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from typing import Literal

import numpy as np

from interplay.generators.base import Request, generate_motion, random_seed
from interplay.generators.plan import (
    CapturePiece,
    GenerationPlan,
    GenerationSegment,
    RetrievalChoice,
    Source,
)
from interplay.generators.retrieval import on_the_spot
from interplay.generators.retrieval.couple import couple_track
from interplay.generators.retrieval.index import RetrievalIndex
from interplay.generators.retrieval.intent import FASTEST_M_S, intent, speed_of
from interplay.generators.retrieval.stitch import Stitcher
from interplay.generators.retrieval.tracks import single_track
from interplay.motion.motion import Motion
from interplay.motion.skeleton import PELVIS
from interplay.planner.plan import plan as make_plan

CHUNK = 40          # frames per streamed chunk at most (2 s)
SPACING = 1.5       # metres between two composed people
TRAVEL = 1.0        # metres of pelvis travel that make composed people stand side by side


def _rng(seed: int, segment: int) -> np.random.Generator:
    return np.random.default_rng([seed % 2**63, segment])


def _pair_end(after: list[dict]) -> dict | None:
    """The previous segment's end as one two-person piece, if it was one."""
    return after[0] if len(after) == 1 and len(after[0]["people"]) == 2 else None


def _pieces(track: list[dict]) -> list[CapturePiece]:
    return [CapturePiece.model_validate(p) for p in track]


def _ends(retrieval: RetrievalChoice) -> list[dict]:
    """Each track's last piece, as the index takes it (`after`: the pose to continue from)."""
    return [t[-1].model_dump() for t in retrieval.tracks]


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
                 after: list[dict] | None = None,
                 roles: Mapping[Literal["0", "1"], str] | None = None,
                 repeat: int = 1, direction: str | None = None) -> RetrievalChoice:
        """The captured pieces for one segment; `after` holds the previous segment's last
        piece per track, whose end pose the new pieces start from. `roles` (the plan's
        {"0": text, "1": text}) gives each composed person their own text: "one pushes the
        other, who stumbles backwards" draws a push for one and a stumble for the other.
        `repeat` and `direction` are the segment's count and direction of travel (its
        `travel`), for what one person's track must do (tracks.py)."""
        idx, after = self.index, after or []
        if persons == 1:      # what the words ask beyond the nearest captures: tracks.py
            return RetrievalChoice(mode="single", synthetic=False, tracks=[_pieces(single_track(
                idx, prompt, frames, rng, after[0] if after else None, intent(prompt, repeat, direction)))])
        if persons == 2:      # a two-person capture (salsa), a spin cut around one: couple.py
            pair = couple_track(idx, prompt, frames, rng, after=_pair_end(after))
            if pair is not None:
                return RetrievalChoice(mode="pair", synthetic=False, tracks=[_pieces(pair)])
        texts = [prompt, prompt]
        if persons == 2 and roles:
            texts = [roles.get("0") or prompt, roles.get("1") or prompt]
        first = idx.track(texts[0], frames, rng, after=after[0] if after else None)
        if persons == 1:
            return RetrievalChoice(mode="single", synthetic=False, tracks=[_pieces(first)])
        # The same text for both: another capture for the second person, so they differ.
        exclude = {first[0]["clip"]} if texts[0] == texts[1] else set()
        second = idx.track(texts[1], frames, rng, exclude=exclude,
                           after=after[1] if len(after) > 1 else None)
        travel = max(self._travel(first), self._travel(second))
        return RetrievalChoice(mode="composed", synthetic=True,
                               tracks=[_pieces(first), _pieces(second)],
                               arrangement="side_by_side" if travel > TRAVEL else "facing")

    def _summarise(self, plan: GenerationPlan) -> None:
        """The plan's `synthetic` and `sources` (clip, licence, label) from its segments' captures."""
        clips = {p.clip for s in plan.segments if s.retrieval for t in s.retrieval.tracks for p in t}
        plan.synthetic = any(s.retrieval is not None and s.retrieval.synthetic for s in plan.segments)
        plan.sources = [Source(clip=c, licence=self.index.clip(c).licence,
                               label=self.index.clip(c).label) for c in sorted(clips)]

    def query(self, seg: GenerationSegment) -> str:
        """The text a segment's captures are looked up by: its prompt (a generator that lays
        part edits over the captures looks up the base motion instead)."""
        return seg.prompt

    def plan(self, req: Request) -> GenerationPlan:
        """The planner's plan plus, per segment, the captures chosen for it and the seed used."""
        seed = req.seed if req.seed is not None else random_seed()
        plan = GenerationPlan.from_plan(make_plan(req.prompt, req.persons, req.seconds),
                                        seed=seed, generator="retrieval")
        after = None
        for seg in plan.segments:
            seg.retrieval = self.retrieve(self.query(seg), seg.end - seg.start, req.persons,
                                          _rng(seed, seg.index), after, seg.roles,
                                          seg.repeat, seg.travel)
            after = _ends(seg.retrieval)
            if req.persons == 1 and speed_of(seg.prompt) == "sprint":
                plan.reasons.append(f"speed: segment {seg.index} asks for a sprint; the fastest "
                                    f"captured runs reach about {FASTEST_M_S:g} m/s, so it is "
                                    "played at that speed, no faster")
        self._summarise(plan)
        return plan

    def redraw(self, plan: GenerationPlan, index: int, seed: int) -> GenerationPlan:
        """A copy of `plan` whose retrieval segment `index` is drawn again with `seed`,
        continuing from the previous segment's captures."""
        out = plan.model_copy(deep=True)
        seg, prev = out.segments[index], out.segments[index - 1].retrieval if index > 0 else None
        seg.retrieval = self.retrieve(self.query(seg), seg.end - seg.start, out.persons,
                                      _rng(seed, index), _ends(prev) if prev else None, seg.roles,
                                      seg.repeat, seg.travel)
        self._summarise(out)
        return out

    # -- frames ------------------------------------------------------------------------------
    def _placement(self, arrangement: str) -> list[tuple[np.ndarray, float]]:
        """Start pelvis position and facing yaw of each composed person."""
        half = SPACING / 2
        if arrangement == "side_by_side":
            return [(np.array([half, 0.0, 0.0]), 0.0), (np.array([-half, 0.0, 0.0]), 0.0)]
        return [(np.array([-half, 0.0, 0.0]), np.pi / 2), (np.array([half, 0.0, 0.0]), -np.pi / 2)]

    def _render(self, stitcher: Stitcher, retrieval: RetrievalChoice, persons: int,
                length: int | None = None) -> list[np.ndarray]:
        """One segment's frames per person, continuing what the stitcher has output so far; a
        person's track shorter than `length` holds its last pose to the end (tracks.py)."""
        tracks = [self.index.pieces([p.model_dump() for p in t]) for t in retrieval.tracks]
        if retrieval.mode == "pair":
            parts = [stitcher.add_pair(piece) for piece in tracks[0]]
            return [np.concatenate([p[i] for p in parts]) for i in range(2)]
        if len(tracks) != persons:
            raise ValueError(f"segment has {len(tracks)} tracks for {persons} people")
        place = self._placement(retrieval.arrangement or "facing") if persons == 2 else [None]
        out = []
        for person, track in enumerate(tracks):
            frames = [stitcher.add_single(person, piece[0], place[person]) for piece in track]
            short = (length or 0) - sum(len(f) for f in frames)
            if short > 0:
                frames.append(stitcher.hold(person, short))
            out.append(np.concatenate(frames))
        return out

    def stream(self, req: Request, plan: GenerationPlan) -> Iterator[tuple[int, list[np.ndarray]]]:
        """(start frame, one (n, 22, 3) float32 chunk per person), in order, n ≤ 40, covering
        every frame of the plan (round(seconds × 20))."""
        persons, seed = plan.persons, plan.seed
        stitcher, expected, after = Stitcher(persons), 0, None
        moved = np.zeros(3)     # the drift taken out of on-the-spot segments so far (x, 0, z)
        for seg in plan.segments:
            start, end = seg.start, seg.end
            if start != expected or end <= start:
                raise ValueError(f"plan segments must tile the motion; segment {seg.index} "
                                 f"spans {start}–{end}, expected to start at {expected}")
            retrieval = seg.retrieval or self.retrieve(self.query(seg), end - start, persons,
                                                       _rng(seed, seg.index), after, seg.roles,
                                                       seg.repeat, seg.travel)
            after = _ends(retrieval)
            frames = self._render(stitcher, retrieval, persons, end - start)
            if persons == 1:    # "hop on the spot": a capture that travels kept on the spot
                frames[0] = (frames[0] + moved).astype(frames[0].dtype)
                if on_the_spot.asks(seg):
                    frames[0], more = on_the_spot.stay(frames[0])
                    moved += more
            if any(len(f) != end - start for f in frames):
                raise ValueError(f"segment {seg.index}: the plan's pieces do not last "
                                 f"{end - start} frames")
            for a in range(0, end - start, CHUNK):
                yield start + a, [f[a:a + CHUNK] for f in frames]
            expected = end

    def generate(self, req: Request) -> Motion:
        """Plan, all frames, clip metrics and per-frame highlights."""
        return generate_motion(self, req)
