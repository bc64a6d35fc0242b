import numpy as np
import pytest

from interplay.text.encoder import DIM, TextEncoder, get_encoder


@pytest.fixture(scope="module")
def enc() -> TextEncoder:
    return get_encoder()


def test_similar_sentences_score_higher_than_unrelated(enc):
    walk, walking, jump = enc.encode(["a person walks forward", "someone is walking", "a person jumps"])
    assert walk @ walking > walk @ jump + 0.2
    assert walking @ walk > walking @ jump + 0.2
    salsa, dance = enc.encode(["two people dance salsa", "a couple dancing together"])
    assert salsa @ dance > salsa @ walk + 0.2


def test_embeddings_are_unit_float32_and_ordered(enc):
    texts = ["a person walks forward", "", "a person jumps", "a person walks forward", "x " * 400]
    v = enc.encode(texts)
    assert v.shape == (5, DIM) and v.dtype == np.float32
    np.testing.assert_allclose(np.linalg.norm(v, axis=1), 1.0, atol=1e-5)
    np.testing.assert_array_equal(v[0], v[3])
    assert v[0] @ v[2] < 0.99


def test_batching_and_padding_do_not_change_embeddings(enc):
    texts = ["a person kicks forward with the left foot", "jump", "a person walks in a circle slowly"]
    together = enc._embed(texts)                      # padded to the longest
    alone = np.concatenate([enc._embed([t]) for t in texts])
    np.testing.assert_allclose(together, alone, atol=1e-4)


def test_cache_is_bounded_and_lru():
    e = TextEncoder(cache_size=2)
    e.encode(["a", "b"])
    e.encode(["a"])            # a is now most recent
    e.encode(["c"])            # evicts b
    assert list(e._cache) == ["a", "c"]
    with pytest.raises(ValueError):
        e.encode("a person walks")


def test_get_encoder_is_a_singleton():
    assert get_encoder() is get_encoder()
