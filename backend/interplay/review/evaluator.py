"""The text–motion evaluator at run time (numpy + onnxruntime, no torch): embeds motions and
texts into one 256-d space where a dot product is their cosine similarity.

Files (written by `python -m models.evaluator.export` into models/weights/evaluator/):
  motion_encoder.onnx  motion (B, T, 239) normalised features, mask (B, T) bool → embedding (B, 256)
  text_proj.npz        MLP over the frozen MiniLM embedding: fc1_w (384, H), fc1_b, fc2_w (H, 256), fc2_b
  normalizer.npz       feature mean/std of the training split (interplay.motion.features.Normalizer)
  config.json          max_frames, patch, embed_dim, …
  calibration.json     the reviewer's threshold and P(match | score) (`review.calibration`),
                       read at load into `.calibration`

    ev = EvaluatorRuntime.load()
    m = ev.embed_motion([joints])           # (1, 256) unit rows
    t = ev.embed_text(["a person walks"])   # (1, 256)
    ev.score(joints, "a person walks")      # cosine in [-1, 1]

Motions longer than the training windows (10 s) are cut into near-equal chunks whose embeddings
are averaged and renormalised.
"""

from __future__ import annotations

import json
import math
from functools import lru_cache
from pathlib import Path
from typing import Protocol, runtime_checkable

import numpy as np

from interplay.motion.features import FEATURE_DIM, Normalizer, encode
from interplay.review.calibration import Calibration, load_calibration
from interplay.settings import REPO_ROOT

DEFAULT_DIR = REPO_ROOT / "models" / "weights" / "evaluator"
FILES = ("motion_encoder.onnx", "text_proj.npz", "normalizer.npz", "config.json")
BATCH = 64


def chunks(frames: int, max_frames: int) -> list[tuple[int, int]]:
    """[start, end) ranges cutting `frames` into ceil(frames / max_frames) near-equal pieces."""
    if frames < 1 or max_frames < 1:
        raise ValueError(f"need frames >= 1 and max_frames >= 1, got {frames}, {max_frames}")
    bounds = np.linspace(0, frames, math.ceil(frames / max_frames) + 1).round().astype(int)
    return [(int(a), int(b)) for a, b in zip(bounds[:-1], bounds[1:])]


def open_weights(d: Path, what: str, package: str, threads: int = 1) -> tuple:
    """(onnxruntime session of motion_encoder.onnx, text_proj arrays, config.json) of an
    evaluator's weights directory (shared with the pair evaluator); FileNotFoundError naming
    the missing files and how to make them."""
    import onnxruntime as ort

    missing = [f for f in FILES if not (d / f).is_file()]
    if missing:
        raise FileNotFoundError(f"{d}: {what} files missing: {', '.join(missing)} "
                                f"(train and export it: python -m {package}.train, "
                                f"then python -m {package}.export)")
    opts = ort.SessionOptions()
    opts.intra_op_num_threads = threads
    opts.inter_op_num_threads = 1
    session = ort.InferenceSession(str(d / "motion_encoder.onnx"), sess_options=opts,
                                   providers=["CPUExecutionProvider"])
    with np.load(d / "text_proj.npz") as z:
        proj = {k: z[k] for k in z.files}
    return session, proj, json.loads((d / "config.json").read_text())


def _gelu(x: np.ndarray) -> np.ndarray:
    """torch's GELU(approximate="tanh")."""
    return 0.5 * x * (1.0 + np.tanh(math.sqrt(2.0 / math.pi) * (x + 0.044715 * x ** 3)))


def _unit(x: np.ndarray) -> np.ndarray:
    return (x / np.maximum(np.linalg.norm(x, axis=-1, keepdims=True), 1e-12)).astype(np.float32)


@runtime_checkable
class Evaluator(Protocol):
    """What the reviewer asks of a text–motion evaluator: how well joints (T, 22, 3) match a
    text, higher is better."""

    def score(self, joints: np.ndarray, text: str) -> float: ...


