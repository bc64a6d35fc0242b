"""SPAM's spatially-aware residual VQ-VAE (CoMA §4.2.1, Fig. 4a; MoMask's RVQ-VAE per part).

Four part encoders read their own (overlapping, CoMA E.2) feature dims of a normalised motion
(B, T, 239); each part has its own residual quantizer stack (Q layers of K EMA codes); one
shared whole-body decoder reads the concatenated part latents and writes all 239 dims.
Temporal downsampling is 4: T frames ↔ n = T/4 tokens per part and layer.

With cfg.parts = False the same code is the single-codebook ablation: one encoder over all
dims, one quantizer stack, the decoder reading one latent.
"""

from __future__ import annotations

import math

import numpy as np
import torch
import torch.nn as nn
import torch.nn.functional as F

from interplay.motion.features import part_feature_mask

from .config import FEATURE_DIM, PARTS, VQConfig


class ResBlock(nn.Module):
    """Dilated conv residual block (T2M-GPT / MoMask): x + conv1(relu(conv3_dilated(relu(x))))."""

    def __init__(self, width: int, dilation: int):
        super().__init__()
        self.conv1 = nn.Conv1d(width, width, 3, padding=dilation, dilation=dilation)
        self.conv2 = nn.Conv1d(width, width, 1)

    def forward(self, x):
        return x + self.conv2(F.relu(self.conv1(F.relu(x))))


def _resnet(width: int, depth: int, reverse: bool = False) -> nn.Sequential:
    dilations = [3 ** i for i in range(depth)]
    return nn.Sequential(*(ResBlock(width, d) for d in (dilations[::-1] if reverse else dilations)))


class Encoder(nn.Module):
    """(B, C_in, T) → (B, latent, T / 4): conv in, two stride-2 stages with residual blocks."""

    def __init__(self, c_in: int, cfg: VQConfig):
        super().__init__()
        stages = int(math.log2(cfg.downsample))
        layers = [nn.Conv1d(c_in, cfg.width, 3, padding=1), nn.ReLU()]
        for _ in range(stages):
            layers += [nn.Conv1d(cfg.width, cfg.width, 4, stride=2, padding=1),
                       _resnet(cfg.width, cfg.depth)]
        layers.append(nn.Conv1d(cfg.width, cfg.latent, 3, padding=1))
        self.net = nn.Sequential(*layers)

    def forward(self, x):
        return self.net(x)


class Decoder(nn.Module):
    """(B, C_latent, n) → (B, 239, 4n): mirror of the encoder with nearest upsampling."""

    def __init__(self, c_in: int, cfg: VQConfig):
        super().__init__()
        stages = int(math.log2(cfg.downsample))
        layers = [nn.Conv1d(c_in, cfg.width, 3, padding=1), nn.ReLU()]
        for _ in range(stages):
            layers += [_resnet(cfg.width, cfg.depth, reverse=True),
                       nn.Upsample(scale_factor=2, mode="nearest"),
                       nn.Conv1d(cfg.width, cfg.width, 3, padding=1)]
        layers += [nn.Conv1d(cfg.width, cfg.width, 3, padding=1), nn.ReLU(),
                   nn.Conv1d(cfg.width, FEATURE_DIM, 3, padding=1)]
        self.net = nn.Sequential(*layers)

    def forward(self, x):
        return self.net(x)


class Quantizer(nn.Module):
    """One codebook (K, dim) updated by exponential moving averages (no gradient), with dead
    codes reset to random latents of the current batch (T2M-GPT). A code is dead when its EMA
    usage is below `dead_fraction` of the mean usage per code, so the rule does not depend on
    the batch size (T2M-GPT's absolute threshold of 1 is 1/8 of the mean with its 4096
    latents per batch; with our ~350 it was 0.7 of the mean, which measured as well as 1/8)."""

    def __init__(self, codes: int, dim: int, decay: float, dead_fraction: float):
        super().__init__()
        self.decay, self.dead_fraction = decay, dead_fraction
        self.register_buffer("codebook", torch.zeros(codes, dim))
        self.register_buffer("ema_sum", torch.zeros(codes, dim))
        self.register_buffer("ema_count", torch.ones(codes))
        self.register_buffer("initialised", torch.zeros((), dtype=torch.bool))

    def indices(self, x: torch.Tensor) -> torch.Tensor:
        """Nearest code (N,) int64 of latents (N, dim)."""
        dist = (x.pow(2).sum(-1, keepdim=True) - 2 * x @ self.codebook.t()
                + self.codebook.pow(2).sum(-1)[None])
        return dist.argmin(-1)

    @torch.no_grad()
    def _init(self, x: torch.Tensor) -> None:
        """Start from the data, not from zeros (first training batch)."""
        self.codebook.copy_(_sample(x, self.codebook.shape[0]))
        self.ema_sum.copy_(self.codebook)
        self.ema_count.fill_(1.0)
        self.initialised.fill_(True)

    @torch.no_grad()
    def _update(self, x: torch.Tensor, codes: torch.Tensor) -> None:
        k = self.codebook.shape[0]
        onehot = F.one_hot(codes, k).type(x.dtype)                    # (N, K)
        self.ema_count.mul_(self.decay).add_(onehot.sum(0), alpha=1 - self.decay)
        self.ema_sum.mul_(self.decay).add_(onehot.t() @ x, alpha=1 - self.decay)
        n = self.ema_count.sum()
        count = (self.ema_count + 1e-5) / (n + k * 1e-5) * n          # Laplace smoothing
        self.codebook.copy_(self.ema_sum / count[:, None])
        dead = self.ema_count < self.dead_fraction * x.shape[0] / k
        if dead.any():
            fresh = _sample(x, k)
            self.codebook[dead] = fresh[dead]
            self.ema_sum[dead] = fresh[dead]
            self.ema_count[dead] = 1.0

    def forward(self, x: torch.Tensor):
        """Latents (N, dim) → (straight-through quantised (N, dim), codes (N,), commitment)."""
        if self.training and not bool(self.initialised):
            self._init(x.detach())
        codes = self.indices(x.detach())
        q = self.codebook[codes].clone()       # before this batch's EMA update
        if self.training:
            self._update(x.detach(), codes)
        commit = F.mse_loss(x, q.detach())
        return x + (q - x).detach(), codes, commit


