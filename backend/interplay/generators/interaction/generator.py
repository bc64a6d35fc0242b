"""Interaction by composition as a generator (issue 15): two people's motion made from real
single-person clips, timed against each other, touching where the prompt asks, both on the
same skeleton. Prompts with no interaction it composes (a couple dancing, jumping together)
and one-person requests go to the retrieval generator, and the plan says why.

    gen = InteractionGenerator(RetrievalIndex(default_clips(), get_encoder()))
    plan = gen.plan(Request("two friends shake hands", persons=2, seconds=6, seed=0))
    plan.generator, plan.composition["kind"]       # "compose", "handshake"
    for start, (a, b) in gen.stream(req, plan): …  # ≤ 40 frames a chunk, every frame

The plan's `composition` holds what was chosen and why: the script (kind, who starts, an
approach first, hands held, with the reasons: keywords, the text encoder, the planner's
roles), the clips each person is made of, the timing (approach, reach, contact, release), the
placement and the plausibility of the result. Frames depend only on the request and the
plan's script, so `stream` makes them again when they are not cached.
"""

from __future__ import annotations

import dataclasses
from collections import OrderedDict
from collections.abc import Iterator

import numpy as np

from interplay.generators.base import Generator, Request, generate_motion, random_seed
from interplay.generators.interaction import moves
from interplay.generators.interaction.bodies import SHARED
from interplay.generators.interaction.kinds import CONTACT, KINDS, Script, why_not
from interplay.generators.interaction.library import Library
from interplay.generators.interaction.reading import read
from interplay.generators.interaction.scene import Cast, finish, idle_role
from interplay.generators.interaction.scenes import contest, gestures, partners, piggyback, touches, travel
from interplay.generators.interaction.scenes.after import Departure, depart, departure, retimed
from interplay.generators.plan import GenerationPlan, Source
from interplay.generators.retrieval.generator import RetrievalGenerator
from interplay.generators.retrieval.index import RetrievalIndex
from interplay.motion.checks.named import plausibility
from interplay.motion.motion import Motion
from interplay.motion.skeleton import FPS, JOINT_INDEX
from interplay.planner.plan import plan as make_plan

NAME = "compose"
CHUNK = 40
ATTEMPTS = 4          # draws tried until one is plausible (no pops, grounded, not inside each other)
CACHE = 8
BUILDERS = {
    "handshake": touches.handshake, "high_five": touches.high_five, "hug": touches.hug,
    "push": touches.push, "wave": gestures.wave, "wave_back": gestures.wave_back,
    "bow": gestures.bow, "mirror": gestures.mirror, "follow": travel.follow,
    "one_stops": travel.one_stops, "side_by_side": travel.side_by_side, "approach": travel.approach,
    "together": gestures.together, "help_up": partners.help_up, "spar": contest.spar,
    "hand_over": partners.hand_over, "touch": partners.touch, "chase": contest.chase,
    "carry": piggyback.piggyback, "lead": travel.lead, "face_to_face": gestures.face_to_face,
}
START = {"help_up": "any"}     # the one helped up starts on the floor
FOREARM_M = round(float(np.linalg.norm(SHARED[JOINT_INDEX["left_wrist"]])), 3)


