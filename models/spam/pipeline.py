"""`make train`: every single-person model from the processed data, in one command.

Stages (budgets in seconds at scale 1; the 2-core machine is shared, so steps follow time):
  data       feature tracks (+ mirrored train tracks), text embeddings, normaliser (cached)
  vq         SPAM RVQ-VAE with the geometric/commonsense losses (the shipped one)
  base, residual            transformers on the SPAM VQ's tokens
  ablation VQs, each for the same number of steps (a fair comparison whatever the load):
    spam_short   SPAM RVQ-VAE as above
    spam_nocs    without the geometric/commonsense losses, + base/residual (smaller budgets)
    spam_single  single-codebook whole-body RVQ-VAE (reconstruction only)
  evaluator  the text–motion evaluator (models/evaluator/train.py), whose numbers the card reports
  export     models/weights/spam/ and spam_nocs/ (ONNX incl. int8 transformers, normalizer,
             config), spam_single/ (the ablation VQ graphs, for `interplay eval`)
  card       models/weights/spam/MODEL_CARD.md + metrics.json with the measured numbers
"""

from __future__ import annotations

import json
import platform
import time
import traceback
from dataclasses import asdict, dataclass, replace
from pathlib import Path

import torch

from models.common.schedule import History
from models.common.sources import training_clips, training_data

from . import checkpoint
from .card import write_card
from .config import LossConfig, SamplingDefaults, TrainConfig, TransformerConfig, VQConfig
from .data import CACHE_DIR, TextBank, fit_normalizer, load_tracks
from .export import export_all, export_vq
from .report import codebook_usage, usage_summary, vq_report
from .train import TokenBatches, encode_tracks, evaluate_transformer, train_transformer, train_vq

ROOT = Path(__file__).resolve().parents[2]
WEIGHTS = ROOT / "models" / "weights"


@dataclass(frozen=True)
class Budgets:
    vq: float = 900                 # seconds
    base: float = 900
    residual: float = 420
    ablation_vq_steps: int = 250    # each ablation VQ (steps, capped by ablation_vq_cap s)
    ablation_vq_cap: float = 150
    base_nocs: float = 150
    residual_nocs: float = 90


# The shipped sizes (stated in the model card).
VQ = VQConfig(codes=256, layers=5, latent=64, width=64, depth=2)
TRANSFORMER = TransformerConfig(codes=VQ.codes, layers_q=VQ.layers, d=128, heads=4, blocks=4)
# Few hundred steps fit the budgets, so batches are small and learning rates high (measured:
# recon L1 0.56 after 100 VQ steps at 8e-4 vs 0.60 at CoMA's 2e-4).
VQ_TRAIN = TrainConfig(batch=32, lr=1e-3, warmup=50)
TR_TRAIN = TrainConfig(batch=32, lr=1e-3, warmup=50)


def _train_stack(name: str, vq_cfg: VQConfig, loss_cfg: LossConfig, vq_train: TrainConfig,
                 budgets: tuple[float, ...], tracks, normalizer, bank, times: dict, log,
                 cache_dir: Path) -> dict:
    """VQ (+ base and residual when budgets = (base s, residual s)) of one variant; returns
    models and numbers. Checkpoints go to <cache_dir>/<name>/."""
    out_dir = cache_dir / name
    t0 = time.perf_counter()
    vq, hist = train_vq(vq_cfg, loss_cfg, vq_train, tracks, normalizer, log, name=f"{name}/vq")
    times[f"{name}/vq"] = time.perf_counter() - t0
    checkpoint.save(vq, out_dir / "vq.pt", loss=asdict(loss_cfg))
    normalizer.save(out_dir / "normalizer.npz")
    transformers = {}
    if budgets:
        batches = token_batches(vq, tracks, normalizer, bank)
        for kind, seconds in zip(("base", "residual"), budgets):
            t0 = time.perf_counter()
            cfg = replace(TRANSFORMER, residual=kind == "residual")
            transformers[kind] = train_transformer(cfg, replace(TR_TRAIN, seconds=seconds),
                                                   batches["train"], log, name=f"{name}/{kind}")
            times[f"{name}/{kind}"] = time.perf_counter() - t0
            checkpoint.save(transformers[kind][0], out_dir / f"{kind}.pt")
    return stack_numbers(name, vq, hist, transformers, tracks, normalizer, bank, times, log)


def token_batches(vq, tracks, normalizer, bank) -> dict[str, TokenBatches]:
    """Token windows of the train and val tracks under one VQ."""
    out = {}
    for split, tc in (("train", TR_TRAIN), ("val", VQ_TRAIN)):
        part = [t for t in tracks if t.split == split]
        out[split] = TokenBatches(part, encode_tracks(vq, part, normalizer), bank, tc,
                                  TRANSFORMER.max_tokens, vq.cfg.downsample)
    return out


