"""ARFlow reaction runtime (numpy + onnxruntime): generate a reactor for a given actor.

The exported graph (models/arflow/export.py) predicts the clean reaction x̂₁ from the flow state
x_t at time t, the actor and an optional intent embedding; frame i depends on frames ≤ i only.
Sampling is ARFlow's x-prediction Euler scheme in `steps` steps, written as reprojection:

    x̂₀ = (x_t − t·x̂₁) / (1 − t)                       (the start the prediction implies)
    x̂₁ ← x̂₁ − w·∇L_pen(x̂₁)                            (physical guidance on the clean pose)
    x̃₀ = γ·x̂₀ + (1 − γ)·x₀   (+ η·ε, optional)          (reprojection towards the real start)
    x_{t'} = (1 − t')·x̃₀ + t'·x̂₁

γ = 1 without reprojection is exactly the plain Euler step x_t + (t' − t)(x̂₁ − x_t)/(1 − t).
The flow starts at x₀ = actor + σ·ε (normalised joints in the actor's heading frame at the first
frame of the window), so the reactor is generated in the actor's frame and mapped back.

Online (`ReactionSession.step`; `reaction_cache.CachedReactionSession` is the fast variant
with cached keys/values): each arriving actor frame runs the `steps` graph calls over a
sliding window of the last `window` frames; the flow states of the earlier frames at every
step are kept (in world coordinates, so the window's frame can move with the actor), so a
frame never changes once emitted and never sees a future actor frame. Within the first window
this equals sampling the whole window at once (`sample_windows`), which the tests check.
Output frames are put on fixed bone lengths by IK → FK (`kinematics.fit_to_skeleton`).
"""

from __future__ import annotations

import json
from dataclasses import dataclass, replace
from functools import lru_cache
from pathlib import Path

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import facing_angle, fit_offsets
from interplay.motion.rotations import yaw_matrix
from interplay.reaction.penetration import ActorSpheres, guide, radii, sphere_centres
from interplay.settings import REPO_ROOT

WEIGHTS_DIR = REPO_ROOT / "models" / "weights" / "arflow"
INPUTS = ("x_t", "t", "actor", "text")
GUIDE_CHUNK = 512          # frames per vectorised guidance call


@dataclass(frozen=True)
class SamplingConfig:
    steps: int = 5
    guidance: float = 0.3         # w: metres per unit penetration gradient (0 = off)
    safe_distance: float = 0.06   # δ (m): gaps beyond it give no gradient
    guidance_iters: int = 2       # gradient steps per sampling step
    rigid: float = 0.6            # weight of the whole-body (translation) gradient
    gamma: float = 0.5            # reprojection weight on the predicted start x̂₀
    eta: float = 0.0              # stochastic strength (diversity)

    def __post_init__(self):
        if self.steps < 1 or not 0.0 <= self.gamma <= 1.0 or self.guidance < 0 or self.eta < 0:
            raise ValueError(f"bad sampling config: {self}")


