"""The evaluator's two towers (TMR-style, deterministic embeddings); the loss is
`models.common.contrastive.info_nce`.

  motion (B, T, 239) normalised features, mask (B, T) bool (True = a real frame), T a multiple
  of `patch` (pad with masked frames)
    → padding zeroed, patches of `patch` frames (a strided conv) to d_model tokens (5 per
      second at patch 4: 16× less attention than per frame, which a shared 2-core CPU needs)
      + sinusoidal positions; a token is real if any of its frames is
    → `layers` pre-norm transformer blocks (padding masked out of attention)
    → masked mean over frames → linear → embed_dim, L2-normalised
  text (B, 384) frozen MiniLM embedding → MLP (tanh-GELU, so numpy can replay it) → embed_dim,
    L2-normalised

A dot product of the two embeddings is their cosine similarity. Attention is written out (no
nn.MultiheadAttention fast paths) so the graph exports to ONNX with dynamic B and T.
"""

from __future__ import annotations

import math

import torch
import torch.nn as nn
import torch.nn.functional as F

from .config import EvaluatorConfig

MAX_POSITIONS = 1024   # sinusoid table length; the runtime feeds at most cfg.max_frames frames


def sinusoids(length: int, dim: int) -> torch.Tensor:
    """(length, dim) sinusoidal position codes (Vaswani et al.)."""
    pos = torch.arange(length, dtype=torch.float32)[:, None]
    freq = torch.exp(torch.arange(0, dim, 2, dtype=torch.float32) * (-math.log(10000.0) / dim))
    out = torch.zeros(length, dim)
    out[:, 0::2] = torch.sin(pos * freq)
    out[:, 1::2] = torch.cos(pos * freq)
    return out


class Block(nn.Module):
    """Pre-norm self-attention + MLP over frames."""

    def __init__(self, cfg: EvaluatorConfig):
        super().__init__()
        d = cfg.d_model
        if d % cfg.heads:
            raise ValueError(f"d_model {d} is not a multiple of heads {cfg.heads}")
        self.d, self.heads, self.scale = d, cfg.heads, 1.0 / math.sqrt(d // cfg.heads)
        self.ln1, self.ln2 = nn.LayerNorm(d), nn.LayerNorm(d)
        self.qkv = nn.Linear(d, 3 * d)
        self.proj = nn.Linear(d, d)
        self.mlp = nn.Sequential(nn.Linear(d, cfg.ff_mult * d), nn.GELU(approximate="tanh"),
                                 nn.Linear(cfg.ff_mult * d, d))
        self.drop = nn.Dropout(cfg.dropout)

    def forward(self, x: torch.Tensor, bias: torch.Tensor) -> torch.Tensor:
        """x (B, T, d); bias (B, 1, 1, T) added to attention logits (-1e9 at padding)."""
        b, t = x.shape[0], x.shape[1]
        d, h = self.d, self.heads
        q, k, v = self.qkv(self.ln1(x)).split(d, dim=-1)
        q, k, v = (z.reshape(b, t, h, d // h).transpose(1, 2) for z in (q, k, v))  # (B, H, T, d/H)
        att = (q @ k.transpose(-2, -1)) * self.scale + bias
        att = self.drop(att.softmax(dim=-1))
        y = (att @ v).transpose(1, 2).reshape(b, t, d)
        x = x + self.drop(self.proj(y))
        return x + self.drop(self.mlp(self.ln2(x)))


class MotionEncoder(nn.Module):
    def __init__(self, cfg: EvaluatorConfig):
        super().__init__()
        self.patch = cfg.patch
        self.inp = nn.Conv1d(cfg.feature_dim, cfg.d_model, kernel_size=cfg.patch, stride=cfg.patch)
        self.register_buffer("pos", sinusoids(MAX_POSITIONS, cfg.d_model), persistent=False)
        self.blocks = nn.ModuleList(Block(cfg) for _ in range(cfg.layers))
        self.ln = nn.LayerNorm(cfg.d_model)
        self.out = nn.Linear(cfg.d_model, cfg.embed_dim)
        self.drop = nn.Dropout(cfg.dropout)

    def forward(self, motion: torch.Tensor, mask: torch.Tensor) -> torch.Tensor:
        """Unit embeddings (B, embed_dim) of motion (B, T, F) with mask (B, T) bool."""
        b = motion.shape[0]
        frame_valid = mask.to(motion.dtype)
        x = self.inp((motion * frame_valid[..., None]).transpose(1, 2)).transpose(1, 2)  # (B, N, d)
        n = x.shape[1]
        x = self.drop(x + self.pos[:n])
        valid = frame_valid.reshape(b, n, self.patch).amax(dim=-1)    # (B, N) token is real
        bias = ((1.0 - valid) * -1e9)[:, None, None, :]                # (B, 1, 1, T)
        for block in self.blocks:
            x = block(x, bias)
        x = self.ln(x)
        pooled = (x * valid[..., None]).sum(dim=1) / valid.sum(dim=1, keepdim=True).clamp(min=1.0)
        return F.normalize(self.out(pooled), dim=-1)


class TextProjection(nn.Module):
    """Frozen MiniLM embedding (B, 384) → unit embedding (B, embed_dim)."""

    def __init__(self, cfg: EvaluatorConfig):
        super().__init__()
        self.fc1 = nn.Linear(cfg.text_dim, cfg.text_hidden)
        self.fc2 = nn.Linear(cfg.text_hidden, cfg.embed_dim)
        self.drop = nn.Dropout(cfg.dropout)

    def forward(self, text: torch.Tensor) -> torch.Tensor:
        h = self.drop(F.gelu(self.fc1(text), approximate="tanh"))
        return F.normalize(self.fc2(h), dim=-1)


class Evaluator(nn.Module):
    def __init__(self, cfg: EvaluatorConfig):
        super().__init__()
        self.cfg = cfg
        self.motion = MotionEncoder(cfg)
        self.text = TextProjection(cfg)
