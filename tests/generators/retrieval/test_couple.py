"""A couple's dance from the captured salsa pairs (`generators/retrieval/couple.py`, issue 15
item 4): the spin check (`partner_spin`) on real captures and on violations of them, and the
retrieval generator on real prompts asking for a dance and a spin, judged by the benchmark's
checks over three seeds."""

import numpy as np
import pytest

from interplay.generators.base import Request
from interplay.generators.retrieval.couple import asks_spin, spin_starts
from interplay.generators.router import load_generator
from interplay.motion.checks.named import run_check

SPIN = {"check": "partner_spin"}
CLOSE = {"check": "close_together"}


@pytest.fixture(scope="module")
def gen():
    return load_generator(use_spam=False)


@pytest.fixture(scope="module")
def salsa(gen):
    return [c for c in gen.index.clips if c.id.startswith("salsa:")]


def test_every_captured_salsa_pair_has_a_follower_spin_and_violations_fail(salsa):
    assert len(salsa) >= 10
    for c in salsa:
        a, b = (np.asarray(p, np.float64) for p in c.people)
        assert run_check([a, b], SPIN).passed, c.id
        # both turning alike (a person with a shifted copy of themselves) is no partner spin
        for me in (a, b):
            twin = me + np.array([0.5, 0.0, 0.0])
            assert not run_check([me, twin], SPIN).passed, c.id
        # the same spin 2 m away from the partner is no couple's spin
        assert not run_check([a, b + np.array([2.0, 0.0, 0.0])], SPIN).passed, c.id


def test_the_index_finds_spins_only_in_two_person_captures_that_have_them(gen, salsa):
    found = spin_starts(gen.index)
    ids = {gen.index.clips[i].id for i in found}
    assert {c.id for c in salsa} <= ids
    assert all(len(gen.index.clips[i].people) == 2 for i in found)


@pytest.mark.parametrize("prompt", ["the leader spins the follower",
                                    "they dance salsa and she turns under his arm",
                                    "a couple dances salsa and the man twirls the woman"])
def test_a_couples_spin_is_drawn_where_a_captured_follower_spins(gen, prompt):
    for seed in range(3):
        mo = gen.retrieval.generate(Request(prompt, 2, 6.0, seed))
        assert all(s["clip"].startswith("salsa:") for s in mo.plan["sources"]), mo.plan["sources"]
        for spec in (SPIN, CLOSE):
            r = run_check(mo.people, spec)
            assert r.passed, (prompt, seed, spec, r.value)


def test_a_couples_dance_stays_close_together(gen):
    for seed in range(3):
        mo = gen.retrieval.generate(Request("two people dance salsa together", 2, 6.0, seed))
        r = run_check(mo.people, CLOSE)
        assert r.passed, (seed, r.value)


def test_spin_words():
    assert asks_spin("the leader spins the follower")
    assert asks_spin("she turns under his arm") and asks_spin("he twirls her")
    assert not asks_spin("two people spin around") and not asks_spin("a person spins twice")
