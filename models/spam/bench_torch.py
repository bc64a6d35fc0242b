"""Torch-eager latency of the four SPAM graphs at the runtime's shapes, for the "torch eager vs
onnxruntime" comparison (the runtime measures the ONNX side with the same shapes):

  vq_encode  motion (1, 4n, 239)      vq_decode  codes (1, 4, Q, n)
  base       tokens (2, 4, n) — CFG's conditional + unconditional passes in one batch
  residual   tokens (2, 4, Q, n), layer (2,)

  python -m models.spam.bench_torch [--seconds 4] [--runs 20] [--json]
"""

from __future__ import annotations

import argparse
import json
import time
from dataclasses import replace
from pathlib import Path

import models.spam  # noqa: F401  (OpenMP wait policy before torch loads)
import torch

from . import checkpoint
from .config import FEATURE_DIM, PARTS, TEXT_DIM
from .data import CACHE_DIR
from .transformer import SPAMTransformer
from .vqvae import RVQVAE


def load_models(ckpt_dir: Path) -> tuple[RVQVAE, SPAMTransformer, SPAMTransformer, str]:
    """The trained checkpoints when present, else untrained models of the shipped sizes."""
    names = ("vq", "base", "residual")
    if all((ckpt_dir / f"{n}.pt").exists() for n in names):
        vq, base, res = (checkpoint.load(ckpt_dir / f"{n}.pt") for n in names)
        return vq, base, res, str(ckpt_dir)
    from .pipeline import TRANSFORMER, VQ
    return (RVQVAE(VQ).eval(), SPAMTransformer(TRANSFORMER).eval(),
            SPAMTransformer(replace(TRANSFORMER, residual=True)).eval(), "untrained")


@torch.no_grad()
def bench(vq: RVQVAE, base: SPAMTransformer, res: SPAMTransformer, tokens: int,
          runs: int = 20, warmup: int = 3) -> dict[str, float]:
    """Median milliseconds per call of each graph for `tokens` steps (4·tokens frames)."""
    k, q, p = vq.cfg.codes, vq.cfg.layers, len(PARTS)
    text, cond = torch.randn(2, p, TEXT_DIM), torch.tensor([1.0, 0.0])
    calls = {
        "vq_encode": (vq.encode, (torch.randn(1, 4 * tokens, FEATURE_DIM),)),
        "vq_decode": (vq.decode, (torch.randint(0, k, (1, p, q, tokens)),)),
        "base": (base, (torch.randint(0, k + 1, (2, p, tokens)), text, cond)),
        "residual": (lambda t, l, x, c: res(t, x, c, l),
                     (torch.randint(0, k, (2, p, q, tokens)), torch.tensor([1, 1]), text, cond)),
    }
    out = {}
    for name, (fn, args) in calls.items():
        for _ in range(warmup):
            fn(*args)
        times = []
        for _ in range(runs):
            t0 = time.perf_counter()
            fn(*args)
            times.append((time.perf_counter() - t0) * 1000)
        out[name] = sorted(times)[len(times) // 2]
    return out


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ckpt", default=str(CACHE_DIR / "spam"))
    ap.add_argument("--seconds", type=float, default=4.0, help="motion length (20 fps)")
    ap.add_argument("--runs", type=int, default=20)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--json", action="store_true")
    a = ap.parse_args(argv)
    torch.set_num_threads(a.threads)
    vq, base, res, source = load_models(Path(a.ckpt))
    tokens = max(1, round(a.seconds * 20 / vq.cfg.downsample))
    ms = bench(vq, base, res, tokens, a.runs)
    result = {"backend": "torch-eager", "torch": torch.__version__, "threads": a.threads,
              "models": source, "tokens": tokens, "frames": 4 * tokens, "median_ms": ms}
    if a.json:
        print(json.dumps(result, indent=1))
    else:
        print(f"torch eager ({source}), {a.threads} threads, n = {tokens} tokens "
              f"({4 * tokens} frames):")
        for name, v in ms.items():
            print(f"  {name:10s} {v:8.2f} ms")


if __name__ == "__main__":
    main()
