"""Export SPAM to ONNX for the numpy/onnxruntime runtime (the contract below is what
`interplay.agents` reads; keep names, dtypes and axes exactly):

  vq_encode.onnx  motion (B, T, 239) f32 normalised       → codes (B, 4, Q, T/4) i64
  vq_decode.onnx  codes (B, 4, Q, n) i64                   → motion (B, 4n, 239) f32 normalised
  base.onnx       tokens (B, 4, n) i64 (K = masked), text (B, 4, 384) f32, cond (B,) f32
                                                           → logits (B, 4, n, K) f32
  residual.onnx   tokens (B, 4, Q, n) i64 (layers ≥ layer ignored), layer (B,) i64 in 1..Q-1,
                  text (B, 4, 384) f32, cond (B,) f32     → logits (B, 4, n, K) f32

plus normalizer.npz (features.Normalizer) and config.json (config.runtime_config).
T must be a multiple of 4 and n ≤ max_tokens. `base.int8.onnx` / `residual.int8.onnx` are the
same transformers with int8 weights (onnxruntime dynamic quantization: MatMul weights per
channel, activations quantized per call); config.json "precision" says which pair the
runtime loads.

  python -m models.spam.export --ckpt models/cache/spam --out models/weights/spam
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import torch
import torch.nn as nn

from interplay.motion.features import Normalizer
from models.common import onnx_export

from . import checkpoint
from .config import FEATURE_DIM, PARTS, SamplingDefaults, runtime_config
from .transformer import SPAMTransformer
from .vqvae import RVQVAE


class VQEncode(nn.Module):
    def __init__(self, vq: RVQVAE):
        super().__init__()
        self.vq = vq

    def forward(self, motion):
        return self.vq.encode(motion)


class VQDecode(nn.Module):
    def __init__(self, vq: RVQVAE):
        super().__init__()
        self.vq = vq

    def forward(self, codes):
        return self.vq.decode(codes)


class Base(nn.Module):
    def __init__(self, model: SPAMTransformer):
        super().__init__()
        self.model = model

    def forward(self, tokens, text, cond):
        return self.model(tokens, text, cond)


class Residual(nn.Module):
    def __init__(self, model: SPAMTransformer):
        super().__init__()
        self.model = model

    def forward(self, tokens, layer, text, cond):
        return self.model(tokens, text, cond, layer)


def example_inputs(vq: RVQVAE, n: int = 6, batch: int = 2) -> dict[str, tuple]:
    """Inputs per graph (also used by the tests)."""
    k, q, p = vq.cfg.codes, vq.cfg.layers, len(PARTS)
    g = torch.Generator().manual_seed(0)
    text = torch.randn(batch, p, 384, generator=g)
    cond = torch.tensor([1.0, 0.0] * (batch // 2) + [1.0] * (batch % 2))
    return {
        "vq_encode": (torch.randn(batch, 4 * n, FEATURE_DIM, generator=g),),
        "vq_decode": (torch.randint(0, k, (batch, p, q, n), generator=g),),
        "base": (torch.randint(0, k + 1, (batch, p, n), generator=g), text, cond),
        "residual": (torch.randint(0, k, (batch, p, q, n), generator=g),
                     torch.randint(1, q, (batch,), generator=g), text, cond),
    }


_SPECS = {  # graph → (input names, output names, dynamic axes)
    "vq_encode": (["motion"], ["codes"], {"motion": {0: "B", 1: "T"}, "codes": {0: "B", 3: "n"}}),
    "vq_decode": (["codes"], ["motion"], {"codes": {0: "B", 3: "n"}, "motion": {0: "B", 1: "T"}}),
    "base": (["tokens", "text", "cond"], ["logits"],
             {"tokens": {0: "B", 2: "n"}, "text": {0: "B"}, "cond": {0: "B"},
              "logits": {0: "B", 2: "n"}}),
    "residual": (["tokens", "layer", "text", "cond"], ["logits"],
                 {"tokens": {0: "B", 3: "n"}, "layer": {0: "B"}, "text": {0: "B"},
                  "cond": {0: "B"}, "logits": {0: "B", 2: "n"}}),
}


def export_graph(module: nn.Module, name: str, inputs: tuple, out_dir: Path) -> Path:
    """<name>.onnx with the contract's input/output names and dynamic batch/time axes."""
    return onnx_export.export_graph(module, inputs, out_dir / f"{name}.onnx", *_SPECS[name])


