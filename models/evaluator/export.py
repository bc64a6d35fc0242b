"""Export a trained evaluator checkpoint for the numpy/onnxruntime runtime and write its card.

    .venv/bin/python -m models.evaluator.export [--ckpt var/evaluator/evaluator.pt]
                                                [--out models/weights/evaluator]

Writes motion_encoder.onnx (dynamic batch and length), text_proj.npz, normalizer.npz,
config.json, and MODEL_CARD.md with retrieval accuracy on the val and test splits measured
through the runtime (`interplay.review.evaluator.EvaluatorRuntime`).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import torch

from interplay.eval.metrics import confidence, r_precision
from interplay.eval.testset import split_samples
from interplay.motion.clip import default_clips
from interplay.motion.features import Normalizer
from interplay.review.evaluator import EvaluatorRuntime as Runtime
from models.common import checkpoint, onnx_export
from models.common.sources import licence_section

from .cli import export_command
from .config import EvaluatorConfig
from .model import Evaluator
from .train import DEFAULT_OUT

ROOT = Path(__file__).resolve().parents[2]
WEIGHTS = ROOT / "models" / "weights" / "evaluator"


def load_checkpoint(path: str | Path) -> tuple[Evaluator, dict]:
    """(the evaluator saved at path, in eval mode; the checkpoint with its normalizer,
    history and data counts)."""
    return checkpoint.load(path, EvaluatorConfig, Evaluator, strict=True, weights_only=False)


def export_onnx(model: Evaluator, path: Path) -> None:
    """The motion encoder as ONNX: motion (B, T, F) float32, mask (B, T) bool → embedding (B, E)."""
    cfg = model.cfg
    x = torch.randn(2, 4 * cfg.patch, cfg.feature_dim)
    mask = torch.ones(2, 4 * cfg.patch, dtype=torch.bool)
    onnx_export.export_graph(model.motion, (x, mask), path, ["motion", "mask"], ["embedding"],
                             {"motion": {0: "batch", 1: "frames"},
                              "mask": {0: "batch", 1: "frames"}, "embedding": {0: "batch"}})


def save_text_proj(model: Evaluator, path: Path) -> None:
    """The text MLP as numpy arrays (the runtime replays it without onnxruntime)."""
    t = model.text
    np.savez(path, fc1_w=t.fc1.weight.detach().numpy().T, fc1_b=t.fc1.bias.detach().numpy(),
             fc2_w=t.fc2.weight.detach().numpy().T, fc2_b=t.fc2.bias.detach().numpy())


def export_towers(model: Evaluator, out: Path, **config) -> None:
    """The files both evaluators' runtimes read, bar the normalizer: motion_encoder.onnx,
    text_proj.npz and config.json (the towers' sizes, then `config`, then the text encoder)."""
    cfg = model.cfg
    out.mkdir(parents=True, exist_ok=True)
    export_onnx(model, out / "motion_encoder.onnx")
    save_text_proj(model, out / "text_proj.npz")
    (out / "config.json").write_text(json.dumps({
        "embed_dim": cfg.embed_dim, "max_frames": cfg.max_frames, "patch": cfg.patch,
        "feature_dim": cfg.feature_dim, "text_dim": cfg.text_dim, "temperature": cfg.temperature,
        **config, "text_encoder": "all-MiniLM-L6-v2 int8 (interplay.text.encoder)"},
        indent=1) + "\n")


def export(ckpt_path: str | Path, out: str | Path) -> dict:
    """Write the runtime files into `out`; returns the checkpoint (for the card)."""
    model, ckpt = load_checkpoint(ckpt_path)
    out = Path(out)
    # The sources it was trained on: `interplay eval` measures on their test split only.
    trained = (ckpt.get("data") or {}).get("training_data") or {}
    export_towers(model, out, **({"sources": sorted(trained["sources"])} if trained else {}))
    n = ckpt["normalizer"]
    Normalizer(np.asarray(n["mean"]), np.asarray(n["std"]),
               {k: v for k, v in n.items() if k not in ("mean", "std")}).save(out / "normalizer.npz")
    return ckpt


def onnx_matches_torch(model: Evaluator, runtime: Runtime, seed: int = 0) -> float:
    """Largest |ONNX - torch| over embeddings of random padded batches of two lengths."""
    g = torch.Generator().manual_seed(seed)
    worst = 0.0
    for t in (3 * model.cfg.patch, 11 * model.cfg.patch):
        x = torch.randn(3, t, model.cfg.feature_dim, generator=g)
        mask = torch.ones(3, t, dtype=torch.bool)
        mask[1, t // 2:] = False
        with torch.no_grad():
            ref = model.motion(x, mask).numpy()
        (got,) = runtime.session.run(["embedding"], {"motion": x.numpy(), "mask": mask.numpy()})
        worst = max(worst, float(np.abs(got - ref).max()))
    return worst


def retrieval_table(runtime: Runtime, clips, pools: int = 20) -> dict:
    """Per split: R-precision top-1/2/3 (pool 32) mean and 95% CI over `pools` draws."""
    out = {}
    for split in ("val", "test"):
        samples = split_samples(clips, split)
        m = runtime.embed_motion([s.joints for s in samples])
        texts = [s.text for s in samples]
        t = runtime.embed_text(texts)
        rng = np.random.default_rng(0)
        runs = np.array([r_precision(m, t, texts, rng) for _ in range(pools)])
        out[split] = {"samples": len(samples), "texts": len(set(texts)),
                      "r_precision": [confidence(runs[:, k]) for k in range(3)]}
    return out


def model_card(ckpt: dict, table: dict, onnx_error: float, params: int, out: Path) -> str:
    cfg = ckpt["config"]
    sizes = ", ".join(f"{f} {(out / f).stat().st_size / 1e6:.1f} MB"
                      for f in ("motion_encoder.onnx", "text_proj.npz"))
    d = ckpt["data"]
    licence = "\n".join(licence_section(d.get("training_data")))
    chosen = [h for h in ckpt["history"] if h.get("best")]
    best = chosen[-1] if chosen else None
    rows = "\n".join(
        f"| {s} | {v['samples']} | {v['texts']} | "
        + " | ".join(f"{m:.3f} ± {c:.3f}" for m, c in v["r_precision"]) + " |"
        for s, v in table.items())
    return f"""# Evaluator (TMR-style text–motion embedding)

Used by `interplay eval` (R-precision, FID, MM-Dist, Diversity, MultiModality) and by the
reviewer agent (`interplay.review.evaluator.Evaluator.score`). Runtime: numpy + onnxruntime.

## Model
- Motion encoder: the 239-d features of `interplay.motion.features.encode`, normalised with
  `normalizer.npz` (train split statistics); patches of {cfg['patch']} frames (strided conv) →
  {cfg['layers']} pre-norm transformer blocks (d={cfg['d_model']}, {cfg['heads']} heads) over
  the tokens with padding masked → masked mean → linear → {cfg['embed_dim']}-d unit vector.
  Windows up to {cfg['max_frames']} frames (10 s); longer motions: chunk embeddings averaged.
- Text side: frozen all-MiniLM-L6-v2 embeddings (384-d, `interplay.text.encoder`) → MLP
  (384 → {cfg['text_hidden']} → {cfg['embed_dim']}, tanh-GELU) → unit vector (`text_proj.npz`).
- {params:,} trained parameters ({sizes}). ONNX vs torch: max |Δembedding| = {onnx_error:.1e}.

## Training
- Data: the TRAIN split only of the processed set (`models/data`, {d['clips']} real clips;
  salsa pairs as two single people; composed synthetic pairs left out), {d['tracks']} person tracks incl. left/right mirrors
  ({d['frames']} frames at 20 fps). Random windows of {cfg['min_frames'] / 20:g}–{cfg['max_frames'] / 20:g} s
  (shorter clips whole). Text per window: the clip prompt (share {cfg['prompt_share']}) or the
  automatic body caption overlapping it most; mirrored windows get mirrored texts (left ↔
  right); {d['texts']} distinct texts. Sources and licences: below.
- Loss: symmetric InfoNCE, temperature {cfg['temperature']}; pairs with the same text or MiniLM
  cosine > {cfg['fn_threshold']} are not negatives. AdamW lr {cfg['lr']}, batch
  {cfg['batch_size']}, feature noise σ {cfg['feature_noise']}, dropout {cfg['dropout']}.
- {ckpt['steps']} steps in {ckpt['train_seconds']:.0f} s on a shared 2-core CPU ({cfg['threads']}
  torch thread); the checkpoint kept is the best by validation R-precision
  (step {best['step'] if best else '-'}).

{licence}
## Retrieval accuracy (through the ONNX runtime)
R-precision: each motion window (≤ 10 s, every person of every clip of the split) ranks its
own prompt among 32 texts (its own + 31 of samples with a different prompt), mean ± 95% CI
over 20 draws. The val split also chose the checkpoint, so test is the unbiased number.

| split | windows | distinct texts | top-1 | top-2 | top-3 |
|---|---|---|---|---|---|
{rows}

Caveat: the test set is small and its prompts are few ({table['test']['texts']} distinct), so
R-precision here measures recognising the action family more than fine wording.

## Reproduce
```
.venv/bin/python -m models.evaluator.train      # → var/evaluator/evaluator.pt
.venv/bin/python -m models.evaluator.export     # → models/weights/evaluator/
```
"""


def main(argv: list[str] | None = None) -> int:
    args, ckpt, model, runtime, err = export_command(
        argv, __doc__.split("\n")[0], DEFAULT_OUT / "evaluator.pt", WEIGHTS, export,
        load_checkpoint, Runtime, onnx_matches_torch)
    if not args.no_card:
        table = retrieval_table(runtime, default_clips(args.data_dir))
        params = sum(p.numel() for p in model.parameters())
        out = Path(args.out)
        (out / "MODEL_CARD.md").write_text(model_card(ckpt, table, err, params, out))
        print(json.dumps(table, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
