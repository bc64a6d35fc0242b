"""Two people whose words name no kind (a board game, feeding a baby, an argument): each does
their own part of the words through the one-person generator, facing the other (the
`face_to_face` fallback), honestly covered by what the words found, never reported as a kind
the words did not ask for."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.generators.base import Request, generate_motion
from interplay.generators.interaction.kinds import fallback, read_script
from interplay.generators.router import load_generator
from interplay.motion.checks.named import plausibility, run_check
from interplay.text.encoder import get_encoder

UNNAMED = ("two friends play chess", "a mother feeds her baby", "two people argue loudly")


@pytest.fixture(scope="module")
def router():
    return load_generator(use_spam=False)


def test_the_fallback_reads_only_what_no_kind_or_other_generator_takes():
    enc = get_encoder()
    for prompt in UNNAMED:
        assert read_script(prompt, None, enc) is None or read_script(prompt, None, enc).kind == "face_to_face"
    assert fallback("two people dance a slow waltz", enc) is None        # a dance: retrieval's
    assert fallback("two people do push-ups", enc) is None
    guess = fallback("two people argue loudly", enc)
    assert guess is not None and guess.kind == "face_to_face" and guess.guessed is not None


@pytest.mark.parametrize("prompt", UNNAMED)
def test_each_does_their_part_facing_the_other(router, prompt):
    gen = router.compose
    for seed in (0, 1):
        mo = generate_motion(gen, Request(prompt, 2, 5.0, seed))
        assert mo.plan["generator"] == "compose" and mo.plan["composition"]["kind"] == "face_to_face"
        people = [np.asarray(p, np.float64) for p in mo.people]
        assert run_check(people, {"check": "face_each_other"}).passed
        assert run_check(people, {"check": "close_together", "max_m": 1.6}).passed
        assert all(r.passed for r in plausibility(people) if r.check == "no_interpenetration")
