"""The reviewer and issue 15's penetration bound, on real data: it reads the contact a text asks
for as the benchmark's prompts mark it, rejects two people over the bound, resolves them itself
(`resolve_penetration`) keeping the asked-for touch, and asks for a re-generation when the
resolution has already run and the bound still fails."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.eval.prompts.suite import load_suite
from interplay.motion import skeleton as sk
from interplay.motion.checks.named import run_check
from interplay.motion.clip import default_clips
from interplay.motion.pair.compose import compose
from interplay.motion.pair.resolve import pair_bounds
from interplay.planner.plan import plan
from interplay.review.checks import commonsense, contact_mode
from interplay.review.reviewer import RESOLVE, CannotApply, correct, review


@pytest.fixture(scope="module")
def clips():
    return default_clips()


def _segment(prompt: str, frames: int):
    seg = plan(prompt, 2, frames / 20).segments[0]
    return seg.model_copy(update={"start": 0, "end": frames, "seconds": frames / 20})


def _cannot(instr, people, seed):
    raise CannotApply(f"{instr['kind']} cannot run here")


def _inside_each_other(clips) -> list[np.ndarray]:
    """Two captured walkers started on the same spot."""
    walks = [c for c in clips if len(c.people) == 1 and not c.synthetic and c.frames >= 120
             and "walk" in c.prompt][:2]
    return [np.asarray(c.people[0][:120], np.float64) - c.people[0][0, sk.PELVIS] * [1, 0, 1]
            for c in walks]


def test_contact_is_read_as_the_benchmark_marks_it():
    pairs = [p for p in load_suite() if p.persons == 2]
    assert len(pairs) >= 20
    for p in pairs:
        assert (contact_mode(p.prompt) != "none") == p.contact, p.prompt
    assert contact_mode("two friends embrace warmly") == "hug"
    assert contact_mode("two people shake hands") == "hands"
    assert contact_mode("two people jump together") == "none"


def test_a_pair_over_the_bound_is_resolved_by_the_reviewer(clips):
    people = _inside_each_other(clips)
    seg = _segment("two people walk side by side", 120)
    checks = commonsense(people, seg.prompt)
    assert "interpenetration" in checks.failed
    first = review(seg, people)
    assert first.verdict == "correct" and first.instructions[0]["kind"] == RESOLVE
    events = []
    out = correct(seg, people, _cannot, emit=events.append)
    fix = next(e for e in events if e["type"] == "correction" and e["instruction"]["kind"] == RESOLVE)
    assert fix["accepted"] and "moved apart" in fix["reason"]
    assert pair_bounds(out.people[0], out.people[1], "none")["ok"]
    assert "interpenetration" not in out.last.checks["failed"]
    for p0, p in zip(people, out.people):
        assert np.allclose(sk.bone_lengths(p0), sk.bone_lengths(p), atol=1e-9)


def test_the_hug_is_kept_while_its_arms_leave_the_partner(clips):
    hug = compose("hug", 1, 6.0, clips=clips)          # hands 7 cm deep in the partner on average
    people = [np.asarray(p, np.float64) for p in hug.people]
    seg = _segment("two people hug each other", len(people[0]))
    assert not pair_bounds(people[0], people[1], "hug")["ok"]
    out = correct(seg, people, _cannot)
    assert pair_bounds(out.people[0], out.people[1], "hug")["ok"]
    assert run_check(out.people, {"check": "hug"}).passed
    assert out.last.verdict == "ok" or "interpenetration" not in out.last.checks["failed"]


def test_still_over_the_bound_after_the_resolution_asks_for_a_new_draw(clips):
    people = _inside_each_other(clips)
    seg = _segment("two people walk side by side", 120)
    rv = review(seg, people, resolved=True)
    assert [i["kind"] for i in rv.instructions] == ["regenerate"]
    assert "after the resolution" in rv.instructions[0]["reason"]
