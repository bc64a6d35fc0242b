"""The pipeline's review of a two-person interaction on the whole motion
(`pipeline/pair_review.py`): the benchmark's pair checks stand for the part edits that one
person's captions cannot confirm ("shakes hands"), a pair that misses them is made again and
kept only when it passes more of them, and the studio's timeline gets the verdict. Real
prompts, the real composition over the processed captures."""

import numpy as np
import pytest

from interplay.generators.base import Request
from interplay.generators.router import load_generator
from interplay.motion.checks.named import run_check
from interplay.pipeline.orchestrator import orchestrate
from interplay.pipeline.pair_review import interaction_specs, review_interaction


@pytest.fixture(scope="module")
def gen():
    return load_generator(use_spam=False)


def _run(gen, prompt, seed=0, seconds=6.0):
    events = []
    out = orchestrate(gen, Request(prompt, 2, seconds, seed), events.append, lambda s, f: None)
    return out, events


def test_a_composed_handshake_is_judged_by_the_handshake_check_not_by_captions(gen):
    out, events = _run(gen, "two people shake hands")
    seg = out.plan.segments[0]
    assert {k: v for k, v in seg.edits.named().items() if v} == {"right_arm": "shakes hands"}
    reviews = [e for e in events if e["type"] == "review"]
    assert reviews[-1]["score_kind"] == "interaction_checks" and reviews[-1]["verdict"] == "ok"
    # no part edit asked of one person's captions ("the right arm rests at the side")
    assert not any(i["kind"] == "edit_part" for e in reviews for i in e["instructions"])
    assert out.review["interaction"]["passed"] == out.review["interaction"]["of"] == 1
    assert run_check(out.people, {"check": "handshake"}).passed
    # the stored timeline holds the same rounds on the last segment
    stored = out.review["segments"][-1]["reviews"]
    assert stored[-1]["score_kind"] == "interaction_checks"


def test_a_pair_that_misses_its_interaction_is_made_again(gen):
    req = Request("two people hug", 2, 6.0, 0)
    plan = gen.plan(req)
    people = np.stack([np.concatenate([c[p] for _, c in gen.stream(req, plan)]) for p in range(2)])
    apart = people.astype(np.float64).copy()
    apart[1, :, :, 0] += 1.5                            # the partner stepped away: no hug
    assert not run_check(list(apart), {"check": "hug"}).passed
    events, sent = [], []
    new, new_plan, report = review_interaction(gen, req, plan, apart, events.append,
                                               lambda s, f: sent.append(s))
    assert [e["type"] for e in events][:2] == ["review", "correction"]
    assert events[0]["verdict"] == "correct" and "hug" in events[0]["instructions"][0]["reason"]
    assert events[1]["accepted"] and events[-1]["verdict"] == "ok"
    assert run_check(list(new), {"check": "hug"}).passed and report["passed"] == 1
    assert sent and new.shape == apart.shape
    assert any("interaction review: made again" in r for r in new_plan.reasons)


def test_without_tries_a_miss_is_reported_not_passed(gen):
    req = Request("two people hug", 2, 6.0, 0)
    plan = gen.plan(req)
    people = np.stack([np.concatenate([c[p] for _, c in gen.stream(req, plan)]) for p in range(2)])
    people = people.astype(np.float64)
    people[1, :, :, 0] += 1.5
    events = []
    same, _, report = review_interaction(gen, req, plan, people, events.append,
                                         lambda s, f: None, tries=0)
    assert same is people and report["passed"] == 0
    assert [e["verdict"] for e in events] == ["correct", "failed"]     # the miss is the last word
    assert report["rounds"][-1]["verdict"] == "failed" and "not fixed after 0 tries" in events[-1]["summary"]


@pytest.mark.parametrize("prompt,checks", [
    ("two people hug", ["hug"]),
    ("they walk towards each other and hug", ["approach", "hug"]),
    ("they walk side by side holding hands", ["hands_held", "side_by_side"]),
    ("one pushes the other, who stumbles backwards", ["push"]),
    ("two people jump together", ["jump_count"]),
    ("two people dance salsa together", ["close_together", "active"]),
    ("the leader spins the follower", ["close_together", "active", "partner_spin"]),
])
def test_the_checks_an_interaction_asks_for(gen, prompt, checks):
    plan = gen.plan(Request(prompt, 2, 6.0, 0))
    assert [s["check"] for s in interaction_specs(plan)] == checks


@pytest.fixture(scope="module")
def router():
    return load_generator()            # the product default: two people composed


def test_each_persons_own_words_are_checked_where_the_roles_are_their_own(router):
    """After the interaction (who leaves) a person's role is read as one person's words are: backing
    away asks travel backwards of them; the kind's own parts (a push's stumble, a couple's spin)
    are left to the kind's checks."""
    from interplay.pipeline.pair_review import role_specs
    plan = router.plan(Request("they hug, then one walks away backwards", 2, 8.0, 0))
    specs = role_specs(plan)
    assert specs and all(s["check"] == "travel_direction" and s["direction"] == "backward" for _, s in specs)
    assert all(a == plan.composition["after"]["frame"] for (a, _), _ in specs)
    for prompt in ("one pushes the other, who stumbles backwards", "the leader spins the follower",
                   "two people shake hands"):
        assert role_specs(router.plan(Request(prompt, 2, 6.0, 0))) == []
    out, _ = _run(router, "they hug, then one walks away backwards", seconds=8.0)
    assert out.review["interaction"]["of"] == 1 + len(specs)
    assert out.review["interaction"]["passed"] == out.review["interaction"]["of"]


def test_who_copies_is_asked_the_leaders_part(router):
    """One shows, the other copies: both are asked the leader's counted action ("demonstrates a
    front kick": a kick each), and the plan gives the copier their own part (it copied nothing
    while "the student copies it" stayed in the leader's role)."""
    from interplay.pipeline.pair_review import role_specs
    prompt = "a karate teacher demonstrates a front kick and the student copies it"
    plan = router.plan(Request(prompt, 2, 7.0, 0))
    assert plan.composition["script"]["kind"] == "mirror"
    specs = role_specs(plan)
    assert sorted(s["person"] for _, s in specs) == [0, 1] and all(s["check"] == "kick" for _, s in specs)
    out, _ = _run(router, prompt, seconds=7.0)
    assert out.review["interaction"]["of"] == 1 + len(specs)
    people = [np.asarray(p, np.float64) for p in out.people]
    assert run_check(people, {"check": "kick", "leg": "any", "at_least": 1, "person": "both"}).passed
