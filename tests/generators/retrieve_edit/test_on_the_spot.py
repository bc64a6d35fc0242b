"""Words that ask to stay on the spot ("hop on the spot", "march in place") keep the body within
the benchmark's 0.6 m (retrieval.on_the_spot): the captured hops and marches travel 4–7 m in
6 s, so their drift is taken out and the planted feet put back; words without them still travel.
"Skip with a rope" is the skipping rope activity, not the captured skip that travels."""

import numpy as np
import pytest

from interplay.generators.base import Request, generate_motion
from interplay.generators.retrieval import on_the_spot
from interplay.generators.retrieval.intent import hold_of, intent
from interplay.generators.router import load_generator
from interplay.motion.checks.named import plausibility, run_check

SEEDS = (0, 1, 2)


@pytest.fixture(scope="module")
def router():
    return load_generator()          # the product default: retrieve-then-edit for one person


def _stays(joints) -> float:
    r = run_check([joints], {"check": "stays_in_place", "max_m": 0.6})
    assert r.passed, r.value
    return r.value


@pytest.mark.parametrize("prompt", ["hop on the spot", "march in place",
                                    "march in place lifting your knees", "jog on the spot"])
def test_on_the_spot_stays_within_the_bound(router, prompt):
    for seed in SEEDS:
        (joints,) = generate_motion(router, Request(prompt, 1, 6.0, seed)).people
        _stays(joints)
        pops = next(p for p in plausibility([joints]) if p.check == "no_pops")
        assert pops.passed, (seed, pops.value)


def test_the_hops_are_still_hops_and_the_knees_still_rise(router):
    for seed in SEEDS:
        (hop,) = generate_motion(router, Request("hop on the spot", 1, 6.0, seed)).people
        assert run_check([hop], {"check": "jump_count", "at_least": 1}).passed, seed
    (march,) = generate_motion(router, Request("march in place lifting your knees", 1, 5.0, 0)).people
    assert run_check([march], {"check": "knee_raise", "at_least": 3}).passed


def test_retrieval_alone_keeps_a_hop_on_the_spot(router):
    for seed in SEEDS:
        _stays(router.retrieval.generate(Request("hop on the spot", 1, 6.0, seed)).people[0])


def test_words_without_the_spot_still_travel(router):
    for seed in SEEDS:
        (joints,) = generate_motion(router, Request("hop forward", 1, 6.0, seed)).people
        assert run_check([joints], {"check": "travels", "min_m": 1.0}).passed, seed


def test_a_walk_then_hops_on_the_spot_joins_without_a_jump(router):
    m = generate_motion(router, Request("walk forward, then hop on the spot", 1, 10.0, 0))
    (joints,) = m.people
    seg = m.plan["segments"][1]
    run = joints[:seg["start"]]
    assert run_check([run], {"check": "travels", "min_m": 1.0}).passed   # the walk still walks
    _stays(joints[seg["start"]:seg["end"]])
    pops = next(p for p in plausibility([joints]) if p.check == "no_pops")
    assert pops.passed, pops.value


def test_stay_takes_out_the_drift_and_says_how_far_it_moved():
    t = np.arange(80)
    joints = np.zeros((80, 22, 3))
    joints[..., 1] = np.linspace(0.0, 1.0, 22)          # a standing column of joints
    joints[..., 2] += (0.05 * t)[:, None]                # travelling 1 m/s along +z
    out, moved = on_the_spot.stay(joints)
    pelvis = out[:, 0, [0, 2]] - out[0, 0, [0, 2]]
    assert np.linalg.norm(pelvis, axis=1).max() < 0.6
    assert np.allclose(out[0], joints[0])                 # it starts where it was
    assert moved[1] == 0.0 and np.allclose(out[-1, 0] - (joints[-1, 0] + moved), 0.0, atol=1e-9)
    still = joints[:, :, :] * [1, 1, 0]
    same, none = on_the_spot.stay(still)                  # already on the spot: untouched
    assert same is still and not none.any()


@pytest.mark.parametrize("text", ["a person marches in place", "a person jogs on the spot",
                                  "a person runs in place", "a person hops on the same spot",
                                  "a person hops without moving from the spot",
                                  "a person dances on the spot"])
def test_the_words_that_ask_for_the_spot(text):
    assert intent(text).in_place
    assert hold_of(text) is None          # "without moving from the spot" is no still stand


def test_a_travel_verb_on_the_spot_is_drawn_by_its_travel():
    it = intent("a person marches in place")
    assert on_the_spot.travelling("a person marches in place", it) == "a person marches"
    hop = intent("a person hops on the spot")
    assert on_the_spot.travelling("a person hops on the spot", hop) == "a person hops on the spot"


def test_skip_with_a_rope_is_the_skipping_rope(router):
    m = generate_motion(router, Request("skip with a rope", 1, 6.0, 0))
    cov = m.plan["segments"][0]["coverage"]
    assert cov["how"] == "primitive" and cov["primitive"] == "jumping_rope"
    _stays(m.people[0])
