"""CODA's CVQ-VAE with the Interactive Codebook Storager (ICS, §3.1 eq. 1–3).

  x_p (B, T, 66) ─φ (shared conv encoder)→ t̃_p (B, n, d') ─C (pose codebook)→ t_p
  z̃_p = ψ(t_p)          self-attention over one person's steps (ψ shared by a and b: the data
                         holds both role orders, so the roles are symmetric)
  ž_a = φ_x(z̃_a, z̃_b)  cross-attention to the other person (and ž_b = φ_x(z̃_b, z̃_a))
  z_p = P(ž_p)          interaction codebook;  w_p = z_p + t_p  (eq. 2)
  m̂_p = φ̂(w_p)          pose decoder → (B, T, 66);  ẑ_p = φ̃(z_p) commonsense decoder
  n = T / 4. With cfg.ics = False (ablation "single codebook"): m̂_p = φ̂(t_p), no ψ/φ_x/P/φ̃.

The commonsense decoder's target: eq. 3 writes ‖z_p − ẑ_p‖₁; we read it as φ̃ reconstructing
the person's motion from the interaction codes alone (L1 to m_p), which makes P store what of
each person's motion is predictable from the pair. Both codebooks: EMA + dead-code reset.
"""

from __future__ import annotations

import math

import torch
import torch.nn as nn

from models.spam.vqvae import Encoder, Quantizer, _resnet

from .attention import RelAttention, rel_index
from .config import POSE_DIM, CVQConfig


class Decoder(nn.Module):
    """(B, latent, n) → (B, 66, 4n): convs with residual blocks and nearest upsampling."""

    def __init__(self, cfg: CVQConfig, width: int | None = None):
        super().__init__()
        w = width or cfg.width
        layers = [nn.Conv1d(cfg.latent, w, 3, padding=1), nn.ReLU()]
        for _ in range(int(math.log2(cfg.downsample))):
            layers += [_resnet(w, cfg.depth, reverse=True),
                       nn.Upsample(scale_factor=2, mode="nearest"), nn.Conv1d(w, w, 3, padding=1)]
        layers += [nn.Conv1d(w, w, 3, padding=1), nn.ReLU(), nn.Conv1d(w, POSE_DIM, 3, padding=1)]
        self.net = nn.Sequential(*layers)

    def forward(self, x):
        return self.net(x)


class ICS(nn.Module):
    """ψ (self-attention) then φ_x (cross-attention), pre-norm residual, plus an MLP; the
    attention bias depends on the time offset only (same step of the other person = 0)."""

    def __init__(self, cfg: CVQConfig):
        super().__init__()
        d, buckets = cfg.latent, 2 * cfg.rel_range + 1
        self.rel_range = cfg.rel_range
        self.ln_s, self.ln_x, self.ln_m, self.ln_o = (nn.LayerNorm(d) for _ in range(4))
        self.self_att = RelAttention(d, cfg.heads, buckets)
        self.cross_att = RelAttention(d, cfg.heads, buckets)
        self.mlp = nn.Sequential(nn.Linear(d, 2 * d), nn.GELU(), nn.Linear(2 * d, d))

    def forward(self, ta: torch.Tensor, tb: torch.Tensor) -> tuple[torch.Tensor, torch.Tensor]:
        """Quantised pose latents (B, n, d') each → pre-quantisation interaction latents ž."""
        steps = torch.arange(ta.shape[1], device=ta.device)
        idx = rel_index(steps, steps, self.rel_range)
        both = torch.cat([ta, tb], 0)                                   # (2B, n, d): a then b
        h = self.ln_s(both)
        z = both + self.self_att(h, h, idx)                             # ψ
        other = torch.cat([z[ta.shape[0]:], z[:ta.shape[0]]], 0)        # b then a
        z = z + self.cross_att(self.ln_x(z), self.ln_x(other), idx)    # φ_x
        z = self.ln_o(z + self.mlp(self.ln_m(z)))
        return z[:ta.shape[0]], z[ta.shape[0]:]


