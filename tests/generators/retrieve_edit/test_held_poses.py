"""Held poses (`retrieve_edit/holds.py`, issue 14 item 5) through the studio's pipeline on real
prompts over the real captures, judged by the benchmark's checks: standing on one leg (the
named stance foot stays down), a squat held down, standing still, arms out to the sides; and
what must not be held (a counted squat goes down and up again)."""

import numpy as np
import pytest

from interplay.generators.base import Request
from interplay.generators.retrieval.intent import hold_of
from interplay.generators.router import load_generator
from interplay.motion.checks import measures as m
from interplay.motion.checks.named import plausibility, run_check
from interplay.pipeline.orchestrator import orchestrate

SEEDS = (0, 1)


@pytest.fixture(scope="module")
def gen():
    return load_generator()          # the product default: retrieve-then-edit for one person


def _people(gen, prompt, seed, seconds=6.0):
    out = orchestrate(gen, Request(prompt, 1, seconds, seed), lambda e: None, lambda s, f: None)
    return [np.asarray(p, np.float64) for p in out.people], out


@pytest.mark.parametrize("prompt,spec", [
    ("balance on your left foot", {"check": "pose_held", "pose": "one_leg", "min_s": 2.0}),
    ("stay down in a low squat", {"check": "pose_held", "pose": "squat", "min_s": 2.0}),
    ("squat down and hold it", {"check": "pose_held", "pose": "squat", "min_s": 2.0}),
    ("stand completely motionless", {"check": "still"}),
    ("freeze and don't move", {"check": "still"}),
    ("keep your arms out", {"check": "pose_held", "pose": "t_pose", "min_s": 2.0}),
])
def test_a_held_pose_is_held(gen, prompt, spec):
    for seed in SEEDS:
        people, out = _people(gen, prompt, seed)
        r = run_check(people, spec)
        assert r.passed, (prompt, seed, r.value, out.plan.generator_reason)
        bad = [x.check for x in plausibility(people) if not x.passed]
        assert not bad, (prompt, seed, bad)


def test_the_named_stance_foot_stays_down_and_the_other_is_lifted(gen):
    people, _ = _people(gen, "balance on your left foot", 0)
    b = m.frame_of(people[0])
    mid = slice(30, 90)
    assert np.median(b.foot_height("right")[mid]) >= 0.15
    assert np.median(b.foot_height("left")[mid]) <= 0.05


def test_a_counted_squat_is_not_held():
    assert hold_of("a person squats twice") is None and hold_of("a person hops on one leg") is None
    assert hold_of("a person stands still") is None          # a stop: the captured stand


def test_a_squat_count_still_goes_down_and_up(gen):
    people, _ = _people(gen, "squat twice", 0)
    assert run_check(people, {"check": "squat_count", "count": 2}).passed
