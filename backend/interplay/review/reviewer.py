"""The motion reviewer (CoMA §3, Algorithm 1 lines 7–16, appendix F) without a video model:
captions per body part from pose codes (`motion.posecodes`), a text–motion alignment score
(the evaluator's cosine when its weights load, else the agreement of the captions with the
plan by MiniLM — the result says which), commonsense checks (`review_checks`), and a
comparison with the plan in the spirit of F.3 (`review_text`): each part with a planned edit
is confirmed by its caption or gets an `edit_part` instruction; bad frame windows get an
`inbetween`; a segment whose body caption contradicts its base motion (or that misses a
touch the text asks for) gets `regenerate` with a new seed. Two people over the penetration
bound (issue 15: `motion.pair.resolve.pair_bounds`) get `resolve_penetration`, which the
reviewer runs itself (`motion.pair.resolve.resolve_pair`, keeping the contact the text asks
for), and `regenerate` when the resolution has already run and the bound still fails; every
two-person correction is resolved the same way before it is reviewed. So a review never says
"ok" to two people over the bound.

    rv = review(segment, [joints])            # Review: captions, score, checks, instructions
    out = correct(segment, [joints], apply)   # ≤ K rounds; a round that makes it worse stops

`apply(instruction, people, seed) -> people` runs one instruction through the generator's
edit operations (the orchestrator supplies it); it raises CannotApply when the generator
cannot run that kind (e.g. part edits without SPAM)."""

from __future__ import annotations

from dataclasses import replace
from typing import Any, Callable

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.captions import PARTS, summarise
from interplay.motion.posecodes import caption_clip
from interplay.planner.schema import Segment
from interplay.review import asked as asked_checks
from interplay.review.agreement import BODY_CUES, confirms, cued
from interplay.review.checks import Checks, commonsense, worse
from interplay.review.evaluator import Evaluator
from interplay.review.judge import WORDS, judge, not_covered
from interplay.review.records import Corrected, Review, Verdict
from interplay.review.resolution import better, resolution_words, resolve_people
from interplay.text.encoder import Encoder

__all__ = ["CannotApply", "Corrected", "RESOLVE", "Review", "correct", "resolution_words",
           "resolve_people", "review"]

PLAN_PART = {"left_arm": "left_upper", "right_arm": "right_upper",
             "left_leg": "left_lower", "right_leg": "right_lower"}
REGENERATE_SCORE = 0.25       # caption agreement under this, with no body cue: the segment is off
MAX_INSTRUCTIONS = 3          # per round (a regenerate goes alone)
RESOLVE = "resolve_penetration"
SCORE_EPS = 1e-6


class CannotApply(RuntimeError):
    """The generator cannot run this instruction (the message says why)."""


def part_captions(joints: np.ndarray) -> tuple[dict[str, list[str]], str]:
    """(part → distinct caption texts in time order, one-sentence summary) of one person."""
    caps = caption_clip(np.asarray(joints, dtype=np.float64))
    texts: dict[str, list[str]] = {p: [] for p in PARTS}
    for c in sorted(caps, key=lambda c: c.start):
        if c.text not in texts[c.part]:
            texts[c.part].append(c.text)
    return texts, summarise(caps)


def _texts(seg: Segment, persons: int) -> list[str]:
    roles: dict[str, str] = {str(k): v for k, v in (seg.roles or {}).items()}
    return [roles.get(str(i)) or seg.prompt for i in range(persons)]


