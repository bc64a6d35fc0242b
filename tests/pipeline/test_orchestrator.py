"""Algorithm 1 in the orchestrator: segments streamed and reviewed in order, review
instructions run through SPAM's edits (the committed placeholder graphs, so edits really run)
or retrieval re-draws, corrected frames re-sent with their start, plan trajectories moving the
later segments along, cancellation and stage errors."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.generators.base import Request
from interplay.generators.retrieval.generator import RetrievalGenerator
from interplay.generators.retrieval.index import RetrievalIndex
from interplay.generators.router import with_spam
from interplay.generators.spam.generator import SpamGenerator
from interplay.generators.spam.runtime import DEFAULT_DIR
from interplay.pipeline.orchestrator import (
    Cancelled,
    OrchestratorConfig,
    StageError,
    orchestrate,
)
from tests.helpers.spam_stub import StubEncoder
from tests.helpers.synthetic_motion import stand_in_clips


@pytest.fixture(scope="module")
def index():
    return RetrievalIndex(stand_in_clips(), StubEncoder())


def _run(gen, req, **kw):
    events, frames = [], []
    out = orchestrate(gen, req, events.append, lambda s, c: frames.append((s, c)), **kw)
    return out, events, frames


def _replay(frames, total: int, persons: int) -> np.ndarray:
    arr = np.full((persons, total, 22, 3), np.nan)
    for s, chunk in frames:
        for p, c in enumerate(chunk):
            arr[p, s:s + len(c)] = c
    return arr


def test_spam_review_runs_part_edits_and_resends_what_it_keeps(index):
    gen = SpamGenerator(with_spam(index, DEFAULT_DIR, allow_untrained=True).spam)
    req = Request("a person walks while raising the left arm above the head", 1, 4.0, seed=2)
    out, events, frames = _run(gen, req)
    assert events[0]["type"] == "plan" and events[0]["plan"]["generator"] == "spam"
    corrections = [e for e in events if e["type"] == "correction"]
    reviews = [e for e in events if e["type"] == "review"]
    assert reviews and reviews[0]["round"] == 0
    asked = [i["kind"] for i in reviews[0]["instructions"]]
    if asked:   # the untrained model rarely does what the plan says: its edits must run
        assert corrections and all(c["score_after"] is not None for c in corrections[:1])
    accepted = [c for c in corrections if c["accepted"]]
    for c in accepted:
        assert c["score_after"] >= c["score_before"]
    # What was streamed last per frame is what the orchestrator returns.
    streamed = _replay(frames, out.people[0].shape[0], 1)
    assert np.allclose(streamed[0], out.people[0], atol=1e-4)
    starts = [s for s, _ in frames]
    assert (len(starts) != len(set(starts))) == bool(accepted)


def test_retrieval_regenerate_redraws_and_keeps_the_stream_consistent(index):
    gen = RetrievalGenerator(index)
    req = Request("a person walks forward, then lies down on the floor", 1, 6.0, seed=5)
    out, events, frames = _run(gen, req)
    segs = [e for e in events if e["type"] == "segment"]
    assert [(e["index"], e["status"]) for e in segs][:2] == [(0, "generating"), (0, "done")]
    streamed = _replay(frames, 120, 1)
    assert not np.isnan(streamed).any()
    assert np.allclose(streamed[0], out.people[0], atol=1e-4)
    for c in (e for e in events if e["type"] == "correction"):
        kind = c["instruction"]["kind"]
        if kind == "inbetween":
            assert c["score_after"] is None and "SPAM" in c["reason"]
        else:
            assert c["score_after"] is not None    # a re-draw ran


def test_no_review_means_no_review_events(index):
    out, events, _ = _run(RetrievalGenerator(index), Request("a person walks", 1, 3.0, seed=1),
                          cfg=OrchestratorConfig(review=False))
    assert not [e for e in events if e["type"] in ("review", "correction")]
    assert out.review["segments"] == []


def test_cancel_and_stage_errors(index):
    gen = RetrievalGenerator(index)
    with pytest.raises(Cancelled):
        _run(gen, Request("a person walks", 1, 3.0, seed=1), cancelled=lambda: True)

    class Broken(RetrievalGenerator):
        def stream(self, req, plan):
            raise RuntimeError("no frames today")
            yield

    with pytest.raises(StageError) as exc:
        _run(Broken(index), Request("a person walks", 1, 3.0, seed=1))
    assert exc.value.stage == "generate" and "no frames today" in exc.value.reason
