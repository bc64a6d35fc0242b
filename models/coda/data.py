"""Pair windows for CODA: `models.arflow.data.pair_set` (both role orders; train mirrored) at
80 frames (4 s), joints in the first person's first-frame heading frame, one mean/std (66,)
shared by both people (`fit_stats`), and the MiniLM embedding of each window's clip prompt."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import torch

from models.arflow.data import PairSet, fit_stats, pair_set

from .config import WINDOW

STRIDE = {"train": 10, "val": 20, "test": 20}   # frames between window starts


@dataclass
class PairTensors:
    a: torch.Tensor          # (N, T, 66) normalised joints, first person
    b: torch.Tensor          # (N, T, 66) second person
    text: torch.Tensor       # (N, 384)
    synthetic: np.ndarray    # (N,) bool
    clip_ids: list[str]

    def __len__(self) -> int:
        return len(self.a)

    def take(self, idx) -> "PairTensors":
        idx = np.asarray(idx)
        return PairTensors(self.a[idx], self.b[idx], self.text[idx], self.synthetic[idx],
                           [self.clip_ids[i] for i in idx])


def load_pairs(split: str, window: int = WINDOW, roles: str = "both") -> PairSet:
    """Pair windows of one split (train mirrored, val/test not)."""
    return pair_set(split, window, STRIDE[split], mirror=split == "train", roles=roles)


def tensors(ps: PairSet, mean: np.ndarray, std: np.ndarray) -> PairTensors:
    return PairTensors(torch.from_numpy((ps.actor - mean) / std).float(),
                       torch.from_numpy((ps.reactor - mean) / std).float(),
                       torch.from_numpy(ps.text).float(), np.asarray(ps.synthetic),
                       list(ps.clip_ids))


def load_all(window: int = WINDOW) -> tuple[dict[str, PairTensors], np.ndarray, np.ndarray]:
    """Train/val/test tensors and the normaliser (mean, std) fitted on train."""
    sets = {s: load_pairs(s, window) for s in ("train", "val", "test")}
    mean, std = fit_stats(sets["train"])
    return {s: tensors(p, mean, std) for s, p in sets.items()}, mean, std
