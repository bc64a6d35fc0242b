"""One generation job as CoMA's Algorithm 1: plan → per segment generate (the router's choice:
SPAM for one person, CODA for two, retrieval as fallback; SPAM conditions each part on the
plan's part edits) → for two people the penetration pass (`pair_pass`) →
review rounds (reviewer.correct: part edits, in-betweens, re-draws) → trajectories (the plan's
per segment, or the request's drawn path / preset for one person) → the penetration pass again
where the paths made two people overlap → the blended whole → the caller's metrics and store.

    result = orchestrate(generator, req, emit, on_frames, cancelled=job.cancelled)

`emit(event)` gets the plan / segment / review / correction events; `on_frames(start, people)`
gets every frame range as it becomes final — segments as they finish, a corrected segment
again with the same start, and after trajectories the frames that moved. A failing stage
raises StageError(stage, reason); a cancelled job raises segment_source.Cancelled.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Callable

import numpy as np

from interplay.catalogue.load import catalogue
from interplay.catalogue.schema import specs
from interplay.generators.base import Editor, Generator, Request
from interplay.generators.plan import GenerationPlan, GenerationSegment
from interplay.generators.primitives.registry import PRIMITIVES
from interplay.generators.retrieval.intent import intent
from interplay.generators.retrieval.verify import checks as asked_checks
from interplay.motion.kinematics import continue_from
from interplay.pipeline import pair_pass, pair_review
from interplay.pipeline.segment_source import Cancelled, SegmentSource
from interplay.pipeline.sent import OnReplace, SentFrames
from interplay.review.reviewer import CannotApply, correct
from interplay.trajectory.apply import TrajectoryConfig

log = logging.getLogger(__name__)
CHUNK = 40
# A path drawn on the studio floor: world coordinates, its own size; the walk is retimed to
# cover it, so the person ends where the path ends.
DRAWN_PATH = TrajectoryConfig(anchor="world", scale_to_motion=False, retime=True)
__all__ = ["orchestrate", "OrchestratorConfig", "Outcome", "StageError", "Cancelled"]


@dataclass(frozen=True)
class OrchestratorConfig:
    rounds: int = 2             # K: review rounds per segment (CoMA's study used 2)
    tolerance: float = 0.1      # relative worsening of a watched metric that rejects a correction
    review: bool = True


DEFAULT = OrchestratorConfig()


class StageError(RuntimeError):
    def __init__(self, stage: str, reason: str):
        super().__init__(f"{stage} failed: {reason}")
        self.stage, self.reason = stage, reason


@dataclass
class Outcome:
    people: list                       # float32 (T, 22, 3) per person
    plan: GenerationPlan
    review: dict = field(default_factory=dict)


@lru_cache(maxsize=1)
def default_evaluator():
    """The text–motion evaluator when its weights load, else None (reviews then score by
    caption agreement)."""
    from interplay.review.evaluator import DEFAULT_DIR, FILES, load_evaluator
    if not all((DEFAULT_DIR / f).is_file() for f in FILES):
        return None
    try:
        return load_evaluator()
    except Exception as exc:   # broken or foreign files: review without it
        log.warning("evaluator weights did not load: %s", exc)
        return None


@lru_cache(maxsize=1)
def default_pair_evaluator():
    """The pair evaluator when its weights load, else None: with its calibration it judges two
    people's segments the one-person evaluator cannot (`review.judge`)."""
    from interplay.review.pair_evaluator import DEFAULT_DIR, load_pair_evaluator
    if not (DEFAULT_DIR / "motion_encoder.onnx").is_file():
        return None
    try:
        return load_pair_evaluator()
    except Exception as exc:   # broken or foreign files: review without it
        log.warning("pair evaluator weights did not load: %s", exc)
        return None


def _trajectories(people: np.ndarray, plan: GenerationPlan, trajectory: dict | None) -> int | None:
    """Apply the plan's segment trajectories (or the request's path for its person) in place;
    the first frame that moved, or None."""
    from interplay.trajectory.apply import apply_trajectory
    first = None
    for p in range(people.shape[0]):
        if trajectory is not None and int(trajectory.get("person", 0)) == p:
            if "points" in trajectory and trajectory["points"] is not None:
                moved = apply_trajectory(people[p], np.asarray(trajectory["points"], float),
                                         cfg=DRAWN_PATH)
            else:
                moved = apply_trajectory(people[p], {k: v for k, v in trajectory.items()
                                                     if k not in ("person", "points")})
            people[p] = moved
            first = 0
            continue
        for seg in plan.segments:
            if seg.trajectory is None or p not in seg.persons:
                continue
            a, b = seg.start, seg.end
            old = people[p].copy()
            people[p, a:b] = apply_trajectory(old[a:b], seg.trajectory.model_dump(mode="json"))
            people[p] = continue_from(people[p], old[b - 1], b)
            first = a if first is None else min(first, a)
    return first


