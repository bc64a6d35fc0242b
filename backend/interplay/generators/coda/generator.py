"""CODA as a generator for two people: every plan segment from its prompt, each continuing
from the previous one's tail tokens (`runtime.CodaRuntime.stream`); each stretch is finished
by `finish`: planted feet held, and a segment whose prompt asks for a touch is refined whole
by `contact_refine` before it streams, its report in the segment's "contact". Which requests
reach it, and the fallback when its weights are missing or untrained, is the router's.

    gen = CodaGenerator(CodaRuntime.load("models/weights/coda"))
    plan = gen.plan(Request("two people shake hands", persons=2, seconds=6, seed=1))  # "coda"
"""

from __future__ import annotations

from typing import Iterator

import numpy as np

from interplay.generators.base import Request, random_seed
from interplay.generators.coda.contact_kinds import contact_kind
from interplay.generators.coda.finish import finish_pair, hold_feet
from interplay.generators.coda.runtime import CHUNK, CodaRuntime
from interplay.generators.plan import GenerationPlan, ModelInfo
from interplay.motion import skeleton as sk
from interplay.planner.plan import plan as make_plan


class CodaGenerator:
    """CODA's plans and frames for two-person requests."""

    def __init__(self, coda: CodaRuntime):
        self.coda = coda

    def plan(self, req: Request) -> GenerationPlan:
        c = self.coda.config
        model = ModelInfo(name="coda", codes=c.codes, interaction_codes=c.interaction_codes,
                          cfg=c.cfg, steps=c.steps, max_seconds_per_window=c.max_frames / sk.FPS)
        seed = req.seed if req.seed is not None else random_seed()
        return GenerationPlan.from_plan(make_plan(req.prompt, req.persons, req.seconds), seed=seed,
                                        generator="coda", synthetic=False, sources=[], model=model)

    def stream(self, req: Request, plan: GenerationPlan) -> Iterator[tuple[int, list[np.ndarray]]]:
        segs = plan.segments
        segments = [(s.prompt, s.end - s.start) for s in segs]
        kinds = [contact_kind(p) for p, _ in segments]
        held, index = [], 0
        for start, people in self.coda.stream(segments, plan.seed):
            while start >= segs[index].end:
                index += 1
            if kinds[index] is None:
                yield start, [p.astype(np.float32) for p in hold_feet(people)]
                continue
            # A contact segment is refined whole (its window is picked from all of it), then
            # streamed; the next segment continues from the model's own frames, so the
            # refinement eases out before a segment joins (free_end False).
            held.append(people)
            a, b = segs[index].start, segs[index].end
            if start + people.shape[1] < b:
                continue
            pair, report = finish_pair(np.concatenate(held, axis=1), segments[index][0],
                                       free_start=index == 0, free_end=index == len(segs) - 1)
            held = []
            segs[index].contact = report
            for f in range(0, b - a, CHUNK):
                yield a + f, [p.astype(np.float32) for p in pair[:, f:f + CHUNK]]