def review(seg: Segment, joints, evaluator: Evaluator | None = None,
           encoder: Encoder | None = None, round: int = 0, resolved: bool = False,
           asked: list[dict] | None = None, pair_checked: bool = False,
           pair_evaluator: Evaluator | None = None, final: bool = False) -> Review:
    """Review one planned segment: `joints` one (T, 22, 3) array per person for the segment's
    frames (T ≥ 3). `resolved`: the penetration resolution has already run on these frames
    (then a pair still over the bound is re-generated rather than resolved again). `asked`:
    the benchmark's checks the segment's words imply (`review.asked`); one it misses fails the
    segment and asks for it again. `pair_checked`: two people whose interaction the
    pipeline judges by its pair checks on the whole motion (`pipeline.pair_review`); their
    part edits ("shakes hands", "hugs") are then not judged by one person's captions, which
    have no words for them. The evaluator's score (the pair evaluator's for two people, when
    given and the text is one it knows) under its calibrated threshold fails the segment and
    asks for it again (`review.judge`). A segment the generator could only show the nearest
    thing for (`coverage.how == "nearest"`) is `not_covered`, never `ok`. `final`: no
    correction follows, so a segment still failing is `failed`, not `correct`."""
    people = [np.asarray(p, dtype=np.float64) for p in joints]
    if not people or any(p.ndim != 3 or p.shape[1:] != (sk.NUM_JOINTS, 3) for p in people):
        raise ValueError(f"joints must be one (T, 22, 3) array per person, got "
                         f"{[getattr(p, 'shape', None) for p in people]}")
    if encoder is None:
        from interplay.text.encoder import get_encoder
        encoder = get_encoder()
    captioned = [part_captions(p) for p in people]
    texts = _texts(seg, len(people))
    judged = judge(people, seg.prompt, texts, [s for _, s in captioned], evaluator,
                   pair_evaluator, encoder, base=seg.base if seg.edits.named() else None,
                   vouched=getattr(getattr(seg, "coverage", None), "how", None)
                   in ("capture", "primitive", "composed"))
    score, kind = judged.score, judged.kind
    parts0, summary0 = captioned[0]
    edits = {} if pair_checked and len(people) == 2 else seg.edits.named()
    confirmed: dict[str, bool] = {}
    instructions: list[dict[str, Any]] = []
    for part, planned in edits.items():
        model_part = PLAN_PART.get(part, part)
        ok, _ = confirms(planned, parts0.get(model_part, []), encoder=encoder)
        confirmed[part] = ok
        if not ok:
            said = "; ".join(parts0.get(model_part, [])) or "nothing"
            instructions.append({"kind": "edit_part", "part": part, "prompt": planned,
                                 "reason": f"the plan says '{planned}', the caption says '{said}'"})
    base = seg.base or seg.prompt
    body_ok, bodies = None, [t for c, _ in captioned for t in c["body"]]
    # The body caption may show the base ("stands") or the whole step ("kicks"): either counts.
    for text in dict.fromkeys((base, seg.prompt)):
        if cued(text, BODY_CUES):
            body_ok = body_ok or confirms(text, bodies, BODY_CUES)[0]
    checks: Checks = commonsense(people, seg.prompt)
    missed = asked_checks.missed(people, asked)
    for name, why in missed:
        checks.failed[f"asked_{name}"] = why
    if judged.failure:
        checks.failed[WORDS] = judged.failure
    uncovered = not_covered(seg)
    if uncovered:
        checks.failed["not_covered"] = uncovered
    regenerate = None
    if uncovered:       # nothing to re-draw it from: said, not corrected
        instructions = []
    elif judged.failure:
        regenerate = judged.failure + (" (" + "; ".join(w for _, w in missed) + ")" if missed else "")
    elif body_ok is False:
        regenerate = (f"the plan says '{base}', the body caption says "
                      f"'{'; '.join(parts0['body'])}'")
    elif body_ok is None and kind == "caption_agreement" and score < REGENERATE_SCORE:
        regenerate = f"the captions ('{summary0}') hardly agree with '{seg.prompt}'"
    elif "missing_contact" in checks.failed:
        regenerate = checks.failed["missing_contact"]
    elif "interpenetration" in checks.failed and resolved:
        regenerate = checks.failed["interpenetration"] + ", after the resolution"
    elif missed:
        regenerate = "the motion does not do what was asked: " + "; ".join(w for _, w in missed)
    if regenerate:
        instructions = [{"kind": "regenerate", "prompt": seg.prompt, "reason": regenerate}]
    elif not uncovered:
        if "interpenetration" in checks.failed:
            instructions.insert(0, {"kind": RESOLVE, "reason": checks.failed["interpenetration"]})
        instructions += [{"kind": "inbetween", "frames": [a, b], "prompt": seg.prompt,
                          "reason": f"{r} in frames {a}–{b}"} for a, b, r in checks.windows]
    instructions = instructions[:MAX_INSTRUCTIONS]
    # one person's words the calibrated judge could not judge: not failed, not confirmed
    unjudged = (len(people) == 1 and judged.threshold is None
                and getattr(evaluator, "calibration", None) is not None)
    checked = checks.to_json()
    if unjudged:
        checked["unconfirmed"] = (f"the evaluator's calibration does not hold for "
                                  f"'{judged.text}': its score {score:.2f} was not judged")
    verdict: Verdict = ("not_covered" if uncovered
                        else ("unconfirmed" if unjudged else "ok") if not instructions
                        else "failed" if final and still_failing(checks.failed, instructions)
                        else "correct")
    return Review(segment=seg.index, round=round,
                  captions={p: "; ".join(v) for p, v in parts0.items()}, summary=summary0,
                  score=round_(score), score_kind=kind, confirmed=confirmed,
                  body_confirmed=body_ok, checks=checked, instructions=instructions,
                  verdict=verdict, person_captions=[s for _, s in captioned],
                  threshold=judged.threshold, confidence=judged.confidence)


WORDS_FAIL = (WORDS, "missing_contact", "interpenetration")     # and every asked_<check>


def still_failing(failed: dict, instructions: list[dict]) -> bool:
    """A segment with nothing more to try fails when it still misses what its words ask: the
    judge's threshold, an asked check, a touch, the penetration bound, or a body caption that
    contradicts them (its re-draw is still asked for). One left only with polish (part edits
    its captions do not show, in-betweens over bad-frame runs) stays `correct`: not `ok`,
    but not contradicted either."""
    return any(k in WORDS_FAIL or k.startswith("asked_") for k in failed) \
        or any(i["kind"] in ("regenerate", RESOLVE) for i in instructions)


def round_(x: float) -> float:
    return float(np.round(x, 4))


