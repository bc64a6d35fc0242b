"""Online ARFlow with cached keys/values: `CachedReactionSession.step` runs the one-frame graph
(`arflow_step.onnx`) once per flow step instead of the whole window.

Keys/values of earlier frames stay valid while the window's frame (the actor's heading at its
first frame) and positions stay put, so the window is re-anchored in hops rather than every
frame: frames anchor … n are in the window; when it holds `window` frames the anchor moves to
n − window/2 and the caches are rebuilt from the kept flow states of the frames still in it
(window/2 frames × steps one-frame calls, once every window/2 frames). Each frame therefore
sees the last window/2 … window − 1 earlier frames (the sliding-window session sees
window − 1). Within the first window both sessions compute the same thing (tested).
Cross-attention keys/values depend on the actor frames only, so one cache serves every flow
step; self-attention keys/values depend on the flow state, so there is one cache per step.
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.reaction.session import (
    ReactionSession,
    actor_spheres,
    fixed_bones,
    sampler_step,
    window_frame,
)

OUTPUTS = ["x1", "new_k", "new_v", "new_mem_k", "new_mem_v"]


class CachedReactionSession(ReactionSession):
    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        if self.model.step_session is None:
            raise ValueError("these ARFlow weights have no arflow_step.onnx (re-export them)")
        mc = self.model.config["model"]
        self.cache_shape = (mc["layers"], 1, mc["heads"], 0, mc["d_model"] // mc["heads"])
        self.anchor = 0
        self._reset_caches()

    def _reset_caches(self) -> None:
        empty = np.zeros(self.cache_shape, np.float32)
        self.mem = [empty, empty]
        self.kv = [[empty, empty] for _ in range(self.cfg.steps)]

    def _call(self, k: int, x_k: np.ndarray, t: float, a_n: np.ndarray, pos: int) -> list:
        """One-frame graph at flow step k: x̂₁ (1, 66) and the new cache entries."""
        step = self.model.step_session
        assert step is not None                   # __init__ refuses weights without it
        out = step.run(OUTPUTS, {
            "x_t": x_k[:, None].astype(np.float32), "t": np.array([t], np.float32),
            "actor": a_n[:, None].astype(np.float32), "text": self.text.astype(np.float32),
            "pos": np.array([pos], np.int64), "past_k": self.kv[k][0], "past_v": self.kv[k][1],
            "mem_k": self.mem[0], "mem_v": self.mem[1]})
        self.kv[k] = [np.concatenate([c, n], axis=3) for c, n in zip(self.kv[k], out[1:3])]
        return out

    def _reanchor(self, to_c) -> None:
        """Rebuild the caches for frames anchor … n − 1 in the new window frame."""
        m = self.model
        self._reset_caches()
        for pos, j in enumerate(range(self.anchor, len(self.states))):
            a_n = m.normalize(to_c(self.actor[j]))[None]
            for k in range(self.cfg.steps):
                out = self._call(k, m.normalize(to_c(self.states[j][k]))[None], k / self.cfg.steps,
                                 a_n, pos)
                if k == 0:
                    new_mem = out[3:5]
            self.mem = [np.concatenate([c, n], axis=3) for c, n in zip(self.mem, new_mem)]

    def step(self, actor_frame: np.ndarray) -> np.ndarray:
        frame = self._accept(actor_frame)
        m, cfg = self.model, self.cfg
        n = len(self.actor) - 1
        moved = n - self.anchor >= m.window
        if moved:
            self.anchor = n - m.window // 2
        rot, shift = window_frame(self.actor[self.anchor])
        to_c = lambda p: p @ rot.T + shift                               # noqa: E731
        to_w = lambda p: (p - shift) @ rot                               # noqa: E731
        if moved:
            self._reanchor(to_c)
        actor_c = to_c(frame)[None]                                      # (1, 22, 3)
        a_n = m.normalize(actor_c)                                       # (1, 66)
        x0 = (a_n + m.noise * self.rng.standard_normal(a_n.shape[1])).astype(np.float32)
        states = np.empty((cfg.steps + 1, sk.NUM_JOINTS, 3))
        states[0] = to_w(m.denormalize(x0[0]))
        x_k, pos = x0, n - self.anchor
        spheres = actor_spheres(actor_c, self.scales, cfg)              # once for all steps
        for k in range(cfg.steps):
            t, t_next = k / cfg.steps, (k + 1) / cfg.steps
            out = self._call(k, x_k, t, a_n, pos)
            if k == 0:
                new_mem = out[3:5]
            x_k = sampler_step(m, x_k, x0, out[0][:, 0], t, t_next, actor_c, self.scales, cfg,
                               self.reproject, self.rng, spheres)
            states[k + 1] = to_w(m.denormalize(x_k[0]))
        self.mem = [np.concatenate([c, nw], axis=3) for c, nw in zip(self.mem, new_mem)]
        self.states.append(states)
        if self.offsets is None:
            from interplay.motion.kinematics import fit_offsets
            self.offsets = fit_offsets(states[-1][None])
            self.lengths = np.linalg.norm(self.offsets, axis=1)
        return fixed_bones(states[-1], self.lengths)
