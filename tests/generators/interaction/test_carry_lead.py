"""A piggyback ride and leading by the hand (issue 24.4): read from everyday phrasings that are
not the catalogue entries' own descriptions, planned and made through the studio's pipeline
(`orchestrate` on the default router: composition for two people, the penetration pass, the
reviews), on three seeds: the kind's catalogue checks pass on the motion, the plausibility
checks pass, and the pair stays within the penetration bound of the contact its words ask."""

import numpy as np
import pytest

from interplay.generators.base import Request
from interplay.generators.interaction.kinds import kind_checks, read_script
from interplay.generators.router import Router, load_generator
from interplay.motion import skeleton as sk
from interplay.motion.checks.contact import riding
from interplay.motion.checks.named import plausibility, run_check
from interplay.motion.pair.resolve import pair_bounds
from interplay.pipeline.orchestrator import orchestrate
from interplay.review.checks import contact_mode

SEEDS = (0, 1, 2)
ASKED = [
    # prompt, seconds, kind
    ("a father carries his little son on his back", 6, "carry"),
    ("a big sister gives her brother a piggyback ride around the garden", 7, "carry"),
    ("a mother leads her little boy by the hand across the park", 7, "lead"),
]


@pytest.fixture(scope="module")
def router():
    return Router(load_generator(use_spam=False).index)


@pytest.fixture(scope="module")
def made(router):
    out = {}
    for prompt, seconds, _ in ASKED:
        runs = []
        for s in SEEDS:
            events: list[dict] = []
            o = orchestrate(router, Request(prompt, 2, float(seconds), s), events.append, lambda *_: None)
            runs.append((o, events))
        out[prompt] = runs
    return out


@pytest.mark.parametrize("prompt,seconds,kind", ASKED, ids=[a[0] for a in ASKED])
def test_the_kind_is_made_and_passes_its_checks_within_the_bound(made, prompt, seconds, kind):
    for seed, (out, _) in zip(SEEDS, made[prompt]):
        comp = out.plan.composition or {}
        assert out.plan.generator == "compose" and comp.get("kind") == kind, out.plan.generator_reason
        people = [np.asarray(p, np.float64) for p in out.people]
        assert all(p.shape == (round(seconds * 20), 22, 3) for p in people)
        for spec in kind_checks(kind):
            r = run_check(people, spec)
            assert r.passed, (seed, spec, r.value)
        bad = [(r.check, r.person, r.value) for r in plausibility(people, contact=True) if not r.passed]
        assert not bad, (seed, bad)
        bound = pair_bounds(people[0], people[1], contact_mode(prompt))
        assert contact_mode(prompt) == "hands" and bound["ok"], (seed, bound)
        assert bound["depth_cm"] <= 2.5, (seed, bound)
        assert out.review["interaction"]["passed"] == out.review["interaction"]["of"]
        assert all(s.coverage.how == "composed" for s in out.plan.segments)


def test_the_rider_climbs_on_from_standing_behind_and_rides_on_the_back(made):
    for out, _ in made["a father carries his little son on his back"]:
        actor = out.plan.composition["script"]["actor"]
        carrier, rider = (np.asarray(out.people[i], np.float64) for i in (actor, 1 - actor))
        up = riding(rider, carrier)
        assert not up[:5].any() and up[-20:].all()          # on the floor first, then up to the end
        feet = rider[up][:, list(sk.FOOT_JOINTS), 1].min(axis=1)
        assert float(np.median(feet)) >= 0.4                  # shins hang, feet well off the floor
        # on the back: the rider's pelvis behind the carrier's (the carrier's own forward)
        fwd = np.cross(carrier[:, sk.LEFT_HIP] - carrier[:, sk.RIGHT_HIP], [0.0, 1.0, 0.0])
        fwd /= np.linalg.norm(fwd, axis=1, keepdims=True)
        behind = ((rider[:, sk.PELVIS] - carrier[:, sk.PELVIS]) * fwd).sum(1)[up]
        assert float(np.median(behind)) < -0.1
        # the rider's hands on the carrier's chest, the carrier's round the rider's thighs
        assert run_check([carrier, rider], {"check": "touches", "target": "trunk", "who": "second",
                                            "min_s": 2.0}).passed
        assert run_check([carrier, rider], {"check": "touches", "target": "leg", "who": "first",
                                            "min_s": 2.0}).passed


def test_a_carrier_who_walks_travels_with_the_rider_on(made):
    for out, _ in made["a big sister gives her brother a piggyback ride around the garden"]:
        assert out.plan.composition["timing"]["contact"]["walks"]
        actor = out.plan.composition["script"]["actor"]
        carrier = np.asarray(out.people[actor], np.float64)
        assert float(np.linalg.norm((carrier[-1, sk.PELVIS] - carrier[0, sk.PELVIS])[[0, 2]])) >= 1.5


def test_who_carries_and_who_leads_is_read_from_the_prompt(router):
    enc = router.index.encoder
    assert read_script("a kid rides on his dad's back", None, enc).actor == 1
    assert read_script("a child is carried on his father's back", None, enc).actor == 1
    assert read_script("a dad lets his daughter ride on his back", None, enc).actor == 0
    s = read_script("one person gives the other a piggyback ride", None, enc)
    assert s.kind == "carry" and s.actor == 0                # 'piggyback' before hand_over's 'give* the other'
    s = read_script("a mother walks her toddler along, holding his hand", None, enc)
    assert s.kind == "lead" and any("text encoder" in r for r in s.reasons)
    # carrying a thing is not a ride, and walking side by side holding hands stays side by side
    bag = read_script("a person carries a heavy bag", None, enc)
    assert bag is None or bag.kind == "face_to_face"         # each their own part, not a ride
    assert read_script("they walk side by side holding hands", None, enc).kind == "side_by_side"