def orchestrate(generator: Generator, req: Request, emit: Callable[[dict], None],
                on_frames: Callable[[int, list[np.ndarray]], None],
                cancelled: Callable[[], bool] = lambda: False, trajectory: dict | None = None,
                evaluator=None, cfg: OrchestratorConfig = DEFAULT,
                on_replace: OnReplace | None = None) -> Outcome:
    stage = "plan"
    # Everything streamed goes through `sent`: frames changed after they were sent (a
    # correction, the pair pass, a path, a re-draw's seams and floor pass) go out again, as
    # replacements with their cause when the caller takes them (`on_replace`).
    sent = SentFrames(on_frames, on_replace)
    try:
        plan = generator.plan(req)
        emit({"type": "plan", "plan": plan.to_json()})
        stage = "generate"
        source = SegmentSource(generator, req, plan)
        kind = plan.generator
        spam = kind == "spam" and isinstance(generator, Editor) and generator.can_edit
        history, resolutions = [], []
        pair_checked = bool(pair_review.interaction_specs(plan))
        for seg in plan.segments:
            i, a, b = seg.index, seg.start, seg.end
            emit({"type": "segment", "index": i, "status": "generating", "generator": kind})
            stage = "generate"
            source.fill(b, sent, cancelled)
            done = pair_pass.resolve_segment(source.people, source.plan, seg,
                                             sent.by("pair_pass", i))
            resolutions += [done] if done else []
            if cfg.review and cfg.rounds > 0 and b - a >= 3:
                stage = "review"
                history.append(_review_segment(generator, source, seg, spam, evaluator, cfg,
                                               emit, sent.by("correction", i), plan.seed,
                                               done is not None, pair_checked))
                # a re-draw moves frames beyond the segment too (seams, the floor pass)
                sent.sync(source.people[:, :source.written], "correction", i)
            if cancelled():
                raise Cancelled()
            emit({"type": "segment", "index": i, "status": "done", "generator": kind})
        people = source.people[:, :source.written].copy()
        interaction = None
        if cfg.review and cfg.rounds > 0 and source.persons == 2:
            stage = "review"
            last = max((r["round"] for h in history if h["segment"] == plan.segments[-1].index
                        for r in h["reviews"]), default=-1)
            people, source.plan, interaction = pair_review.review_interaction(
                generator, req, source.plan, people, emit, sent.by("interaction"),
                first_round=last + 1,
                tries=cfg.rounds)
            if interaction is not None:      # the stored timeline shows it on the last segment
                entry = next((h for h in history if h["segment"] == plan.segments[-1].index), None)
                if entry is not None:
                    entry["reviews"] += [{k: v for k, v in r.items() if k != "type"}
                                         for r in interaction["rounds"]]
                    entry["corrections"] += interaction["corrections"]
        stage = "trajectory"
        first = _trajectories(people, source.plan, trajectory)
        if first is not None:
            for s in range(first, people.shape[1], CHUNK):
                sent.send(s, [p[s:s + CHUNK] for p in people], "trajectory")
        resolutions += pair_pass.resolve_motion(people, source.plan, sent.by("pair_pass"))
        sent.sync(people, "sync")      # nothing, unless a stage changed frames unsent
        plan = source.plan
        if trajectory is not None:
            plan = plan.model_copy()
            plan.trajectory = trajectory
        review: dict[str, object] = {"rounds": cfg.rounds, "tolerance": cfg.tolerance,
                  "score_kind": "evaluator" if evaluator is not None else "caption_agreement",
                  "segments": history}
        if resolutions:
            review["pair_resolution"] = resolutions
        if interaction is not None:
            review["interaction"] = interaction
        return Outcome(people=[p.astype(np.float32) for p in people], plan=plan, review=review)
    except (Cancelled, StageError):
        raise
    except Exception as exc:
        log.exception("job stage %s failed", stage)
        raise StageError(stage, f"{type(exc).__name__}: {exc}") from exc


# A primitive's base posture (generators/primitives/postures.NAMES) as the posture the
# benchmark's checks read at its first frame; standing and a walk start standing.
PRIMITIVE_START = {"prone": "lying", "supine": "lying", "floor": "sitting", "kneeling": "kneeling",
                   "all_fours": "all_fours", "seated": "low"}


def _primitive_start(seg: GenerationSegment) -> str | None:
    cov = seg.coverage
    prim = PRIMITIVES.get(cov.primitive or "") if cov is not None and cov.how == "primitive" else None
    return PRIMITIVE_START.get(prim.posture) if prim is not None else None


