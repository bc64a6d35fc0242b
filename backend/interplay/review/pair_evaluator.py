"""The text ↔ two-person-motion evaluator at run time (numpy + onnxruntime, no torch): embeds
pair windows and texts into one space where a dot product is their cosine similarity, and the
Fréchet distance (FID) between two sets of pair embeddings.

Files (written by `python -m models.pair_evaluator.export` into models/weights/pair_evaluator/):
  motion_encoder.onnx  motion (B, T, 293) normalised pair features, mask (B, T) bool → (B, E)
  text_proj.npz        MLP over the frozen MiniLM embedding (as the single-person evaluator)
  normalizer.npz       mean, std (293,) of the train split's pair features
  config.json          max_frames, patch, embed_dim, feature_dim, …

    ev = PairEvaluator.load()
    m = ev.embed(windows)                  # windows (N, 2, L, 22, 3) joints, any world frame
    t = ev.embed_text(["two people hug each other"])
    interplay.eval.metrics.fid(m_real, m_generated)   # Fréchet distance of the two sets

Pair features per frame (`pair_features`): the window is moved rigidly so the first person's
pelvis starts at the XZ origin facing +Z with the floor at y = 0 (`pairs.canonical_window`),
then [first's joints (66), second's joints (66), both joints' velocities (2 × 66, m/s),
relative_root (4: the second's pelvis in the first's per-frame heading frame and the sin/cos
of their yaw difference), the 5 × 5 key-joint distance map (25)] = 293 numbers. Windows longer
than max_frames are cut into near-equal chunks (each canonicalised) whose embeddings are
averaged and renormalised.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import floor_height
from interplay.motion.pair.windows import canonical_window, distance_map, relative_root
from interplay.review.calibration import load_calibration
from interplay.review.evaluator import EvaluatorRuntime, _unit, chunks, open_weights
from interplay.settings import REPO_ROOT

DEFAULT_DIR = REPO_ROOT / "models" / "weights" / "pair_evaluator"
PAIR_FEATURE_DIM = 4 * sk.NUM_JOINTS * 3 + 4 + len(sk.KEY_JOINTS) ** 2      # 293
BATCH = 64


def check_windows(windows) -> np.ndarray:
    """(N, 2, L, 22, 3) finite float64 joints with L ≥ 2, or a ValueError saying what is wrong."""
    w = np.asarray(windows, dtype=np.float64)
    if w.ndim != 5 or w.shape[1] != 2 or w.shape[3:] != (sk.NUM_JOINTS, 3) or w.shape[2] < 2:
        raise ValueError(f"pair windows must be (N, 2, L >= 2, {sk.NUM_JOINTS}, 3), got {w.shape}")
    if not np.all(np.isfinite(w)):
        raise ValueError("pair windows contain NaN or infinite joints")
    return w


def pair_features(window: np.ndarray) -> np.ndarray:
    """Raw (not normalised) features (L, 293) of one pair window (2, L, 22, 3) (module doc)."""
    w = canonical_window(np.asarray(window, dtype=np.float64))
    w[..., 1] -= floor_height([w[0], w[1]])                              # any world height
    a, b = w[0], w[1]                                                    # (L, 22, 3)
    vel = np.diff(w, axis=1, prepend=w[:, :1]) * sk.FPS                  # (2, L, 22, 3)
    vel[:, 0] = vel[:, 1] if w.shape[1] > 1 else 0.0                     # first frame: next one's
    flat = lambda x: x.reshape(len(x), -1)                               # noqa: E731
    return np.concatenate([flat(a), flat(b), flat(vel[0]), flat(vel[1]), relative_root(a, b),
                           flat(distance_map(a, b, sk.KEY_JOINTS))], axis=1).astype(np.float32)


class PairEvaluator(EvaluatorRuntime):
    """Shares the text side (MiniLM → MLP) and the ONNX batching with the single-person
    evaluator; the motion side takes pair windows."""

    def __init__(self, session, text_proj, normalizer: dict[str, np.ndarray], config: dict,
                 text_encoder=None):
        super().__init__(session, text_proj, None, config, text_encoder)
        self.mean = np.asarray(normalizer["mean"], dtype=np.float32)
        self.std = np.asarray(normalizer["std"], dtype=np.float32)
        if self.mean.shape != (PAIR_FEATURE_DIM,) or int(config["feature_dim"]) != PAIR_FEATURE_DIM:
            raise ValueError(f"pair evaluator normalizer/config are not for {PAIR_FEATURE_DIM}-d "
                             f"pair features")

    @classmethod
    def load(cls, directory: str | Path | None = None, threads: int = 1) -> "PairEvaluator":
        d = Path(directory or DEFAULT_DIR)
        session, proj, config = open_weights(d, "pair evaluator", "models.pair_evaluator", threads)
        with np.load(d / "normalizer.npz") as z:
            norm = {"mean": z["mean"], "std": z["std"]}
        out = cls(session, proj, norm, config)
        out.calibration = load_calibration(d)
        return out

    def embed_pair_features(self, features: np.ndarray) -> np.ndarray:
        """Unit embeddings (N, E) of raw pair features (N, T, 293), T ≤ max_frames, all real
        frames (padded to the patch with masked frames)."""
        f = (np.asarray(features, dtype=np.float32) - self.mean) / self.std
        n, t = f.shape[:2]
        tp = -(-t // self.patch) * self.patch
        x = np.zeros((n, tp, PAIR_FEATURE_DIM), np.float32)
        x[:, :t] = f
        mask = np.zeros((n, tp), bool)
        mask[:, :t] = True
        out = [self.session.run(["embedding"], {"motion": x[i:i + BATCH], "mask": mask[i:i + BATCH]})[0]
               for i in range(0, n, BATCH)]
        return np.concatenate(out) if out else np.zeros((0, self.dim), np.float32)

    def embed(self, windows) -> np.ndarray:
        """Unit embeddings (N, E) float32 of pair windows (N, 2, L, 22, 3) at 20 fps (joints in
        metres, Y up, any world frame: each window is canonicalised). Deterministic."""
        w = check_windows(windows)
        total = np.zeros((len(w), self.dim), np.float64)
        for a, b in chunks(w.shape[2], self.max_frames):
            if b - a < 2:                                                # a 1-frame tail: skip
                continue
            feats = np.stack([pair_features(x[:, a:b]) for x in w]) if len(w) else \
                np.zeros((0, b - a, PAIR_FEATURE_DIM), np.float32)
            total += self.embed_pair_features(feats)
        return _unit(total)

    def embed_motion(self, motions):                                     # noqa: D102
        raise TypeError("PairEvaluator embeds pair windows: use embed(windows)")

    def score(self, window: np.ndarray, text: str) -> float:
        """Cosine in [-1, 1] between one pair window (2, L, 22, 3) and a text."""
        return float(self.embed(np.asarray(window)[None])[0] @ self.embed_text([text])[0])


_CACHE: dict[str, PairEvaluator] = {}


def load_pair_evaluator(directory: str | Path | None = None) -> PairEvaluator:
    """The pair evaluator from models/weights/pair_evaluator (or `directory`), once per process."""
    key = str(directory or DEFAULT_DIR)
    if key not in _CACHE:
        _CACHE[key] = PairEvaluator.load(key)
    return _CACHE[key]
