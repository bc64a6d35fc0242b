"""Attention with a learned relative-time bias (no absolute positions, so any sequence length
up to the export's max_tokens runs through the same weights). Written with plain matmul +
softmax so it exports to ONNX opset 17 unchanged."""

from __future__ import annotations

import torch
import torch.nn as nn


def rel_index(tq: torch.Tensor, tk: torch.Tensor, rel_range: int) -> torch.Tensor:
    """Bucket (Lq, Lk) int64 of the time offset tk - tq clipped to ±rel_range, shifted ≥ 0."""
    return (tk[None, :] - tq[:, None]).clamp(-rel_range, rel_range) + rel_range


class RelAttention(nn.Module):
    """Multi-head attention of queries x (B, Lq, d) over keys/values y (B, Lk, d); `bias_index`
    (Lq, Lk) int64 picks one learned per-head bias from `buckets` of them."""

    def __init__(self, d: int, heads: int, buckets: int, dropout: float = 0.0):
        super().__init__()
        self.heads, self.dropout = heads, dropout
        self.q, self.kv, self.proj = nn.Linear(d, d), nn.Linear(d, 2 * d), nn.Linear(d, d)
        self.bias = nn.Parameter(torch.zeros(heads, buckets))

    def forward(self, x: torch.Tensor, y: torch.Tensor, bias_index: torch.Tensor) -> torch.Tensor:
        b, lq, d = x.shape
        lk = y.shape[1]
        dh = d // self.heads
        q = self.q(x).reshape(b, lq, self.heads, dh).transpose(1, 2)          # (B, H, Lq, dh)
        k, v = self.kv(y).reshape(b, lk, 2, self.heads, dh).permute(2, 0, 3, 1, 4)
        att = q @ k.transpose(-1, -2) * dh ** -0.5 + self.bias[:, bias_index][None]
        att = att.softmax(-1)
        if self.training and self.dropout > 0:
            att = nn.functional.dropout(att, self.dropout)
        return self.proj((att @ v).transpose(1, 2).reshape(b, lq, d))
