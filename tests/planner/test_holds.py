"""Held poses keep their pose and its detail in the plan (issue 14, item 7): one "holds …" edit
per arm over the whole step, on the eval-prompts suite's dev prompts."""

import pytest

from interplay.planner.manner.holds import continues_hold, held
from interplay.planner.plan import embedded_plan
from interplay.planner.vocabulary import load_vocabulary
from tests.planner.suite import plan_of

CROSSED = "holds both arms crossed in front of the chest"
T_POSE = "holds the {} arm stretched out to the side at shoulder height"


def _only(p):
    (seg,) = p.segments
    return seg


@pytest.mark.parametrize("prompt_id,base,edits", [
    ("part_locomotion-09", "a person walks", {"left_arm": CROSSED, "right_arm": CROSSED}),
    ("part_locomotion-05", "a person walks forward",
     {"left_arm": T_POSE.format("left"), "right_arm": T_POSE.format("right")}),
    ("poses_held-01", "a person stands",                             # "hold a T-pose"
     {"left_arm": T_POSE.format("left"), "right_arm": T_POSE.format("right")}),
    ("poses_held-03", "a person stands", {"left_arm": "holds the left hand on the hip",
                                          "right_arm": "holds the right hand on the hip"}),
    ("poses_held-05", "a person stands", {"left_arm": "holds the left arm raised above the head",
                                          "right_arm": "holds the right arm raised above the head"}),
    ("poses_held-09", "a person stands",
     {"left_arm": "holds the left arm straight out in front at shoulder height",
      "right_arm": "holds the right arm straight out in front at shoulder height"}),
    ("poses_held-11", "a person stands", {"right_arm": "holds the right arm raised above the head"}),
])
def test_a_held_pose_is_one_edit_per_arm_over_the_whole_clip(prompt_id, base, edits):
    seg = _only(plan_of(prompt_id))
    assert seg.base == base
    assert seg.edits.named() == edits
    assert seg.start == 0 and seg.end == round(seg.seconds * 20)


def test_the_words_that_keep_a_pose_stay_in_the_prompt_not_a_step_of_their_own():
    seg = _only(plan_of("poses_held-05"))              # "raise both arms and keep them up"
    assert seg.prompt == "a person raises both arms and keeps them up"
    kneel = _only(plan_of("poses_held-07"))            # "kneel on one knee and stay there"
    assert kneel.base == "a person kneels on one knee and stays there"
    hips = plan_of("poses_held-03")                    # "put your hands on your hips and wait"
    assert any(r.startswith("holds: 'waits'") for r in hips.reasons)


def test_a_wait_after_travel_is_its_own_step_and_movements_stay_movements():
    p = embedded_plan("walk forward, then wait", 1, 6.0, load_vocabulary)
    assert len(p.segments) == 2
    seg = _only(embedded_plan("a person walks while raising the left arm", 1, None, None))
    assert seg.edits.named() == {"left_arm": "raises the left arm"}


def test_a_held_pose_through_travel_then_a_new_step():
    walk, sit = embedded_plan("walk with your arms crossed, then sit down", 1, 8.0,
                              load_vocabulary).segments
    assert walk.edits.left_arm == CROSSED and sit.edits.named() == {}


@pytest.mark.parametrize("phrase,parts", [
    ("with the hands on the hips", ("left_arm", "right_arm")),
    ("with the left hand on the hip", ("left_arm",)),
    ("with their hands behind their head", ("left_arm", "right_arm")),
    ("holding hands", ()),
    ("waves the right hand", ()),
])
def test_held_pose_table(phrase, parts):
    got = held(phrase)
    assert tuple(got) == parts and all(v.startswith("holds ") for v in got.values())


@pytest.mark.parametrize("clause,kept", [("keeps them up", True), ("waits", True),
                                         ("stays there", True), ("holds the pose for a while", True),
                                         ("walks away", False), ("keeps walking", False)])
def test_clauses_that_only_keep_a_pose(clause, kept):
    assert continues_hold(clause) is kept