def stack_numbers(name: str, vq, vq_hist: History, transformers: dict, tracks, normalizer,
                  bank, times: dict, log) -> dict:
    """Models and measured numbers of one trained variant: test reconstruction, train code
    usage, and per transformer (`transformers`: kind → (model, History)) its final train and
    validation CE/accuracy."""
    res = {"vq": vq, "vq_steps": vq_hist.steps,
           "vq_final": {k: vq_hist.last(k) for k in vq_hist.rows[-1] if k not in ("step", "t")}}
    t0 = time.perf_counter()
    res["recon"] = vq_report(vq, [t for t in tracks if t.split == "test"], normalizer)
    train_tracks = [t for t in tracks if t.split == "train"]
    res["usage"] = codebook_usage(encode_tracks(vq, train_tracks, normalizer), vq.cfg.codes)
    times[f"{name}/vq_report"] = time.perf_counter() - t0
    log(f"[{name}] recon {res['recon']}")
    if transformers:
        val = token_batches(vq, tracks, normalizer, bank)["val"]
    for kind, (model, hist) in transformers.items():
        res[kind] = model
        res[f"{kind}_steps"] = hist.steps
        res[f"{kind}_final"] = {"ce": hist.last("ce", 20), "acc": hist.last("acc", 20)}
        res[f"{kind}_val"] = evaluate_transformer(model, val)
        log(f"[{name}/{kind}] val {res[f'{kind}_val']}")
    return res


def _evaluator(times: dict, log) -> str:
    """Train the text–motion evaluator; a status line for the card."""
    from models.evaluator import train as evaluator_train
    t0 = time.perf_counter()
    try:
        evaluator_train.main([])
    except Exception:  # a separate model: report it, do not lose the SPAM run
        log(traceback.format_exc())
        return "failed (see the training log)"
    finally:
        times["evaluator"] = time.perf_counter() - t0
    return "trained by models/evaluator/train.py main()"


def run_all(scale: float = 1.0, budgets: Budgets = Budgets(), log=print,
            weights_dir: Path = WEIGHTS, cache_dir: Path = CACHE_DIR,
            run_evaluator: bool = True) -> dict:
    """Train, export and document everything; returns the numbers of metrics.json."""
    torch.set_num_threads(2)
    b = Budgets(**{k: type(v)(v * scale) for k, v in asdict(budgets).items()})
    start, times = time.perf_counter(), {}
    t0 = time.perf_counter()
    tracks = load_tracks(cache_dir=cache_dir)
    normalizer, bank = fit_normalizer(tracks), TextBank(tracks, cache_dir)
    times["data"] = time.perf_counter() - t0
    log(f"[data] {len(tracks)} tracks, {sum(len(t.features) for t in tracks)} frames, "
        f"{len(bank.row)} texts, {times['data']:.0f}s")

    stack = dict(tracks=tracks, normalizer=normalizer, bank=bank, times=times, log=log,
                 cache_dir=cache_dir)
    spam = _train_stack("spam", VQ, LossConfig(), replace(VQ_TRAIN, seconds=b.vq),
                        (b.base, b.residual), **stack)
    short = replace(VQ_TRAIN, steps=max(1, b.ablation_vq_steps), seconds=b.ablation_vq_cap)
    spam_short = _train_stack("spam_short", VQ, LossConfig(), short, (), **stack)
    nocs = _train_stack("spam_nocs", VQ, LossConfig(geometric=False), short,
                        (b.base_nocs, b.residual_nocs), **stack)
    single = _train_stack("spam_single", replace(VQ, parts=False, latent=2 * VQ.latent),
                          LossConfig(), short, (), **stack)
    evaluator = _evaluator(times, log) if run_evaluator else "not run (run_evaluator=False)"
    results = {"spam": spam, "spam_short": spam_short, "spam_nocs": nocs, "spam_single": single}
    numbers = finish(results, tracks, normalizer, bank, times, b, evaluator, weights_dir, start)
    log(f"[done] {times['total'] / 60:.1f} min")
    return numbers


def finish(results: dict, tracks, normalizer, bank, times: dict, budgets: Budgets,
           evaluator: str, weights_dir: Path, start: float, note: str | None = None) -> dict:
    """Export the shipped variants, write metrics.json and the model cards; the numbers."""
    t0 = time.perf_counter()
    for name in ("spam", "spam_nocs"):
        res = results[name]
        export_all(res["vq"], res["base"], res["residual"], normalizer, weights_dir / name)
    export_vq(results["spam_single"]["vq"], normalizer, weights_dir / "spam_single",
              "single-codebook (whole-body) VQ ablation: reconstruction only "
              "(`interplay eval` row single_vq); numbers in models/weights/spam/MODEL_CARD.md")
    times["export"] = time.perf_counter() - t0
    times.setdefault("total", time.perf_counter() - start)
    numbers = {
        "machine": f"{platform.machine()}, {torch.get_num_threads()} torch threads, "
                   f"torch {torch.__version__}",
        "times_s": {k: round(v, 1) for k, v in times.items()},
        "budgets_s": asdict(budgets), "evaluator": evaluator,
        "sampling": asdict(SamplingDefaults()),
        "data": {"tracks": len(tracks), "train_frames": sum(len(t.features) for t in tracks
                                                            if t.split == "train"),
                 "texts": len(bank.row)},
        "configs": {"vq": asdict(VQ), "transformer": asdict(TRANSFORMER),
                    "vq_train": asdict(VQ_TRAIN), "transformer_train": asdict(TR_TRAIN)},
        # The sources and licences the tracks came from (the card's licence section).
        "training_data": training_data(training_clips()),
    }
    if note:
        numbers["note"] = note
    for name, res in results.items():
        numbers[name] = {k: v for k, v in res.items()
                         if k not in ("vq", "base", "residual", "usage")}
        numbers[name]["usage"] = usage_summary(res["usage"])
        numbers[name]["usage_layers"] = res["usage"]
    (weights_dir / "spam" / "metrics.json").write_text(json.dumps(numbers, indent=1) + "\n")
    write_card(numbers, weights_dir / "spam" / "MODEL_CARD.md",
               weights_dir / "spam_nocs" / "MODEL_CARD.md")
    return numbers
