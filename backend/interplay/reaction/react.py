"""The reaction stage's entry points: `open_session` (the cached one-frame session when the
weights have it, else the sliding-window one) and `react`, a whole reactor for a whole actor.

    session = open_session(prompt="shake hands", seed=3)
    for frame in actor:                       # (22, 3) each, world metres, 20 fps
        reactor_frame = session.step(frame)   # the reactor never sees the actor's future
    reactor = react(actor, prompt="shake hands", seed=3)     # (T, 22, 3)
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import fit_to_skeleton
from interplay.reaction.cached import CachedReactionSession
from interplay.reaction.session import ReactionModel, ReactionSession, SamplingConfig, get_reaction_model


def open_session(model=None, prompt: str | None = None, seed: int = 0, guidance: bool = True,
                 reproject: bool | None = None, sampling=None,
                 cache: bool = True) -> ReactionSession:
    """The cached session when the weights have the one-frame graph (and `cache`), else the
    sliding-window one."""
    model = model or get_reaction_model()
    cls = CachedReactionSession if cache and model.step_session is not None else ReactionSession
    return cls(model, prompt, seed, guidance, reproject, sampling)


def react(actor_joints: np.ndarray, prompt: str | None = None, seed: int = 0,
          guidance: bool = True, reproject: bool | None = None,
          model: ReactionModel | None = None, sampling: SamplingConfig | None = None,
          cache: bool = True) -> np.ndarray:
    """Reactor joints (T, 22, 3) for actor joints (T, 22, 3) (world, metres, 20 fps), generated
    online frame by frame (the reactor never sees the actor's future; the cached session when
    the weights have it), then fitted by IK → FK on fixed bone lengths over the whole
    sequence at once."""
    actor = np.asarray(actor_joints, dtype=np.float64)
    if actor.ndim != 3 or actor.shape[1:] != (sk.NUM_JOINTS, 3) or len(actor) == 0:
        raise ValueError(f"actor joints must be (T, 22, 3) with T ≥ 1, got {actor.shape}")
    session = open_session(model, prompt, seed, guidance, reproject, sampling, cache=cache)
    for f in actor:
        session.step(f)
    return fit_to_skeleton(session.raw(), session.offsets)[0]
