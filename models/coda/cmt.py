"""CODA's Conditional Masked Transformer (§3.2): both people's pose tokens in one sequence of
2n tokens (person embedding; time enters as a learned relative-time bias, separate tables for
pairs within one person and across the two people), text conditioning added to every block
(the MiniLM vector projected to d; a learned null vector where the text is all zeros, the
classifier-free-guidance "unconditional" input), bidirectional attention, cross-entropy on
masked tokens.

  codes (B, 2, n) int64 with K = mask id, text (B, 384) → logits (B, 2, n, K)
"""

from __future__ import annotations

import torch
import torch.nn as nn

from .attention import RelAttention, rel_index
from .config import CMTConfig


class Block(nn.Module):
    def __init__(self, cfg: CMTConfig):
        super().__init__()
        self.ln_a, self.ln_m = nn.LayerNorm(cfg.d), nn.LayerNorm(cfg.d)
        self.att = RelAttention(cfg.d, cfg.heads, 2 * (2 * cfg.rel_range + 1), cfg.dropout)
        self.cond = nn.Linear(cfg.d, cfg.d)
        self.mlp = nn.Sequential(nn.Linear(cfg.d, cfg.ff * cfg.d), nn.GELU(),
                                 nn.Linear(cfg.ff * cfg.d, cfg.d), nn.Dropout(cfg.dropout))

    def forward(self, x, c, idx):
        x = x + self.cond(c)[:, None]
        h = self.ln_a(x)
        x = x + self.att(h, h, idx)
        return x + self.mlp(self.ln_m(x))


class CMT(nn.Module):
    def __init__(self, cfg: CMTConfig):
        super().__init__()
        self.cfg = cfg
        d = cfg.d
        self.tok_emb = nn.Embedding(cfg.codes + 1, d)
        self.person_emb = nn.Parameter(torch.randn(2, d) * 0.02)
        self.text_proj = nn.Linear(cfg.text_dim, d)
        self.null_text = nn.Parameter(torch.zeros(d))
        self.drop = nn.Dropout(cfg.dropout)
        self.blocks = nn.ModuleList(Block(cfg) for _ in range(cfg.blocks))
        self.ln_f = nn.LayerNorm(d)
        self.head = nn.Linear(d, cfg.codes)
        self.apply(_init)

    def bias_index(self, n: int, device=None) -> torch.Tensor:
        """(2n, 2n) bucket: relative time offset, + one table offset across the two people."""
        steps = torch.arange(n, device=device)
        t = torch.cat([steps, steps])
        person = torch.cat([torch.zeros(n, dtype=torch.long, device=device),
                            torch.ones(n, dtype=torch.long, device=device)])
        cross = (person[:, None] != person[None, :]).long()
        return rel_index(t, t, self.cfg.rel_range) + cross * (2 * self.cfg.rel_range + 1)

    def forward(self, codes: torch.Tensor, text: torch.Tensor) -> torch.Tensor:
        b, _, n = codes.shape
        x = self.tok_emb(codes) + self.person_emb[None, :, None]          # (B, 2, n, d)
        x = self.drop(x.reshape(b, 2 * n, -1))
        has = (text.abs().sum(-1, keepdim=True) > 0).to(x.dtype)           # (B, 1)
        c = has * self.text_proj(text) + (1 - has) * self.null_text        # (B, d)
        idx = self.bias_index(n, codes.device)
        for block in self.blocks:
            x = block(x, c, idx)
        return self.head(self.ln_f(x)).reshape(b, 2, n, -1)


def _init(m: nn.Module) -> None:
    if isinstance(m, (nn.Linear, nn.Embedding)):
        nn.init.normal_(m.weight, std=0.02)
        if isinstance(m, nn.Linear) and m.bias is not None:
            nn.init.zeros_(m.bias)
