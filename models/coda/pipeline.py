"""`python -m models.coda --all [--scale S]`: CODA end to end (part of `make train`).

Stages (seconds at scale 1; the 2-core machine is shared, so steps follow time):
  data        pair windows (train mirrored, both role orders), normaliser, text embeddings
  coda        CVQ-VAE with ICS + full CCL, then the CMT on its pose tokens   (the shipped one)
  ablations   each CVQ-VAE for the same number of steps (a fair comparison whatever the load),
              each with a short CMT so that every exported directory is complete:
                coda_short  the full model (the reference row for the ablations)
                coda_noics  no interaction codebook: the decoder reads t only (single codebook)
                coda_nogdm  λ_GDM = 0;   coda_noppl  λ_PPL = 0
  sampling    CFG scale / temperature / top-k chosen on the validation split
  export      models/weights/<variant>/ (ONNX, normalizer.npz, config.json), MODEL_CARD.md,
              metrics.json (models/weights/coda/)
"""

from __future__ import annotations

import argparse
import json
import platform
import time
from dataclasses import asdict, dataclass, replace
from pathlib import Path

import numpy as np
import torch

from models.common.sources import training_clips, training_data

from .card import write_cards
from .config import CMTConfig, CVQConfig, LossConfig, TrainConfig
from .data import load_all
from .evaluate import pair_numbers, recon_report, to_joints
from .export import SAMPLING, export_all, save
from .search import choose_sampling
from .train import Joints, encode_pairs, evaluate_cmt, train_cmt, train_cvq

ROOT = Path(__file__).resolve().parents[2]
WEIGHTS = ROOT / "models" / "weights"
CACHE = ROOT / "models" / "cache" / "coda"


@dataclass(frozen=True)
class Budgets:
    vq: float = 400.0              # seconds
    cmt: float = 240.0
    ablation_vq_steps: int = 130   # each ablation CVQ-VAE (steps, capped by ablation_vq_cap s)
    ablation_vq_cap: float = 130.0
    ablation_cmt: float = 60.0
    search: float = 100.0          # sampling-default search on val


CVQ = CVQConfig()
CMT_CFG = CMTConfig(codes=CVQ.codes)
VQ_TRAIN = TrainConfig(batch=16, lr=1e-3, warmup=30, log_every=25)
CMT_TRAIN = TrainConfig(batch=32, lr=1e-3, warmup=30, log_every=25)
VARIANTS = {  # name → (CVQ config, loss config)
    "coda": (CVQ, LossConfig()),
    "coda_short": (CVQ, LossConfig()),
    "coda_noics": (replace(CVQ, ics=False), LossConfig()),
    "coda_nogdm": (CVQ, LossConfig(w_gdm=0.0)),
    "coda_noppl": (CVQ, LossConfig(w_ppl=0.0)),
}
EXPORTED = ("coda", "coda_noics", "coda_nogdm", "coda_noppl")
THREADS = 1


def train_variant(name: str, vq_train: TrainConfig, cmt_seconds: float, sets, joints, mean,
                  std, times: dict, log) -> dict:
    cvq_cfg, loss_cfg = VARIANTS[name]
    t0 = time.perf_counter()
    vq, hist = train_cvq(cvq_cfg, loss_cfg, vq_train, sets["train"], joints, log, f"{name}/cvq")
    times[f"{name}/cvq"] = time.perf_counter() - t0
    save(vq, CACHE / name / "cvq.pt", loss=asdict(loss_cfg))
    np.savez(CACHE / name / "normalizer.npz", mean=mean, std=std)
    res = {"vq": vq, "cvq_steps": hist.steps, "cvq_seconds": round(hist.seconds, 1),
           "loss_config": asdict(loss_cfg),
           "cvq_final": {k: hist.last(k) for k in hist.rows[-1] if k not in ("step", "t")}}
    if cmt_seconds > 0:
        t0 = time.perf_counter()
        codes = encode_pairs(vq, sets["train"])
        cmt, chist = train_cmt(CMT_CFG, replace(CMT_TRAIN, seconds=cmt_seconds), codes,
                               sets["train"].text, log, f"{name}/cmt")
        times[f"{name}/cmt"] = time.perf_counter() - t0
        save(cmt, CACHE / name / "cmt.pt")
        res.update(cmt=cmt, cmt_steps=chist.steps, cmt_seconds=round(chist.seconds, 1),
                   cmt_final={"ce": chist.last("ce"), "acc": chist.last("acc")},
                   cmt_val=evaluate_cmt(cmt, encode_pairs(vq, sets["val"]), sets["val"].text))
        log(f"[{name}/cmt] val {res['cmt_val']}")
    t0 = time.perf_counter()
    res["recon"] = recon_report(vq, sets["test_as_is"], mean, std)
    times[f"{name}/report"] = time.perf_counter() - t0
    res["pose_code_usage"] = int(torch.unique(encode_pairs(vq, sets["train"])).numel())
    log(f"[{name}] recon {res['recon']}")
    return res