def _sample(x: torch.Tensor, k: int) -> torch.Tensor:
    """k random rows of x (N, dim) (with replacement when N < k), plus a little noise."""
    idx = torch.randint(0, x.shape[0], (k,), device=x.device)
    return x[idx] + 0.01 * x.std() * torch.randn(k, x.shape[1], device=x.device)


class ResidualVQ(nn.Module):
    """Q quantizers, each coding what the previous ones left (MoMask). During training the
    stack is cut at a random depth with probability `quantizer_dropout`."""

    def __init__(self, cfg: VQConfig):
        super().__init__()
        self.dropout = cfg.quantizer_dropout
        self.layers = nn.ModuleList(
            Quantizer(cfg.codes, cfg.latent, cfg.ema_decay, cfg.dead_fraction)
            for _ in range(cfg.layers))

    def forward(self, x: torch.Tensor):
        """(N, dim) → (quantised (N, dim), codes (N, Q) with -1 for dropped layers, commit)."""
        active = len(self.layers)
        if self.training and torch.rand(()) < self.dropout:
            active = int(torch.randint(1, active + 1, ()))
        residual, out, commit = x, torch.zeros_like(x), x.new_zeros(())
        codes = torch.full((x.shape[0], len(self.layers)), -1, dtype=torch.long, device=x.device)
        for q, layer in enumerate(self.layers[:active]):
            qx, codes[:, q], c = layer(residual)
            out = out + qx
            residual = residual - qx.detach()
            commit = commit + c
        return out, codes, commit

    def encode(self, x: torch.Tensor) -> torch.Tensor:
        """(N, dim) → codes (N, Q) int64, every layer."""
        residual, codes = x, []
        for layer in self.layers:
            c = layer.indices(residual)
            residual = residual - layer.codebook[c]
            codes.append(c)
        return torch.stack(codes, -1)

    def decode(self, codes: torch.Tensor) -> torch.Tensor:
        """codes (..., Q) → summed code vectors (..., dim)."""
        return sum(layer.codebook[codes[..., q]] for q, layer in enumerate(self.layers))


class RVQVAE(nn.Module):
    def __init__(self, cfg: VQConfig):
        super().__init__()
        self.cfg = cfg
        masks = [part_feature_mask(p) for p in PARTS] if cfg.parts else [np.ones(FEATURE_DIM, bool)]
        for s, m in enumerate(masks):   # which feature dims each stream reads
            self.register_buffer(f"dims{s}", torch.from_numpy(np.flatnonzero(m)), persistent=False)
        self.encoders = nn.ModuleList(Encoder(int(m.sum()), cfg) for m in masks)
        self.quantizers = nn.ModuleList(ResidualVQ(cfg) for _ in masks)
        self.decoder = Decoder(cfg.streams * cfg.latent, cfg)

    def _latents(self, x: torch.Tensor) -> list[torch.Tensor]:
        """Normalised motion (B, T, 239) → one (B, n, latent) per stream."""
        if x.shape[-1] != FEATURE_DIM:
            raise ValueError(f"motion must be (B, T, {FEATURE_DIM}), got {tuple(x.shape)}")
        return [enc(x[..., getattr(self, f"dims{s}")].transpose(1, 2)).transpose(1, 2)
                for s, enc in enumerate(self.encoders)]

    def _decode_latents(self, latents: list[torch.Tensor]) -> torch.Tensor:
        """Per-stream (B, n, latent) → motion (B, 4n, 239), through the shared decoder."""
        return self.decoder(torch.cat(latents, -1).transpose(1, 2)).transpose(1, 2)

    def forward(self, x: torch.Tensor):
        """Normalised motion (B, T, 239), T % 4 == 0 → (reconstruction (B, T, 239),
        commitment loss, codes (B, S, Q, n))."""
        quantised, codes, commit = [], [], x.new_zeros(())
        for lat, rvq in zip(self._latents(x), self.quantizers):
            b, n, d = lat.shape
            q, c, cl = rvq(lat.reshape(b * n, d))
            quantised.append(q.reshape(b, n, d))
            codes.append(c.reshape(b, n, -1).permute(0, 2, 1))
            commit = commit + cl
        return self._decode_latents(quantised), commit, torch.stack(codes, 1)

    def encode(self, x: torch.Tensor) -> torch.Tensor:
        """Normalised motion (B, T, 239) → codes (B, S, Q, T/4) int64."""
        out = []
        for lat, rvq in zip(self._latents(x), self.quantizers):
            b, n, d = lat.shape
            out.append(rvq.encode(lat.reshape(b * n, d)).reshape(b, n, -1).permute(0, 2, 1))
        return torch.stack(out, 1)

    def decode(self, codes: torch.Tensor) -> torch.Tensor:
        """codes (B, S, Q, n) int64 → normalised motion (B, 4n, 239)."""
        lat = [rvq.decode(codes[:, s].permute(0, 2, 1)) for s, rvq in enumerate(self.quantizers)]
        return self._decode_latents(lat)
