"""Train the pair evaluator on the train split's pair windows (CPU, 1 thread, a wall-clock
budget).

    .venv/bin/python -m models.pair_evaluator.train            # → var/pair_evaluator/pair_evaluator.pt
    .venv/bin/python -m models.pair_evaluator.train --tiny --steps 40 --out /tmp/pe   # smoke

Loss: symmetric InfoNCE between pair windows and texts (same-kind pairs are not negatives),
where the text → motion direction also ranks the text's own window above `broken` broken
pairs (displaced / time-shifted / other partner), so the embedding encodes whether the two
people belong together, not only what each does. The checkpoint kept is the best by
validation kind accuracy (ties: the mean cosine margin of a real window over its displaced
copy against its own kind's texts). Then `python -m models.pair_evaluator.export`
(`python -m models.pair_evaluator` runs both).
"""

from __future__ import annotations

import time
from dataclasses import asdict
from pathlib import Path

import numpy as np
import torch

from interplay.text.encoder import get_encoder
from models.common.contrastive import info_nce
from models.common.sources import training_clips, training_data
from models.evaluator.cli import train_command
from models.evaluator.model import Evaluator
from models.evaluator.train import fit

from .config import PairEvaluatorConfig
from .data import PairSet, broken_batch, build_set, displaced, raw_features

ROOT = Path(__file__).resolve().parents[2]
DEFAULT_OUT = ROOT / "var" / "pair_evaluator"
TINY = dict(d_model=32, layers=1, heads=2, text_hidden=64, embed_dim=16, batch_size=24,
            broken=8, eval_every=20)


def kind_texts(data: PairSet) -> tuple[list[str], np.ndarray]:
    """All prompts (V) and each one's kind index (V,)."""
    texts, owner = [], []
    for k, name in enumerate(data.kinds):
        for p in data.prompts.get(name, []):
            texts.append(p)
            owner.append(k)
    return texts, np.array(owner)


@torch.no_grad()
def embed(model: Evaluator, feats: np.ndarray, batch: int = 128) -> np.ndarray:
    """Unit embeddings (N, E) of normalised feature windows (N, L, 293), L a multiple of the patch."""
    out = []
    for i in range(0, len(feats), batch):
        x = torch.from_numpy(np.asarray(feats[i:i + batch], np.float32))
        out.append(model.motion(x, torch.ones(x.shape[:2], dtype=torch.bool)).numpy())
    return np.concatenate(out)


@torch.no_grad()
def validate(model: Evaluator, val: PairSet, text_emb: np.ndarray, owner: np.ndarray,
             broken_feats: np.ndarray) -> tuple[float, float]:
    """(kind accuracy: a window's best-matching text is of its kind; mean margin: own-kind text
    cosine of the real window minus that of its displaced copy)."""
    model.eval()
    t = model.text(torch.from_numpy(text_emb)).numpy()                   # (V, E)
    m, mb = embed(model, val.features), embed(model, broken_feats)
    acc = float(np.mean(owner[np.argmax(m @ t.T, axis=1)] == val.kind))
    own = owner[None, :] == val.kind[:, None]                            # (N, V)
    best = lambda e: np.where(own, e @ t.T, -np.inf).max(axis=1)         # noqa: E731
    return acc, float(np.mean(best(m) - best(mb)))


def train(cfg: PairEvaluatorConfig, clips=None, log=print) -> dict:
    torch.manual_seed(cfg.seed)
    torch.set_num_threads(cfg.threads)
    rng = np.random.default_rng(cfg.seed)
    start = time.time()
    clips = training_clips(clips=clips)      # the processed set unless given; switch applied
    data, norm = build_set(clips, "train", cfg.window, cfg.stride,
                           max_shift=-(-cfg.shift[1] // cfg.stride))
    val, _ = build_set(clips, "val", cfg.window, cfg.window // 2, mirror=False, normalizer=norm,
                       kinds=data.kinds)
    texts, owner = kind_texts(data)
    text_raw = get_encoder().encode(texts).astype(np.float32)            # (V, 384)
    vrng = np.random.default_rng(1)
    val_broken = np.stack([displaced(w, 1.0, vrng.uniform(0, 2 * np.pi)) for w in val.joints])
    val_broken = ((raw_features(val_broken) - norm[0]) / norm[1]).astype(np.float32)
    by_kind = [np.flatnonzero(data.kind == k) for k in range(len(data.kinds))]
    shift_strides = (max(1, cfg.shift[0] // cfg.stride), max(1, cfg.shift[1] // cfg.stride))
    log(f"{len(data)} train windows of {len(data.kinds)} kinds {data.kinds}, {len(texts)} texts, "
        f"{len(val)} val windows; setup {time.time() - start:.1f} s")

    text_table = torch.from_numpy(text_raw)

    def batch_loss(model: Evaluator) -> torch.Tensor:
        kinds = rng.integers(len(by_kind), size=cfg.batch_size)          # kinds equally often
        idx = np.array([rng.choice(by_kind[k]) for k in kinds])
        length = int(rng.integers(cfg.min_frames // cfg.patch, cfg.window // cfg.patch + 1)) * cfg.patch
        off = int(rng.integers(0, cfg.window - length + 1))
        bro = broken_batch(data, idx[:cfg.broken], rng, cfg.displace, shift_strides)
        bro = (raw_features(bro[:, :, off:off + length]) - norm[0]) / norm[1]
        x = torch.from_numpy(np.concatenate([data.features[idx, off:off + length].astype(np.float32),
                                             bro.astype(np.float32)]))
        x = x + cfg.feature_noise * torch.randn_like(x)
        emb = model.motion(x, torch.ones(x.shape[:2], dtype=torch.bool))
        text_ids = np.array([rng.choice(np.flatnonzero(owner == k)) for k in data.kind[idx]])
        same = torch.from_numpy(data.kind[idx][:, None] == data.kind[idx][None, :])
        # same-kind windows are not negatives; the broken ones are negatives of every text
        return info_nce(emb[:len(idx)], model.text(text_table[text_ids]), same, cfg.temperature,
                        text_negatives=emb[len(idx):])

    def check(model: Evaluator) -> tuple:
        acc, margin = validate(model, val, text_raw, owner, val_broken)
        return ((round(acc, 3), margin),
                {"val_kind_accuracy": round(acc, 4), "val_displaced_margin": round(margin, 4)},
                f"val kind acc {acc:.3f} displaced margin {margin:.3f}")

    run = fit(Evaluator(cfg), cfg, batch_loss, check, log)
    return {"model": run.pop("model"), "config": asdict(cfg),
            "normalizer": {"mean": norm[0], "std": norm[1]}, "kinds": data.kinds,
            "prompts": data.prompts, **run,
            "data": {"windows": len(data), "val_windows": len(val), "texts": len(texts),
                     "clips": len({c.id for c in clips if c.split == "train" and len(c.people) == 2}),
                     "training_data": training_data(c for c in clips
                                                    if c.split == "train" and len(c.people) == 2)}}


def main(argv: list[str] | None = None) -> int:
    return train_command(argv, __doc__.split("\n")[0],
                         (PairEvaluatorConfig(), PairEvaluatorConfig(**TINY)), train, DEFAULT_OUT,
                         "pair_evaluator.pt")


if __name__ == "__main__":
    raise SystemExit(main())
