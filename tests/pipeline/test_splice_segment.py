"""Re-running one segment in place (`pipeline/rerun.py`) on real captures: the other segments'
frames are the stored values bit for bit, the re-run one is new, the borders continue without a
jump (position and heading), bones keep their lengths, and the result is a stored version with
its parent, its plan entry and the parent's review without that segment. Bad indices and
motions without segments are ValueErrors."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.generators.retrieval.generator import RetrievalGenerator
from interplay.generators.retrieval.index import RetrievalIndex
from interplay.motion import skeleton as sk
from interplay.motion.clip import default_clips
from interplay.motion.kinematics import facing_angle
from interplay.pipeline.rerun import rerun_stored, segment_span, splice_segment
from interplay.store import MotionRepository, make_engine
from interplay.text.encoder import get_encoder

SEGMENTS = [{"prompt": "a person walks forward", "start": 0, "end": 60, "persons": [0]},
            {"prompt": "a person jumps", "start": 60, "end": 90, "persons": [0]},
            {"prompt": "a person sits down", "start": 90, "end": 120, "persons": [0]}]


@pytest.fixture(scope="module")
def walk():
    clips = default_clips()
    one = next(c for c in clips if len(c.people) == 1 and c.frames >= 120)
    return one, clips


@pytest.fixture(scope="module")
def generator(walk):
    _, clips = walk
    singles = [c for c in clips if len(c.people) == 1][:40]
    return RetrievalGenerator(RetrievalIndex(singles, get_encoder()))


@pytest.fixture
def repo(tmp_path):
    return MotionRepository(make_engine(f"sqlite:///{tmp_path / 'r.db'}"))


def _jump(x: np.ndarray) -> float:
    """Largest per-frame pelvis displacement (m) of (T, 22, 3)."""
    return float(np.linalg.norm(np.diff(x[:, sk.PELVIS], axis=0), axis=-1).max())


def test_splice_keeps_the_rest_exactly_and_meets_both_borders(walk):
    clip, _ = walk
    old = [clip.people[0][:120].astype(np.float32)]
    # a different piece of motion, far away and turned: the splice must place it
    other = np.asarray(clip.people[0][:120], dtype=np.float64)
    new = [other[10:40] @ np.array([[0, 0, 1], [0, 1, 0], [-1, 0, 0]]).T + [5.0, 0.0, -3.0]]
    out = splice_segment(old, new, 60, 90)
    assert out[0].dtype == np.float32 and out[0].shape == old[0].shape
    assert np.array_equal(out[0][:60], old[0][:60]) and np.array_equal(out[0][90:], old[0][90:])
    assert not np.allclose(out[0][65:85], old[0][65:85], atol=1e-3)
    # no jump at either border: no bigger than the motion's own largest step (plus a little)
    own = _jump(np.asarray(old[0], np.float64))
    for t in (59, 89):
        step = np.linalg.norm(out[0][t + 1, sk.PELVIS] - out[0][t, sk.PELVIS])
        assert step <= own + 0.02, (t, step, own)
        turn = abs(float(facing_angle(out[0][t + 1][None])[0] - facing_angle(out[0][t][None])[0]))
        assert min(turn, 2 * np.pi - turn) < 0.35
    # bones: the person's lengths
    bones = sk.bone_lengths(out[0].astype(np.float64))
    assert np.abs(bones[60:90] - np.median(sk.bone_lengths(old[0].astype(np.float64)), 0)).max() < 0.01


def test_segment_span_checks():
    plan = {"segments": SEGMENTS}
    assert segment_span(plan, 1, 120) == (60, 90, "a person jumps")
    for bad in (-1, 3):
        with pytest.raises(ValueError, match="does not exist"):
            segment_span(plan, bad, 120)
    with pytest.raises(ValueError, match="no planned segments"):
        segment_span({"generator": "arflow"}, 0, 120)
    with pytest.raises(ValueError, match="too short"):
        segment_span({"segments": [{"prompt": "x", "start": 0, "end": 2}]}, 0, 120)


def test_rerun_stored_is_a_new_version_with_only_that_segment_changed(walk, generator, repo):
    clip, _ = walk
    review = {"rounds": 2, "segments": [{"segment": i, "reviews": [], "corrections": []}
                                        for i in range(3)]}
    parent = repo.create(prompt="a person walks forward, then jumps, then sits down",
                         people=[clip.people[0][:120]], seconds=6.0, seed=1,
                         plan={"segments": SEGMENTS, "generator": "retrieval"}, review=review,
                         client_id="c" * 22)
    made = rerun_stored(repo, generator, parent, 1, seed=77, client_id="c" * 22)
    assert made.parent_id == parent.id and made.id != parent.id and made.frames == 120
    assert made.seconds == parent.seconds and made.seed == 77
    old, new = parent.people[0], made.people[0]
    assert np.array_equal(new[:60], old[:60]) and np.array_equal(new[90:], old[90:])
    assert np.abs(new[60:90] - old[60:90]).max() > 0.01
    entry = made.plan["edits"][-1]
    assert entry["kind"] == "rerun_segment" and entry["segment"] == 1 and entry["seed"] == 77
    assert entry["frames"] == [60, 90] and entry["prompt"] == "a person jumps"
    assert made.edit == {"mode": "rerun", "segment": 1, "part": None, "prompt": "a person jumps",
                         "frames": [60, 90], "trajectory": None, "seed": 77}
    assert [s["segment"] for s in made.review["segments"]] == [0, 2]
    assert len(made.highlights["contacts"]) == 120 and "foot_skating" in made.metrics
    assert [m.id for m in repo.for_client("c" * 22)] == [made.id, parent.id]
    # a second re-run with another seed is another version, and differs again
    again = rerun_stored(repo, generator, made, 1, seed=78)
    assert again.parent_id == made.id and len(again.plan["edits"]) == 2
    assert np.array_equal(again.people[0][90:], old[90:])