class CVQVAE(nn.Module):
    def __init__(self, cfg: CVQConfig):
        super().__init__()
        self.cfg = cfg
        self.encoder = Encoder(POSE_DIM, cfg)
        self.pose_q = Quantizer(cfg.codes, cfg.latent, cfg.ema_decay, cfg.dead_fraction)
        self.decoder = Decoder(cfg)
        if cfg.ics:
            self.ics = ICS(cfg)
            self.inter_q = Quantizer(cfg.interaction_codes, cfg.latent, cfg.ema_decay,
                                     cfg.dead_fraction)
            self.common_decoder = Decoder(cfg, width=cfg.width // 2)

    def latents(self, x: torch.Tensor) -> torch.Tensor:
        """Normalised joints (B, T, 66), T % 4 == 0 → t̃ (B, n, d')."""
        if x.shape[-1] != POSE_DIM:
            raise ValueError(f"joints must be (B, T, {POSE_DIM}), got {tuple(x.shape)}")
        return self.encoder(x.transpose(1, 2)).transpose(1, 2)

    def _quantise(self, q: Quantizer, lat: torch.Tensor):
        b, n, d = lat.shape
        out, codes, commit = q(lat.reshape(b * n, d))
        return out.reshape(b, n, d), codes.reshape(b, n), commit

    def _decode(self, dec: Decoder, w: torch.Tensor) -> torch.Tensor:
        return dec(w.transpose(1, 2)).transpose(1, 2)

    def forward(self, xa: torch.Tensor, xb: torch.Tensor) -> dict[str, torch.Tensor]:
        """Both people (B, T, 66) → reconstructions rec_a/rec_b (B, T, 66), commonsense
        reconstructions com_a/com_b (ICS only), commit_pose, commit_inter, codes (B, 2, n)."""
        b = xa.shape[0]
        t, codes, commit = self._quantise(self.pose_q, self.latents(torch.cat([xa, xb], 0)))
        out = {"codes": torch.stack([codes[:b], codes[b:]], 1), "commit_pose": commit}
        if not self.cfg.ics:
            rec = self._decode(self.decoder, t)
            out["commit_inter"] = commit.new_zeros(())
        else:
            za, zb = self.ics(t[:b], t[b:])
            z, icodes, icommit = self._quantise(self.inter_q, torch.cat([za, zb], 0))
            rec = self._decode(self.decoder, z + t)                     # w = z + t (eq. 2)
            com = self._decode(self.common_decoder, z)
            out.update(commit_inter=icommit, com_a=com[:b], com_b=com[b:],
                       inter_codes=torch.stack([icodes[:b], icodes[b:]], 1))
        out["rec_a"], out["rec_b"] = rec[:b], rec[b:]
        return out

    def encode(self, x: torch.Tensor) -> torch.Tensor:
        """One person's normalised joints (B, T, 66) → pose codes (B, T/4) int64."""
        lat = self.latents(x)
        b, n, d = lat.shape
        return self.pose_q.indices(lat.reshape(b * n, d)).reshape(b, n)

    def decode(self, codes_a: torch.Tensor, codes_b: torch.Tensor) -> tuple[torch.Tensor, torch.Tensor]:
        """Pose codes (B, n) per person → normalised joints (B, 4n, 66) each, through the ICS and
        the interaction codebook (nearest code, as in training's forward pass)."""
        b = codes_a.shape[0]
        t = self.pose_q.codebook[torch.cat([codes_a, codes_b], 0)]      # (2B, n, d')
        if self.cfg.ics:
            za, zb = self.ics(t[:b], t[b:])
            z = torch.cat([za, zb], 0)
            n, d = z.shape[1], z.shape[2]
            z = self.inter_q.codebook[self.inter_q.indices(z.reshape(-1, d))].reshape(-1, n, d)
            t = z + t
        rec = self._decode(self.decoder, t)
        return rec[:b], rec[b:]
