"""Both people doing one person's action ("two people jump together", issue 15 item 1), on the
real processed captures through the router, two seeds each: composed as "together", each
person does what the words ask (the benchmark's own checks on each), both start together,
side by side on the same bones and never inside each other; a couple's dance is still left
to retrieve-then-edit."""

import numpy as np
import pytest

from interplay.generators.base import Request, generate_motion
from interplay.generators.interaction.scenes.gestures import solo_text
from interplay.generators.router import Router, load_generator
from interplay.motion import skeleton as sk
from interplay.motion.checks.named import plausibility, run_check

SEEDS = (0, 1)
TOGETHER = [
    ("two people jump together", 5, {"check": "jump_count", "at_least": 1}),
    ("both of them squat twice at the same time", 6, {"check": "squat_count", "count": 2}),
    ("two people kick with the right leg at the same time", 5, {"check": "kick", "leg": "right", "at_least": 1}),
]


@pytest.fixture(scope="module")
def router():
    return Router(load_generator(use_spam=False).index)      # the default router, no models


@pytest.mark.parametrize("prompt,seconds,check", TOGETHER, ids=[t[0] for t in TOGETHER])
def test_both_do_it_side_by_side(router, prompt, seconds, check):
    for seed in SEEDS:
        m = generate_motion(router, Request(prompt, 2, float(seconds), seed))
        assert m.plan["generator"] == "compose" and m.plan["composition"]["kind"] == "together"
        a, b = (np.asarray(p, np.float64) for p in m.people)
        for person in (a, b):
            r = run_check([person], check)
            assert r.passed, (seed, check, r.value)
        failed = [r.check for r in plausibility([a, b], start="standing") if not r.passed]
        assert failed == [], (seed, failed)
        gap = np.linalg.norm((b[:, sk.PELVIS] - a[:, sk.PELVIS])[:, [0, 2]], axis=1)
        assert gap.min() >= 0.8 and gap.max() <= 2.0, (seed, gap.min(), gap.max())
        bones = [np.linalg.norm(p[:, 1:] - p[:, sk.PARENTS[1:]], axis=-1) for p in (a, b)]
        assert np.abs(bones[0] - bones[1]).max() < 1e-4


def test_each_persons_words():
    assert solo_text("two people jump together") == "jump"
    assert solo_text("both of them squat twice at the same time") == "squat twice"
    assert solo_text("they raise both arms together") == "raise both arms"


def test_a_couples_dance_is_not_composed_together(router):
    plan = router.plan(Request("two people dance together", 2, 4.0, 0))
    assert plan.generator == "retrieve_edit" and "not an interaction" in plan.generator_reason
