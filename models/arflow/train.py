"""Train ARFlow on the train split's pair windows (CPU, a wall-clock budget), keep the best
checkpoint by validation x-prediction loss, then export ONNX + normalizer + card.

    .venv/bin/python -m models.arflow                       # full run → var/arflow/, weights
    .venv/bin/python -m models.arflow --tiny --steps 30 --out /tmp/af --no-export  # smoke
"""

from __future__ import annotations

import argparse
import json
from dataclasses import asdict, replace
from pathlib import Path

import numpy as np
import torch

from interplay.motion import skeleton as sk
from models.common import checkpoint
from models.common.schedule import Budget, optimizer_step
from models.common.sources import training_clips, training_data

from .config import ARFlowConfig, TrainConfig
from .data import PairSet, fit_stats, pair_set, save_stats
from .model import ARFlow, flow_state, loss_terms

ROOT = Path(__file__).resolve().parents[2]
DEFAULT_OUT = ROOT / "var" / "arflow"
TINY = dict(d_model=32, layers=1, heads=2, ff=64)


def batch_loss(model: ARFlow, cfg: ARFlowConfig, actor, reactor, text, mean, std, parents,
               gen: torch.Generator, train: bool = True) -> tuple[torch.Tensor, dict]:
    """Total loss and its terms for one batch of normalised (B, L, 66) tensors."""
    b = actor.shape[0]
    t = torch.rand(b, generator=gen)
    x_t, _ = flow_state(actor, reactor, t, cfg.noise, gen)
    if train and cfg.text:
        keep = (torch.rand(b, generator=gen) >= cfg.text_dropout).float()[:, None]
        text = text * keep
    pred = model(x_t, t, actor, text)
    terms = loss_terms(pred, reactor, mean, std, parents)
    total = terms["rec"] + cfg.velocity_weight * terms["vel"] + cfg.bone_weight * terms["bone"]
    return total, {k: float(v.detach()) for k, v in terms.items()}


@torch.no_grad()
def evaluate(model: ARFlow, cfg: ARFlowConfig, data: dict, mean, std, parents) -> float:
    """Mean validation loss over the whole set, at fixed seeds (comparable between evals)."""
    model.eval()
    gen = torch.Generator().manual_seed(123)
    losses = []
    for i in range(0, len(data["actor"]), 256):
        sl = slice(i, i + 256)
        loss, _ = batch_loss(model, cfg, data["actor"][sl], data["reactor"][sl], data["text"][sl],
                             mean, std, parents, gen, train=False)
        losses.append(float(loss) * len(data["actor"][sl]))
    model.train()
    return sum(losses) / max(1, len(data["actor"]))


def tensors(ps: PairSet, mean: np.ndarray, std: np.ndarray) -> dict[str, torch.Tensor]:
    return {"actor": torch.from_numpy((ps.actor - mean) / std).float(),
            "reactor": torch.from_numpy((ps.reactor - mean) / std).float(),
            "text": torch.from_numpy(ps.text).float()}


def train(cfg: ARFlowConfig, tc: TrainConfig, out: Path, train_set: PairSet, val_set: PairSet,
          log=print) -> dict:
    torch.manual_seed(tc.seed)
    torch.set_num_threads(tc.threads)
    out.mkdir(parents=True, exist_ok=True)
    mean, std = fit_stats(train_set)
    save_stats(out / "normalizer.npz", mean, std, train_set.actor.shape[0] * cfg.window)
    tr, va = tensors(train_set, mean, std), tensors(val_set, mean, std)
    mean_t, std_t = torch.from_numpy(mean), torch.from_numpy(std)
    parents = torch.tensor([max(p, 0) for p in sk.PARENTS])
    model = ARFlow(cfg)
    opt = torch.optim.AdamW(model.parameters(), lr=tc.lr, weight_decay=tc.weight_decay)

    def lr(s: int) -> float:
        """Linear warm-up times a cosine down to 5 % over the steps."""
        return tc.lr * (min(1.0, (s + 1) / tc.warmup)
                        * max(0.05, 0.5 * (1 + np.cos(np.pi * min(1.0, s / tc.steps)))))

    gen = torch.Generator().manual_seed(tc.seed)
    n = len(tr["actor"])
    history, best, budget = [], float("inf"), Budget(tc.steps, tc.budget_s)
    first_loss = last_loss = None
    for step in range(tc.steps):
        idx = torch.randint(0, n, (tc.batch_size,), generator=gen)
        loss, terms = batch_loss(model, cfg, tr["actor"][idx], tr["reactor"][idx], tr["text"][idx],
                                 mean_t, std_t, parents, gen)
        optimizer_step(opt, lr(step), loss, model.parameters())
        first_loss = float(loss.detach()) if first_loss is None else first_loss
        last_loss = float(loss.detach())
        done = budget.done(step + 1)
        if (step + 1) % tc.eval_every == 0 or done:
            val = evaluate(model, cfg, va, mean_t, std_t, parents) if len(va["actor"]) else last_loss
            history.append({"step": step + 1, "train": last_loss, "val": val, **terms,
                            "seconds": round(budget.elapsed(), 1)})
            log(json.dumps(history[-1]))
            if val < best:
                best = val
                checkpoint.save(model, out / "arflow.pt", step=step + 1, val=val)
        if done:
            break
    train_ids = set(train_set.clip_ids)
    summary = {"steps": step + 1, "seconds": round(budget.elapsed(), 1), "best_val": best,
               "first_loss": first_loss, "last_loss": last_loss, "history": history,
               "train_windows": len(train_set), "val_windows": len(val_set),
               "parameters": sum(p.numel() for p in model.parameters()),
               "train_config": asdict(tc),
               "training_data": training_data(c for c in training_clips() if c.id in train_ids)}
    (out / "train_summary.json").write_text(json.dumps(summary, indent=1))
    return summary


def main(argv: list[str] | None = None, prog: str | None = None) -> dict:
    ap = argparse.ArgumentParser(prog=prog, description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--out", type=Path, default=DEFAULT_OUT)
    ap.add_argument("--steps", type=int)
    ap.add_argument("--budget", type=float, help="wall-clock seconds")
    ap.add_argument("--tiny", action="store_true", help="tiny model (smoke tests)")
    ap.add_argument("--max-windows", type=int, help="subsample the training windows (smoke)")
    ap.add_argument("--no-export", action="store_true")
    ap.add_argument("--weights", type=Path, help="export directory (default models/weights/arflow)")
    args = ap.parse_args(argv)
    cfg = replace(ARFlowConfig(), **TINY) if args.tiny else ARFlowConfig()
    tc = TrainConfig()
    if args.steps:
        tc = replace(tc, steps=args.steps, eval_every=min(tc.eval_every, args.steps))
    if args.budget:
        tc = replace(tc, budget_s=args.budget)
    train_set = pair_set("train", cfg.window, tc.stride)
    val_set = pair_set("val", cfg.window, tc.stride * 2, mirror=False)
    if args.max_windows and len(train_set) > args.max_windows:
        keep = np.random.default_rng(0).choice(len(train_set), args.max_windows, replace=False)
        train_set = PairSet(train_set.actor[keep], train_set.reactor[keep], train_set.text[keep],
                            train_set.synthetic[keep], [train_set.clip_ids[i] for i in keep])
        val_set = PairSet(val_set.actor[:64], val_set.reactor[:64], val_set.text[:64],
                          val_set.synthetic[:64], val_set.clip_ids[:64])
    summary = train(cfg, tc, args.out, train_set, val_set)
    if not args.no_export:
        from .export import export
        export(args.out, args.weights)
    return summary


if __name__ == "__main__":
    main()
