"""Training budgets and learning-rate schedules. The machine is a shared 2-core CPU, so a
stage runs for a number of steps or of wall-clock seconds, whichever ends first (`Budget`);
`Schedule` adds SPAM's and CODA's learning rate over that budget, `warmup_cosine` is the
evaluators' (over steps), `History` records what a stage did and `optimizer_step` is the one
update every training loop makes."""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np
import torch


class Budget:
    """Steps or wall-clock seconds, whichever ends first; the clock starts at construction."""

    def __init__(self, steps: int, seconds: float):
        self.steps, self.seconds, self.start = steps, seconds, time.perf_counter()

    def elapsed(self) -> float:
        return time.perf_counter() - self.start

    def done(self, step: int) -> bool:
        return step >= self.steps or self.elapsed() >= self.seconds


class Schedule(Budget):
    """Budget and learning rate of one stage from a train config (steps, seconds, lr,
    warmup): linear warm-up over `warmup` steps times a cosine from lr to 10 % of it over the
    share of the budget spent (steps or seconds, whichever is further along)."""

    def __init__(self, cfg):
        super().__init__(cfg.steps, cfg.seconds)
        self.cfg = cfg

    def lr(self, step: int) -> float:
        frac = min(1.0, max(step / self.cfg.steps, self.elapsed() / self.cfg.seconds))
        warm = min(1.0, (step + 1) / self.cfg.warmup)
        return self.cfg.lr * warm * (0.1 + 0.45 * (1 + math.cos(math.pi * frac)))


def warmup_cosine(step: int, lr: float, warmup: int, total: int) -> float:
    """Linear warm-up over `warmup` steps, then a cosine from lr to 10 % of it at `total`."""
    if step < warmup:
        return lr * (step + 1) / warmup
    frac = min(1.0, (step - warmup) / max(1, total - warmup))
    return lr * (0.1 + 0.9 * 0.5 * (1 + math.cos(math.pi * frac)))


def optimizer_step(opt: torch.optim.Optimizer, lr: float, loss: torch.Tensor, params,
                   max_norm: float = 1.0) -> None:
    """One update at learning rate lr: gradients of loss, clipped to max_norm over params."""
    for g in opt.param_groups:
        g["lr"] = lr
    opt.zero_grad(set_to_none=True)
    loss.backward()
    torch.nn.utils.clip_grad_norm_(params, max_norm)
    opt.step()


@dataclass
class History:
    """What a stage did: per-log-step losses, steps run, seconds taken."""
    rows: list[dict] = field(default_factory=list)
    steps: int = 0
    seconds: float = 0.0

    def last(self, key: str, n: int = 5) -> float:
        vals = [r[key] for r in self.rows[-n:] if key in r]
        return float(np.mean(vals)) if vals else float("nan")