def run_all(scale: float = 1.0, budgets: Budgets = Budgets(), early: bool = False, log=print,
            weights: Path = WEIGHTS) -> dict:
    # One thread, measured on the shared 2-core CPU at load ~9: 0.9–2 s per CVQ step with one
    # torch thread vs 20 s with two (two threads wait on each other when cores are busy).
    torch.set_num_threads(THREADS)
    b = Budgets(**{k: type(v)(max(1, v * scale)) for k, v in asdict(budgets).items()})
    start, times = time.perf_counter(), {}
    sets, mean, std = load_all()
    sets["test_as_is"] = sets["test"].take(_as_is(sets["test"]))
    sets["val_as_is"] = sets["val"].take(_as_is(sets["val"]))
    joints = Joints(mean, std)
    times["data"] = time.perf_counter() - start
    log("[data] " + ", ".join(f"{k} {len(v)}" for k, v in sets.items()))
    real = {s: pair_numbers(to_joints(sets[s].a, mean, std), to_joints(sets[s].b, mean, std))
            for s in ("test_as_is", "val_as_is")}
    results = {"coda": train_variant("coda", replace(VQ_TRAIN, seconds=b.vq), b.cmt, sets,
                                     joints, mean, std, times, log)}
    sampling = dict(SAMPLING)
    if not early:
        short = replace(VQ_TRAIN, steps=b.ablation_vq_steps, seconds=b.ablation_vq_cap)
        for name in [v for v in VARIANTS if v != "coda"]:
            results[name] = train_variant(name, short, b.ablation_cmt if name in EXPORTED else 0,
                                          sets, joints, mean, std, times, log)
        t0 = time.perf_counter()
        sampling, grid = choose_sampling(results["coda"]["vq"], results["coda"]["cmt"],
                                         sets["val_as_is"], mean, std, real["val_as_is"],
                                         b.search, log)
        results["coda"]["sampling_search"] = grid
        times["sampling_search"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    roundtrip = {}
    for name in EXPORTED:
        if name in results:
            res = results[name]
            roundtrip[name] = export_all(res["vq"], res["cmt"], mean, std, weights / name,
                                         sampling, trained=not early,
                                         extra={"variant": name, "losses": res["loss_config"]})
    times["export"] = time.perf_counter() - t0
    times["total"] = time.perf_counter() - start
    train_ids = set(sets["train"].clip_ids)
    numbers = {
        "trained": not early, "scale": scale, "budgets_s": asdict(b),
        "machine": f"{platform.machine()}, {torch.get_num_threads()} torch threads, "
                   f"torch {torch.__version__}",
        "times_s": {k: round(v, 1) for k, v in times.items()},
        "data": {s: {"windows": len(sets[s]), "synthetic": int(sets[s].synthetic.sum()),
                     "clips": len(set(sets[s].clip_ids))} for s in sets},
        # The sources and licences of the train pairs (the card's licence section).
        "training_data": training_data(c for c in training_clips() if c.id in train_ids),
        "configs": {"cvq": asdict(CVQ), "cmt": asdict(CMT_CFG), "cvq_train": asdict(VQ_TRAIN),
                    "cmt_train": asdict(CMT_TRAIN)},
        "sampling": sampling, "onnx_roundtrip_max_error": roundtrip, "real": real,
        "variants": {n: {k: v for k, v in r.items() if k not in ("vq", "cmt")}
                     for n, r in results.items()},
    }
    (weights / "coda").mkdir(parents=True, exist_ok=True)
    (weights / "coda" / "metrics.json").write_text(json.dumps(numbers, indent=1) + "\n")
    write_cards(numbers, weights)
    log(f"[done] CODA {times['total'] / 60:.1f} min")
    return numbers


def _as_is(data) -> list[int]:
    """Indices of one role order per window (pair_set alternates as-is, swapped)."""
    return list(range(0, len(data), 2))


def main(argv: list[str] | None = None, prog: str | None = None) -> None:
    ap = argparse.ArgumentParser(prog=prog, description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--all", action="store_true", help="train, evaluate, export every variant")
    ap.add_argument("--scale", type=float, default=1.0, help="multiply every budget")
    ap.add_argument("--early", action="store_true",
                    help="main model only, no ablations/search; config 'trained': false")
    a = ap.parse_args(argv)
    if not a.all:
        ap.error("nothing to do: pass --all")
    CACHE.mkdir(parents=True, exist_ok=True)
    with open(CACHE / "train.log", "a") as fh:
        def log(msg: str) -> None:
            print(msg, flush=True)
            fh.write(msg + "\n")
            fh.flush()
        run_all(a.scale, early=a.early, log=log)
