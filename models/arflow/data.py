"""Training pairs for ARFlow: (actor, reactor) windows of joints in the actor's first-frame
heading frame (`pair_windows`: both role orders, mirrored), flattened to (N, L, 66), the
MiniLM embedding of each window's clip prompt, and a per-dim mean/std shared by both people
(x₀ and x₁ must be normalised alike for the flow between them to be a straight line)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from interplay.motion.pair.windows import pair_windows
from models.common.sources import training_clips

from .config import POSE_DIM


@dataclass
class PairSet:
    actor: np.ndarray       # (N, L, 66) float32 metres, actor's first-frame heading frame
    reactor: np.ndarray     # (N, L, 66)
    text: np.ndarray        # (N, 384) prompt embedding
    synthetic: np.ndarray   # (N,) bool
    clip_ids: list[str]

    def __len__(self) -> int:
        return len(self.actor)


def pair_set(split: str, length: int, stride: int, mirror: bool = True, roles: str = "both",
             clips=None, encoder=None) -> PairSet:
    """Every pair window of `split` (train/val/test) from the processed set."""
    clips = [c for c in training_clips(clips=clips) if c.split == split and len(c.people) == 2]
    w = pair_windows(clips, length, stride, roles=roles, mirror=mirror)
    n = len(w)
    prompts = {c.id: c.prompt for c in clips}
    if encoder is None:
        from interplay.text.encoder import get_encoder
        encoder = get_encoder()
    uniq = sorted(set(w.clip_ids))
    table = dict(zip(uniq, encoder.encode([prompts[i] for i in uniq]))) if uniq else {}
    text = (np.stack([table[i] for i in w.clip_ids]).astype(np.float32) if n
            else np.zeros((0, 384), np.float32))
    return PairSet(w.joints[:, 0].reshape(n, length, POSE_DIM),
                   w.joints[:, 1].reshape(n, length, POSE_DIM), text, w.synthetic,
                   list(w.clip_ids))


def fit_stats(data: PairSet, min_std: float = 0.05) -> tuple[np.ndarray, np.ndarray]:
    """Mean and std (66,) over every frame of both people (std floored at min_std metres)."""
    both = np.concatenate([data.actor.reshape(-1, POSE_DIM), data.reactor.reshape(-1, POSE_DIM)])
    return (both.mean(axis=0).astype(np.float32),
            np.maximum(both.std(axis=0), min_std).astype(np.float32))


def save_stats(path: Path, mean: np.ndarray, std: np.ndarray, frames: int) -> None:
    np.savez(path, mean=mean, std=std, frames=frames)
