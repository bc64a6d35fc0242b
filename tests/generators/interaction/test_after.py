"""What two people do after their interaction (`interaction/after.py`): "shake hands, then walk
away" composes the handshake over the plan's first part and then each who leaves turns from the
other and walks off, joined without a pop; who stays stands; kinds made of walking, and a push
whose stumble is its answer, are not cut."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.generators.base import Request, generate_motion
from interplay.generators.interaction.scenes.after import INTERACTION, JOIN, departure
from interplay.generators.router import load_generator
from interplay.motion import skeleton as sk
from interplay.motion.checks.named import plausibility, run_check
from interplay.motion.metrics import foot_skating
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


@pytest.mark.parametrize("prompt", [
    "two people shake hands, then one walks away in a circle",
    "they hug, then walk away from each other",
])
def test_the_turn_away_steps_instead_of_sliding(router, prompt):
    """A leaver turns round in the interaction's last JOIN frames: each foot stays planted,
    then steps (lifted) to where the walk starts it; before scenes/stepping.py both feet swung
    round the pelvis at up to 1.7 m/s on the ground (the reviewer's foot-skating window)."""
    for seed in (0, 1):
        mo = generate_motion(router.compose, Request(prompt, 2, 6.0, seed))
        frame = mo.plan["composition"]["after"]["frame"]
        for person, leaves in zip(mo.people, mo.plan["composition"]["after"]["leaves"]):
            if not leaves:
                continue
            joints = np.asarray(person, np.float64)
            speed, plant = foot_skating(joints)                 # frames 1 … T-2
            turn = slice(frame - JOIN - 1, frame + 1)
            slid = (plant & (speed > 0.5))[turn].any(axis=1)
            assert not slid.any(), (seed, np.nonzero(slid)[0] + frame - JOIN)
            lifted = joints[frame - JOIN:frame][:, [sk.LEFT_ANKLE, sk.RIGHT_ANKLE], 1]
            assert (lifted.max(axis=0) - lifted.min(axis=0) > 0.03).all()    # both feet step
