"""Training loops of CODA: the CVQ-VAE on pair windows (eq. 3 + CCL), then the CMT on the
pose tokens of both people. Budgets are wall-clock seconds (the CPU is shared) or steps,
whichever ends first; learning rate: linear warm-up, cosine to 10 % (`models.common.schedule`,
as SPAM's).

  python -m models.coda --all [--scale S]           # everything CODA (part of make train)
  python -m models.coda --all --scale 0.1 --early   # a short run, "trained": false
"""

from __future__ import annotations

import math

import numpy as np
import torch
import torch.nn.functional as F

from models.common.schedule import History, Schedule, optimizer_step

from .ccl import ccl
from .cmt import CMT
from .config import CMTConfig, CVQConfig, LossConfig, TrainConfig
from .cvq import CVQVAE
from .data import PairTensors


class Joints(torch.nn.Module):
    """Normalised (B, T, 66) → metres (B, T, 22, 3) with the shared mean/std."""

    def __init__(self, mean: np.ndarray, std: np.ndarray):
        super().__init__()
        self.register_buffer("mean", torch.as_tensor(mean, dtype=torch.float32))
        self.register_buffer("std", torch.as_tensor(std, dtype=torch.float32))

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        return (x * self.std + self.mean).reshape(*x.shape[:2], 22, 3)


def cvq_loss(model: CVQVAE, loss_cfg: LossConfig, joints: Joints, xa, xb):
    """Eq. 3 (+ the commonsense decoder term) + CCL on one batch; (total, terms as floats)."""
    out = model(xa, xb)
    cfg = model.cfg
    recon = (F.l1_loss(out["rec_a"], xa) + F.l1_loss(out["rec_b"], xb)) / 2
    total = recon + cfg.alpha * out["commit_pose"] + cfg.beta * out["commit_inter"]
    terms = {"recon": recon, "commit": out["commit_pose"]}
    if cfg.ics:
        common = (F.l1_loss(out["com_a"], xa) + F.l1_loss(out["com_b"], xb)) / 2
        total = total + loss_cfg.w_common * common
        terms["common"] = common
    c, cterms = ccl(joints(out["rec_a"]), joints(out["rec_b"]), joints(xa), joints(xb), loss_cfg)
    terms.update(cterms)
    total = total + c
    terms["loss"] = total
    return total, {k: float(v.detach()) for k, v in terms.items()}


def train_cvq(cfg: CVQConfig, loss_cfg: LossConfig, tc: TrainConfig, data: PairTensors,
              joints: Joints, log=print, name: str = "cvq") -> tuple[CVQVAE, History]:
    torch.manual_seed(tc.seed)
    model = CVQVAE(cfg).train()
    params = list(model.parameters())
    opt = torch.optim.AdamW(params, lr=tc.lr, betas=(0.9, 0.99), weight_decay=0.0)
    gen = torch.Generator().manual_seed(tc.seed)
    sched, hist, step = Schedule(tc), History(), 0
    while not sched.done(step):
        idx = torch.randint(0, len(data), (tc.batch,), generator=gen)
        loss, terms = cvq_loss(model, loss_cfg, joints, data.a[idx], data.b[idx])
        optimizer_step(opt, sched.lr(step), loss, params)
        step += 1
        if step % tc.log_every == 0 or step == 1:
            hist.rows.append({"step": step, "t": round(sched.elapsed(), 1), **terms})
            log(f"[{name}] step {step} {sched.elapsed():.0f}s " +
                " ".join(f"{k} {v:.4f}" for k, v in terms.items()))
    hist.steps, hist.seconds = step, sched.elapsed()
    return model.eval(), hist


@torch.no_grad()
def encode_pairs(model: CVQVAE, data: PairTensors, batch: int = 256) -> torch.Tensor:
    """Pose codes (N, 2, n) of every pair window."""
    model.eval()
    out = [torch.stack([model.encode(data.a[i:i + batch]), model.encode(data.b[i:i + batch])], 1)
           for i in range(0, len(data), batch)]
    return torch.cat(out) if out else torch.zeros(0, 2, 0, dtype=torch.long)


def mask_tokens(codes: torch.Tensor, mask_id: int, gen: torch.Generator):
    """Cosine schedule (MaskGIT): ratio cos(π/2·r), r ~ U(0, 1), over the 2n tokens of each
    sample (at least one masked). Returns (inputs, mask (B, 2, n) bool)."""
    b = codes.shape[0]
    flat = codes.reshape(b, -1)
    ratio = torch.cos(math.pi / 2 * torch.rand(b, generator=gen))
    k = (ratio * flat.shape[1]).ceil().clamp(min=1)
    ranks = torch.rand(flat.shape, generator=gen).argsort(-1).argsort(-1)
    mask = ranks < k[:, None]
    return flat.masked_fill(mask, mask_id).reshape(codes.shape), mask.reshape(codes.shape)


def cmt_loss(model: CMT, codes, text, gen: torch.Generator, cond_drop: float = 0.0):
    """Cross-entropy on the masked tokens; (loss, accuracy)."""
    inputs, mask = mask_tokens(codes, model.cfg.mask_id, gen)
    if cond_drop > 0:
        keep = (torch.rand(len(text), generator=gen) >= cond_drop).float()[:, None]
        text = text * keep
    logits = model(inputs, text)
    loss = F.cross_entropy(logits[mask], codes[mask])
    acc = (logits[mask].argmax(-1) == codes[mask]).float().mean()
    return loss, acc


def train_cmt(cfg: CMTConfig, tc: TrainConfig, codes: torch.Tensor, text: torch.Tensor,
              log=print, name: str = "cmt") -> tuple[CMT, History]:
    torch.manual_seed(tc.seed)
    model = CMT(cfg).train()
    params = list(model.parameters())
    opt = torch.optim.AdamW(params, lr=tc.lr, betas=(0.9, 0.99), weight_decay=0.01)
    gen = torch.Generator().manual_seed(tc.seed)
    sched, hist, step = Schedule(tc), History(), 0
    while not sched.done(step):
        idx = torch.randint(0, len(codes), (tc.batch,), generator=gen)
        loss, acc = cmt_loss(model, codes[idx], text[idx], gen, tc.cond_drop)
        optimizer_step(opt, sched.lr(step), loss, params)
        step += 1
        if step % tc.log_every == 0 or step == 1:
            hist.rows.append({"step": step, "t": round(sched.elapsed(), 1), "ce": float(loss.detach()),
                              "acc": float(acc)})
            log(f"[{name}] step {step} {sched.elapsed():.0f}s ce {float(loss.detach()):.3f} "
                f"acc {float(acc):.3f}")
    hist.steps, hist.seconds = step, sched.elapsed()
    return model.eval(), hist


@torch.no_grad()
def evaluate_cmt(model: CMT, codes: torch.Tensor, text: torch.Tensor, repeats: int = 4) -> dict:
    """Masked-token CE and accuracy on held-out windows at fixed seeds (comparable runs)."""
    model.eval()
    gen = torch.Generator().manual_seed(7)
    ce, acc = [], []
    for _ in range(repeats):
        loss, a = cmt_loss(model, codes, text, gen)
        ce.append(float(loss))
        acc.append(float(a))
    return {"ce": float(np.mean(ce)), "acc": float(np.mean(acc))}
