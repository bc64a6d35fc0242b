"""ARFlow network: x-prediction of the clean reaction from the flow state.

    x₀ = actor + σ·ε                    (actor's joints, normalised, plus a little noise)
    x_t = (1 − t)·x₀ + t·x₁             (x₁ = the reaction, t ∈ [0, 1])
    x̂₁ = f(x_t, t, actor, text)

f is a causal transformer decoder over frames: reactor token i self-attends to reactor tokens
≤ i and cross-attends to actor tokens ≤ i (the directional mask), so frame i never sees the
actor's future — the model runs online. Time and the optional intent (MiniLM embedding) are
projected to d and added to every reactor token (ARFlow appendix E).
"""

from __future__ import annotations

import math

import torch
import torch.nn.functional as F
from torch import nn

from .config import POSE_DIM, TEXT_DIM, ARFlowConfig


def time_embedding(t: torch.Tensor, dim: int) -> torch.Tensor:
    """Sinusoidal embedding (B, dim) of flow times t (B,) in [0, 1]."""
    half = dim // 2
    freqs = torch.exp(-math.log(10000.0) * torch.arange(half, dtype=torch.float32) / half)
    ang = (t[:, None] * 1000.0) * freqs[None]
    return torch.cat([torch.sin(ang), torch.cos(ang)], dim=1)


