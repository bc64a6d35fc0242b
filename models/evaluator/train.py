"""Train the evaluator on the train split (CPU, 2 threads, a wall-clock budget).

    .venv/bin/python -m models.evaluator.train                # full run → var/evaluator/evaluator.pt
    .venv/bin/python -m models.evaluator.train --steps 20 --tiny --out /tmp/ev   # smoke

The best checkpoint by validation R-precision (pool 32, averaged over 10 pools; ties broken by
the mean cosine margin of the true text over the best other text) is kept.
Then `python -m models.evaluator.export` writes the ONNX/npz files and the model card
(`python -m models.evaluator` runs both).
"""

from __future__ import annotations

import time
from dataclasses import asdict
from pathlib import Path

import numpy as np
import torch

from interplay.eval.metrics import r_precision
from interplay.eval.testset import split_samples
from interplay.motion.features import Normalizer, encode
from interplay.text.encoder import get_encoder
from models.common.contrastive import info_nce
from models.common.schedule import Budget, optimizer_step, warmup_cosine
from models.common.sources import training_clips, training_data

from .cli import train_command
from .config import EvaluatorConfig
from .data import TextTable, Track, build_tracks, pad, sample_batch, track_weights
from .model import Evaluator

ROOT = Path(__file__).resolve().parents[2]
DEFAULT_OUT = ROOT / "var" / "evaluator"
TINY = dict(d_model=32, layers=1, heads=2, text_hidden=64, embed_dim=32, batch_size=16,
            eval_every=10)


@torch.no_grad()
def embed_windows(model: Evaluator, feats: list[np.ndarray], batch: int = 64) -> np.ndarray:
    """Unit motion embeddings (N, E) of normalised feature windows (each ≤ max_frames)."""
    out = []
    for i in range(0, len(feats), batch):
        x, m = pad(feats[i:i + batch], model.cfg.patch)
        out.append(model.motion(torch.from_numpy(x), torch.from_numpy(m)).numpy())
    return np.concatenate(out)


@torch.no_grad()
def retrieval(model: Evaluator, feats: list[np.ndarray], text_emb: np.ndarray,
              labels: list[str], pools: int = 10, seed: int = 0) -> tuple[np.ndarray, float]:
    """R-precision top-1..3 (3,) averaged over `pools` random distractor draws, and the mean
    margin (own text's cosine minus the best other distinct text's), which still ranks
    checkpoints once R-precision saturates on the small validation split."""
    model.eval()
    m = embed_windows(model, feats)
    t = model.text(torch.from_numpy(text_emb)).numpy()
    rng = np.random.default_rng(seed)
    rp = np.mean([r_precision(m, t, labels, rng) for _ in range(pools)], axis=0)
    sims = m @ t.T                                                     # (N, N)
    other = np.asarray(labels)[None, :] != np.asarray(labels)[:, None]
    margin = np.diag(sims) - np.where(other, sims, -np.inf).max(axis=1)
    return rp, float(margin.mean())


def split_set(clips, split: str, normalizer: Normalizer, cfg: EvaluatorConfig):
    """(normalised feature windows, MiniLM text embeddings (N, 384), texts) of a split."""
    samples = split_samples(clips, split, cfg.max_frames)
    feats = [normalizer.normalize(encode(s.joints)) for s in samples]
    texts = [s.text for s in samples]
    return feats, get_encoder().encode(texts), texts


