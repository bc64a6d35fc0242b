"""Checkpoints that carry their config: {"model": state_dict, "config": asdict(model.cfg),
**extra} (extra: e.g. "kind", which network of a package it is, or the step and loss it was
kept at). Every network takes one frozen config dataclass as `cfg`, so the file alone
rebuilds it; `config_from_dict` reads the config back, also from older checkpoints."""

from __future__ import annotations

from dataclasses import asdict, fields
from pathlib import Path

import torch
import torch.nn as nn


def config_from_dict(cls, d: dict, strict: bool = False):
    """A config dataclass `cls` from a checkpoint's dict: missing keys take the defaults,
    lists become tuples again; unknown keys are ignored (a checkpoint written before a field
    was dropped), or a ValueError when `strict`."""
    names = {f.name for f in fields(cls)}
    unknown = set(d) - names
    if unknown and strict:
        raise ValueError(f"unknown {cls.__name__} keys: {sorted(unknown)}")
    return cls(**{k: tuple(v) if isinstance(v, list) else v for k, v in d.items() if k in names})


def save(model: nn.Module, path: str | Path, **extra) -> None:
    """The model's weights and config (+ extra) at path; parent folders are made."""
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    torch.save({"model": model.state_dict(), "config": asdict(model.cfg), **extra}, path)


def restore(model_cls, cfg, state: dict) -> nn.Module:
    """model_cls(cfg) with the weights `state`, in eval mode."""
    model = model_cls(cfg)
    model.load_state_dict(state)
    return model.eval()


def load(path: str | Path, cfg_cls, model_cls, strict: bool = False,
         weights_only: bool = True) -> tuple[nn.Module, dict]:
    """(the network saved at path, in eval mode; the whole checkpoint dict).
    weights_only=False for checkpoints that also hold numpy arrays (the evaluators')."""
    ckpt = torch.load(path, map_location="cpu", weights_only=weights_only)
    return restore(model_cls, config_from_dict(cfg_cls, ckpt["config"], strict), ckpt["model"]), ckpt


def save_kind(model: nn.Module, path: str | Path, kinds: dict[str, tuple], **extra) -> None:
    """save() with "kind": the name under which `kinds` ({kind: (config class, model class)})
    lists the model's class."""
    kind = next(k for k, (_, model_cls) in kinds.items() if isinstance(model, model_cls))
    save(model, path, kind=kind, **extra)


def load_kind(path: str | Path, kinds: dict[str, tuple], what: str) -> nn.Module:
    """The network of a package with several (`kinds`, as in save_kind) saved at path."""
    ckpt = torch.load(path, map_location="cpu", weights_only=True)
    if ckpt.get("kind") not in kinds:
        raise ValueError(f"{path}: not a {what} checkpoint (kind={ckpt.get('kind')!r})")
    cfg_cls, model_cls = kinds[ckpt["kind"]]
    return restore(model_cls, config_from_dict(cfg_cls, ckpt["config"]), ckpt["model"])

