"""Sampling defaults chosen on the validation split: for each (CFG scale, temperature, top-k)
of a small grid, one generated pair per validation window from its prompt (n = 20 tokens),
decoded through the CVQ-VAE, scored by how far its pair statistics are from the real
validation pairs': |ΔIF| + |Δ contact share| + |Δ mean pelvis distance (m)| + 0.1·|Δ ln(1+IV)|.
The grid is walked in order until the time budget ends (the first entry is the paper's)."""

from __future__ import annotations

import math
import time

import numpy as np
import torch

from .cmt import CMT
from .cvq import CVQVAE
from .data import PairTensors
from .evaluate import pair_numbers, to_joints
from .export import SAMPLING
from .sample import sample_codes

GRID = [(2.0, 1.0, 51), (3.5, 1.0, 51), (1.0, 1.0, 51), (2.0, 0.8, 51), (3.5, 0.8, 25),
        (2.0, 1.0, 512)]


def pelvis_distance(a: np.ndarray, b: np.ndarray) -> float:
    """Mean horizontal distance (m) between the two pelvises over windows (N, T, 22, 3)."""
    return float(np.linalg.norm((a[:, :, 0] - b[:, :, 0])[..., [0, 2]], axis=-1).mean())


def pair_stats(a: np.ndarray, b: np.ndarray) -> dict[str, float]:
    out = pair_numbers(a, b)
    out["pelvis_distance_m"] = pelvis_distance(a, b)
    out["contact_share"] = out["contact_frames"] / a.shape[1]
    return out


def score(gen: dict, real: dict) -> float:
    return (abs(gen["if"] - real["if"]) + abs(gen["contact_share"] - real["contact_share"])
            + abs(gen["pelvis_distance_m"] - real["pelvis_distance_m"])
            + 0.1 * abs(math.log1p(gen["iv_cm3"]) - math.log1p(real["iv_cm3"])))


@torch.no_grad()
def generate(vq: CVQVAE, cmt: CMT, text: torch.Tensor, n: int, setting: dict, seed: int = 0):
    """Generated pairs (N, 4n, 22, 3)·2 as normalised tensors (x_a, x_b)."""
    gen = torch.Generator().manual_seed(seed)
    codes = sample_codes(cmt, text, n, setting["steps"], setting["cfg"], setting["temperature"],
                         setting["topk"], gen)
    return vq.decode(codes[:, 0], codes[:, 1])


def choose_sampling(vq: CVQVAE, cmt: CMT, val: PairTensors, mean, std, real: dict,
                    seconds: float, log=print) -> tuple[dict, list[dict]]:
    """(best setting, every tried row with its scores)."""
    real = dict(real)
    ra, rb = to_joints(val.a, mean, std), to_joints(val.b, mean, std)
    real.update(pelvis_distance_m=pelvis_distance(ra, rb),
                contact_share=real["contact_frames"] / ra.shape[1])
    n = val.a.shape[1] // vq.cfg.downsample
    start, rows = time.perf_counter(), []
    for cfg, temp, topk in GRID:
        if rows and time.perf_counter() - start > seconds:
            break
        setting = {**SAMPLING, "cfg": cfg, "temperature": temp, "topk": topk}
        xa, xb = generate(vq, cmt, val.text, n, setting)
        stats = pair_stats(to_joints(xa, mean, std), to_joints(xb, mean, std))
        rows.append({"setting": setting, **stats, "score": score(stats, real)})
        log(f"[sampling] {setting} score {rows[-1]['score']:.3f} {stats}")
    best = min(rows, key=lambda r: r["score"])["setting"]
    return best, [{"real": real}] + rows
