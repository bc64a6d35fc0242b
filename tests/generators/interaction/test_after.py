"""What two people do after their interaction (`interaction/after.py`): "shake hands, then walk
away" composes the handshake over the plan's first part and then each who leaves turns from the
other and walks off, joined without a pop; who stays stands; kinds made of walking, and a push
whose stumble is its answer, are not cut."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.generators.base import Request, generate_motion
from interplay.generators.interaction.scenes.after import INTERACTION, departure
from interplay.generators.router import load_generator
from interplay.motion.checks.named import plausibility, run_check
from interplay.planner.plan import plan


@pytest.fixture(scope="module")
def router():
    return load_generator(use_spam=False)


def test_the_leaving_part_is_read_from_the_plan():
    part = departure(plan("they hug, then one walks away", 2, 7.0).segments, "hug")
    assert part is not None and any(part.leaves) and part.frame >= INTERACTION
    one = departure(plan("two people shake hands, then one walks away in a circle", 2, 8.0).segments, "handshake")
    assert one is not None and one.leaves == (False, True) and one.roles[0] == "a person stands still"
    assert departure(plan("two friends shake hands", 2, 6.0).segments, "handshake") is None
    assert departure(plan("one pushes the other, who stumbles backwards", 2, 6.0).segments, "push") is None


@pytest.mark.parametrize("prompt, kind, check", [
    ("two friends shake hands and then walk away from each other", "handshake", {"check": "handshake"}),
    ("they hug, then one walks away", "hug", {"check": "hug"}),
])
def test_they_do_it_then_part(router, prompt, kind, check):
    for seed in (0, 1):
        mo = generate_motion(router.compose, Request(prompt, 2, 7.0, seed))
        comp = mo.plan["composition"]
        assert comp["kind"] == kind and "after" in comp
        people = [np.asarray(p, np.float64) for p in mo.people]
        assert run_check(people, check).passed
        assert run_check(people, {"check": "separate"}).passed
        bad = [r.check for r in plausibility(people, contact=True) if not r.passed]
        assert bad == [], bad
        again = generate_motion(router.compose, Request(prompt, 2, 7.0, seed))
        assert np.allclose(np.asarray(again.people), np.asarray(mo.people))    # made again alike
        segs = mo.plan["segments"]
        assert segs[1]["start"] == comp["after"]["frame"]                     # the timeline says so