def correct(seg: Segment, joints, apply: Callable, evaluator: Evaluator | None = None,
            rounds: int = 2, tolerance: float = 0.1, seed: int = 0, encoder: Encoder | None = None,
            emit: Callable[[dict], None] | None = None, resolved: bool = False,
            free_ends: tuple[bool, bool] = (True, True), asked: list[dict] | None = None,
            pair_checked: bool = False, pair_evaluator: Evaluator | None = None) -> Corrected:
    """Algorithm 1's self-correction loop on one segment: review, run the instructions through
    `apply`, at most `rounds` rounds. A correction is kept only if the score does not drop and
    no watched metric gets worse beyond `tolerance`; otherwise the previous motion is kept and
    the loop stops, except after a rejected re-draw (`regenerate`), which is tried again with
    another seed in the next round (the best draw so far is kept). A segment still failing
    when the loop ends (`still_failing`) gets a last review with verdict `failed` (its checks
    say why), never `ok`. `emit` receives the review and correction events. The last review's calibrated
    confidence goes into the segment's `coverage.confidence` when it has a coverage.

    Two people: `resolve_penetration` is run here (`resolve_people`, the segment's edges free
    or eased as `free_ends` says) and kept when it meets the penetration bound or lowers it
    (bones cannot change: rigid moves and IK); whatever `apply` returns for two people is
    resolved before it is reviewed. `resolved`: the frames given were resolved already.
    `asked` (`review.asked`): a correction that passes more of these checks is kept unless it
    makes a watched metric worse; one that passes fewer is rejected. One that newly passes the
    judge's threshold is kept unless a check fails that passed before (its metrics may move)."""
    if rounds < 0:
        raise ValueError(f"rounds must be ≥ 0, got {rounds}")
    emit = emit or (lambda e: None)
    people = [np.asarray(p, dtype=np.float64) for p in joints]
    kw: dict[str, Any] = dict(evaluator=evaluator, encoder=encoder, asked=asked, pair_checked=pair_checked,
              pair_evaluator=pair_evaluator)
    current = review(seg, people, round=0, resolved=resolved, final=rounds == 0, **kw)
    emit(current.event())
    reviews, corrections, stop, last_round = [current], [], False, 0
    rng = np.random.default_rng([seed % 2**63, seg.index])
    for r in range(1, rounds + 1):
        if current.verdict != "correct" or stop:
            break
        changed, again, last_round = False, False, r
        for instr in current.instructions:
            event = {"type": "correction", "segment": current.segment, "round": r,
                     "instruction": instr, "accepted": False, "score_before": current.score,
                     "score_after": None}
            report = None
            try:
                if instr["kind"] == RESOLVE:
                    candidate, report = resolve_people(seg, people, free_ends)
                else:
                    candidate = apply(instr, people, int(rng.integers(2**31)))
                    if len(candidate) == 2:
                        candidate, _ = resolve_people(seg, candidate, free_ends)
            except CannotApply as exc:
                event["reason"] = str(exc)
                corrections.append(event)
                emit(event)
                continue
            two = len(candidate) == 2
            after = review(seg, candidate, round=r, resolved=resolved or two,
                           final=r == rounds, **kw)
            event["score_after"] = after.score
            if report is not None:
                # a physical fix: kept when the bound is met or lower, whatever the text score
                ok = better(report["before"], report["after"])
                event["reason"] = resolution_words(report)
            else:
                worse_keys = worse(current.metrics, after.metrics, tolerance)
                if WORDS in current.checks["failed"] and WORDS not in after.checks["failed"]:
                    # it now shows its words: a watched metric may move (a jump floats)
                    # as long as no check fails that passed before
                    worse_keys = sorted(set(after.checks["failed"]) - set(current.checks["failed"]))
                gain = asked_checks.passed(candidate, asked) - asked_checks.passed(people, asked)
                ok = not worse_keys and (gain > 0 or gain == 0
                                         and after.score + SCORE_EPS >= current.score)
                if not ok:
                    event["reason"] = (f"worse {', '.join(worse_keys)}" if worse_keys else
                                       f"it misses {-gain} more of what was asked" if gain < 0
                                       else "the score dropped")
            if ok:
                event["accepted"] = True
                people = [np.asarray(p, np.float64) for p in candidate]
                current, changed, resolved = after, True, resolved or two
            elif instr["kind"] == "regenerate":
                again = True            # another draw next round; this one is not kept
            else:
                stop = True
            corrections.append(event)
            emit(event)
            if stop:
                break
        if not changed:
            if again:
                continue
            break
        current = review(seg, people, round=r, resolved=resolved, final=r == rounds, **kw)
        emit(current.event())
        reviews.append(current)
    if current.verdict == "correct" and still_failing(current.checks["failed"],
                                                      current.instructions):
        current = replace(current, round=last_round, verdict="failed")
        emit(current.event())
        reviews.append(current)
    cov = getattr(seg, "coverage", None)
    if cov is not None and current.confidence is not None:
        cov.confidence = current.confidence
    return Corrected(people=people, reviews=reviews, corrections=corrections)
