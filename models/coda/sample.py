"""Iterative masked decoding (CODA §3.3, MaskGIT schedule) in torch — the reference for the
runtime's numpy loop and what picks the sampling defaults on the validation split.

Per step s = 0..S-1: logits = l_uncond + cfg · (l_cond − l_uncond) (text zeros = uncond),
divided by the temperature, restricted to the `topk` most likely codes, sampled at the masked
positions; confidence = probability of the sampled code (kept codes: +∞); then the
ceil(cos(π/2 · (s+1)/S) · 2n − 1e-6) least confident positions are masked again. Decoding the final
codes with decode.onnx runs the interaction-codebook residual (w = z + t).
"""

from __future__ import annotations

import math

import torch

from .cmt import CMT


@torch.no_grad()
def sample_codes(cmt: CMT, text: torch.Tensor, n: int, steps: int = 10, cfg: float = 2.0,
                 temperature: float = 1.0, topk: int = 51,
                 gen: torch.Generator | None = None) -> torch.Tensor:
    """Codes (B, 2, n) for prompt embeddings text (B, 384)."""
    cmt.eval()
    b, k, mask_id = text.shape[0], cmt.cfg.codes, cmt.cfg.mask_id
    codes = torch.full((b, 2 * n), mask_id, dtype=torch.long)
    null = torch.zeros_like(text)
    for s in range(steps):
        masked = codes == mask_id
        inp = codes.reshape(b, 2, n)
        if cfg != 1.0:
            both = cmt(torch.cat([inp, inp]), torch.cat([text, null])).reshape(2 * b, 2 * n, k)
            logits = both[b:] + cfg * (both[:b] - both[b:])
        else:
            logits = cmt(inp, text).reshape(b, 2 * n, k)
        logits = logits / max(temperature, 1e-4)
        if topk < k:
            kth = logits.topk(topk, -1).values[..., -1:]
            logits = logits.masked_fill(logits < kth, float("-inf"))
        probs = logits.softmax(-1)
        drawn = torch.multinomial(probs.reshape(-1, k), 1, generator=gen).reshape(b, 2 * n)
        conf = probs.gather(-1, drawn[..., None])[..., 0]
        codes = torch.where(masked, drawn, codes)
        conf = torch.where(masked, conf, torch.full_like(conf, float("inf")))
        remask = math.ceil(math.cos(math.pi / 2 * (s + 1) / steps) * 2 * n - 1e-6)  # 0 at the end
        if remask > 0:
            low = conf.argsort(-1)[:, :remask]
            codes = codes.scatter(1, low, mask_id)
    return codes.reshape(b, 2, n)
