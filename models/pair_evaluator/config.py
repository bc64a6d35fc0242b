"""Frozen config of the pair evaluator (sizes, data, training budget).

The motion tower and text projection are the single-person evaluator's modules
(`models.evaluator.model`), which read only the size fields below, so this config is passed to
them directly. Checkpoints store {"model": state_dict, "config": asdict(cfg)};
`export.load_checkpoint` reads them back (`models.common.checkpoint`, strict: unknown keys are
an error, lists become tuples)."""

from __future__ import annotations

from dataclasses import dataclass

from interplay.review.pair_evaluator import PAIR_FEATURE_DIM

TEXT_DIM = 384             # MiniLM sentence embedding (interplay.text.encoder.DIM)


@dataclass(frozen=True)
class PairEvaluatorConfig:
    # motion encoder: pair features (T, 293) → patches of frames → transformer → unit vector
    feature_dim: int = PAIR_FEATURE_DIM
    patch: int = 4                # frames per token
    d_model: int = 96
    layers: int = 2
    heads: int = 4
    ff_mult: int = 2
    dropout: float = 0.1
    max_frames: int = 40          # 2 s; the runtime averages longer windows' chunks
    embed_dim: int = 32           # small: FID over ~100 test windows needs a stable covariance
    # text side: frozen MiniLM (384) → MLP → embed_dim
    text_dim: int = TEXT_DIM
    text_hidden: int = 256
    # InfoNCE; windows of the same interaction kind are not each other's negatives
    temperature: float = 0.1
    # training data (train split only): pair_windows of `window` frames every `stride`
    window: int = 40
    stride: int = 5
    min_frames: int = 20          # each batch is cropped to a random length in [min, window]
    feature_noise: float = 0.05   # Gaussian noise on normalised features (std)
    # broken pairs (second person displaced, time-shifted or swapped for another clip's)
    # are extra negatives of every text: the embedding must see whether two people belong together
    broken: int = 24              # broken windows per batch
    displace: tuple = (0.6, 1.5)  # metres, horizontal, random direction
    shift: tuple = (10, 30)       # frames the second person is moved in time
    # optimisation
    batch_size: int = 64
    steps: int = 4000
    seconds: float = 270.0        # wall-clock budget (stops at whichever comes first)
    lr: float = 1e-3
    warmup: int = 100
    weight_decay: float = 0.01
    eval_every: int = 100
    seed: int = 0
    threads: int = 1              # 2 threads thrash on the shared 2-core machine