class ReactionModel:
    """The ONNX graph, normalizer and config of one weights directory (build once)."""

    def __init__(self, weights_dir: Path = WEIGHTS_DIR, threads: int = 1):
        import onnxruntime as ort

        weights_dir = Path(weights_dir)
        if not (weights_dir / "arflow.onnx").exists():
            raise FileNotFoundError(f"no ARFlow weights in {weights_dir} (run `make train`)")
        self.config = json.loads((weights_dir / "config.json").read_text())
        with np.load(weights_dir / "normalizer.npz") as z:
            self.mean, self.std = z["mean"].astype(np.float32), z["std"].astype(np.float32)
        if self.mean.shape != (sk.NUM_JOINTS * 3,):
            raise ValueError(f"{weights_dir}: normalizer is not for 22 × 3 joints")
        self.window = int(self.config["window"])
        self.noise = float(self.config["noise"])
        self.sampling = SamplingConfig(**{k: v for k, v in self.config.get("sampling", {}).items()
                                          if k in SamplingConfig.__dataclass_fields__})
        opts = ort.SessionOptions()
        opts.intra_op_num_threads = threads
        opts.inter_op_num_threads = 1
        self.session = ort.InferenceSession(str(weights_dir / "arflow.onnx"), sess_options=opts,
                                            providers=["CPUExecutionProvider"])
        names = tuple(i.name for i in self.session.get_inputs())
        if names != INPUTS:
            raise ValueError(f"{weights_dir}/arflow.onnx has inputs {names}, expected {INPUTS}")
        # The one-frame graph with cached keys/values (online fast path), when exported.
        step = weights_dir / "arflow_step.onnx"
        self.step_session = (ort.InferenceSession(str(step), sess_options=opts,
                                                  providers=["CPUExecutionProvider"])
                             if step.exists() else None)

    def normalize(self, joints: np.ndarray) -> np.ndarray:
        """(..., 22, 3) metres → (..., 66) normalised."""
        return ((joints.reshape(*joints.shape[:-2], -1) - self.mean) / self.std).astype(np.float32)

    def denormalize(self, x: np.ndarray) -> np.ndarray:
        return (x * self.std + self.mean).reshape(*x.shape[:-1], sk.NUM_JOINTS, 3).astype(np.float64)

    def predict(self, x_t: np.ndarray, t: np.ndarray, actor: np.ndarray, text: np.ndarray) -> np.ndarray:
        """x̂₁ (B, T, 66) from normalised x_t, actor (B, T, 66), t (B,), text (B, 384)."""
        return self.session.run(["x1"], {"x_t": x_t.astype(np.float32), "t": t.astype(np.float32),
                                         "actor": actor.astype(np.float32),
                                         "text": text.astype(np.float32)})[0]


@lru_cache(maxsize=2)
def get_reaction_model(weights_dir: str = str(WEIGHTS_DIR)) -> ReactionModel:
    return ReactionModel(Path(weights_dir))


def prompt_embedding(prompt: str | None) -> np.ndarray:
    """MiniLM embedding (384,) of the intent prompt; zeros without one (trained with dropout)."""
    if not prompt or not prompt.strip():
        return np.zeros(384, np.float32)
    from interplay.text.encoder import get_encoder
    return get_encoder().encode([prompt])[0].astype(np.float32)


