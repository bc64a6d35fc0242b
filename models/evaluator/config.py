"""Frozen config of the evaluator (model sizes and the training budget).

Checkpoints store {"model": state_dict, "config": asdict(cfg)}; `export.load_checkpoint`
reads them back (`models.common.checkpoint`, strict: unknown keys are an error, missing keys
take the defaults)."""

from __future__ import annotations

from dataclasses import dataclass

FEATURE_DIM = 239          # interplay.motion.features.FEATURE_DIM
TEXT_DIM = 384             # MiniLM sentence embedding (interplay.text.encoder.DIM)


@dataclass(frozen=True)
class EvaluatorConfig:
    # motion encoder: patches of frames → transformer → masked mean pool → linear → unit vector
    feature_dim: int = FEATURE_DIM
    patch: int = 4                # frames per token (T is padded to a multiple)
    d_model: int = 128
    layers: int = 3
    heads: int = 4
    ff_mult: int = 2
    dropout: float = 0.1
    max_frames: int = 200         # 10 s at 20 fps; the runtime averages longer motions' chunks
    embed_dim: int = 256
    # text side: frozen MiniLM (384) → MLP → embed_dim
    text_dim: int = TEXT_DIM
    text_hidden: int = 512
    # InfoNCE
    temperature: float = 0.07
    fn_threshold: float = 0.8     # texts this similar (MiniLM cosine) are not each other's negatives
    # training data (train split only)
    min_frames: int = 40          # random windows of 2–10 s (shorter clips are taken whole)
    prompt_share: float = 0.5     # a window's text: the clip prompt, else an overlapping body caption
    mirror_prob: float = 0.5      # left/right mirrored joints and texts
    feature_noise: float = 0.05   # Gaussian noise on normalised features (std)
    # optimisation
    batch_size: int = 64
    steps: int = 3000
    seconds: float = 540.0        # wall-clock budget (stops at whichever comes first)
    lr: float = 5e-4
    warmup: int = 100
    weight_decay: float = 0.01
    eval_every: int = 50
    seed: int = 0
    threads: int = 1             # 2 threads thrash on the shared 2-core machine (1 is 2× faster)
