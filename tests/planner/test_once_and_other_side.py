"""Counts of one and sides by ellipsis that the rewrite to the data's words used to drop (issue
14, planner): "a tuck jump", "do one squat", "throw a punch", "a karate front kick" are one of
their action, as the retrieval's intent reads it; "punch with the left fist, then the right"
is two punches, one per side; "the right" alone after an action without a side stays a turn."""

from __future__ import annotations

import pytest

from interplay.generators.retrieval.intent import intent
from interplay.planner.plan import plan


@pytest.mark.parametrize("prompt,action", [
    ("do a tuck jump", "jump"), ("do one squat", "squat"), ("throw a punch", "punch"),
    ("do a karate front kick with the right leg", "kick"), ("the man does a single hop", None),
])
def test_a_count_of_one_is_kept(prompt, action):
    seg = plan(prompt, 1, 6).segments[0]
    assert " once" in seg.prompt, seg.prompt
    if action is not None:
        got = intent(seg.prompt, seg.repeat)
        assert (got.action, got.count) == (action, 1)


@pytest.mark.parametrize("prompt", ["do jumping jacks", "take a walk", "jump", "squat twice",
                                    "do two squats", "do a full turn"])
def test_no_count_of_one_where_none_is_said(prompt):
    assert all(" once" not in s.prompt for s in plan(prompt, 1, 6).segments)


@pytest.mark.parametrize("prompt,second", [
    ("punch with the left fist, then the right", "punches with the right fist"),
    ("kick with the right leg, then the left", "kicks with the left leg"),
    ("wave with the left hand then the right one", "waves with the right hand"),
])
def test_the_other_side_repeats_the_action(prompt, second):
    segs = plan(prompt, 1, 6).segments
    assert len(segs) == 2 and segs[1].prompt.endswith(second), [s.prompt for s in segs]
    assert intent(segs[1].prompt).side == ("left" if "left" in second else "right")


def test_a_side_after_a_sideless_action_is_still_a_turn():
    segs = plan("walk forward then turn right", 1, 6).segments
    assert segs[1].prompt == "a person turns right"
