"""The evaluator runtime (numpy + onnxruntime) with the committed weights, on real captures."""

import numpy as np
import pytest

from interplay.motion.clip import default_clips
from interplay.review.evaluator import EvaluatorRuntime, chunks, load_evaluator


@pytest.fixture(scope="module")
def ev() -> EvaluatorRuntime:
    return load_evaluator()


@pytest.fixture(scope="module")
def clips():
    return {c.id: c for c in default_clips() if not c.synthetic}


def _first(clips, prompt, split="test"):
    return next(c for c in clips.values() if c.prompt == prompt and c.split == split)


def test_embeddings_are_unit_rows_and_batching_does_not_change_them(ev, clips):
    motions = [c.people[0].astype(float) for c in list(clips.values())[:5]]
    both = ev.embed_motion(motions)
    assert both.shape == (5, ev.dim)
    np.testing.assert_allclose(np.linalg.norm(both, axis=1), 1.0, atol=1e-5)
    for i in (0, 3):                  # alone vs padded in a batch of different lengths
        np.testing.assert_allclose(ev.embed_motion([motions[i]])[0], both[i], atol=1e-4)
    t = ev.embed_text(["a person walks forward", "a person squats down and stands back up"])
    assert t.shape == (2, ev.dim)
    np.testing.assert_allclose(np.linalg.norm(t, axis=1), 1.0, atol=1e-5)


def test_motion_is_closest_to_its_own_prompt(ev, clips):
    """Held-out test captures: each scores its own prompt above the other actions'."""
    prompts = ["a person walks forward", "a person squats down and stands back up",
               "a person kicks forward with the left foot", "a person lies down on the floor"]
    motions = [_first(clips, p).people[0].astype(float) for p in prompts]
    sims = ev.embed_motion(motions) @ ev.embed_text(prompts).T
    assert (sims.argmax(axis=1) == np.arange(len(prompts))).all()
    assert -1.0 <= ev.score(motions[0], prompts[0]) <= 1.0
    assert ev.score(motions[0], prompts[0]) > ev.score(motions[0], prompts[1])


def test_translation_and_turning_do_not_change_the_embedding(ev, clips):
    walk = _first(clips, "a person walks forward").people[0].astype(float)
    c, s = np.cos(1.0), np.sin(1.0)
    yaw = np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    moved = walk @ yaw.T + np.array([3.0, 0.0, -2.0])
    np.testing.assert_allclose(ev.embed_motion([moved]), ev.embed_motion([walk]), atol=1e-3)


def test_long_motions_are_chunked_and_averaged(ev, clips):
    salsa = next(c for c in clips.values() if c.source == "cmu-salsa").people[0].astype(float)
    assert len(salsa) > 2 * ev.max_frames
    parts = chunks(len(salsa), ev.max_frames)
    assert parts[0][0] == 0 and parts[-1][1] == len(salsa)
    assert max(b - a for a, b in parts) <= ev.max_frames
    whole = ev.embed_motion([salsa])[0]
    from interplay.motion.features import encode
    feats = encode(salsa)
    pieces = ev.embed_features([feats[a:b] for a, b in parts])
    mean = pieces.mean(axis=0)
    np.testing.assert_allclose(whole, mean / np.linalg.norm(mean), atol=1e-4)


def test_bad_input_is_refused(ev, tmp_path):
    with pytest.raises(ValueError, match="list"):
        ev.embed_text("a person walks")
    with pytest.raises(ValueError, match="list"):
        ev.embed_motion(np.zeros((10, 22, 3)))
    with pytest.raises(ValueError, match="features"):
        ev.embed_features([np.zeros((10, 5))])
    with pytest.raises(FileNotFoundError, match="motion_encoder.onnx"):
        EvaluatorRuntime.load(tmp_path)