def asked_of(seg: GenerationSegment) -> list[dict]:
    """The benchmark's checks (specs for `run_check`) that one person's segment words imply:
    the retrieval's reading of them (`retrieval.intent`, `retrieval.verify.checks`); the first
    segment starts standing unless it is asked to start elsewhere; a held pose is held; and
    the checks the catalogue gives the entry its words were read as (`coverage.entry`)."""
    it = intent(seg.prompt, seg.repeat, seg.travel)
    out = asked_checks(it, it.start, it.end, first=seg.index == 0)
    start = _primitive_start(seg)
    if start is not None:           # a primitive starts in its own base posture (crunches: lying)
        out = [{**spec, "posture": start} if spec["check"] == "posture_at_start" else spec
               for spec in out]
    if it.hold is not None:         # a held pose: held at least 1 s (less of a short segment)
        held = round(min(1.0, 0.4 * (seg.end - seg.start) / 20), 2)
        out.append({"check": "still"} if it.hold == "still" else
                   {"check": "pose_held", "pose": it.hold.split(":")[0], "min_s": held})
    # the checks the catalogue names for the entry the words were read as (one per check kind)
    entry = catalogue().get(seg.coverage.entry) if seg.coverage and seg.coverage.entry else None
    if entry is not None and seg.coverage is not None and seg.coverage.how != "nearest":
        asked = {spec["check"] for spec in out}
        out += [spec for spec in specs(entry, it.count, it.side) if spec["check"] not in asked]
    return out


def _review_segment(generator: Generator, source: SegmentSource, seg: GenerationSegment,
                    spam: bool, evaluator,
                    cfg: OrchestratorConfig, emit, on_frames, seed: int,
                    resolved: bool = False, pair_checked: bool = False) -> dict:
    """Review rounds on one segment; corrected frames go back into `source` and out again."""
    i, a, b = seg.index, seg.start, seg.end
    calls: list = []          # per applied instruction: the re-drawn source (or None)

    def apply(instr: dict, people: list[np.ndarray], s: int) -> list[np.ndarray]:
        kind = instr["kind"]
        if kind in ("regenerate", "edit_part") and not spam and seg.retrieval is not None:
            # Retrieval cannot edit a part: it re-draws the segment's captures instead, and the
            # reviewer keeps the new draw only if it is better.
            if kind == "edit_part":
                instr["via"] = "regenerate"
            other, frames = source.redraw(i, s)
            calls.append(other)
            return frames
        # SPAM re-makes a SPAM segment's parts and frames; on captured clips (retrieval,
        # retrieve-then-edit) it makes the in-betweens over bad frames, kept only if better
        editor = isinstance(generator, Editor) and generator.can_edit
        if not (spam or editor and kind == "inbetween") or source.persons != 1 \
                or not isinstance(generator, Editor):
            why = ("this segment has two people" if source.persons != 1
                   else (generator.reason if isinstance(generator, Editor) else None)
                   or ("a captured segment is re-drawn, not edited" if editor else "not loaded"))
            raise CannotApply(f"{kind} needs the SPAM model for one person ({why})")
        full = source.people[0, :source.written].copy()
        full[a:b] = people[0]
        span = (a, b)
        if kind == "inbetween":
            span = (a + int(instr["frames"][0]), a + int(instr["frames"][1]))
        part = instr.get("part") if kind == "edit_part" else None
        edit, _ = generator.edit(full, part, instr["prompt"], span, s, context=seg.prompt)
        calls.append(None)
        return [np.asarray(edit.joints, dtype=np.float64)[a:b]]

    window = [source.people[p, a:b].copy() for p in range(source.persons)]
    last = i == len(source.plan.segments) - 1
    out = correct(seg, window, apply, evaluator=evaluator, rounds=cfg.rounds,
                  tolerance=cfg.tolerance, seed=seed, emit=emit, resolved=resolved,
                  free_ends=(i == 0, last), asked=asked_of(seg) if source.persons == 1 else None,
                  pair_checked=pair_checked,
                  pair_evaluator=default_pair_evaluator() if evaluator is not None
                  and source.persons == 2 else None)
    applied = [e for e in out.corrections if e["score_after"] is not None]
    redrawn = [c for c, e in zip(calls, applied) if e["accepted"] and c is not None]
    if redrawn:
        source.adopt(redrawn[-1], b)
    if any(e["accepted"] for e in applied):
        for p in range(source.persons):
            source.people[p, a:b] = out.people[p]
        for s in range(a, b, CHUNK):
            on_frames(s, [source.people[p, s:min(b, s + CHUNK)] for p in range(source.persons)])
    return {"segment": i, **out.history()}
