"""Torch eager vs onnxruntime for the same weights: median latency of the four SPAM graphs at
the runtime's shapes, in torch (the checkpoints) and in onnxruntime (the exported graphs, float
and int8 transformers, two intra-op threads without spinning, as the runtime builds them):

  vq_encode  motion (1, 4n, 239)      vq_decode  codes (1, 4, Q, n)
  base       tokens (2, 4, n) — CFG's conditional + unconditional passes in one batch
  residual   tokens (2, 4, Q, n), layer (2,)

  python -m models.bench_torch [--seconds 6] [--runs 20] [--json]

Where it lives: this is a measurement, not part of a model. It trains and ships nothing and
no model code imports it; it only reads SPAM's checkpoints and exported graphs. So it stands
beside train_all.py at the top of the training side, outside the SPAM package (measurement
does not live inside a model package) and outside models/common (which holds what the models
are built from). It cannot join the product's benchmarks (`interplay bench`,
backend/interplay/bench) because it needs torch, which the product never imports.
"""

from __future__ import annotations

import argparse
import json
import time
from dataclasses import replace
from pathlib import Path

import torch

from models.spam import checkpoint
from models.spam.config import FEATURE_DIM, PARTS, TEXT_DIM
from models.spam.data import CACHE_DIR
from models.spam.transformer import SPAMTransformer
from models.spam.vqvae import RVQVAE


def load_models(ckpt_dir: Path) -> tuple[RVQVAE, SPAMTransformer, SPAMTransformer, str]:
    """The trained checkpoints when present, else untrained models of the shipped sizes."""
    names = ("vq", "base", "residual")
    if all((ckpt_dir / f"{n}.pt").exists() for n in names):
        vq, base, res = (checkpoint.load(ckpt_dir / f"{n}.pt") for n in names)
        return vq, base, res, str(ckpt_dir)
    from models.spam.pipeline import TRANSFORMER, VQ
    return (RVQVAE(VQ).eval(), SPAMTransformer(TRANSFORMER).eval(),
            SPAMTransformer(replace(TRANSFORMER, residual=True)).eval(), "untrained")


def _median_ms(fn, args, runs: int, warmup: int) -> float:
    for _ in range(warmup):
        fn(*args)
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        fn(*args)
        times.append((time.perf_counter() - t0) * 1000)
    return sorted(times)[len(times) // 2]


def bench_onnx(weights: Path, inputs_of: dict, runs: int, warmup: int, threads: int) -> dict:
    """{precision: {graph: median ms}} of the exported graphs on the torch inputs."""
    import onnxruntime as ort
    opts = ort.SessionOptions()
    opts.intra_op_num_threads, opts.inter_op_num_threads = threads, 1
    opts.add_session_config_entry("session.intra_op.allow_spinning", "0")
    inputs = {"vq_encode": ("motion",), "vq_decode": ("codes",),
              "base": ("tokens", "text", "cond"), "residual": ("tokens", "layer", "text", "cond")}
    out = {}
    for precision in ("fp32", "int8"):
        out[precision] = {}
        for name, args in inputs_of.items():
            path = weights / (f"{name}.int8.onnx" if precision == "int8" and name in
                              ("base", "residual") else f"{name}.onnx")
            if not path.is_file():
                continue
            sess = ort.InferenceSession(str(path), opts, providers=["CPUExecutionProvider"])
            feed = dict(zip(inputs[name], (a.numpy() for a in args)))
            out[precision][name] = _median_ms(lambda sess=sess, feed=feed: sess.run(None, feed), (),
                                              runs, warmup)
    return out


def graph_inputs(vq: RVQVAE, tokens: int) -> dict[str, tuple]:
    k, q, p = vq.cfg.codes, vq.cfg.layers, len(PARTS)
    g = torch.Generator().manual_seed(0)
    text, cond = torch.randn(2, p, TEXT_DIM, generator=g), torch.tensor([1.0, 0.0])
    return {"vq_encode": (torch.randn(1, 4 * tokens, FEATURE_DIM, generator=g),),
            "vq_decode": (torch.randint(0, k, (1, p, q, tokens), generator=g),),
            "base": (torch.randint(0, k + 1, (2, p, tokens), generator=g), text, cond),
            "residual": (torch.randint(0, k, (2, p, q, tokens), generator=g),
                         torch.tensor([1, 1]), text, cond)}


@torch.no_grad()
def bench(vq: RVQVAE, base: SPAMTransformer, res: SPAMTransformer, tokens: int,
          runs: int = 20, warmup: int = 3) -> dict[str, float]:
    """Median milliseconds per torch call of each graph for `tokens` steps (4·tokens frames)."""
    fns = {"vq_encode": vq.encode, "vq_decode": vq.decode, "base": base,
           "residual": lambda t, l, x, c: res(t, x, c, l)}
    return {name: _median_ms(fns[name], args, runs, warmup)
            for name, args in graph_inputs(vq, tokens).items()}


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(prog="python -m models.bench_torch",
                                 description=__doc__.split("\n")[0])
    ap.add_argument("--ckpt", default=str(CACHE_DIR / "spam"))
    ap.add_argument("--weights", default=str(Path(__file__).resolve().parent / "weights" / "spam"),
                    help="exported graphs of the same weights")
    ap.add_argument("--seconds", type=float, default=6.0, help="motion length (20 fps)")
    ap.add_argument("--runs", type=int, default=20)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--json", action="store_true")
    a = ap.parse_args(argv)
    torch.set_num_threads(a.threads)
    vq, base, res, source = load_models(Path(a.ckpt))
    tokens = max(1, round(a.seconds * 20 / vq.cfg.downsample))
    ms = bench(vq, base, res, tokens, a.runs)
    onnx = bench_onnx(Path(a.weights), graph_inputs(vq, tokens), a.runs, 3, a.threads)
    result = {"torch": torch.__version__, "threads": a.threads, "models": source,
              "weights": a.weights, "tokens": tokens, "frames": 4 * tokens,
              "median_ms": {"torch_eager": ms, "onnxruntime_fp32": onnx["fp32"],
                            "onnxruntime_int8": onnx["int8"]}}
    if a.json:
        print(json.dumps(result, indent=1))
        return
    print(f"median ms per call, {a.threads} threads, n = {tokens} tokens ({4 * tokens} frames); "
          f"torch: {source}, onnx: {a.weights}")
    print(f"  {'graph':10s} {'torch eager':>12s} {'ort fp32':>9s} {'ort int8':>9s}")
    for name, v in ms.items():
        cells = [onnx[p].get(name) for p in ("fp32", "int8")]
        print(f"  {name:10s} {v:12.2f} " + " ".join(
            f"{c:9.2f}" if c is not None else f"{'-':>9s}" for c in cells))


if __name__ == "__main__":
    main()
