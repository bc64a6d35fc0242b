"""Views of real captures (mirrored, played backwards) and what retrieval reads off a segment's
words: the views do what their names say by the benchmark's own checks, their texts follow,
plans naming them survive JSON, and the intent rules read the planner's real segments."""

import numpy as np
import pytest

from interplay.generators.plan import GenerationPlan
from interplay.generators.retrieval.intent import Intent, intent
from interplay.generators.retrieval.views import View, mirror_text
from interplay.generators.router import load_generator
from interplay.motion.checks.named import run_check
from interplay.planner.plan import plan as make_plan
from interplay.trajectory.apply import skating

KICK = "hdm05:HDM_bd_kickLFront1Reps_001_120"      # a captured left front kick
WALK = "8action:train/walking_1"                   # a captured forward walk


@pytest.fixture(scope="module")
def gen():
    return load_generator(use_spam=False)


def test_view_names_parse_and_refuse_what_they_are_not():
    assert View.parse(KICK) == View(KICK)
    v = View.parse(f"{WALK}#mirrored#reversed")
    assert v.mirrored and v.reversed and View.parse(v.ref) == v
    assert v.span(10, 30, 100) == (70, 90) and View(WALK, mirrored=True).span(10, 30, 100) == (10, 30)
    with pytest.raises(ValueError, match="unknown clip view"):
        View.parse(f"{WALK}#sideways")
    assert mirror_text("kicks with the Left foot, then the right") == "kicks with the Right foot, then the left"


def test_a_mirrored_left_kick_is_a_right_kick_and_says_so(gen):
    idx = gen.index
    left, right = idx.clip(KICK), idx.clip(f"{KICK}#mirrored")
    assert "left" in left.prompt and "right" in right.prompt and right.id == f"{KICK}#mirrored"
    assert run_check([left.people[0]], {"check": "kick", "leg": "left", "count": 1}).passed
    assert run_check([right.people[0]], {"check": "kick", "leg": "right", "count": 1}).passed
    # Same frames, reflected: bones keep their lengths, heights are untouched.
    np.testing.assert_allclose(np.sort(right.people[0][..., 1], axis=1),
                               np.sort(left.people[0][..., 1], axis=1), atol=1e-6)
    assert idx.measured(f"{KICK}#mirrored").events("kick", "right")


def test_a_reversed_walk_walks_backwards_facing_forward(gen):
    walk, back = gen.index.clip(WALK).people[0], gen.index.clip(f"{WALK}#reversed").people[0]
    assert run_check([back], {"check": "travel_direction", "direction": "backward", "min_m": 2.0}).passed
    assert not run_check([back], {"check": "travel_direction", "direction": "forward"}).passed
    # The feet stay planted as in the capture: the same planted frames, the same (tiny) skating.
    assert skating(back) == pytest.approx(skating(walk), rel=1e-6, abs=1e-9) and skating(walk) < 0.1


def test_a_plan_naming_views_streams_the_same_after_json(gen):
    from interplay.generators.base import Request
    for seed in range(8):      # a draw with a mirrored capture in it (HDM05's kicks are left ones)
        req = Request("kick twice with your right leg, then sit down", 1, 10.0, seed=seed)
        plan = gen.plan(req)
        clips = [p.clip for s in plan.segments for p in s.retrieval.tracks[0]]
        if any("#mirrored" in c for c in clips):
            break
    assert any("#mirrored" in c for c in clips)
    assert {s.clip for s in plan.sources} == set(clips)
    assert all("left" not in s.label for s in plan.sources if "#mirrored" in s.clip)
    again = GenerationPlan.model_validate(plan.to_json())
    a = np.concatenate([c[0] for _, c in gen.stream(req, plan)])
    b = np.concatenate([c[0] for _, c in gen.stream(req, again)])
    np.testing.assert_array_equal(a, b)
    assert a.shape == (200, 22, 3)


@pytest.mark.parametrize("prompt,seconds,want", [
    ("kick twice with your right leg", 6, Intent(side="right", action="kick", count=2)),
    ("jump three times", 6, Intent(action="jump", count=3)),
    ("take three steps forward", 5, Intent(action="step", count=3)),
    ("squat twice", 6, Intent(action="squat", count=2)),
    ("run backwards", 5, Intent(travel="backward", speed="run")),
    ("step sideways to the left", 5, Intent(travel="left")),
    ("get up from lying on the floor", 6, Intent(start="lying", end="standing", rises=True)),
    ("stand up from sitting on the floor", 6, Intent(start="sitting", end="standing", rises=True)),
    ("sit down on the ground", 6, Intent(end="sitting")),
    ("walk happily with a spring in your step", 6, Intent()),
    ("walk a few steps and wave", 6, Intent()),
])
def test_intent_of_the_planners_segments(prompt, seconds, want):
    for seg in make_plan(prompt, 1, seconds).segments:
        got = intent(seg.prompt, seg.repeat, seg.travel)
        assert got == want, (seg.prompt, got)
