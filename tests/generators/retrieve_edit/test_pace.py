"""A slow walk from captures that walk faster (issue 14 item 4: speeds in their bands): the
captured slow and tired walks go 0.9–1.3 m/s, over the benchmark's slow band; a last segment
asked to go slowly is played slower, on the performer's bones, still stepping."""

import numpy as np
import pytest

from interplay.generators.base import Request
from interplay.generators.retrieve_edit.generator import RetrieveEditGenerator
from interplay.generators.retrieve_edit.pace import SLOW_MAX_M_S, slow_down, travel_speed
from interplay.generators.router import load_generator
from interplay.motion import skeleton as sk
from interplay.motion.checks.named import run_check


@pytest.fixture(scope="module")
def router():
    return load_generator(use_spam=False)


def _bones(j):
    return np.linalg.norm(j[:, 1:] - j[:, list(sk.PARENTS[1:])], axis=-1)


def test_a_captured_walk_is_played_slower_on_its_own_bones(router):
    walk = np.asarray(router.retrieval.generate(Request("a person walks forward", seconds=6, seed=0))
                      .people[0], np.float64)
    assert travel_speed(walk) > SLOW_MAX_M_S
    slow, rate = slow_down(walk)
    assert 0.5 <= rate < 1.0 and slow.shape == walk.shape
    assert run_check([slow], {"check": "speed_band", "band": "slow"}).passed
    assert np.abs(_bones(slow) - _bones(walk)[:1]).max() < 1e-6
    assert run_check([slow], {"check": "step_count", "count": 4, "tolerance": 3}).passed
    still, one = slow_down(walk[:1].repeat(40, 0))
    assert one == 1.0 and np.array_equal(still, walk[:1].repeat(40, 0))


@pytest.mark.parametrize("prompt", ["a tired walk, dragging the feet", "walk slowly"])
def test_slow_prompts_land_in_the_slow_band(router, prompt):
    gen = RetrieveEditGenerator(router.index)
    for seed in (0, 1):
        m = gen.generate(Request(prompt, 1, 6.0, seed))
        assert run_check([m.people[0]], {"check": "speed_band", "band": "slow"}).passed, seed
        assert "played slower" in m.plan["generator_reason"]