def plain(x):
    """A report made of numpy scalars and tuples as plain JSON values."""
    if isinstance(x, dict):
        return {str(k): plain(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [plain(v) for v in x]
    if isinstance(x, np.generic):
        return x.item()
    if isinstance(x, float):
        return round(x, 4)
    return x




def _roles(plan) -> dict | None:
    """Each person's role over the whole request, when the planner gave any: their roles in
    the segments, in order, those that only stand still left out unless nothing else is
    left ({"0": "a person pushes the other person", "1": "a person stumbles backwards"})."""
    segs = [s.roles for s in plan.segments if s.roles]
    if not segs:
        return None
    out = {}
    for k in ("0", "1"):
        texts = list(dict.fromkeys(str(r[k]) for r in segs if r.get(k)))
        busy = [t for t in texts if not idle_role(t)]
        if busy or texts:
            out[k] = "; then ".join(busy or texts[:1])
    return out or None


def _texts(prompt: str, roles: dict | None) -> list[str]:
    return [str((roles or {}).get(k) or prompt) for k in ("0", "1")]


class InteractionGenerator:
    """Two-person interactions composed from real clips (see the module doc); `index` is the
    retrieval index whose clips it uses; `retrieval` serves what it does not compose (the
    retrieval generator over the same index by default; the router gives retrieve-then-edit)."""

    def __init__(self, index: RetrievalIndex, retrieval: Generator | None = None):
        self.index = index
        self.retrieval: Generator = retrieval if retrieval is not None else RetrievalGenerator(index)
        self.library = Library.of_index(index)
        self._frames: OrderedDict[tuple, list[np.ndarray]] = OrderedDict()

    # -- planning ----------------------------------------------------------------------------
    def _fallback(self, req: Request, seed: int, why: str) -> GenerationPlan:
        plan = self.retrieval.plan(Request(req.prompt, req.persons, req.seconds, seed))
        own = f" ({plan.generator_reason})" if plan.generator_reason else ""
        plan.generator_reason = f"composition: {why}; the {plan.generator} generator made this instead{own}"
        return plan

    def plan(self, req: Request) -> GenerationPlan:
        seed = req.seed if req.seed is not None else random_seed()
        if req.persons != 2:
            return self._fallback(req, seed, "composes two people only")
        base = make_plan(req.prompt, 2, req.seconds)
        roles = _roles(base)
        script = read(req.prompt, roles, self.index.encoder)
        if script is None:
            return self._fallback(req, seed, f"no interaction it composes ({why_not(req.prompt, self.index.encoder)})")
        part = departure(base.segments, script.kind)
        if part is not None:
            base = retimed(base, part)
        try:
            people, composition = self.compose(script, req, seed, roles, part)
        except ValueError as exc:
            if not (script.approach and script.kind != "approach"):
                return self._fallback(req, seed, f"the {script.kind} could not be composed ({exc})")
            script = dataclasses.replace(script, approach=False, reasons=script.reasons + (
                f"no time to walk up to each other first in {req.seconds:g} s ({exc}): they start close",))
            try:
                people, composition = self.compose(script, req, seed, roles, part)
            except ValueError as exc2:
                return self._fallback(req, seed, f"the {script.kind} could not be composed ({exc2})")
        plan = GenerationPlan.from_plan(base, seed=seed, generator=NAME, synthetic=True,
                                        composition=composition)
        clips = sorted({s["clip"] for p in composition["people"] for s in p["clips"]})
        plan.sources = [Source(clip=c, licence=self.index.clip(c).licence, label=self.index.clip(c).label)
                        for c in clips if c in self.index.by_id]
        self._remember(req, seed, composition["script"], people)
        return plan

    def compose(self, script: Script, req: Request, seed: int, roles: dict | None = None,
                part: Departure | None = None) -> tuple[list[np.ndarray], dict]:
        """The two people's joints and the composition report for a script (deterministic
        for the seed; up to ATTEMPTS draws, the first plausible one kept, else the best); with
        `part`, the interaction ends at its frame and who leaves leaves (`after.py`)."""
        total = int(round(req.seconds * FPS))
        frames = part.frame if part is not None else total
        rng = np.random.default_rng([seed % 2**63, KINDS.index(script.kind)])
        contact = script.kind in CONTACT or script.held
        best: tuple | None = None
        errors = []
        for attempt in range(ATTEMPTS):
            cast = Cast(rng, self.library, script, frames, _texts(req.prompt, roles),
                        solo=lambda text, s: self._solo(text, req.seconds, s))
            try:
                made = BUILDERS[script.kind](cast)
                if part is not None:
                    made, after = depart(finish(made), part, self._solo, seed, total, self._stand)
                    for person, src in enumerate(after):
                        for clip in src:
                            cast.source(person, clip, "after")
                people = finish(made)
            except ValueError as exc:
                errors.append(str(exc))
                continue
            checks = plausibility(people, start=START.get(script.kind, "standing"), contact=contact)
            failed = [f"{r.check}" + (f" (person {r.person})" if r.person is not None else "")
                      for r in checks if not r.passed]
            if best is None or len(failed) < len(best[2]):
                best = (people, cast, failed, attempt)
            if not failed:
                break
        if best is None:
            raise ValueError("; ".join(dict.fromkeys(errors)) or "no draw worked")
        people, cast, failed, attempt = best
        composition = plain({
            "kind": script.kind, "script": script.to_json(), "reasons": list(script.reasons),
            "skeleton": f"both people on the SMPL template's bones (forearm {FOREARM_M} m)",
            "people": [{"text": t, "clips": s} for t, s in zip(cast.texts, cast.sources)],
            "timing": cast.report, "draw": attempt + 1,
            **({"after": part.to_json()} if part is not None else {}),
            "plausibility": {"failed": failed, "contact_asked": contact},
        })
        return [p.astype(np.float32) for p in people], composition

    def _stand(self, frames: int, seed: int) -> tuple[np.ndarray, list[dict]]:
        """Quiet standing for `frames` (a real standing run of the library) and its clip."""
        clip = moves.standing(np.random.default_rng(seed), self.library.pool, frames)
        return clip.joints, [clip.source]

    def _solo(self, text: str, seconds: float, seed: int) -> tuple[np.ndarray, list[dict]]:
        """One person's motion for `text` by the generator that serves one person, and the
        clips it is made of."""
        m = generate_motion(self.retrieval, Request(text, 1, seconds, seed))
        return np.asarray(m.people[0]), [{"clip": s["clip"], "licence": s["licence"]}
                                         for s in m.plan.get("sources", [])]

    def _remember(self, req: Request, seed: int, script: dict, people: list[np.ndarray]) -> None:
        key = (req.prompt, float(req.seconds), seed, repr(sorted(script.items())))
        self._frames[key] = people
        self._frames.move_to_end(key)
        while len(self._frames) > CACHE:
            self._frames.popitem(last=False)

    # -- frames ------------------------------------------------------------------------------
    def frames(self, req: Request, plan: GenerationPlan) -> list[np.ndarray]:
        """Both people's joints for a composed plan (cached from `plan`, else made again)."""
        comp = plan.composition or {}
        script = comp.get("script")
        if not script:
            raise ValueError("a compose plan needs its composition's script")
        key = (req.prompt, float(req.seconds), plan.seed, repr(sorted(script.items())))
        if key in self._frames:
            return self._frames[key]
        s = Script(script["kind"], int(script["actor"]), bool(script["approach"]),
                   bool(script["held"]), tuple(script.get("reasons", ())), script.get("part"))
        people, _ = self.compose(s, req, plan.seed, _roles(plan), departure(plan.segments, s.kind))
        self._remember(req, plan.seed, script, people)
        return people

    def stream(self, req: Request, plan: GenerationPlan) -> Iterator[tuple[int, list[np.ndarray]]]:
        """(start frame, [person 0 chunk, person 1 chunk]), ≤ 40 frames each, every frame;
        plans this generator handed to retrieval stream from retrieval."""
        if plan.generator != NAME:
            yield from self.retrieval.stream(req, plan)
            return
        people = self.frames(req, plan)
        total = sum(s.end - s.start for s in plan.segments)
        if len(people[0]) != total:
            raise ValueError(f"composed {len(people[0])} frames for a plan of {total}")
        for a in range(0, total, CHUNK):
            yield a, [p[a:a + CHUNK] for p in people]

    def generate(self, req: Request) -> Motion:
        return generate_motion(self, req)