def window_frame(actor_first: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(rot (3, 3), shift (3,)) taking world points to the heading frame of the actor's pose
    (22, 3): pelvis at the XZ origin facing +Z, heights kept (as pairs.canonical_window)."""
    rot = yaw_matrix(-facing_angle(actor_first))
    shift = -(rot @ actor_first[sk.PELVIS])
    shift[1] = 0.0
    return rot, shift


def sampler_step(model: ReactionModel, x_k: np.ndarray, x0: np.ndarray, x1: np.ndarray,
                 t: float, t_next: float, actor_c: np.ndarray, scales,
                 cfg: SamplingConfig, reproject: bool, rng: np.random.Generator,
                 spheres: ActorSpheres | None = None) -> np.ndarray:
    """One flow step for frames (..., 66) normalised: x_k the state, x0 the start, x1 the
    predicted clean reaction, actor_c (..., 22, 3) the actor in the same (canonical) frame,
    scales the (actor, reactor) radius scales: one pair or one per frame (F, 2). spheres:
    the actor's `actor_spheres` for all these frames, when the caller keeps them across flow
    steps (the online sessions: one frame, five steps)."""
    if cfg.guidance > 0 and spheres is not None:
        pose = guide(model.denormalize(x1).reshape(-1, sk.NUM_JOINTS, 3), spheres.centres, 0.0,
                     0.0, cfg.guidance, cfg.safe_distance, cfg.guidance_iters, cfg.rigid, spheres)
        x1 = model.normalize(pose.reshape(*x1.shape[:-1], sk.NUM_JOINTS, 3))
    elif cfg.guidance > 0:
        lead = x1.shape[:-1]
        pose = model.denormalize(x1).reshape(-1, sk.NUM_JOINTS, 3)
        act = actor_c.reshape(-1, sk.NUM_JOINTS, 3)
        s = np.broadcast_to(np.asarray(scales, dtype=np.float64).reshape(-1, 2),
                            (len(pose), 2))                              # per frame (a, r)
        for i in range(0, len(pose), GUIDE_CHUNK):                       # bounded memory
            sl = slice(i, i + GUIDE_CHUNK)
            pose[sl] = guide(pose[sl], sphere_centres(act[sl]), radii(scale=1.0) * s[sl, 1:2],
                             radii(scale=1.0) * s[sl, 0:1], cfg.guidance, cfg.safe_distance,
                             cfg.guidance_iters, cfg.rigid)
        x1 = model.normalize(pose.reshape(*lead, sk.NUM_JOINTS, 3))
    x0_hat = (x_k - t * x1) / (1.0 - t)
    x0_t = cfg.gamma * x0_hat + (1.0 - cfg.gamma) * x0 if reproject else x0_hat
    if cfg.eta > 0:
        x0_t = x0_t + cfg.eta * rng.standard_normal(x0_t.shape)
    return ((1.0 - t_next) * x0_t + t_next * x1).astype(np.float32)


def actor_spheres(actor_c: np.ndarray, scales, cfg: SamplingConfig) -> ActorSpheres | None:
    """The guidance's view of actor frames (F, 22, 3) with radius scales (actor, reactor),
    built once per arriving frame by the sessions; None without guidance."""
    if cfg.guidance <= 0:
        return None
    return ActorSpheres(sphere_centres(actor_c), radii(scale=1.0) * scales[1],
                        radii(scale=1.0) * scales[0], cfg.safe_distance)


def sample_windows(model: ReactionModel, actor: np.ndarray, text: np.ndarray | None = None,
                   seed: int = 0, guidance: bool = True, reproject: bool | None = None,
                   sampling: SamplingConfig | None = None, batch: int = 64) -> np.ndarray:
    """Reactors (N, T, 22, 3) for actor windows (N, T, 22, 3) already in the actor's
    first-frame heading frame (T ≤ window), all frames at once (offline / evaluation)."""
    actor = np.asarray(actor, dtype=np.float64)
    n, frames = actor.shape[:2]
    if actor.shape[2:] != (sk.NUM_JOINTS, 3) or frames > model.window:
        raise ValueError(f"actor windows must be (N, ≤{model.window}, 22, 3), got {actor.shape}")
    cfg = sampling or model.sampling
    cfg = cfg if guidance else replace(cfg, guidance=0.0)
    reproject = guidance if reproject is None else reproject
    text = np.zeros((n, 384), np.float32) if text is None else np.broadcast_to(text, (n, 384))
    rng = np.random.default_rng(seed)
    a_n = model.normalize(actor)
    x0 = (a_n + model.noise * rng.standard_normal(a_n.shape)).astype(np.float32)
    scales = np.array([_scales(a) for a in actor] if cfg.guidance > 0 else [(1.0, 1.0)] * n)
    frame_scales = np.repeat(scales, frames, axis=0)                     # (N·T, 2)
    x = x0
    for k in range(cfg.steps):
        t, t_next = k / cfg.steps, (k + 1) / cfg.steps
        x1 = np.concatenate([model.predict(x[i:i + batch], np.full(len(x[i:i + batch]), t),
                                           a_n[i:i + batch], text[i:i + batch])
                             for i in range(0, n, batch)])
        x = sampler_step(model, x, x0, x1, t, t_next, actor, frame_scales, cfg, reproject, rng)
    return model.denormalize(x)


def _scales(actor: np.ndarray) -> tuple[float, float]:
    """(actor, reactor) radius scales: the actor's build for both (the reactor's bones are
    not known before it is generated; the pairs' people are of similar build)."""
    from interplay.motion.pair.body import body_scale
    s = body_scale(actor)
    return s, s


class ReactionSession:
    """Online reaction: feed actor frames (22, 3) one at a time, get reactor frames back."""

    def __init__(self, model: ReactionModel | None = None, prompt: str | None = None,
                 seed: int = 0, guidance: bool = True, reproject: bool | None = None,
                 sampling: SamplingConfig | None = None, offsets: np.ndarray | None = None):
        self.model = model or get_reaction_model()
        cfg = sampling or self.model.sampling
        self.cfg = cfg if guidance else replace(cfg, guidance=0.0)
        self.reproject = guidance if reproject is None else reproject
        self.text = prompt_embedding(prompt)[None]
        self.rng = np.random.default_rng(seed)
        self.offsets = offsets
        self.actor: list[np.ndarray] = []      # world (22, 3) per frame
        self.states: list[np.ndarray] = []     # world (steps + 1, 22, 3) flow states per frame
        self.scales: tuple[float, float] | None = None

    def _accept(self, actor_frame: np.ndarray) -> np.ndarray:
        """Check and keep the next actor frame (22, 3) (world); the radius scales come from the
        first one. Shared by the cached session."""
        frame = np.asarray(actor_frame, dtype=np.float64)
        if frame.shape != (sk.NUM_JOINTS, 3) or not np.all(np.isfinite(frame)):
            raise ValueError(f"actor frame must be finite (22, 3), got {frame.shape}")
        self.actor.append(frame)
        if self.scales is None:
            self.scales = _scales(frame[None])
        return frame

    def step(self, actor_frame: np.ndarray) -> np.ndarray:
        """The reactor's frame (22, 3) for the next actor frame (22, 3), world coordinates."""
        self._accept(actor_frame)
        m, cfg = self.model, self.cfg
        lo = max(0, len(self.actor) - m.window)
        rot, shift = window_frame(self.actor[lo])
        to_c = lambda p: p @ rot.T + shift                               # noqa: E731
        to_w = lambda p: (p - shift) @ rot                               # noqa: E731
        actor_c = to_c(np.stack(self.actor[lo:]))                        # (w, 22, 3)
        a_n = m.normalize(actor_c)[None]                                  # (1, w, 66)
        x0 = (a_n[:, -1] + m.noise * self.rng.standard_normal(a_n.shape[2])).astype(np.float32)
        states = np.empty((cfg.steps + 1, sk.NUM_JOINTS, 3))
        states[0] = to_w(m.denormalize(x0[0]))
        past = np.stack(self.states[lo:]) if len(self.states) > lo else None   # (w−1, K+1, 22, 3)
        spheres = actor_spheres(actor_c[-1:], self.scales, cfg)
        x_k = x0
        for k in range(cfg.steps):
            t, t_next = k / cfg.steps, (k + 1) / cfg.steps
            xs = x_k[:, None] if past is None else np.concatenate(
                [m.normalize(to_c(past[:, k]))[None], x_k[:, None]], axis=1)
            x1 = m.predict(xs, np.array([t]), a_n, self.text)[:, -1]      # (1, 66)
            x_k = sampler_step(m, x_k, x0, x1, t, t_next, actor_c[-1:], self.scales, cfg,
                               self.reproject, self.rng, spheres)
            states[k + 1] = to_w(m.denormalize(x_k[0]))
        self.states.append(states)
        if self.offsets is None:
            self.offsets = fit_offsets(states[-1][None])
            self.lengths = np.linalg.norm(self.offsets, axis=1)
        return fixed_bones(states[-1], self.lengths)

    def raw(self) -> np.ndarray:
        """The sampled reactor so far (T, 22, 3) before the bone-length fit."""
        return np.stack([s[-1] for s in self.states])


# _CHAIN[j, k] = 1 when bone k (joint k to its parent) lies on the path from the root to joint j.
_CHAIN = np.zeros((sk.NUM_JOINTS, sk.NUM_JOINTS))
for _j in range(1, sk.NUM_JOINTS):
    _CHAIN[_j] = _CHAIN[sk.PARENTS[_j]]
    _CHAIN[_j, _j] = 1.0
_PARENT_INDEX = np.array([max(int(p), 0) for p in sk.PARENTS])


def fixed_bones(pose: np.ndarray, lengths: np.ndarray) -> np.ndarray:
    """A pose (22, 3) with every bone set to its length (22,) along its predicted direction
    (a per-frame FK that keeps the sampled bone directions: the root plus the sum of the
    scaled bone directions down each chain, one matmul; a one-frame IK → FK fit takes tens
    of ms)."""
    d = pose - pose[_PARENT_INDEX]                                       # (22, 3); root row 0
    norm = np.maximum(np.sqrt(np.einsum("jk,jk->j", d, d)), 1e-9)
    return pose[0] + _CHAIN @ (d * (lengths / norm)[:, None])
