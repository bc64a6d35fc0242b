"""Export CODA to ONNX for the numpy/onnxruntime runtime (`interplay.agents` codes against
this contract; keep names, dtypes and axes exactly):

  encode.onnx  x (B, T, 66) f32 normalised joints of one person, T % 4 == 0
                                                    → codes (B, T/4) i64 pose-codebook ids
  decode.onnx  codes_a (B, n) i64, codes_b (B, n) i64
                                                    → x_a, x_b (B, 4n, 66) f32 normalised joints
               (pose-codebook lookup → ICS attention → interaction-codebook quantisation →
               w = z + t → pose decoder; the no-ICS ablation decodes t directly)
  cmt.onnx     codes (B, 2, n) i64 (K = mask id), text (B, 384) f32 (all zeros: unconditional)
                                                    → logits (B, 2, n, K) f32
  Dynamic B and n (n ≤ max_tokens); plus normalizer.npz (mean, std (66,)) and config.json.

  python -m models.coda.export --ckpt models/cache/coda/coda --out models/weights/coda
"""

from __future__ import annotations

import argparse
import json
from dataclasses import asdict
from pathlib import Path

import numpy as np
import torch
import torch.nn as nn

from models.common import checkpoint, onnx_export

from .cmt import CMT
from .config import FPS, POSE_DIM, TEXT_DIM, CMTConfig, CVQConfig
from .cvq import CVQVAE


class Encode(nn.Module):
    def __init__(self, vq: CVQVAE):
        super().__init__()
        self.vq = vq

    def forward(self, x):
        return self.vq.encode(x)


class Decode(nn.Module):
    def __init__(self, vq: CVQVAE):
        super().__init__()
        self.vq = vq

    def forward(self, codes_a, codes_b):
        return self.vq.decode(codes_a, codes_b)


_SPECS = {  # graph → (input names, output names, dynamic axes)
    "encode": (["x"], ["codes"], {"x": {0: "B", 1: "T"}, "codes": {0: "B", 1: "n"}}),
    "decode": (["codes_a", "codes_b"], ["x_a", "x_b"],
               {"codes_a": {0: "B", 1: "n"}, "codes_b": {0: "B", 1: "n"},
                "x_a": {0: "B", 1: "T"}, "x_b": {0: "B", 1: "T"}}),
    "cmt": (["codes", "text"], ["logits"],
            {"codes": {0: "B", 2: "n"}, "text": {0: "B"}, "logits": {0: "B", 2: "n"}}),
}


def example_inputs(k: int, n: int = 7, batch: int = 2) -> dict[str, tuple]:
    g = torch.Generator().manual_seed(0)
    text = torch.randn(batch, TEXT_DIM, generator=g)
    text[-1] = 0.0                                        # one unconditional row
    return {"encode": (torch.randn(batch, 4 * n, POSE_DIM, generator=g),),
            "decode": (torch.randint(0, k, (batch, n), generator=g),
                       torch.randint(0, k, (batch, n), generator=g)),
            "cmt": (torch.randint(0, k + 1, (batch, 2, n), generator=g), text)}


def export_graph(module: nn.Module, name: str, inputs: tuple, out_dir: Path) -> Path:
    """<name>.onnx with the contract's input/output names and dynamic axes."""
    return onnx_export.export_graph(module, inputs, out_dir / f"{name}.onnx", *_SPECS[name])


def check_graphs(vq: CVQVAE, cmt: CMT, out_dir: Path, n: int = 9, batch: int = 3) -> float:
    """Largest |torch − onnxruntime| over the three graphs at a size unlike the export's
    (codes: the share that differ)."""
    inputs = example_inputs(vq.cfg.codes, n, batch)
    modules = {"encode": Encode(vq), "decode": Decode(vq), "cmt": cmt}
    return max(onnx_export.max_error(module, inputs[name], out_dir / f"{name}.onnx")
               for name, module in modules.items())


def runtime_config(vq: CVQVAE, cmt: CMT, sampling: dict, trained: bool, extra: dict) -> dict:
    return {"trained": trained, "codes": vq.cfg.codes,
            "interaction_codes": vq.cfg.interaction_codes if vq.cfg.ics else 0,
            "ics": vq.cfg.ics, "downsample": vq.cfg.downsample,
            "max_tokens": cmt.cfg.max_tokens, "mask_id": cmt.cfg.mask_id, "fps": FPS,
            "dim": POSE_DIM, "text_dim": TEXT_DIM, "sampling": sampling,
            "sizes": {"cvq": asdict(vq.cfg), "cmt": asdict(cmt.cfg)}, **extra}


def export_all(vq: CVQVAE, cmt: CMT, mean: np.ndarray, std: np.ndarray, out_dir: str | Path,
               sampling: dict, trained: bool = True, extra: dict | None = None) -> float:
    """Write the three graphs, normalizer.npz and config.json; returns the round-trip error."""
    if cmt.cfg.codes != vq.cfg.codes:
        raise ValueError("CMT and CVQ-VAE disagree on K")
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    vq, cmt = vq.eval(), cmt.eval()
    inputs = example_inputs(vq.cfg.codes)
    for name, module in {"encode": Encode(vq), "decode": Decode(vq), "cmt": cmt}.items():
        export_graph(module, name, inputs[name], out_dir)
    np.savez(out_dir / "normalizer.npz", mean=mean.astype(np.float32), std=std.astype(np.float32))
    (out_dir / "config.json").write_text(
        json.dumps(runtime_config(vq, cmt, sampling, trained, extra or {}), indent=1) + "\n")
    return check_graphs(vq, cmt, out_dir)


KINDS = {"cvq": (CVQConfig, CVQVAE), "cmt": (CMTConfig, CMT)}   # the checkpoints' "kind"


def save(model: CVQVAE | CMT, path: str | Path, **extra) -> None:
    checkpoint.save_kind(model, path, KINDS, **extra)


def load(path: str | Path) -> CVQVAE | CMT:
    """The network saved at path, in eval mode."""
    return checkpoint.load_kind(path, KINDS, "CODA")


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--ckpt", required=True, help="dir with cvq.pt, cmt.pt, normalizer.npz")
    ap.add_argument("--out", required=True)
    a = ap.parse_args(argv)
    ck = Path(a.ckpt)
    stats = np.load(ck / "normalizer.npz")
    prev = Path(a.out) / "config.json"
    sampling = json.loads(prev.read_text())["sampling"] if prev.exists() else SAMPLING
    err = export_all(load(ck / "cvq.pt"), load(ck / "cmt.pt"), stats["mean"], stats["std"],
                     a.out, sampling)
    print(f"wrote {a.out} (onnxruntime vs torch max error {err:.2e})")


# The paper's CFG 2 and temperature 1 (D.2); topk = how many of the K codes stay eligible.
SAMPLING = {"steps": 10, "cfg": 2.0, "temperature": 1.0, "topk": 51}


if __name__ == "__main__":
    main()
