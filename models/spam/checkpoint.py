"""SPAM's checkpoints: `models.common.checkpoint`'s format with "kind" naming the network."""

from __future__ import annotations

from pathlib import Path

from models.common import checkpoint

from .config import TransformerConfig, VQConfig
from .transformer import SPAMTransformer
from .vqvae import RVQVAE

KINDS = {"vq": (VQConfig, RVQVAE), "transformer": (TransformerConfig, SPAMTransformer)}


def save(model: RVQVAE | SPAMTransformer, path: str | Path, **extra) -> None:
    checkpoint.save_kind(model, path, KINDS, **extra)


def load(path: str | Path) -> RVQVAE | SPAMTransformer:
    """The model saved at path, in eval mode."""
    return checkpoint.load_kind(path, KINDS, "SPAM")
