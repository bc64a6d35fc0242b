"""Export ARFlow to ONNX for the numpy/onnxruntime runtime (`interplay.reaction.session` reads
this contract; keep names, dtypes and axes):

  arflow.onnx  x_t (B, T, 66) f32 normalised flow state, t (B,) f32 flow time in [0, 1],
               actor (B, T, 66) f32 normalised actor joints, text (B, 384) f32 (zeros: none)
                                                            → x1 (B, T, 66) f32 predicted reaction
  T ≤ config.json "window"; frame i of x1 depends on inputs at frames ≤ i only.

  arflow_step.onnx  one new frame with cached keys/values (the online fast path; see
               model.ARFlowStep): x_t, actor (B, 1, 66), t (B,), text (B, 384), pos (1,) i64,
               past_k, past_v, mem_k, mem_v (layers, B, heads, P, dh) f32, P ≥ 0
                                   → x1 (B, 1, 66), new_k, new_v, new_mem_k, new_mem_v
                                     (layers, B, heads, 1, dh)

plus normalizer.npz (mean, std (66,) over both people's joints, metres) and config.json.

  python -m models.arflow.export --ckpt var/arflow --out models/weights/arflow
"""

from __future__ import annotations

import argparse
import json
import shutil
from pathlib import Path

import torch

from models.common import checkpoint, onnx_export

from .config import POSE_DIM, TEXT_DIM, ARFlowConfig
from .model import ARFlow, ARFlowStep

ROOT = Path(__file__).resolve().parents[2]
WEIGHTS = ROOT / "models" / "weights" / "arflow"
# Sampling defaults shipped with the graph (runtime may override): Euler steps, guidance
# strength (metres of step per unit penetration gradient), safe distance (m), reprojection
# weight γ on the predicted initial point, stochastic strength η.
SAMPLING = {"steps": 5, "guidance": 0.3, "safe_distance": 0.06, "gamma": 0.5, "eta": 0.0,
            "guidance_iters": 2, "rigid": 0.6}


def load_checkpoint(ckpt_dir: Path) -> tuple[ARFlow, dict]:
    """(the model of <ckpt_dir>/arflow.pt in eval mode, the checkpoint: config, step, val)."""
    return checkpoint.load(Path(ckpt_dir) / "arflow.pt", ARFlowConfig, ARFlow)


def load(ckpt_dir: Path) -> ARFlow:
    return load_checkpoint(ckpt_dir)[0]


def example_inputs(cfg: ARFlowConfig, batch: int = 2, frames: int = 7) -> tuple:
    g = torch.Generator().manual_seed(0)
    return (torch.randn(batch, frames, POSE_DIM, generator=g), torch.rand(batch, generator=g),
            torch.randn(batch, frames, POSE_DIM, generator=g), torch.randn(batch, TEXT_DIM, generator=g))


def export(ckpt_dir: Path, out: Path | None = None, sampling: dict | None = None) -> Path:
    out = Path(out or WEIGHTS)
    out.mkdir(parents=True, exist_ok=True)
    model, ck = load_checkpoint(ckpt_dir)
    onnx_export.export_graph(model, example_inputs(model.cfg), out / "arflow.onnx", INPUTS, ["x1"],
                             {"x_t": {0: "batch", 1: "frames"}, "t": {0: "batch"},
                              "actor": {0: "batch", 1: "frames"}, "text": {0: "batch"},
                              "x1": {0: "batch", 1: "frames"}})
    export_step(model, out / "arflow_step.onnx")
    shutil.copy(Path(ckpt_dir) / "normalizer.npz", out / "normalizer.npz")
    config = {"window": model.cfg.window, "pose_dim": POSE_DIM, "text_dim": TEXT_DIM,
              "text": model.cfg.text, "noise": model.cfg.noise, "model": ck["config"],
              "step": ck.get("step"), "val_loss": ck.get("val"),
              "sampling": {**SAMPLING, **(sampling or {})}}
    (out / "config.json").write_text(json.dumps(config, indent=1))
    check(model, out / "arflow.onnx")
    check_step(model, out / "arflow_step.onnx")
    if (Path(ckpt_dir) / "train_summary.json").exists():
        from .card import write_card
        write_card(out, ckpt_dir)
    return out


INPUTS = ["x_t", "t", "actor", "text"]
STEP_INPUTS = [*INPUTS, "pos", "past_k", "past_v", "mem_k", "mem_v"]
STEP_OUTPUTS = ["x1", "new_k", "new_v", "new_mem_k", "new_mem_v"]


def step_inputs(cfg: ARFlowConfig, past: int = 3) -> tuple:
    g = torch.Generator().manual_seed(1)
    cache = (cfg.layers, 1, cfg.heads, past, cfg.d_model // cfg.heads)
    return (torch.randn(1, 1, POSE_DIM, generator=g), torch.rand(1, generator=g),
            torch.randn(1, 1, POSE_DIM, generator=g), torch.randn(1, TEXT_DIM, generator=g),
            torch.tensor([past]), *(torch.randn(cache, generator=g) for _ in range(4)))


def export_step(model: ARFlow, path: Path) -> None:
    cache_axes = {1: "batch", 3: "past"}
    onnx_export.export_graph(ARFlowStep(model), step_inputs(model.cfg), path, STEP_INPUTS,
                             STEP_OUTPUTS, {"x_t": {0: "batch"}, "t": {0: "batch"},
                                            "actor": {0: "batch"}, "text": {0: "batch"},
                                            **{n: cache_axes for n in STEP_INPUTS[5:]},
                                            **{n: {1: "batch"} for n in STEP_OUTPUTS[1:]},
                                            "x1": {0: "batch"}})


def check(model: ARFlow, path: Path, tol: float = 1e-3) -> float:
    """Max |ONNX − torch| on a fresh input of another batch/length (dynamic axes); raises if > tol."""
    args = example_inputs(model.cfg, batch=3, frames=min(11, model.cfg.window))
    err = onnx_export.max_error(model, args, path)
    if err > tol:
        raise RuntimeError(f"ONNX export differs from torch by {err:.2e}")
    return err


def check_step(model: ARFlow, path: Path, tol: float = 1e-3) -> float:
    """Max |ONNX − torch| of the one-frame graph, with an empty and a filled cache."""
    step = ARFlowStep(model)
    err = max(onnx_export.max_error(step, step_inputs(model.cfg, past), path) for past in (0, 5))
    if err > tol:
        raise RuntimeError(f"one-frame ONNX export differs from torch by {err:.2e}")
    return err


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--ckpt", type=Path, default=ROOT / "var" / "arflow")
    ap.add_argument("--out", type=Path, default=WEIGHTS)
    args = ap.parse_args(argv)
    print(export(args.ckpt, args.out))


if __name__ == "__main__":
    main()