def export_all(vq: RVQVAE, base: SPAMTransformer, residual: SPAMTransformer,
               normalizer: Normalizer, out_dir: str | Path,
               sampling: SamplingDefaults | None = None, trained: bool = True,
               int8: bool = True) -> Path:
    """Write the four graphs (+ the int8 transformers when int8), normalizer.npz and
    config.json (precision "int8" when they were written) to out_dir."""
    if not vq.cfg.parts:
        raise ValueError("only the 4-part VQ has the (B, 4, Q, n) contract")
    if base.cfg.residual or not residual.cfg.residual:
        raise ValueError("pass the base model as base= and the residual model as residual=")
    if (base.cfg.codes, residual.cfg.codes, residual.cfg.layers_q) != (vq.cfg.codes,) * 2 + (
            vq.cfg.layers,):
        raise ValueError("transformers and VQ disagree on K or Q")
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    inputs = example_inputs(vq)
    modules = {"vq_encode": VQEncode(vq), "vq_decode": VQDecode(vq),
               "base": Base(base), "residual": Residual(residual)}
    for name, module in modules.items():
        export_graph(module, name, inputs[name], out_dir)
    if int8:
        quantize_int8(out_dir)
    normalizer.save(out_dir / "normalizer.npz")
    config = runtime_config(vq.cfg, base.cfg, sampling, trained, "int8" if int8 else "fp32")
    (out_dir / "config.json").write_text(json.dumps(config, indent=1) + "\n")
    return out_dir


INT8_GRAPHS = ("base", "residual")


def quantize_int8(out_dir: str | Path) -> list[Path]:
    """<graph>.int8.onnx next to each float transformer graph (dynamic quantization: int8
    weights, activations quantized per call; the int8 MatMuls are ~2× faster on this CPU)."""
    from onnxruntime.quantization import QuantType, quantize_dynamic

    out = []
    for name in INT8_GRAPHS:
        src, dst = Path(out_dir) / f"{name}.onnx", Path(out_dir) / f"{name}.int8.onnx"
        quantize_dynamic(str(src), str(dst), weight_type=QuantType.QInt8, per_channel=True)
        out.append(dst)
    return out


def export_vq(vq: RVQVAE, normalizer: Normalizer, out_dir: str | Path, note: str) -> Path:
    """Only the VQ graphs (reconstruction rows of `interplay eval`, e.g. the single-codebook
    ablation, whose codes are (B, 1, Q, n)) + normalizer.npz + config.json."""
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    motion = torch.randn(2, 24, FEATURE_DIM, generator=torch.Generator().manual_seed(0))
    with torch.no_grad():
        codes = vq.encode(motion)
    export_graph(VQEncode(vq), "vq_encode", (motion,), out_dir)
    export_graph(VQDecode(vq), "vq_decode", (codes,), out_dir)
    normalizer.save(out_dir / "normalizer.npz")
    (out_dir / "config.json").write_text(json.dumps(
        {"trained": True, "graphs": ["vq_encode", "vq_decode"], "note": note,
         "vq": {k: getattr(vq.cfg, k) for k in ("parts", "codes", "layers", "latent",
                                                 "downsample")}}, indent=1) + "\n")
    (out_dir / "MODEL_CARD.md").write_text(f"# {out_dir.name}: VQ graphs only\n\n{note}.\n")
    return out_dir


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--ckpt", required=True, help="dir with vq.pt, base.pt, residual.pt, "
                                                  "normalizer.npz")
    ap.add_argument("--out", required=True)
    a = ap.parse_args(argv)
    ck = Path(a.ckpt)
    export_all(checkpoint.load(ck / "vq.pt"), checkpoint.load(ck / "base.pt"),
               checkpoint.load(ck / "residual.pt"), Normalizer.load(ck / "normalizer.npz"), a.out)
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
