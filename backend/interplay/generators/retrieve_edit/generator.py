"""Retrieve-then-edit: real captured clips as the base of every segment (`RetrievalGenerator`:
text → clips, pose-matched cuts, cross-faded seams), then the edits that retrieval cannot give
laid over them:

1. the plan's arm actions (held poses, a raised hand, a wave while walking, `actions`), by IK
   on the performer's bones over the segment's frames, eased in and out at its borders
   (`arm_poses`); the legs, pelvis and untouched arm stay exactly as captured;
2. knees lifted high in every step where the plan asks for it (`leg_lifts`); a last segment
   asked to go slowly played slower where its captures go faster than a slow walk (`pace`);
3. segments whose words no capture covers but a motion primitive does (push-ups, claps, a
   limp, a nod) built by that primitive and placed where the motion is (`primitive_steps`);
4. the whole motion put on the floor where it carries weight (`ground.on_floor`).

Every choice is written into the plan: the captures per segment (as retrieval's), and per
segment the arm actions laid over it and the part edits left to the captured motion
(`GenerationSegment.contact` is CODA's; these go into `edit_reasons`).

Two people: the same, per person (roles from the plan when present, else the segment's
edits apply to the first person only).

    gen = RetrieveEditGenerator(index)
    plan = gen.plan(Request("walk forward while waving your right hand", seconds=6, seed=3))
    for start, chunk in gen.stream(req, plan): ...
"""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np

from interplay.generators.base import Request, generate_motion
from interplay.generators.plan import GenerationPlan, GenerationSegment, GeneratorName
from interplay.generators.retrieval.generator import CHUNK, RetrievalGenerator
from interplay.generators.retrieval.index import RetrievalIndex
from interplay.generators.retrieval.intent import speed_of
from interplay.generators.retrieve_edit.actions import arm_actions, knee_lifts
from interplay.generators.retrieve_edit.arm_poses import ArmAction, apply
from interplay.generators.retrieve_edit.ground import on_floor
from interplay.generators.retrieve_edit.holds import apply_hold, hold_of, query_of
from interplay.generators.retrieve_edit.holds import reason as hold_reason
from interplay.generators.retrieve_edit.leg_lifts import lift_knees
from interplay.generators.retrieve_edit.pace import SLOW_MAX_M_S, slow_down
from interplay.generators.retrieve_edit.primitive_steps import choose, lay
from interplay.motion.motion import Motion

NAME: GeneratorName = "retrieve_edit"


def _actions(plan: GenerationPlan) -> tuple[list[ArmAction], list[str]]:
    """Every segment's arm actions (one run per arm where consecutive segments hold the same
    pose, so a pose held across a seam does not ease out and back in) and the reasons."""
    acts: list[ArmAction] = []
    reasons: list[str] = []
    for seg in plan.segments:
        new, why = arm_actions(seg)
        if seg.retrieval is not None and seg.retrieval.mode == "pair":
            # both people of one capture (a salsa): their arms hold each other as captured, and
            # the leader's arm goes up for a spin only while it turns the follower
            if new:
                reasons.append(f"segment {seg.index}: a two-person capture, its arms kept as "
                               "captured (no arm action laid over)")
            continue
        why += knee_lifts(seg)[1]
        hold = hold_of(seg)
        if hold is not None:
            why.append(hold_reason(hold, seg))
        reasons += [f"segment {seg.index}: {w}" for w in why]
        for a in new:
            prev = next((p for p in reversed(acts) if p.side == a.side), None)
            if prev is not None and prev.pose == a.pose and prev.end == a.start:
                acts[acts.index(prev)] = ArmAction(a.side, a.pose, prev.start, a.end)
            else:
                acts.append(a)
    return acts, reasons


def _slowed(plan: GenerationPlan) -> GenerationSegment | None:
    """The segment `pace.slow_down` may slow: one person's last, when asked to go slowly."""
    last = plan.segments[-1]
    return last if plan.persons == 1 and speed_of(last.prompt) == "slow" else None


class BaseRetrieval(RetrievalGenerator):
    """Retrieval that looks up a segment's base motion ("a person walks forward") where arm
    actions will be laid over it: the segment's whole prompt ("walks forward while waving")
    finds a standing wave, whose legs do not walk."""

    def query(self, seg: GenerationSegment) -> str:
        if len(seg.persons) != 1:
            return seg.prompt
        hold = hold_of(seg)
        if hold is not None:
            return query_of(hold)
        acts, _ = arm_actions(seg)
        return seg.base if acts or knee_lifts(seg)[0] else seg.prompt


class RetrieveEditGenerator:
    """Retrieval's clips with the plan's arm actions laid over them, on the floor."""

    def __init__(self, index: RetrievalIndex):
        self.index = index
        self.retrieval = BaseRetrieval(index)

    def plan(self, req: Request) -> GenerationPlan:
        plan = self.retrieval.plan(req)
        plan.generator = NAME
        made = choose(plan, self.index.encoder)
        _, reasons = _actions(plan)
        reasons += made
        slow = _slowed(plan)
        if slow is not None:
            reasons.append(f"segment {slow.index}: played slower where its captures travel faster "
                           f"than {SLOW_MAX_M_S:g} m/s (a slow walk, `pace.slow_down`)")
        plan.generator_reason = "; ".join(
            ["real captured clips per segment, arm actions laid over them by IK, feet put on "
             "the floor"] + reasons)
        return plan

    def redraw(self, plan: GenerationPlan, index: int, seed: int) -> GenerationPlan:
        return self.retrieval.redraw(plan, index, seed)

    def frames(self, req: Request, plan: GenerationPlan) -> list[np.ndarray]:
        """Every frame of the plan, one (T, 22, 3) float32 array per person."""
        chunks = [people for _, people in self.retrieval.stream(req, plan)]
        people = [np.concatenate([c[i] for c in chunks]).astype(np.float64)
                  for i in range(plan.persons)]
        if plan.persons == 1:          # primitive segments first: the arm poses go over them too
            people[0] = lay(people[0], plan)
        for seg in plan.segments:
            legs, _ = knee_lifts(seg)
            if legs and not (seg.retrieval is not None and seg.retrieval.mode == "pair"):
                people[0] = lift_knees(people[0], legs, seg.start, seg.end)
            hold = hold_of(seg)
            if hold is not None:
                people[0] = apply_hold(people[0], hold, seg.start, seg.end)
        slow = _slowed(plan)
        if slow is not None:
            people[0][slow.start:slow.end] = slow_down(people[0][slow.start:slow.end])[0]
        acts, _ = _actions(plan)
        if acts:
            people[0] = apply(people[0], acts)
        return [on_floor(p).astype(np.float32) for p in people]

    def stream(self, req: Request, plan: GenerationPlan) -> Iterator[tuple[int, list[np.ndarray]]]:
        """(start frame, one (n ≤ 40, 22, 3) chunk per person), in order, covering the plan.
        The floor pass sees the whole motion, so the frames are made first (a 6 s motion in
        tens of milliseconds) and then streamed."""
        people = self.frames(req, plan)
        for a in range(0, len(people[0]), CHUNK):
            yield a, [p[a:a + CHUNK] for p in people]

    def generate(self, req: Request) -> Motion:
        return generate_motion(self, req)
