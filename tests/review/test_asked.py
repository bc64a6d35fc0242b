"""The reviewer judges a segment by what its words ask, with the benchmark's own checks (issue
14 item 6), on real captured jumps: one jump reviewed for "jumps twice" fails and is asked for
again; a correction that makes two jumps is kept even when the text score drops; one that
loses what was asked is rejected; the job pipeline derives the checks from the plan's words."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.motion.clip import default_clips
from interplay.pipeline.orchestrator import asked_of
from interplay.planner.plan import plan
from interplay.review.reviewer import correct, review

ASKED = [{"check": "jump_count", "count": 2}]


@pytest.fixture(scope="module")
def jumps():
    by_id = {c.id: c for c in default_clips()}
    return [np.asarray(by_id[i].people[0], np.float64) for i in ("cmu:13_39", "cmu:13_41")]


def _segment(prompt: str, frames: int):
    seg = plan(prompt, 1, frames / 20).segments[0]
    return seg.model_copy(update={"start": 0, "end": frames, "seconds": frames / 20})


def _twice(jumps) -> np.ndarray:
    a, b = jumps
    b = b - b[:1, :1] * np.array([1.0, 0.0, 1.0]) + a[-1:, :1] * np.array([1.0, 0.0, 1.0])
    return np.concatenate([a, b])


def test_one_jump_for_two_asked_fails_and_is_asked_again(jumps):
    one = jumps[0]
    seg = _segment("a person jumps twice", len(one))
    rv = review(seg, [one], asked=ASKED)
    assert rv.verdict == "correct" and "asked_jump_count" in rv.checks["failed"]
    assert rv.instructions[0]["kind"] == "regenerate"
    assert "asked count 2" in rv.instructions[0]["reason"]
    assert review(seg, [one]).checks["failed"].get("asked_jump_count") is None   # not asked: silent


def test_a_correction_that_does_what_was_asked_is_kept(jumps):
    two = _twice(jumps)
    one = np.concatenate([jumps[0], np.repeat(jumps[0][-1:], len(two) - len(jumps[0]), 0)])
    seg = _segment("a person jumps twice", len(two))
    # a second jump adds flight and foot motion to the held pose's: the metrics' tolerance is
    # opened here so that only what was asked decides
    out = correct(seg, [one], lambda instr, people, s: [two], rounds=1, asked=ASKED, tolerance=10.0)
    assert out.corrections[0]["accepted"], out.corrections[0]
    assert out.reviews[-1].verdict == "ok" and np.array_equal(out.people[0], two)


def test_a_correction_that_loses_what_was_asked_is_rejected(jumps):
    two = _twice(jumps)
    still = np.repeat(two[:1], len(two), 0)
    seg = _segment("a person jumps twice", len(two))
    # asked to end lying too, the two jumps are re-generated; a re-generation that stands
    # still ends no more lying and loses both jumps
    out = correct(seg, [two], lambda instr, people, s: [still], rounds=1, tolerance=10.0,
                  asked=ASKED + [{"check": "posture_at_end", "posture": "lying"}])
    first = out.corrections[0]
    assert first["instruction"]["kind"] == "regenerate" and not first["accepted"]
    assert first["reason"] == "it misses 1 more of what was asked"
    assert np.array_equal(out.people[0], two)


def test_the_pipeline_reads_the_checks_from_the_plan():
    segs = plan("jump twice, then walk backwards", 1, 8).segments
    first, second = (asked_of(s) for s in segs)
    assert {"check": "jump_count", "count": 2} in first
    assert {"check": "posture_at_start", "posture": "standing"} in first
    assert any(c["check"] == "travel_direction" and c["direction"] == "backward" for c in second)
    assert all(c["check"] != "posture_at_start" for c in second)
