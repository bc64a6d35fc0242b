"""The reviewer on real captures of the processed set: captions confirm or contradict a plan,
commonsense checks catch broken motion, and the correction loop keeps only improvements."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.motion.clip import default_clips
from interplay.planner.plan import plan
from interplay.planner.schema import Segment
from interplay.review.checks import commonsense
from interplay.review.reviewer import CannotApply, correct, review


@pytest.fixture(scope="module")
def clips():
    return default_clips()


def _clip(clips, label: str, people: int = 1):
    return next(c for c in clips if c.label == label and len(c.people) == people)


def _segment(prompt: str, frames: int, persons: int = 1) -> Segment:
    """The planner's segment for a one-step prompt (the one with part edits if it split it),
    laid over `frames` frames."""
    segs = plan(prompt, persons, frames / 20).segments
    seg = next((s for s in segs if s.edits.named()), segs[0])
    return seg.model_copy(update={"start": 0, "end": frames, "seconds": frames / 20})


def test_walk_confirms_walking_and_asks_for_the_missing_arm_edit(clips):
    walk = _clip(clips, "walk").people[0][:80]
    seg = _segment("a person walks while raising the left arm above the head", 80)
    assert seg.edits.left_arm
    rv = review(seg, [walk])
    assert rv.score_kind == "caption_agreement" and -1 <= rv.score <= 1
    assert "walks" in rv.captions["body"] and rv.body_confirmed is True
    assert rv.confirmed == {"left_arm": False}
    assert rv.instructions[0] == {"kind": "edit_part", "part": "left_arm",
                                  "prompt": seg.edits.left_arm,
                                  "reason": rv.instructions[0]["reason"]}
    assert rv.verdict == "correct"
    ev = rv.event()
    assert ev["type"] == "review" and set(ev["captions"]) == {
        "body", "left_upper", "right_upper", "left_lower", "right_lower"}


def test_arm_raised_above_the_head_is_confirmed(clips):
    grab = _clip(clips, "grabHighR").people[0]
    seg = _segment("a person raises the right arm above the head", len(grab))
    rv = review(seg, [grab])
    assert rv.confirmed.get("right_arm") is True, rv.captions
    assert not [i for i in rv.instructions if i["kind"] == "edit_part"]


def test_body_that_contradicts_the_plan_is_regenerated(clips):
    walk = _clip(clips, "walk").people[0][:80]
    rv = review(_segment("a person lies down on the floor", 80), [walk])
    assert rv.body_confirmed is False
    assert [i["kind"] for i in rv.instructions] == ["regenerate"]


def test_sunk_motion_fails_ground_penetration_with_a_repaint_window(clips):
    walk = _clip(clips, "walk").people[0][:80].copy()
    assert "ground_penetration" not in commonsense([walk]).failed
    walk[20:50, :, 1] -= 0.15            # 30 frames sink 15 cm under the floor
    checks = commonsense([walk])
    assert "ground_penetration" in checks.failed
    assert any(a <= 20 and b >= 50 and "ground penetration" in r for a, b, r in checks.windows)


def test_handshake_without_a_touch_is_missing_contact(clips):
    pair = [p.copy() for p in _clip(clips, "composed handshake", 2).people]
    assert "missing_contact" not in commonsense(pair, "two people shake hands").failed
    pair[1][..., 0] += 3.0               # 3 m apart: no hand can reach
    checks = commonsense(pair, "two people shake hands")
    assert "missing_contact" in checks.failed
    seg = _segment("two people shake hands", len(pair[0]), persons=2)
    rv = review(seg, pair)
    assert [i["kind"] for i in rv.instructions] == ["regenerate"]


def test_correction_loop_keeps_improvements_and_redraws_again_when_worse(clips):
    walk = _clip(clips, "walk").people[0][:80]
    seg = _segment("a person squats", 80)
    squat = _clip(clips, "squat1Reps").people[0][:80]   # what the plan asks for
    events = []

    def better(instr, people, seed):
        return [squat.astype(np.float64)]

    out = correct(seg, [walk], better, rounds=2, emit=events.append)
    assert out.first.body_confirmed is False and out.last.body_confirmed is True
    assert out.corrections[0]["accepted"] and out.corrections[0]["score_after"] >= out.first.score
    assert np.array_equal(out.people[0], squat)
    assert [e["type"] for e in events][:2] == ["review", "correction"]

    def sink(instr, people, seed):
        bad = people[0].copy()
        bad[..., 1] -= 0.2
        return [bad]

    # a worse re-draw is not kept; another is tried in the next round; none passes: failed
    out = correct(seg, [walk], sink, rounds=2)
    assert [c["accepted"] for c in out.corrections] == [False, False]
    assert [c["round"] for c in out.corrections] == [1, 2]
    assert np.array_equal(out.people[0], walk)
    assert [r.verdict for r in out.reviews] == ["correct", "failed"]
    assert out.last.round == 2 and out.last.body_confirmed is False

    def unable(instr, people, seed):
        raise CannotApply("no model")

    out = correct(seg, [walk], unable, rounds=2)
    assert out.corrections[0]["reason"] == "no model" and not out.corrections[0]["accepted"]
    assert correct(seg, [walk], better, rounds=0).corrections == []


def test_review_rejects_bad_joints():
    with pytest.raises(ValueError, match="22, 3"):
        review(_segment("a person walks", 10), [np.zeros((10, 21, 3))])
