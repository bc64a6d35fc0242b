"""Symmetric InfoNCE (CLIP/TMR-style) over a batch of matched motion and text embeddings,
the loss of both evaluators (`models.evaluator`, `models.pair_evaluator`)."""

from __future__ import annotations

import torch
import torch.nn.functional as F


def info_nce(motion: torch.Tensor, text: torch.Tensor, not_negative: torch.Tensor,
             temperature: float, text_negatives: torch.Tensor | None = None) -> torch.Tensor:
    """Symmetric InfoNCE over matched (motion_i, text_i) unit embeddings (B, E).

    not_negative (B, B) bool marks off-diagonal pairs that must not count as negatives (same
    text or kind, or texts more similar than a false-negative threshold); they are dropped
    from both softmaxes. The diagonal (the positives) is always kept. text_negatives (K, E):
    motions that are extra negatives of every text, in the text → motion direction only
    (the pair evaluator's broken pairs)."""
    logits = motion @ text.T / temperature                             # (B, B): motion × text
    eye = torch.eye(len(logits), dtype=torch.bool, device=logits.device)
    logits = logits.masked_fill(not_negative & ~eye, float("-inf"))
    target = torch.arange(len(logits), device=logits.device)
    by_text = logits.T
    if text_negatives is not None:
        by_text = torch.cat([by_text, text @ text_negatives.T / temperature], dim=1)
    return 0.5 * (F.cross_entropy(logits, target) + F.cross_entropy(by_text, target))
