"""The job pipeline's review of a two-person interaction on the whole motion (issue 15 items
3–4): what the prompt asks the two to do together (`interaction.kinds.read_script`, the
plan's composition when composition made it) is judged by the benchmark's own pair checks
(`motion.checks.named`: handshake, high five, hug, push, wave back, follows, a couple's dance
close together with its spin, …). Part captions
cannot say "shakes hands" or "hugs", and an interaction spans segments (a push, then the
stumble), so this runs once over the finished frames, after the per-segment reviews.

A motion that misses one is made again with another seed (the same generator's plan for the
same request, deterministic for the job's seed), resolved by the penetration pass, and kept
when it passes more of the checks; at most `tries` times. Events go to the stream as review /
correction events on the last segment, so the studio's timeline shows the verdict.

    specs = interaction_specs(plan)       # [{"check": "handshake"}]
    people, plan, report = review_interaction(generator, req, plan, people, emit, on_frames)
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from interplay.catalogue.words import words
from interplay.generators.base import Generator, Request
from interplay.generators.interaction.kinds import kind_checks, read_script
from interplay.generators.interaction.scene import idle_role
from interplay.generators.plan import GenerationPlan
from interplay.generators.retrieval.couple import asks_spin
from interplay.generators.retrieval.intent import intent
from interplay.generators.retrieval.verify import COUNT_CHECKS
from interplay.generators.retrieval.verify import checks as asked_checks
from interplay.motion.pair.resolve import pair_bounds
from interplay.pipeline import pair_pass
from interplay.review import asked
from interplay.review.checks import contact_mode

OnFrames = Callable[[int, list[np.ndarray]], None]
CHUNK = 40
DANCE_CHECKS = [{"check": "close_together"}, {"check": "active", "person": "both"}]


def interaction_specs(plan: GenerationPlan) -> list[dict]:
    """The pair checks a two-person plan's words ask for ([] for one person, or when the
    prompt names no interaction the checks know)."""
    if plan.persons != 2:
        return []
    spin = asks_spin(plan.prompt)
    if spin or words("dance").search(plan.prompt.lower()):
        return [dict(s) for s in DANCE_CHECKS] + ([{"check": "partner_spin"}] if spin else [])
    comp = plan.composition or {}
    script = comp.get("script")
    if script:
        kind, held, approach = script["kind"], bool(script["held"]), bool(script["approach"])
    else:
        read = read_script(plan.prompt)
        if read is None:
            return []
        kind, held, approach = read.kind, read.held, read.approach
    if kind == "together":
        roles = {str(k): v for k, v in (plan.segments[0].roles or {}).items()}
        text = roles.get("0") or plan.segments[0].prompt
        return [{**spec, "person": "both"} for spec in _counted(intent(text, plan.segments[0].repeat))]
    out = [dict(s) for s in kind_checks(kind)]        # the catalogue entry's checks
    if held:
        out.insert(0, {"check": "hands_held"})
    if approach and kind != "approach":
        out.insert(0, {"check": "approach"})
    return out


def _counted(it) -> list[dict]:
    """The count check of a counted action a person's words name ("squats": squat_count; "kicks":
    kick), the count said or at least one; [] for other words."""
    n = {"count": it.count} if it.count is not None else {"at_least": 1}
    if it.action in COUNT_CHECKS:
        return [{"check": COUNT_CHECKS[it.action], **n}]
    if it.action in ("kick", "punch"):
        key = "leg" if it.action == "kick" else "hand"
        return [{"check": it.action, key: it.side or "any", **n}]
    return []


# An interaction the words do not name but the text encoder read from its nearest description
# passes its kind's checks without confirming the words unless that description is a near
# paraphrase (cosine ≥ SURE_GUESS, the bound a primitive needs over a captured verb): below it
# the verdict is `unconfirmed`, not `ok`.
SURE_GUESS = 0.8


def _bounds_ok(people: np.ndarray, plan: GenerationPlan) -> bool:
    return all(pair_bounds(people[0, s.start:s.end], people[1, s.start:s.end],
                           contact_mode(s.prompt))["ok"]
               for s in plan.segments if s.end - s.start >= 2 and s.end <= people.shape[1])


# A person's role read as one person's words are (`retrieval.intent`, `verify.checks`), and
# the checks of that reading kept for the two: where they go, what they count, kick or punch,
# how they turn, whether they stay. Postures and speeds are the composed kind's to decide.
ROLE_CHECKS = ("travel_direction", "kick", "punch", "jump_count", "squat_count", "step_count",
               "turn", "stays_in_place")


def role_specs(plan: GenerationPlan) -> list[tuple[tuple[int, int], dict]]:
    """((start, end) frames, spec with its `person`) for what each person's role asks on its own
    ("a person walks away": travel forward; "squats three times": three squats) in the segments
    where their roles are their own (each to their own part face to face; after the
    interaction; both doing the leader's part where one copies the other), beside the
    interaction's checks: the kind may pass while a person's part of
    the words is missing, and the verdict must not say `ok` then."""
    comp = plan.composition or {}
    script = comp.get("script") or {}
    kind = script.get("kind")
    # the roles are the kind's own parts (a push and its stumble, a handshake) except where
    # each does their own part (face to face), after the interaction (who leaves), and where
    # one copies the other (mirror: the leader's part is asked of both)
    own = kind in ("face_to_face", "mirror")
    start = 0 if own else int((comp.get("after") or {}).get("frame", -1))
    if plan.persons != 2 or start < 0:
        return []
    leader = str(script.get("actor", 0))
    out = []
    for seg in [s for s in plan.segments if s.start >= start]:
        roles: dict[str, str] = {str(k): v for k, v in (seg.roles or {}).items()}
        for key, role in roles.items():
            person, text = int(key), str(role or "").strip().rstrip(".")
            if kind == "mirror":                        # the copier does the leader's part
                text = str(roles.get(leader) or "").strip().rstrip(".")
            if (kind != "mirror" and person not in seg.persons) or not text or idle_role(text):
                continue
            it = intent(text, seg.repeat)
            specs = [spec for spec in asked_checks(it, None, None) if spec["check"] in ROLE_CHECKS]
            # a counted action with no count said is asked at least once ("demonstrates a kick")
            specs += [c for c in _counted(it) if c["check"] not in {x["check"] for x in specs}]
            out += [((seg.start, seg.end), {**spec, "person": person}) for spec in specs]
    return out


def _missed(specs: list[dict], roles: list[tuple[tuple[int, int], dict]], people: np.ndarray
            ) -> list[tuple[str, str]]:
    """The interaction's checks missed on the whole motion, then each role's (`role_specs`) on
    its segment."""
    out = asked.missed(list(people), specs)
    for (a, b), spec in roles:
        if b <= people.shape[1]:
            out += [(name, f"person {spec['person']}: {why}") for name, why in
                    asked.missed([p[a:b] for p in people], [spec])]
    return out


def _event(plan: GenerationPlan, r: int, specs: list[dict], people: np.ndarray
           ) -> tuple[dict, int, int]:
    """The review event of one round, how many of the checks passed and of how many (the
    interaction's and the roles'; run once each)."""
    roles = role_specs(plan)
    missed = _missed(specs, roles, people)
    failed = {f"asked_{name}": why for name, why in missed}
    instructions = [{"kind": "regenerate", "prompt": plan.prompt,
                     "reason": "the two do not do what was asked: "
                               + "; ".join(w for _, w in missed)}] if missed else []
    n = len(specs) + len(roles)
    checks: dict = {"failed": failed, "windows": [], "metrics": {}}
    guess = ((plan.composition or {}).get("script") or {}).get("guessed")
    verdict = "correct" if missed else "ok"
    if verdict == "ok" and guess is not None and guess < SURE_GUESS:
        verdict = "unconfirmed"
        checks["unconfirmed"] = (f"the interaction was read by the text encoder ({guess:.2f} to "
                                 "its nearest description), not named: its checks test that reading")
    return {"type": "review", "segment": plan.segments[-1].index, "round": r,
            "captions": {}, "summary": f"interaction checks: {n - len(missed)} of {n} passed",
            "score": round((n - len(missed)) / n, 4), "score_kind": "interaction_checks",
            "confirmed": {}, "checks": checks,
            "instructions": instructions, "verdict": verdict}, n - len(missed), n


def _made(generator: Generator, req: Request, seed: int) -> tuple[GenerationPlan, np.ndarray]:
    plan = generator.plan(Request(req.prompt, req.persons, req.seconds, seed))
    chunks = [c for _, c in generator.stream(req, plan)]
    people = np.stack([np.concatenate([np.asarray(c[p], np.float64) for c in chunks])
                       for p in range(2)])
    pair_pass.resolve_motion(people, plan, lambda *_: None)
    return plan, people


def review_interaction(generator: Generator, req: Request, plan: GenerationPlan,
                       people: np.ndarray, emit: Callable[[dict], None], on_frames: OnFrames,
                       first_round: int = 1, tries: int = 2
                       ) -> tuple[np.ndarray, GenerationPlan, dict | None]:
    """Judge `people` (2, T, 22, 3) by the plan's interaction checks, re-make it up to `tries`
    times while one fails; (people, plan, report for the job's review) — the inputs when the
    plan asks no checks, or nothing better was made."""
    specs = interaction_specs(plan)
    if not specs or people.shape[0] != 2:
        return people, plan, None
    event, best, of = _event(plan, first_round, specs, people)
    emit(event)
    rounds, corrections = [event], []
    rng = np.random.default_rng([plan.seed % 2**63, 15])
    for k in range(tries):
        if not rounds[-1]["instructions"]:          # nothing missed (the roles' checks too)
            break
        seed = int(rng.integers(2**31))
        instr = rounds[-1]["instructions"][0]
        correction = {"type": "correction", "segment": event["segment"], "round": first_round + k + 1,
                      "instruction": {**instr, "seed": seed}, "accepted": False,
                      "score_before": rounds[-1]["score"], "score_after": None}
        try:
            new_plan, new = _made(generator, req, seed)
        except ValueError as exc:           # a generator that cannot make it again says why
            correction["reason"] = str(exc)
            corrections.append(correction)
            emit(correction)
            break
        after, got, got_of = _event(new_plan, first_round + k + 1, specs, new)
        correction["score_after"] = after["score"]
        if got > best and new.shape[1] == people.shape[1] and _bounds_ok(new, new_plan):
            correction["accepted"] = True
            people, plan, best, of = new, new_plan, got, got_of
            plan.reasons.append(f"interaction review: made again with seed {seed} "
                                f"({instr['reason']})")
            n = people.shape[1]
            for s in range(0, n, CHUNK):
                on_frames(s, [p[s:min(n, s + CHUNK)] for p in people])
            corrections.append(correction)
            emit(correction)
            emit(after)
            rounds.append(after)
        else:
            correction["reason"] = ("it passes no more of the checks" if got <= best
                                    else "over the penetration bound")
            corrections.append(correction)
            emit(correction)
    if rounds[-1]["instructions"]:       # what the tries could not fix ends failed, never "correct"
        last = rounds[-1]
        final = {**last, "round": max(last["round"], *(c["round"] for c in corrections)) + 1
                 if corrections else last["round"] + 1,
                 "verdict": "failed", "instructions": [],
                 "summary": f"{last['summary']}; not fixed after {len(corrections)} "
                            f"{'try' if len(corrections) == 1 else 'tries'}"}
        emit(final)
        rounds.append(final)
    return people, plan, {"checks": specs, "rounds": rounds, "corrections": corrections,
                          "passed": best, "of": of}
