"""CODA's torch CCL terms equal the numpy definitions in `interplay.motion.pair.interaction` on a real
captured salsa window (GDM eq. 6, part AABB overlap, bone-to-bone chain distances, PPL eq. 7),
and give finite gradients."""

from __future__ import annotations

import numpy as np
import pytest

torch = pytest.importorskip("torch")

from interplay.motion.clip import default_clips  # noqa: E402
from interplay.motion.pair import interaction as ia  # noqa: E402
from interplay.motion.pair.windows import pair_windows  # noqa: E402
from models.coda import ccl  # noqa: E402


@pytest.fixture(scope="module")
def pairs():
    """A real salsa window (target) and a perturbed copy pulled towards each other (pred)."""
    clips = [c for c in default_clips() if len(c.people) == 2 and not c.synthetic][:1]
    assert clips, "no captured two-person clip in the processed data"
    w = pair_windows(clips, 24, 24, roles="as_is", mirror=False).joints[0].astype(np.float64)
    rng = np.random.default_rng(0)
    pred = w + rng.normal(0, 0.03, w.shape)
    # Bring the second person's pelvis within 0.3 m of the first's (same direction) so some
    # part boxes overlap and chains come close.
    gap = (w[0, :, :1] - w[1, :, :1]) * np.array([1.0, 0.0, 1.0])
    dist = np.linalg.norm(gap, axis=-1, keepdims=True)
    pred[1] += gap * (1 - 0.3 / dist)
    return pred, w


def _t(x):
    return torch.from_numpy(np.ascontiguousarray(x))


def test_gdm_matches_numpy(pairs):
    (pa, pb), (ta, tb) = pairs
    want = ia.gdm_error((pa, pb), (ta, tb))
    got = float(ccl.gdm_loss(_t(pa), _t(pb), _t(ta), _t(tb)))
    assert got == pytest.approx(want, rel=1e-6)
    assert want > 0.01          # the perturbation is visible to the loss


def test_chain_distances_overlap_and_ppl_match_numpy(pairs):
    (pa, pb), (ta, tb) = pairs
    np.testing.assert_allclose(ccl.part_min_distance(_t(pa), _t(pb)).numpy(),
                               ia.part_min_distance(pa, pb), atol=1e-6)
    overlap = ia.part_box_overlap(pa, pb)
    assert overlap.any() and not overlap.all()
    np.testing.assert_array_equal(ccl.part_box_overlap(_t(pa), _t(pb)).numpy(), overlap)
    want = ia.penetration_penalty(ia.part_min_distance(pa, pb), ia.part_min_distance(ta, tb),
                                  overlap)
    got = float(ccl.ppl_loss(_t(pa), _t(pb), _t(ta), _t(tb)))
    assert got == pytest.approx(want, rel=1e-6) and want > 0


def test_losses_vanish_on_the_target_and_have_finite_gradients(pairs):
    (pa, pb), (ta, tb) = pairs
    a = _t(pa).float().requires_grad_()
    b = _t(pb).float().requires_grad_()
    ta_t, tb_t = _t(ta).float(), _t(tb).float()
    total, terms = ccl.ccl(a[None], b[None], ta_t[None], tb_t[None],
                           ccl.LossConfig(gdm_frame_stride=1, ppl_frame_stride=1))
    total.backward()
    assert torch.isfinite(a.grad).all() and torch.isfinite(b.grad).all() and a.grad.abs().sum() > 0
    same, same_terms = ccl.ccl(ta_t[None], tb_t[None], ta_t[None], tb_t[None], ccl.LossConfig())
    for k in ("com", "ktraj", "velocity", "bone", "ppl"):
        assert float(same_terms[k].detach()) < 1e-6 < float(terms[k].detach()), k
