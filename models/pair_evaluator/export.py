"""Export a trained pair evaluator for the numpy/onnxruntime runtime and write its card.

    .venv/bin/python -m models.pair_evaluator.export [--ckpt var/pair_evaluator/pair_evaluator.pt]
                                                     [--out models/weights/pair_evaluator]

Writes motion_encoder.onnx (dynamic batch and length), text_proj.npz, normalizer.npz,
config.json, metrics.json and MODEL_CARD.md with numbers measured through the runtime
(`interplay.review.pair_evaluator.PairEvaluator`): kind retrieval accuracy on the val and
test splits, and FID of real and broken pairs against the train split's real pairs.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from interplay.eval.metrics import fid
from interplay.motion.clip import default_clips
from interplay.review.pair_evaluator import PairEvaluator
from models.common import checkpoint
from models.evaluator.cli import export_command
from models.evaluator.export import export_towers, onnx_matches_torch
from models.evaluator.model import Evaluator

from .card import model_card
from .config import PairEvaluatorConfig
from .data import build_set, displaced, time_shifted
from .train import DEFAULT_OUT

ROOT = Path(__file__).resolve().parents[2]
WEIGHTS = ROOT / "models" / "weights" / "pair_evaluator"
WINDOW, STRIDE = 40, 20          # as interplay eval-react's test windows


def load_checkpoint(path: str | Path) -> tuple[Evaluator, dict]:
    """(the pair evaluator saved at path, in eval mode; the checkpoint)."""
    return checkpoint.load(path, PairEvaluatorConfig, Evaluator, strict=True, weights_only=False)


def export(ckpt_path: str | Path, out: str | Path) -> dict:
    """Write the runtime files into `out`; returns the checkpoint."""
    model, ckpt = load_checkpoint(ckpt_path)
    out = Path(out)
    export_towers(model, out, kinds=ckpt["kinds"], prompts=ckpt["prompts"])
    np.savez(out / "normalizer.npz", mean=np.asarray(ckpt["normalizer"]["mean"], np.float32),
             std=np.asarray(ckpt["normalizer"]["std"], np.float32))
    return ckpt


def kind_accuracy(ev: PairEvaluator, clips, split: str, prompts: dict[str, list[str]]) -> dict:
    """Top-1/top-2 kind accuracy of a split's windows (both role orders, not mirrored) ranking
    every training prompt: a hit when the best text (best two distinct kinds) is of its kind."""
    kinds = sorted(prompts)
    data, _ = build_set(clips, split, WINDOW, STRIDE, mirror=False,
                        normalizer=(np.zeros(1, np.float32), np.ones(1, np.float32)), kinds=kinds)
    texts, owner = [], []
    for k, name in enumerate(kinds):
        texts += prompts[name]
        owner += [k] * len(prompts[name])
    sims = ev.embed(data.joints) @ ev.embed_text(texts).T                # (N, V)
    per_kind = np.stack([sims[:, np.array(owner) == k].max(axis=1) for k in range(len(kinds))], 1)
    order = np.argsort(-per_kind, axis=1)
    top1 = order[:, 0] == data.kind
    top2 = top1 | (order[:, 1] == data.kind)
    return {"windows": int(len(data)), "top1": float(top1.mean()), "top2": float(top2.mean()),
            "per_kind_top1": {kinds[k]: float(top1[data.kind == k].mean())
                              for k in range(len(kinds)) if np.any(data.kind == k)}}


def fid_table(ev: PairEvaluator, clips, seed: int = 0) -> dict:
    """FID against the train split's real windows (captured and composed separately) of:
    the val and test real windows, and the test windows broken — second person displaced by
    1 m (random direction), time-shifted by 1 s, or replaced by another test window's."""
    rng = np.random.default_rng(seed)
    out = {}
    for name, synthetic in (("captured", False), ("composed", True)):
        sel = [c for c in clips if c.synthetic == synthetic]
        ref = build_set(sel, "train", WINDOW, STRIDE, mirror=False, normalizer=_NO_NORM)[0]
        val = build_set(sel, "val", WINDOW, STRIDE, mirror=False, normalizer=_NO_NORM)[0]
        test = build_set(sel, "test", WINDOW, STRIDE, mirror=False, normalizer=_NO_NORM)[0]
        e_ref = ev.embed(ref.joints)
        rows = {"train_windows": len(ref), "test_windows": len(test)}
        if len(val) > 1:
            rows["val real"] = fid(ev.embed(val.joints), e_ref)
        rows["test real"] = fid(ev.embed(test.joints), e_ref)
        moved = np.stack([displaced(w, 1.0, rng.uniform(0, 2 * np.pi)) for w in test.joints])
        rows["test, second displaced 1 m"] = fid(ev.embed(moved), e_ref)
        shifted = [time_shifted(test, i, 1) for i in range(len(test))]  # +STRIDE frames = 1 s
        shifted = [w for w in shifted if w is not None]
        if len(shifted) > 1:
            rows["test, second 1 s later"] = fid(ev.embed(np.stack(shifted)), e_ref)
            rows["shifted_windows"] = len(shifted)
        perm = rng.permutation(len(test))
        other = np.stack([test.joints[:, 0], test.joints[perm, 1]], axis=1)
        rows["test, second from another window"] = fid(ev.embed(other), e_ref)
        out[name] = rows
    return out


_NO_NORM = (np.zeros(1, np.float32), np.ones(1, np.float32))


def main(argv: list[str] | None = None) -> int:
    args, ckpt, model, ev, err = export_command(
        argv, __doc__.split("\n")[0], DEFAULT_OUT / "pair_evaluator.pt", WEIGHTS, export,
        load_checkpoint, PairEvaluator, onnx_matches_torch)
    if not args.no_card:
        clips = default_clips(args.data_dir)
        metrics = {"onnx_error": err,
                   "retrieval": {s: kind_accuracy(ev, clips, s, ckpt["prompts"]) for s in ("val", "test")},
                   "fid": fid_table(ev, clips)}
        out = Path(args.out)
        (out / "metrics.json").write_text(json.dumps(metrics, indent=1) + "\n")
        params = sum(p.numel() for p in model.parameters())
        (out / "MODEL_CARD.md").write_text(model_card(ckpt, metrics, params, out))
        print(json.dumps(metrics, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