def fit(model: Evaluator, cfg, batch_loss, validate, log=print) -> dict:
    """The loop both evaluators train with (cfg: this config or the pair evaluator's): AdamW,
    `warmup_cosine` learning rate, gradients clipped to 1, for cfg.steps or cfg.seconds. Every
    eval_every steps (and at the last) `validate(model)` gives (score, history fields, log
    text), and the weights of the best score (higher is better; tuples break ties) are kept.
    Returns {"model": those weights, "history", "losses", "steps", "train_seconds"}."""
    opt = torch.optim.AdamW(model.parameters(), lr=cfg.lr, weight_decay=cfg.weight_decay)
    best, best_state, history, losses = None, None, [], []
    budget, step = Budget(cfg.steps, cfg.seconds), 0
    while not budget.done(step):
        model.train()
        loss = batch_loss(model)
        optimizer_step(opt, warmup_cosine(step, cfg.lr, cfg.warmup, cfg.steps), loss,
                       model.parameters())
        losses.append(loss.item())
        step += 1
        if step % cfg.eval_every == 0 or step == cfg.steps:
            score, fields, text = validate(model)
            history.append({"step": step, "seconds": round(budget.elapsed(), 1),
                            "loss": float(np.mean(losses[-cfg.eval_every:])), **fields})
            log(f"step {step} {history[-1]['seconds']} s loss {history[-1]['loss']:.3f} {text}")
            if best is None or score > best:
                best, best_state = score, {k: v.clone() for k, v in model.state_dict().items()}
                history[-1]["best"] = True
    if best_state is None:                                             # fewer steps than eval_every
        best_state = model.state_dict()
    return {"model": best_state, "history": history, "losses": losses, "steps": step,
            "train_seconds": round(budget.elapsed(), 1)}


def train(cfg: EvaluatorConfig, clips=None, log=print) -> dict:
    """Train on the train split of `clips` (default: the processed set) and return the
    checkpoint dict (model, config, normalizer, history, timing)."""
    torch.manual_seed(cfg.seed)
    torch.set_num_threads(cfg.threads)
    rng = np.random.default_rng(cfg.seed)
    start = time.time()
    clips = training_clips(clips=clips)      # the processed set unless given; switch applied

    table = TextTable()
    raw = build_tracks(clips, table, "train")
    normalizer = Normalizer.fit([t.features for t in raw])
    tracks = [Track(normalizer.normalize(t.features), t.prompt, t.captions) for t in raw]
    weights = track_weights(tracks)
    text_raw = get_encoder().encode(table.texts)                      # (V, 384) unit
    not_negative = (text_raw @ text_raw.T) > cfg.fn_threshold          # (V, V); diagonal True
    val = split_set(clips, "val", normalizer, cfg)
    log(f"{len(tracks)} tracks ({sum(len(t.features) for t in tracks)} frames), "
        f"{len(table.texts)} texts, {len(val[0])} val windows; setup {time.time() - start:.1f} s")

    text_table = torch.from_numpy(text_raw)

    def batch_loss(model: Evaluator) -> torch.Tensor:
        windows, text_ids = sample_batch(tracks, weights, cfg.batch_size, cfg.min_frames,
                                         cfg.max_frames, rng, cfg.prompt_share)
        x, mask = pad(windows, cfg.patch)
        x = torch.from_numpy(x)
        x = x + cfg.feature_noise * torch.randn_like(x)
        m_emb = model.motion(x, torch.from_numpy(mask))
        t_emb = model.text(text_table[text_ids])
        nn_mask = torch.from_numpy(not_negative[np.ix_(text_ids, text_ids)])
        return info_nce(m_emb, t_emb, nn_mask, cfg.temperature)

    def validate(model: Evaluator) -> tuple:
        rp, margin = retrieval(model, *val)
        return ((round(float(rp.mean()), 6), margin),
                {"val_r_precision": [round(float(v), 4) for v in rp], "val_margin": round(margin, 4)},
                f"val R@1/2/3 {rp[0]:.3f} {rp[1]:.3f} {rp[2]:.3f} margin {margin:.3f}")

    run = fit(Evaluator(cfg), cfg, batch_loss, validate, log)
    return {"model": run.pop("model"), "config": asdict(cfg),
            "normalizer": {"mean": normalizer.mean, "std": normalizer.std, **normalizer.meta},
            **run,
            "data": {"tracks": len(tracks), "frames": int(sum(len(t.features) for t in tracks)),
                     "texts": len(table.texts),
                     "clips": sum(c.split == "train" and not c.synthetic for c in clips),
                     "training_data": training_data(c for c in clips
                                                    if c.split == "train" and not c.synthetic)}}


def main(argv: list[str] | None = None) -> int:
    return train_command(argv, __doc__.split("\n")[0], (EvaluatorConfig(), EvaluatorConfig(**TINY)),
                   train, DEFAULT_OUT, "evaluator.pt")


if __name__ == "__main__":
    raise SystemExit(main())
