"""Training loops of SPAM: the RVQ-VAE on feature windows, then the base and residual masked
transformers on the VQ's token tracks. Every stage is budgeted by wall-clock seconds (the
machine is a shared 2-core CPU) and by steps, whichever ends first; the learning rate warms up
linearly and then follows a cosine to 10% over the budget.

Budgets, schedule and the stage record are `models.common.schedule`'s (CODA's too).
`python -m models.spam --all` runs every stage (`models/spam/pipeline.py`).
"""

from __future__ import annotations

import math

import numpy as np
import torch
import torch.nn.functional as F

from interplay.motion.features import Normalizer
from models.common.schedule import History, Schedule, optimizer_step

from .config import PARTS, LossConfig, TrainConfig, TransformerConfig, VQConfig
from .data import TextBank, Track, part_texts, sample_windows
from .losses import MotionLoss
from .transformer import SPAMTransformer
from .vqvae import RVQVAE

VQ_WINDOWS = (24, 40, 64)     # frames; most clips are 1–3 s, so windows vary per batch


def _optimiser(model: torch.nn.Module, lr: float) -> torch.optim.Optimizer:
    return torch.optim.AdamW([p for p in model.parameters() if p.requires_grad], lr=lr,
                             betas=(0.9, 0.99), weight_decay=0.0)


def _log(hist: History, step: int, sched: Schedule, terms: dict, log, name: str, every: int):
    row = {"step": step, "t": round(sched.elapsed(), 1)}
    row.update({k: float(v.detach()) if torch.is_tensor(v) else float(v) for k, v in terms.items()})
    hist.rows.append(row)
    if log and step % every == 0:
        log(f"[{name}] step {step} t={row['t']}s " + " ".join(
            f"{k}={v:.4f}" for k, v in row.items() if k not in ("step", "t")))


