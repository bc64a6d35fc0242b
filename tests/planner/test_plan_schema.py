"""The Plan schema: what a valid plan is, readable errors for what is not, and the JSON keys the
API streamed before (index/prompt/start/end/persons per segment)."""

import json

import pytest

from interplay.planner.schema import Plan, TrajectorySpec, validate_plan


def _plan(**over) -> dict:
    seg = {"index": 0, "prompt": "a person walks", "base": "a person walks", "seconds": 2.0,
           "start": 0, "end": 40, "persons": [0]}
    seg2 = {"index": 1, "prompt": "a person jumps", "base": "a person jumps",
            "edits": {"left_arm": "raises the left arm"}, "seconds": 1.0, "start": 40, "end": 60,
            "persons": [0], "repeat": 2}
    data = {"prompt": "walk then jump", "rewritten": "a person walks, then a person jumps",
            "persons": 1, "seconds": 3.0, "segments": [seg, seg2], "planner": "embedded"}
    data.update(over)
    return data


def test_a_valid_plan_round_trips_through_json_with_the_streamed_keys():
    plan = validate_plan(_plan())
    data = json.loads(json.dumps(plan.to_json()))
    assert Plan.model_validate(data) == plan
    for seg in data["segments"]:
        assert {"index", "prompt", "start", "end", "persons"} <= set(seg)
    assert data["segments"][1]["edits"] == {"left_arm": "raises the left arm", "right_arm": None,
                                             "left_leg": None, "right_leg": None}
    assert data["fallback_reason"] is None and data["segments"][0]["repeat"] == 1


@pytest.mark.parametrize("change,message", [
    (lambda d: d["segments"][1].update(start=41, end=61), "starts at frame 41, expected 40"),
    (lambda d: d.update(seconds=4.0), "segments end at frame 60, but 4 s is 80 frames"),
    (lambda d: d["segments"][0].update(persons=[1]), "person 1 does not exist"),
    (lambda d: d["segments"][1].update(index=5), "index is 5, expected 1"),
    (lambda d: d["segments"][0].update(end=0, seconds=0.5), "segments.0"),
    (lambda d: d["segments"][0].update(seconds=1.0), "must equal (end - start) / 20"),
    (lambda d: d["segments"][0].update(roles={"0": "walks", "1": "stands"}), "roles are for two"),
    (lambda d: d["segments"][0].update(trajectory={"shape": "blob"}), "segments.0.trajectory.shape"),
    (lambda d: d["segments"][0].update(edits={"tail": "wags"}), "segments.0.edits.tail"),
    (lambda d: d.update(planner="gpt"), "planner"),
    (lambda d: d.update(segments=[]), "segments"),
])
def test_invalid_plans_raise_value_errors_that_say_where(change, message):
    data = _plan()
    change(data)
    with pytest.raises(ValueError) as err:
        validate_plan(data)
    assert message in str(err.value) and str(err.value).startswith("invalid plan:")


def test_not_an_object_and_blank_edits():
    with pytest.raises(ValueError, match="must be a JSON object"):
        validate_plan([1, 2])
    data = _plan()
    data["segments"][1]["edits"] = {"left_arm": "none", "right_arm": "  "}
    assert validate_plan(data).segments[1].edits.named() == {}


def test_trajectory_spec_checks_its_numbers_and_polyline_points():
    TrajectorySpec(shape="polyline", waypoints=[(0, 0), (1, 2)])
    TrajectorySpec(shape="line", turn_at={"clock": 3})
    with pytest.raises(ValueError, match="at least two waypoints"):
        TrajectorySpec(shape="polyline", waypoints=[(0, 0)])
    with pytest.raises(ValueError):
        TrajectorySpec(shape="circle", size_m=-1)
    with pytest.raises(ValueError):
        TrajectorySpec(shape="line", turn_at={"clock": 13})
