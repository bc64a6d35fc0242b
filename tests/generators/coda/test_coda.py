"""CODA on the committed weights (models/weights/coda): shapes, seeding, fixed bones, the floor,
and the decoded pair of a held-out test window's own tokens is close to that window."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.eval.pair import pair_set
from interplay.generators.coda.files import DEFAULT_DIR, FILES
from interplay.generators.coda.runtime import CodaRuntime
from interplay.motion.metrics import bone_deviation

pytestmark = pytest.mark.skipif(not all((DEFAULT_DIR / f).is_file() for f in FILES),
                                reason="no CODA weights committed yet")


@pytest.fixture(scope="module")
def rt():
    return CodaRuntime.load(DEFAULT_DIR)


def test_generate_is_seeded_with_fixed_bones_on_the_floor(rt):
    a = rt.generate("two people shake hands", 2.0, seed=3)
    assert a.shape == (2, 40, 22, 3) and np.all(np.isfinite(a))
    assert np.array_equal(a, rt.generate("two people shake hands", 2.0, seed=3))
    assert not np.allclose(a, rt.generate("two people shake hands", 2.0, seed=4))
    for p in a:
        assert bone_deviation(p).max() < 1e-6
        assert 1.0 < np.ptp(p[0, :, 1]) < 2.2          # a standing person's height, metres
    lowest = np.concatenate([p[..., 1].min(axis=1) for p in a])
    assert abs(np.percentile(lowest, 2)) < 0.01 and lowest.min() > -1e-9


def test_a_test_windows_own_tokens_decode_close_to_it(rt):
    test = pair_set("test")
    for kind in (False, True):                     # captured salsa, composed
        idx = np.flatnonzero(test.synthetic == kind)
        w, other = test.windows[idx[0]], test.windows[idx[-1]]     # (2, 80, 22, 3) canonical
        rec = rt.decode(rt.encode(w))
        own = float(np.linalg.norm(rec - w, axis=-1).mean())
        apart = float(np.linalg.norm(rec - other, axis=-1).mean())
        # the VQ-VAE's reconstruction of held-out motion: much closer to its own window than
        # to another test window of the same kind, and within the model card's error scale
        assert own < 0.5 * apart and own < 0.25, (kind, own, apart)


def test_windows_beyond_the_trained_length_continue(rt):
    frames = 3 * rt.config.max_frames                  # three windows and more
    out = rt.generate("two people shake hands", frames / 20, seed=1)
    assert out.shape == (2, frames, 22, 3) and np.all(np.isfinite(out))
    step = np.linalg.norm(np.diff(out[:, :-4, 0], axis=1), axis=-1)   # pelvis m per frame
    assert step.max() < 0.25                       # ≤ 5 m/s: no jump at the window seams
