"""The pair evaluator runtime on the committed weights and held-out pairs: shapes, determinism,
invariance to where the pair stands in the world, clear errors, and that it tells a real test
pair set from the same pairs with the second person displaced by 1 m."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.eval.metrics import fid
from interplay.motion.clip import default_clips
from interplay.motion.pair.windows import pair_windows
from interplay.motion.rotations import yaw_matrix
from interplay.review.pair_evaluator import (
    DEFAULT_DIR,
    PairEvaluator,
    check_windows,
    load_pair_evaluator,
)

pytestmark = pytest.mark.skipif(not (DEFAULT_DIR / "motion_encoder.onnx").exists(),
                                reason="no pair evaluator weights")


@pytest.fixture(scope="module")
def ev() -> PairEvaluator:
    return load_pair_evaluator()


def _windows(split: str, synthetic: bool, stride: int = 20) -> np.ndarray:
    clips = [c for c in default_clips() if c.split == split and len(c.people) == 2
             and c.synthetic == synthetic]
    return pair_windows(clips, 40, stride, roles="both", mirror=False, canonical=False).joints


def test_shapes_determinism_and_world_frame(ev):
    w = _windows("test", False)[:6].astype(np.float64)
    a = ev.embed(w)
    assert a.shape == (6, ev.dim) and a.dtype == np.float32
    assert np.allclose(np.linalg.norm(a, axis=1), 1.0, atol=1e-5)
    assert np.array_equal(a, ev.embed(w))
    # the same pairs turned 1 rad, moved 3 m and lifted 0.5 m embed the same
    moved = w @ yaw_matrix(np.array(1.0)).T + np.array([3.0, 0.5, -2.0])
    assert np.abs(ev.embed(moved) - a).max() < 1e-4
    # longer windows are chunked: an (N, 2, 100, 22, 3) input still gives (N, dim)
    clip = next(c for c in default_clips() if c.split == "test" and len(c.people) == 2)
    long = np.stack(clip.people)[None, :, :100]
    assert ev.embed(long).shape == (1, ev.dim)
    t = ev.embed_text(["two people hug each other", "two people dance salsa"])
    assert t.shape == (2, ev.dim)


def test_bad_windows_are_value_errors(ev):
    with pytest.raises(ValueError):
        check_windows(np.zeros((2, 40, 22, 3)))                          # one person's shape
    with pytest.raises(ValueError):
        ev.embed(np.zeros((1, 2, 40, 21, 3)))
    bad = np.zeros((1, 2, 40, 22, 3))
    bad[0, 1, 3, 4, 0] = np.nan
    with pytest.raises(ValueError):
        ev.embed(bad)


@pytest.mark.parametrize("synthetic", [False, True])
def test_displaced_second_person_raises_fid(ev, synthetic):
    ref = ev.embed(_windows("train", synthetic, stride=40))
    test = _windows("test", synthetic).astype(np.float64)
    real = fid(ev.embed(test), ref)
    angle = np.random.default_rng(0).uniform(0, 2 * np.pi, len(test))
    moved = test.copy()
    moved[:, 1, ..., 0] += np.sin(angle)[:, None, None]
    moved[:, 1, ..., 2] += np.cos(angle)[:, None, None]
    assert fid(ev.embed(moved), ref) > 2.0 * real
    # and pair by pair: a real window lies nearer (cosine) to some train window than its
    # displaced copy does, for nearly every window
    nearest = lambda e: (e @ ref.T).max(axis=1)                        # noqa: E731
    assert np.mean(nearest(ev.embed(test)) > nearest(ev.embed(moved))) > 0.85
