"""Penetration loss between a generated reactor and a given actor, with its analytic gradient
(numpy; the physical guidance of ARFlow §3.2).

Both bodies are the 45-sphere bodies of `interplay.motion.pair.body`. For every reactor sphere s
and actor sphere a in the same frame, the signed surface gap is g = |c_s − c_a| − r_s − r_a
(negative when they overlap); the loss penalises gaps below a safe distance δ:

    L = Σ_frames Σ_s Σ_a relu(δ − g)²

so the gradient is zero beyond δ (ARFlow's safe distance). Sphere centres are fixed linear
mixes of two joints (c = (1 − f)·p + f·child), so ∂L/∂joints = Mᵀ ∂L/∂c with the constant
(S, 22) mixing matrix M below: no network or decoder needs differentiating.

Distances come from |c|² + |a|² − 2·c·aᵀ and the centre gradient from Σ_a w·(c_s − c_a) =
c_s·Σ_a w − W·a: matmuls over (T, S, S) instead of a (T, S, S, 3) difference array (2–4× less
time, same values to 1e-12). A broad phase (per-part bounding spheres, only pairs of nearby
parts evaluated) was measured and dropped: at 45 × 45 spheres its own bookkeeping cost more
than the pairs it skipped (see docs/reaction.md).
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.pair.body import (
    SPHERE_CHILD,
    SPHERE_FRACTION,
    SPHERE_PARENT,
    SPHERE_RADII,
    body_scale,
)

NUM_SPHERES = len(SPHERE_RADII)
# c = MIX @ joints for one frame: (S, 22).
MIX = np.zeros((NUM_SPHERES, sk.NUM_JOINTS))
MIX[np.arange(NUM_SPHERES), SPHERE_PARENT] += 1.0 - SPHERE_FRACTION
MIX[np.arange(NUM_SPHERES), SPHERE_CHILD] += SPHERE_FRACTION


def sphere_centres(joints: np.ndarray) -> np.ndarray:
    """Centres (..., S, 3) of the sphere body of joints (..., 22, 3)."""
    return MIX @ joints                                                  # (S,22)@(...,22,3)


def radii(joints: np.ndarray | None = None, scale: float | None = None) -> np.ndarray:
    """Sphere radii (S,) for a person: the table's radii times `scale` (default: the
    person's body_scale from joints (T, 22, 3); 1 without joints)."""
    if scale is None:
        scale = body_scale(joints) if joints is not None else 1.0
    return SPHERE_RADII * float(scale)


class ActorSpheres:
    """What the loss needs of the actor, computed once per guided pose rather than per
    gradient step: centres (T, S, 3), their transpose and squared norms, and the reach
    δ + r_s + r_a (T, S, S) of every sphere pair."""

    def __init__(self, centres: np.ndarray, reactor_radii: np.ndarray | float,
                 actor_radii: np.ndarray | float, safe: float):
        t = centres.shape[0]
        if centres.shape != (t, NUM_SPHERES, 3):
            raise ValueError(f"actor sphere centres must be (T, {NUM_SPHERES}, 3), "
                             f"got {centres.shape}")
        rr = np.broadcast_to(reactor_radii, (t, NUM_SPHERES))
        ra = np.broadcast_to(actor_radii, (t, NUM_SPHERES))
        self.centres = centres
        self.centres_t = np.ascontiguousarray(centres.transpose(0, 2, 1))    # (T, 3, S)
        self.norms = np.einsum("tak,tak->ta", centres, centres)[:, None, :]  # (T, 1, S)
        self.reach = safe + rr[:, :, None] + ra[:, None, :]                  # (T, S, S)


def penetration_loss(reactor: np.ndarray, actor_centres: np.ndarray, reactor_radii: np.ndarray,
                     actor_radii: np.ndarray, safe: float = 0.02) -> tuple[float, np.ndarray]:
    """Loss L and gradient ∂L/∂reactor (T, 22, 3) for reactor joints (T, 22, 3) against the
    actor's sphere centres (T, S, 3) in the same frames, radii (S,) or per frame (T, S) each,
    safe distance δ (m)."""
    reactor = np.asarray(reactor, dtype=np.float64)
    if reactor.ndim != 3 or reactor.shape[1:] != (sk.NUM_JOINTS, 3):
        raise ValueError(f"reactor joints must be (T, 22, 3), got {reactor.shape}")
    if actor_centres.shape[0] != reactor.shape[0]:
        raise ValueError(f"actor sphere centres must be ({reactor.shape[0]}, {NUM_SPHERES}, 3), "
                         f"got {actor_centres.shape}")
    return _loss(reactor, ActorSpheres(actor_centres, reactor_radii, actor_radii, safe))


def _loss(reactor: np.ndarray, a: ActorSpheres) -> tuple[float, np.ndarray]:
    c = MIX @ reactor                                                    # (T, S, 3)
    # distances by |c|² + |a|² − 2 c·a (matmuls; no (T, S, S, 3) difference array)
    d2 = np.einsum("tsk,tsk->ts", c, c)[:, :, None] + a.norms - 2.0 * (c @ a.centres_t)
    dist = np.sqrt(np.maximum(d2, 0.0, out=d2), out=d2)                  # (T, S, S)
    viol = np.maximum(a.reach - dist, 0.0)
    flat = viol.ravel()
    loss = float(flat @ flat)
    if loss == 0.0:
        return loss, np.zeros_like(reactor)
    # dL/dc_s = Σ_a w_sa (c_s − c_a) with w = −2 viol / |c_s − c_a|
    near = dist.min() <= 1e-6            # a coincident pair has no direction (rounding ~1e-8 m)
    w = viol / np.maximum(dist, 1e-6)
    w *= -2.0                                                            # (T, S, S)
    grad_c = c * w.sum(axis=2)[..., None] - w @ a.centres                # (T, S, 3)
    if near:                                                             # push it along +Z
        grad_c[..., 2] += (-2.0 * viol * (dist <= 1e-6)).sum(axis=2)
    return loss, MIX.T @ grad_c


def guide(reactor: np.ndarray, actor_centres: np.ndarray, reactor_radii: np.ndarray | float,
          actor_radii: np.ndarray | float, strength: float, safe: float = 0.02, iters: int = 1,
          rigid: float = 0.0, spheres: ActorSpheres | None = None) -> np.ndarray:
    """The predicted clean reactor moved down the penetration gradient: `iters` steps of
    x ← x − (strength / iters)·(∇L + rigid·Σ_j ∇_j L), the second term the gradient with
    respect to a horizontal translation of the whole body, applied to every joint — with
    rigid > 0 the reactor steps back as a whole rather than bending away joint by joint
    (strength in metres per unit gradient). spheres: the actor's `ActorSpheres` when already
    built (then actor_centres and the radii are not read)."""
    x = np.asarray(reactor, dtype=np.float64).copy()
    actor = spheres or ActorSpheres(actor_centres, reactor_radii, actor_radii, safe)
    if x.ndim != 3 or x.shape[1:] != (sk.NUM_JOINTS, 3) or actor.centres.shape[0] != len(x):
        raise ValueError(f"reactor joints (T, 22, 3) and actor centres (T, S, 3) expected, got "
                         f"{x.shape} and {actor.centres.shape}")
    for _ in range(max(1, iters)):
        loss, grad = _loss(x, actor)
        if loss == 0.0:
            break
        if rigid > 0:
            shift = grad.sum(axis=1, keepdims=True)                      # (T, 1, 3)
            shift[..., 1] = 0.0                                          # stay on the floor
            grad = grad + rigid * shift
        x -= (strength / max(1, iters)) * grad
    return x
