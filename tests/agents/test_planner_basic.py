import pytest

from interplay.agents.planner_basic import allocate_frames, basic_plan, split_prompt


def test_splits_on_connectives_and_sentence_ends_in_order():
    assert split_prompt("a person walks forward, then jumps. Finally they sit down") == [
        "a person walks forward", "jumps", "they sit down"]
    assert split_prompt("walk; run and then jump after that wave") == ["walk", "run", "jump", "wave"]
    assert split_prompt("A person walks. A person jumps! Then he sits.") == [
        "A person walks", "A person jumps", "he sits"]
    # No split inside numbers or words containing "then" ("Athens").
    assert split_prompt("a person walks 1.5 m towards Athens") == ["a person walks 1.5 m towards Athens"]


@pytest.mark.parametrize("seconds", [1.0, 2.5, 6.0, 7.3, 20.0])
def test_segments_tile_the_requested_frames(seconds):
    plan = basic_plan("a person walks forward then turns around then runs back; finally jumps", 1, seconds)
    segs = plan["segments"]
    assert plan["planner"] == "basic" and plan["persons"] == 1
    assert [s["index"] for s in segs] == list(range(len(segs)))
    assert segs[0]["start"] == 0 and segs[-1]["end"] == round(seconds * 20)
    for a, b in zip(segs, segs[1:]):
        assert a["end"] == b["start"]
    assert all(s["end"] - s["start"] >= 20 for s in segs)   # ≥ 1 s each
    assert len(segs) == min(4, int(round(seconds * 20)) // 20)


def test_durations_follow_segment_length_and_subjects_are_filled():
    plan = basic_plan("a person walks slowly forward across the whole room then jumps", 2, 10)
    long, short = plan["segments"]
    assert long["end"] - long["start"] > short["end"] - short["start"]
    assert short["prompt"] == "two people jumps"
    assert long["persons"] == short["persons"] == [0, 1]
    assert plan["rewritten"].startswith("a person walks slowly")


def test_allocate_frames_sums_exactly():
    for total in (20, 57, 120, 400):
        frames = allocate_frames([1, 3, 2], total)
        assert sum(frames) == total and min(frames) >= min(20, total // 3)


@pytest.mark.parametrize("args", [("", 1, 6), ("   ", 1, 6), ("x" * 501, 1, 6),
                                  ("walk", 3, 6), ("walk", 1, 0), ("walk", 1, float("nan"))])
def test_bad_requests_raise_value_error(args):
    with pytest.raises(ValueError):
        basic_plan(*args)