class EvaluatorRuntime:
    def __init__(self, session, text_proj: dict[str, np.ndarray], normalizer: Normalizer | None,
                 config: dict, text_encoder=None):
        self.session = session
        self.text_proj = {k: np.asarray(v, dtype=np.float32) for k, v in text_proj.items()}
        self.normalizer = normalizer
        self.config = config
        # The processed sources the weights were trained on (None: not recorded, all of them):
        # measurements made with this evaluator use only their clips.
        self.sources: tuple[str, ...] | None = (tuple(config["sources"]) if config.get("sources")
                                                else None)
        self.max_frames = int(config["max_frames"])
        self.patch = int(config["patch"])
        self.dim = int(config["embed_dim"])
        self._text_encoder = text_encoder
        # The threshold and P(match | score) measured on held-out captures for these weights
        # (`review.calibration`; None: not calibrated, the reviewer then has no threshold).
        self.calibration: Calibration | None = None

    @classmethod
    def load(cls, directory: str | Path = DEFAULT_DIR, threads: int = 1) -> "EvaluatorRuntime":
        d = Path(directory)
        session, proj, config = open_weights(d, "evaluator", "models.evaluator", threads)
        out = cls(session, proj, Normalizer.load(d / "normalizer.npz"), config)
        out.calibration = load_calibration(d)
        return out

    # -- motion ------------------------------------------------------------------------------
    def embed_features(self, features: list[np.ndarray]) -> np.ndarray:
        """Unit embeddings (N, dim) of raw (not normalised) feature arrays (T_i, 239)."""
        if self.normalizer is None:
            raise TypeError(f"{type(self).__name__} does not embed single-person features")
        pieces, owner = [], []                      # chunks of ≤ max_frames and whose they are
        for i, f in enumerate(features):
            f = np.asarray(f, dtype=np.float32)
            if f.ndim != 2 or f.shape[1] != FEATURE_DIM or len(f) < 1:
                raise ValueError(f"motion {i}: features must be (T >= 1, {FEATURE_DIM}), got {f.shape}")
            f = self.normalizer.normalize(f)
            for a, b in chunks(len(f), self.max_frames):
                pieces.append(f[a:b])
                owner.append(i)
        emb = np.zeros((len(pieces), self.dim), dtype=np.float32)
        order = np.argsort([len(p) for p in pieces], kind="stable")  # similar lengths per batch
        for s in range(0, len(order), BATCH):
            idx = order[s:s + BATCH]
            t = -(-max(len(pieces[k]) for k in idx) // self.patch) * self.patch
            x = np.zeros((len(idx), t, FEATURE_DIM), dtype=np.float32)
            mask = np.zeros((len(idx), t), dtype=bool)
            for row, k in enumerate(idx):
                x[row, :len(pieces[k])] = pieces[k]
                mask[row, :len(pieces[k])] = True
            (emb[idx],) = self.session.run(["embedding"], {"motion": x, "mask": mask})
        out = np.zeros((len(features), self.dim), dtype=np.float64)
        np.add.at(out, np.asarray(owner, dtype=int), emb)
        return _unit(out)

    def embed_motion(self, motions: list[np.ndarray]) -> np.ndarray:
        """Unit embeddings (N, dim) of single-person motions, each joints (T, 22, 3) at 20 fps."""
        if isinstance(motions, np.ndarray) and motions.ndim == 3:
            raise ValueError("embed_motion() takes a list of (T, 22, 3) arrays, not one array")
        return self.embed_features([encode(np.asarray(m, dtype=np.float64)) for m in motions])

    # -- text --------------------------------------------------------------------------------
    def project_text(self, minilm: np.ndarray) -> np.ndarray:
        """Unit embeddings (N, dim) from MiniLM embeddings (N, 384)."""
        p = self.text_proj
        h = _gelu(np.asarray(minilm, dtype=np.float32) @ p["fc1_w"] + p["fc1_b"])
        return _unit(h @ p["fc2_w"] + p["fc2_b"])

    def embed_text(self, texts: list[str]) -> np.ndarray:
        """Unit embeddings (N, dim) of texts."""
        if isinstance(texts, str):
            raise ValueError("embed_text() takes a list of strings, not a single string")
        if self._text_encoder is None:
            from interplay.text.encoder import get_encoder
            self._text_encoder = get_encoder()
        return self.project_text(self._text_encoder.encode(list(texts)))

    def score(self, joints: np.ndarray, text: str) -> float:
        """Cosine similarity in [-1, 1] between one motion (T, 22, 3) and a text."""
        return float(self.embed_motion([joints])[0] @ self.embed_text([text])[0])


@lru_cache(maxsize=2)
def _load(directory: str) -> EvaluatorRuntime:
    return EvaluatorRuntime.load(directory)


def load_evaluator(directory: str | Path | None = None) -> EvaluatorRuntime:
    """The evaluator from models/weights/evaluator (or `directory`), loaded once per process."""
    return _load(str(directory or DEFAULT_DIR))
