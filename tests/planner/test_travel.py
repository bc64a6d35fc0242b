"""Backwards and sideways are a direction of travel on the segment (issue 14, item 7), never a
reversed path the trajectory stage would turn the person round to follow — on the
eval-prompts suite's dev prompts, and the same for an LLM's plan."""

import pytest

from interplay.planner.llm import LLMAnswer, to_plan
from interplay.planner.manner.travel import direction, untangle
from interplay.planner.plan import embedded_plan
from interplay.planner.schema import TrajectorySpec
from interplay.planner.verbs import VERBS
from interplay.planner.vocabulary import load_vocabulary
from tests.planner.suite import plan_of


def _only(p):
    (seg,) = p.segments
    return seg


@pytest.mark.parametrize("prompt_id,travel", [
    ("directions_speeds-01", "backward"),     # walk backwards
    ("directions_speeds-03", "left"),         # step sideways to the left
    ("directions_speeds-09", "backward"),     # run backwards
    ("part_locomotion-07", "backward"),       # walk backwards while waving
    ("directions_speeds-07", "forward"),      # jog forward
])
def test_direction_of_travel_without_a_reversed_path(prompt_id, travel):
    seg = _only(plan_of(prompt_id))
    assert seg.travel == travel
    assert seg.trajectory is None
    assert seg.model_dump(mode="json")["travel"] == travel


def test_walking_backwards_while_waving_keeps_the_wave():
    seg = _only(plan_of("part_locomotion-07"))
    assert seg.base == "a person walks backwards" and seg.edits.right_arm.startswith("waves")


def test_a_distance_backwards_sets_the_time_not_a_path():
    seg = _only(embedded_plan("a person walks 4 metres backwards", 1, None, load_vocabulary))
    assert seg.travel == "backward" and seg.trajectory is None
    assert seg.seconds == pytest.approx(4 / (1.3 * 0.7), abs=0.05)   # slower than forwards
    assert any(r.startswith("travel: ") for r in embedded_plan(
        "a person walks 4 metres backwards", 1, None, None).reasons)


def test_shapes_and_turns_stay_paths():
    circle = _only(embedded_plan("a person walks backwards in a circle", 1, None, None))
    assert circle.travel == "backward" and circle.trajectory.shape == "circle"
    left = _only(embedded_plan("a person walks to the left", 1, None, None))
    assert left.travel is None and left.trajectory.direction == "left"   # turn, then walk
    assert _only(embedded_plan("a person walks in a circle", 1, None, None)).travel is None


@pytest.mark.parametrize("text,verb,way", [
    ("stumbles backwards", "stumble", "backward"), ("hops to the right", "hop", "right"),
    ("leans back", "lean", None), ("walks back to the start", "walk", None),
    ("lies on the back", "lie", None), ("shuffles sideways", "shuffle", "left"),
])
def test_direction_words(text, verb, way):
    assert direction(text, VERBS[verb]) == way


def test_untangle_drops_only_a_straight_path_in_the_travel_direction():
    back = TrajectorySpec(shape="polyline", direction="backward", waypoints=[(0, 0), (0, -3)])
    assert untangle(back, "backward") == (None, None)
    line = TrajectorySpec(shape="line", direction="backward", distance_m=3.0)
    assert untangle(line, "backward") == (None, 3.0)
    circle = TrajectorySpec(shape="circle")
    assert untangle(circle, "backward") == (circle, None)


def test_an_llm_backwards_line_becomes_travel():
    answer = LLMAnswer.model_validate({"rewritten": "a person walks backwards", "segments": [
        {"prompt": "a person walks backwards", "base": "a person walks backwards",
         "trajectory": {"shape": "line", "direction": "backward", "distance_m": 3.0},
         "seconds": 3.0}]})
    seg = _only(to_plan(answer, "walk backwards", 1, 4.0))
    assert seg.travel == "backward" and seg.trajectory is None
    pair = LLMAnswer.model_validate({"rewritten": "x", "segments": [
        {"prompt": "one pushes", "base": "a person pushes", "seconds": 1.0, "persons": [0],
         "timing": {"lead": 0, "response": "contact", "phase": "lead"}},
        {"prompt": "the other stumbles", "base": "a person stumbles backwards", "seconds": 1.5,
         "persons": [1], "travel": "backward",
         "timing": {"lead": 0, "response": "contact", "phase": "response"}}]})
    p = to_plan(pair, "one pushes the other, who stumbles backwards", 2, 5.0)
    assert [s.timing.phase for s in p.segments] == ["lead", "response"]
    assert p.segments[1].travel == "backward"
