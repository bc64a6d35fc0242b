"""SPAM's spatially-aware masked transformers (CoMA §4.2.2, Fig. 4b; MoMask's base and
residual transformers with factorised space-time attention as in video transformers).

Tokens are laid out (B, 4 parts, n steps). Each part's sequence is prefixed by its text
token (the part's MiniLM embedding projected to d; a learned null token where cond = 0, for
classifier-free guidance), so a part sequence is L = n + 1 long. Every block runs
  spatial attention  over the 4 part tokens of one step  ((B·L, 4, d)),
  temporal attention over the L steps of one part         ((B·4, L, d)),
  an MLP,
all pre-norm and bidirectional (masked modelling: no causal mask).

Base model:     tokens (B, 4, n) with mask_id = K for masked        → logits (B, 4, n, K)
Residual model: tokens (B, 4, Q, n), layer j (B,) in 1..Q-1: embeds layers < j with one table
                per layer, sums them, adds a layer-j embedding       → logits of layer j (B, 4, n, K)
"""

from __future__ import annotations

import torch
import torch.nn as nn
import torch.nn.functional as F

from .config import PARTS, TransformerConfig


class Attention(nn.Module):
    def __init__(self, cfg: TransformerConfig):
        super().__init__()
        self.heads, self.dropout = cfg.heads, cfg.dropout
        self.qkv = nn.Linear(cfg.d, 3 * cfg.d)
        self.proj = nn.Linear(cfg.d, cfg.d)

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        """(N, L, d) → (N, L, d), full attention over L."""
        n, l, d = x.shape
        q, k, v = (t.reshape(n, l, self.heads, d // self.heads).transpose(1, 2)
                   for t in self.qkv(x).split(d, -1))
        y = F.scaled_dot_product_attention(q, k, v, dropout_p=self.dropout if self.training else 0.0)
        return self.proj(y.transpose(1, 2).reshape(n, l, d))


class Block(nn.Module):
    def __init__(self, cfg: TransformerConfig):
        super().__init__()
        self.ln_s, self.ln_t, self.ln_m = (nn.LayerNorm(cfg.d) for _ in range(3))
        self.spatial, self.temporal = Attention(cfg), Attention(cfg)
        self.mlp = nn.Sequential(nn.Linear(cfg.d, cfg.ff * cfg.d), nn.GELU(),
                                 nn.Linear(cfg.ff * cfg.d, cfg.d), nn.Dropout(cfg.dropout))

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        b, p, l, d = x.shape                                          # (B, 4, L, d)
        s = x.transpose(1, 2).reshape(b * l, p, d)                    # parts of one step
        x = x + self.spatial(self.ln_s(s)).reshape(b, l, p, d).transpose(1, 2)
        t = x.reshape(b * p, l, d)                                    # steps of one part
        x = x + self.temporal(self.ln_t(t)).reshape(b, p, l, d)
        return x + self.mlp(self.ln_m(x))


class SPAMTransformer(nn.Module):
    def __init__(self, cfg: TransformerConfig):
        super().__init__()
        self.cfg = cfg
        k, d = cfg.codes, cfg.d
        if cfg.residual:   # one input table per layer 0..Q-2, one output head per layer 1..Q-1
            self.tok_emb = nn.ModuleList(nn.Embedding(k, d) for _ in range(cfg.layers_q - 1))
            self.layer_emb = nn.Embedding(cfg.layers_q, d)
            self.head = nn.Parameter(torch.randn(cfg.layers_q - 1, k, d) * 0.02)
        else:              # K codes + the mask token
            self.tok_emb = nn.Embedding(k + 1, d)
            self.head = nn.Linear(d, k)
        self.text_proj = nn.Linear(cfg.text_dim, d)
        self.null_text = nn.Parameter(torch.zeros(d))
        self.part_emb = nn.Parameter(torch.randn(len(PARTS), d) * 0.02)
        self.pos_emb = nn.Parameter(torch.randn(cfg.max_tokens + 1, d) * 0.02)
        self.drop = nn.Dropout(cfg.dropout)
        self.blocks = nn.ModuleList(Block(cfg) for _ in range(cfg.blocks))
        self.ln_f = nn.LayerNorm(d)
        self.apply(_init)

    def _embed_tokens(self, tokens: torch.Tensor, layer: torch.Tensor | None) -> torch.Tensor:
        """Token embeddings (B, 4, n, d)."""
        if not self.cfg.residual:
            return self.tok_emb(tokens)
        # Layers >= j are ignored (they may hold anything, e.g. the mask id): clamp, then zero.
        safe = tokens.clamp(0, self.cfg.codes - 1)
        q = torch.arange(len(self.tok_emb), device=tokens.device)
        keep = (q[None] < layer[:, None]).to(self.null_text.dtype)    # (B, Q-1)
        emb = sum(table(safe[:, :, i]) * keep[:, i, None, None, None]
                  for i, table in enumerate(self.tok_emb))
        return emb + self.layer_emb(layer)[:, None, None, :]

    def forward(self, tokens: torch.Tensor, text: torch.Tensor, cond: torch.Tensor,
                layer: torch.Tensor | None = None) -> torch.Tensor:
        """tokens (B, 4, n) [base] or (B, 4, Q, n) [residual]; text (B, 4, text_dim);
        cond (B,) 1 = use text, 0 = unconditional; layer (B,) for the residual model.
        Returns logits (B, 4, n, K)."""
        x = self._embed_tokens(tokens, layer)                         # (B, 4, n, d)
        n = x.shape[2]
        c = cond.to(x.dtype)[:, None, None]
        txt = c * self.text_proj(text) + (1 - c) * self.null_text     # (B, 4, d)
        x = torch.cat([txt[:, :, None], x], 2)                        # (B, 4, n+1, d)
        x = x + self.pos_emb[: n + 1] + self.part_emb[:, None]
        x = self.drop(x)
        for block in self.blocks:
            x = block(x)
        h = self.ln_f(x[:, :, 1:])                                    # (B, 4, n, d)
        if not self.cfg.residual:
            return self.head(h)
        w = self.head[layer - 1]                                      # (B, K, d)
        return torch.einsum("bpnd,bkd->bpnk", h, w)


def _init(m: nn.Module) -> None:
    if isinstance(m, (nn.Linear, nn.Embedding)):
        nn.init.normal_(m.weight, std=0.02)
        if isinstance(m, nn.Linear) and m.bias is not None:
            nn.init.zeros_(m.bias)
