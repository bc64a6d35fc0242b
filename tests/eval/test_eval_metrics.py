"""The metric maths on cases with known answers, and the trained evaluator on real test data:
captured motions match their own prompts better than shuffled prompts."""

import numpy as np
import pytest

from interplay.eval import metrics as M


def _unit(x):
    return x / np.linalg.norm(x, axis=1, keepdims=True)


def test_fid_of_identical_sets_is_zero_and_of_a_shift_is_its_square():
    x = np.random.default_rng(0).normal(size=(200, 16))
    assert M.fid(x, x) == pytest.approx(0.0, abs=1e-8)
    shift = np.zeros(16)
    shift[3] = 0.5
    assert M.fid(x + shift, x) == pytest.approx(0.25, rel=1e-6)   # same covariance


def test_frechet_of_one_dimensional_gaussians():
    # (mu1 - mu2)^2 + (sigma1 - sigma2)^2 for 1-D Gaussians
    value = M.frechet(np.array([1.0]), np.array([[4.0]]), np.array([0.0]), np.array([[1.0]]))
    assert value == pytest.approx(1.0 + 1.0)
    # rank-deficient covariances (fewer samples than dims) stay real and non-negative
    rng = np.random.default_rng(1)
    assert M.fid(rng.normal(size=(10, 64)), rng.normal(size=(12, 64))) > 0


def test_r_precision_of_a_perfect_and_of_a_wrong_matcher():
    rng = np.random.default_rng(0)
    labels = [f"text {i % 40}" for i in range(80)]
    texts = _unit(rng.normal(size=(40, 32)))[[i % 40 for i in range(80)]]
    assert M.r_precision(texts, texts, labels, rng).tolist() == [1.0, 1.0, 1.0]
    # every motion sits exactly on another label's text: its own is never first
    wrong = texts[[(i + 1) % 80 for i in range(80)]]
    top = M.r_precision(wrong, texts, labels, rng)
    assert top[0] == 0.0 and np.all(np.diff(top) >= 0)


def test_r_precision_by_chance_is_k_over_the_pool():
    rng = np.random.default_rng(2)
    labels = [str(i) for i in range(300)]
    motion, text = _unit(rng.normal(size=(300, 64))), _unit(rng.normal(size=(300, 64)))
    runs = np.mean([M.r_precision(motion, text, labels, rng, pool=32) for _ in range(20)], axis=0)
    assert runs == pytest.approx(np.arange(1, 4) / 32, abs=0.02)


def test_r_precision_never_uses_the_true_text_as_a_distractor():
    """Two samples share a text: the other one's copy of it must not count against a hit."""
    rng = np.random.default_rng(0)
    e = np.eye(3)
    motion = np.array([e[0], e[0], e[1], e[2]])
    text = motion.copy()
    top = M.r_precision(motion, text, ["a", "a", "b", "c"], rng, pool=3, top_k=1)
    assert top.tolist() == [1.0]
    with pytest.raises(ValueError, match="different texts"):
        M.r_precision(motion, text, ["a"] * 4, rng)


def test_mm_dist_diversity_and_multimodality():
    rng = np.random.default_rng(0)
    x = _unit(rng.normal(size=(50, 8)))
    assert M.mm_dist(x, x) == 0.0
    assert M.mm_dist(x, -x) == pytest.approx(2.0)
    two = np.array([[0.0, 0.0], [3.0, 4.0]])
    assert M.diversity(two, rng) == pytest.approx(5.0)          # the only pair
    assert M.diversity(x, rng, pairs=300) > 1.0                # random unit vectors in 8-d: ~1.4
    same = [np.repeat(x[:1], 10, axis=0), np.repeat(x[1:2], 10, axis=0)]
    assert M.multimodality(same) == 0.0
    assert M.multimodality([two, two]) == pytest.approx(5.0)


def test_confidence_interval():
    mean, ci = M.confidence([1.0, 2.0, 3.0, 4.0])
    assert mean == 2.5
    assert ci == pytest.approx(1.96 * np.std([1, 2, 3, 4]) / 2)
    assert M.confidence([5.0, 5.0]) == (5.0, 0.0)


# ---- the trained evaluator on the real test split -----------------------------------------

@pytest.fixture(scope="module")
def test_embeddings():
    from interplay.eval.testset import split_samples
    from interplay.motion.clip import default_clips
    from interplay.review.evaluator import load_evaluator
    ev = load_evaluator()
    samples = split_samples(default_clips(), "test", sources=ev.sources)   # what it was trained on
    texts = [s.text for s in samples]
    return ev.embed_motion([s.joints for s in samples]), ev.embed_text(texts), texts


def test_real_test_motions_match_their_texts_better_than_shuffled_texts(test_embeddings):
    motion, text, labels = test_embeddings
    rng = np.random.default_rng(0)
    labels_arr = np.array(labels, dtype=object)
    # shuffled texts: each motion gets the text of a random sample with a different prompt
    other = np.array([rng.choice(np.flatnonzero(labels_arr != lab)) for lab in labels])
    matched = (motion * text).sum(axis=1)
    shuffled = (motion * text[other]).sum(axis=1)
    assert matched.mean() > shuffled.mean() + 0.2
    assert np.mean(matched > shuffled) > 0.8
    assert M.mm_dist(motion, text) < M.mm_dist(motion, text[other])
    real = np.mean([M.r_precision(motion, text, labels, rng) for _ in range(5)], axis=0)
    fake = np.mean([M.r_precision(motion, text[other], list(labels_arr[other]), rng)
                    for _ in range(5)], axis=0)
    assert real[2] > 0.6 and real[2] > fake[2] + 0.4   # chance for top-3 of 32 is 0.09
