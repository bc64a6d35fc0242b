"""Everyday activities (catalogue/activities.toml, built by generators/primitives/activity.py
from part instructions on captured base postures): every entry builds a plausible motion that
passes its own checks, strokes are counted exactly, and the planner's segments reach them from
words no word list names — while captured verbs, postures and what nothing covers keep their
own route."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.catalogue.load import catalogue
from interplay.catalogue.schema import specs
from interplay.generators.plan import GenerationPlan
from interplay.generators.primitives.body import bone_error
from interplay.generators.primitives.postures import posture
from interplay.generators.primitives.registry import PRIMITIVES, activities, build
from interplay.generators.primitives.timing import phase
from interplay.generators.retrieve_edit.primitive_steps import choose
from interplay.motion.checks import measures as m
from interplay.motion.checks.named import run_check
from interplay.planner.plan import embedded_plan
from interplay.text.encoder import get_encoder

MAX_STEP_M = 0.25      # a joint's largest move in one frame (5 m/s: a fast hand, never a flip)


def _entries():
    return [a for a in catalogue().action if a.made_by.primitive == "activity"]


def test_every_activity_is_found_and_described():
    names = activities()
    assert len(names) == len(_entries()) >= 80
    for a in _entries():
        assert len(a.descriptions) >= 2 and a.examples, a.name


@pytest.mark.parametrize("name", [a.name for a in catalogue().action if a.made_by.primitive == "activity"])
def test_activity_builds_and_passes_its_own_checks(name):
    prim = PRIMITIVES[name]
    joints = build(prim, {"seconds": 6.0})
    assert joints.shape == (120, 22, 3) and np.isfinite(joints).all()
    assert bone_error(joints, posture(prim.posture, 6.0)) < 0.005   # the walk's own spread: 3 mm
    step = np.linalg.norm(np.diff(joints, axis=0), axis=-1).max()
    assert step < MAX_STEP_M, (name, round(float(step), 3))
    assert joints[..., 1].min() > -0.12            # a knee or toe may graze the floor, no more
    entry = catalogue().get(name)
    assert entry is not None
    for spec in specs(entry):
        assert run_check([joints], spec).passed, (name, spec)


def test_strokes_are_counted_exactly():
    for count in (3, 5):
        joints = build(PRIMITIVES["hammering"], {"count": count, "seconds": 5.0})
        cycle, _ = phase(len(joints), count)
        up = m.hand_point(joints, "right")[:, 1]
        tops = [i for i in range(1, len(up) - 1)
                if cycle[i] >= 0 and up[i] > up[i - 1] and up[i] >= up[i + 1]]
        assert len(tops) == count


def _routes(prompt: str) -> list[tuple[str, str | None]]:
    plan = GenerationPlan.from_plan(embedded_plan(prompt, 1, None, None), seed=0,
                                    generator="retrieve_edit")
    choose(plan, get_encoder())
    return [(s.coverage.how, s.coverage.entry) for s in plan.segments if s.coverage is not None]


def test_words_no_list_names_reach_an_activity():
    assert _routes("hammer a nail into the wall") == [("primitive", "hammering")]
    assert _routes("floss your teeth") == [("primitive", "brushing_teeth")]
    # a captured verb whose whole words name an activity far better than the verb alone
    assert _routes("push a shopping cart down the aisle") == [("primitive", "pushing_cart")]


def test_captured_verbs_postures_and_the_uncovered_keep_their_route():
    assert _routes("jump three times")[0][0] == "capture"
    assert _routes("sit down on a chair and knit a scarf")[0] == ("capture", "sit")
    assert _routes("a person levitates and spins in the air")[0][0] == "nearest"
