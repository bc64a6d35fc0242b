"""CODA on the committed weights (models/weights/coda): shapes, seeding, fixed bones, the floor,
and the decoded pair of a held-out test window's own tokens is close to that window."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.agents.coda import CodaRuntime
from interplay.agents.coda_graphs import DEFAULT_DIR, FILES
from interplay.eval.pair import pair_set
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
    assert abs(np.percentile(lowest, 2)) < 1e-6


def test_a_test_windows_own_tokens_decode_close_to_it(rt):
    test = pair_set("test")
    errors = []
    for kind in (False, True):                     # one captured, one composed window
        w = test.windows[np.flatnonzero(test.synthetic == kind)[0]]   # (2, 80, 22, 3) canonical
        rec = rt.decode(rt.encode(w))
        errors.append(float(np.linalg.norm(rec - w, axis=-1).mean()))
    # a VQ-VAE reconstruction of held-out motion: centimetres, not the metres between
    # unrelated poses (two different test windows are ~0.3 m apart on the same measure)
    assert max(errors) < 0.12, errors


def test_windows_beyond_the_model_range_continue(rt):
    frames = rt.config.max_frames + 40
    out = rt.generate("two people walk side by side", frames / 20, seed=1)
    assert out.shape == (2, frames, 22, 3) and np.all(np.isfinite(out))
    step = np.linalg.norm(np.diff(out[:, :, 0], axis=1), axis=-1)    # pelvis m/frame
    assert step.max() < 0.5                       # no teleport at the window seams
