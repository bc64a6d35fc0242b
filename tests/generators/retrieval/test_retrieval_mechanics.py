"""Retrieval and generator mechanics on a tiny stand-in set of synthetic FK clips (see
conftest.py): train preference, seed determinism, chaining, streaming, two-person modes."""

import numpy as np
import pytest

from interplay.generators.base import Request
from interplay.generators.retrieval.generator import CHUNK
from interplay.generators.retrieval.stitch import heading
from interplay.generators.router import build_generator
from interplay.motion import skeleton as sk


@pytest.fixture(scope="module")
def gen(stand_in_dir):
    return build_generator(stand_in_dir, use_spam=False)   # retrieval, not SPAM


def test_prefers_train_clips_and_chains_to_the_requested_length(gen):
    track = gen.index.track("a person walks forward", 300, np.random.default_rng(0))
    assert sum(p["end"] - p["start"] for p in track) == 300
    assert {p["clip"] for p in track} <= {"synth:walk0", "synth:walk1"}   # walk2 is test split
    assert len(track) >= 4                                                # clips are 70–90 frames


def test_same_seed_same_motion_other_seed_other_choice(gen):
    req = Request("a person walks forward", 1, 5.0, seed=11)
    a, b = gen.generate(req), gen.generate(req)
    np.testing.assert_array_equal(a.people[0], b.people[0])
    assert a.plan == b.plan and a.seed == 11
    plans = {str(gen.plan(Request("a person walks forward", 1, 5.0, seed=s)).segments[0].retrieval)
             for s in range(6)}
    assert len(plans) > 1
    assert gen.plan(Request("a person walks", 1, 2.0)).seed is not None


def test_stream_chunks_cover_every_frame_in_order(gen):
    req = Request("a person walks forward, then jumps; finally walks", 1, 7.3, seed=2)
    plan = gen.plan(req)
    chunks = list(gen.stream(req, plan))
    starts = [s for s, _ in chunks]
    sizes = [len(people[0]) for _, people in chunks]
    assert starts[0] == 0 and all(s1 == s0 + n for s0, s1, n in zip(starts, starts[1:], sizes))
    assert sum(sizes) == 146 and max(sizes) <= CHUNK
    seg_starts = {s.start for s in plan.segments}
    assert seg_starts <= set(starts)                          # chunks never straddle segments
    joined = np.concatenate([people[0] for _, people in chunks])
    np.testing.assert_array_equal(joined, gen.generate(req).people[0])


def test_two_people_use_the_pair_capture_for_a_pair_prompt(gen):
    m = gen.generate(Request("two people dance salsa", 2, 6.0, seed=1))
    seg = m.plan["segments"][0]["retrieval"]
    assert seg["mode"] == "pair" and not m.plan["synthetic"]
    assert all(p["clip"] == "synth:salsa" for p in seg["tracks"][0])
    assert len(m.people) == 2 and m.frames == 120


def test_two_people_otherwise_composed_from_single_captures_and_labelled(gen):
    m = gen.generate(Request("two people jump", 2, 3.0, seed=1))
    seg = m.plan["segments"][0]["retrieval"]
    assert seg["mode"] == "composed" and seg["synthetic"] and m.plan["synthetic"]
    assert seg["arrangement"] == "facing"
    a, b = (p[0, sk.PELVIS] for p in m.people)
    assert abs(np.linalg.norm((a - b)[[0, 2]]) - 1.5) < 0.05
    towards = (b - a) * [1, 0, 1] / np.linalg.norm((b - a)[[0, 2]])
    assert heading(m.people[0][:5]) @ towards > 0.9 and heading(m.people[1][:5]) @ towards < -0.9
    walk = gen.generate(Request("two people walk forward", 2, 3.0, seed=1))
    assert walk.plan["segments"][0]["retrieval"]["arrangement"] == "side_by_side"


def test_bad_requests_and_plans_raise_value_error(gen):
    for kwargs in ({"persons": 3}, {"seconds": 0}, {"seed": "x"}):
        with pytest.raises(ValueError):
            Request("a person walks", **kwargs)
    req = Request("a person walks", 1, 3.0, seed=0)
    plan = gen.plan(req)
    plan.segments[0].retrieval.tracks[0][0].clip = "nope"
    with pytest.raises(ValueError, match="unknown clip"):
        list(gen.stream(req, plan))