class Attention(nn.Module):
    """Multi-head attention with an additive mask (written out so the ONNX graph is plain)."""

    def __init__(self, d: int, heads: int):
        super().__init__()
        self.heads = heads
        self.q = nn.Linear(d, d)
        self.kv = nn.Linear(d, 2 * d)
        self.out = nn.Linear(d, d)

    def forward(self, x: torch.Tensor, mem: torch.Tensor, mask: torch.Tensor) -> torch.Tensor:
        b, t, d = x.shape
        h = self.heads
        q = self.q(x).view(b, t, h, d // h).transpose(1, 2)                  # (B, h, T, dh)
        k, v = self.kv(mem).view(b, -1, 2, h, d // h).permute(2, 0, 3, 1, 4)  # (B, h, S, dh)
        att = (q @ k.transpose(-1, -2)) / math.sqrt(d // h) + mask            # (B, h, T, S)
        y = att.softmax(dim=-1) @ v
        return self.out(y.transpose(1, 2).reshape(b, t, d))


class Block(nn.Module):
    """Pre-norm decoder layer: causal self-attention, causal cross-attention to the actor, MLP."""

    def __init__(self, cfg: ARFlowConfig):
        super().__init__()
        d = cfg.d_model
        self.n1, self.n2, self.n3, self.nm = (nn.LayerNorm(d) for _ in range(4))
        self.self_att = Attention(d, cfg.heads)
        self.cross_att = Attention(d, cfg.heads)
        self.mlp = nn.Sequential(nn.Linear(d, cfg.ff), nn.GELU(), nn.Linear(cfg.ff, d))
        self.drop = nn.Dropout(cfg.dropout)

    def forward(self, x, mem, mask):
        h = self.n1(x)
        x = x + self.drop(self.self_att(h, h, mask))
        x = x + self.drop(self.cross_att(self.n2(x), self.nm(mem), mask))
        return x + self.drop(self.mlp(self.n3(x)))


class ARFlow(nn.Module):
    def __init__(self, cfg: ARFlowConfig):
        super().__init__()
        self.cfg = cfg
        d = cfg.d_model
        self.pos = nn.Parameter(torch.randn(cfg.window, d) * 0.02)
        self.actor_in = nn.Sequential(nn.Linear(POSE_DIM, d), nn.GELU(), nn.Linear(d, d))
        self.state_in = nn.Linear(POSE_DIM, d)
        self.time_mlp = nn.Sequential(nn.Linear(d, d), nn.GELU(), nn.Linear(d, d))
        self.text_in = nn.Linear(TEXT_DIM, d) if cfg.text else None
        self.blocks = nn.ModuleList(Block(cfg) for _ in range(cfg.layers))
        self.norm = nn.LayerNorm(d)
        self.head = nn.Linear(d, POSE_DIM)

    def forward(self, x_t: torch.Tensor, t: torch.Tensor, actor: torch.Tensor,
                text: torch.Tensor) -> torch.Tensor:
        """x_t, actor (B, T, 66) normalised, t (B,), text (B, 384) (zeros: no prompt)
        → x̂₁ (B, T, 66), T ≤ cfg.window."""
        n = x_t.shape[1]
        pos = self.pos[:n]
        idx = torch.arange(n, device=x_t.device)
        mask = torch.where(idx[None, :] <= idx[:, None], 0.0, -1e9)           # (T, T) causal
        cond = self.time_mlp(time_embedding(t, self.cfg.d_model))
        if self.text_in is not None:
            cond = cond + self.text_in(text)
        x = self.state_in(x_t) + pos + cond[:, None]
        mem = self.actor_in(actor) + pos
        for blk in self.blocks:
            x = blk(x, mem, mask)
        return self.head(self.norm(x))


def flow_state(actor: torch.Tensor, reaction: torch.Tensor, t: torch.Tensor,
               noise: float, gen: torch.Generator | None = None) -> tuple[torch.Tensor, torch.Tensor]:
    """(x_t, x₀) for clean actor/reaction (B, T, 66) at times t (B,)."""
    x0 = actor + noise * torch.randn(actor.shape, generator=gen)
    tt = t[:, None, None]
    return (1 - tt) * x0 + tt * reaction, x0


def loss_terms(pred: torch.Tensor, target: torch.Tensor, mean: torch.Tensor, std: torch.Tensor,
               parents: torch.Tensor) -> dict[str, torch.Tensor]:
    """x-prediction loss (normalised MSE), velocity (frame-difference MSE, normalised) and bone
    length (metres², over all bones of the unnormalised joints)."""
    rec = F.mse_loss(pred, target)
    vel = F.mse_loss(pred[:, 1:] - pred[:, :-1], target[:, 1:] - target[:, :-1])
    pj = (pred * std + mean).view(*pred.shape[:2], 22, 3)
    tj = (target * std + mean).view(*target.shape[:2], 22, 3)
    child = torch.arange(1, 22)
    bl_p = (pj[:, :, child] - pj[:, :, parents[1:]]).norm(dim=-1)
    bl_t = (tj[:, :, child] - tj[:, :, parents[1:]]).norm(dim=-1)
    return {"rec": rec, "vel": vel, "bone": F.mse_loss(bl_p, bl_t)}


class ARFlowStep(nn.Module):
    """One new frame of `ARFlow` with cached keys/values (the online runtime's fast path).

    Inputs: x_t, actor (B, 1, 66) of the new frame, t (B,), text (B, 384), pos (1,) int64 its
    position in the window, past_k/past_v (layers, B, heads, P, dh) the self-attention
    keys/values of the P earlier frames at this flow step, mem_k/mem_v (layers, B, heads, P, dh)
    the cross-attention keys/values of the P earlier actor frames (these do not depend on
    the flow step). Outputs: x1 (B, 1, 66) and the new frame's four (layers, B, heads, 1, dh)
    entries to append. Equal to ARFlow's output at that frame (causal mask)."""

    def __init__(self, model: ARFlow):
        super().__init__()
        self.m = model

    def forward(self, x_t, t, actor, text, pos, past_k, past_v, mem_k, mem_v):
        m, cfg = self.m, self.m.cfg
        b, d, h = x_t.shape[0], cfg.d_model, cfg.heads
        p = m.pos[pos]                                                    # (1, d)
        cond = m.time_mlp(time_embedding(t, d))
        if m.text_in is not None:
            cond = cond + m.text_in(text)
        x = m.state_in(x_t) + p + cond[:, None]
        mem = m.actor_in(actor) + p
        outs = ([], [], [], [])
        for i, blk in enumerate(m.blocks):
            y = blk.n1(x)
            att = blk.self_att
            q = att.q(y).view(b, 1, h, d // h).transpose(1, 2)
            k, v = att.kv(y).view(b, 1, 2, h, d // h).permute(2, 0, 3, 1, 4)
            kk, vv = torch.cat([past_k[i], k], dim=2), torch.cat([past_v[i], v], dim=2)
            w = ((q @ kk.transpose(-1, -2)) / math.sqrt(d // h)).softmax(dim=-1)
            x = x + att.out((w @ vv).transpose(1, 2).reshape(b, 1, d))
            ca = blk.cross_att
            q = ca.q(blk.n2(x)).view(b, 1, h, d // h).transpose(1, 2)
            mk, mv = ca.kv(blk.nm(mem)).view(b, 1, 2, h, d // h).permute(2, 0, 3, 1, 4)
            mkk, mvv = torch.cat([mem_k[i], mk], dim=2), torch.cat([mem_v[i], mv], dim=2)
            w = ((q @ mkk.transpose(-1, -2)) / math.sqrt(d // h)).softmax(dim=-1)
            x = x + ca.out((w @ mvv).transpose(1, 2).reshape(b, 1, d))
            x = x + blk.mlp(blk.n3(x))
            for lst, val in zip(outs, (k, v, mk, mv)):
                lst.append(val)
        return (m.head(m.norm(x)),) + tuple(torch.stack(o) for o in outs)
