"""ARFlow runtime on the shipped weights and held-out captured pairs: the analytic penetration
gradient, guidance lowering penetration, online stepping equal to whole-window sampling and
blind to the actor's future, fixed bone lengths."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.clip import default_clips
from interplay.motion.metrics import clip_metrics
from interplay.motion.pair.windows import pair_windows
from interplay.reaction.penetration import guide, penetration_loss, radii, sphere_centres
from interplay.reaction.react import react
from interplay.reaction.session import (
    WEIGHTS_DIR,
    ReactionSession,
    SamplingConfig,
    get_reaction_model,
    sample_windows,
)

pytestmark = pytest.mark.skipif(not (WEIGHTS_DIR / "arflow.onnx").exists(),
                                reason="no ARFlow weights")


@pytest.fixture(scope="module")
def windows():
    clips = [c for c in default_clips() if c.split == "test" and len(c.people) == 2
             and not c.synthetic]
    return pair_windows(clips, 40, 20, roles="as_is", mirror=False).joints.astype(np.float64)


@pytest.fixture(scope="module")
def model():
    return get_reaction_model()


def test_penetration_gradient_is_the_loss_derivative(windows):
    actor, reactor = windows[0, 0, :5], windows[0, 1, :5].copy()
    # Pull the captured partner into the actor so spheres overlap.
    reactor += actor[:, sk.PELVIS:sk.PELVIS + 1] - reactor[:, sk.PELVIS:sk.PELVIS + 1]
    reactor[..., 2] += 0.1
    ra, rr = radii(actor), radii(reactor)
    loss, grad = penetration_loss(reactor, sphere_centres(actor), rr, ra)
    assert loss > 0
    rng = np.random.default_rng(0)
    for _ in range(5):
        t, j, k = rng.integers(5), rng.integers(22), rng.integers(3)
        e = np.zeros_like(reactor)
        e[t, j, k] = 1e-6
        up = penetration_loss(reactor + e, sphere_centres(actor), rr, ra)[0]
        down = penetration_loss(reactor - e, sphere_centres(actor), rr, ra)[0]
        assert (up - down) / 2e-6 == pytest.approx(grad[t, j, k], rel=1e-3, abs=1e-7)
    moved = guide(reactor, sphere_centres(actor), rr, ra, strength=1.0, iters=5)
    assert penetration_loss(moved, sphere_centres(actor), rr, ra)[0] < 0.2 * loss


def test_penetration_loss_equals_the_sphere_pair_sum(windows):
    """The matmul form gives the loss written out pair by pair (every window's captured pair,
    the partner pulled 20 cm towards the actor so spheres overlap)."""
    for actor, reactor in windows[:, :, ::8]:
        reactor = reactor + 0.2 * (actor[:, :1] - reactor[:, :1]) * np.array([1, 0, 1])
        ac, rc = sphere_centres(actor), sphere_centres(reactor)
        ra, rr = radii(actor), radii(reactor)
        gap = np.linalg.norm(rc[:, :, None] - ac[:, None], axis=-1) - rr[:, None] - ra[None]
        want = float(np.sum(np.maximum(0.06 - gap, 0.0) ** 2))
        assert penetration_loss(reactor, ac, rr, ra, 0.06)[0] == pytest.approx(want, rel=1e-9,
                                                                              abs=1e-15)


def test_no_gradient_beyond_the_safe_distance(windows):
    actor = windows[0, 0, :3]
    far = actor + np.array([3.0, 0.0, 0.0])
    loss, grad = penetration_loss(far, sphere_centres(actor), radii(far), radii(actor), 0.05)
    assert loss == 0 and not grad.any()


def test_online_steps_equal_window_sampling(model, windows):
    actor = windows[1, 0, :12]
    for guidance in (False, True):
        whole = sample_windows(model, actor[None], seed=4, guidance=guidance)[0]
        s = ReactionSession(model, seed=4, guidance=guidance)
        for f in actor:
            s.step(f)
        assert np.abs(s.raw() - whole).max() < 1e-4


def test_reactor_never_sees_the_future(model, windows):
    actor = np.concatenate([windows[2, 0], windows[3, 0]])[:60]    # longer than one window
    other = actor.copy()
    other[45:] = other[45:] + np.array([0.5, 0.0, 0.3])            # a different future
    a = react(actor, seed=1, guidance=True)
    b = react(other, seed=1, guidance=True)
    s1, s2 = ReactionSession(model, seed=1), ReactionSession(model, seed=1)
    first = [s1.step(f) for f in actor]
    second = [s2.step(f) for f in other]
    assert np.allclose(first[:45], second[:45])
    assert not np.allclose(first[45:], second[45:])
    # Whole-sequence fit: bones of one length for every frame.
    for out in (a, b):
        lengths = sk.bone_lengths(out)
        assert np.ptp(lengths, axis=0).max() < 1e-6
        assert np.isfinite(out).all() and out.shape == actor.shape


def test_guidance_lowers_penetration_on_held_out_pairs(model, windows):
    actor = windows[:12, 0]
    plain = sample_windows(model, actor, seed=0, guidance=False)
    guided = sample_windows(model, actor, seed=0, guidance=True)
    iv = [np.mean([clip_metrics([a, r])["intersection_volume"] for a, r in zip(actor, g)])
          for g in (plain, guided)]
    assert iv[1] < 0.5 * iv[0], iv


def test_seeds_and_stochastic_sampling(model, windows):
    actor = windows[0, 0, :10][None]
    cfg = SamplingConfig(eta=0.05)
    a = sample_windows(model, actor, seed=0, sampling=cfg)
    b = sample_windows(model, actor, seed=0, sampling=cfg)
    c = sample_windows(model, actor, seed=1, sampling=cfg)
    assert np.array_equal(a, b) and not np.allclose(a, c)


def test_bad_input(model):
    with pytest.raises(ValueError, match="22, 3"):
        react(np.zeros((5, 21, 3)), model=model)
    with pytest.raises(ValueError, match="finite"):
        ReactionSession(model).step(np.full((22, 3), np.nan))
    with pytest.raises(ValueError, match="sampling"):
        SamplingConfig(steps=0)


def test_cached_session_matches_the_full_graph(model, windows):
    from interplay.reaction.cached import CachedReactionSession
    from interplay.reaction.session import window_frame
    if model.step_session is None:
        pytest.skip("weights without arflow_step.onnx")
    actor = np.concatenate([windows[0, 0], windows[1, 0]])[:model.window + 8]
    plain, cached = ReactionSession(model, seed=6), CachedReactionSession(model, seed=6)
    for f in actor:
        plain.step(f)
        cached.step(f)
    w = model.window
    # Same anchor in the first window: the same computation.
    assert np.abs(plain.raw()[:w] - cached.raw()[:w]).max() < 1e-4
    # After the hop (unguided, so each step is the plain Euler step): the last frame's flow
    # states follow from the full graph on the cached session's own window (anchor … n),
    # fed the kept flow states of the earlier frames.
    s = CachedReactionSession(model, seed=6, guidance=False)
    for f in actor:
        s.step(f)
    n, anc, k_steps = len(actor) - 1, s.anchor, s.cfg.steps
    assert 0 < anc < n - 1
    rot, shift = window_frame(s.actor[anc])
    to_c = lambda p: p @ rot.T + shift                                   # noqa: E731
    a_n = model.normalize(to_c(np.stack(s.actor[anc:])))[None]
    for k in range(k_steps):
        xs = model.normalize(to_c(np.stack([st[k] for st in s.states[anc:]])))[None]
        x1 = model.predict(xs, np.array([k / k_steps]), a_n, s.text)[:, -1]
        t, tn = k / k_steps, (k + 1) / k_steps
        nxt = (1 - tn) * (xs[:, -1] - t * x1) / (1 - t) + tn * x1
        assert np.abs(nxt - model.normalize(to_c(s.states[n][k + 1]))[None]).max() < 1e-4
