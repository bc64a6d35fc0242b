"""The one checkpoint format and loader: {"model": state_dict, "config": asdict(cfg), "kind"}."""

from __future__ import annotations

from dataclasses import asdict
from pathlib import Path

import torch

from .config import TransformerConfig, VQConfig, from_dict
from .transformer import SPAMTransformer
from .vqvae import RVQVAE

_KINDS = {"vq": (VQConfig, RVQVAE), "transformer": (TransformerConfig, SPAMTransformer)}


def save(model: RVQVAE | SPAMTransformer, path: str | Path, **extra) -> None:
    kind = "vq" if isinstance(model, RVQVAE) else "transformer"
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    torch.save({"model": model.state_dict(), "config": asdict(model.cfg), "kind": kind, **extra},
               path)


def load(path: str | Path) -> RVQVAE | SPAMTransformer:
    """The model saved at path, in eval mode."""
    ckpt = torch.load(path, map_location="cpu", weights_only=True)
    if ckpt.get("kind") not in _KINDS:
        raise ValueError(f"{path}: not a SPAM checkpoint (kind={ckpt.get('kind')!r})")
    cfg_cls, model_cls = _KINDS[ckpt["kind"]]
    model = model_cls(from_dict(cfg_cls, ckpt["config"]))
    model.load_state_dict(ckpt["model"])
    return model.eval()