def train_vq(cfg: VQConfig, loss_cfg: LossConfig, tc: TrainConfig, tracks: list[Track],
             normalizer: Normalizer, log=print, name: str = "vq") -> tuple[RVQVAE, History]:
    torch.manual_seed(tc.seed)
    rng = np.random.default_rng(tc.seed)
    train = [t for t in tracks if t.split == "train"]
    feats = [normalizer.normalize(t.features) for t in train]
    windows = [w for w in VQ_WINDOWS if any(len(f) >= w for f in feats)] or [min(map(len, feats))
                                                                              // 4 * 4]
    model, crit = RVQVAE(cfg).train(), MotionLoss(loss_cfg, normalizer)
    opt, sched, hist, step = _optimiser(model, tc.lr), Schedule(tc), History(), 0
    while not sched.done(step):
        length = int(rng.choice(windows))
        picks = sample_windows(train, rng, tc.batch, length)
        x = torch.from_numpy(np.stack([feats[i][s:s + length] for i, s in picks]))
        recon, commit, codes = model(x)
        terms = crit(recon, x, commit, cfg.beta)
        optimizer_step(opt, sched.lr(step), terms["loss"], model.parameters())
        _log(hist, step, sched, terms, log, name, tc.log_every)
        step += 1
    hist.steps, hist.seconds = step, sched.elapsed()
    return model.eval(), hist


@torch.no_grad()
def encode_tracks(vq: RVQVAE, tracks: list[Track], normalizer: Normalizer) -> list[np.ndarray]:
    """Codes (4, Q, n) int64 of each whole track (T cut to a multiple of 4; n may be 0)."""
    out = []
    for t in tracks:
        frames = len(t.features) // vq.cfg.downsample * vq.cfg.downsample
        if frames == 0:
            out.append(np.zeros((vq.cfg.streams, vq.cfg.layers, 0), np.int64))
            continue
        x = torch.from_numpy(normalizer.normalize(t.features[:frames]))[None]
        out.append(vq.encode(x)[0].numpy())
    return out


class TokenBatches:
    """Random equal-length token windows of the train tracks with their texts."""

    def __init__(self, tracks: list[Track], codes: list[np.ndarray], bank: TextBank,
                 tc: TrainConfig, max_tokens: int, downsample: int):
        keep = [i for i, c in enumerate(codes) if c.shape[-1] >= 1]
        self.tracks, self.codes = [tracks[i] for i in keep], [codes[i] for i in keep]
        self.lengths = np.array([c.shape[-1] for c in self.codes])
        self.bank, self.tc, self.max_tokens, self.ds = bank, tc, max_tokens, downsample

    def sample(self, rng: np.random.Generator, batch: int):
        """tokens (B, 4, Q, n) int64, text (B, 4, 384) f32, cond (B,) f32."""
        # n follows the data's length distribution: a random track's length, capped.
        n = int(min(self.lengths[rng.integers(len(self.lengths))], self.max_tokens))
        room = np.maximum(self.lengths - n + 1, 0).astype(np.float64)
        idx = rng.choice(len(self.codes), size=batch, p=room / room.sum())
        tokens, texts = [], []
        for i in idx:
            s = int(rng.integers(0, room[i]))
            tokens.append(self.codes[i][..., s:s + n])
            parts = rng.random() < self.tc.part_prompt_share
            texts += part_texts(self.tracks[i], s * self.ds, (s + n) * self.ds, parts)
        text = self.bank(texts).reshape(batch, len(PARTS), -1)
        cond = (rng.random(batch) >= self.tc.cond_drop).astype(np.float32)
        return (torch.from_numpy(np.stack(tokens)), torch.from_numpy(text),
                torch.from_numpy(cond))


def mask_tokens(tokens: torch.Tensor, mask_id: int, codes: int, gen: torch.Generator):
    """MoMask masking of base tokens (B, 4, n): a cosine-scheduled share of positions (at
    least one) is masked; in 20% of samples whole parts are masked too (as in part editing).
    Of the masked inputs 10% become a random code and 10% stay (BERT). Returns (inputs,
    mask (B, 4, n) bool of positions to predict)."""
    b, p, n = tokens.shape
    ratio = torch.cos(torch.rand(b, generator=gen) * math.pi / 2)              # (B,)
    scores = torch.rand(b, p * n, generator=gen)
    k = (ratio * p * n).ceil().clamp(min=1).long()
    rank = scores.argsort(-1).argsort(-1)
    mask = (rank < k[:, None]).reshape(b, p, n)
    whole = torch.rand(b, generator=gen) < 0.2
    parts = torch.rand(b, p, generator=gen) < 0.5
    mask |= (whole[:, None] & parts)[:, :, None].expand(b, p, n)
    inputs = tokens.clone()
    u = torch.rand(b, p, n, generator=gen)
    inputs[mask & (u < 0.8)] = mask_id
    rand_pos = mask & (u >= 0.8) & (u < 0.9)
    inputs[rand_pos] = torch.randint(0, codes, (int(rand_pos.sum()),), generator=gen)
    return inputs, mask


def transformer_loss(model: SPAMTransformer, tokens, text, cond, gen: torch.Generator):
    """Cross-entropy and accuracy of one batch: masked base tokens (CoMA eq. 5) or a random
    residual layer j in 1..Q-1 given layers < j (eq. 6)."""
    cfg = model.cfg
    if not cfg.residual:
        target = tokens[:, :, 0]
        inputs, mask = mask_tokens(target, cfg.mask_id, cfg.codes, gen)
        logits = model(inputs, text, cond)
    else:
        layer = torch.randint(1, cfg.layers_q, (tokens.shape[0],), generator=gen)
        target = tokens[torch.arange(tokens.shape[0]), :, layer]                  # (B, 4, n)
        mask = torch.ones_like(target, dtype=torch.bool)
        logits = model(tokens, text, cond, layer)
    ce = F.cross_entropy(logits[mask], target[mask])
    acc = (logits[mask].argmax(-1) == target[mask]).float().mean()
    return ce, acc


def train_transformer(cfg: TransformerConfig, tc: TrainConfig, batches: TokenBatches,
                      log=print, name: str = "base") -> tuple[SPAMTransformer, History]:
    torch.manual_seed(tc.seed)
    rng, gen = np.random.default_rng(tc.seed), torch.Generator().manual_seed(tc.seed)
    model = SPAMTransformer(cfg).train()
    opt, sched, hist, step = _optimiser(model, tc.lr), Schedule(tc), History(), 0
    while not sched.done(step):
        ce, acc = transformer_loss(model, *batches.sample(rng, tc.batch), gen)
        optimizer_step(opt, sched.lr(step), ce, model.parameters())
        _log(hist, step, sched, {"ce": ce, "acc": acc}, log, name, tc.log_every)
        step += 1
    hist.steps, hist.seconds = step, sched.elapsed()
    return model.eval(), hist


@torch.no_grad()
def evaluate_transformer(model: SPAMTransformer, batches: TokenBatches, batches_n: int = 20,
                         batch: int = 32, seed: int = 123) -> dict:
    """Mean CE/accuracy on fixed random windows (e.g. of the val tracks), eval mode."""
    rng, gen = np.random.default_rng(seed), torch.Generator().manual_seed(seed)
    ce, acc = zip(*(transformer_loss(model.eval(), *batches.sample(rng, batch), gen)
                    for _ in range(batches_n)))
    return {"ce": float(np.mean(ce)), "acc": float(np.mean(acc))}
